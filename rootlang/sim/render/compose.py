"""A recording → the scene every back end draws (and the replay's timeline).

This is the one place that decides what a picture of a run shows and how it looks: the floor and
its mat, table tops (a dashed red edge; off them is a drop), light regions (faint), walls,
obstacles, the dock, the marker's ink (eraser sweeps remove it), the path driven (thin, faint),
the robot at its final pose and a scale bar. World millimetres, y up, as in the recording.
"""

from __future__ import annotations

import bisect
import itertools
import math
from collections.abc import Sequence
from dataclasses import replace

from rootlang.colors import Color, color_name, hex_rgb
from rootlang.diagnostics import seconds_text
from rootlang.runtime.trace import ViewLine
from rootlang.sim import world as w
from rootlang.sim.models import ERASER_BEHIND, spec_for
from rootlang.sim.recording import Frame, Recording, Stroke
from rootlang.sim.render.robot import robot_shapes
from rootlang.sim.render.scene import (
    Box,
    Circle,
    Erase,
    Happening,
    Ink,
    Label,
    Moment,
    Paint,
    Point,
    Polygon,
    Polyline,
    Replay,
    Scene,
    Shape,
    bounds,
    dashes,
    length_text,
    nice_length,
    place,
    rectangle,
    shape_points,
)
from rootlang.sim.sensors import body_point
from rootlang.units import note_name

SURROUND = "#e4e4e7"  # outside the floor
DROP = "#a1a1aa"  # floor that is off every table top
TABLE_EDGE = Paint(stroke="#dc2626")
WALL = "#52525b"
DARK = "#27272a"
PATH = "#2563eb"
BRIGHT, SHADE = "#facc15", "#1e3a8a"
LIGHT_OPACITY = 0.15
MIN_VIEW_MM = 500.0
PATH_TOLERANCE_MM = 1.0  # the path is drawn this close to where the robot went
LINE_FRACTION = 1 / 500  # thin lines are this much of the picture's longer side


def _darker(color: Color) -> str:
    red, green, blue = (channel * 3 // 5 for channel in color.rgb)
    return hex_rgb((red, green, blue))


# --- the world ----------------------------------------------------------------------------------


def _shape(shape: w.Shape, paint: Paint) -> Shape:
    """A world shape as a scene shape; a line is drawn with its own pen width in ``paint.fill``."""
    if isinstance(shape, w.Rect):
        return Polygon(shape.points, paint)
    if isinstance(shape, w.Circle):
        return Circle((shape.x, shape.y), shape.radius, paint)
    if isinstance(shape, w.Polygon):
        return Polygon(shape.points, paint)
    return Polyline(
        shape.points, Paint(stroke=paint.fill, width_mm=shape.width, opacity=paint.opacity)
    )


def _floor(world: w.World, unit: float) -> list[Shape]:
    floor = w.Rect(0.0, 0.0, world.width, world.height)
    shapes = [_shape(floor, Paint(fill=DROP if world.table else world.floor_color.hex))]
    shapes += [_shape(top, Paint(fill=world.floor_color.hex)) for top in world.table]
    shapes += [_shape(item.shape, Paint(fill=item.color.hex)) for item in world.mat]
    for region in world.lights:
        color = BRIGHT if region.level >= world.ambient_light else SHADE
        shapes.append(_shape(region.shape, Paint(fill=color, opacity=LIGHT_OPACITY)))
    edge = Paint(stroke=TABLE_EDGE.stroke, width_mm=unit * 1.5)
    for top in world.table:
        outline = shape_points(_shape(top, edge)) if not isinstance(top, w.Circle) else _ring(top)
        closed = [*outline, outline[0]]
        shapes += [Polyline(dash, edge) for dash in dashes(closed, unit * 8, unit * 5)]
    return shapes


def _ring(circle: w.Circle, steps: int = 72) -> list[Point]:
    return [
        (circle.x + circle.radius * math.cos(a), circle.y + circle.radius * math.sin(a))
        for a in (2 * math.pi * i / steps for i in range(steps))
    ]


def _solids(world: w.World, unit: float) -> list[Shape]:
    shapes: list[Shape] = []
    for wall in world.all_walls():
        (x1, y1), (x2, y2) = wall.start, wall.end
        length = math.dist(wall.start, wall.end) + wall.thickness  # square ends that meet
        angle = math.degrees(math.atan2(y2 - y1, x2 - x1))
        middle = ((x1 + x2) / 2, (y1 + y2) / 2)
        shapes.append(Polygon(rectangle(middle, length, wall.thickness, angle), Paint(fill=WALL)))
    for obstacle in world.obstacles:
        paint = Paint(obstacle.color.hex, _darker(obstacle.color), unit)
        shapes.append(_shape(obstacle.shape, paint))
    if world.dock is not None:
        shapes += _dock(world.dock, unit)
    return shapes


def _dock(dock: w.Dock, unit: float) -> list[Shape]:
    """A Create 3 dock: its back plate (behind the point it stands on) and its name."""
    pose = (dock.x, dock.y, dock.heading)
    base = place(Polygon(rectangle((-30.0, 0.0), 60.0, 200.0), Paint("#3f3f46", DARK, unit)), *pose)
    tag = place(Label((-30.0, 0.0), "dock", 36.0, "#fafafa", "middle"), *pose)
    assert isinstance(tag, Label)
    return [base, replace(tag, at=(tag.at[0], tag.at[1] - 12.0))]  # centred on the plate


# --- the run ------------------------------------------------------------------------------------


def _tip(frame: Frame, kind: str) -> Point:
    """Where the tool touches the floor: the marker at the centre, the eraser behind it."""
    if kind == "marker":
        return (frame.x_mm, frame.y_mm)
    return body_point((frame.x_mm, frame.y_mm, math.radians(frame.heading_deg)), -ERASER_BEHIND, 0)


def _cumulative(points: Sequence[Point]) -> list[float]:
    return list(
        itertools.accumulate((math.dist(a, b) for a, b in itertools.pairwise(points)), initial=0.0)
    )


def timed(
    points: Sequence[Point], tips: Sequence[Point], times_s: Sequence[float]
) -> tuple[float, ...]:
    """When a line was drawn: a time for each of ``points``, from where the tool was (``tips``) at
    ``times_s``. A point gets the moment the tool had gone as far along as the point is along the
    line (the lengths matched up), so a replay draws the ink right under the robot."""
    if not times_s:
        return tuple(0.0 for _ in points)
    travelled = _cumulative(tips)
    along = _cumulative(points)
    stretch = travelled[-1] / along[-1] if along[-1] > 0 else 0.0
    result: list[float] = []
    for distance in along:
        target = distance * stretch
        i = min(bisect.bisect_left(travelled, target), len(travelled) - 1)
        if i == 0 or travelled[i] == travelled[i - 1]:
            result.append(times_s[i])
            continue
        f = (target - travelled[i - 1]) / (travelled[i] - travelled[i - 1])
        result.append(times_s[i - 1] + (times_s[i] - times_s[i - 1]) * f)
    return tuple(result)


def _frames_while_drawing(frames: Sequence[Frame], stroke: Stroke) -> list[Frame]:
    """The frames from the stroke's start until its tool is lifted (that frame included)."""
    start = bisect.bisect_left(frames, stroke.t_ms, key=lambda frame: frame.t_ms)
    chosen: list[Frame] = []
    for frame in itertools.islice(frames, start, None):
        chosen.append(frame)
        if frame.tool != stroke.kind:
            break
    return chosen


def _ink(recording: Recording, unit: float) -> list[Ink]:
    ink: list[Ink] = []
    for stroke in recording.strokes:
        if not stroke.points:
            continue
        points: tuple[Point, ...] = tuple((float(x), float(y)) for x, y in stroke.points)
        if len(points) == 1:
            points = (points[0], points[0])  # a dot
        frames = _frames_while_drawing(recording.frames, stroke)
        tips = [_tip(f, stroke.kind) for f in frames]
        times = timed(points, tips, [f.t_ms / 1000 for f in frames])
        if stroke.kind == "eraser":
            ink.append(Erase(points, stroke.width_mm, times))
        else:
            paint = Paint(stroke=stroke.color, width_mm=max(stroke.width_mm, unit * 1.5))
            ink.append(Polyline(points, paint, times))
    return ink


def straighten(points: Sequence[Point], tolerance: float) -> list[Point]:
    """Drop the points that lie (within ``tolerance`` mm) on the line between their neighbours,
    so a straight drive is one segment, not one per frame."""
    kept: list[Point] = list(points[:1])
    for point, following in itertools.pairwise(points):
        if not kept or _off_line(kept[-1], point, following) > tolerance:
            kept.append(point)
    return [*kept, *points[-1:]] if len(points) > 1 else kept


def _off_line(start: Point, point: Point, end: Point) -> float:
    """How far ``point`` is from the line through ``start`` and ``end`` (or from ``start``)."""
    length = math.dist(start, end)
    if length == 0:
        return math.dist(start, point)
    cross = (end[0] - start[0]) * (point[1] - start[1]) - (end[1] - start[1]) * (
        point[0] - start[0]
    )
    return abs(cross) / length


def _path(recording: Recording, unit: float) -> Polyline | None:
    points = straighten([(float(x), float(y)) for x, y in recording.path()], PATH_TOLERANCE_MM)
    if len(points) < 2:
        return None
    frames = recording.frames
    times = timed(points, [_tip(f, "marker") for f in frames], [f.t_ms / 1000 for f in frames])
    return Polyline(tuple(points), Paint(stroke=PATH, width_mm=unit, opacity=0.45), times)


def _robot(recording: Recording) -> tuple[Shape, ...]:
    final = recording.final_frame
    if final is None:
        return ()
    shapes, ring = robot_shapes(recording.model)
    placed = [place(s, final.x_mm, final.y_mm, final.heading_deg) for s in shapes]
    lit = placed[ring]
    if final.led_mode != "off" and isinstance(lit, Circle):
        led = Paint(stroke=hex_rgb(final.led_rgb), width_mm=lit.paint.width_mm)
        placed[ring] = Circle(lit.center, lit.radius_mm, led)
    return tuple(placed)


def _scale_bar(view: Box, unit: float) -> list[Shape]:
    length = nice_length(view.width / 5)
    x, y = view.left + unit * 12, view.bottom + unit * 10
    pen = Paint(stroke=DARK, width_mm=unit * 1.5)
    tick = unit * 4
    return [
        Polyline(((x, y + tick), (x, y), (x + length, y), (x + length, y + tick)), pen),
        Label((x + length / 2, y + unit * 3), length_text(length), unit * 12, DARK, "middle"),
    ]


def _world_points(world: w.World) -> list[Point]:
    """Where the world's things are (not its bare floor and border walls)."""
    shapes: list[w.Shape] = [item.shape for item in world.mat]
    shapes += [o.shape for o in world.obstacles] + [r.shape for r in world.lights]
    shapes += list(world.table)
    points: list[Point] = [p for wall in world.walls for p in (wall.start, wall.end)]
    for shape in shapes:
        points += shape_points(_shape(shape, Paint()))
    if world.dock is not None:
        points += shape_points(_dock(world.dock, 0.0)[0])
    return points


def _view(recording: Recording) -> tuple[Box, float]:
    """What the picture shows: the world's things and everywhere the robot went, at least
    ``MIN_VIEW_MM`` square, with a margin (the scale bar sits in the bottom one). A bare floor
    is not shown whole, so a small drawing stays big. Also the width of a thin line."""
    reach = spec_for(recording.model).length / 2
    went = [(float(x), float(y)) for x, y in recording.path()]
    went += [(float(x), float(y)) for stroke in recording.strokes for x, y in stroke.points]
    start = recording.world.robot
    went.append((start.x, start.y))
    around = [(x + dx, y + dy) for x, y in went for dx, dy in ((-reach, -reach), (reach, reach))]
    box = bounds([*_world_points(recording.world), *around])
    assert box is not None  # the start is always there
    grow_x, grow_y = max(0.0, MIN_VIEW_MM - box.width) / 2, max(0.0, MIN_VIEW_MM - box.height) / 2
    unit = max(box.width + 2 * grow_x, box.height + 2 * grow_y) * LINE_FRACTION
    margin = unit * 12
    view = Box(
        box.left - grow_x - margin,
        box.bottom - grow_y - margin * 2.5,
        box.right + grow_x + margin,
        box.top + grow_y + margin,
    )
    return view, unit


def scene_of(recording: Recording) -> Scene:
    """The still picture of a run: everything as it was at the end."""
    world = recording.world
    view, unit = _view(recording)
    return Scene(
        view=view,
        background=SURROUND,
        title=f"{world.name}: {recording.model.display_name}",
        below=(*_floor(world, unit), *_solids(world, unit)),
        ink=tuple(_ink(recording, unit)),
        path=_path(recording, unit),
        robot=_robot(recording),
        overlay=tuple(_scale_bar(view, unit)),
    )


def _timeline(recording: Recording) -> tuple[Happening, ...]:
    """What the replay's list shows without the program's own view: the run's happenings, what
    the robot said, the notes it played (by name) and its lights (by colour name), in time
    order."""
    items: list[tuple[int, str]] = [(e.t_ms, e.text) for e in recording.events]
    items += [(s.t_ms, f"say “{s.text}”") for s in recording.said]
    for note in recording.notes:
        pitch = (
            note_name(note.frequency_hz)
            if note.end_hz == note.frequency_hz
            else f"{note_name(note.frequency_hz)}→{note_name(note.end_hz)}"
        )
        items.append((note.t_ms, f"♪ {pitch} for {seconds_text(note.duration_ms / 1000)}"))
    for light in recording.lights:
        shown = "off" if light.mode == "off" else f"{light.mode} {color_name(light.rgb)}"
        items.append((light.t_ms, f"light {shown}"))
    items.sort(key=lambda item: item[0])  # stable: same-time items keep the order above
    return tuple(Happening(t / 1000, text) for t, text in items)


def replay_of(
    recording: Recording, title: str = "", story: Sequence[ViewLine] | None = None
) -> Replay:
    """The moving parts of the HTML replay: the robot, its poses and lights, and the list: the
    child's view of the run (``story``, as ``rootlang sim`` prints it) when given, else what
    the recording tells."""
    shapes, ring = robot_shapes(recording.model)
    moments = tuple(
        Moment(
            f.t_ms / 1000,
            f.x_mm,
            f.y_mm,
            f.heading_deg,
            None if f.led_mode == "off" else hex_rgb(f.led_rgb),
            f.led_mode,
        )
        for f in recording.frames
    )
    said = tuple((s.t_ms / 1000, s.text) for s in recording.said)
    if story is None:
        events = _timeline(recording)
    else:
        events = tuple(Happening(v.time_ms / 1000, v.text, v.kind, v.line) for v in story)
    return Replay(shapes, ring, moments, events, said, title)
