"""Blocks -> text: a Blockly workspace (its JSON serialization) back to the program.

Each block becomes the syntax-tree node its form describes (values made by the same functions
the parser uses), and the tree is printed by ``rootlang format``'s printer: the text is always
canonical, and a workspace made from a program gives back exactly that program's ``format``.
Each line gets the number it will have, so comments (from the blocks' comment bubbles) and
blank lines land where the block's ``data`` says they were; a bubble edited in the browser puts
its lines above the block.

Everything a workspace may get wrong (not a workspace, an unknown block, a missing value, a
block lying loose, a name a program can't hold) is a RootlangError naming the block.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from rootlang import ast, jsontree
from rootlang.blocks import names as d
from rootlang.blocks.definitions import field_defaults
from rootlang.blocks.text_to_blocks import comment_from_bubble, program_workspace
from rootlang.colors import Color
from rootlang.diagnostics import RootlangError, Span
from rootlang.formatting import INDENT, format_program
from rootlang.forms import EVENT_FORMS, Body, Choice, Form, Slot, Text
from rootlang.grammar import build, odd_character, terminal
from rootlang.grammar.build import number_text
from rootlang.grammar.rules import event_read_as
from rootlang.units import FUNCTIONS, ONE_VALUE_FUNCTIONS, Written
from rootlang.wording.shown import Code, Phrase

__all__ = ["Converted", "convert", "to_text"]

JSON = dict[str, Any]
_NAME, _NOTE, _HEX = terminal("NAME"), terminal("NOTE"), terminal("HEX_COLOR")  # the grammar's
_BUILT_IN_FUNCTIONS = frozenset(
    name for name, function in FUNCTIONS.items() if function.written is not Written.OWN_RULE
)


def to_text(workspace: Mapping[str, Any] | str, language: str | None = None) -> str:
    """The program a workspace shows, in canonical form with its keywords in ``language`` (by
    default as :func:`~rootlang.locale.translate.program_language` reads text: the command
    line's ``--language``, else the one it declares in a ``# language:`` comment, else English);
    RootlangError naming the block at fault when the workspace can't be a program."""
    return convert(workspace, language).text


@dataclass(frozen=True)
class Converted:
    """A workspace made a program: its ``text`` (in its language), and the canonical English
    text and the syntax tree that text reads back as."""

    text: str
    english: str
    program: ast.Program

    def text_workspace(self) -> JSON:
        """The text's own blocks, as :func:`~rootlang.blocks.to_workspace` gives them for
        ``text`` (ids from its lines): without parsing the text again."""
        return program_workspace(self.program, self.english)


def convert(workspace: Mapping[str, Any] | str, language: str | None = None) -> Converted:
    """:func:`to_text`, with the program the text reads back as."""
    from rootlang.locale.translate import from_english, program_language

    builder = _Builder(_workspace(workspace))
    try:
        program = builder.program()
    except RecursionError:  # blocks inside blocks deeper than any program needs
        raise RootlangError.of("E701", reason="its blocks are nested too deep") from None
    text = format_program(program)
    read = _reads_back(text, program)
    return Converted(from_english(text, program_language(text, language)), text, read)


def _reads_back(text: str, program: ast.Program) -> ast.Program:
    """The text must read back as the program the blocks make, and as itself (``format``
    leaves it as it is): the blocks are checked one by one above, and this is the net under
    them, so no combination of blocks ever gives a file rootlang can't read, that means
    something else, or that ``format`` would change (E707). The program it reads back as."""
    from rootlang.checks import parse

    try:
        read = parse(text, "", "en")
        again = format_program(read)
    except RootlangError as error:
        raise RootlangError.of("E707", reason=error.diagnostics[0]) from None
    if not ast.same_tree(read, program):
        line = next(
            (
                one.span.line
                for one, other in zip(ast.walk(read), ast.walk(program), strict=False)
                if isinstance(one, ast.Expression) and not ast.same_tree(one, other)
            ),
            1,
        )
        raise RootlangError.of("E707", reason=f"line {line} would read back as something else")
    if again != text:
        line = next(
            number
            for number, (one, other) in enumerate(
                zip([*text.split("\n"), ""], [*again.split("\n"), ""], strict=False), 1
            )
            if one != other
        )
        reason = f"line {line} would read back as {again.split(chr(10))[line - 1]!r}"
        raise RootlangError.of("E707", reason=reason)
    return read


def _workspace(workspace: Mapping[str, Any] | str) -> JSON:
    if isinstance(workspace, str):
        try:
            loaded = jsontree.loads(workspace)  # a long script nests deep: see jsontree
        except ValueError as error:
            raise RootlangError.of("E701", reason=f"it is not JSON ({error})") from None
    else:
        loaded = dict(workspace)
    if not isinstance(loaded, dict):
        raise RootlangError.of("E701", reason="it is not a JSON object")
    blocks = loaded.get("blocks", {"blocks": []})
    if not isinstance(blocks, dict) or not isinstance(blocks.get("blocks", []), list):
        raise RootlangError.of("E701", reason='"blocks" holds no list of blocks')
    from rootlang.blocks.pictures import to_words  # Level 1's picture blocks: their word blocks

    try:
        return to_words(loaded)
    except RecursionError:
        raise RootlangError.of("E701", reason="its blocks are nested too deep") from None


def _block_error(
    code: str, block_type: object, block_id: object, **values: object
) -> RootlangError:
    return RootlangError.of(code, Span(0, 0, 0, 0), block=block_type, id=block_id, **values)


class _Builder:
    """Builds the syntax tree a workspace shows. Each line gets a number as it would be
    written, so the printer puts the blank lines and comments where the blocks' data says."""

    def __init__(self, workspace: JSON) -> None:
        self.top = _mapping(workspace.get("blocks")).get("blocks", [])
        self.variables: dict[str, str] = {}
        variables = workspace.get("variables")
        for variable in variables if isinstance(variables, list) else []:
            if isinstance(variable, dict) and isinstance(variable.get("id"), str):
                self.variables[variable["id"]] = str(variable.get("name", ""))
        self.procedures: dict[str, int] = {}
        comments = workspace.get("workspaceComments")
        self.workspace_comments = [
            _mapping(comment) for comment in (comments if isinstance(comments, list) else [])
        ]
        self.line = 0
        self.comments: list[ast.Comment] = []
        self.calculations = 0  # value blocks inside each other where the builder is

    # ---- structure -------------------------------------------------------------------------

    def program(self) -> ast.Program:
        self._workspace_comments()
        blocks = [self._checked(block) for block in self.top]
        for block in blocks:
            if block["type"] == d.PROCEDURE_BLOCK:
                name = self._name(block, _field(block, "NAME"), procedure=True)
                self.procedures[name] = len(self._parameters(block))
        scripts: list[ast.Script] = []
        procedures: list[ast.Procedure] = []
        for block in blocks:
            if block["type"] == d.PROCEDURE_BLOCK:
                procedures.append(self._procedure(block))
            elif _is_event(block["type"]):
                scripts.append(self._script(block))
            else:
                raise _block_error("E704", block["type"], block.get("id"))
            self.line += 1  # the blank line between scripts
        span = Span(1, 1, max(self.line, 1), 1)
        return ast.Program(span, tuple(scripts), tuple(procedures), "", tuple(self.comments))

    def _workspace_comments(self) -> None:
        """Comments lying on the workspace (not on a block) open the program, line by line,
        as they are written in a program: a blank line stays blank, a line starting with
        ``#`` is that comment, any other line is a comment with ``# `` put before it."""
        for comment in self.workspace_comments:
            block = {"type": "workspace comment", "id": comment.get("id")}
            for line in _comment_lines(block, comment.get("text", "")):
                self.line += 1
                if line.strip():
                    written = line.rstrip() if line.startswith("#") else f"# {line.strip()}"
                    span = Span(self.line, 1, self.line, 2)
                    self.comments.append(ast.Comment(span, written[1:], True))
            self.line += 1

    def _checked(self, block: object) -> JSON:
        if not isinstance(block, dict) or not isinstance(block.get("type"), str):
            raise RootlangError.of("E701", reason="a block without a type")
        block_type = block["type"]
        known = (
            block_type in d.FORMS_BY_BLOCK
            or block_type in _STATEMENTS
            or block_type in _EXPRESSIONS
        )
        if not known:
            raise _block_error("E702", block_type, block.get("id"))
        return block

    def _header(
        self, lines: _Lines, index: int, depth: int, block: JSON, inputs: list[str] | None = None
    ) -> Span:
        """The span of a header line, after the blank lines and comments above it: the
        block's own, then those on the values in ``inputs`` (None: all of them) — a line of
        text has no place for a value's comment of its own, so it goes above the line."""
        values = [("c", line) for line in _value_comments(block, inputs)]
        self._extra_lines([*lines.before(index), *values], depth)
        self.line += 1
        column = depth * len(INDENT) + 1
        end = lines.end_of_line(index)
        if end is not None:
            span = Span(self.line, column + 1_000, self.line, column + 1_001)
            self.comments.append(ast.Comment(span, comment_from_bubble(end)[1:], False))
        return Span(self.line, column, self.line, column + 1)

    def _extra_lines(self, lines: list[tuple[str, str]], depth: int) -> None:
        for kind, comment in lines:
            self.line += 1
            if kind in "ce":
                column = depth * len(INDENT) + 1
                span = Span(self.line, column, self.line, column + 1)
                self.comments.append(ast.Comment(span, comment_from_bubble(comment)[1:], True))

    def _script(self, block: JSON) -> ast.Script:
        lines = _Lines(block, 1)
        span = self._header(lines, 0, 0, block)
        form = d.FORMS_BY_BLOCK[block["type"]]
        event = self._form_node(block, form, span)
        assert isinstance(event, ast.Event)
        if isinstance(event, ast.ConditionBecomesTrue):  # as the parser reads its line
            event = event_read_as(span, event.condition)
        body = self._body(block, "BODY", 1)
        self._extra_lines(lines.after(), 0)
        return ast.Script(span, event, body)

    def _procedure(self, block: JSON) -> ast.Procedure:
        lines = _Lines(block, 1)
        span = self._header(lines, 0, 0, block)
        name = self._name(block, _field(block, "NAME"), procedure=True)
        parameters = tuple(ast.Parameter(span, p) for p in self._parameters(block))
        body = self._body(block, "BODY", 1)
        self._extra_lines(lines.after(), 0)
        return ast.Procedure(span, name, parameters, body)

    def _body(self, block: JSON, name: str, depth: int) -> ast.Block:
        """The statements in a statement input: a block and the ones below it (``depth`` 1:
        a script's own)."""
        if depth > ast.NESTING_LIMIT + 1:  # counted: never deeper than a program may go
            raise _cannot_hold(block, what=f"more than {ast.NESTING_LIMIT} blocks around it",
                               fix="take some blocks out, or make a procedure.")  # fmt: skip
        statements: list[ast.Statement] = []
        current: Any = self._input(block, name, required=True, statement=True)
        while current is not None:
            current = self._checked(current)
            statements.append(self._statement(current, depth))
            following = current.get("next")
            current = following.get("block") if isinstance(following, dict) else None
        return tuple(statements)

    def _statement(self, block: JSON, depth: int) -> ast.Statement:
        block_type = block["type"]
        if block_type == d.IF_BLOCK:
            return self._if(block, depth)
        lines = _Lines(block, 1)
        span = self._header(lines, 0, depth, block)
        statement: ast.Statement
        if block_type == d.PRINT_BLOCK:
            statement = ast.Print(span, self._values(block, span))
        elif block_type == d.CALL_BLOCK:
            name = self._name(block, _mapping(block.get("extraState")).get("name"), procedure=True)
            statement = ast.CallProcedure(span, name, self._values(block, span), span)
        elif block_type == d.SET_BLOCK:
            value = self._value(block, "VALUE", span)
            statement = ast.SetVariable(span, self._variable(block), value)
        elif block_type == d.CHANGE_BLOCK:
            by = self._value(block, "DELTA", span)
            statement = ast.ChangeVariable(span, self._variable(block), by)
        else:
            form = d.FORMS_BY_BLOCK.get(block_type)
            if form is None or form.node is ast.SensorRead or form in EVENT_FORMS:
                needs = "to be inside another block: it gives a value"
                if form is not None and form in EVENT_FORMS:
                    needs = "to stand at the top of a script"
                raise _needs(block, needs=needs)
            node = self._form_node(block, form, span, depth)
            assert isinstance(node, ast.Statement)
            statement = node
        self._extra_lines(lines.after(), depth)
        return statement

    def _if(self, block: JSON, depth: int) -> ast.If:
        state = _mapping(block.get("extraState"))
        count = state.get("elseIfCount", 0)
        if not isinstance(count, int) or not 0 <= count < 10_000:
            raise _needs(block, needs="a number of else-ifs (extraState.elseIfCount)")  # fmt: skip
        has_else = bool(state.get("hasElse"))
        lines = _Lines(block, count + 1 + has_else)
        branches: list[ast.Branch] = []
        first: Span | None = None
        for index in range(count + 1):
            span = self._header(lines, index, depth, block, [f"IF{index}"])
            first = first or span
            condition = self._value(block, f"IF{index}", span)
            branches.append(ast.Branch(span, condition, self._body(block, f"DO{index}", depth + 1)))
        otherwise: ast.Block | None = None
        else_span: Span | None = None
        if has_else:
            else_span = self._header(lines, count + 1, depth, block, [])
            otherwise = self._body(block, "ELSE", depth + 1)
        self._extra_lines(lines.after(), depth)
        assert first is not None
        return ast.If(first, tuple(branches), otherwise, else_span)

    # ---- parts -----------------------------------------------------------------------------

    def _form_node(self, block: JSON, form: Form, span: Span, depth: int = 0) -> ast.Node:
        values: dict[str, Any] = dict(form.fixed)
        for part in form.parts:
            if isinstance(part, Choice):
                label = _field(block, d.field_name(part.field))
                try:
                    values[part.field] = part.value_of_label(str(label))
                except KeyError:
                    options = ", ".join(part.label(value) for value, _ in part.options)
                    raise _needs(block, needs=f"one of {options} in {d.field_name(part.field)}",
                                       ) from None  # fmt: skip
            elif isinstance(part, Slot):
                values[part.field] = self._value(block, d.field_name(part.field), span)
            elif isinstance(part, Text):
                values[part.field] = self._string(block, _field(block, d.field_name(part.field)))
            elif isinstance(part, Body):
                values[part.field] = self._body(block, d.field_name(part.field), depth + 1)
        return form.node(span=span, **values)

    def _input(self, block: JSON, name: str, *, required: bool, statement: bool = False) -> Any:
        connection = _mapping(_mapping(block.get("inputs")).get(name))
        child = connection.get("block") or connection.get("shadow")
        if child is None and required:
            needs = f"blocks inside it ({name})" if statement else f"a value in {name}"
            raise _needs(block, needs=needs)
        return child

    def _value(self, block: JSON, name: str, span: Span) -> ast.Expression:
        return self._expression(self._input(block, name, required=True), span)

    def _values(self, block: JSON, span: Span) -> tuple[ast.Expression, ...]:
        count = self._count(block)
        return tuple(self._value(block, f"ARG{index}", span) for index in range(count))

    def _count(self, block: JSON) -> int:
        count = _mapping(block.get("extraState")).get("values", 0)
        if not isinstance(count, int) or count < 0:
            raise _needs(block, needs="a number of values (extraState.values)")  # fmt: skip
        return count

    def _parameters(self, block: JSON) -> list[str]:
        parameters = _mapping(block.get("extraState")).get("parameters", [])
        if not isinstance(parameters, list):
            raise _needs(block, needs="a list of parameters")
        return [self._name(block, parameter) for parameter in parameters]

    def _name(self, block: JSON, name: object, *, procedure: bool = False) -> str:
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            raise _cannot_hold(block, what=f"the name {name!r}",
                               fix="names start with a letter, then letters a to z, digits "
                               "or _ (no spaces).")  # fmt: skip
        from rootlang.checks import usable_name

        if not usable_name(name.lower(), procedure=procedure):
            raise _cannot_hold(
                block,
                what=f"the name {name!r}",
                fix="that is a word of the language; pick another name.",
            )
        return name.lower()

    def _variable(self, block: JSON) -> str:
        reference = _field(block, "VAR")
        name = None
        if isinstance(reference, dict):
            name = self.variables.get(str(reference.get("id")), reference.get("name"))
        return self._name(block, name)

    def _string(self, block: JSON, value: object) -> str:
        if not isinstance(value, str) or odd_character(value) or ('"' in value and "”" in value):
            raise _cannot_hold(block, what=f"the text {value!r}",
                               fix="a text is one line, with no \" and ” both in it, "
                               "and no control characters.")  # fmt: skip
        return value

    def _number(self, block: JSON, field: str) -> float:
        value = _field(block, field)
        try:
            number = float(value)
        except (TypeError, ValueError, OverflowError):  # OverflowError: 10**400
            number = math.nan
        if not math.isfinite(number) or abs(number) > 1e15:
            raise _cannot_hold(block, what=f"the number {value!r}",
                               fix="write a number, like 10 or 2.5.")  # fmt: skip
        return float(number_text(number))

    def _choice(self, block: JSON, field: str, allowed: Any) -> str:
        value = _field(block, field)
        if not isinstance(value, str) or value not in allowed:
            raise _needs(block, needs=f"one of {', '.join(allowed)} in {field}")  # fmt: skip
        return value

    # ---- expressions -----------------------------------------------------------------------

    def _expression(self, block: Any, span: Span) -> ast.Expression:
        self.calculations += 1  # the value blocks this one is inside, and itself
        try:
            return self._counted_expression(block, span)
        finally:
            self.calculations -= 1

    def _counted_expression(self, block: Any, span: Span) -> ast.Expression:
        block = self._checked(block)
        if self.calculations > ast.NESTING_LIMIT + 1:  # counted: as deep as a line may go
            raise _cannot_hold(block, what=f"more than {ast.NESTING_LIMIT} values around it",
                               fix="work the value out in smaller steps.")  # fmt: skip
        block_type = block["type"]
        form = d.FORMS_BY_BLOCK.get(block_type)
        if form is not None and form.node is ast.SensorRead:
            node = self._form_node(block, form, span)
            assert isinstance(node, ast.Expression)
            return node
        make = _EXPRESSIONS.get(block_type)
        if make is None:
            raise _needs(block, needs="to stand on its own line: it gives no value")  # fmt: skip
        expression: ast.Expression = make(self, block, span)
        return expression

    def _number_block(self, block: JSON, span: Span) -> ast.Expression:
        return build.number_literal(span, self._number(block, "NUM"))

    def _quantity(self, block: JSON, span: Span) -> ast.Expression:
        kind = next(kind for kind, name in d.QUANTITY_BLOCKS.items() if name == block["type"])
        units = [unit.name for unit in d.UNITS.values() if unit.kind is kind]
        unit = self._choice(block, "UNIT", units)
        number = self._number(block, "NUM")
        magnitude = build.with_unit(span, build.number_literal(span, abs(number)), unit)
        return build.minus(span, magnitude) if number < 0 else magnitude

    def _text(self, block: JSON, span: Span) -> ast.Expression:
        return build.text_literal(span, self._string(block, _field(block, "TEXT")))

    def _boolean(self, block: JSON, span: Span) -> ast.Expression:
        return build.boolean_literal(span, self._choice(block, "BOOL", ("true", "false")) == "true")

    def _color(self, block: JSON, span: Span) -> ast.Expression:
        name = self._choice(block, "COLOR", tuple(d.NAMED_COLORS))
        return build.color_literal(span, d.NAMED_COLORS[name])

    def _hex(self, block: JSON, span: Span) -> ast.Expression:
        value = _field(block, "HEX")
        if not isinstance(value, str) or not _HEX.fullmatch(value):
            raise _cannot_hold(
                block,
                what=f"the colour {value!r}",
                fix="write a colour as # and six digits 0-9 or a-f, like #ff8000.",
            )
        return build.color_literal(span, Color.from_hex(value))

    def _note(self, block: JSON, span: Span) -> ast.Expression:
        value = _field(block, "NOTE")
        if not isinstance(value, str) or not _NOTE.fullmatch(value.strip()):
            raise _cannot_hold(block, what=f"the note {value!r}",
                               fix="write a note as a letter A to G, maybe # or b, and an "
                               "octave: C4, F#5, Bb3.")  # fmt: skip
        return build.note_literal(span, value.strip())

    def _rgb(self, block: JSON, span: Span) -> ast.Expression:
        channels = [self._value(block, name, span) for name in ("RED", "GREEN", "BLUE")]
        return build.rgb(span, channels)

    def _with_unit(self, block: JSON, span: Span) -> ast.Expression:
        unit = self._choice(block, "UNIT", d.ALL_UNITS)
        return build.with_unit(span, self._value(block, "VALUE", span), unit)

    def _negate(self, block: JSON, span: Span) -> ast.Expression:
        return build.minus(span, self._value(block, "VALUE", span))

    def _not(self, block: JSON, span: Span) -> ast.Expression:
        return ast.Unary(span, "not", self._value(block, "VALUE", span))

    def _binary(self, block: JSON, span: Span) -> ast.Expression:
        operator = self._choice(block, "OP", tuple(d.BINARY_BLOCKS[block["type"]]))
        left, right = self._value(block, "A", span), self._value(block, "B", span)
        return ast.Binary(span, operator, left, right)

    def _function(self, block: JSON, span: Span) -> ast.Expression:
        name = self._choice(block, "FUNCTION", ONE_VALUE_FUNCTIONS)
        return ast.FunctionCall(span, name, (self._value(block, "VALUE", span),))

    def _min_max(self, block: JSON, span: Span) -> ast.Expression:
        name = self._choice(block, "FUNCTION", ("min", "max"))
        values = (self._value(block, "A", span), self._value(block, "B", span))
        return ast.FunctionCall(span, name, values)

    def _random(self, block: JSON, span: Span) -> ast.Expression:
        values = (self._value(block, "A", span), self._value(block, "B", span))
        return ast.FunctionCall(span, "random", values)

    def _join(self, block: JSON, span: Span) -> ast.Expression:
        return ast.FunctionCall(span, "join", self._some_values(block, span))

    def _some_values(self, block: JSON, span: Span) -> tuple[ast.Expression, ...]:
        """A function's values: at least one (``join()`` is no text rootlang reads)."""
        if self._count(block) == 0:
            raise _needs(block, needs="at least one value (press + to add one)")
        return self._values(block, span)

    def _call_value(self, block: JSON, span: Span) -> ast.Expression:
        raw_name = _mapping(block.get("extraState")).get("name")
        count = self._count(block)
        if isinstance(raw_name, str) and raw_name.lower() in _BUILT_IN_FUNCTIONS:
            return ast.FunctionCall(span, raw_name.lower(), self._some_values(block, span))
        name = self._name(block, raw_name, procedure=True)
        takes = self.procedures.get(name)
        if takes is None:
            there_is_none = f" block: there is no procedure {name}"
            raise _needs(block, needs=Phrase(("a ", Code(f"to {name}"), there_is_none)))
        if (count == 0) != (takes == 0):
            raise _needs(block, needs=f"{takes} values for {name}")  # fmt: skip
        return ast.ProcedureCall(span, name, self._values(block, span))

    def _get(self, block: JSON, span: Span) -> ast.Expression:
        return ast.Variable(span, self._variable(block))


def _needs(block: JSON, *, needs: str | Phrase) -> RootlangError:
    """E703: the block misses something, or stands where it can't."""
    return _block_error("E703", block["type"], block.get("id"), needs=needs)


def _cannot_hold(block: JSON, *, what: str, fix: str) -> RootlangError:
    """E705: the block holds a value a program can't hold."""
    return _block_error("E705", block["type"], block.get("id"), what=what, fix=fix)


def _mapping(value: object) -> JSON:
    """A JSON object, or an empty one for anything else (a workspace may hold anything)."""
    return value if isinstance(value, dict) else {}


def _field(block: JSON, name: str) -> Any:
    """A field's value; one the workspace leaves out has the value a new block shows."""
    fields = block.get("fields")
    if isinstance(fields, dict) and name in fields:
        return fields[name]
    return field_defaults(block["type"]).get(name)


def _is_event(block_type: str) -> bool:
    form = d.FORMS_BY_BLOCK.get(block_type)
    return form is not None and form in EVENT_FORMS


_STATEMENTS = frozenset(
    {d.IF_BLOCK, d.PROCEDURE_BLOCK, d.PRINT_BLOCK, d.CALL_BLOCK, d.SET_BLOCK, d.CHANGE_BLOCK}
)
_EXPRESSIONS: dict[str, Any] = {
    d.NUMBER_BLOCK: _Builder._number_block,
    **{block: _Builder._quantity for block in d.QUANTITY_BLOCKS.values()},
    d.TEXT_BLOCK: _Builder._text,
    d.BOOLEAN_BLOCK: _Builder._boolean,
    d.COLOR_BLOCK: _Builder._color,
    d.HEX_COLOR_BLOCK: _Builder._hex,
    d.RGB_BLOCK: _Builder._rgb,
    d.NOTE_BLOCK: _Builder._note,
    d.WITH_UNIT_BLOCK: _Builder._with_unit,
    d.NEGATE_BLOCK: _Builder._negate,
    d.NOT_BLOCK: _Builder._not,
    **{block: _Builder._binary for block in d.BINARY_BLOCKS},
    d.FUNCTION_BLOCK: _Builder._function,
    d.MIN_MAX_BLOCK: _Builder._min_max,
    d.RANDOM_BLOCK: _Builder._random,
    d.JOIN_BLOCK: _Builder._join,
    d.CALL_VALUE_BLOCK: _Builder._call_value,
    d.GET_BLOCK: _Builder._get,
}


def _pattern(value: object) -> str:
    """Blank lines ("b"), comments ("c") and empty ``#`` comments ("e"); anything else in a
    layout is left out."""
    return "".join(kind for kind in value if kind in "bce") if isinstance(value, str) else ""


def _comment_lines(block: JSON, text: object) -> list[str]:
    """A comment bubble's lines (``\\n`` parts them, as Blockly's text box does); a line
    holding another line break (CR, U+2028 ...) or a control character is refused (E705):
    written out it would start a line of program of its own."""
    lines = str(text).split("\n")
    for line in lines:
        if odd_character(line):
            raise _cannot_hold(
                block,
                what=f"the comment {line!r}",
                fix="a line of a comment can't hold a line break or a control character.",
            )
    return lines


def _value_comments(block: JSON, inputs: list[str] | None) -> list[str]:
    """The comment lines on the value blocks in a block's ``inputs`` (None: all of them), in
    the order they read, the values inside a value included (walked with a list of its own:
    values can nest deeper than Python's stack before they are counted)."""
    found: list[str] = []
    todo = _values_in(block, inputs)[::-1]
    while todo:
        child = todo.pop()
        comment = _mapping(_mapping(child.get("icons")).get("comment")).get("text")
        if comment is not None:
            found.extend(_comment_lines(child, comment))
        todo.extend(_values_in(child, None)[::-1])
    return found


def _values_in(block: JSON, inputs: list[str] | None) -> list[JSON]:
    """The value blocks plugged into a block's ``inputs`` (None: all of them), in order."""
    values: list[JSON] = []
    connections = _mapping(block.get("inputs"))
    for name in connections if inputs is None else inputs:
        connection = _mapping(connections.get(name))
        for child in (connection.get("block"), connection.get("shadow")):
            if isinstance(child, dict) and _gives_value(child.get("type")):
                values.append(child)
                break  # a block over a shadow: the shadow is not shown
    return values


def _gives_value(block_type: object) -> bool:
    if not isinstance(block_type, str):
        return False
    form = d.FORMS_BY_BLOCK.get(block_type)
    return block_type in _EXPRESSIONS or (form is not None and form.node is ast.SensorRead)


class _Lines:
    """Where a block's comments and blank lines go (its ``data``), filled from its bubble."""

    def __init__(self, block: JSON, headers: int) -> None:
        layout: JSON = {}
        raw = block.get("data")
        if isinstance(raw, str) and raw.startswith("{"):
            try:
                layout = _mapping(json.loads(raw))
            except ValueError:
                layout = {}
        before = layout.get("before")
        before = before if isinstance(before, list) else []
        self._before = [_pattern(p) for p in before][:headers]
        self._before += [""] * (headers - len(self._before))
        self._eol = _indices(layout.get("eol"))
        self.empty_eol = _indices(layout.get("eole"))
        after = layout.get("after")
        self._after = _pattern(after)
        comment = _mapping(_mapping(block.get("icons")).get("comment")).get("text")
        self._comments = _comment_lines(block, comment) if comment is not None else []
        slots = sum(p.count("c") for p in self._before) + len(self._eol) + self._after.count("c")
        if slots != len(self._comments):  # the bubble was edited: its lines go above the block
            kept = [p.replace("c", "") for p in self._before]  # blank lines and empty `#`s
            self._before = [kept[0] + "c" * len(self._comments), *kept[1:]]
            self._eol, self._after = set(), self._after.replace("c", "")
        self._next = 0

    def _take(self) -> str:
        comment = self._comments[self._next]
        self._next += 1
        return comment

    def before(self, index: int) -> list[tuple[str, str]]:
        return [(kind, self._take() if kind == "c" else "") for kind in self._before[index]]

    def end_of_line(self, index: int) -> str | None:
        if index in self._eol:
            return self._take()
        return "" if index in self.empty_eol else None

    def after(self) -> list[tuple[str, str]]:
        return [(kind, self._take() if kind == "c" else "") for kind in self._after]


def _indices(value: object) -> set[int]:
    return (
        {index for index in value if isinstance(index, int)} if isinstance(value, list) else set()
    )
