"""Worlds: what the simulated robot lives in, read from a TOML file.

A world is plain data (frozen dataclasses): the floor, walls and obstacles, a coloured mat, light
regions, table tops (off them is a drop), a dock, the robot's model and start pose, a time limit
and scripted stimuli (touches, the nose button, being picked up or tilted). The format is
documented in ``docs/worlds.md``. Coordinates are world millimetres with the origin at the floor's
lower-left corner, x to the right and y up; headings are degrees counterclockwise from +x, so 90
faces "up" the page, like the protocol's own start heading.

A bad file raises :class:`~rootlang.diagnostics.RootlangError` (E3xx) naming the file, the key and
what was expected; nothing is half-loaded.
"""

from __future__ import annotations

import itertools
import math
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Literal, TypeAlias

from rootlang import forms
from rootlang.colors import NAMED_COLORS, Color
from rootlang.diagnostics import NO_SPAN, RootlangError, did_you_mean, file_problem
from rootlang.robots import RobotModel
from rootlang.wording.shown import Described, Phrase, Suggestion, suggestion

Point: TypeAlias = tuple[float, float]


# --- shapes (world millimetres) ---------------------------------------------------------------


@dataclass(frozen=True)
class Rect:
    """An axis-aligned rectangle; (x, y) is its lower-left corner."""

    x: float
    y: float
    width: float
    height: float

    @property
    def points(self) -> tuple[Point, ...]:
        x, y, w, h = self.x, self.y, self.width, self.height
        return ((x, y), (x + w, y), (x + w, y + h), (x, y + h))

    def contains(self, px: float, py: float) -> bool:
        return self.x <= px <= self.x + self.width and self.y <= py <= self.y + self.height


@dataclass(frozen=True)
class Circle:
    """A circle: its centre and radius."""

    x: float
    y: float
    radius: float

    def contains(self, px: float, py: float) -> bool:
        return (px - self.x) ** 2 + (py - self.y) ** 2 <= self.radius**2


@dataclass(frozen=True)
class Polygon:
    """A closed polygon, its corners in order (either direction)."""

    points: tuple[Point, ...]

    def contains(self, px: float, py: float) -> bool:
        inside = False
        corners = self.points
        for (x1, y1), (x2, y2) in zip(corners, corners[1:] + corners[:1], strict=True):
            if (y1 > py) != (y2 > py) and px < x1 + (py - y1) * (x2 - x1) / (y2 - y1):
                inside = not inside
        return inside


@dataclass(frozen=True)
class Line:
    """A polyline drawn with a pen ``width`` mm wide (round ends)."""

    points: tuple[Point, ...]
    width: float

    def contains(self, px: float, py: float) -> bool:
        half = self.width / 2
        return any(
            _distance_to_segment(px, py, a, b) <= half for a, b in itertools.pairwise(self.points)
        )


Shape: TypeAlias = "Rect | Circle | Polygon | Line"
SHAPE_NAMES = ("rect", "circle", "polygon", "line")


def _distance_to_segment(px: float, py: float, a: Point, b: Point) -> float:
    ax, ay = a
    dx, dy = b[0] - ax, b[1] - ay
    length2 = dx * dx + dy * dy
    t = 0.0 if length2 == 0 else max(0.0, min(1.0, ((px - ax) * dx + (py - ay) * dy) / length2))
    return math.hypot(px - (ax + t * dx), py - (ay + t * dy))


# --- the parts of a world ---------------------------------------------------------------------


@dataclass(frozen=True)
class MatItem:
    """A coloured piece of the floor mat; later items are printed on top of earlier ones."""

    shape: Shape
    color: Color


@dataclass(frozen=True)
class Wall:
    """A straight wall from ``start`` to ``end``."""

    start: Point
    end: Point
    thickness: float = 20.0


@dataclass(frozen=True)
class Obstacle:
    """A solid thing on the floor (a box, a pillar, a chair leg)."""

    shape: Rect | Circle | Polygon
    color: Color = NAMED_COLORS["black"]


@dataclass(frozen=True)
class LightRegion:
    """A lit (or shaded) part of the room; the brightest region over a point wins."""

    shape: Shape
    level: float  # percent


@dataclass(frozen=True)
class Dock:
    """A Create 3 dock; ``heading`` is the way it faces (a docked robot faces the other way)."""

    x: float
    y: float
    heading: float


@dataclass(frozen=True)
class RobotStart:
    """The robot a world starts with: its model, pose, marker colour, battery and name."""

    model: RobotModel = RobotModel.RT1
    x: float = 0.0
    y: float = 0.0
    heading: float = 90.0
    marker_color: Color = NAMED_COLORS["black"]
    battery: float = 100.0  # percent
    battery_drain: float = 1.0  # percent a minute while driving (a third of it standing still)
    name: str = ""


StimulusAction = Literal["touch", "nose", "bump", "pick up", "tilt"]
BUMPER_SIDE_NAMES = forms.BUMPER_SIDE_NAMES  # (as programs name them)
TOUCH_SENSOR_NAMES = forms.TOUCH_SENSOR_NAMES


@dataclass(frozen=True)
class StimulusKind:
    """What a person can do to the robot, as a world file and the studio's page name it: the
    parts it presses (their names, and how a message names them), and whether the page offers
    it (its buttons: touch a sensor, press a bumper, the nose button)."""

    action: StimulusAction
    parts: tuple[str, ...] = ()
    parts_named: str = ""
    on_the_page: bool = False


STIMULI: dict[str, StimulusKind] = {
    kind.action: kind
    for kind in (
        StimulusKind("touch", TOUCH_SENSOR_NAMES, "touch sensors", on_the_page=True),
        StimulusKind("nose", on_the_page=True),
        StimulusKind("bump", BUMPER_SIDE_NAMES, "bumper sides", on_the_page=True),
        StimulusKind("pick up"),
        StimulusKind("tilt"),
    )
}
"""Every stimulus, by its one spelling: the world files', the page's and the simulator's."""
STIMULUS_ACTIONS: tuple[str, ...] = tuple(STIMULI)


@dataclass(frozen=True)
class Stimulus:
    """Something a person does to the robot at a given (simulated) time."""

    at: float  # seconds since the start
    action: StimulusAction
    sensors: tuple[str, ...] = ()  # touch: which of TOUCH_SENSOR_NAMES; bump: BUMPER_SIDE_NAMES
    duration: float = 0.2  # seconds held (touch, pick up, tilt)
    pitch: float = 0.0  # tilt: degrees, nose up positive
    roll: float = 0.0  # tilt: degrees, right side down positive


Surface = Literal["floor", "whiteboard"]


@dataclass(frozen=True)
class World:
    """Everything the simulated robot lives in (see the module's docstring)."""

    name: str = "default"
    path: str = ""
    width: float = 2000.0
    height: float = 2000.0
    floor_color: Color = NAMED_COLORS["white"]
    border_walls: bool = True
    surface: Surface = "floor"
    ambient_light: float = 50.0  # percent
    time_limit: float = 60.0  # seconds of simulated time
    robot: RobotStart = field(default_factory=lambda: RobotStart(x=1000.0, y=1000.0))
    walls: tuple[Wall, ...] = ()
    obstacles: tuple[Obstacle, ...] = ()
    mat: tuple[MatItem, ...] = ()
    lights: tuple[LightRegion, ...] = ()
    table: tuple[Rect | Circle | Polygon, ...] = ()  # empty: the whole floor is safe
    dock: Dock | None = None
    stimuli: tuple[Stimulus, ...] = ()

    def all_walls(self) -> tuple[Wall, ...]:
        """The walls, plus the four round the floor's edge when ``border_walls``."""
        if not self.border_walls:
            return self.walls
        w, h = self.width, self.height
        corners = ((0.0, 0.0), (w, 0.0), (w, h), (0.0, h))
        border = tuple(Wall(a, b) for a, b in zip(corners, corners[1:] + corners[:1], strict=True))
        return border + self.walls

    def with_model(self, model: RobotModel) -> World:
        return replace(self, robot=replace(self.robot, model=model))

    def mat_color_at(self, x: float, y: float) -> Color:
        for item in reversed(self.mat):
            if item.shape.contains(x, y):
                return item.color
        return self.floor_color

    def on_table(self, x: float, y: float) -> bool:
        """False over a drop: off every table top (when there are table tops) or off the floor."""
        if not (0 <= x <= self.width and 0 <= y <= self.height):
            return False
        return not self.table or any(top.contains(x, y) for top in self.table)


def default_world(model: RobotModel = RobotModel.RT1) -> World:
    """A 2 m square white floor with walls round it, the robot in the middle facing up."""
    return World(name="default").with_model(model)


# --- loading ----------------------------------------------------------------------------------

WORLD_KEYS = (
    "name",
    "time_limit",
    "floor",
    "robot",
    "wall",
    "obstacle",
    "mat",
    "light",
    "table",
    "dock",
    "stimulus",
)


def load_world(path: str | Path, shown_as: str | None = None) -> World:
    """Read a world file; a problem raises RootlangError (E301-E305) naming file (as
    ``shown_as``, default ``path``) and key."""
    file = Path(path)
    shown = shown_as or str(file)
    try:
        text = file.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise RootlangError.of("E301", path=shown) from None
    except (OSError, UnicodeDecodeError) as error:
        raise RootlangError.of("E302", path=shown, reason=file_problem(error)) from None
    return parse_world(text, str(file), shown)


def parse_world(text: str, path: str = "<world>", shown_as: str | None = None) -> World:
    # the TOML reader loads here: a program in the default world starts without it
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover - Python 3.10
        import tomli as tomllib
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as error:
        raise RootlangError.of("E302", path=shown_as or path, reason=str(error)) from None
    return _WorldReader(path, shown_as or path).world(data)


@dataclass
class _Table:
    """One TOML table being read, with its key path for messages (``mat[2].width``)."""

    reader: _WorldReader
    where: str
    data: Mapping[str, object]

    def key(self, name: str) -> str:
        return f"{self.where}.{name}" if self.where else name

    def only(self, *allowed: str) -> None:
        for name in self.data:
            if name not in allowed:
                guess = did_you_mean(name, allowed)
                hint = suggestion(guess) or f" I know: {', '.join(allowed)}."
                raise self.reader.error("E304", key=self.key(name), hint=hint)

    def has(self, name: str) -> bool:
        return name in self.data

    def number(
        self,
        name: str,
        default: float | None = None,
        *,
        low: float | None = None,
        high: float | None = None,
        positive: bool = False,
    ) -> float:
        value = self.data.get(name)
        if value is None:
            if default is None:
                raise self.reader.missing(self.key(name), "a number")
            return default
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.reader.wrong(self.key(name), "a number", value)
        number = float(value)
        if not math.isfinite(number):
            raise self.reader.wrong(self.key(name), "a number", value)
        if positive and number <= 0:
            raise self.reader.wrong(self.key(name), "a number above 0", value)
        if (low is not None and number < low) or (high is not None and number > high):
            raise self.reader.wrong(self.key(name), f"a number from {low:g} to {high:g}", value)
        return number

    def text(self, name: str, default: str | None = None) -> str:
        value = self.data.get(name)
        if value is None:
            if default is None:
                raise self.reader.missing(self.key(name), "some text")
            return default
        if not isinstance(value, str):
            raise self.reader.wrong(self.key(name), "some text in quotes", value)
        return value

    def choice(self, name: str, options: Sequence[str], default: str | None = None) -> str:
        value = self.text(name, default)
        if value.lower() not in options:
            raise self.reader.wrong(self.key(name), "one of " + ", ".join(options), value)
        return value.lower()

    def flag(self, name: str, default: bool) -> bool:
        value = self.data.get(name, default)
        if not isinstance(value, bool):
            raise self.reader.wrong(self.key(name), "true or false", value)
        return value

    def color(self, name: str, default: Color | None = None) -> Color:
        value = self.data.get(name)
        if value is None and default is not None:
            return default
        if isinstance(value, str):
            word = value.strip().lower()
            if word in NAMED_COLORS:
                return NAMED_COLORS[word]
            digits = word.lstrip("#")
            if len(digits) == 6 and all(c in "0123456789abcdef" for c in digits):
                return Color.from_hex(digits)
        expected = Phrase.listed(["a colour name (" + ", ".join(NAMED_COLORS) + ")", '"#rrggbb"'])
        if value is None:
            raise self.reader.missing(self.key(name), expected)
        raise self.reader.wrong(self.key(name), expected, value)

    def point(self, name: str, value: object = None) -> Point:
        value = self.data.get(name) if value is None else value
        if (
            isinstance(value, list)
            and len(value) == 2
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in value)
        ):
            return (float(value[0]), float(value[1]))
        if value is None:
            raise self.reader.missing(self.key(name), "a point [x, y] in mm")
        raise self.reader.wrong(self.key(name), "a point [x, y] in mm", value)

    def points(self, name: str, at_least: int) -> tuple[Point, ...]:
        value = self.data.get(name)
        expected = f"a list of at least {at_least} points [[x, y], ...] in mm"
        if value is None:
            raise self.reader.missing(self.key(name), expected)
        if not isinstance(value, list) or len(value) < at_least:
            raise self.reader.wrong(self.key(name), expected, value)
        return tuple(self.point(f"{name}[{i}]", item) for i, item in enumerate(value))

    def tables(self, name: str) -> list[_Table]:
        value = self.data.get(name, [])
        if isinstance(value, dict):
            value = [value]
        if not isinstance(value, list) or not all(isinstance(item, dict) for item in value):
            raise self.reader.wrong(self.key(name), f"[[{name}]] tables", value)
        return [_Table(self.reader, f"{self.key(name)}[{i}]", item) for i, item in enumerate(value)]

    def table(self, name: str) -> _Table | None:
        value = self.data.get(name)
        if value is None:
            return None
        if not isinstance(value, dict):
            raise self.reader.wrong(self.key(name), f"a [{name}] table", value)
        return _Table(self.reader, self.key(name), value)

    def shape(self, *kinds: str, extra: Sequence[str] = ()) -> Shape:
        """A shape from ``shape = "rect"`` and its own keys (rect is the default)."""
        kind = self.choice("shape", kinds, "rect")
        if kind == "rect":
            self.only("shape", "x", "y", "width", "height", *extra)
            return Rect(
                self.number("x"),
                self.number("y"),
                self.number("width", positive=True),
                self.number("height", positive=True),
            )
        if kind == "circle":
            self.only("shape", "x", "y", "radius", *extra)
            return Circle(self.number("x"), self.number("y"), self.number("radius", positive=True))
        if kind == "polygon":
            self.only("shape", "points", *extra)
            return Polygon(self.points("points", 3))
        self.only("shape", "points", "width", *extra)
        return Line(self.points("points", 2), self.number("width", 5.0, positive=True))

    def solid_shape(self, *extra: str) -> Rect | Circle | Polygon:
        shape = self.shape("rect", "circle", "polygon", extra=extra)
        assert not isinstance(shape, Line)  # "line" is not among the kinds allowed
        return shape


@dataclass
class _WorldReader:
    """Reads one world file's data, naming the file in its errors as ``shown``."""

    path: str
    shown: str

    def error(self, code: str, **values: object) -> RootlangError:
        return RootlangError.of(code, NO_SPAN, path=self.shown, **values)

    def wrong(self, key: str, expected: str | Phrase, value: object) -> RootlangError:
        return self.error("E303", key=key, expected=_described(expected), got=_shown(value))

    def missing(self, key: str, expected: str | Phrase) -> RootlangError:
        return self.error("E305", key=key, expected=_described(expected))

    def world(self, data: Mapping[str, object]) -> World:
        top = _Table(self, "", data)
        top.only(*WORLD_KEYS)
        defaults = World()
        floor = top.table("floor") or _Table(self, "floor", {})
        floor.only("width", "height", "color", "walls", "surface", "light")
        width = floor.number("width", defaults.width, positive=True)
        height = floor.number("height", defaults.height, positive=True)
        return World(
            name=top.text("name", Path(self.path).stem),
            path=self.path,
            width=width,
            height=height,
            floor_color=floor.color("color", defaults.floor_color),
            border_walls=floor.flag("walls", True),
            surface="whiteboard"
            if floor.choice("surface", ("floor", "whiteboard"), "floor") == "whiteboard"
            else "floor",
            ambient_light=floor.number("light", defaults.ambient_light, low=0, high=100),
            time_limit=top.number("time_limit", defaults.time_limit, positive=True),
            robot=self.robot(top.table("robot"), width, height),
            walls=tuple(self.wall(item) for item in top.tables("wall")),
            obstacles=tuple(
                Obstacle(item.solid_shape("color"), item.color("color", NAMED_COLORS["black"]))
                for item in top.tables("obstacle")
            ),
            mat=tuple(
                MatItem(item.shape(*SHAPE_NAMES, extra=("color",)), item.color("color"))
                for item in top.tables("mat")
            ),
            lights=tuple(
                LightRegion(
                    item.shape(*SHAPE_NAMES, extra=("level",)),
                    item.number("level", low=0, high=100),
                )
                for item in top.tables("light")
            ),
            table=tuple(item.solid_shape() for item in top.tables("table")),
            dock=self.dock(top.table("dock")),
            stimuli=tuple(
                sorted((self.stimulus(item) for item in top.tables("stimulus")), key=_at)
            ),
        )

    def robot(self, table: _Table | None, width: float, height: float) -> RobotStart:
        if table is None:
            return RobotStart(x=width / 2, y=height / 2)
        table.only("model", "x", "y", "heading", "marker_color", "battery", "battery_drain", "name")
        model_name = table.text("model", "RT1")
        try:
            model = RobotModel.from_name(model_name)
        except ValueError:
            models = Phrase.listed(['"RT0"', '"RT1"', '"Create3"'])
            raise self.wrong(table.key("model"), models, model_name) from None
        return RobotStart(
            model=model,
            x=table.number("x", width / 2, low=0, high=width),
            y=table.number("y", height / 2, low=0, high=height),
            heading=table.number("heading", 90.0),
            marker_color=table.color("marker_color", NAMED_COLORS["black"]),
            battery=table.number("battery", 100.0, low=0, high=100),
            battery_drain=table.number("battery_drain", 1.0, low=0, high=100),
            name=table.text("name", ""),
        )

    def wall(self, table: _Table) -> Wall:
        table.only("from", "to", "thickness")
        return Wall(
            table.point("from"), table.point("to"), table.number("thickness", 20.0, positive=True)
        )

    def dock(self, table: _Table | None) -> Dock | None:
        if table is None:
            return None
        table.only("x", "y", "heading")
        return Dock(table.number("x"), table.number("y"), table.number("heading", 270.0))

    def stimulus(self, table: _Table) -> Stimulus:
        kind = STIMULI[table.choice("action", STIMULUS_ACTIONS)]
        action = kind.action
        at = table.number("at", low=0)
        if kind.parts:
            table.only("at", "action", "sensors", "duration")
            known, what = kind.parts, kind.parts_named
            raw = table.data.get("sensors", [known[0]])
            names = [raw] if isinstance(raw, str) else raw
            expected = f"a list of {what} (" + ", ".join(known) + ")"
            if (
                not isinstance(names, list)
                or not names
                or not all(isinstance(n, str) and n.lower() in known for n in names)
            ):
                raise self.wrong(table.key("sensors"), expected, raw)
            sensors = tuple(str(n).lower() for n in names)
            duration = table.number("duration", 0.2, positive=True)
            return Stimulus(at, action, sensors, duration)
        if action == "nose":
            table.only("at", "action")
            return Stimulus(at, "nose", duration=0.1)
        if action == "pick up":
            table.only("at", "action", "duration")
            return Stimulus(at, action, duration=table.number("duration", 2.0, positive=True))
        table.only("at", "action", "duration", "pitch", "roll")
        return Stimulus(
            at,
            "tilt",
            duration=table.number("duration", 2.0, positive=True),
            pitch=table.number("pitch", 0.0, low=-90, high=90),
            roll=table.number("roll", 0.0, low=-90, high=90),
        )


def _at(stimulus: Stimulus) -> float:
    return stimulus.at


def _shown(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, dict):
        return "a table"
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "..."


# --- finding worlds by name ---------------------------------------------------------------------

BUILT_IN_WORLDS = Path(__file__).resolve().parent.parent / "worlds"
"""The ready-made worlds shipped inside the package (``arena``, ``line_mat`` ...)."""
WORLD_SUFFIX = ".toml"


def built_in_world_names() -> list[str]:
    return sorted(path.stem for path in BUILT_IN_WORLDS.glob("*" + WORLD_SUFFIX))


def world_names(folder: Path) -> list[str]:
    """Every world a name can reach from a program in ``folder``: its ``worlds/`` folder's, then
    the built-in ones (a name in both is the folder's)."""
    own = sorted(path.stem for path in (folder / "worlds").glob("*" + WORLD_SUFFIX))
    return list(dict.fromkeys(own + built_in_world_names()))


def world_file_named(name: str, folder: Path) -> Path | None:
    """The file a world name stands for: ``folder/worlds/NAME.toml`` first, then the built-in
    world; None when neither exists. ``worlds/NAME.toml`` and ``NAME.toml`` are names too, so
    programs written for the gallery's old ``worlds`` folder find the built-in copies."""
    stem = name.removeprefix("worlds/").removesuffix(WORLD_SUFFIX)
    if not stem or "/" in stem or "\\" in stem or stem.startswith("."):
        return None
    for place in (folder / "worlds", BUILT_IN_WORLDS):
        candidate = place / (stem + WORLD_SUFFIX)
        if candidate.is_file():
            return candidate
        # names are case-insensitive, as in a program (`# world: Arena`), on every system
        same = [
            path for path in place.glob("*" + WORLD_SUFFIX) if path.stem.lower() == stem.lower()
        ]
        if same:
            return sorted(same)[0]
    return None


def world_suggestion(name: str, folder: Path) -> Suggestion | str:
    """A " Did you mean ...?" for a world name no world has (`arean`), or ""."""
    stem = name.removeprefix("worlds/").removesuffix(WORLD_SUFFIX)
    close = did_you_mean(stem, world_names(folder))
    return suggestion(close)


def load_named_world(name: str, folder: Path, shown: Callable[[Path], str] = str) -> World:
    """``--world NAME``: the world of that name (see :func:`world_file_named`), else E306 listing
    the worlds there are; its errors name its file as ``shown`` does."""
    found = world_file_named(name, folder)
    if found is None:
        known = ", ".join(world_names(folder)) or "none"
        suggestion = world_suggestion(name, folder)
        raise RootlangError.of("E306", name=name, known=known, suggestion=suggestion)
    return load_world(found, shown(found))


def load_world_option(option: str, folder: Path, shown: Callable[[Path], str] = str) -> World:
    """``--world W``: a file (anything with a suffix or a folder in it, or that exists), else a
    world's name as :func:`load_named_world` finds it from ``folder``; its errors name its
    file as ``shown`` does (default: as given)."""
    given = Path(option)
    if given.exists() or given.suffix or len(given.parts) > 1:
        return load_world(given, shown(given))  # loading it says if it is missing
    return load_named_world(option, folder, shown)


def _described(expected: str | Phrase) -> Described | Phrase:
    """What a key should be, in words the catalogue translates whole (or a phrase's parts)."""
    return Described(expected) if isinstance(expected, str) else expected
