"""Device 13, light sensors (Root): the two ambient light sensors behind the "eyes"."""

from __future__ import annotations

from collections.abc import Mapping

from rootlang.protocol import LightState, Packet
from rootlang.sim.devices.base import Context, Handler, Pose, SimDevice
from rootlang.sim.models import EYE_AHEAD, EYE_SIDE
from rootlang.sim.sensors import body_point, light_level

PERIOD_MS = 120  # chosen: how often the eyes are read for events
DARK_PERCENT = 20.0  # chosen: both eyes below this are "both dark"
DIFFERENCE_PERCENT = 5.0  # chosen: one eye this much brighter than the other is "brighter"
PER_PERCENT = 10  # spec: readings are in tenths of a percent


class LightSensors(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.state = self._reading(robot.physics.pose)[0]  # known at power-on, not announced
        self.next_ms = PERIOD_MS  # its next reading for events

    def commands(self) -> Mapping[str, Handler]:
        return {"get_light_values": self._get_light_values}

    def sense(self, pose: Pose) -> None:
        """Read if its period has come round: an event when the state changes."""
        now = self.robot.now_ms
        if now < self.next_ms or not self.robot.world.lights:  # no lamps: the room's level only
            return
        self.next_ms = (now // PERIOD_MS + 1) * PERIOD_MS
        state, left, right = self._reading(pose)
        if state != self.state:
            self.state = state
            self.robot.event("light_event", timestamp=now, state=state, left=left, right=right)

    def _eyes(self, pose: Pose) -> tuple[int, int]:
        world = self.robot.world
        left = light_level(world, body_point(pose, EYE_AHEAD, EYE_SIDE))
        right = light_level(world, body_point(pose, EYE_AHEAD, -EYE_SIDE))
        return round(left * PER_PERCENT), round(right * PER_PERCENT)

    def _reading(self, pose: Pose) -> tuple[LightState, int, int]:
        left, right = self._eyes(pose)
        dark, difference = DARK_PERCENT * PER_PERCENT, DIFFERENCE_PERCENT * PER_PERCENT
        if left < dark and right < dark:
            state = LightState.BOTH_DARK
        elif left - right > difference:
            state = LightState.LEFT_BRIGHTER
        elif right - left > difference:
            state = LightState.RIGHT_BRIGHTER
        else:
            state = LightState.BOTH_BRIGHT
        return state, left, right

    def _get_light_values(self, packet: Packet) -> None:
        left, right = self._eyes(self.robot.physics.pose)
        self.robot.respond(packet, timestamp=self.robot.now_ms, left=left, right=right)
