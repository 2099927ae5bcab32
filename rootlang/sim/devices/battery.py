"""Device 14, battery: drains as the robot drives (less standing still); an event when it has
dropped by more than ten points since the last one (the spec's words)."""

from __future__ import annotations

import math
from collections.abc import Mapping

from rootlang.protocol import Packet
from rootlang.sim.devices.base import Context, Handler, SimDevice

IDLE_SHARE = 1 / 3  # chosen: standing still drains a third of what driving does
EVENT_DROP = 10.0  # spec: an event "when the battery level drops by more than 10%" (points)
MS_PER_MINUTE = 60_000  # the world gives the drain in percent a minute


class Battery(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.percent = robot.world.robot.battery
        self._reported = self.percent  # the level at the last event (or at power-on)
        self._counted_ms = 0  # the level is counted up to here
        self._moving_per_ms = robot.world.robot.battery_drain / MS_PER_MINUTE  # percent
        self._idle_per_ms = self._moving_per_ms * IDLE_SHARE

    def commands(self) -> Mapping[str, Handler]:
        return {"get_battery_level": self._get_battery_level}

    def drain(self, *, moving: bool) -> None:
        """Use up the battery for the time since it was last counted."""
        now = self.robot.now_ms
        ms, self._counted_ms = now - self._counted_ms, now
        per_ms = self._moving_per_ms if moving else self._idle_per_ms
        self.percent = max(0.0, self.percent - per_ms * ms)
        if self._reported - self.percent > EVENT_DROP:
            self._reported = self.percent
            self.robot.event("battery_level_event", timestamp=now, **self._fields())

    def event_due(self, step_ms: int) -> int | None:
        """When (ms, on a step), standing still, the level will have dropped enough for its
        next event; None if it never will."""
        per_ms = self._idle_per_ms
        floor = self._reported - EVENT_DROP  # the event comes once the level is below this
        if per_ms <= 0 or floor < 0:
            return None
        to_go = self.percent - floor
        steps = math.floor(to_go / per_ms / step_ms) + 1  # the first step strictly below
        return self.robot.now_ms + max(1, steps) * step_ms

    def _fields(self) -> dict[str, int]:
        low, high = self.robot.spec.battery_mv
        voltage = round(low + (high - low) * self.percent / 100)
        return {"voltage": voltage, "percent": round(self.percent)}

    def _get_battery_level(self, packet: Packet) -> None:
        self.robot.respond(packet, timestamp=self.robot.now_ms, **self._fields())
