"""The blocks' vocabulary, which both directions of the conversion and the definitions read:
the block types, the block each form makes, the field names, the operator menus.
"""

from __future__ import annotations

from typing import Any

from rootlang import forms
from rootlang.colors import NAMED_COLORS
from rootlang.forms import Form
from rootlang.units import OPERATORS, UNITS, Binding, Kind

__all__ = [
    "ALL_UNITS",
    "BINARY_BLOCKS",
    "BOOLEAN_BLOCK",
    "CALL_BLOCK",
    "CALL_VALUE_BLOCK",
    "CHANGE_BLOCK",
    "COLOR_BLOCK",
    "FORMS_BY_BLOCK",
    "FUNCTION_BLOCK",
    "GET_BLOCK",
    "HEX_COLOR_BLOCK",
    "IF_BLOCK",
    "JOIN_BLOCK",
    "JSON",
    "MIN_MAX_BLOCK",
    "NAMED_COLORS",
    "NEGATE_BLOCK",
    "NOTE_BLOCK",
    "NOT_BLOCK",
    "NUMBER_BLOCK",
    "PRINT_BLOCK",
    "PROCEDURES_CATEGORY",
    "PROCEDURE_BLOCK",
    "QUANTITY_BLOCKS",
    "RANDOM_BLOCK",
    "RGB_BLOCK",
    "SET_BLOCK",
    "TEXT_BLOCK",
    "UNITS",
    "VARIADIC",
    "WITH_UNIT_BLOCK",
    "field_name",
]

JSON = dict[str, Any]

# Built-in Blockly blocks the conversion uses as they are (variables, and `if` with its
# else-if / else editor); their colours come from the toolbox categories.
IF_BLOCK = "controls_if"
SET_BLOCK = "variables_set"
CHANGE_BLOCK = "math_change"
GET_BLOCK = "variables_get"

# Blocks that take any number of values carry {"values": n} (and a call its "name") in their
# extraState; root_blocks.js gives them their inputs ARG0, ARG1 ...
PRINT_BLOCK = "root_print"
CALL_BLOCK = "root_call"
CALL_VALUE_BLOCK = "root_call_value"
PROCEDURE_BLOCK = "root_procedure"
JOIN_BLOCK = "root_join"
VARIADIC = "root_values"  # the mutator root_blocks.js registers
PROCEDURES_CATEGORY = "ROOT_PROCEDURES"  # the toolbox category RootBlocks.attach fills

FORMS_BY_BLOCK: dict[str, Form] = {
    form.block: form
    for form in (
        *forms.STATEMENT_FORMS,
        *forms.EVENT_FORMS,
        *(sensor.form for sensor in forms.SENSORS.values()),
    )
}


def field_name(name: str) -> str:
    """A node field's name on its block: ``distance`` -> ``DISTANCE``."""
    return name.upper()


# ---- value blocks --------------------------------------------------------------------------


QUANTITY_BLOCKS: dict[Kind, str] = {
    kind: f"root_{kind.value}"
    for kind in (Kind.LENGTH, Kind.ANGLE, Kind.TIME, Kind.SPEED, Kind.FREQUENCY, Kind.PERCENT)
}
"""A number with a unit of that kind: ``[10] [cm ▾]``."""

NUMBER_BLOCK = "root_number"
TEXT_BLOCK = "root_text"
BOOLEAN_BLOCK = "root_boolean"
COLOR_BLOCK = "root_color"
HEX_COLOR_BLOCK = "root_hex_color"
RGB_BLOCK = "root_rgb"
NOTE_BLOCK = "root_note"
WITH_UNIT_BLOCK = "root_with_unit"
NEGATE_BLOCK = "root_negate"
NOT_BLOCK = "root_not"
FUNCTION_BLOCK = "root_function"
MIN_MAX_BLOCK = "root_min_max"
RANDOM_BLOCK = "root_random"

ALL_UNITS: tuple[str, ...] = tuple(dict.fromkeys(unit.name for unit in UNITS.values()))
# The block of each way an operator binds: sums and products, comparisons, `and` and `or`.
_OPERATOR_BLOCKS = {
    Binding.SUM: "root_arithmetic",
    Binding.PRODUCT: "root_arithmetic",
    Binding.COMPARE: "root_compare",
    Binding.AND: "root_logic",
    Binding.OR: "root_logic",
}


def _binary_blocks() -> dict[str, dict[str, str]]:
    blocks: dict[str, dict[str, str]] = {}
    for op, operator in OPERATORS.items():
        blocks.setdefault(_OPERATOR_BLOCKS[operator.binds], {})[op] = operator.shown or op
    return blocks


BINARY_BLOCKS = _binary_blocks()
"""Operator blocks: their operators as written -> as the block's menu shows them (from
:data:`rootlang.units.OPERATORS`)."""
