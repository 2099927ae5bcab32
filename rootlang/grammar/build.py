"""Turn lark's tree of one or more lines into AST statements and block headers.

Each line becomes either an :mod:`rootlang.ast` statement or a :class:`Header` (a line that opens
a block: ``when``, ``to``, ``repeat``, ``if`` ...); :mod:`rootlang.grammar.blocks` then nests the
lines by their indentation. A statement or event a form describes is built from its form
(:class:`rootlang.grammar.rules.Built`); the rest have a method here. Mistakes that the
grammar recognises on purpose (``set x = 5``, ``repeat`` without a count, a number too big)
are collected in ``diagnostics`` instead of stopping, so one pass reports them all.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any, Literal

from lark import Token, Transformer, Tree, v_args
from lark.tree import Meta
from lark.visitors import Discard

from rootlang import ast
from rootlang.colors import NAMED_COLORS, Color
from rootlang.diagnostics import Diagnostic, Span, diagnostic
from rootlang.grammar.rules import built, canonical, event_read_as
from rootlang.units import OPERATORS, Kind, Quantity, note_frequency, rgb_color, unit_named

HeaderKind = Literal["when", "to", "loop", "if", "else if", "else"]


@dataclass(frozen=True)
class Header:
    """A line that opens a block, of its ``kind``; ``value`` is what the kind
    needs (the event, the condition, ``(name, parameters)`` for ``to``, or a loop's statement
    built from its form with no body yet: ``repeat``, ``forever``, ``repeat until``, ``while``)."""

    kind: HeaderKind
    span: Span
    value: Any = None


Line = ast.Statement | Header


def token_span(token: Token, line_offset: int = 0) -> Span:
    assert token.line is not None and token.column is not None
    assert token.end_line is not None and token.end_column is not None
    line, end_line = token.line + line_offset, token.end_line + line_offset
    return Span(line, token.column, end_line, token.end_column)


def _present(*items: Any) -> list[Any]:
    return [item for item in items if item is not None]


@v_args(meta=True)
class LineBuilder(Transformer[Token, list[Line]]):
    """Build lines; spans come from lark's positions (propagate_positions=True)."""

    def __init__(self, line_offset: int = 0) -> None:
        super().__init__()
        self.line_offset = line_offset  # when parsing one line of a file on its own
        self.diagnostics: list[Diagnostic] = []
        self._loose_tuples: dict[int, _Tuple] = {}  # `(a, b)` not (yet) used as arguments

    def transform(self, tree: Tree[Token]) -> list[Line]:
        """lark's ``transform`` without its recursion: lark's tree is as deep as the line's
        brackets (thousands, in a line a child or a program wrote), so it is built bottom-up
        with a list of its own; lines too deep for the rest of rootlang are E018 afterwards
        (:func:`too_deep`)."""
        values: list[Any] = []
        todo: list[tuple[Any, int]] = [(tree, -1)]  # (node, where its children's values start)
        while todo:
            node, start = todo.pop()
            if start >= 0:  # its children are built: build the node
                children = values[start:]
                del values[start:]
                value = self._call_userfunc(node, children)  # type: ignore[no-untyped-call]
            elif isinstance(node, Tree):
                todo.append((node, len(values)))
                todo.extend((child, -1) for child in reversed(node.children))
                continue
            elif isinstance(node, Token):
                value = self._call_userfunc_token(node)  # type: ignore[no-untyped-call]
            else:
                value = node
            if value is not Discard:
                values.append(value)
        return values[0]  # type: ignore[no-any-return]

    def _span(self, meta: Meta) -> Span:
        offset = self.line_offset
        return Span(meta.line + offset, meta.column, meta.end_line + offset, meta.end_column)

    def _token_span(self, token: Token) -> Span:
        return token_span(token, self.line_offset)

    def start(self, meta: Meta, children: list[Line]) -> list[Line]:
        for tuple_ in self._loose_tuples.values():
            self.diagnostics.append(diagnostic("E017", tuple_.span))
        return children

    # ---- headers -------------------------------------------------------------------------

    def when_header(self, meta: Meta, children: list[Any]) -> Header:
        event = children[0]  # built from its form (rootlang.grammar.rules)
        if isinstance(event, ast.ConditionBecomesTrue):  # `when (bumper left pressed)` too
            event = event_read_as(event.span, event.condition)
        return Header("when", self._span(meta), event)

    def to_header(self, meta: Meta, children: list[Any]) -> Header:
        name, parameters = children
        return Header("to", self._span(meta), (name, tuple(parameters or ())))

    def parameters(self, meta: Meta, children: list[ast.Parameter]) -> list[ast.Parameter]:
        return children

    def name(self, meta: Meta, children: list[Token]) -> ast.Parameter:
        return ast.Parameter(self._token_span(children[0]), str(children[0]).lower())

    def loop_header(self, meta: Meta, children: list[Any]) -> Header:
        return Header("loop", self._span(meta), children[0])  # built from its form, no body yet

    def repeat_without_count(self, meta: Meta, children: list[Any]) -> Header:
        self.diagnostics.append(diagnostic("E006", self._span(meta)))
        return Header("loop", self._span(meta), ast.Forever(self._span(meta), ()))

    def if_header(self, meta: Meta, children: list[Any]) -> Header:
        return Header("if", self._span(meta), children[0])

    def else_if_header(self, meta: Meta, children: list[Any]) -> Header:
        return Header("else if", self._span(meta), children[0])

    def else_header(self, meta: Meta, children: list[Any]) -> Header:
        return Header("else", self._span(meta))

    # ---- statements (most are built from their forms: __default__) --------------------

    def print(self, meta: Meta, children: list[Any]) -> ast.Statement:
        return ast.Print(self._span(meta), tuple(_present(*children)))

    def set_variable(self, meta: Meta, children: list[Any]) -> ast.Statement:
        name, value = children
        return ast.SetVariable(self._span(meta), name.name, value)

    def set_with_equals(self, meta: Meta, children: list[Any]) -> ast.Statement:
        name, sign, value = children
        self.diagnostics.append(diagnostic("E005", self._token_span(sign), name=name.name))
        return ast.SetVariable(self._span(meta), name.name, value)

    def change(self, meta: Meta, children: list[Any]) -> ast.Statement:
        name, by = children
        return ast.ChangeVariable(self._span(meta), name.name, by)

    def call(self, meta: Meta, children: list[Any]) -> ast.Statement:
        callee, *arguments = children
        return ast.CallProcedure(
            self._span(meta), callee.name, self._arguments(_present(*arguments)), callee.span
        )

    def callee(self, meta: Meta, children: list[Token]) -> ast.Parameter:
        return self.name(meta, children)

    # ---- expressions ---------------------------------------------------------------------

    def or_(self, meta: Meta, children: list[Any]) -> ast.Expression:
        return ast.Binary(self._span(meta), "or", children[0], children[1])

    def and_(self, meta: Meta, children: list[Any]) -> ast.Expression:
        return ast.Binary(self._span(meta), "and", children[0], children[1])

    def not_(self, meta: Meta, children: list[Any]) -> ast.Expression:
        return ast.Unary(self._span(meta), "not", children[0])

    def compare(self, meta: Meta, children: list[Any]) -> ast.Expression:
        return self.binary(meta, children)

    def binary(self, meta: Meta, children: list[Any]) -> ast.Expression:
        left, op, right = children
        return ast.Binary(self._span(meta), _OPERATOR_SPELLINGS[str(op).lower()], left, right)

    def negate(self, meta: Meta, children: list[Any]) -> ast.Expression:
        return minus(self._span(meta), children[1])

    def with_unit(self, meta: Meta, children: list[Any]) -> ast.Expression:
        operand, unit_token = children
        return with_unit(self._span(meta), operand, str(unit_token))

    def number(self, meta: Meta, children: list[Token]) -> ast.Expression:
        value = float(children[0])
        if not math.isfinite(value) or value > 1e15:
            self.diagnostics.append(diagnostic("E015", self._span(meta)))
            value = 0.0
        return number_literal(self._span(meta), value)

    def text(self, meta: Meta, children: list[Token]) -> ast.Expression:
        return text_literal(self._span(meta), _string(children[0]))

    def boolean(self, meta: Meta, children: list[Token]) -> ast.Expression:
        return boolean_literal(self._span(meta), canonical(children[0]) == "true")

    def color_name(self, meta: Meta, children: list[Token]) -> Color:
        return NAMED_COLORS[canonical(children[0])]

    def named_color(self, meta: Meta, children: list[Color]) -> ast.Expression:
        return color_literal(self._span(meta), children[0])

    def hex_color(self, meta: Meta, children: list[Token]) -> ast.Expression:
        return color_literal(self._span(meta), Color.from_hex(str(children[0])))

    def rgb(self, meta: Meta, children: list[ast.Expression]) -> ast.Expression:
        return rgb(self._span(meta), children)

    def note(self, meta: Meta, children: list[Token]) -> ast.Expression:
        return note_literal(self._span(meta), str(children[0]))

    def variable(self, meta: Meta, children: list[Token]) -> ast.Expression:
        return ast.Variable(self._span(meta), str(children[0]).lower())

    def call_value(self, meta: Meta, children: list[Any]) -> ast.Expression:
        name = str(children[0]).lower()
        arguments = self._arguments(children[1:])
        return ast.ProcedureCall(self._span(meta), name, arguments)

    def function(self, meta: Meta, children: list[Any]) -> ast.Expression:
        name = str(children[0]).lower()
        return ast.FunctionCall(self._span(meta), name, self._arguments(children[1:]))

    def random(self, meta: Meta, children: list[Any]) -> ast.Expression:
        return ast.FunctionCall(self._span(meta), "random", tuple(children))

    def parenthesis(self, meta: Meta, children: list[Any]) -> ast.Expression:
        if len(children) == 1:
            return children[0]  # type: ignore[no-any-return]
        tuple_ = _Tuple(self._span(meta), tuple(children))
        self._loose_tuples[id(tuple_)] = tuple_
        return tuple_

    def _arguments(self, values: list[Any]) -> tuple[ast.Expression, ...]:
        """``area(3 cm, 4 cm)`` passes a tuple; ``polygon 6, 5 cm`` passes the values."""
        if len(values) == 1 and isinstance(values[0], _Tuple):
            del self._loose_tuples[id(values[0])]
            return values[0].items
        return tuple(values)

    def __default__(self, data: str, children: list[Any], meta: Meta) -> Any:
        """A statement, an event or a sensor written from its form (rootlang.grammar.rules)
        is built from it."""
        made = built().get(str(data))
        if made is None:
            raise AssertionError(f"grammar rule {data!r} has no builder")  # a bug in rootlang
        return made.node(self._span(meta), children)


# Each spelling of an operator the grammar reads -> the operator (`≤` -> `<=`, `MOD` -> `mod`).
_OPERATOR_SPELLINGS = {
    spelling: op
    for op, described in OPERATORS.items()
    for spelling in (described.written, *described.also)
}


@dataclass(frozen=True, eq=False, repr=False, slots=True)
class _Tuple(ast.Expression):
    """``(a, b)``: only meaningful as the arguments of a call."""

    items: tuple[ast.Expression, ...]


def too_deep(line: Line) -> bool:
    """Whether a line has more calculations inside each other than :data:`ast.NESTING_LIMIT`."""
    item = line.value if isinstance(line, Header) else line
    if isinstance(item, tuple):  # `to name a, b`: names only
        return False
    return isinstance(item, ast.Node) and ast.calculation_depth(item) > ast.NESTING_LIMIT


def _plain_number(expression: ast.Expression) -> float | None:
    value = expression.value if isinstance(expression, ast.Literal) else None
    if isinstance(value, Quantity) and not value.unit:
        return value.value
    return None


def _string(token: Token) -> str:
    return str(token)[1:-1]


# ---- values, made the one way for the parser and the blocks ------------------------------
# Each literal carries its canonical text (what `rootlang format` and the blocks print). A minus
# on a number, a unit on a number and `rgb` of three numbers fold into one literal.


def number_literal(span: Span, value: float) -> ast.Literal:
    return ast.Literal(span, Quantity.number(value), number_text(value))


def text_literal(span: Span, value: str) -> ast.Literal:
    return ast.Literal(span, value, string_text(value))


def boolean_literal(span: Span, value: bool) -> ast.Literal:
    return ast.Literal(span, value, "true" if value else "false")


def color_literal(span: Span, color: Color) -> ast.Literal:
    """A named colour (``red``) or one written in hex (``#ff8000``)."""
    return ast.Literal(span, color, color.name or color.hex)


def note_literal(span: Span, written: str) -> ast.Literal:
    name = note_name(written)
    return ast.Literal(span, Quantity(note_frequency(name), Kind.FREQUENCY, "Hz"), f"note {name}")


def minus(span: Span, operand: ast.Expression) -> ast.Expression:
    if isinstance(operand, ast.Literal) and isinstance(operand.value, Quantity):
        value = operand.value.with_value(-operand.value.value or 0.0)  # never -0
        text = negated_text(operand.text) if value.value else operand.text  # no "-0"
        return ast.Literal(span, value, text)
    return ast.Unary(span, "-", operand)


def with_unit(span: Span, operand: ast.Expression, unit_word: str) -> ast.Expression:
    """``10 cm`` (a literal), or ``size cm``; KeyError for a word that is not a unit."""
    unit = unit_named(unit_word)
    value = operand.value if isinstance(operand, ast.Literal) else None
    if isinstance(value, Quantity) and value.kind.is_quantity and not value.unit:
        text = quantity_text(operand.text, unit.name) if isinstance(operand, ast.Literal) else ""
        return ast.Literal(span, Quantity.of(value.value, unit.name), text)
    return ast.WithUnit(span, operand, unit.name)


def rgb(span: Span, channels: Sequence[ast.Expression]) -> ast.Expression:
    numbers = [_plain_number(channel) for channel in channels]
    # a negative channel is written in brackets, `rgb (-1) 128 0`: that stays a call to print
    if all(number is not None and number >= 0 for number in numbers):
        red, green, blue = (number or 0.0 for number in numbers)
        text = "rgb " + " ".join(c.text for c in channels if isinstance(c, ast.Literal))
        return ast.Literal(span, rgb_color(red, green, blue), text)
    return ast.FunctionCall(span, "rgb", tuple(channels))


def number_text(value: float) -> str:
    """A number as written in canonical form: ``10``, ``2.5``, ``0.0001`` (never ``1e-04``)."""
    if value == int(value) and abs(value) < 1e15:
        return str(int(value))
    import decimal  # (only for a fraction: start-up)

    return format(decimal.Decimal(repr(value)), "f")


def quantity_text(number: str, unit: str) -> str:
    """``10 cm``, ``50 %``, but ``90°``: the degree sign sits on its number."""
    return f"{number}{unit}" if unit == "°" else f"{number} {unit}"


def negated_text(text: str) -> str:
    return text[1:] if text.startswith("-") else f"-{text}"


def string_text(value: str) -> str:
    """Text between straight quotes, or curly ones when it holds a straight quote."""
    return f"\u201c{value}\u201d" if '"' in value else f'"{value}"'


def note_name(written: str) -> str:
    """``c4`` -> ``C4``, ``bb3`` -> ``Bb3``, ``f#5`` -> ``F#5``."""
    return written[0].upper() + written[1:].lower()
