"""Device 16, accelerometer: gravity as the robot's body feels it (tilted by a person)."""

from __future__ import annotations

from collections.abc import Mapping

from rootlang.protocol import Packet
from rootlang.sim.devices.base import Context, Handler, SimDevice
from rootlang.sim.sensors import gravity_reading

LEVEL = (0.0, 0.0)


class Accelerometer(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.tilt = LEVEL  # pitch (nose up), roll (right side down), degrees

    def commands(self) -> Mapping[str, Handler]:
        return {"get_accelerometer": self._get_accelerometer}

    def tilted(self, pitch: float, roll: float, hold_ms: int) -> None:
        """A person tilts the robot now, for ``hold_ms``."""
        self.robot.happened(f"tilted pitch {pitch:g} roll {roll:g}")
        self.tilt = (pitch, roll)
        self.robot.at(self.robot.now_ms + hold_ms, self._level)

    def _level(self) -> None:
        self.tilt = LEVEL

    def _get_accelerometer(self, packet: Packet) -> None:
        robot = self.robot
        x, y, z = gravity_reading(robot.world, robot.physics.pose[2], *self.tilt)
        robot.respond(packet, timestamp=robot.now_ms, x=x, y=y, z=z)
