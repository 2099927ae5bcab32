"""A tiny host for driving the virtual robot with packets in tests."""

from __future__ import annotations

from typing import Any

from rootlang.protocol import Packet, decode, encode
from rootlang.robots import RobotModel
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import World, parse_world


class Host:
    """Sends commands with incrementing ids and keeps every decoded packet the robot sends."""

    def __init__(self, robot: VirtualRobot) -> None:
        self.robot = robot
        self.next_id = 1
        self.received: list[Packet] = []

    def send(self, name: str, **fields: Any) -> int:
        packet_id = self.next_id
        self.next_id = self.next_id % 255 + 1
        self.robot.write(encode(name, fields, packet_id, robot=self.robot.model))
        self._collect()
        return packet_id

    def wait(self, seconds: float) -> list[Packet]:
        """Let time pass; returns what arrived meanwhile."""
        before = len(self.received)
        self.robot.advance(seconds)
        self._collect()
        return self.received[before:]

    def ask(self, name: str, **fields: Any) -> Packet:
        """Send a Get command and return its (immediate) response."""
        packet_id = self.send(name, **fields)
        return self.response(name, packet_id)

    def response(self, command: str, packet_id: int) -> Packet:
        found = [p for p in self.received if p.name == f"{command}_response" and p.id == packet_id]
        assert len(found) == 1, f"{len(found)} responses to {command} #{packet_id}"
        return found[0]

    def events(self, name: str) -> list[Packet]:
        return [p for p in self.received if p.name == name]

    def _collect(self) -> None:
        for data in self.robot.read():
            packet = decode(data, "robot", robot=self.robot.model)
            assert isinstance(packet, Packet)
            self.received.append(packet)


def make_robot(world_text: str = "", model: RobotModel | None = None) -> tuple[VirtualRobot, Host]:
    robot = VirtualRobot(world(world_text), model=model)
    return robot, Host(robot)


def world(text: str = "") -> World:
    return parse_world(text, "test.toml")


PLAIN = """
[floor]
width = 3000
height = 3000
walls = false
[robot]
x = 1500
y = 1500
heading = 90
"""
