"""Device 11, IR proximity (Create 3): seven reflective sensors across the front, read as rays
into the world's walls and obstacles."""

from __future__ import annotations

import math
from collections.abc import Mapping

from rootlang.protocol import Packet
from rootlang.sim.devices.base import Context, Handler, Pose, SimDevice
from rootlang.sim.models import IR_ANGLES, IR_RANGE
from rootlang.sim.sensors import ir_counts

PERIOD_MS = 80  # chosen: how often the sensors are read for events
DEFAULT_THRESHOLD = 500  # chosen (the spec gives no defaults): counts that turn a sensor on
DEFAULT_HYSTERESIS = 50  # chosen: ... and how far below that it must fall to turn off
SENSORS_IN_GET_VALUES = 6  # spec: Get IR Proximity Values answers the first six


class IrProximity(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.state = 0  # one bit per sensor that is on
        self.thresholds = [DEFAULT_THRESHOLD] * len(IR_ANGLES)
        self.hysteresis = DEFAULT_HYSTERESIS
        self.next_ms = PERIOD_MS  # its next reading for events

    def commands(self) -> Mapping[str, Handler]:
        return {
            "get_ir_proximity_values": self._get_ir_proximity_values,
            "get_packed_ir_proximity": self._get_packed_ir_proximity,
            "set_ir_event_thresholds": self._set_ir_event_thresholds,
            "get_ir_event_thresholds": self._get_ir_event_thresholds,
        }

    def sense(self, pose: Pose) -> None:
        """Read if its period has come round: an event when a sensor turns on or off."""
        now = self.robot.now_ms
        if now < self.next_ms:
            return
        self.next_ms = (now // PERIOD_MS + 1) * PERIOD_MS
        values = self._values(pose)
        state = self._bits(values)
        if state != self.state:
            self.state = state
            self.robot.event("ir_proximity_event", timestamp=now, state=state, sensors=values)

    def _values(self, pose: Pose) -> list[int]:
        x, y, heading = pose
        radius = self.robot.spec.width / 2
        values = []
        for angle in IR_ANGLES:
            direction = heading + math.radians(angle)
            c, s = math.cos(direction), math.sin(direction)
            start = (x + radius * c, y + radius * s)
            end = (x + (radius + IR_RANGE) * c, y + (radius + IR_RANGE) * s)
            values.append(ir_counts(self.robot.physics.ray(start, end)))
        return values

    def _bits(self, values: list[int]) -> int:
        state = 0
        for i, value in enumerate(values):
            was_on = self.state >> i & 1
            threshold = self.thresholds[i]
            on = value >= threshold or (was_on and value > threshold - self.hysteresis)
            state |= int(on) << i
        return state

    def _get_ir_proximity_values(self, packet: Packet) -> None:
        values = self._values(self.robot.physics.pose)
        self.robot.respond(
            packet, timestamp=self.robot.now_ms, sensors=values[:SENSORS_IN_GET_VALUES]
        )

    def _get_packed_ir_proximity(self, packet: Packet) -> None:
        values = self._values(self.robot.physics.pose)
        self.robot.respond(
            packet, timestamp=self.robot.now_ms, state=self._bits(values), sensors=values
        )

    def _set_ir_event_thresholds(self, packet: Packet) -> None:
        self.hysteresis = int(packet["hysteresis"])
        self.thresholds = [int(v) for v in packet["thresholds"]]

    def _get_ir_event_thresholds(self, packet: Packet) -> None:
        self.robot.respond(packet, hysteresis=self.hysteresis, thresholds=self.thresholds)
