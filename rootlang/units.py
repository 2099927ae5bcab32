"""Values, units and the arithmetic that keeps units honest.

This is the ONE implementation of the unit rules. The checks apply them to *kinds* before a
program runs (``binary_kind``, ``unary_kind``, ``function_kind``, ``with_unit_kind``); the
runtime applies the very same rules to *values* (``apply_binary``, ``apply_unary``,
``apply_function``, ``apply_unit``), which call the kind rules first. Both report a broken
rule as a :class:`UnitError` carrying a catalogue code and the message values, so a mistake
found at run time reads exactly like one found by ``rootlang check``.

Every quantity is stored in a canonical unit — mm, degrees, seconds, mm/s, Hz, percent — and
remembers the unit it was written in for display: ``10 cm + 5 mm`` is 105 mm shown as
``10.5 cm``.
"""

from __future__ import annotations

import enum
import math
import operator
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from rootlang.colors import Color
from rootlang.wording.shown import Code, Described, InUnit, Phrase


class Kind(enum.Enum):
    """What sort of value something is. The first seven are quantities (numbers with a unit)."""

    NUMBER = "number"
    LENGTH = "length"
    ANGLE = "angle"
    TIME = "time"
    SPEED = "speed"
    FREQUENCY = "frequency"
    PERCENT = "percent"
    TEXT = "text"
    BOOLEAN = "boolean"
    COLOR = "colour"

    @property
    def is_quantity(self) -> bool:
        return self not in (Kind.TEXT, Kind.BOOLEAN, Kind.COLOR)

    @property
    def described(self) -> Described:
        """How a message names this kind: "a distance", "a plain number"."""
        return Described(_DESCRIPTIONS[self])

    @property
    def example(self) -> str:
        """A value of this kind as a student would write it."""
        return _EXAMPLES[self]

    @property
    def canonical_unit(self) -> str:
        return _CANONICAL[self]


_DESCRIPTIONS = {
    Kind.NUMBER: "a plain number",
    Kind.LENGTH: "a distance",
    Kind.ANGLE: "an angle",
    Kind.TIME: "a time",
    Kind.SPEED: "a speed",
    Kind.FREQUENCY: "a frequency",
    Kind.PERCENT: "a percentage",
    Kind.TEXT: "text",
    Kind.BOOLEAN: "true or false",
    Kind.COLOR: "a colour",
}
A_NUMBER = Described("a number")  # a number with or without a unit
_EXAMPLES = {
    Kind.NUMBER: "4",
    Kind.LENGTH: "10 cm",
    Kind.ANGLE: "90 degrees",
    Kind.TIME: "2 seconds",
    Kind.SPEED: "5 cm/s",
    Kind.FREQUENCY: "440 Hz",
    Kind.PERCENT: "50 %",
    Kind.TEXT: '"hello"',
    Kind.BOOLEAN: "true",
    Kind.COLOR: "red",
}
_CANONICAL = {
    Kind.NUMBER: "",
    Kind.LENGTH: "mm",
    Kind.ANGLE: "degrees",
    Kind.TIME: "seconds",
    Kind.SPEED: "mm/s",
    Kind.FREQUENCY: "Hz",
    Kind.PERCENT: "%",
    Kind.TEXT: "",
    Kind.BOOLEAN: "",
    Kind.COLOR: "",
}


@dataclass(frozen=True)
class Unit:
    """A unit word: its kind and how many canonical units one of it is."""

    name: str
    kind: Kind
    factor: float


def _units() -> dict[str, Unit]:
    table = {
        "mm": (Kind.LENGTH, 1.0),
        "cm": (Kind.LENGTH, 10.0),
        "m": (Kind.LENGTH, 1000.0),
        "inch": (Kind.LENGTH, 25.4),
        "inches": (Kind.LENGTH, 25.4),
        "degrees": (Kind.ANGLE, 1.0),
        "degree": (Kind.ANGLE, 1.0),
        "deg": (Kind.ANGLE, 1.0),
        "°": (Kind.ANGLE, 1.0),
        "seconds": (Kind.TIME, 1.0),
        "second": (Kind.TIME, 1.0),
        "sec": (Kind.TIME, 1.0),
        "s": (Kind.TIME, 1.0),
        "ms": (Kind.TIME, 0.001),
        "cm/s": (Kind.SPEED, 10.0),
        "mm/s": (Kind.SPEED, 1.0),
        "Hz": (Kind.FREQUENCY, 1.0),
        "%": (Kind.PERCENT, 1.0),
    }
    return {name.lower(): Unit(name, kind, factor) for name, (kind, factor) in table.items()}


UNITS: dict[str, Unit] = _units()
"""Every unit word a program may write, keyed in lower case (units are case-insensitive)."""


def unit_named(word: str) -> Unit:
    """The unit for a word as written (``CM``, ``Hz``, ``cm / s``); KeyError if unknown."""
    return UNITS["".join(word.split()).lower()]


_NOTE_STEPS = {"c": -9, "d": -7, "e": -5, "f": -4, "g": -2, "a": 0, "b": 2}


def note_frequency(name: str) -> float:
    """Hz of a note name such as ``C4``, ``F#5``, ``Bb3`` (A4 = 440 Hz, equal temperament)."""
    letter, rest = name[0].lower(), name[1:]
    step = _NOTE_STEPS[letter]
    if rest[:1] == "#":
        step, rest = step + 1, rest[1:]
    elif rest[:1] in ("b", "B") and len(rest) > 1:
        step, rest = step - 1, rest[1:]
    octave = int(rest)
    return float(440.0 * 2.0 ** ((step + 12 * (octave - 4)) / 12))


_NOTE_NAMES = ("C", "C#", "D", "D#", "E", "F", "F#", "G", "G#", "A", "A#", "B")


def note_name(frequency_hz: float) -> str:
    """The note a frequency plays, ``C4`` for 262 Hz (the nearest semitone, when within a
    quarter of one), else the frequency: ``300 Hz``."""
    if frequency_hz <= 0:
        return f"{frequency_hz:g} Hz"
    semitones = 12 * math.log2(frequency_hz / 440.0) + 9 + 12 * 4  # from C0
    nearest = round(semitones)
    if abs(semitones - nearest) > 0.25:
        return f"{frequency_hz:g} Hz"
    octave, step = divmod(nearest, 12)
    return f"{_NOTE_NAMES[step]}{octave}"


def format_number(value: float) -> str:
    """Numbers the way a person writes them: ``10``, ``10.5``, ``0.333``."""
    if math.isfinite(value) and value == int(value) and abs(value) < 1e15:
        return str(int(value))
    return f"{value:.4g}" if abs(value) >= 1e-3 or value == 0 else f"{value:.3g}"


@dataclass(frozen=True)
class Quantity:
    """A number with a unit: ``value`` in the kind's canonical unit, ``unit`` for display."""

    value: float
    kind: Kind = Kind.NUMBER
    unit: str = ""

    @classmethod
    def of(cls, number: float, unit_word: str | None = None) -> Quantity:
        """``Quantity.of(10, "cm")`` is 100 mm shown in cm; no unit word: a plain number."""
        if unit_word is None:
            return cls(float(number))
        unit = unit_named(unit_word)
        return cls(float(number) * unit.factor, unit.kind, unit.name)

    @classmethod
    def number(cls, value: float) -> Quantity:
        return cls(float(value))

    @property
    def shown(self) -> float:
        """The value in the unit it is displayed in."""
        if not self.unit:
            return self.value
        return self.value / unit_named(self.unit).factor

    def with_value(self, value: float) -> Quantity:
        return Quantity(value, self.kind, self.unit)

    def with_shown(self, shown: float) -> Quantity:
        """The same kind and display unit, ``shown`` in that unit (``round`` keeps 10 cm)."""
        factor = unit_named(self.unit).factor if self.unit else 1.0
        return Quantity(float(shown) * factor, self.kind, self.unit)

    def __str__(self) -> str:
        shown = self.shown
        number = format_number(shown)
        if not self.unit:
            return number
        word = _SINGULAR.get(self.unit, self.unit)
        if abs(shown) != 1:
            word = _PLURAL.get(word, word)
        return f"{number}{word}" if word in _UNSPACED else f"{number} {word}"


_PLURAL = {"second": "seconds", "degree": "degrees", "inch": "inches"}
_SINGULAR = {plural: singular for singular, plural in _PLURAL.items()}
_UNSPACED = {"%", "°"}
"""Units shown right after the number, as people write them: 50%, 90°."""


Value = Quantity | str | bool | Color
"""A run-time value: a quantity (plain numbers too), text, true/false or a colour."""


class UnitError(Exception):
    """A broken unit rule: ``code`` and ``values`` fill a catalogue message; the caller adds
    the span."""

    def __init__(self, code: str, **values: object) -> None:
        super().__init__(code, values)
        self.code = code
        self.values = values


def kind_of(value: Value) -> Kind:
    if isinstance(value, bool):
        return Kind.BOOLEAN
    if isinstance(value, str):
        return Kind.TEXT
    if isinstance(value, Color):
        return Kind.COLOR
    return value.kind


def describe(kind: Kind, unit: str = "") -> InUnit | Described:
    """ "a distance in cm" when the unit is known, else "a distance"."""
    if unit and kind.is_quantity and kind is not Kind.NUMBER:
        return InUnit(kind.described, unit)
    return kind.described


# ---- the rules, on kinds ----------------------------------------------------------------------


class Binding(enum.IntEnum):
    """How tightly an operator holds its sides, loosest first: the grammar's levels
    (``root.lark``'s ``or_expr`` ... ``product``), which ``rootlang format`` brackets by."""

    OR = 1
    AND = 2
    COMPARE = 4  # (3 is `not`'s level)
    SUM = 5
    PRODUCT = 6


class Rule(enum.Enum):
    """What an operator does with its sides' kinds (:func:`binary_kind`)."""

    LOGIC = "logic"  # true or false on both sides
    EQUALITY = "equality"  # two values of one kind
    ORDERING = "ordering"  # two quantities of one kind
    SAME = "same"  # two quantities of one kind, giving that kind (`+`, `-`, `mod`)
    PRODUCT = "product"  # a number times a quantity, a speed times a time
    QUOTIENT = "quotient"  # a quantity by a number, by one of its kind, a distance by a time


@dataclass(frozen=True)
class Operator:
    """One operator between two values, as every part of rootlang reads it: the grammar (its
    token, its other spellings), the syntax tree (``written``), ``rootlang format`` (how
    tightly it binds), the blocks (its block's menu), the unit rules and the runtime (its
    rule, how it computes) and the messages (what it tried: "I can't add ...")."""

    written: str  # as a program is printed and the syntax tree holds it
    binds: Binding
    rule: Rule
    action: Described | Phrase  # "I can't {action} a distance and a time."
    compute: Callable[[Any, Any], Any]  # on the two values (on the numbers of two quantities)
    token: str = ""  # the grammar's token for it ("": a keyword of root.lark's rules)
    also: tuple[str, ...] = ()  # other spellings read as it: `×`, `==`, `≤`
    shown: str = ""  # as the blocks' menu shows it, if not as written


_COMPARE = Described("compare")
OPERATORS: dict[str, Operator] = {
    op.written: op
    for op in (
        Operator("+", Binding.SUM, Rule.SAME, Described("add"), operator.add, "ADD_OP"),
        Operator("-", Binding.SUM, Rule.SAME, Described("subtract"), operator.sub, "MINUS"),
        Operator("*", Binding.PRODUCT, Rule.PRODUCT, Described("multiply"), operator.mul,
                 "MUL_OP", also=("×",)),
        Operator("/", Binding.PRODUCT, Rule.QUOTIENT, Described("divide"), operator.truediv,
                 "MUL_OP", also=("÷",)),
        # `mod` as Scratch does it: the remainder takes the sign of the divisor (-7 mod 3 = 2)
        Operator("mod", Binding.PRODUCT, Rule.SAME, Described("take the remainder of"),
                 operator.mod, "MUL_OP"),
        Operator("=", Binding.COMPARE, Rule.EQUALITY, _COMPARE,
                 lambda left, right: _equal(left, right), "COMPARE", also=("==",)),
        Operator("!=", Binding.COMPARE, Rule.EQUALITY, _COMPARE,
                 lambda left, right: not _equal(left, right), "COMPARE", also=("<>", "≠"),
                 shown="≠"),
        Operator("<", Binding.COMPARE, Rule.ORDERING, _COMPARE, operator.lt, "COMPARE"),
        Operator(">", Binding.COMPARE, Rule.ORDERING, _COMPARE, operator.gt, "COMPARE"),
        Operator("<=", Binding.COMPARE, Rule.ORDERING, _COMPARE, operator.le, "COMPARE",
                 also=("≤",), shown="≤"),
        Operator(">=", Binding.COMPARE, Rule.ORDERING, _COMPARE, operator.ge, "COMPARE",
                 also=("≥",), shown="≥"),
        Operator("and", Binding.AND, Rule.LOGIC, Phrase(("combine with ", Code("and"))),
                 lambda left, right: bool(left) and bool(right)),
        Operator("or", Binding.OR, Rule.LOGIC, Phrase(("combine with ", Code("or"))),
                 lambda left, right: bool(left) or bool(right)),
    )
}  # fmt: skip
"""Every operator between two values, the one description all readers take it from."""


def _operators(*rules: Rule) -> tuple[str, ...]:
    return tuple(op for op, described in OPERATORS.items() if described.rule in rules)


ARITHMETIC = _operators(Rule.SAME, Rule.PRODUCT, Rule.QUOTIENT)
ORDERING = _operators(Rule.ORDERING)
EQUALITY = _operators(Rule.EQUALITY)
LOGIC = _operators(Rule.LOGIC)
_PRODUCTS = {
    (Kind.SPEED, Kind.TIME): Kind.LENGTH,
    (Kind.TIME, Kind.SPEED): Kind.LENGTH,
}
_QUOTIENTS = {
    (Kind.LENGTH, Kind.TIME): Kind.SPEED,
    (Kind.LENGTH, Kind.SPEED): Kind.TIME,
}


def binary_kind(
    op: str, left: Kind, right: Kind, left_unit: str = "", right_unit: str = ""
) -> Kind:
    """The kind of ``left op right``, or UnitError (E110) naming both sides."""
    result = _binary_result(op, left, right)
    if result is None:
        raise UnitError(
            "E110",
            action=OPERATORS[op].action,
            left=describe(left, left_unit),
            right=describe(right, right_unit),
        )
    return result


def _binary_result(op: str, left: Kind, right: Kind) -> Kind | None:
    rule = OPERATORS[op].rule
    if rule is Rule.LOGIC:
        return Kind.BOOLEAN if left is right is Kind.BOOLEAN else None
    if rule is Rule.EQUALITY:
        return Kind.BOOLEAN if left is right else None
    if not (left.is_quantity and right.is_quantity):
        return None
    if rule is Rule.ORDERING:
        return Kind.BOOLEAN if left is right else None
    if rule is Rule.SAME:
        return left if left is right else None
    if rule is Rule.PRODUCT:
        if left is Kind.NUMBER or right is Kind.NUMBER:
            return right if left is Kind.NUMBER else left
        return _PRODUCTS.get((left, right))
    # a quotient
    if right is Kind.NUMBER:
        return left
    if left is right:
        return Kind.NUMBER
    return _QUOTIENTS.get((left, right))


def unary_kind(op: str, operand: Kind) -> Kind:
    """``-x`` keeps the kind of a quantity; ``not x`` needs true or false."""
    if op == "not":
        if operand is not Kind.BOOLEAN:
            raise UnitError(
                "E113",
                function=Code("not", quoted=False),
                wanted=Kind.BOOLEAN.described,
                actual=operand.described,
            )
        return Kind.BOOLEAN
    if not operand.is_quantity:
        raise UnitError(
            "E113", function=Code("-", quoted=False), wanted=A_NUMBER, actual=operand.described
        )
    return operand


def rgb_channel_kind(actual: Kind) -> Kind:
    """A channel of ``rgb r g b`` must be a plain number (E109)."""
    expect_kind("rgb", "rgb 255 128 0", Kind.NUMBER, actual)
    return actual


def rgb_color(red: float, green: float, blue: float) -> Color:
    """The colour ``rgb red green blue``: each channel rounded and kept within 0 to 255."""
    red_, green_, blue_ = (max(0, min(255, round(channel))) for channel in (red, green, blue))
    return Color(red_, green_, blue_)


class Written(enum.Enum):
    """How a built-in function is written."""

    ONE_VALUE = "one value"  # `round x`: the grammar's FUNCTION1, the blocks' function block
    BRACKETS = "brackets"  # `min(a, b)`: the grammar's FUNCTION2
    OWN_RULE = "own rule"  # `random a to b`, `rgb r g b`: a grammar rule and a block of its own


KindRule = Callable[[str, Sequence[Kind]], Kind]
"""A function's units rule: the kind it gives for values of these kinds, or UnitError."""
Implementation = Callable[[Sequence[Value]], Value]
"""What a function does to values that passed its units rule."""


@dataclass(frozen=True)
class Function:
    """A built-in function, all of it: how many values it takes (``more``: at least that many),
    how it is written, its units rule, what it does (None: the runtime's own, ``random`` draws
    from the run's seeded source) and its name in Dutch, Spanish, French and German (empty:
    written as in English), which ``rootlang.locale.keywords`` adds to its table."""

    name: str
    values: int
    written: Written
    kind: KindRule
    apply: Implementation | None
    words: tuple[str, str, str, str] = ("", "", "", "")
    more: bool = False  # takes more values than ``values`` too

    def takes(self, count: int) -> bool:
        """Whether the function takes ``count`` values."""
        return count == self.values or (self.more and count > self.values)


def _text_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    return Kind.TEXT


def _rgb_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    for kind in arguments:
        rgb_channel_kind(kind)
    return Kind.COLOR


def _angle_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    _require(function, arguments[0], Kind.ANGLE)
    return Kind.NUMBER


def _number_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    _require(function, arguments[0], Kind.NUMBER)
    return Kind.NUMBER


def _quantity_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    """A number with or without a unit, given back with its kind."""
    first = arguments[0]
    if not first.is_quantity:
        raise UnitError(
            "E113", function=Code(function, quoted=False), wanted=A_NUMBER, actual=first.described
        )
    return first


def _same_quantities_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    """Two numbers of one kind (`min 3 cm, 2 seconds` makes no sense)."""
    first = _quantity_kind(function, arguments)
    second = arguments[1]
    if second is not first:
        raise UnitError(
            "E110",
            action=Phrase(("use ", Code(function), " on")),
            left=first.described,
            right=second.described,
        )
    return first


def _require(function: str, actual: Kind, wanted: Kind) -> None:
    if actual is not wanted:
        raise UnitError(
            "E113",
            function=Code(function, quoted=False),
            wanted=wanted.described,
            actual=actual.described,
        )


def _quantities(arguments: Sequence[Value]) -> list[Quantity]:
    found = [argument for argument in arguments if isinstance(argument, Quantity)]
    assert len(found) == len(arguments)  # the units rule passed
    return found


def _join(arguments: Sequence[Value]) -> Value:
    return "".join(show(argument) for argument in arguments)


def _rgb(arguments: Sequence[Value]) -> Value:
    red, green, blue = (channel.value for channel in _quantities(arguments))
    return rgb_color(red, green, blue)


def _trigonometry(of: Callable[[float], float]) -> Implementation:
    return lambda arguments: Quantity.number(of(math.radians(_quantities(arguments)[0].value)))


def _sqrt(arguments: Sequence[Value]) -> Value:
    (first,) = _quantities(arguments)
    if first.value < 0:
        raise UnitError("E115", value=str(first))
    return Quantity.number(math.sqrt(first.value))


def _round(arguments: Sequence[Value]) -> Value:
    (first,) = _quantities(arguments)  # half up, as Scratch does (round 2.5 = 3, -2.5 = -2)
    return first.with_shown(math.floor(first.shown + 0.5))


def _abs(arguments: Sequence[Value]) -> Value:
    (first,) = _quantities(arguments)
    return first.with_value(abs(first.value))


def _pick(which: Callable[..., Quantity]) -> Implementation:
    return lambda arguments: which(*_quantities(arguments), key=lambda q: q.value)


_ONE, _BRACKETS, _OWN = Written.ONE_VALUE, Written.BRACKETS, Written.OWN_RULE
FUNCTIONS: dict[str, Function] = {
    function.name: function
    for function in (
        Function("round", 1, _ONE, _quantity_kind, _round,
                 ("afronden", "redondea", "arrondi", "runde")),
        Function("abs", 1, _ONE, _quantity_kind, _abs),
        Function("sqrt", 1, _ONE, _number_kind, _sqrt, ("wortel", "raíz", "racine", "wurzel")),
        Function("sin", 1, _ONE, _angle_kind, _trigonometry(math.sin)),
        Function("cos", 1, _ONE, _angle_kind, _trigonometry(math.cos)),
        Function("min", 2, _BRACKETS, _same_quantities_kind, _pick(min)),
        Function("max", 2, _BRACKETS, _same_quantities_kind, _pick(max)),
        Function("join", 1, _BRACKETS, _text_kind, _join, ("plak", "une", "colle", "verbinde"),
                 more=True),
        Function("random", 2, _OWN, _same_quantities_kind, None,
                 ("willekeurig", "aleatorio", "hasard", "zufall")),
        Function("rgb", 3, _OWN, _rgb_kind, _rgb),
    )
}  # fmt: skip
"""Every built-in function by name (``random a to b`` counts two values). ``rgb r g b`` is a
colour the grammar builds (folded when its channels are numbers written out); with other
channels it is a call like the others."""


ONE_VALUE_FUNCTIONS: tuple[str, ...] = tuple(
    name for name, function in FUNCTIONS.items() if function.written is Written.ONE_VALUE
)
"""The functions written `round x` (the blocks' function block offers them)."""


def function_kind(function: str, arguments: Sequence[Kind]) -> Kind:
    """The kind a built-in function gives for arguments of these kinds, or UnitError."""
    return FUNCTIONS[function].kind(function, arguments)


def with_unit_kind(unit_word: str, operand: Kind) -> Kind:
    """The kind of ``<operand> <unit>`` (``d cm``): a unit only follows a plain number (E114)."""
    unit = unit_named(unit_word)
    if operand is not Kind.NUMBER:
        raise UnitError("E114", unit=unit.name, actual=operand.described)
    return unit.kind


def expect_kind(command: str, example: str, wanted: Kind, actual: Kind) -> None:
    """Raise UnitError unless ``actual`` is ``wanted``: E108 for a plain number where a unit is
    needed ("move needs a distance, like `move 10 cm`"), else E109 naming what it got."""
    if actual is wanted:
        return
    values: dict[str, object] = {
        "command": Code(command, quoted=False),
        "wanted": wanted.described,
        "example": Code(example, quoted=False),
    }
    if actual is Kind.NUMBER and wanted.is_quantity:  # the checker may fill in `write`
        raise UnitError("E108", write="", **values)
    raise UnitError("E109", actual=actual.described, **values)


# ---- the rules, on values (for the runtime) ------------------------------------------------------


def apply_binary(op: str, left: Value, right: Value) -> Value:
    """Evaluate ``left op right``. Raises UnitError for broken unit rules and ZeroDivisionError
    for ``/`` or ``mod`` by zero (the runtime reports that with its own code)."""
    described = OPERATORS[op]
    rule = described.rule
    if isinstance(left, Quantity) and isinstance(right, Quantity):  # first, for busy loops
        kind = left.kind
        if rule is Rule.SAME and kind is right.kind and kind.is_quantity:  # as the rules say
            return Quantity(described.compute(left.value, right.value), kind, left.unit)
    left_kind, right_kind = kind_of(left), kind_of(right)
    result = _binary_result(op, left_kind, right_kind)
    if result is None:
        binary_kind(op, left_kind, right_kind, _unit(left), _unit(right))  # raises E110
        raise AssertionError("binary_kind accepted what _binary_result refused")
    if rule in (Rule.LOGIC, Rule.EQUALITY):
        truth: bool = described.compute(left, right)
        return truth
    assert isinstance(left, Quantity) and isinstance(right, Quantity)
    value = described.compute(left.value, right.value)  # (Python's own ZeroDivisionError)
    if rule is Rule.ORDERING:
        ordered: bool = value
        return ordered
    unit = left.unit if rule is Rule.SAME else _display_unit(result, left, right)
    return Quantity(value, result, unit)


def _unit(value: Value) -> str:
    return value.unit if isinstance(value, Quantity) else ""


def _display_unit(kind: Kind, left: Quantity, right: Quantity) -> str:
    for side in (left, right):
        if side.kind is kind:
            return side.unit
    if kind is Kind.SPEED and left.unit in ("cm", "m"):
        return "cm/s"
    return kind.canonical_unit


def _equal(left: Value, right: Value) -> bool:
    if isinstance(left, Quantity) and isinstance(right, Quantity):
        return math.isclose(left.value, right.value, rel_tol=1e-9, abs_tol=1e-9)
    if isinstance(left, Color) and isinstance(right, Color):
        return left.same_as(right)
    if isinstance(left, str) and isinstance(right, str):
        return left.lower() == right.lower()
    return left == right


def apply_unit(unit_word: str, operand: Value) -> Quantity:
    """Evaluate ``<operand> <unit>``: ``apply_unit("cm", 10)`` is 10 cm."""
    with_unit_kind(unit_word, kind_of(operand))
    assert isinstance(operand, Quantity)
    return Quantity.of(operand.value, unit_word)


def apply_unary(op: str, operand: Value) -> Value:
    unary_kind(op, kind_of(operand))
    if op == "not":
        return not operand
    assert isinstance(operand, Quantity)
    return operand.with_value(-operand.value)


def apply_function(function: str, arguments: Sequence[Value]) -> Value:
    """Evaluate a built-in function (not ``random``: the runtime owns the random source)."""
    entry = FUNCTIONS[function]
    entry.kind(function, [kind_of(argument) for argument in arguments])
    assert entry.apply is not None, function
    return entry.apply(arguments)


def show(value: Value) -> str:
    """A value as ``print`` and ``join`` show it."""
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)
