"""``rootlang format``: a program in canonical form, comments and blank lines kept.

Canonical form: four spaces per level; keywords in lower case and their usual spelling
(``repeat forever``, ``marker``, ``color``, ``=``, ``!=``); values as :attr:`ast.Literal.text`
writes them; only the brackets the meaning needs; one space around operators; an
end-of-line comment two spaces after its line; ``# comment`` with one space; at most one blank
line in a row, none right under a header, exactly one between scripts and procedures.

The printer works on the syntax tree alone, so the blocks (:mod:`rootlang.blocks`) use it too:
they rebuild a tree from a workspace, with line numbers that say where the blank lines and
comments go, and print it with :func:`format_program`. Statements and events are printed from
their forms in :mod:`rootlang.forms`.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import NamedTuple

from rootlang import ast
from rootlang.diagnostics import RootlangError, Span
from rootlang.forms import Body, Choice, Slot, Text, Word, body_of, form_of
from rootlang.units import ONE_VALUE_FUNCTIONS, OPERATORS, Binding, Quantity

__all__ = [
    "INDENT",
    "comment_line",
    "expression_text",
    "format_program",
    "format_source",
    "line_text",
    "reads_back_as",
]

INDENT = "    "

# Precedence levels, loosest first, as in rootlang/grammar/root.lark: the operators' own
# (rootlang.units.Binding), `not` between `and` and a comparison, and a minus sign, a unit and
# a single value holding tighter than any operator.
OR, AND, COMPARE, SUM, PRODUCT = Binding
NOT = AND + 1
UNARY, POSTFIX, ATOM = PRODUCT + 1, PRODUCT + 2, PRODUCT + 3
# (level, left operand at least, right operand at least): a comparison is not chained
_BINARY_LEVELS = {
    op: (operator.binds, operator.binds + (operator.binds is COMPARE), operator.binds + 1)
    for op, operator in OPERATORS.items()
}


def format_source(source: str, file: str = "", written_in: str | None = None) -> str:
    """The canonical text of a program, in the language it is written in (``written_in``, else
    the one it declares); RootlangError if it does not parse, and E708 in the one case that
    must never happen: the text printed would read back as another program."""
    from rootlang.checks import parse  # lark loads lazily
    from rootlang.locale.translate import from_english, program_language

    language = program_language(source, written_in)
    program = parse(source, file, language)
    printed = format_program(program)
    if not reads_back_as(printed, program):
        raise RootlangError.of("E708")
    return from_english(printed, language)


def reads_back_as(printed: str, program: ast.Program) -> bool:
    """Whether English text rootlang printed reads back as ``program``: the printers' net."""
    from rootlang.checks import parse

    try:
        return ast.same_tree(parse(printed, "", "en"), program)
    except RootlangError:
        return False


def format_program(program: ast.Program) -> str:
    writer = _Writer(program.comments)
    for item in program.items:
        writer.top_level(item)
    writer.finish()
    return writer.text()


# ---- lines ---------------------------------------------------------------------------------


def line_text(node: ast.Node) -> str:
    """The one line that writes a statement, or a script's or procedure's header (for a block
    statement: its header line; ``if`` gives its first line)."""
    match node:
        case ast.Script(event=event):
            return f"when {event_text(event)}"
        case ast.Procedure(name=name, parameters=parameters):
            return _words(f"to {name}", ", ".join(p.name for p in parameters))
        case ast.If(branches=branches):
            return f"if {expression_text(branches[0].condition)}"
        case ast.Print(values=values):
            return _words("print", _values(values))
        case ast.SetVariable(name=name, value=value):
            return f"set {name} to {expression_text(value)}"
        case ast.ChangeVariable(name=name, by=by):
            return f"change {name} by {expression_text(by)}"
        case ast.CallProcedure(name=name, arguments=arguments):
            return _words(name, _values(arguments))
    return _form_text(node)


def event_text(event: ast.Event) -> str:
    return _form_text(event)


def _form_text(node: ast.Node) -> str:
    words: list[str] = []
    for part in form_of(node).parts:
        if isinstance(part, Word):
            words.append(part.text if part.printed else "")
        elif isinstance(part, Choice):
            words.append(part.words(getattr(node, part.field)))
        elif isinstance(part, Slot):
            words.append(expression_text(getattr(node, part.field)))
        elif isinstance(part, Text):
            words.append(_quoted(getattr(node, part.field)))
        else:
            assert isinstance(part, Body)
    return " ".join(word for word in words if word)


def _words(first: str, rest: str) -> str:
    return f"{first} {rest}" if rest else first


def _values(values: Sequence[ast.Expression]) -> str:
    return ", ".join(expression_text(value) for value in values)


def _quoted(text: str) -> str:
    from rootlang.grammar.build import string_text

    return string_text(text)


# ---- expressions ---------------------------------------------------------------------------


def expression_text(expression: ast.Expression, at_least: int = OR) -> str:
    """An expression with the brackets its place needs: ``at_least`` is the loosest level
    that may stand there unbracketed (see the levels above)."""
    return _text(expression, at_least, None)


def _text(expression: ast.Expression, at_least: int, followed_by: int | None) -> str:
    """The expression where a value of level ``at_least`` or tighter may stand, followed by
    something of level ``followed_by`` (None: nothing an expression could take in).

    An expression that ends in an open value (``round x``, ``random 1 to 6``, ``-x``,
    ``a + b``) takes in what follows it when the open place accepts that level: ``round x
    cm`` is ``round (x cm)``, so ``(round x) cm`` needs its brackets; else what follows may
    still be taken in deeper, so the last value is written knowing what follows it:
    ``round (random 1 to 4) * 90`` keeps the brackets that make it a quarter turn."""
    layout = _layout(expression)
    taken_in = layout.open is not None and followed_by is not None and layout.open <= followed_by
    if layout.level < at_least or taken_in:
        return f"({_text(expression, OR, None)})"
    last = len(layout.parts) - 1
    return "".join(
        part if isinstance(part, str)
        else _text(part.value, part.at_least,
                   followed_by if index == last and layout.open is not None else part.followed_by)
        for index, part in enumerate(layout.parts)
    )  # fmt: skip


class _Place(NamedTuple):
    """A value inside an expression: the loosest level that may stand there unbracketed, and
    the level of what follows it within the expression (see :func:`_text`)."""

    value: ast.Expression
    at_least: int
    followed_by: int | None = None


@dataclass(frozen=True)
class _Layout:
    """How an expression is written: words and values in turn, its ``level``, and ``open``:
    the loosest level its last place accepts, when it ends in one that can take in what
    follows (that place is its last part, or, for ``name(a, b)``, the brackets' own value)."""

    level: int
    parts: tuple[str | _Place, ...]
    open: int | None = None


def _layout(expression: ast.Expression) -> _Layout:
    node = ast.expression(expression)
    match node:
        case ast.Literal(value=value, text=text):
            if text.startswith("-"):
                return _Layout(UNARY, (text,), open=UNARY)
            if text.startswith("rgb "):
                return _Layout(ATOM, (text,), open=POSTFIX)  # its last channel takes a unit
            has_unit = isinstance(value, Quantity) and bool(value.unit)
            return _Layout(POSTFIX if has_unit else ATOM, (text,))
        case ast.Variable(name=name):
            return _Layout(ATOM, (name,))
        case ast.SensorRead():
            return _Layout(ATOM, (_form_text(node),))
        case ast.WithUnit(operand=operand, unit=unit):
            from rootlang.grammar.build import quantity_text

            written = quantity_text("{}", unit)
            before, after = written.split("{}")
            return _Layout(POSTFIX, (before, _Place(operand, ATOM, POSTFIX), after))
        case ast.Unary(op="not", operand=operand):
            return _Layout(NOT, ("not ", _Place(operand, NOT)), open=NOT)
        case ast.Unary(operand=operand):
            return _Layout(UNARY, ("-", _Place(operand, UNARY)), open=UNARY)
        case ast.Binary(op=op, left=left, right=right):
            level, left_at_least, right_at_least = _BINARY_LEVELS[op]
            parts = (_Place(left, left_at_least, level), f" {op} ", _Place(right, right_at_least))
            return _Layout(level, parts, open=right_at_least)
        case ast.FunctionCall(function=function, arguments=arguments):
            return _function(function, arguments)
        case ast.ProcedureCall(name=name, arguments=arguments):
            return _call(name, arguments, writes_one_open=True)
        case _:
            ast.assert_never(node)


def _function(function: str, arguments: Sequence[ast.Expression]) -> _Layout:
    if function == "random" and len(arguments) == 2:
        low, high = arguments
        return _Layout(ATOM, ("random ", _Place(low, SUM), " to ", _Place(high, SUM)), open=SUM)
    if function == "rgb" and len(arguments) == 3:
        first, second, third = (_Place(channel, ATOM, POSTFIX) for channel in arguments)
        # each channel a plain value; the last is open to a unit (`rgb 1 2 3 cm`)
        return _Layout(ATOM, ("rgb ", first, " ", second, " ", third), open=POSTFIX)
    return _call(function, arguments, writes_one_open=function in ONE_VALUE_FUNCTIONS)


def _call(name: str, arguments: Sequence[ast.Expression], *, writes_one_open: bool) -> _Layout:
    """``name``, ``name x`` or ``name(a, b)``. ``writes_one_open``: the name takes the value
    after it (a procedure with values, ``round``), so ``name(a, b)`` is the name and one value
    in brackets, which a unit after it would go into; else the brackets are the call's own
    (``min(a, b)``)."""
    if not arguments:
        return _Layout(ATOM, (name,))
    if writes_one_open and len(arguments) == 1:
        return _Layout(ATOM, (f"{name} ", _Place(arguments[0], UNARY)), open=UNARY)
    values = [part for argument in arguments for part in (", ", _Place(argument, OR))][1:]
    return _Layout(ATOM, (f"{name}(", *values, ")"), open=UNARY if writes_one_open else None)


# ---- layout: lines, comments, blank lines ------------------------------------------------


def comment_line(comment: ast.Comment) -> str:
    """A comment in canonical form: ``# text`` (``#`` alone, or ``##...`` kept as they are)."""
    text = comment.text
    return f"#{text}" if not text or text[0] in " #" else f"# {text}"


class _Writer:
    """Writes lines in source order, fitting each comment and blank line in where it was."""

    def __init__(self, comments: Iterable[ast.Comment]) -> None:
        ordered = sorted(comments, key=lambda comment: comment.span)
        self.own_line = [comment for comment in ordered if comment.own_line]
        self.end_of_line = {
            comment.span.line: comment for comment in ordered if not comment.own_line
        }
        self.lines: list[str] = []
        self.last_line = 0  # the source line of the last line written
        self.opened = False  # the last line written opens a block
        self.widths: list[int] = [0]  # indentation as written, per depth of the open blocks
        self.depth = 0
        self.new_item = False

    def text(self) -> str:
        return "".join(f"{line}\n" for line in self.lines)

    def top_level(self, item: ast.Script | ast.Procedure) -> None:
        self.new_item = bool(self.lines)
        self._line(0, item.span, line_text(item), opens=True)
        self._block(item.body, 1)

    def finish(self) -> None:
        self._comments_before(None, 0)

    def _block(self, block: ast.Block, depth: int) -> None:
        for statement in block:
            self._statement(statement, depth)

    def _statement(self, statement: ast.Statement, depth: int) -> None:
        if isinstance(statement, ast.If):
            for index, branch in enumerate(statement.branches):
                text = line_text(statement) if index == 0 else (
                    f"else if {expression_text(branch.condition)}"
                )  # fmt: skip
                self._line(depth, branch.span, text, opens=True)
                self._block(branch.body, depth + 1)
            if statement.otherwise is not None:
                else_span = statement.else_span or statement.span
                self._line(depth, else_span, "else", opens=True)
                self._block(statement.otherwise, depth + 1)
            return
        body = body_of(statement)
        self._line(depth, statement.span, line_text(statement), opens=body is not None)
        if body is not None:
            self._block(body, depth + 1)

    def _line(self, depth: int, span: Span, text: str, *, opens: bool) -> None:
        self._comments_before(span.line, depth)
        comment = self.end_of_line.pop(span.line, None)
        if comment is not None:
            text = f"{text}  {comment_line(comment)}"
        self._write(depth, span.line, text, column=span.column)
        self.opened = opens

    def _comments_before(self, line: int | None, depth: int) -> None:
        """Own-line comments above ``line`` (None: the end), each at the depth where it was
        written, between the depth of the line after it and the block the line before opened."""
        deepest = self.depth + (1 if self.opened else 0)
        while self.own_line and (line is None or self.own_line[0].span.line < line):
            comment = self.own_line.pop(0)
            written = comment.span.column - 1
            at = depth
            for level in range(depth, deepest + 1):
                if self._width(level) <= written:
                    at = level
            self._write(at, comment.span.line, comment_line(comment), column=None)
            deepest = at

    def _width(self, depth: int) -> int:
        if depth < len(self.widths):
            return self.widths[depth]
        return self.widths[-1] + 1

    def _write(self, depth: int, source_line: int, text: str, *, column: int | None) -> None:
        if depth == 0 and self.new_item:
            blank = True
            self.new_item = False
        else:
            blank = source_line > self.last_line + 1 and bool(self.lines) and not self.opened
        if blank:
            self.lines.append("")
        self.lines.append(f"{INDENT * depth}{text}")
        self.last_line = source_line
        self.opened = False
        self.depth = depth
        if column is not None:  # a statement: the blocks it is in are open at these widths
            del self.widths[depth:]
            self.widths.append(column - 1)
