"""Blockly block definitions and the toolbox, generated from the language description.

Statement, event and sensor blocks come from the forms in :mod:`rootlang.forms`: a word becomes
a label, a choice a drop-down, a value slot an input, a body a statement input. Values
(numbers with their units, text, colours, notes), operators, functions and the few special
statements (``if``, ``print``, procedures and their calls, variables) are declared here, once;
their block types, field names and operator menus are in :mod:`rootlang.blocks.names`, which
both directions of the conversion read. The toolbox's starting values are made by the text
to blocks direction (``default_value_block``).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from typing import Any

from rootlang import ast, forms
from rootlang.blocks.names import (
    ALL_UNITS,
    BINARY_BLOCKS,
    BOOLEAN_BLOCK,
    CALL_BLOCK,
    CALL_VALUE_BLOCK,
    COLOR_BLOCK,
    FORMS_BY_BLOCK,
    FUNCTION_BLOCK,
    HEX_COLOR_BLOCK,
    IF_BLOCK,
    JOIN_BLOCK,
    JSON,
    MIN_MAX_BLOCK,
    NEGATE_BLOCK,
    NOT_BLOCK,
    NOTE_BLOCK,
    NUMBER_BLOCK,
    PRINT_BLOCK,
    PROCEDURE_BLOCK,
    PROCEDURES_CATEGORY,
    QUANTITY_BLOCKS,
    RANDOM_BLOCK,
    RGB_BLOCK,
    TEXT_BLOCK,
    VARIADIC,
    WITH_UNIT_BLOCK,
    field_name,
)
from rootlang.blocks.text_to_blocks import default_value_block
from rootlang.colors import NAMED_COLORS
from rootlang.forms import Body, Category, Choice, Form, Slot, Text, Word
from rootlang.units import ONE_VALUE_FUNCTIONS, UNITS, Kind

__all__ = [
    "ALL_UNITS",
    "FORMS_BY_BLOCK",
    "NAMED_COLORS",
    "QUANTITY_BLOCKS",
    "UNITS",
    "block_definitions",
    "field_defaults",
    "field_name",
    "toolbox",
]


def _unit_words(kind: Kind) -> tuple[str, ...]:
    return tuple(unit.name for unit in UNITS.values() if unit.kind is kind)


@dataclass(frozen=True)
class _Palette:
    """What the toolbox shows of each category, in order (block type, and its state)."""

    category: Category
    blocks: tuple[JSON, ...]


def _dropdown(name: str, options: Any) -> JSON:
    return {"type": "field_dropdown", "name": name, "options": [[label, value]
            for value, label in options]}  # fmt: skip


def _value_definitions() -> list[JSON]:
    ops = Category.OPERATORS.colour
    values: list[JSON] = [
        {"type": NUMBER_BLOCK, "message0": "%1", "args0": [
            {"type": "field_number", "name": "NUM", "value": 0}], "output": None, "colour": ops},
        {"type": TEXT_BLOCK, "message0": "“%1”", "args0": [
            {"type": "field_input", "name": "TEXT", "text": ""}], "output": None, "colour": ops},
        {"type": BOOLEAN_BLOCK, "message0": "%1", "args0": [
            _dropdown("BOOL", [("true", "true"), ("false", "false")])],
         "output": None, "colour": ops},
        {"type": COLOR_BLOCK, "message0": "%1", "args0": [
            _dropdown("COLOR", [(name, name) for name in NAMED_COLORS])],
         "output": None, "colour": Category.LIGHTS.colour},
        {"type": HEX_COLOR_BLOCK, "message0": "colour %1", "args0": [
            {"type": "field_input", "name": "HEX", "text": "#ff8000"}],
         "output": None, "colour": Category.LIGHTS.colour},
        {"type": RGB_BLOCK, "message0": "rgb %1 %2 %3", "args0": [
            {"type": "input_value", "name": name} for name in ("RED", "GREEN", "BLUE")],
         "inputsInline": True, "output": None, "colour": Category.LIGHTS.colour},
        {"type": NOTE_BLOCK, "message0": "note %1", "args0": [
            {"type": "field_input", "name": "NOTE", "text": "C4"}],
         "output": None, "colour": Category.SOUND.colour},
        {"type": WITH_UNIT_BLOCK, "message0": "%1 %2", "args0": [
            {"type": "input_value", "name": "VALUE"},
            _dropdown("UNIT", [(unit, unit) for unit in ALL_UNITS])],
         "inputsInline": True, "output": None, "colour": ops},
        {"type": NEGATE_BLOCK, "message0": "- %1", "args0": [
            {"type": "input_value", "name": "VALUE"}], "output": None, "colour": ops},
        {"type": NOT_BLOCK, "message0": "not %1", "args0": [
            {"type": "input_value", "name": "VALUE"}], "output": None, "colour": ops},
        {"type": FUNCTION_BLOCK, "message0": "%1 %2", "args0": [
            _dropdown("FUNCTION", [(f, f) for f in ONE_VALUE_FUNCTIONS]),
            {"type": "input_value", "name": "VALUE"}], "output": None, "colour": ops},
        {"type": MIN_MAX_BLOCK, "message0": "%1 ( %2 , %3 )", "args0": [
            _dropdown("FUNCTION", [("min", "min"), ("max", "max")]),
            {"type": "input_value", "name": "A"}, {"type": "input_value", "name": "B"}],
         "inputsInline": True, "output": None, "colour": ops},
        {"type": RANDOM_BLOCK, "message0": "random %1 to %2", "args0": [
            {"type": "input_value", "name": "A"}, {"type": "input_value", "name": "B"}],
         "inputsInline": True, "output": None, "colour": ops},
        {"type": JOIN_BLOCK, "message0": "join", "mutator": VARIADIC,
         "inputsInline": True, "output": None, "colour": ops},
        {"type": CALL_VALUE_BLOCK, "message0": "", "mutator": VARIADIC,
         "inputsInline": True, "output": None, "colour": Category.PROCEDURES.colour},
    ]  # fmt: skip
    for kind, block in QUANTITY_BLOCKS.items():
        units = [(unit, unit) for unit in _unit_words(kind)]
        values.append({
            "type": block, "message0": "%1 %2", "output": None, "colour": ops,
            "args0": [{"type": "field_number", "name": "NUM", "value": 0},
                      _dropdown("UNIT", units)],
        })  # fmt: skip
    for block, operators in BINARY_BLOCKS.items():
        values.append({
            "type": block, "message0": "%1 %2 %3", "inputsInline": True, "output": None,
            "colour": ops, "args0": [
                {"type": "input_value", "name": "A"},
                _dropdown("OP", list(operators.items())),
                {"type": "input_value", "name": "B"}],
        })  # fmt: skip
    return values


def _special_statements() -> list[JSON]:
    return [
        {"type": PRINT_BLOCK, "message0": "print", "mutator": VARIADIC, "inputsInline": True,
         "previousStatement": None, "nextStatement": None, "colour": Category.SOUND.colour},
        {"type": CALL_BLOCK, "message0": "", "mutator": VARIADIC, "inputsInline": True,
         "previousStatement": None, "nextStatement": None,
         "colour": Category.PROCEDURES.colour},
        {"type": PROCEDURE_BLOCK, "message0": "to %1", "args0": [
            {"type": "field_input", "name": "NAME", "text": "shape"}],
         "message1": "%1", "args1": [{"type": "input_statement", "name": "BODY"}],
         "mutator": "root_parameters", "inputsInline": True, "colour": Category.PROCEDURES.colour,
         "tooltip": "A procedure: call it by its name, with a value for each parameter."},
        # Blockly's own `if` (its else-if / else editor, its words), in the Control colour: its
        # style's blue carries white words at 4.14:1, under WCAG AA's 4.5:1
        {"type": IF_BLOCK, "message0": "%{BKY_CONTROLS_IF_MSG_IF} %1",
         "args0": [{"type": "input_value", "name": "IF0", "check": "Boolean"}],
         "message1": "%{BKY_CONTROLS_IF_MSG_THEN} %1",
         "args1": [{"type": "input_statement", "name": "DO0"}],
         "previousStatement": None, "nextStatement": None, "colour": Category.CONTROL.colour,
         "suppressPrefixSuffix": True, "mutator": "controls_if_mutator",
         "extensions": ["controls_if_tooltip"]},
    ]  # fmt: skip


# ---- form blocks ---------------------------------------------------------------------------


def _form_definition(form: Form) -> JSON:
    message: list[str] = []
    arguments: list[JSON] = []
    body: str | None = None
    for part in form.parts:
        if isinstance(part, Word):
            if part.printed:
                message.append(part.text.replace("%", "%%"))
            continue
        if isinstance(part, Body):
            body = field_name(part.field)
            continue
        message.append(f"%{len(arguments) + 1}")
        if isinstance(part, Choice):
            options = [(part.label(value), part.label(value)) for value, _ in part.options]
            arguments.append(_dropdown(field_name(part.field), options))
        elif isinstance(part, Slot):
            arguments.append({"type": "input_value", "name": field_name(part.field)})
        else:
            assert isinstance(part, Text)
            arguments.append({"type": "field_input", "name": field_name(part.field),
                              "text": part.default})  # fmt: skip
    definition: JSON = {"type": form.block, "colour": form.category.colour, "inputsInline": True}
    is_event = form in forms.EVENT_FORMS
    if is_event:
        message.insert(0, "when")
        body = "BODY"
    definition["message0"] = " ".join(message)
    if arguments:
        definition["args0"] = arguments
    if body is not None:
        definition["message1"] = "%1"
        definition["args1"] = [{"type": "input_statement", "name": body}]
    if form.node is ast.SensorRead:
        definition["output"] = None
    elif not is_event:
        definition["previousStatement"] = None
        definition["nextStatement"] = None
    if form.tooltip:
        definition["tooltip"] = form.tooltip
    return definition


@functools.cache
def _definitions() -> tuple[JSON, ...]:
    made = [_form_definition(form) for form in FORMS_BY_BLOCK.values()]
    return (*made, *_special_statements(), *_value_definitions())


@functools.cache
def field_defaults(block_type: str) -> dict[str, Any]:
    """The values a new block's fields show (a menu's first choice, a field's start text)."""
    defaults: dict[str, Any] = {}
    for definition in _definitions():
        if definition["type"] != block_type:
            continue
        for key, arguments in definition.items():
            for argument in arguments if key.startswith("args") else ():
                if argument["type"] == "field_dropdown":
                    defaults[argument["name"]] = argument["options"][0][1]
                elif argument["type"] == "field_number":
                    defaults[argument["name"]] = argument["value"]
                elif argument["type"] == "field_input":
                    defaults[argument["name"]] = argument["text"]
    return defaults


def block_definitions(language: str = "en") -> list[JSON]:
    """Every rootlang block, for ``Blockly.common.defineBlocksWithJsonArray`` (after
    ``root_blocks.js`` has registered the mutators they name), labelled in ``language``."""
    from rootlang.locale.blocks import localized_blocks

    return localized_blocks([dict(definition) for definition in _definitions()], language)


# ---- the toolbox ---------------------------------------------------------------------------

_CATEGORY_ORDER = (
    Category.EVENTS, Category.MOTION, Category.DRAWING, Category.LIGHTS, Category.SOUND,
    Category.CONTROL, Category.SENSORS, Category.OPERATORS, Category.VARIABLES,
    Category.PROCEDURES, Category.MESSAGES,
)  # fmt: skip


def toolbox(language: str = "en") -> JSON:
    """A category toolbox: every block, each value input holding a shadow block with a
    sensible default, so a block dragged out works as it is; categories named in
    ``language``."""
    from rootlang.locale.blocks import localized_toolbox

    return localized_toolbox(_toolbox(), language)


def _toolbox() -> JSON:
    contents: dict[Category, list[JSON]] = {category: [] for category in _CATEGORY_ORDER}
    for form in FORMS_BY_BLOCK.values():
        item: JSON = {"kind": "block", "type": form.block}
        inputs = {field_name(slot.field): default_input(slot.default) for slot in form.slots}
        if inputs:
            item["inputs"] = inputs
        contents[form.category].append(item)
    contents[Category.CONTROL].insert(
        0,
        {
            "kind": "block",
            "type": IF_BLOCK,
            "inputs": {"IF0": default_input("bumper any pressed")},
        },
    )
    contents[Category.SOUND].append(
        {
            "kind": "block",
            "type": PRINT_BLOCK,
            "extraState": {"values": 1},
            "inputs": {"ARG0": default_input('"hello"')},
        }
    )
    contents[Category.OPERATORS].extend(_operator_items())
    contents[Category.LIGHTS].extend(
        {"kind": "block", "type": block} for block in (COLOR_BLOCK, HEX_COLOR_BLOCK)
    )
    contents[Category.PROCEDURES].insert(
        0, {"kind": "block", "type": PROCEDURE_BLOCK, "extraState": {"parameters": ["size"]}}
    )
    categories: list[JSON] = []
    for category in _CATEGORY_ORDER:
        entry: JSON = {
            "kind": "category",
            "name": category.label,
            "colour": category.colour,
            "contents": contents[category],
        }
        if category is Category.VARIABLES:  # Blockly's own: "Create variable", set, change, get
            entry["custom"] = "VARIABLE"
            del entry["contents"]
        if category is Category.PROCEDURES:  # these, then a call for each `to` block there is
            entry["custom"] = PROCEDURES_CATEGORY
        categories.append(entry)
    return {"kind": "categoryToolbox", "contents": categories}  # fmt: skip


def default_input(text: str) -> JSON:
    """An input holding the value written as ``text``: a shadow (drop a block on it to
    replace it) when it is made of shadows alone, as Blockly wants (``timer > 5 seconds``
    holds a sensor block, so it is a block of its own)."""
    block = default_value_block(text)
    return {"shadow": block} if _only_shadows(block) else {"block": block}


def _only_shadows(block: JSON) -> bool:
    return all(
        "block" not in connection and all(_only_shadows(child) for child in connection.values())
        for connection in block.get("inputs", {}).values()
    )


def _operator_items() -> list[JSON]:
    def item(block: str, **inputs: str) -> JSON:
        return {
            "kind": "block",
            "type": block,
            "inputs": {name: default_input(text) for name, text in inputs.items()},
        }

    return [
        {"kind": "block", "type": NUMBER_BLOCK},
        *({"kind": "block", "type": block} for block in QUANTITY_BLOCKS.values()),
        {"kind": "block", "type": TEXT_BLOCK},
        {"kind": "block", "type": BOOLEAN_BLOCK},
        {"kind": "block", "type": NOTE_BLOCK},
        item("root_arithmetic", A="1", B="1"),
        item("root_compare", A="1", B="1"),
        item("root_logic", A="true", B="true"),
        item(NOT_BLOCK, VALUE="true"),
        item(NEGATE_BLOCK, VALUE="1"),
        item(WITH_UNIT_BLOCK, VALUE="1"),
        item(FUNCTION_BLOCK, VALUE="2.5"),
        item(MIN_MAX_BLOCK, A="1", B="2"),
        item(RANDOM_BLOCK, A="1", B="6"),
        {"kind": "block", "type": JOIN_BLOCK, "extraState": {"values": 2}, "inputs": {
            "ARG0": default_input('"hello "'),
            "ARG1": default_input('"world"')}},
        item(RGB_BLOCK, RED="255", GREEN="128", BLUE="0"),
    ]  # fmt: skip
