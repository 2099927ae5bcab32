"""Device 4, colour sensor (Root RT1): 32 sensors in a row under the robot's front.

The floor they read is a raster of sensor colours (:class:`~rootlang.sim.sensors.FloorRaster`),
which the marker paints into. A reading samples the strip swept since the last one, so a thin
line is not missed between two readings.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from rootlang.protocol import ColorFormat, ColorLighting, Packet
from rootlang.protocol.fields import COLOR_SENSORS
from rootlang.sim.devices.base import Context, Handler, Pose, SimDevice
from rootlang.sim.models import COLOR_SENSOR_AHEAD, COLOR_SENSOR_SPAN
from rootlang.sim.sensors import REFLECTANCE, FloorRaster

Row = tuple[tuple[float, float], tuple[float, float]]  # leftmost and rightmost sensor, world mm

SENSORS_PER_BANK = 8  # spec: Get Color Sensor Data answers a bank of 8 sensors
SAMPLE_EVERY_MM = 2.0  # chosen: a sample row every 2 mm of travel finds a 3 mm marker line
MOST_ROWS = 64  # chosen: a cap on the rows of one reading (a jump, not travel)
DARK_REFLECTANCE = 0.02  # chosen: what a sensor reads with its lights off
MILLIVOLTS_FULL_SCALE = 3300  # spec: format 1 is millivolts of a 3.3 V supply ...
ADC_FULL_SCALE = 4095  # ... format 0 the raw 12-bit ADC counts
HALF_SPAN = COLOR_SENSOR_SPAN / 2


class ColorSensor(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.floor = FloorRaster(robot.world)
        self.colors = bytes(COLOR_SENSORS)  # what is under each sensor (all white at first)
        # where the row was at the last reading: the pose, and the row once worked out
        self._last: tuple[Pose, Row | None] = (robot.physics.pose, None)

    def commands(self) -> Mapping[str, Handler]:
        return {"get_color_sensor_data": self._get_color_sensor_data}

    def sense(self, pose: Pose) -> None:
        (last_pose, before) = self._last
        if self.floor.plain or self.robot.picked_up:
            self._last = (pose, None)  # (the row only when it is needed)
            return
        after = _sensor_row(pose)
        before = before or _sensor_row(last_pose)
        self._last = (pose, after)
        travel = max(math.dist(before[0], after[0]), math.dist(before[1], after[1]))
        rows = max(1, min(MOST_ROWS, math.ceil(travel / SAMPLE_EVERY_MM)))
        sampled = self.floor.sweep(before, after, rows)
        final = sampled[-COLOR_SENSORS:]
        if final != self.colors:  # one event a reading for what is under the sensors now ...
            self.colors = final
            self.robot.event("color_sensor_event", colors=final)
            return
        # ... or, if that has not changed, two for a line crossed on the way (a thin line that
        # was under the sensors only for a moment between two readings)
        if sampled == final * rows:
            return  # the usual case: the same all the way
        n = COLOR_SENSORS
        crossed = (sampled[n * k : n * k + n] for k in range(rows - 1))
        passing = next(row for row in crossed if row != final)
        self.robot.event("color_sensor_event", colors=passing)
        self.robot.event("color_sensor_event", colors=final)

    def _get_color_sensor_data(self, packet: Packet) -> None:
        bank, lighting = int(packet["bank"]), ColorLighting(packet["lighting"])
        millivolts = packet["format"] == ColorFormat.MILLIVOLTS
        full_scale = MILLIVOLTS_FULL_SCALE if millivolts else ADC_FULL_SCALE
        first = SENSORS_PER_BANK * bank
        values = []
        for color in self.colors[first : first + SENSORS_PER_BANK]:
            red, green, blue = REFLECTANCE[color]
            reflectance = {
                ColorLighting.OFF: DARK_REFLECTANCE, ColorLighting.RED: red,
                ColorLighting.GREEN: green, ColorLighting.BLUE: blue,
                ColorLighting.ALL: (red + green + blue) / 3,
            }[lighting]  # fmt: skip
            values.append(round(reflectance * full_scale))
        self.robot.respond(packet, data=values)


def _sensor_row(pose: Pose) -> Row:
    """Its ends: the same points as ``body_point`` gives, with one cosine and sine for both."""
    x, y, heading = pose
    c, s = math.cos(heading), math.sin(heading)
    middle_x, middle_y = x + COLOR_SENSOR_AHEAD * c, y + COLOR_SENSOR_AHEAD * s
    across_x, across_y = HALF_SPAN * s, HALF_SPAN * c
    return (middle_x - across_x, middle_y + across_y), (middle_x + across_x, middle_y - across_y)
