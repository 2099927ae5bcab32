"""Text -> blocks: a program as a Blockly workspace, in Blockly's own JSON serialization.

The program is first put in canonical form (``rootlang format``), so the workspace holds
exactly what the text will be again: every comment goes on the block of its line (the block's
comment bubble holds the text; the block's ``data`` says which lines were blank and which were
comments, so the way back puts each where it was). Block ids come from source positions: a
statement or header is ``L<line>``, an expression ``L<line>C<column>E<end column>``, so an
error or the running statement can be shown on its block.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from rootlang import ast
from rootlang.blocks import names as d
from rootlang.colors import Color
from rootlang.diagnostics import RootlangError, Span
from rootlang.formatting import INDENT, comment_line, format_program
from rootlang.forms import Body, Choice, Slot, Text, form_of
from rootlang.units import ONE_VALUE_FUNCTIONS, Quantity

if TYPE_CHECKING:
    from rootlang.grammar import LinesRead

__all__ = [
    "bubble_line",
    "comment_from_bubble",
    "default_value_block",
    "program_workspace",
    "to_workspace",
]

JSON = dict[str, Any]
ROW_HEIGHT = 28  # pixels per text line when scripts are stacked down the workspace
SCRIPT_GAP = 40


def to_workspace(
    source: str, file: str = "", language: str | None = None, lines_read: LinesRead | None = None
) -> JSON:
    """The workspace for a program (written in ``language``, else the one it declares);
    RootlangError (every syntax error) when it does not parse. ``lines_read``: lines read
    before (the studio converts one program again and again as the child types: only the
    lines changed are read again; the errors then come without their fixes)."""
    program = _parsed(source, file, language, lines_read)
    canonical = format_program(program)
    if canonical != source:
        program = _parsed(canonical, file, "en", lines_read)
    return program_workspace(program, canonical)


def _parsed(
    source: str, file: str, language: str | None, lines_read: LinesRead | None
) -> ast.Program:
    from rootlang.checks import parse  # lark loads lazily
    from rootlang.grammar import parse_lines

    if lines_read is None:
        return parse(source, file, language)
    program, found = parse_lines(source, file, language, lines_read=lines_read)
    if any(item.severity == "error" for item in found):
        raise RootlangError([item.in_file(file) for item in found if item.severity == "error"])
    return program


def program_workspace(program: ast.Program, canonical: str) -> JSON:
    """The workspace for a program parsed from its canonical text ``canonical``."""
    builder = _Builder(_layout(program, canonical.split("\n")))
    blocks: list[JSON] = []
    y = 20
    for item in program.items:
        block = builder.top_level(item)
        block["x"], block["y"] = 20, y
        blocks.append(block)
        y += (_last_line(item) - item.span.line + 1) * ROW_HEIGHT + SCRIPT_GAP
    workspace: JSON = {"blocks": {"languageVersion": 0, "blocks": blocks}}
    if builder.variables:
        workspace["variables"] = [
            {"name": name, "id": _variable_id(name)} for name in sorted(builder.variables)
        ]
    if not program.items and program.comments:  # nothing to hang them on: a workspace comment
        workspace["workspaceComments"] = [{
            "id": "comments", "x": 20, "y": 20, "width": 300, "height": 100,
            "text": canonical.rstrip("\n"),
        }]  # fmt: skip
    return workspace


def _last_line(item: ast.Node) -> int:
    return max(node.span.end_line for node in ast.walk(item))


def default_value_block(text: str) -> JSON:
    """The block for a value written as text (``10 cm``, ``note C4``): a toolbox default."""
    from rootlang.checks import parse

    program = parse(f"when started\n{INDENT}say {text}\n")
    statement = program.scripts[0].body[0]
    assert isinstance(statement, ast.Say)
    block = _Builder(_Layout()).expression(statement.text)
    return _without_ids(block)


def _without_ids(block: JSON) -> JSON:
    block.pop("id", None)
    for connection in block.get("inputs", {}).values():
        for child in connection.values():
            _without_ids(child)
    return block


def _variable_id(name: str) -> str:
    return f"v:{name}"


def _block_id(span: Span) -> str:
    return f"L{span.line}"


def _expression_id(span: Span) -> str:
    return f"L{span.line}C{span.column}E{span.end_column}"


# ---- where comments and blank lines belong -------------------------------------------------


@dataclass
class _Lines:
    """The comments and blank lines that go with one block: before each of its header lines
    (``if`` has one per ``else if`` and ``else``), at the end of each, and after the block."""

    # header index -> per line: "b" blank, "c" a comment (a line of the bubble), "e" an empty
    # `#` (kept here, not in the bubble: Blockly saves no bubble whose text is empty)
    before: dict[int, str] = field(default_factory=dict)
    end_of_line: set[int] = field(default_factory=set)
    empty_end_of_line: set[int] = field(default_factory=set)
    after: str = ""
    comments: list[str] = field(default_factory=list)  # in text order

    def data(self) -> str | None:
        layout: JSON = {}
        before = [self.before.get(index, "") for index in range(max(self.before, default=-1) + 1)]
        if any(before):
            layout["before"] = before
        if self.end_of_line:
            layout["eol"] = sorted(self.end_of_line)
        if self.empty_end_of_line:
            layout["eole"] = sorted(self.empty_end_of_line)
        if self.after:
            layout["after"] = self.after
        return json.dumps(layout, separators=(",", ":")) if layout else None


@dataclass
class _Layout:
    by_block: dict[str, _Lines] = field(default_factory=dict)

    def lines(self, block_id: str) -> _Lines:
        return self.by_block.setdefault(block_id, _Lines())


@dataclass(frozen=True)
class _HeaderLine:
    line: int
    depth: int
    block_id: str
    index: int  # which header line of its block (0, or an else-if / else of an `if`)


def _header_lines(program: ast.Program) -> Iterator[_HeaderLine]:
    def block(statements: ast.Block, depth: int) -> Iterator[_HeaderLine]:
        for statement in statements:
            block_id = _block_id(statement.span)
            if isinstance(statement, ast.If):
                for index, branch in enumerate(statement.branches):
                    yield _HeaderLine(branch.span.line, depth, block_id, index)
                    yield from block(branch.body, depth + 1)
                if statement.otherwise is not None:
                    else_line = (statement.else_span or statement.span).line
                    index = len(statement.branches)
                    yield _HeaderLine(else_line, depth, block_id, index)
                    yield from block(statement.otherwise, depth + 1)
            else:
                yield _HeaderLine(statement.span.line, depth, block_id, 0)
                body = getattr(statement, "body", None)
                if body is not None:
                    yield from block(body, depth + 1)

    for item in program.items:
        yield _HeaderLine(item.span.line, 0, _block_id(item.span), 0)
        yield from block(item.body, 1)


def _layout(program: ast.Program, lines: list[str]) -> _Layout:
    """Give each blank line and comment of the canonical text to a block: a comment at the
    depth of the next line goes before it; a deeper one after the last block at its depth."""
    layout = _Layout()
    headers = list(_header_lines(program))
    by_line = {header.line: header for header in headers}
    own_line = {c.span.line: c for c in program.comments if c.own_line}
    end_of_line = {c.span.line: c for c in program.comments if not c.own_line}
    last_at_depth: dict[int, _HeaderLine] = {}
    pending = ""  # blank lines ("b") and comments ("c") not yet given to a block
    pending_comments: list[str] = []
    next_header = 0
    for number in range(1, len(lines) + 1):
        header = by_line.get(number)
        if header is not None:
            next_header += 1
            if header.depth == 0:  # the blank line between scripts is always there
                pending = pending.removeprefix("b")
            owner = layout.lines(header.block_id)
            owner.before[header.index] = owner.before.get(header.index, "") + pending
            owner.comments.extend(pending_comments)
            pending, pending_comments = "", []
            comment = end_of_line.get(number)
            if comment is not None and not comment.text:
                owner.empty_end_of_line.add(header.index)
            elif comment is not None:
                owner.end_of_line.add(header.index)
                owner.comments.append(comment_line(comment))
            for depth in [depth for depth in last_at_depth if depth > header.depth]:
                del last_at_depth[depth]
            last_at_depth[header.depth] = header
            continue
        comment = own_line.get(number)
        if comment is None:
            if number < len(lines) and lines[number - 1] == "":
                pending += "b"
            continue
        depth = (comment.span.column - 1) // len(INDENT)
        following = headers[next_header] if next_header < len(headers) else None
        if comment.text:
            pending += "c"
            pending_comments.append(comment_line(comment))
        else:
            pending += "e"
        if following is not None and following.depth >= depth:
            continue  # goes before the next line, with the blank lines above it
        previous = last_at_depth.get(depth) or last_at_depth.get(max(last_at_depth, default=0))
        if previous is None:
            continue  # a file of comments only: the workspace keeps them on their own
        owner = layout.lines(previous.block_id)
        owner.after += pending
        owner.comments.extend(pending_comments)
        pending, pending_comments = "", []
    return layout


# ---- blocks --------------------------------------------------------------------------------


class _Builder:
    def __init__(self, layout: _Layout) -> None:
        self.layout = layout
        self.variables: set[str] = set()

    def top_level(self, item: ast.Script | ast.Procedure) -> JSON:
        if isinstance(item, ast.Script):
            block = self._form_block(item.event, _block_id(item.span))
        else:
            names = [parameter.name for parameter in item.parameters]
            fields = {"NAME": item.name, **{f"PARAM{i}": name for i, name in enumerate(names)}}
            block = {"type": d.PROCEDURE_BLOCK, "id": _block_id(item.span), "fields": fields,
                     "extraState": {"parameters": names}}  # fmt: skip
            self.variables.update(p.name for p in item.parameters)
        self._connect(block, "BODY", self.chain(item.body))
        return self._with_lines(block)

    def chain(self, statements: ast.Block) -> JSON | None:
        """A stack of statement blocks, each the ``next`` of the one before."""
        first: JSON | None = None
        previous: JSON | None = None
        for statement in statements:
            block = self.statement(statement)
            if previous is None:
                first = block
            else:
                previous["next"] = {"block": block}
            previous = block
        return first

    def statement(self, node: ast.Statement) -> JSON:
        block_id = _block_id(node.span)
        block: JSON
        match node:
            case ast.If(branches=branches, otherwise=otherwise):
                block = {"type": d.IF_BLOCK, "id": block_id}
                state: JSON = {}
                if len(branches) > 1:
                    state["elseIfCount"] = len(branches) - 1
                if otherwise is not None:
                    state["hasElse"] = True
                if state:
                    block["extraState"] = state
                for index, branch in enumerate(branches):
                    self._connect(block, f"IF{index}", self.expression(branch.condition))
                    self._connect(block, f"DO{index}", self.chain(branch.body))
                if otherwise is not None:
                    self._connect(block, "ELSE", self.chain(otherwise))
            case ast.Print(values=values):
                block = self._values_block(d.PRINT_BLOCK, block_id, values)
            case ast.SetVariable(name=name, value=value):
                block = self._variable_block(d.SET_BLOCK, block_id, name)
                self._connect(block, "VALUE", self.expression(value))
            case ast.ChangeVariable(name=name, by=by):
                block = self._variable_block(d.CHANGE_BLOCK, block_id, name)
                self._connect(block, "DELTA", self.expression(by))
            case ast.CallProcedure(name=name, arguments=arguments):
                block = self._values_block(d.CALL_BLOCK, block_id, arguments, name)
            case _:
                block = self._form_block(node, block_id)
        return self._with_lines(block)

    def _form_block(self, node: ast.Node, block_id: str) -> JSON:
        form = form_of(node)
        block: JSON = {"type": form.block, "id": block_id}
        for part in form.parts:
            if isinstance(part, Choice):
                self._field(block, part.field, part.label(getattr(node, part.field)))
            elif isinstance(part, Text):
                self._field(block, part.field, getattr(node, part.field))
            elif isinstance(part, Slot):
                value = self.expression(getattr(node, part.field))
                self._connect(block, d.field_name(part.field), value)
            elif isinstance(part, Body):
                self._connect(
                    block, d.field_name(part.field), self.chain(getattr(node, part.field))
                )
        return block

    def _with_lines(self, block: JSON) -> JSON:
        lines = self.layout.by_block.get(block["id"])
        if lines is None:
            return block
        data = lines.data()
        if data is not None:
            block["data"] = data
        if lines.comments:
            text = "\n".join(bubble_line(line) for line in lines.comments)
            block["icons"] = {"comment": {"text": text, "pinned": False,
                                          "height": 80, "width": 160}}  # fmt: skip
        return block

    def _variable_block(self, block_type: str, block_id: str, name: str) -> JSON:
        self.variables.add(name)
        return {"type": block_type, "id": block_id, "fields": {"VAR": {"id": _variable_id(name)}}}

    def _values_block(
        self, block_type: str, block_id: str, values: tuple[ast.Expression, ...], name: str = ""
    ) -> JSON:
        state: JSON = {"name": name} if name else {}
        state["values"] = len(values)
        block: JSON = {"type": block_type, "id": block_id, "extraState": state}
        for index, value in enumerate(values):
            self._connect(block, f"ARG{index}", self.expression(value))
        return block

    @staticmethod
    def _field(block: JSON, name: str, value: object) -> None:
        block.setdefault("fields", {})[d.field_name(name)] = value

    @staticmethod
    def _connect(block: JSON, name: str, child: JSON | None) -> None:
        if child is None:
            return
        kind = "shadow" if child.pop("_literal", False) else "block"
        block.setdefault("inputs", {})[name] = {kind: child}

    # ---- expressions -----------------------------------------------------------------------

    def expression(self, node: ast.Expression) -> JSON:
        block_id = _expression_id(node.span)
        match node:
            case ast.Literal(value=value, text=text):
                block = _literal(value, text, block_id)
                block["_literal"] = True
                return block
            case ast.Variable(name=name):
                return self._variable_block(d.GET_BLOCK, block_id, name)
            case ast.SensorRead():
                return self._form_block(node, block_id)
            case ast.WithUnit(operand=operand, unit=unit):
                block = {"type": d.WITH_UNIT_BLOCK, "id": block_id, "fields": {"UNIT": unit}}
                self._connect(block, "VALUE", self.expression(operand))
                return block
            case ast.Unary(op=op, operand=operand):
                kind = d.NOT_BLOCK if op == "not" else d.NEGATE_BLOCK
                block = {"type": kind, "id": block_id}
                self._connect(block, "VALUE", self.expression(operand))
                return block
            case ast.Binary(op=op, left=left, right=right):
                kind = next(k for k, ops in d.BINARY_BLOCKS.items() if op in ops)
                block = {"type": kind, "id": block_id, "fields": {"OP": op}}
                self._connect(block, "A", self.expression(left))
                self._connect(block, "B", self.expression(right))
                return block
            case ast.FunctionCall(function=function, arguments=arguments):
                return self._function(function, arguments, block_id)
            case ast.ProcedureCall(name=name, arguments=arguments):
                return self._values_block(d.CALL_VALUE_BLOCK, block_id, arguments, name)
        raise TypeError(f"no block for {type(node).__name__}")  # a bug in rootlang

    def _function(
        self, function: str, arguments: tuple[ast.Expression, ...], block_id: str
    ) -> JSON:
        count = len(arguments)
        inputs: tuple[str, ...]
        if function in ONE_VALUE_FUNCTIONS and count == 1:
            block: JSON = {"type": d.FUNCTION_BLOCK, "fields": {"FUNCTION": function}}
            inputs = ("VALUE",)
        elif function in ("min", "max") and count == 2:
            block, inputs = {"type": d.MIN_MAX_BLOCK, "fields": {"FUNCTION": function}}, ("A", "B")
        elif function == "random" and count == 2:
            block, inputs = {"type": d.RANDOM_BLOCK}, ("A", "B")
        elif function == "rgb" and count == 3:
            block, inputs = {"type": d.RGB_BLOCK}, ("RED", "GREEN", "BLUE")
        elif function == "join":
            return self._values_block(d.JOIN_BLOCK, block_id, arguments)
        else:  # a function given the wrong number of values (the checks say so): kept as is
            return self._values_block(d.CALL_VALUE_BLOCK, block_id, arguments, function)
        block["id"] = block_id
        for name, argument in zip(inputs, arguments, strict=True):
            self._connect(block, name, self.expression(argument))
        return block


def bubble_line(comment: str) -> str:
    """A comment line (canonical: ``#``, ``# text``, ``##text``, ``#  text``) as its block's
    bubble shows it: without the ``#`` and the one space after it, so ``# draw it`` shows
    ``draw it``; ``##x`` shows ``#x``, and ``# #x`` keeps its space (`` #x``) to stay apart."""
    text = comment[1:]
    plain = text.startswith(" ") and text[1:2] not in ("", " ", "#")
    return text[1:] if plain else text


def comment_from_bubble(line: str) -> str:
    """A bubble's line as a canonical comment again (the inverse of :func:`bubble_line`; a
    space or ``#`` a child typed first is kept, trailing spaces go as ``format`` drops them)."""
    line = line.rstrip()
    return f"#{line}" if not line or line[0] in " #" else f"# {line}"


def _literal(value: object, text: str, block_id: str) -> JSON:
    if isinstance(value, bool):
        return {"type": d.BOOLEAN_BLOCK, "id": block_id, "fields": {"BOOL": text}}
    if isinstance(value, str):
        return {"type": d.TEXT_BLOCK, "id": block_id, "fields": {"TEXT": value}}
    if isinstance(value, Color):
        if text.startswith("#"):
            return {"type": d.HEX_COLOR_BLOCK, "id": block_id, "fields": {"HEX": text}}
        if text.startswith("rgb "):
            block: JSON = {"type": d.RGB_BLOCK, "id": block_id, "inputs": {}}
            for index, (name, number) in enumerate(zip(("RED", "GREEN", "BLUE"), text.split()[1:],
                                                       strict=True)):  # fmt: skip
                channel = {"type": d.NUMBER_BLOCK, "id": f"{block_id}.{index + 1}",
                           "fields": {"NUM": _number(number)}}  # fmt: skip
                block["inputs"][name] = {"shadow": channel}
            return block
        return {"type": d.COLOR_BLOCK, "id": block_id, "fields": {"COLOR": text}}
    assert isinstance(value, Quantity)
    if text.startswith("-") and not text[1:2].isdigit():  # -note C4: a minus on the note
        minus: JSON = {"type": d.NEGATE_BLOCK, "id": block_id}
        minus["inputs"] = {"VALUE": {"shadow": _literal(value, text[1:], f"{block_id}.1")}}
        return minus
    if text.startswith("note "):
        return {"type": d.NOTE_BLOCK, "id": block_id, "fields": {"NOTE": text[5:]}}
    if not value.unit:
        return {"type": d.NUMBER_BLOCK, "id": block_id, "fields": {"NUM": _number(text)}}
    number = text[: len(text) - len(value.unit)].strip()
    return {"type": d.QUANTITY_BLOCKS[value.kind], "id": block_id,
            "fields": {"NUM": _number(number), "UNIT": value.unit}}  # fmt: skip


def _number(text: str) -> int | float:
    """A number field's value as Blockly keeps it (a JSON number)."""
    value = float(text)
    return int(value) if value == int(value) and abs(value) < 2**53 else value
