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

from rootlang import ast
from rootlang.diagnostics import Span
from rootlang.forms import Body, Choice, Slot, Text, Word, body_of, form_of
from rootlang.units import ONE_VALUE_FUNCTIONS, Quantity

__all__ = [
    "INDENT",
    "comment_line",
    "expression_text",
    "format_program",
    "format_source",
    "line_text",
]

INDENT = "    "

# Precedence levels, loosest first, as in rootlang/grammar/root.lark.
OR, AND, NOT, COMPARE, SUM, PRODUCT, UNARY, POSTFIX, ATOM = range(1, 10)
_BINARY_LEVELS = {
    "or": (OR, OR, AND),  # (level, left operand at least, right operand at least)
    "and": (AND, AND, NOT),
    **{op: (COMPARE, SUM, SUM) for op in ("=", "!=", "<", ">", "<=", ">=")},
    **{op: (SUM, SUM, PRODUCT) for op in ("+", "-")},
    **{op: (PRODUCT, PRODUCT, UNARY) for op in ("*", "/", "mod")},
}


def format_source(source: str, file: str = "", written_in: str | None = None) -> str:
    """The canonical text of a program, in the language it is written in (``written_in``, else
    the one it declares); RootlangError if it does not parse."""
    from rootlang.checks import parse  # lark loads lazily
    from rootlang.locale.translate import from_english, program_language

    language = program_language(source, written_in)
    return from_english(format_program(parse(source, file, language)), language)


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
    return _Expression.of(expression).text(at_least, None)


@dataclass(frozen=True)
class _Expression:
    """How an expression prints: ``level``, and ``tail``: the loosest level its last value
    accepts, when it ends in an open value (``round x``, ``random 1 to 6``, ``-x``) that
    would swallow what comes after it (``round x cm`` is ``round (x cm)``)."""

    body: str
    level: int
    tail: int | None = None

    def text(self, at_least: int, followed_by: int | None) -> str:
        swallows = self.tail is not None and followed_by is not None and self.tail <= followed_by
        return f"({self.body})" if self.level < at_least or swallows else self.body

    @staticmethod
    def of(expression: ast.Expression) -> _Expression:
        node = ast.expression(expression)
        match node:
            case ast.Literal(value=value, text=text):
                if text.startswith("-"):
                    return _Expression(text, UNARY, UNARY)
                if text.startswith("rgb "):
                    return _Expression(text, ATOM, ATOM)
                has_unit = isinstance(value, Quantity) and bool(value.unit)
                return _Expression(text, POSTFIX if has_unit else ATOM)
            case ast.Variable(name=name):
                return _Expression(name, ATOM)
            case ast.SensorRead():
                return _Expression(_form_text(node), ATOM)
            case ast.WithUnit(operand=operand, unit=unit):
                from rootlang.grammar.build import quantity_text

                inner = _Expression.of(operand).text(ATOM, POSTFIX)
                return _Expression(quantity_text(inner, unit), POSTFIX)
            case ast.Unary(op="not", operand=operand):
                return _Expression(f"not {_Expression.of(operand).text(NOT, None)}", NOT, NOT)
            case ast.Unary(operand=operand):
                return _Expression(f"-{_Expression.of(operand).text(UNARY, None)}", UNARY, UNARY)
            case ast.Binary(op=op, left=left, right=right):
                level, left_at_least, right_at_least = _BINARY_LEVELS[op]
                left_text = _Expression.of(left).text(left_at_least, level)
                right_expression = _Expression.of(right)
                body = f"{left_text} {op} {right_expression.text(right_at_least, None)}"
                tail = right_expression.tail if right_expression.level >= right_at_least else None
                return _Expression(body, level, tail)
            case ast.FunctionCall(function=function, arguments=arguments):
                return _function(function, arguments)
            case ast.ProcedureCall(name=name, arguments=arguments):
                if not arguments:
                    return _Expression(name, ATOM)
                if len(arguments) == 1:
                    return _Expression(f"{name} {_open(arguments[0], UNARY)}", ATOM, UNARY)
                return _Expression(f"{name}({_values(arguments)})", ATOM)
            case _:
                ast.assert_never(node)


def _function(function: str, arguments: Sequence[ast.Expression]) -> _Expression:
    if function in ONE_VALUE_FUNCTIONS and len(arguments) == 1:
        return _Expression(f"{function} {_open(arguments[0], UNARY)}", ATOM, UNARY)
    if function == "random" and len(arguments) == 2:
        low, high = (_Expression.of(argument) for argument in arguments)
        body = f"random {low.text(SUM, None)} to {high.text(SUM, None)}"
        return _Expression(body, ATOM, SUM)
    if function == "rgb" and len(arguments) == 3:
        channels = " ".join(_Expression.of(argument).text(ATOM, POSTFIX) for argument in arguments)
        return _Expression(f"rgb {channels}", ATOM, ATOM)
    return _Expression(f"{function}({_values(arguments)})", ATOM)


def _open(argument: ast.Expression, at_least: int) -> str:
    """The last value of an open expression (nothing follows it inside)."""
    return _Expression.of(argument).text(at_least, None)


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
