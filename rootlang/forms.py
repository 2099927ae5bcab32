"""The one description of the language: every statement, event, expression and sensor, once.

Each :class:`Form` says how one construct is written — a sequence of parts: fixed words, a
choice among a few words, a value slot of a known kind, an indented body — and which Blockly
block shows it. Everything else reads this table instead of keeping its own:

- the grammar's rule for each statement, and how the node is built from what it read, are
  written from the parts when the grammar loads (:mod:`rootlang.grammar.rules`);
- ``rootlang format`` prints statements and events from the parts (:mod:`rootlang.formatting`);
- the block definitions and the toolbox are generated from them, and blocks are read back into
  syntax-tree nodes by them (:mod:`rootlang.blocks`);
- the checks and the runtime take each argument's kind and how its message names it
  (``ARGUMENT_RULES``), which statements move the robot (``MOTION``), and the robot feature
  and packet behind every event and sensor (``EVENTS``, ``SENSORS``).

A syntax-tree type may have several forms (``set wheels left .. right ..``, ``set left wheel
..``): the first form that matches a node is how it is written. A test walks :mod:`rootlang.ast`
and fails for any node type that has no form here (or no special case in the printers).
"""

from __future__ import annotations

import dataclasses
import enum
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any, Generic, TypeVar

from rootlang import ast
from rootlang.colors import NAMED_COLORS, SENSOR_COLORS
from rootlang.units import Kind

__all__ = [
    "ARGUMENT_RULES",
    "EVENTS",
    "EVENT_FORMS",
    "EVENT_WORDS",
    "EXPRESSIONS",
    "MOTION",
    "SENSORS",
    "SPECIAL_NODES",
    "STATEMENT_FORMS",
    "STATEMENT_WORDS",
    "Body",
    "Category",
    "Choice",
    "Form",
    "Sensor",
    "Slot",
    "Text",
    "Word",
    "form_of",
]


class Category(enum.Enum):
    """A toolbox category: its name and colour (each category its own hue, as in Scratch)."""

    EVENTS = ("Events", "#ffab19")
    MOTION = ("Motion", "#4c97ff")
    DRAWING = ("Drawing", "#0fbd8c")
    LIGHTS = ("Lights", "#9966ff")
    SOUND = ("Sound", "#cf63cf")
    CONTROL = ("Control", "#e6a100")
    SENSORS = ("Sensors", "#5cb1d6")
    OPERATORS = ("Operators", "#59c059")
    VARIABLES = ("Variables", "#ff8c1a")
    PROCEDURES = ("Procedures", "#ff6680")
    MESSAGES = ("Messages", "#c2609a")

    @property
    def label(self) -> str:
        return self.value[0]

    @property
    def colour(self) -> str:
        return self.value[1]


# ---- parts of a form ---------------------------------------------------------------------


@dataclass(frozen=True)
class Word:
    """Words written as they are: ``move``, ``radius``, ``play sweep from``. ``terminal``: the
    grammar reads them as that one token of its own (``and wait``, which `and` would otherwise
    begin a condition with)."""

    text: str
    terminal: str = ""


Meaning = TypeVar("Meaning")


@dataclass(frozen=True)
class Choice(Generic[Meaning]):
    """One of a few words, stored in the node's ``field``: ``(node value, words written)``.
    Words may be empty (``anywhere`` in ``when color red seen`` is not written); ``labels``
    override what the block's menu shows for such a choice. ``meanings``: what each value
    stands for on the robot (the colour sensors a zone covers, the light state ...), read by
    the runtime with :meth:`meaning`. ``terminal``: the grammar reads the words as one token
    of that name (its words those of every choice that names it), else each option is a line
    of its own (``dock`` / ``undock``); ``also``: other spellings it reads, and their value
    (``forwards``, ``pen``)."""

    field: str
    options: tuple[tuple[Any, str], ...]
    labels: Mapping[Any, str] = dataclasses.field(default_factory=dict)
    meanings: Mapping[Any, Meaning] = dataclasses.field(default_factory=dict)
    terminal: str = ""
    also: Mapping[str, Any] = dataclasses.field(default_factory=dict)

    def meaning(self, value: Any) -> Meaning:
        return self.meanings[value]

    def value_of_words(self, written: str) -> Any:
        """The value the words read stand for (lower case, single spaces); KeyError if none."""
        for value, words in self.options:
            if words == written:
                return value
        return self.also[written]

    def words(self, value: Any) -> str:
        return next(words for option, words in self.options if option == value)

    def label(self, value: Any) -> str:
        return self.labels.get(value) or self.words(value)

    def value_of_label(self, label: str) -> Any:
        """The node value a block's menu item stands for; KeyError if none."""
        for value, _ in self.options:
            if self.label(value) == label:
                return value
        raise KeyError(label)


@dataclass(frozen=True)
class Slot:
    """A value: the node's expression ``field``, of ``kind`` (None: any value). ``default`` is
    the text of the value a block from the toolbox starts with. ``label`` and ``example`` are
    how a message about a wrong kind names the command and shows it right."""

    field: str
    kind: Kind | None
    default: str
    label: str = ""
    example: str = ""


@dataclass(frozen=True)
class Text:
    """A word or text the child types, stored as a plain string (a message's name)."""

    field: str
    default: str


@dataclass(frozen=True)
class Body:
    """The indented block under a header line."""

    field: str = "body"


Part = Word | Choice[Any] | Slot | Text | Body


@dataclass(frozen=True)
class Form:
    """One way a construct is written, and the block that shows it.

    ``fixed`` gives the node fields this form does not show (``set left wheel`` has
    ``right=None``); a node *matches* when its fixed fields are equal, its choices are among
    the options and its slots are filled."""

    block: str
    node: type[ast.Node]
    category: Category
    parts: tuple[Part, ...]
    fixed: Mapping[str, Any] = dataclasses.field(default_factory=dict)
    tooltip: str = ""
    also: tuple[str, ...] = ()  # other first words the parser takes (`forever` alone)

    def matches(self, node: ast.Node) -> bool:
        if type(node) is not self.node:
            return False
        if any(getattr(node, name) != value for name, value in self.fixed.items()):
            return False
        for part in self.parts:
            if isinstance(part, Choice) and getattr(node, part.field) not in dict(part.options):
                return False
            if isinstance(part, Slot) and getattr(node, part.field) is None:
                return False
        return True

    @property
    def slots(self) -> tuple[Slot, ...]:
        return tuple(part for part in self.parts if isinstance(part, Slot))

    def first_words(self) -> tuple[str, ...]:
        """The words a line in this form can start with (none when it starts with a value)."""
        first = self.parts[0]
        if isinstance(first, Word):
            return (first.text.split()[0], *self.also)
        if isinstance(first, Choice):
            return (*(words.split()[0] for _, words in first.options if words), *self.also)
        return self.also

    def node_fields(self) -> set[str]:
        """Every field of the node this form sets (the rest must be in ``fixed``)."""
        named = {p.field for p in self.parts if not isinstance(p, Word)}
        return named | set(self.fixed)


def _choice(name: str, *words: str, terminal: str = "", **also: Any) -> Choice[Any]:
    return Choice(name, tuple((word, word) for word in words), terminal=terminal, also=also)


def _flag(name: str, yes: str, no: str, terminal: str = "") -> Choice[Any]:
    return Choice(name, ((True, yes), (False, no)), terminal=terminal)


def _meant(
    name: str, meanings: Mapping[str, Meaning], *words: str, terminal: str = ""
) -> Choice[Meaning]:
    """A choice of ``words`` (each written as it is), with what each stands for."""
    return Choice(name, tuple((word, word) for word in words), meanings=meanings,
                  terminal=terminal)  # fmt: skip


_DIRECTION = _choice("direction", "left", "right", terminal="DIRECTION")

# ---- statements --------------------------------------------------------------------------

_DISTANCE = Slot("distance", Kind.LENGTH, "10 cm", "move", "move 10 cm")
_GO_X = Slot("x", Kind.LENGTH, "20 cm", "go to x", "go to x 20 cm y 10 cm")
_GO_Y = Slot("y", Kind.LENGTH, "10 cm", "go to ... y", "go to x 20 cm y 10 cm")
_LEFT_WHEEL = Slot("left", Kind.SPEED, "5 cm/s", "set wheels", "set left wheel 5 cm/s")
_RIGHT_WHEEL = Slot("right", Kind.SPEED, "5 cm/s", "set wheels", "set right wheel 5 cm/s")
_GRAVITY_MODE = _choice("mode", "on", "off", "auto", terminal="GRAVITY_MODE")
_GRAVITY_AMOUNT = Slot(
    "amount", Kind.PERCENT, "50 %", "set gravity compensation", "set gravity compensation on 50 %"
)
_LIGHT_COLOR = Slot("color", Kind.COLOR, "green", "light", "light red")
_SWEEP = (
    Word("play sweep from"),
    Slot("start", Kind.FREQUENCY, "200 Hz", "play sweep from", "from 200 Hz"),
    Word("to"),
    Slot("end", Kind.FREQUENCY, "800 Hz", "play sweep ... to", "to 800 Hz"),
    Word("for"),
    Slot("duration", Kind.TIME, "2 seconds", "play sweep ... for", "for 2 seconds"),
)
_CONDITION = Slot("condition", Kind.BOOLEAN, "bumper any pressed")
# `when bumper any pressed` would read as the event `when bumped`: a condition of its own
_WHEN_CONDITION = Slot("condition", Kind.BOOLEAN, "timer > 5 seconds")
_MESSAGE = Slot("message", Kind.TEXT, '"go"', "send", 'send "go"')
_RETURN_VALUE = Slot("value", None, "0")
_M, _D, _L, _S, _C, _MSG = (
    Category.MOTION,
    Category.DRAWING,
    Category.LIGHTS,
    Category.SOUND,
    Category.CONTROL,
    Category.MESSAGES,
)

STATEMENT_FORMS: tuple[Form, ...] = (
    Form("root_move", ast.Move, _M, (Word("move"), _DISTANCE), {"direction": ""},
         "Drive straight; a negative distance goes backwards."),
    Form("root_move_direction", ast.Move, _M,
         (Word("move"), _choice("direction", "forward", "backward", terminal="MOVE_DIRECTION",
                                forwards="forward", backwards="backward"), _DISTANCE)),
    Form("root_turn", ast.Turn, _M, (Word("turn"), _DIRECTION,
         Slot("angle", Kind.ANGLE, "90 degrees", "turn", "turn right 90 degrees"))),
    Form("root_arc", ast.Arc, _M, (
        Word("arc"), _DIRECTION,
        Slot("angle", Kind.ANGLE, "90 degrees", "arc", "arc right 90 degrees radius 10 cm"),
        Word("radius"),
        Slot("radius", Kind.LENGTH, "10 cm", "arc ... radius", "arc right 90 degrees radius 10 cm"),
    )),
    Form("root_go_to", ast.GoTo, _M, (Word("go to x"), _GO_X, Word("y"), _GO_Y),
         {"facing": None}),
    Form("root_go_to_facing", ast.GoTo, _M, (
        Word("go to x"), _GO_X, Word("y"), _GO_Y, Word("facing"),
        Slot("facing", Kind.ANGLE, "90 degrees", "facing", "facing 90 degrees"),
    )),
    Form("root_set_wheels", ast.SetWheels, _M,
         (Word("set wheels left"), _LEFT_WHEEL, Word("right"), _RIGHT_WHEEL)),
    Form("root_set_left_wheel", ast.SetWheels, _M,
         (Word("set left wheel"), _LEFT_WHEEL), {"right": None}),
    Form("root_set_right_wheel", ast.SetWheels, _M,
         (Word("set right wheel"), _RIGHT_WHEEL), {"left": None}),
    Form("root_drive", ast.Drive, _M,
         (Word("drive"), Slot("speed", Kind.SPEED, "5 cm/s", "drive", "drive 5 cm/s"))),
    Form("root_stop_moving", ast.StopMoving, _M, (Word("stop moving"),)),
    Form("root_reset_position", ast.ResetPosition, _M, (Word("reset position"),)),
    Form("root_dock", ast.Dock, _M, (_flag("docking", "dock", "undock"),),
         tooltip="Create 3: drive onto the dock, or off it."),
    Form("root_gravity", ast.SetGravityCompensation, _M,
         (Word("set gravity compensation"), _GRAVITY_MODE), {"amount": None}),
    Form("root_gravity_amount", ast.SetGravityCompensation, _M,
         (Word("set gravity compensation"), _GRAVITY_MODE, _GRAVITY_AMOUNT)),
    Form("root_tool", ast.Tool, _D,
         (_choice("tool", "marker", "eraser", terminal="TOOL", pen="marker"),
          _flag("down", "down", "up", terminal="TOOL_POSITION"))),
    Form("root_light", ast.Light, _L, (Word("light"), _LIGHT_COLOR), {"mode": "on"}),
    Form("root_light_mode", ast.Light, _L,
         (Word("light"), _choice("mode", "blink", "spin", terminal="LIGHT_MODE", on="on"),
          _LIGHT_COLOR)),
    Form("root_light_off", ast.Light, _L, (Word("light off"),), {"mode": "off", "color": None}),
    Form("root_play", ast.PlayNote, _S, (
        Word("play"),
        Slot("frequency", Kind.FREQUENCY, "note C4", "play", "play note C4 for 1 second"),
        Word("for"),
        Slot("duration", Kind.TIME, "0.5 seconds", "play ... for", "play 440 Hz for 1 second"),
    )),
    Form("root_play_sweep", ast.PlaySweep, _S, _SWEEP, {"volume": None}),
    Form("root_play_sweep_volume", ast.PlaySweep, _S, (
        *_SWEEP, Word("volume"),
        Slot("volume", Kind.PERCENT, "50 %", "volume", "volume 50 %"),
    )),
    Form("root_say", ast.Say, _S, (Word("say"), Slot("text", None, '"hello"'))),
    Form("root_stop_sound", ast.StopSound, _S, (Word("stop sound"),)),
    Form("root_wait", ast.Wait, _C,
         (Word("wait"), Slot("duration", Kind.TIME, "1 second", "wait", "wait 2 seconds"))),
    Form("root_wait_until", ast.WaitUntil, _C, (Word("wait until"), _CONDITION)),
    Form("root_repeat", ast.Repeat, _C,
         (Word("repeat"), Slot("count", Kind.NUMBER, "4", "repeat", "repeat 4"), Body())),
    Form("root_forever", ast.Forever, _C, (Word("repeat forever"), Body()), also=("forever",)),
    Form("root_repeat_until", ast.RepeatUntil, _C, (Word("repeat until"), _CONDITION, Body())),
    Form("root_while", ast.While, _C, (Word("while"), _CONDITION, Body())),
    Form("root_stop", ast.Stop, _C,
         (Word("stop"), _choice("target", "this script", "other scripts", "all",
                                terminal="STOP_TARGET"))),
    Form("root_send", ast.Send, _MSG, (Word("send"), _MESSAGE), {"wait": False}),
    Form("root_send_and_wait", ast.Send, _MSG,
         (Word("send"), _MESSAGE, Word("and wait", terminal="AND_WAIT")),
         {"wait": True}),
    Form("root_return", ast.Return, Category.PROCEDURES, (Word("return"),), {"value": None}),
    Form("root_return_value", ast.Return, Category.PROCEDURES, (Word("return"), _RETURN_VALUE)),
)  # fmt: skip
"""Every statement but the few the printers handle themselves (see ``SPECIAL_NODES``)."""

SPECIAL_NODES: dict[type[ast.Node], tuple[str, ...]] = {
    ast.If: ("if", "else"),  # if / else if / else: Blockly's own `controls_if` block
    ast.Print: ("print",),  # any number of values
    ast.SetVariable: ("set",),  # Blockly's variable blocks
    ast.ChangeVariable: ("change",),
    ast.CallProcedure: (),  # one block per procedure, any number of values
    ast.Branch: (),  # part of If
    ast.Script: (),
    ast.Procedure: (),
    ast.Parameter: (),
    ast.Program: (),
    ast.Comment: (),
}
"""Node types written by code rather than by a form (each named where it is handled), with
the words a statement of that type starts with."""

EXPRESSIONS: tuple[type[ast.Expression], ...] = (
    ast.Literal, ast.Variable, ast.WithUnit, ast.Unary, ast.Binary, ast.FunctionCall,
    ast.ProcedureCall, ast.SensorRead,
)  # fmt: skip
"""Values: printed with the brackets they need by ``rootlang.formatting.expression_text``, and
made into value blocks by ``rootlang.blocks`` (sensors from their forms in ``SENSORS``)."""

# ---- events ------------------------------------------------------------------------------

# What the choices of events and sensors stand for on the robot: the protocol's names for the
# touch sensors and light states (the protocol's enums load only with the runtime), the colour
# sensor's 32 sensors (left to right) and the 7 IR sensors (left to right) each side covers.
_TOUCH_SENSORS: dict[str, tuple[str, ...]] = {
    "front left": ("FRONT_LEFT",),
    "front right": ("FRONT_RIGHT",),
    "back left": ("REAR_LEFT",),
    "back right": ("REAR_RIGHT",),
    "any": ("FRONT_LEFT", "FRONT_RIGHT", "REAR_LEFT", "REAR_RIGHT"),
}
_COLOR_ZONES = {
    "anywhere": range(0, 32),
    "left": range(0, 10),
    "middle": range(10, 22),
    "right": range(22, 32),
    "everywhere": range(0, 32),
}
_OBSTACLE_SIDES = {"any": range(0, 7), "left": range(0, 2), "front": range(2, 5),
                   "right": range(5, 7)}  # fmt: skip
_LIGHT_STATES = {
    "dark": "BOTH_DARK",
    "bright": "BOTH_BRIGHT",
    "brighter on left": "LEFT_BRIGHTER",
    "brighter on right": "RIGHT_BRIGHTER",
}

TOUCH_SENSOR: Choice[tuple[str, ...]] = _meant(
    "sensor", _TOUCH_SENSORS, *_TOUCH_SENSORS, terminal="TOUCH_SENSOR"
)
"""Which touch sensor: its meaning, the ``TouchSensors`` bits it stands for (by name)."""
COLOR_ZONE: Choice[range] = Choice(
    "zone", tuple((zone, f"on {zone}" if zone != "anywhere" else "") for zone in _COLOR_ZONES),
    {"anywhere": "anywhere"}, _COLOR_ZONES,
)  # fmt: skip
"""Where ``when color ... seen`` looks: its meaning, the colour sensors it covers."""
OBSTACLE_SIDE: Choice[range] = Choice(
    "side", tuple((side, f"on {side}" if side != "any" else "") for side in _OBSTACLE_SIDES),
    {"any": "anywhere"}, _OBSTACLE_SIDES,
)  # fmt: skip
"""Where ``when obstacle seen`` looks: its meaning, the IR sensors it covers."""
LIGHT_STATE: Choice[str] = _meant("state", _LIGHT_STATES, *_LIGHT_STATES, terminal="LIGHT_STATE")
"""``when light ...``: its meaning, the ``LightState`` it stands for (by name)."""

_PRESSED = _flag("pressed", "pressed", "released")
_ANY_COLOR = tuple((name, name) for name in (*SENSOR_COLORS, *NAMED_COLORS))
_E = Category.EVENTS

EVENT_FORMS: tuple[Form, ...] = (
    Form("root_when_started", ast.Started, _E, (Word("started"),)),
    Form("root_when_stopped", ast.Stopped, _E, (Word("stopped"),),
         tooltip="Runs when the program is stopped; may light and sound, not move (2 seconds)."),
    Form("root_when_bumped", ast.BumperEvent, _E, (Word("bumped"),),
         {"side": "any", "pressed": True}),
    Form("root_when_bumper", ast.BumperEvent, _E,
         (Word("bumper"), _choice("side", "left", "right", "both", "any", terminal="BUMPER_SIDE"),
          _PRESSED)),
    Form("root_when_touched", ast.TouchEvent, _E, (Word("touched"),),
         {"sensor": "any", "pressed": True}),
    Form("root_when_touch", ast.TouchEvent, _E, (Word("touch"), TOUCH_SENSOR, _PRESSED)),
    Form("root_when_color", ast.ColorSeen, _E, (
        Word("color"), Choice("color", tuple(dict(_ANY_COLOR).items()), terminal="color_name"),
        Word("seen"),
        COLOR_ZONE,
    )),
    Form("root_when_light", ast.LightEvent, _E, (Word("light"), LIGHT_STATE)),
    Form("root_when_cliff", ast.CliffEvent, _E, (Word("cliff"), _flag("detected", "detected",
                                                                      "cleared"))),
    Form("root_when_stalled", ast.StalledEvent, _E, (Word("stalled"),)),
    Form("root_when_battery_low", ast.BatteryLowEvent, _E, (Word("battery low"),)),
    Form("root_when_obstacle", ast.ObstacleSeen, _E, (Word("obstacle seen"), OBSTACLE_SIDE)),
    Form("root_when_docked", ast.DockEvent, _E, (_flag("docked", "docked", "undocked"),)),
    Form("root_when_message", ast.MessageReceived, Category.MESSAGES,
         (Word("message"), Text("message", "go"), Word("received"))),
    Form("root_when_condition", ast.ConditionBecomesTrue, _E, (_WHEN_CONDITION,),
         tooltip="Runs each time the condition turns from false to true."),
)  # fmt: skip
"""How each event is written after ``when``; each is a hat block."""


@dataclass(frozen=True)
class EventSource:
    """Where a robot event comes from: the robot ``feature`` it needs (as the checks name it,
    see ``rootlang.checks.FEATURES``) and the ``packet`` that carries it."""

    feature: str
    packet: str


EVENTS: dict[type[ast.RobotEvent], EventSource] = {
    ast.BumperEvent: EventSource("bumpers", "bumper_event"),
    ast.TouchEvent: EventSource("touch sensors", "touch_sensor_event"),
    ast.ColorSeen: EventSource("colour sensor", "color_sensor_event"),
    ast.LightEvent: EventSource("light sensors", "light_event"),
    ast.CliffEvent: EventSource("cliff sensor", "cliff_event"),
    ast.StalledEvent: EventSource("stall sensing", "motor_stall_event"),
    ast.BatteryLowEvent: EventSource("battery sensor", "battery_level_event"),
    ast.ObstacleSeen: EventSource("obstacle sensors", "ir_proximity_event"),
    ast.DockEvent: EventSource("dock", "docking_sensor_event"),
}
"""The events the robot sends; the others (started, stopped, message, condition) are the
program's own."""

# ---- sensors -----------------------------------------------------------------------------


@dataclass(frozen=True)
class Sensor:
    """A sensor reading: the kind of value it gives, how it is written (``where`` is its
    choice of side), the robot ``feature`` it needs and the ``packet`` that tells it (None:
    every robot has it, or the host keeps it)."""

    sensor: ast.SensorKind
    kind: Kind
    form: Form
    feature: str | None = None
    packet: str | None = None


def _sensor(
    sensor: ast.SensorKind,
    kind: Kind,
    parts: tuple[Part, ...],
    feature: str | None = None,
    packet: str | None = None,
) -> Sensor:
    form = Form(f"root_sensor_{sensor.value}", ast.SensorRead, Category.SENSORS, parts,
                {"sensor": sensor} if any(isinstance(p, Choice) for p in parts)
                else {"sensor": sensor, "where": None})  # fmt: skip
    return Sensor(sensor, kind, form, feature, packet)


_K = ast.SensorKind
SENSORS: dict[ast.SensorKind, Sensor] = {
    sensor.sensor: sensor
    for sensor in (
        _sensor(_K.BUMPER, Kind.BOOLEAN, (Word("bumper"), _choice("where", "left", "right",
                "both", "any", terminal="BUMPER_SIDE"), Word("pressed")),
                "bumpers", "bumper_event"),
        _sensor(_K.TOUCH, Kind.BOOLEAN, (Word("touch"), _meant("where", _TOUCH_SENSORS,
                *_TOUCH_SENSORS, terminal="TOUCH_SENSOR"), Word("pressed")), "touch sensors",
                "touch_sensor_event"),
        _sensor(_K.COLOR, Kind.COLOR, (Word("color on"),
                _meant("where", _COLOR_ZONES, "left", "middle", "right", "everywhere",
                       terminal="COLOR_ZONE")),
                "colour sensor", "color_sensor_event"),
        _sensor(_K.LIGHT, Kind.PERCENT, (Word("light"), _choice("where", "left", "right",
                                                                terminal="DIRECTION")),
                "light sensors", "get_light_values"),
        _sensor(_K.BATTERY, Kind.PERCENT, (Word("battery"),), "battery sensor",
                "get_battery_level"),
        _sensor(_K.POSITION, Kind.LENGTH, (Word("position"), _choice("where", "x", "y",
                                                                     terminal="AXIS"))),
        _sensor(_K.HEADING, Kind.ANGLE, (Word("heading"),)),
        _sensor(_K.TILT, Kind.NUMBER, (Word("tilt"), _choice("where", "x", "y", "z",
                                                             terminal="AXIS")),
                "accelerometer", "get_accelerometer"),
        _sensor(_K.CLIFF, Kind.BOOLEAN, (Word("cliff"),), "cliff sensor", "cliff_event"),
        _sensor(_K.OBSTACLE, Kind.PERCENT, (Word("obstacle"),
                _meant("where", _OBSTACLE_SIDES, "left", "front", "right",
                       terminal="OBSTACLE_SIDE")),
                "obstacle sensors", "get_packed_ir_proximity"),
        _sensor(_K.TIMER, Kind.TIME, (Word("timer"),)),
        _sensor(_K.DOCKED, Kind.BOOLEAN, (Word("docked"),), "dock", "docking_sensor_event"),
    )
}  # fmt: skip

# ---- what the checks and the runtime read ------------------------------------------------

ARGUMENT_RULES: dict[tuple[type[ast.Node], str], tuple[Kind, str, str]] = {
    (form.node, slot.field): (slot.kind, slot.label, slot.example)
    for form in STATEMENT_FORMS
    for slot in form.slots
    if slot.kind is not None and slot.kind is not Kind.BOOLEAN
}
"""(statement type, field) -> (the kind it needs, how a message names the command, an
example): what a wrong kind of value is told, at check time and at run time alike."""

MOTION: tuple[type[ast.Statement], ...] = (
    ast.Move, ast.Turn, ast.Arc, ast.GoTo, ast.SetWheels, ast.Drive, ast.Dock,
)  # fmt: skip
"""Statements that move the robot (not allowed in ``when stopped``)."""


STATEMENT_WORDS: frozenset[str] = frozenset(
    word
    for words in (*(form.first_words() for form in STATEMENT_FORMS), *SPECIAL_NODES.values())
    for word in words
)
"""Every word a statement can start with (what an unknown command may have meant)."""
EVENT_WORDS: frozenset[str] = frozenset(word for form in EVENT_FORMS for word in form.first_words())
"""Every word an event can start with, after ``when``."""


def form_of(node: ast.Node) -> Form:
    """The form a node is written in (the first that matches); KeyError if it has none."""
    for form in _FORMS_BY_NODE.get(type(node), ()):
        if form.matches(node):
            return form
    raise KeyError(type(node).__name__)


def _forms_by_node() -> dict[type[ast.Node], tuple[Form, ...]]:
    table: dict[type[ast.Node], list[Form]] = {}
    sensors = tuple(sensor.form for sensor in SENSORS.values())
    for form in (*STATEMENT_FORMS, *EVENT_FORMS, *sensors):
        table.setdefault(form.node, []).append(form)
    return {node: tuple(forms) for node, forms in table.items()}


_FORMS_BY_NODE = _forms_by_node()
