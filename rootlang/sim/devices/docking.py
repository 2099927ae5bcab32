"""Device 19, docking sensors (Create 3): the dock's contacts and the IR receivers that see its
beams. The motors' Dock and Undock commands ask it where the robot is."""

from __future__ import annotations

import math
from collections.abc import Mapping

from rootlang.protocol import Packet
from rootlang.sim.devices.base import Context, Handler, Pose, SimDevice
from rootlang.sim.motion import wrap
from rootlang.sim.sensors import dock_ir, docked_pose

ON_DOCK_MM = 30.0  # chosen: the contacts meet when the centre is this close to its docked place
ON_DOCK_TURN = math.radians(15)  # chosen: ... and the heading this close to the docked one


class Docking(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        pose = robot.physics.pose
        self.reading: tuple[int, ...] = (int(self.on_dock(pose)), *dock_ir(robot.world, pose))

    def commands(self) -> Mapping[str, Handler]:
        return {"get_docking_values": self._get_docking_values}

    def on_dock(self, pose: Pose) -> bool:
        target = docked_pose(self.robot.world)
        if target is None:
            return False
        close = math.dist(pose[:2], target[:2]) < ON_DOCK_MM
        return close and abs(wrap(pose[2] - target[2])) < ON_DOCK_TURN

    def sense(self, pose: Pose) -> None:
        reading = (int(self.on_dock(pose)), *dock_ir(self.robot.world, pose))
        if reading != self.reading:
            if reading[0] != self.reading[0]:
                self.robot.happened("docked" if reading[0] else "undocked")
            self.reading = reading
            self._send_event()

    def first_reading(self) -> None:
        """At power-on: a robot that sits on its dock says so."""
        if self.reading[0]:
            self._send_event()

    def _send_event(self) -> None:
        self.robot.event("docking_sensor_event", timestamp=self.robot.now_ms, **self._fields())

    def _fields(self) -> dict[str, int]:
        contacts, ir0, ir1, ir2 = self.reading
        return {"contacts": contacts, "ir_sensor_0": ir0, "ir_sensor_1": ir1, "ir_sensor_2": ir2}

    def _get_docking_values(self, packet: Packet) -> None:
        self.robot.respond(packet, timestamp=self.robot.now_ms, **self._fields())
