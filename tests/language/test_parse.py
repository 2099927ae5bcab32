"""What the parser builds: typed nodes with spans, case-insensitive, units as values."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from rootlang import ast
from rootlang.checks import diagnose, load_checked, parse
from rootlang.colors import Color
from rootlang.units import Kind, Quantity, apply_binary, note_frequency

GALLERY = Path(__file__).parents[2] / "programs"


def only_statement(source: str) -> ast.Statement:
    program = parse("when started\n    " + source + "\n")
    (statement,) = program.scripts[0].body
    return statement


def test_case_and_trailing_colon_do_not_matter() -> None:
    statement = only_statement("Move Backward 10 CM")
    assert isinstance(statement, ast.Move) and statement.backward
    assert isinstance(statement.distance, ast.Literal)
    assert statement.distance.value == Quantity(100.0, Kind.LENGTH, "cm")
    assert parse("WHEN Started:\n    stop moving\n").scripts[0].body


def test_spans_point_at_the_source() -> None:
    statement = only_statement("turn left 45 degrees")
    assert isinstance(statement, ast.Turn)
    assert (statement.span.line, statement.span.column, statement.span.end_column) == (2, 5, 25)
    assert (statement.angle.span.column, statement.angle.span.end_column) == (15, 25)


def test_events_are_typed() -> None:
    source = (
        "when bumper left pressed\n    stop moving\nwhen color red seen on left\n    stop moving\n"
    )
    first, second = parse(source).scripts
    assert isinstance(first.event, ast.BumperEvent) and first.event.side == "left"
    assert isinstance(second.event, ast.ColorSeen) and second.event.zone == "left"


def test_procedures_calls_and_values() -> None:
    source = "to double x\n    return x * 2\nwhen started\n    set d to double 3 cm - 1 cm\n"
    checked = load_checked(source)
    statement = checked.scripts[0].body[0]
    assert isinstance(statement, ast.SetVariable) and isinstance(statement.value, ast.Binary)
    assert isinstance(statement.value.left, ast.ProcedureCall)
    assert checked.returns_value == {"double"}


def test_colours_and_notes() -> None:
    light = only_statement("light rgb 255 128 0")
    assert isinstance(light, ast.Light) and isinstance(light.color, ast.Literal)
    assert light.color.value == Color(255, 128, 0)
    assert round(note_frequency("A4")) == 440 and round(note_frequency("C4"), 2) == 261.63
    assert round(note_frequency("F#5"), 1) == 740.0 and round(note_frequency("Bb3"), 2) == 233.08


def test_unit_arithmetic() -> None:
    assert str(apply_binary("+", Quantity.of(10, "cm"), Quantity.of(5, "mm"))) == "10.5 cm"
    assert str(apply_binary("*", Quantity.of(10, "cm"), Quantity.number(2))) == "20 cm"
    speed = apply_binary("/", Quantity.of(10, "cm"), Quantity.of(2, "s"))
    assert isinstance(speed, Quantity) and speed.kind is Kind.SPEED


def test_shared_and_local_variables() -> None:
    source = (
        "when started\n    set a to 1\n    set b to 2\n"
        "when bumped\n    print a\n"
        "to show\n    print c\nwhen touched\n    set c to 3\n    show\n"
    )
    checked = load_checked(source)
    assert checked.shared_variables == {"a", "c"}
    assert checked.script_variables[checked.scripts[0]] == {"b"}


def test_kinds_are_known_before_the_run() -> None:
    checked = load_checked("when started\n    set s to 5 cm/s\n    drive s * 2\n")
    drive = checked.scripts[0].body[1]
    assert isinstance(drive, ast.Drive) and checked.kind_of(drive.speed) is Kind.SPEED


@pytest.mark.parametrize("path", sorted(GALLERY.glob("*.root")), ids=lambda p: p.name)
def test_gallery_programs_are_clean(path: Path) -> None:
    found = diagnose(path.read_text(encoding="utf-8"), path.name)
    assert [d for d in found if d.severity == "error"] == []


@pytest.mark.parametrize("path", sorted(GALLERY.glob("mistakes/*.root")), ids=lambda p: p.name)
def test_gallery_mistakes_are_found(path: Path) -> None:
    from rootlang.robots import RobotModel

    assert diagnose(path.read_text(encoding="utf-8"), path.name, RobotModel.RT1)


@pytest.mark.parametrize(("written", "read_as"), [("==", "="), ("<>", "!="), ("≤", "<=")])
def test_other_spellings_of_comparisons_are_read(written: str, read_as: str) -> None:
    # docs/language.md promises `==` and `<>` for `=` and `!=` (habits from other languages)
    program = parse(f"when started\n    set x to 1\n    if x {written} 1\n        say 1\n")
    condition = program.scripts[0].body[1].branches[0].condition  # type: ignore[attr-defined]
    assert isinstance(condition, ast.Binary) and condition.op == read_as


def test_quantities_print_as_people_write_them() -> None:
    from rootlang.units import Quantity

    shown = [
        str(Quantity.of(n, unit))
        for n, unit in (
            (1, "seconds"),
            (1.5, "second"),
            (2, "degree"),
            (30, "°"),
            (1, "inches"),
            (50, "%"),
            (10, "cm"),
        )
    ]
    assert shown == ["1 second", "1.5 seconds", "2 degrees", "30°", "1 inch", "50%", "10 cm"]


def test_every_node_prints_as_its_dataclass_would() -> None:
    # one __repr__ on ast.Node stands in for a generated one on each node type (start-up)
    for path in sorted(GALLERY.glob("*.root")):
        for node in ast.walk(parse(path.read_text(encoding="utf-8"))):
            names = [field.name for field in dataclasses.fields(node)]
            twin = dataclasses.make_dataclass(type(node).__qualname__, names, eq=False)
            assert repr(node) == repr(twin(*(getattr(node, name) for name in names)))


def test_no_node_type_makes_a_repr_of_its_own() -> None:
    types = [item for item in vars(ast).values() if isinstance(item, type)]
    own = [
        kind.__name__
        for kind in types
        if issubclass(kind, ast.Node) and kind.__repr__ is not ast.Node.__repr__
    ]
    assert own == [], "give these node types repr=False (ast.Node's __repr__ prints the same)"
