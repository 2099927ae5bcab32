"""Device 17, touch sensors: Root's four top buttons, a Create 3's buttons 1 and 2."""

from __future__ import annotations

from rootlang.protocol import TouchSensors
from rootlang.sim.devices.base import Context, SimDevice
from rootlang.sim.world import TOUCH_SENSOR_NAMES

# A world's names for them (front left, front right, back left, back right) -> the spec's bits.
SENSOR_FLAGS = dict(
    zip(
        TOUCH_SENSOR_NAMES,
        (TouchSensors.FRONT_LEFT, TouchSensors.FRONT_RIGHT, TouchSensors.REAR_LEFT,
         TouchSensors.REAR_RIGHT),
        strict=True,
    )
)  # fmt: skip
_NAMES = {flag: name for name, flag in SENSOR_FLAGS.items()}


class Touch(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.state = 0  # the bits of the sensors touched now

    def touched(self, names: tuple[str, ...], hold_ms: int) -> None:
        """A person touches these sensors (a world's names) now, for ``hold_ms``; those the
        model does not have are not felt."""
        bits = 0
        for name in names:
            if name in self.robot.spec.touch_sensors:
                bits |= SENSOR_FLAGS[name]
        if bits:
            self._set(self.state | bits)
            self.robot.at(self.robot.now_ms + hold_ms, lambda: self._set(self.state & ~bits))

    def _set(self, bits: int) -> None:
        if bits != self.state:
            self.state = bits
            names = [_NAMES[flag] for flag in TouchSensors if flag & bits]  # the world's names
            self.robot.happened("touch " + (", ".join(names) or "released"))
            self.robot.event("touch_sensor_event", timestamp=self.robot.now_ms, state=bits)
