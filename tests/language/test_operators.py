"""The operators are described once (rootlang.units.OPERATORS): the grammar, the syntax tree,
`rootlang format`, the blocks, the unit rules, the runtime and the messages all read them there."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from rootlang import ast
from rootlang.blocks import to_text, to_workspace
from rootlang.blocks.names import BINARY_BLOCKS
from rootlang.checks import parse
from rootlang.formatting import format_source
from rootlang.units import OPERATORS, Kind, Quantity, Rule, apply_binary, binary_kind


def _values(op: str) -> tuple[str, str]:
    return ("true", "false") if OPERATORS[op].rule is Rule.LOGIC else ("7", "2")


@pytest.mark.parametrize("op", list(OPERATORS))
def test_every_reader_of_an_operator_agrees(op: str) -> None:
    left, right = _values(op)
    for spelling in (op, *OPERATORS[op].also):
        source = f"when started\n    print {left} {spelling} {right}\n"
        (statement,) = parse(source).scripts[0].body
        assert isinstance(statement, ast.Print)
        (read,) = statement.values
        assert isinstance(read, ast.Binary) and read.op == op
        assert format_source(source) == f"when started\n    print {left} {op} {right}\n"
    blocks = [block for block, menu in BINARY_BLOCKS.items() if op in menu]
    assert len(blocks) == 1  # one block's menu offers it
    canonical = f"when started\n    print {left} {op} {right}\n"
    assert to_text(json.loads(json.dumps(to_workspace(canonical)))) == canonical
    sides = Kind.BOOLEAN if OPERATORS[op].rule is Rule.LOGIC else Kind.NUMBER
    assert binary_kind(op, sides, sides) in (Kind.NUMBER, Kind.BOOLEAN)


def test_the_runtime_computes_each_operator_as_the_table_says() -> None:
    seven, two = Quantity(7, Kind.NUMBER, ""), Quantity(2, Kind.NUMBER, "")
    assert [apply_binary(op, seven, two) for op in OPERATORS if op not in ("and", "or")] == [
        Quantity(9, Kind.NUMBER, ""), Quantity(5, Kind.NUMBER, ""),
        Quantity(14, Kind.NUMBER, ""), Quantity(3.5, Kind.NUMBER, ""),
        Quantity(1, Kind.NUMBER, ""), False, True, False, True, False, True,
    ]  # fmt: skip
    assert (apply_binary("and", True, False), apply_binary("or", True, False)) == (False, True)


ADDED = """
import json, operator
from rootlang import units
from rootlang.wording.shown import Described
units.OPERATORS["^"] = units.Operator(
    "^", units.Binding.PRODUCT, units.Rule.PRODUCT, Described("raise"), operator.pow, "MUL_OP"
)
from rootlang.blocks import to_text, to_workspace
from rootlang.blocks.names import BINARY_BLOCKS
from rootlang.checks import diagnose
from rootlang.formatting import format_source
source = "when started\\n    print 2^3 + 1\\n    print (1 + 1) ^ 2\\n"
canonical = format_source(source)
workspace = json.loads(json.dumps(to_workspace(canonical)))
wrong = diagnose('when started\\n    print 2 cm ^ "a"\\n')
print(json.dumps({
    "canonical": canonical,
    "blocks": to_text(workspace),
    "menu": BINARY_BLOCKS["root_arithmetic"].get("^"),
    "mistakes": [item.english for item in diagnose(source)],
    "wrong": [item.english for item in wrong],
    "computed": str(units.apply_binary("^", units.Quantity(2, units.Kind.NUMBER, ""),
                                       units.Quantity(3, units.Kind.NUMBER, ""))),
}))
"""


def test_an_operator_added_to_the_table_alone_works_everywhere(tmp_path: Path) -> None:
    """A new operator, `^`, written in rootlang.units.OPERATORS and nowhere else: the grammar
    reads it, `rootlang format` prints it with the brackets it needs, the blocks offer and
    read it, the checks know its kinds, the message names what it tried and it computes."""
    environment = {**os.environ, "XDG_CACHE_HOME": str(tmp_path)}  # the grammar built anew
    ran = subprocess.run(
        [sys.executable, "-c", ADDED], capture_output=True, text=True, env=environment,
        check=False, timeout=120,
    )  # fmt: skip
    assert ran.returncode == 0, ran.stderr
    found = json.loads(ran.stdout)
    assert found["canonical"] == "when started\n    print 2 ^ 3 + 1\n    print (1 + 1) ^ 2\n"
    assert found["blocks"] == found["canonical"]
    assert found["menu"] == "^"
    assert found["mistakes"] == []
    assert found["wrong"] == ["I can't raise a distance in cm and text."]
    assert found["computed"] == "8"
