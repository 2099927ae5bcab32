"""Nest parsed lines into scripts, procedures and blocks by their indentation.

Indentation is measured here rather than in a lark post-lexer, so every indentation mistake
gets its own plain message (E003 mixed tabs and spaces, E004 a command at the left edge,
E007 ``else`` without ``if``, E008 an unexpected indent, E009 a missing block, E010 a dedent
that lines up with nothing, E016 ``when``/``to`` indented, E018 a block inside more than
:data:`~rootlang.ast.NESTING_LIMIT` others, E028 a whole program indented, E035 a program with
no ``when`` or ``to`` line at all) and one bad line never hides the mistakes after it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from rootlang import ast
from rootlang.diagnostics import Diagnostic, Span, diagnostic
from rootlang.grammar.build import Header, Line
from rootlang.wording.shown import unquoted


@dataclass(frozen=True)
class Broken:
    """A line that did not parse (already reported); the lines indented under it are still
    read and checked, as the lines of a block (at the left edge: of a script), so a child
    sees every mistake at once."""

    span: Span


@dataclass(frozen=True)
class IndentedLine:
    """A line (or a broken one) with its number, indentation and first word."""

    number: int
    indent: int  # width, tabs counted as 4
    item: Line | Broken
    first_word: str


def indentation(text: str) -> str:
    return text[: len(text) - len(text.lstrip(" \t"))]


class Nester:
    """Walks the lines once, top to bottom, building blocks and collecting diagnostics."""

    def __init__(self, lines: list[IndentedLine]) -> None:
        self.lines = lines
        self.position = 0
        self.diagnostics: list[Diagnostic] = []

    def program(self, file: str, comments: list[ast.Comment]) -> ast.Program:
        scripts: list[ast.Script] = []
        procedures: list[ast.Procedure] = []
        if self.lines and all(line.indent > 0 for line in self.lines):  # no `when started`
            self.diagnostics.append(diagnostic("E028", self.lines[0].item.span))
            self.position = len(self.lines)
        elif self.lines and not any(_opens_program(line.item) for line in self.lines):
            self.diagnostics.append(diagnostic("E035", self.lines[0].item.span))  # one message,
            self.position = len(self.lines)  # not one a line
        while self.position < len(self.lines):
            line = self._next()
            item = line.item
            if line.indent > 0:
                if not isinstance(item, Broken):
                    self.diagnostics.append(diagnostic("E008", item.span, where=_at(0)))
                self._skip_deeper(0)
                continue
            if isinstance(item, Broken) and self._peek_indent() > 0:  # its lines: checked, in a
                scripts.append(ast.Script(item.span, ast.Started(item.span), self._body(line, 0)))
            elif isinstance(item, Header) and item.kind == "when":  # script as a `when started`'s
                scripts.append(ast.Script(item.span, item.value, self._body(line, 0)))
            elif isinstance(item, Header) and item.kind == "to":
                name, parameters = item.value
                body = self._body(line, 0)
                procedures.append(ast.Procedure(item.span, name.name, parameters, body))
            else:
                self._misplaced(line)
                self._skip_deeper(0)
        end = self.lines[-1].item.span if self.lines else Span(1, 1, 1, 1)
        span = Span(1, 1, end.end_line, end.end_column)
        return ast.Program(span, tuple(scripts), tuple(procedures), file, tuple(comments))

    def _misplaced(self, line: IndentedLine) -> None:
        item = line.item
        if isinstance(item, Broken):
            return
        if isinstance(item, Header) and item.kind in ("else", "else if"):
            self.diagnostics.append(diagnostic("E007", item.span))
        else:
            command = unquoted(line.first_word)
            self.diagnostics.append(diagnostic("E004", item.span, command=command))

    def _next(self) -> IndentedLine:
        line = self.lines[self.position]
        self.position += 1
        return line

    def _peek_indent(self) -> int:
        if self.position < len(self.lines):
            return self.lines[self.position].indent
        return -1

    def _skip_deeper(self, indent: int) -> None:
        while self._peek_indent() > indent:
            self.position += 1

    def _body(self, header: IndentedLine, depth: int) -> ast.Block:
        """The block under ``header``, which is inside ``depth`` blocks of its script."""
        inner = self._peek_indent()
        if inner <= header.indent:
            self.diagnostics.append(diagnostic("E009", header.item.span))
            return ()
        return self._block(inner, header.indent, depth)

    def _block(self, indent: int, parent: int, depth: int) -> ast.Block:
        statements: list[ast.Statement] = []
        while self.position < len(self.lines):
            line = self.lines[self.position]
            if line.indent <= parent:
                break
            if line.indent < indent:
                span = line.item.span
                self.diagnostics.append(diagnostic("E010", span, inner=indent, outer=parent))
            elif line.indent > indent:
                if not isinstance(line.item, Broken):
                    self.diagnostics.append(diagnostic("E008", line.item.span, where=_at(indent)))
                self._skip_deeper(indent)
                continue
            self.position += 1
            opens = (
                self._peek_indent() > line.indent and depth < ast.NESTING_LIMIT
            )  # (deeper: E018)
            if isinstance(line.item, Broken) and opens:
                statements += self._body(line, depth + 1)  # lines under a broken one: checked
                continue  # where they are, as the lines of a block with no words of its own
            statement = self._statement(line, depth)
            if statement is not None:
                statements.append(statement)
        return tuple(statements)

    def _statement(self, line: IndentedLine, depth: int) -> ast.Statement | None:
        item = line.item
        if isinstance(item, Broken):
            self._skip_deeper(line.indent)
            return None
        if isinstance(item, ast.Statement):
            return item
        if depth >= ast.NESTING_LIMIT and item.kind not in ("when", "to"):  # its block: too deep
            self.diagnostics.append(diagnostic("E018", item.span, limit=ast.NESTING_LIMIT))
            self._skip_deeper(line.indent)
            return None
        if item.kind in ("when", "to"):
            self.diagnostics.append(diagnostic("E016", item.span, word=item.kind))
            self._skip_deeper(line.indent)
            return None
        if item.kind in ("else", "else if"):
            self.diagnostics.append(diagnostic("E007", item.span))
            self._body(line, depth + 1)
            return None
        if item.kind == "if":
            return self._if(line, item, depth + 1)
        assert item.kind == "loop" and isinstance(item.value, ast.Statement)
        loop: Any = item.value  # a form's with a body (rootlang.forms): its lines are these
        nested: ast.Statement = replace(loop, span=item.span, body=self._body(line, depth + 1))
        return nested

    def _if(self, line: IndentedLine, header: Header, depth: int) -> ast.Statement:
        branches = [ast.Branch(header.span, header.value, self._body(line, depth))]
        otherwise: ast.Block | None = None
        else_span: Span | None = None
        while self.position < len(self.lines):
            following = self.lines[self.position]
            item = following.item
            if following.indent != line.indent or not isinstance(item, Header):
                break
            if item.kind == "else if":
                self.position += 1
                branches.append(ast.Branch(item.span, item.value, self._body(following, depth)))
            elif item.kind == "else":
                self.position += 1
                otherwise, else_span = self._body(following, depth), item.span
                break
            else:
                break
        return ast.If(header.span, tuple(branches), otherwise, else_span)


def _opens_program(item: Line | Broken) -> bool:
    """A `when` or `to` line, or a broken line that may be one."""
    return isinstance(item, Broken) or (isinstance(item, Header) and item.kind in ("when", "to"))


def _at(indent: int) -> str:
    """Where a line lined up at ``indent`` starts, in words for E008."""
    return ", at the left edge" if indent == 0 else f" ({indent} spaces from the left edge)"
