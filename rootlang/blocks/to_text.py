"""Blocks -> text: a Blockly workspace (its JSON serialization) back to the program.

Each block is written as the words its form gives it, every value in brackets; the result is
then parsed and printed by ``rootlang format``, which drops the brackets the meaning does not
need. So the text is always canonical, and a workspace made from a program gives back exactly
that program's ``format``. Comments come back from the blocks' comment bubbles, put where the
block's ``data`` says they were; a bubble edited in the browser puts its lines above the block.

Everything a workspace may get wrong (not a workspace, an unknown block, a missing value, a
block lying loose, a name a program can't hold) is a RootlangError naming the block.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Mapping
from typing import Any

from rootlang import ast
from rootlang.blocks import definitions as d
from rootlang.blocks.to_blocks import comment_from_bubble
from rootlang.diagnostics import RootlangError, Span
from rootlang.formatting import INDENT, format_source
from rootlang.forms import EVENT_FORMS, Body, Choice, Form, Slot, Text, Word
from rootlang.grammar.build import number_text, quantity_text, string_text
from rootlang.units import FUNCTIONS

__all__ = ["to_text"]

JSON = dict[str, Any]
_NAME = re.compile(r"[a-z][a-z0-9_]*", re.IGNORECASE)
_NOTE = re.compile(r"[a-g](#|b)?[0-9]", re.IGNORECASE)
_HEX = re.compile(r"#[0-9a-f]{6}", re.IGNORECASE)
_BUILT_IN_FUNCTIONS = frozenset(FUNCTIONS) - {"random"}


def to_text(workspace: Mapping[str, Any] | str) -> str:
    """The program a workspace shows, in canonical form; RootlangError naming the block at
    fault when the workspace can't be a program."""
    state = _workspace(workspace)
    writer = _Writer(state)
    raw = writer.program()
    try:
        return format_source(raw)
    except RootlangError as error:  # something a block holds reads wrong as text
        first = error.diagnostics[0]
        block_type, block_id = writer.owner_of(first.span.line)
        raise _block_error("E705", block_type, block_id, what="something that doesn't read",
                           fix=first.message) from None  # fmt: skip


def _workspace(workspace: Mapping[str, Any] | str) -> JSON:
    if isinstance(workspace, str):
        try:
            loaded = json.loads(workspace)
        except ValueError as error:
            raise RootlangError.of("E701", reason=f"it is not JSON ({error})") from None
    else:
        loaded = dict(workspace)
    if not isinstance(loaded, dict):
        raise RootlangError.of("E701", reason="it is not a JSON object")
    blocks = loaded.get("blocks", {"blocks": []})
    if not isinstance(blocks, dict) or not isinstance(blocks.get("blocks", []), list):
        raise RootlangError.of("E701", reason='"blocks" holds no list of blocks')
    return loaded


def _block_error(
    code: str, block_type: object, block_id: object, **values: object
) -> RootlangError:
    return RootlangError.of(code, Span(0, 0, 0, 0), block=block_type, id=block_id, **values)


class _Writer:
    def __init__(self, workspace: JSON) -> None:
        self.top = workspace.get("blocks", {}).get("blocks", [])
        self.variables: dict[str, str] = {}
        for variable in workspace.get("variables", []) or []:
            if isinstance(variable, dict) and isinstance(variable.get("id"), str):
                self.variables[variable["id"]] = str(variable.get("name", ""))
        self.lines: list[str] = []
        self.owners: list[tuple[str, str]] = []
        self.procedures: dict[str, int] = {}

    def owner_of(self, line: int) -> tuple[str, str]:
        if 1 <= line <= len(self.owners):
            return self.owners[line - 1]
        return ("workspace", "-")

    # ---- structure -------------------------------------------------------------------------

    def program(self) -> str:
        blocks = [self._checked(block) for block in self.top]
        for block in blocks:
            if block["type"] == d.PROCEDURE_BLOCK:
                parameters = self._parameters(block)
                self.procedures[self._name(block, block.get("fields", {}).get("NAME"))] = len(
                    parameters
                )
        for block in blocks:
            if block["type"] != d.PROCEDURE_BLOCK and not _is_event(block["type"]):
                raise _block_error("E704", block["type"], block.get("id"))
            self._statement(block, 0)
            self._write("", block)
        return "\n".join(self.lines) + "\n"

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

    def _write(self, text: str, block: JSON) -> None:
        self.lines.append(text)
        self.owners.append((block["type"], str(block.get("id"))))

    def _statement(self, block: JSON, depth: int) -> None:
        """One statement block (with its body), and the ones below it."""
        current: JSON | None = block
        while current is not None:
            current = self._checked(current)
            headers = self._headers(current)
            lines = _Lines(current, len(headers))
            for index, (text, body) in enumerate(headers):
                for kind, comment in lines.before(index):
                    self._write(
                        f"{INDENT * depth}{comment_from_bubble(comment)}" if kind == "c" else "",
                        current,
                    )
                end = lines.end_of_line(index)
                if end is not None:
                    text = f"{text}  {comment_from_bubble(end)}"
                self._write(f"{INDENT * depth}{text}", current)
                if body is not None:
                    child = self._input(current, body, required=True, statement=True)
                    self._statement(child, depth + 1)
            for kind, comment in lines.after():
                self._write(
                    f"{INDENT * depth}{comment_from_bubble(comment)}" if kind == "c" else "",
                    current,
                )
            following = current.get("next")
            current = following.get("block") if isinstance(following, dict) else None

    def _headers(self, block: JSON) -> list[tuple[str, str | None]]:
        """The header lines of a block, each with the input holding its body (if any)."""
        block_type = block["type"]
        if block_type == d.IF_BLOCK:
            state = block.get("extraState") or {}
            lines: list[tuple[str, str | None]] = []
            for index in range(int(state.get("elseIfCount", 0)) + 1):
                keyword = "if" if index == 0 else "else if"
                lines.append((f"{keyword} {self._value(block, f'IF{index}')}", f"DO{index}"))
            if state.get("hasElse"):
                lines.append(("else", "ELSE"))
            return lines
        if block_type == d.PROCEDURE_BLOCK:
            name = self._name(block, block.get("fields", {}).get("NAME"))
            parameters = ", ".join(self._parameters(block))
            return [(f"to {name} {parameters}".rstrip(), "BODY")]
        if block_type == d.PRINT_BLOCK:
            return [(f"print {self._values(block)}".rstrip(), None)]
        if block_type == d.CALL_BLOCK:
            name = self._name(block, (block.get("extraState") or {}).get("name"))
            return [(f"{name} {self._values(block)}".rstrip(), None)]
        if block_type == d.SET_BLOCK:
            return [(f"set {self._variable(block)} to {self._value(block, 'VALUE')}", None)]
        if block_type == d.CHANGE_BLOCK:
            return [(f"change {self._variable(block)} by {self._value(block, 'DELTA')}", None)]
        form = d.FORMS_BY_BLOCK.get(block_type)
        if form is None or form.node is ast.SensorRead:
            raise _block_error("E703", block_type, block.get("id"),
                               needs="to be inside another block: it gives a value")  # fmt: skip
        text = self._form(block, form)
        if form in EVENT_FORMS:
            return [(f"when {text}", "BODY")]
        body = next((d.field_name(p.field) for p in form.parts if isinstance(p, Body)), None)
        return [(text, body)]

    # ---- parts -----------------------------------------------------------------------------

    def _form(self, block: JSON, form: Form) -> str:
        words: list[str] = []
        fields = block.get("fields") or {}
        for part in form.parts:
            if isinstance(part, Word):
                words.append(part.text)
            elif isinstance(part, Choice):
                label = fields.get(d.field_name(part.field))
                try:
                    words.append(part.words(part.value_of_label(str(label))))
                except KeyError:
                    options = ", ".join(part.label(value) for value, _ in part.options)
                    raise _block_error("E703", block["type"], block.get("id"),
                                       needs=f"one of {options} in {d.field_name(part.field)}",
                                       ) from None  # fmt: skip
            elif isinstance(part, Slot):
                words.append(self._value(block, d.field_name(part.field)))
            elif isinstance(part, Text):
                words.append(self._string(block, fields.get(d.field_name(part.field))))
        return " ".join(word for word in words if word)

    def _input(self, block: JSON, name: str, *, required: bool, statement: bool = False) -> Any:
        connection = (block.get("inputs") or {}).get(name)
        child = None
        if isinstance(connection, dict):
            child = connection.get("block") or connection.get("shadow")
        if child is None and required:
            needs = f"blocks inside it ({name})" if statement else f"a value in {name}"
            raise _block_error("E703", block["type"], block.get("id"), needs=needs)
        return child

    def _value(self, block: JSON, name: str) -> str:
        return self._expression(self._input(block, name, required=True))

    def _values(self, block: JSON) -> str:
        count = self._count(block)
        return ", ".join(self._value(block, f"ARG{index}") for index in range(count))

    def _count(self, block: JSON) -> int:
        count = (block.get("extraState") or {}).get("values", 0)
        if not isinstance(count, int) or count < 0:
            raise _block_error("E703", block["type"], block.get("id"),
                               needs="a number of values (extraState.values)")  # fmt: skip
        return count

    def _parameters(self, block: JSON) -> list[str]:
        parameters = (block.get("extraState") or {}).get("parameters", [])
        if not isinstance(parameters, list):
            raise _block_error("E703", block["type"], block.get("id"), needs="a list of parameters")
        return [self._name(block, parameter) for parameter in parameters]

    def _name(self, block: JSON, name: object) -> str:
        if not isinstance(name, str) or not _NAME.fullmatch(name):
            raise _block_error("E705", block["type"], block.get("id"), what=f"the name {name!r}",
                               fix="names start with a letter, then letters a to z, digits "
                               "or _ (no spaces).")  # fmt: skip
        return name.lower()

    def _variable(self, block: JSON) -> str:
        reference = (block.get("fields") or {}).get("VAR")
        name = None
        if isinstance(reference, dict):
            name = self.variables.get(str(reference.get("id")), reference.get("name"))
        return self._name(block, name)

    def _string(self, block: JSON, value: object) -> str:
        if not isinstance(value, str) or "\n" in value or ('"' in value and "”" in value):
            raise _block_error("E705", block["type"], block.get("id"), what=f"the text {value!r}",
                               fix="a text is one line, with no \" and ” both in it.")  # fmt: skip
        return string_text(value)

    def _number(self, block: JSON, field: str) -> str:
        value = (block.get("fields") or {}).get(field)
        try:
            number = float(value)  # type: ignore[arg-type]
        except (TypeError, ValueError):
            number = math.nan
        if not math.isfinite(number):
            raise _block_error("E705", block["type"], block.get("id"), what=f"the number {value!r}",
                               fix="write a number, like 10 or 2.5.")  # fmt: skip
        return number_text(number)

    def _field(self, block: JSON, field: str, allowed: Any) -> str:
        value = (block.get("fields") or {}).get(field)
        if not isinstance(value, str) or value not in allowed:
            raise _block_error("E703", block["type"], block.get("id"),
                               needs=f"one of {', '.join(allowed)} in {field}")  # fmt: skip
        return value

    # ---- expressions -----------------------------------------------------------------------

    def _expression(self, block: Any) -> str:
        block = self._checked(block)
        block_type = block["type"]
        form = d.FORMS_BY_BLOCK.get(block_type)
        if form is not None and form.node is ast.SensorRead:
            return f"({self._form(block, form)})"
        make = _EXPRESSIONS.get(block_type)
        if make is None:
            raise _block_error("E703", block_type, block.get("id"),
                               needs="to stand on its own line: it gives no value")  # fmt: skip
        return f"({make(self, block)})"

    def _number_block(self, block: JSON) -> str:
        return self._number(block, "NUM")

    def _quantity(self, block: JSON) -> str:
        kind = next(kind for kind, name in d.QUANTITY_BLOCKS.items() if name == block["type"])
        units = [unit.name for unit in d.UNITS.values() if unit.kind is kind]
        return quantity_text(self._number(block, "NUM"), self._field(block, "UNIT", units))

    def _text(self, block: JSON) -> str:
        return self._string(block, (block.get("fields") or {}).get("TEXT"))

    def _boolean(self, block: JSON) -> str:
        return self._field(block, "BOOL", ("true", "false"))

    def _color(self, block: JSON) -> str:
        return self._field(block, "COLOR", tuple(d.NAMED_COLORS))

    def _hex(self, block: JSON) -> str:
        value = (block.get("fields") or {}).get("HEX")
        if not isinstance(value, str) or not _HEX.fullmatch(value):
            raise _block_error(
                "E705",
                block["type"],
                block.get("id"),
                what=f"the colour {value!r}",
                fix="write a colour as # and six digits 0-9 or a-f, like #ff8000.",
            )
        return value.lower()

    def _note(self, block: JSON) -> str:
        value = (block.get("fields") or {}).get("NOTE")
        if not isinstance(value, str) or not _NOTE.fullmatch(value.strip()):
            raise _block_error("E705", block["type"], block.get("id"), what=f"the note {value!r}",
                               fix="write a note as a letter A to G, maybe # or b, and an "
                               "octave: C4, F#5, Bb3.")  # fmt: skip
        return f"note {value.strip()}"

    def _rgb(self, block: JSON) -> str:
        channels = (self._value(block, name) for name in ("RED", "GREEN", "BLUE"))
        return "rgb " + " ".join(channels)

    def _with_unit(self, block: JSON) -> str:
        unit = self._field(block, "UNIT", d.ALL_UNITS)
        return quantity_text(self._value(block, "VALUE"), unit)

    def _negate(self, block: JSON) -> str:
        return f"-{self._value(block, 'VALUE')}"

    def _not(self, block: JSON) -> str:
        return f"not {self._value(block, 'VALUE')}"

    def _binary(self, block: JSON) -> str:
        operator = self._field(block, "OP", tuple(d.BINARY_BLOCKS[block["type"]]))
        return f"{self._value(block, 'A')} {operator} {self._value(block, 'B')}"

    def _function(self, block: JSON) -> str:
        name = self._field(block, "FUNCTION", d.ONE_VALUE_FUNCTIONS)
        return f"{name} {self._value(block, 'VALUE')}"

    def _min_max(self, block: JSON) -> str:
        name = self._field(block, "FUNCTION", ("min", "max"))
        return f"{name}({self._value(block, 'A')}, {self._value(block, 'B')})"

    def _random(self, block: JSON) -> str:
        return f"random {self._value(block, 'A')} to {self._value(block, 'B')}"

    def _join(self, block: JSON) -> str:
        return f"join({self._values(block)})"

    def _call_value(self, block: JSON) -> str:
        name = self._name(block, (block.get("extraState") or {}).get("name"))
        count = self._count(block)
        takes = self.procedures.get(name)
        if takes is None and name not in _BUILT_IN_FUNCTIONS:
            raise _block_error(
                "E703",
                block["type"],
                block.get("id"),
                needs=f"a `to {name}` block: there is no procedure {name}",
            )
        if takes is not None and (count == 0) != (takes == 0):
            raise _block_error("E703", block["type"], block.get("id"),
                               needs=f"{takes} values for {name}")  # fmt: skip
        return f"{name}({self._values(block)})" if count else name

    def _get(self, block: JSON) -> str:
        return self._variable(block)


def _is_event(block_type: str) -> bool:
    form = d.FORMS_BY_BLOCK.get(block_type)
    return form is not None and form in EVENT_FORMS


_STATEMENTS = frozenset(
    {d.IF_BLOCK, d.PROCEDURE_BLOCK, d.PRINT_BLOCK, d.CALL_BLOCK, d.SET_BLOCK, d.CHANGE_BLOCK}
)
_EXPRESSIONS: dict[str, Any] = {
    d.NUMBER_BLOCK: _Writer._number_block,
    **{block: _Writer._quantity for block in d.QUANTITY_BLOCKS.values()},
    d.TEXT_BLOCK: _Writer._text,
    d.BOOLEAN_BLOCK: _Writer._boolean,
    d.COLOR_BLOCK: _Writer._color,
    d.HEX_COLOR_BLOCK: _Writer._hex,
    d.RGB_BLOCK: _Writer._rgb,
    d.NOTE_BLOCK: _Writer._note,
    d.WITH_UNIT_BLOCK: _Writer._with_unit,
    d.NEGATE_BLOCK: _Writer._negate,
    d.NOT_BLOCK: _Writer._not,
    **{block: _Writer._binary for block in d.BINARY_BLOCKS},
    d.FUNCTION_BLOCK: _Writer._function,
    d.MIN_MAX_BLOCK: _Writer._min_max,
    d.RANDOM_BLOCK: _Writer._random,
    d.JOIN_BLOCK: _Writer._join,
    d.CALL_VALUE_BLOCK: _Writer._call_value,
    d.GET_BLOCK: _Writer._get,
}


class _Lines:
    """Where a block's comments and blank lines go (its ``data``), filled from its bubble."""

    def __init__(self, block: JSON, headers: int) -> None:
        layout: JSON = {}
        raw = block.get("data")
        if isinstance(raw, str) and raw.startswith("{"):
            try:
                layout = json.loads(raw)
            except ValueError:
                layout = {}
        before = layout.get("before")
        before = before if isinstance(before, list) else []
        self._before = [p if isinstance(p, str) else "" for p in before][:headers]
        self._before += [""] * (headers - len(self._before))
        eol = layout.get("eol")
        eol = eol if isinstance(eol, list) else []
        self._eol = {index for index in eol if isinstance(index, int)}
        self._after = str(layout.get("after", "")) if isinstance(layout.get("after"), str) else ""
        comment = ((block.get("icons") or {}).get("comment") or {}).get("text")
        self._comments = str(comment).split("\n") if comment else []
        slots = sum(p.count("c") for p in self._before) + len(self._eol) + self._after.count("c")
        if slots != len(self._comments):  # the bubble was edited: its lines go above the block
            self._before = ["c" * len(self._comments)] + [
                p.replace("c", "") for p in self._before[1:]
            ]
            self._eol, self._after = set(), self._after.replace("c", "")
        self._next = 0

    def _take(self) -> str:
        comment = self._comments[self._next]
        self._next += 1
        return comment

    def before(self, index: int) -> list[tuple[str, str]]:
        return [(kind, self._take() if kind == "c" else "") for kind in self._before[index]]

    def end_of_line(self, index: int) -> str | None:
        return self._take() if index in self._eol else None

    def after(self) -> list[tuple[str, str]]:
        return [(kind, self._take() if kind == "c" else "") for kind in self._after]
