"""The gallery (programs/*.root) covers the whole language, and its index lists every program.

Coverage is measured on the AST, so it can't silently rot: a new statement, event, expression,
sensor, unit or choice word (``bumper both``, ``light spin``, ``stop other scripts`` ...) added to
:mod:`rootlang.ast` or :mod:`rootlang.units` fails this test until some program uses it.
"""

from __future__ import annotations

import dataclasses
import re
import typing
from pathlib import Path

import pytest

from rootlang import ast
from rootlang.checks import parse
from rootlang.units import ARITHMETIC, EQUALITY, FUNCTIONS, LOGIC, ORDERING, UNITS, Quantity

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
GALLERY = sorted(PROGRAMS.glob("*.root"))


def _node_classes(base: type[ast.Node]) -> set[type[ast.Node]]:
    """The concrete node classes of the AST module under ``base``."""
    return {
        value
        for value in vars(ast).values()
        if isinstance(value, type)
        and issubclass(value, base)
        and value is not base
        and value.__module__ == ast.__name__
        and not any(
            issubclass(other, value) and other is not value
            for other in vars(ast).values()
            if isinstance(other, type)
        )
    }


def _choices(cls: type[ast.Node]) -> dict[str, set[object]]:
    """For each field typed as a choice of words (or true/false), the values it can take."""
    hints = typing.get_type_hints(cls, vars(ast))
    found: dict[str, set[object]] = {}
    for field in dataclasses.fields(cls):
        hint = hints[field.name]
        if hint is bool:
            found[field.name] = {True, False}
        elif typing.get_origin(hint) is typing.Literal:
            found[field.name] = set(typing.get_args(hint))
    return found


@pytest.fixture(scope="module")
def gallery_nodes() -> list[ast.Node]:
    nodes: list[ast.Node] = []
    for program in GALLERY:
        nodes.extend(ast.walk(parse(program.read_text(encoding="utf-8"), str(program))))
    return nodes


def test_the_gallery_has_at_least_30_programs() -> None:
    assert len(GALLERY) >= 30


@pytest.mark.parametrize("base", [ast.Statement, ast.Event, ast.Expression])
def test_every_kind_of_node_is_used(base: type[ast.Node], gallery_nodes: list[ast.Node]) -> None:
    used = {type(node) for node in gallery_nodes}
    missing = sorted(cls.__name__ for cls in _node_classes(base) - used)
    assert not missing, f"no program in programs/ uses {missing}"


def test_every_choice_word_is_used(gallery_nodes: list[ast.Node]) -> None:
    seen: set[tuple[str, str, object]] = set()
    for node in gallery_nodes:
        for name in _choices(type(node)):
            seen.add((type(node).__name__, name, getattr(node, name)))
    wanted = {
        (cls.__name__, name, value)
        for base in (ast.Statement, ast.Event, ast.Expression)
        for cls in _node_classes(base)
        for name, values in _choices(cls).items()
        for value in values
    }
    assert not sorted(wanted - seen, key=str), f"never used: {sorted(wanted - seen, key=str)}"


def test_every_sensor_operator_function_and_unit_is_used(gallery_nodes: list[ast.Node]) -> None:
    sensors = {node.sensor for node in gallery_nodes if isinstance(node, ast.SensorRead)}
    assert set(ast.SensorKind) - sensors == set()
    binary = {node.op for node in gallery_nodes if isinstance(node, ast.Binary)}
    assert {*ARITHMETIC, *ORDERING, *EQUALITY, *LOGIC} - binary == set()
    functions = {node.function for node in gallery_nodes if isinstance(node, ast.FunctionCall)}
    functions |= {  # `rgb 255 128 0`: a colour the parser folds
        "rgb" for node in gallery_nodes if isinstance(node, ast.Literal) and node.text[:4] == "rgb "
    }
    assert set(FUNCTIONS) - functions == set()
    units = {node.unit.lower() for node in gallery_nodes if isinstance(node, ast.WithUnit)}
    units |= {
        node.value.unit.lower()
        for node in gallery_nodes
        if isinstance(node, ast.Literal) and isinstance(node.value, Quantity)
    }
    assert set(UNITS) - units == set(), "units no program writes"


def test_the_index_lists_every_program() -> None:
    index = (PROGRAMS / "README.md").read_text(encoding="utf-8")
    listed = set(re.findall(r"\[((?:mistakes/)?\w+\.root)\]", index))
    on_disk = {p.relative_to(PROGRAMS).as_posix() for p in PROGRAMS.glob("**/*.root")}
    assert on_disk - listed == set(), "programs missing from programs/README.md"
    assert listed - on_disk == set(), "programs/README.md lists programs that don't exist"


def test_every_program_says_what_it_shows_and_the_index_says_the_same() -> None:
    index = (PROGRAMS / "README.md").read_text(encoding="utf-8")
    for program in [*GALLERY, *sorted((PROGRAMS / "mistakes").glob("*.root"))]:
        first = program.read_text(encoding="utf-8").splitlines()[0]
        assert first.startswith(f"# {program.name}: "), program
        shows = first.split(": ", 1)[1]
        assert f"| {shows} |" in index, f"programs/README.md doesn't say {shows!r}"
