"""An in-memory robot for tests: a :class:`Transport` that answers commands by the packet table.

It is a fake robot with simple, exact behaviour (no physics): motion commands take
``distance / speed`` on the clock and update the pose; a newer motion, marker or sound command
finishes the older one at once (as the real robot does); Get commands answer from
:attr:`LoopbackRobot.readings`. Tests script it to misbehave: inject events, corrupt packets,
repeat packets, answer late, drop answers, or disconnect. It keeps every packet it received.

Responses repeat the request's first three bytes (same packet name and id), and everything the
robot sends goes to the host with ``loop.call_soon``, never from inside ``send``.
"""

from __future__ import annotations

import asyncio
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from rootlang.protocol import Packet, UnknownPacket, decode, encode, spec
from rootlang.protocol.behaviour import START, Actuator
from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock
from rootlang.runtime.transport import (
    USUAL_PROTOCOL,
    DisconnectHandler,
    PacketHandler,
    RobotInfo,
    Transport,
)

ROOT_WHEELBASE_MM = 102.0
SPEED_MM_S = 100.0
MARKER_SECONDS = 0.25


@dataclass
class Received:
    """One packet the fake robot got, and when."""

    time: float
    packet: Packet


@dataclass
class _Action:
    """A command in progress: its answer is sent when it ends (or is interrupted)."""

    request: Packet
    timer: asyncio.TimerHandle | None
    started: float
    seconds: float
    start_pose: tuple[float, float, float]
    end_pose: tuple[float, float, float]


@dataclass
class LoopbackRobot(Transport):
    clock: Clock
    model: RobotModel = RobotModel.RT1
    protocol_version: tuple[int, int] = USUAL_PROTOCOL
    name: str = "Loopback"
    readings: dict[str, dict[str, Any]] = field(default_factory=dict)
    """Fields of the answer to each Get command, by the command's name."""
    drop: set[str] = field(default_factory=set)
    """Commands the robot never answers."""
    answer_delay: dict[str, float] = field(default_factory=dict)
    """Extra seconds before answering these commands."""
    duplicate_answers: bool = False
    received: list[Received] = field(default_factory=list)
    pose: tuple[float, float, float] = (0.0, 0.0, 90.0)
    wheel_speeds: tuple[int, int] = (0, 0)
    connected: bool = False
    on_send: Callable[[Packet], None] | None = None
    """Test hook, called inside ``send`` with each packet received."""

    def __post_init__(self) -> None:
        self._on_packet: PacketHandler = lambda data: None
        self._on_disconnect: DisconnectHandler = lambda reason: None
        self._event_id = 0
        self._actions: dict[Actuator, _Action] = {}

    # ---- Transport ----

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        self._on_packet, self._on_disconnect = on_packet, on_disconnect
        self.connected = True
        return RobotInfo(self.model, self.name, protocol_version=self.protocol_version)

    async def send(self, packet: bytes) -> None:
        if not self.connected:
            raise ConnectionError("the loopback robot is not connected")
        request = decode(packet, sender="host", robot=self.model)
        if isinstance(request, UnknownPacket):
            return  # the real robot ignores commands it doesn't know
        self.received.append(Received(self.clock.now(), request))
        if self.on_send is not None:
            self.on_send(request)
        self._obey(request)

    async def disconnect(self) -> None:
        self.connected = False
        for action in self._actions.values():
            if action.timer is not None:
                action.timer.cancel()
        self._actions.clear()

    # ---- what tests do to the robot ----

    def emit(
        self, name: str, fields: dict[str, Any] | None = None, *, packet_id: int | None = None
    ) -> None:
        """Send an event (with the next event id unless one is given); fields not given are 0,
        the timestamp is the clock's."""
        if packet_id is None:
            packet_id = self._event_id
            self._event_id = (self._event_id + 1) % 256
        self.deliver(encode(name, self._complete(name, fields or {}), packet_id, robot=self.model))

    def _complete(self, name: str, fields: dict[str, Any]) -> dict[str, Any]:
        values: dict[str, Any] = dict.fromkeys(spec(name).field_names, 0)
        if "timestamp" in values:
            values["timestamp"] = round(self.clock.now() * 1000)
        values.update(fields)
        return values

    def deliver(self, data: bytes) -> None:
        """Hand raw bytes to the host (corrupt ones too), soon, never re-entrantly."""
        if self.connected:
            asyncio.get_running_loop().call_soon(self._on_packet, bytes(data))

    def drop_link(self, reason: str = "the robot went out of range") -> None:
        """An unexpected disconnect, as when the robot is switched off."""
        if self.connected:
            self.connected = False
            asyncio.get_running_loop().call_soon(self._on_disconnect, reason)

    def names_received(self) -> list[str]:
        return [item.packet.name for item in self.received]

    def is_moving(self) -> bool:
        return self.wheel_speeds != (0, 0) or any(
            action.request.spec.behaviour.moves for action in self._actions.values()
        )

    # ---- behaviour ----

    def _obey(self, request: Packet) -> None:
        name = request.name
        behaviour = request.spec.behaviour  # the packet table's: its actuator, what it does
        group = behaviour.actuator
        if group is not None:
            self._finish(group)
        if behaviour.stops:  # what it cancels is answered, as by a robot
            for actuator in list(self._actions):
                self._finish(actuator)
            self.wheel_speeds = (0, 0)
            self.pose = START
        elif behaviour.resets:
            self.pose = START
        elif behaviour.sets_wheels:
            left, right = self.wheel_speeds
            self.wheel_speeds = (
                request.fields.get("left", left),
                request.fields.get("right", right),
            )
        elif behaviour.moves:  # a drive, turn or arc stops the wheels first
            self.wheel_speeds = (0, 0)
        response = spec(name).response
        if response is None or name in self.drop:
            return
        seconds = self._duration(request) + self.answer_delay.get(name, 0.0)
        end_pose = self._end_pose(request)
        loop = asyncio.get_running_loop()
        if group is None:
            loop.call_later(seconds, self._answer, request)
            return
        action = _Action(request, None, self.clock.now(), seconds, self.pose, end_pose)
        action.timer = loop.call_later(seconds, self._finish, group)
        self._actions[group] = action

    def _finish(self, group: Actuator, *, answer: bool = True) -> None:
        action = self._actions.pop(group, None)
        if action is None:
            return
        if action.timer is not None:
            action.timer.cancel()
        done = (
            1.0
            if action.seconds <= 0
            else min((self.clock.now() - action.started) / action.seconds, 1.0)
        )
        self.pose = _between(action.start_pose, action.end_pose, done)
        if answer:
            self._answer(action.request)

    def _answer(self, request: Packet) -> None:
        response = spec(request.name).response
        if response is None or not self.connected:
            return
        values = self._complete(response.name, self.readings.get(request.name, {}))
        if {"x", "y", "heading"} <= set(response.field_names):
            x, y, heading = self.pose
            values.update(x=round(x), y=round(y), heading=round(heading * 10) % 3600)
        if "position" in values and "position" in request.fields:
            values["position"] = request.fields["position"]
        data = encode(response.name, values, request.id, robot=self.model)
        self.deliver(data)
        if self.duplicate_answers:
            self.deliver(data)

    def _duration(self, request: Packet) -> float:
        values = request.fields
        if request.name == "drive_distance":
            return float(abs(values["distance"])) / SPEED_MM_S
        if request.name == "rotate_angle":
            return _turn_seconds(float(values["angle"]) / 10.0)
        if request.name == "drive_arc":
            arc = abs(math.radians(values["angle"] / 10.0)) * abs(values["radius"])
            return float(arc) / SPEED_MM_S
        if request.name in ("play_note", "play_sweep"):
            return float(values["duration"]) / 1000.0
        if request.name == "say_phrase":
            return 0.1 * len(str(values["phrase"]))
        if request.name == "set_marker_position":
            return MARKER_SECONDS
        if request.name == "navigate_to_position":
            x, y, _ = self.pose
            return math.hypot(values["x"] - x, values["y"] - y) / SPEED_MM_S
        return 0.0

    def _end_pose(self, request: Packet) -> tuple[float, float, float]:
        x, y, heading = self.pose
        values = request.fields
        if request.name == "drive_distance":
            distance = values["distance"]
            radians = math.radians(heading)
            return (x + distance * math.cos(radians), y + distance * math.sin(radians), heading)
        if request.name == "rotate_angle":
            return (x, y, heading - values["angle"] / 10.0)  # positive is clockwise
        if request.name == "navigate_to_position":
            facing = values["heading"]
            return (float(values["x"]), float(values["y"]), heading if facing < 0 else facing / 10)
        return self.pose


def _turn_seconds(degrees: float) -> float:
    return abs(math.radians(degrees)) * ROOT_WHEELBASE_MM / 2 / SPEED_MM_S


def _between(
    start: tuple[float, float, float], end: tuple[float, float, float], done: float
) -> tuple[float, float, float]:
    x = start[0] + (end[0] - start[0]) * done
    y = start[1] + (end[1] - start[1]) * done
    heading = (start[2] + (end[2] - start[2]) * done) % 360
    return (x, y, heading)
