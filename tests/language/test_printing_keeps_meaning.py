"""Printing never changes what a program does: whatever tree the printer is given (from text,
or built from blocks), the text it prints reads back as that very tree, is a fixed point of
``format``, and goes through the blocks unchanged (never refused with E707).

Trees are generated the way the blocks build them, with no brackets to help: every operator,
every built-in function (``random`` and ``rgb`` included), unary minus and ``not``, units on
any value, procedures used for their value, every sensor, in every value slot of every
statement the language has."""

from __future__ import annotations

import json
from functools import cache

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rootlang import ast, forms, units
from rootlang.blocks import to_text, to_workspace
from rootlang.checks import parse
from rootlang.formatting import expression_text, format_source
from rootlang.grammar.build import minus, rgb, with_unit
from rootlang.spans import Span

# Procedures of each kind a value can call: with one value, with two, with none.
PROCEDURES = """\
to twice v
    return v * 2
to area a, b
    return a * b
to seven
    return 7
"""
NOWHERE = Span(1, 1, 1, 1)
OPERATORS = tuple(units.OPERATORS)
UNITS = ("cm", "mm", "degrees", "seconds", "cm/s", "%", "hz")


def program(*lines: str) -> str:
    return PROCEDURES + "when started\n" + "".join(f"    {line}\n" for line in lines)


def statements(text: str) -> ast.Block:
    """The lines of the program's ``when started``."""
    script = parse(text, "", "en").items[-1]
    assert isinstance(script, ast.Script)
    return script.body


@cache
def leaves() -> tuple[ast.Expression, ...]:
    """Values as the grammar builds them: literals of every kind (negative ones, with units,
    colours, notes), a variable, a procedure with no values, and every sensor."""
    written = [
        "5", "2.5", "-3", "10 cm", "-2 cm", "90 degrees", "1 second", '"hi"', "true",
        "red", "#ff8000", "note C4", "rgb 1 2 3", "x", "seven",
    ]  # fmt: skip
    sensors = [form.form for form in forms.SENSORS.values()]
    written += [" ".join(_part_text(part) for part in sensor.parts) for sensor in sensors]
    printed = statements(program(*(f"print {value}" for value in written)))
    return tuple(value for line in printed if isinstance(line, ast.Print) for value in line.values)


def _part_text(part: forms.Part) -> str:
    if isinstance(part, forms.Word):
        return part.text
    assert isinstance(part, forms.Choice)
    written: str = next(words for _, words in reversed(part.options) if words)
    return written


def _function(name: str, values: tuple[ast.Expression, ...]) -> ast.Expression:
    if name == "rgb":
        return rgb(NOWHERE, values)  # plain numbers fold into a colour, as the grammar does
    return ast.FunctionCall(NOWHERE, name, values)


def _extend(inner: st.SearchStrategy[ast.Expression]) -> st.SearchStrategy[ast.Expression]:
    def values(count: int) -> st.SearchStrategy[tuple[ast.Expression, ...]]:
        return st.tuples(*[inner] * count)

    functions = [
        st.builds(_function, st.just(name), values(function.values))
        for name, function in units.FUNCTIONS.items()
    ]
    return st.one_of(
        st.builds(lambda op, a, b: ast.Binary(NOWHERE, op, a, b), st.sampled_from(OPERATORS),
                  inner, inner),
        st.builds(lambda a: minus(NOWHERE, a), inner),
        st.builds(lambda a: ast.Unary(NOWHERE, "not", a), inner),
        st.builds(lambda a, unit: with_unit(NOWHERE, a, unit), inner, st.sampled_from(UNITS)),
        st.builds(lambda a: ast.ProcedureCall(NOWHERE, "twice", (a,)), inner),
        st.builds(lambda a, b: ast.ProcedureCall(NOWHERE, "area", (a, b)), inner, inner),
        *functions,
    )  # fmt: skip


EXPRESSIONS = st.recursive(st.sampled_from(leaves()), _extend, max_leaves=12)


@cache
def slot_lines() -> tuple[tuple[str, tuple[str, ...]], ...]:
    """Every statement form's line, its value slots to be filled (a ``{}`` each) and the node
    fields they fill; a header's body is one line."""
    found = []
    for form in forms.STATEMENT_FORMS:
        words: list[str] = []
        fields: list[str] = []
        for part in form.parts:
            if isinstance(part, forms.Slot):
                words.append("{}")
                fields.append(part.field)
            elif isinstance(part, forms.Text):
                words.append(part.default)
            elif isinstance(part, forms.Body):
                words.append(":\n        wait 1 second")
            else:
                words.append(_part_text(part))
        if fields:
            found.append((" ".join(words).replace(" :", ":"), tuple(fields)))
    return tuple(found)


def assert_reads_back(text: str) -> None:
    """``format`` keeps the text's meaning, is a fixed point, and the blocks give it back."""
    canonical = format_source(text)
    assert ast.same_tree(parse(canonical, "", "en"), parse(text, "", "en")), canonical
    assert format_source(canonical) == canonical
    workspace = json.loads(json.dumps(to_workspace(canonical)))  # as it travels to a browser
    assert to_text(workspace) == canonical  # never E707 for text rootlang printed


SETTINGS = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@SETTINGS
@given(EXPRESSIONS)
def test_a_value_reads_back_as_the_tree_it_was_printed_from(value: ast.Expression) -> None:
    text = program(f"print {expression_text(value)}", f"set x to {expression_text(value)}")
    for line in statements(text):
        assert isinstance(line, ast.Print | ast.SetVariable)
        read = line.values[0] if isinstance(line, ast.Print) else line.value
        assert ast.same_tree(read, value), expression_text(value)
    assert_reads_back(text)


@SETTINGS
@given(st.data())
def test_every_value_slot_of_every_statement_keeps_its_value(data: st.DataObject) -> None:
    line, fields = data.draw(st.sampled_from(slot_lines()))
    values = [data.draw(EXPRESSIONS) for _ in fields]
    text = program(line.format(*(expression_text(value) for value in values)))
    statement = statements(text)[0]
    for field, value in zip(fields, values, strict=True):
        assert ast.same_tree(getattr(statement, field), value), text
    assert_reads_back(text)


def test_the_issue_s_quarter_turn_keeps_its_brackets() -> None:
    """A random quarter turn stays one: `round (random 1 to 4) * 90`, not up to 360."""
    text = program(
        "turn right round (random 1 to 4) * 90 degrees", "print round (random 1 to 4) * 90"
    )
    assert "round (random 1 to 4) * 90" in format_source(text)
    assert_reads_back(text)
