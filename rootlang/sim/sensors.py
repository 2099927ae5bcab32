"""What the robot's sensors read from the world: pure functions of pose and world, plus the floor.

The floor is a raster of *sensor colours* (the five a colour sensor can tell apart), one byte per
cell: the mat is drawn into it once, and the robot's own marker paints into it as it draws (the
eraser wipes back to the mat), so the colour sensors see the robot's lines. A reading samples the
strip swept by the sensor row since the last reading, so a thin line is not missed between two
readings. Sampling uses Pillow's QUAD transform (one C call for 32 sensors x N rows), through
:mod:`rootlang.sim.pillow_fence`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import TYPE_CHECKING

from rootlang.colors import NAMED_COLORS, SENSOR_COLORS, Color
from rootlang.protocol.fields import COLOR_SENSORS
from rootlang.sim.models import DOCK_OFFSET, IR_RANGE
from rootlang.sim.world import Circle, Line, Polygon, Rect, Shape, World

if TYPE_CHECKING:
    from PIL import Image, ImageDraw

Point = tuple[float, float]
WHITE = 0  # SensorColor.WHITE: the class of an unmarked floor
MAX_CELLS = 16e6

# Reflectance (0-1) of each sensor colour under red, green and blue light (chosen).
REFLECTANCE: dict[int, tuple[float, float, float]] = {
    0: (0.90, 0.90, 0.90),  # white
    1: (0.05, 0.05, 0.05),  # black
    2: (0.85, 0.10, 0.10),  # red
    3: (0.10, 0.70, 0.15),  # green
    4: (0.10, 0.15, 0.75),  # blue
}


def sensor_color(color: Color) -> int:
    """The sensor colour (0-4) a printed colour reads as: the nearest of the five."""
    best = min(
        range(len(SENSOR_COLORS)),
        key=lambda i: (_distance2(color, NAMED_COLORS[SENSOR_COLORS[i]]), i),
    )
    return best


def _distance2(a: Color, b: Color) -> int:
    return sum((p - q) ** 2 for p, q in zip(a.rgb, b.rgb, strict=True))


class FloorRaster:
    """The floor as sensor colours, one byte per ``mm_per_cell`` square.

    Its pictures (and Pillow) are made on first need: a plain floor (no mat) shows nothing until
    the marker draws on it, so a run that never draws needs neither."""

    mat: Image.Image  # the printed mat
    floor: Image.Image  # what the sensors see: the mat, and the marker's lines on it

    def __init__(self, world: World, mm_per_cell: float | None = None):
        if mm_per_cell is None:  # 1 mm cells; coarser for big floors (at most 16 M cells)
            mm_per_cell = max(1.0, math.sqrt(world.width * world.height / MAX_CELLS))
        self.scale = 1.0 / mm_per_cell
        self.size = (
            max(1, math.ceil(world.width * self.scale)),
            max(1, math.ceil(world.height * self.scale)),
        )
        self.world = world
        self.plain = not world.mat  # nothing to see until the marker draws
        self.drawn = False
        if not self.plain:
            self._make_pictures()

    def _make_pictures(self) -> None:
        from PIL import Image, ImageDraw

        from rootlang.sim.pillow_fence import line_painter, sample_quad

        self.mat = Image.new("L", self.size, sensor_color(self.world.floor_color))
        draw = ImageDraw.Draw(self.mat)
        for item in self.world.mat:
            self._draw(draw, item.shape, sensor_color(item.color))
        self.floor = self.mat.copy()
        self._draw_floor = ImageDraw.Draw(self.floor)
        self._sample_quad = sample_quad
        self._paint_line = line_painter(self.floor)
        self.drawn = True

    def _cells(self, points: Sequence[Point]) -> list[Point]:
        return [(x * self.scale, y * self.scale) for x, y in points]

    def _draw(self, draw: ImageDraw.ImageDraw, shape: Shape, value: int) -> None:
        if isinstance(shape, Rect):
            draw.polygon(self._cells(shape.points), fill=value)
        elif isinstance(shape, Circle):
            (cx, cy), r = self._cells([(shape.x, shape.y)])[0], shape.radius * self.scale
            draw.ellipse((cx - r, cy - r, cx + r, cy + r), fill=value)
        elif isinstance(shape, Polygon):
            draw.polygon(self._cells(shape.points), fill=value)
        else:
            assert isinstance(shape, Line)
            self._line(draw, shape.points, shape.width, value)

    def _line(
        self, draw: ImageDraw.ImageDraw, points: Sequence[Point], width: float, value: int
    ) -> None:
        cells = self._cells(points)
        pen = self._pen(width)
        draw.line(cells, fill=value, width=pen)
        r = width * self.scale / 2
        if pen > 4:  # round joints and ends (thinner lines do without)
            for cx, cy in cells:
                draw.ellipse((cx - r, cy - r, cx + r, cy + r), fill=value)

    def _pen(self, width: float) -> int:
        """A line's width in whole cells."""
        return max(1, round(width * self.scale))

    def paint(self, start: Point, end: Point, width: float, value: int) -> None:
        """The marker drew a line from ``start`` to ``end`` (at every reading while it draws)."""
        if not self.drawn:
            self._make_pictures()
        s, pen = self.scale, self._pen(width)
        if pen > 4:  # with round joints and ends
            self._line(self._draw_floor, (start, end), width, value)
        else:
            self._paint_line(((start[0] * s, start[1] * s), (end[0] * s, end[1] * s)), value, pen)
        self.plain = False

    def erase(self, corners: Sequence[Point]) -> None:
        """The eraser wiped this quadrilateral: back to the printed mat."""
        if not self.drawn:
            return  # nothing drawn yet: the floor is the mat
        cells = self._cells(corners)
        left = max(0, math.floor(min(x for x, _ in cells)))
        top = max(0, math.floor(min(y for _, y in cells)))
        right = min(self.floor.width, math.ceil(max(x for x, _ in cells)) + 1)
        bottom = min(self.floor.height, math.ceil(max(y for _, y in cells)) + 1)
        if right <= left or bottom <= top:
            return
        from PIL import Image, ImageDraw

        mask = Image.new("1", (right - left, bottom - top), 0)
        ImageDraw.Draw(mask).polygon([(x - left, y - top) for x, y in cells], fill=1)
        box = (left, top, right, bottom)
        self.floor.paste(self.mat.crop(box), box, mask)

    def sweep(self, before: tuple[Point, Point], after: tuple[Point, Point], rows: int) -> bytes:
        """Sensor colours along the row of 32 sensors, ``rows`` times from ``before`` to ``after``.

        ``before`` and ``after`` are (leftmost sensor, rightmost sensor) in world mm. Row k of the
        result (32 bytes) is the row ``(k + 1) / rows`` of the way, so the last row is ``after``.
        """
        if not self.drawn:
            self._make_pictures()
        (bl, br), (al, ar) = before, after
        n = COLOR_SENSORS
        # Pillow samples pixel centres: widen the quad by half a sensor gap each side, and shift
        # it half a row forward, so sample (i, k) lands exactly on sensor i at row k.
        gap_x, gap_y = (br[0] - bl[0]) / (2 * (n - 1)), (br[1] - bl[1]) / (2 * (n - 1))
        move_lx, move_ly = (al[0] - bl[0]) / (2 * rows), (al[1] - bl[1]) / (2 * rows)
        move_rx, move_ry = (ar[0] - br[0]) / (2 * rows), (ar[1] - br[1]) / (2 * rows)
        s = self.scale
        x0, y0 = (bl[0] - gap_x + move_lx) * s, (bl[1] - gap_y + move_ly) * s  # upper left
        sw_x, sw_y = (al[0] - gap_x + move_lx) * s, (al[1] - gap_y + move_ly) * s  # lower left
        se_x, se_y = (ar[0] + gap_x + move_rx) * s, (ar[1] + gap_y + move_ry) * s  # lower right
        ne_x, ne_y = (br[0] + gap_x + move_rx) * s, (br[1] + gap_y + move_ry) * s  # upper right
        quad = (x0, y0, sw_x, sw_y, se_x, se_y, ne_x, ne_y)
        return self._sample_quad(self.floor, (n, rows), quad)


# --- geometry helpers -------------------------------------------------------------------------


def body_point(pose: tuple[float, float, float], ahead: float, left: float) -> Point:
    """A point fixed on the robot (mm ahead of and to the left of its centre), in the world."""
    x, y, heading = pose
    c, s = math.cos(heading), math.sin(heading)
    return (x + ahead * c - left * s, y + ahead * s + left * c)


def light_level(world: World, point: Point) -> float:
    """Ambient light (percent) at a point: the brightest light region over it.

    Circles fade from their level at the centre to the room's at the edge, so a lamp can be
    found by steering towards the brighter side; other shapes are lit evenly.
    """
    x, y = point
    level = world.ambient_light
    for region in world.lights:
        shape = region.shape
        if isinstance(shape, Circle):
            distance = math.hypot(x - shape.x, y - shape.y)
            if distance < shape.radius:
                fade = 1 - distance / shape.radius
                level = max(
                    level, world.ambient_light + (region.level - world.ambient_light) * fade
                )
        elif shape.contains(x, y):
            level = max(level, region.level)
    return level


def ir_counts(distance: float | None) -> int:
    """A reflective IR sensor's reading (0-4095) for something ``distance`` mm away."""
    if distance is None or distance >= IR_RANGE:
        return 0
    return round(4095 * (1 - distance / IR_RANGE) ** 2)


def gravity_reading(
    world: World, heading: float, pitch_deg: float = 0.0, roll_deg: float = 0.0
) -> tuple[int, int, int]:
    """The accelerometer at rest (milli-g): it reads the push that holds the robot up.

    On a floor that is +1000 on z. On a whiteboard (a wall; world +y is up) the push is along
    the board: y reads 1000 when the robot faces up, x -1000 when it faces right. ``pitch``
    (nose up) and ``roll`` (right side down) tilt a robot on the floor.
    """
    if world.surface == "whiteboard":
        return (round(-1000 * math.cos(heading)), round(1000 * math.sin(heading)), 0)
    pitch, roll = math.radians(pitch_deg), math.radians(roll_deg)
    return (
        round(-1000 * math.sin(roll) * math.cos(pitch)),
        round(1000 * math.sin(pitch)),
        round(1000 * math.cos(pitch) * math.cos(roll)),
    )


# Characters a Create 3 dock sends on its IR beams (chosen from the Roomba dock codes).
DOCK_RED_BUOY, DOCK_GREEN_BUOY, DOCK_FORCE_FIELD = 8, 4, 1
DOCK_CODE_BASE = 160
DOCK_BEAM_RANGE = 1500.0
DOCK_BEAM_HALF_ANGLE = math.radians(35)


def docked_pose(world: World) -> tuple[float, float, float] | None:
    """Where a docked Create 3's centre is, and its heading (radians), in this world."""
    dock = world.dock
    if dock is None:
        return None
    facing = math.radians(dock.heading)
    return (
        dock.x + DOCK_OFFSET * math.cos(facing),
        dock.y + DOCK_OFFSET * math.sin(facing),
        facing + math.pi,
    )


def dock_ir(world: World, pose: tuple[float, float, float]) -> tuple[int, int, int]:
    """The characters the halo (0) and front (1) docking sensors receive from the dock's beams."""
    dock = world.dock
    if dock is None:
        return (0, 0, 0)
    dx, dy = pose[0] - dock.x, pose[1] - dock.y
    distance = math.hypot(dx, dy)
    facing = math.radians(dock.heading)
    off_axis = math.remainder(math.atan2(dy, dx) - facing, math.tau)
    if distance > DOCK_BEAM_RANGE or abs(off_axis) > DOCK_BEAM_HALF_ANGLE:
        return (0, 0, 0)
    code = DOCK_CODE_BASE
    if off_axis > -math.radians(5):
        code |= DOCK_RED_BUOY  # the dock's left beam, seen from the dock
    if off_axis < math.radians(5):
        code |= DOCK_GREEN_BUOY
    if distance < DOCK_OFFSET + 300:
        code |= DOCK_FORCE_FIELD
    towards_dock = math.atan2(-dy, -dx)
    sees_dock = abs(math.remainder(towards_dock - pose[2], math.tau)) < math.radians(30)
    return (code, code if sees_dock else 0, 0)
