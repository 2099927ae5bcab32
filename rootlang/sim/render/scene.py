"""The scene: a picture of a run as a short list of primitive shapes, built once.

Every picture back end (SVG, PNG, the HTML replay) draws the same :class:`Scene`, built from a
recording by :mod:`~rootlang.sim.render.compose`, so no back end works out any geometry of its
own; the replay also gets a :class:`Replay` (the robot in its own frame, its poses over time and
the timeline). Coordinates are world millimetres with **y pointing up** (the robot's protocol
frame: it starts at (0, 0) facing 90°, i.e. +y). Each back end flips y to its own screen.

Paint order: ``below`` (floor, mat, light regions, table edges, walls, dock), then the faint
``path`` driven, then ``ink`` (the marker's drawing in the order it was drawn, in its true colours
over the path; an :class:`Erase` removes the ink drawn before it, not the mat), then the ``robot``
at its final pose, then ``overlay`` (the scale bar).
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, replace

Point = tuple[float, float]


@dataclass(frozen=True)
class Paint:
    """How a shape is filled and outlined; colours are ``#rrggbb``, widths in mm."""

    fill: str | None = None
    stroke: str | None = None
    width_mm: float = 0.0
    opacity: float = 1.0


@dataclass(frozen=True)
class Polygon:
    points: tuple[Point, ...]
    paint: Paint


@dataclass(frozen=True)
class Polyline:
    """An open line with round caps and joins. ``times_s`` (one per point) lets a replay draw it
    progressively; still pictures ignore it."""

    points: tuple[Point, ...]
    paint: Paint
    times_s: tuple[float, ...] = ()


@dataclass(frozen=True)
class Circle:
    center: Point
    radius_mm: float
    paint: Paint


@dataclass(frozen=True)
class Label:
    """Text whose baseline starts (``start``), is centred (``middle``) or ends (``end``) at
    ``at``."""

    at: Point
    text: str
    size_mm: float
    color: str
    anchor: str = "start"


@dataclass(frozen=True)
class Erase:
    """The eraser's sweep: removes marker ink drawn before it along a band ``width_mm`` wide."""

    points: tuple[Point, ...]
    width_mm: float
    times_s: tuple[float, ...] = ()


Shape = Polygon | Polyline | Circle | Label
Ink = Polyline | Erase


@dataclass(frozen=True)
class Box:
    """An axis-aligned rectangle in world mm (y up)."""

    left: float
    bottom: float
    right: float
    top: float

    @property
    def width(self) -> float:
        return self.right - self.left

    @property
    def height(self) -> float:
        return self.top - self.bottom


@dataclass(frozen=True)
class Scene:
    view: Box
    background: str
    title: str = ""
    below: tuple[Shape, ...] = ()
    ink: tuple[Ink, ...] = ()
    path: Polyline | None = None
    robot: tuple[Shape, ...] = ()
    overlay: tuple[Shape, ...] = ()


@dataclass(frozen=True)
class Moment:
    """The robot at one instant: its pose and what its lights show (``led`` None when off)."""

    t_s: float
    x_mm: float
    y_mm: float
    heading_deg: float
    led: str | None = None
    led_mode: str = "on"


@dataclass(frozen=True)
class Replay:
    """Everything the page shows, beyond the still scene."""

    robot: tuple[Shape, ...]  # in the robot's frame (forward +x)
    light_ring: int  # index in ``robot`` of the shape the LEDs colour
    moments: tuple[Moment, ...]
    events: tuple[Happening, ...] = ()
    said: tuple[tuple[float, str], ...] = ()
    title: str = ""  # the program's name (the page's heading)


@dataclass(frozen=True)
class Happening:
    """A line of the replay's list: when, what, its kind (``start``, ``command``, ``print``,
    ``error``, ``end`` ... styled by the page) and the program line behind it (0: none)."""

    t_s: float
    text: str
    kind: str = "event"
    line: int = 0


# --- geometry helpers (the one place that rotates, rounds corners and dashes) ---


def rotate(point: Point, degrees: float) -> Point:
    angle = math.radians(degrees)
    cos, sin = math.cos(angle), math.sin(angle)
    return (point[0] * cos - point[1] * sin, point[0] * sin + point[1] * cos)


def place(shape: Shape, x_mm: float, y_mm: float, heading_deg: float) -> Shape:
    """Move a shape drawn in the robot's frame (forward = +x, left = +y) to a pose in the world."""

    def move(point: Point) -> Point:
        turned = rotate(point, heading_deg)
        return (turned[0] + x_mm, turned[1] + y_mm)

    if isinstance(shape, Polygon):
        return replace(shape, points=tuple(move(p) for p in shape.points))
    if isinstance(shape, Polyline):
        return replace(shape, points=tuple(move(p) for p in shape.points))
    if isinstance(shape, Circle):
        return replace(shape, center=move(shape.center))
    return replace(shape, at=move(shape.at))


def rectangle(
    center: Point, width: float, height: float, angle_deg: float = 0.0
) -> tuple[Point, ...]:
    """The corners of a ``width`` × ``height`` rectangle centred on ``center``, turned by
    ``angle_deg``."""
    half_w, half_h = width / 2, height / 2
    corners = ((-half_w, -half_h), (half_w, -half_h), (half_w, half_h), (-half_w, half_h))
    return tuple(
        (center[0] + dx, center[1] + dy) for dx, dy in (rotate(c, angle_deg) for c in corners)
    )


def rounded_rectangle(
    width: float, height: float, radius: float, steps: int = 6
) -> tuple[Point, ...]:
    """A rectangle centred on the origin with corners rounded by ``radius`` (as a polygon)."""
    radius = min(radius, width / 2, height / 2)
    inner_x, inner_y = width / 2 - radius, height / 2 - radius
    points: list[Point] = []
    for corner, (cx, cy) in enumerate(
        ((inner_x, inner_y), (-inner_x, inner_y), (-inner_x, -inner_y), (inner_x, -inner_y))
    ):
        for step in range(steps + 1):
            angle = math.radians(90 * corner + 90 * step / steps)
            points.append((cx + radius * math.cos(angle), cy + radius * math.sin(angle)))
    return tuple(points)


def dashes(points: Sequence[Point], dash_mm: float, gap_mm: float) -> list[tuple[Point, ...]]:
    """Cut a polyline into dashes (so every back end draws the same dashes)."""
    pieces: list[tuple[Point, ...]] = []
    current: list[Point] = []
    drawing, left_in_phase = True, dash_mm
    for start, end in itertools.pairwise(points):
        length = math.dist(start, end)
        if length == 0:
            continue
        done = 0.0
        if drawing and not current:
            current.append(start)
        while length - done >= left_in_phase:
            done += left_in_phase
            cut = _along(start, end, done / length)
            if drawing:
                current.append(cut)
                pieces.append(tuple(current))
                current = []
            else:
                current = [cut]
            drawing = not drawing
            left_in_phase = dash_mm if drawing else gap_mm
        left_in_phase -= length - done
        if drawing:
            current.append(end)
    if len(current) > 1:
        pieces.append(tuple(current))
    return pieces


def _along(start: Point, end: Point, fraction: float) -> Point:
    return (start[0] + (end[0] - start[0]) * fraction, start[1] + (end[1] - start[1]) * fraction)


def bounds(points: Iterable[Point]) -> Box | None:
    xs: list[float] = []
    ys: list[float] = []
    for x, y in points:
        xs.append(x)
        ys.append(y)
    if not xs:
        return None
    return Box(min(xs), min(ys), max(xs), max(ys))


def shape_points(shape: Shape | Erase) -> list[Point]:
    """Points that bound a shape (for fitting the view)."""
    if isinstance(shape, Polygon | Polyline | Erase):
        return list(shape.points)
    if isinstance(shape, Circle):
        (x, y), r = shape.center, shape.radius_mm
        return [(x - r, y - r), (x + r, y + r)]
    return [shape.at]


def nice_length(longest_mm: float) -> float:
    """A round length (1, 2 or 5 × a power of ten) of at most ``longest_mm``."""
    power = 10 ** math.floor(math.log10(max(longest_mm, 1.0)))
    for factor in (5, 2, 1):
        if factor * power <= longest_mm:
            return float(factor * power)
    return float(power)


def length_text(mm: float) -> str:
    if mm >= 1000:
        return f"{mm / 1000:g} m"
    if mm >= 10:
        return f"{mm / 10:g} cm"
    return f"{mm:g} mm"
