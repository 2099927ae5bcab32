"""The syntax tree of a Root program: frozen dataclasses, every node with its source ``span``.

The parser (:mod:`rootlang.grammar`) builds these; the checks (:mod:`rootlang.checks`) read them
and record what they learn (the kind of every expression, which variables are shared) in a
:class:`rootlang.checks.CheckedProgram` beside the tree, so the tree itself never changes.

Conventions:

- Names (variables, procedures, parameters, messages compared by the runtime) are stored in
  lower case: the language is case-insensitive.
- Nodes compare and hash by identity (``eq=False``), so a node can key a dict (the checks map
  each expression to its kind) and two equal-looking lines stay two nodes.
- Choices among a few words are plain strings typed with ``Literal`` (``"left"``, ``"right"``).
- Literal values are already run-time values (:data:`rootlang.units.Value`): ``10 cm`` is a
  :class:`Literal` holding ``Quantity(100.0, Kind.LENGTH, "cm")``, ``red`` holds a
  :class:`rootlang.colors.Color`, note names hold a frequency in Hz.
"""

from __future__ import annotations

import enum
from collections.abc import Iterator
from dataclasses import dataclass, fields
from typing import Literal as Choice
from typing import NoReturn, cast

from rootlang.spans import Span
from rootlang.units import Value

Direction = Choice["left", "right"]
BumperSide = Choice["left", "right", "both", "any"]
TouchSensor = Choice["front left", "front right", "back left", "back right", "any"]
ColorZone = Choice["left", "middle", "right", "everywhere", "anywhere"]
LightState = Choice["dark", "bright", "brighter on left", "brighter on right"]
ObstacleSide = Choice["left", "front", "right", "any"]

NESTING_LIMIT = 100
"""The most blocks inside each other in a script or procedure, and the most calculations inside
each other in one line (docs/language.md §5); deeper is E018 at that line. Every pass that walks
the tree by recursion (the checks, ``format``, the blocks, the interpreter's expressions) stays
far inside Python's stack because of it (docs/runtime.md, "Depth")."""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Node:
    """Any node of the tree, with where it is written."""

    span: Span

    def __repr__(self) -> str:
        # As a dataclass prints itself, written once (every node type has repr=False): one
        # generated for each of the node types costs rootlang's start-up about 2%.
        shown = ", ".join(f"{f.name}={getattr(self, f.name)!r}" for f in fields(self) if f.repr)
        return f"{type(self).__qualname__}({shown})"


# ---- expressions ---------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Expression(Node):
    """Anything that gives a value."""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Literal(Expression):
    """A value written out: ``10 cm``, ``4``, ``"hi"``, ``true``, ``red``, ``rgb 1 2 3``,
    ``#ff8000``, ``note C4``. ``value`` is the run-time value (a Quantity, str, bool or Color);
    ``text`` is how it is written in canonical form (``note C4``, not its 261.6 Hz), which
    ``rootlang format`` and the blocks print."""

    value: Value
    text: str = ""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Variable(Expression):
    """A variable or a procedure parameter read by name (lower case)."""

    name: str


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class WithUnit(Expression):
    """A unit after a value that is not a number literal: ``size cm``, ``(a + b) seconds``.
    ``unit`` is the unit word as written (see :func:`rootlang.units.unit_named`)."""

    operand: Expression
    unit: str


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Unary(Expression):
    """``-x`` (op ``"-"``) or ``not x`` (op ``"not"``)."""

    op: Choice["-", "not"]
    operand: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Binary(Expression):
    """Arithmetic, comparison or logic. ``op`` is one of ``+ - * / mod = != < > <= >= and or``
    (``≠ ≤ ≥`` are read as ``!= <= >=``)."""

    op: str
    left: Expression
    right: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class FunctionCall(Expression):
    """A built-in function: ``round``, ``abs``, ``sqrt``, ``sin``, ``cos`` (one argument),
    ``min``, ``max``, ``join`` (two), ``random a to b`` (function ``"random"``, two)."""

    function: str
    arguments: tuple[Expression, ...]


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class ProcedureCall(Expression):
    """A procedure used for its ``return`` value: ``double 3 cm``, ``area(3 cm, 4 cm)``."""

    name: str
    arguments: tuple[Expression, ...]


class SensorKind(str, enum.Enum):
    """Which sensor a :class:`SensorRead` reads. How each is written (its ``where`` words), the
    kind of value it gives and the robot feature it needs: its entry in
    :data:`rootlang.forms.SENSORS`."""

    BUMPER = "bumper"
    TOUCH = "touch"
    COLOR = "color"  # the colour most of that zone's sensors see
    LIGHT = "light"
    BATTERY = "battery"
    POSITION = "position"
    HEADING = "heading"
    TILT = "tilt"  # the acceleration along that axis, in g
    CLIFF = "cliff"
    OBSTACLE = "obstacle"  # the strongest reflection on that side, as a percentage
    TIMER = "timer"  # the time since the program started
    DOCKED = "docked"


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class SensorRead(Expression):
    """The robot's latest reading of a sensor: ``bumper left pressed``, ``color on middle``,
    ``light left``, ``position x``, ``timer``... ``where`` is None for sensors without a side."""

    sensor: SensorKind
    where: str | None


AnyExpression = (
    Literal | Variable | WithUnit | Unary | Binary | FunctionCall | ProcedureCall | SensorRead
)
"""Every kind of expression: a ``match`` on :func:`expression` ending in :func:`assert_never`
is one mypy checks handles them all."""


# ---- events (script headers) ---------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Event(Node):
    """What starts a script (the part after ``when``)."""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Started(Event):
    """``when started``"""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Stopped(Event):
    """``when stopped``: runs last, may light and sound but not move, limited to 2 seconds."""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class BumperEvent(Event):
    """``when bumped`` is ``BumperEvent("any", True)``; ``when bumper left released`` is
    ``BumperEvent("left", False)``."""

    side: BumperSide
    pressed: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class TouchEvent(Event):
    """``when touched`` is ``TouchEvent("any", True)``; ``when touch back left released``..."""

    sensor: TouchSensor
    pressed: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class ColorSeen(Event):
    """``when color red seen [on left|middle|right|everywhere]``; zone ``"anywhere"`` when not
    given. ``color`` is one of the sensor's five colours."""

    color: str
    zone: ColorZone


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class LightEvent(Event):
    """``when light dark|bright|brighter on left|brighter on right``"""

    state: LightState


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class CliffEvent(Event):
    """``when cliff detected`` (True) / ``when cliff cleared`` (False)"""

    detected: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class StalledEvent(Event):
    """``when stalled``"""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class BatteryLowEvent(Event):
    """``when battery low`` (a battery event below 20 %)"""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class ObstacleSeen(Event):
    """``when obstacle seen [on left|front|right]`` (Create 3); side ``"any"`` when not given."""

    side: ObstacleSide


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class DockEvent(Event):
    """``when docked`` (True) / ``when undocked`` (False) (Create 3)"""

    docked: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class MessageReceived(Event):
    """``when message "go" received``; ``message`` is the text as written."""

    message: str


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class ConditionBecomesTrue(Event):
    """``when <condition>``: fires when the condition turns from false to true."""

    condition: Expression


RobotEvent = (
    BumperEvent | TouchEvent | ColorSeen | LightEvent | CliffEvent | StalledEvent
    | BatteryLowEvent | ObstacleSeen | DockEvent
)  # fmt: skip
"""The events a robot's packet starts: each has its packet and feature in ``rootlang.forms.EVENTS``
and its edge test in ``rootlang.runtime.scheduler.edge_test`` (a ``match`` that mypy checks)."""
ProgramEvent = Started | Stopped | MessageReceived | ConditionBecomesTrue
"""The events the program itself starts."""


# ---- statements ----------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Statement(Node):
    """One line of a script or procedure (with its indented block, for block statements)."""


Block = tuple[Statement, ...]


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class FormStatement(Statement):
    """A statement its form describes in full: the checks check each of its values against the
    kind of its form's slot, in the one case for all of them (a new one needs no case there)."""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Move(FormStatement):
    """``move 10 cm`` (direction ``""``), ``move forward 10 cm``, ``move backward 10 cm``
    (the distance is negated at run time)."""

    distance: Expression
    direction: Choice["", "forward", "backward"]

    @property
    def backward(self) -> bool:
        return self.direction == "backward"


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Turn(FormStatement):
    """``turn right 90 degrees``"""

    direction: Direction
    angle: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Arc(FormStatement):
    """``arc right 90 degrees radius 10 cm``"""

    direction: Direction
    angle: Expression
    radius: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class GoTo(FormStatement):
    """``go to x 20 cm y 10 cm [facing 90 degrees]``, in robot coordinates (start at (0, 0)
    facing 90°)."""

    x: Expression
    y: Expression
    facing: Expression | None


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class SetWheels(FormStatement):
    """``set wheels left 5 cm/s right -5 cm/s``; ``set left wheel 5 cm/s`` leaves ``right`` None
    (that wheel keeps its speed), and the other way round."""

    left: Expression | None
    right: Expression | None


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Drive(FormStatement):
    """``drive 5 cm/s``: both wheels at one speed."""

    speed: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class StopMoving(FormStatement):
    """``stop moving``"""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class ResetPosition(FormStatement):
    """``reset position``"""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Dock(FormStatement):
    """``dock`` (docking True) / ``undock`` (False); Create 3."""

    docking: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class SetGravityCompensation(FormStatement):
    """``set gravity compensation on|off|auto [50 %]``"""

    mode: Choice["on", "off", "auto"]
    amount: Expression | None


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Tool(FormStatement):
    """``marker down`` / ``marker up`` / ``eraser down`` / ``eraser up``"""

    tool: Choice["marker", "eraser"]
    down: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Light(FormStatement):
    """``light red`` (mode "on"), ``light off`` (color None), ``light blink green``,
    ``light spin rgb 0 128 255``."""

    mode: Choice["on", "off", "blink", "spin"]
    color: Expression | None


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class PlayNote(FormStatement):
    """``play note C4 for 0.5 seconds`` / ``play 440 Hz for 1 second``"""

    frequency: Expression
    duration: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class PlaySweep(FormStatement):
    """``play sweep from 200 Hz to 800 Hz for 2 seconds [volume 50 %]``"""

    start: Expression
    end: Expression
    duration: Expression
    volume: Expression | None


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Say(Statement):
    """``say "hello"`` (any value; shown as text)"""

    text: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class StopSound(FormStatement):
    """``stop sound``"""


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Wait(FormStatement):
    """``wait 2 seconds``"""

    duration: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class WaitUntil(FormStatement):
    """``wait until <condition>``"""

    condition: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Repeat(FormStatement):
    """``repeat 4 [times]``"""

    count: Expression
    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Forever(FormStatement):
    """``repeat forever`` / ``forever``"""

    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class RepeatUntil(FormStatement):
    """``repeat until <condition>``: checks before each round."""

    condition: Expression
    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class While(FormStatement):
    """``while <condition>``"""

    condition: Expression
    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Branch(Node):
    """One ``if <condition>`` or ``else if <condition>`` with its block."""

    condition: Expression
    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class If(Statement):
    """``if`` / ``else if`` ... / ``else``: the first branch whose condition holds runs, else
    ``otherwise`` (None when there is no ``else``)."""

    branches: tuple[Branch, ...]
    otherwise: Block | None
    else_span: Span | None = None  # the ``else`` line, where its comments belong


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Stop(FormStatement):
    """``stop this script`` / ``stop other scripts`` / ``stop all``"""

    target: Choice["this script", "other scripts", "all"]


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Send(FormStatement):
    """``send "go"`` / ``send "go" and wait``"""

    message: Expression
    wait: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Print(Statement):
    """``print a, b, ...``"""

    values: tuple[Expression, ...]


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class SetVariable(Statement):
    """``set speed to 5 cm/s``"""

    name: str
    value: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class ChangeVariable(Statement):
    """``change count by 1``"""

    name: str
    by: Expression


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class CallProcedure(Statement):
    """``square 10 cm``, ``polygon 6, 5 cm``. The parser also makes one for an unknown command
    (``mve 10 cm``), which the checks then report with a "did you mean"."""

    name: str
    arguments: tuple[Expression, ...]
    name_span: Span


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Return(Statement):
    """``return`` / ``return <value>`` (inside a procedure only)"""

    value: Expression | None


AnyStatement = (
    Move
    | Turn
    | Arc
    | GoTo
    | SetWheels
    | Drive
    | StopMoving
    | ResetPosition
    | Dock
    | SetGravityCompensation
    | Tool
    | Light
    | PlayNote
    | PlaySweep
    | Say
    | StopSound
    | Wait
    | WaitUntil
    | Repeat
    | Forever
    | RepeatUntil
    | While
    | If
    | Stop
    | Send
    | Print
    | SetVariable
    | ChangeVariable
    | CallProcedure
    | Return
)
"""Every kind of statement: a ``match`` on :func:`statement` ending in :func:`assert_never`
is one mypy checks handles them all (a test checks every Statement type is here)."""


def statement(node: Statement) -> AnyStatement:
    """``node`` as the union of the statement types, for a ``match`` mypy checks is complete."""
    return cast("AnyStatement", node)


def expression(node: Expression) -> AnyExpression:
    """``node`` as the union of the expression types, for a ``match`` mypy checks is complete."""
    return cast("AnyExpression", node)


# ---- the program ---------------------------------------------------------------------------


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Script(Node):
    """``when <event>`` and its block. ``span`` covers the header line only."""

    event: Event
    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Parameter(Node):
    """A procedure's parameter, as its header names it (lower case)."""

    name: str


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Procedure(Node):
    """``to name param, param`` and its block. ``span`` covers the header line only."""

    name: str
    parameters: tuple[Parameter, ...]
    body: Block


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Comment(Node):
    """``# text``: ``text`` is what follows the ``#``; ``own_line`` when nothing but spaces comes
    before it on its line (otherwise it ends the line of a statement or header)."""

    text: str
    own_line: bool


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class Program(Node):
    """A whole file: scripts and procedures in source order, and its comments (kept for
    ``rootlang format`` and the blocks; the checks and the runtime ignore them)."""

    scripts: tuple[Script, ...]
    procedures: tuple[Procedure, ...]
    file: str = ""
    comments: tuple[Comment, ...] = ()
    language: str = "en"  # the language its text was read in (the tree itself is English)

    @property
    def items(self) -> tuple[Script | Procedure, ...]:
        """Scripts and procedures together, in the order they are written."""
        return tuple(sorted((*self.scripts, *self.procedures), key=lambda item: item.span))


def assert_never(node: NoReturn) -> NoReturn:
    """The end of a ``match`` on node types: ``mypy --strict`` rejects the call unless every
    type the value may have was matched before it (``typing.assert_never`` is Python 3.11+)."""
    raise AssertionError(f"no case for {type(node).__name__}")


def children(item: Node) -> tuple[Node, ...]:
    """The nodes directly inside ``item`` (for walking the tree), in field order."""
    found: list[Node] = []
    for name in _field_names(type(item)):
        value = getattr(item, name)
        if isinstance(value, Node):  # (most fields: no call to _collect)
            found.append(value)
        elif isinstance(value, tuple):
            _collect(value, found)
    return tuple(found)


def _field_names(node_type: type[Node]) -> tuple[str, ...]:
    """Every field but the spans and comments, looked up once per node type."""
    names = _FIELD_NAMES.get(node_type)
    if names is None:
        names = tuple(field.name for field in fields(node_type) if field.name not in _NOT_CHILDREN)
        _FIELD_NAMES[node_type] = names
    return names


_NOT_CHILDREN = frozenset({"span", "name_span", "else_span", "comments"})
_FIELD_NAMES: dict[type[Node], tuple[str, ...]] = {}


def walk(item: Node) -> Iterator[Node]:
    """``item`` and every node inside it, parents before children, in source order."""
    stack = [item]
    while stack:
        current = stack.pop()
        yield current
        stack.extend(reversed(children(current)))


def calculation_depth(item: Node) -> int:
    """How many calculations are inside each other in ``item`` (an expression, or a line's
    statement or event): a name, number (``5 cm`` too) or sensor 0, ``n - 1`` 1, ``(n - 1) * 2``
    2. Brackets that change nothing are not in the tree, so they don't count. Counted without
    recursion, as the tree may be deeper than Python's stack before it is checked."""
    deepest = 0
    stack = [(item, 0)]
    while stack:
        node, depth = stack.pop()
        if isinstance(node, _CALCULATIONS):
            depth += 1
            deepest = max(deepest, depth)
        stack.extend((child, depth) for child in children(node) if not isinstance(child, Statement))
    return deepest


def _collect(value: object, found: list[Node]) -> None:
    if isinstance(value, Node):
        found.append(value)
    elif isinstance(value, tuple):
        for element in value:
            _collect(element, found)


_CALCULATIONS = (Binary, Unary, WithUnit, FunctionCall, ProcedureCall)


def same_tree(one: Node, other: Node) -> bool:
    """Whether two trees are one program, wherever and however they are written: every field
    but positions, the file and the language the text was in; a comment by its words. The
    printers' net (``format``, the blocks, ``translate``): what they print must read back
    as the tree they printed. Compared without recursion (a tree may be nested deep)."""
    pending: list[tuple[object, object]] = [(one, other)]
    while pending:
        first, second = pending.pop()
        if isinstance(first, Comment) and isinstance(second, Comment):
            if (first.text.strip(), first.own_line) != (second.text.strip(), second.own_line):
                return False
        elif isinstance(first, Node):
            if type(first) is not type(second):
                return False
            pending.extend(
                (getattr(first, name), getattr(second, name))
                for name in _compared_names(type(first))
            )
        elif isinstance(first, tuple):
            if not isinstance(second, tuple) or len(first) != len(second):
                return False
            pending.extend(zip(first, second, strict=True))
        elif type(first) is not type(second) or first != second:
            return False
    return True


def _compared_names(node_type: type[Node]) -> tuple[str, ...]:
    names = _COMPARED_NAMES.get(node_type)
    if names is None:
        names = tuple(
            field.name
            for field in fields(node_type)
            if "Span" not in str(field.type) and field.name not in ("file", "language")
        )
        _COMPARED_NAMES[node_type] = names
    return names


_COMPARED_NAMES: dict[type[Node], tuple[str, ...]] = {}
