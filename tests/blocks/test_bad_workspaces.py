"""Workspaces that can't be programs get a clear error naming the block, never a traceback."""

from __future__ import annotations

import copy
import json
import random
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

from rootlang.blocks import to_text, to_workspace
from rootlang.diagnostics import RootlangError
from rootlang.formatting import format_source

REPO = Path(__file__).resolve().parents[2]
SQUARE = (REPO / "programs" / "square.root").read_text(encoding="utf-8")


def script(*statements: dict[str, Any]) -> dict[str, Any]:
    body: dict[str, Any] | None = None
    for statement in reversed(statements):
        statement = dict(statement)
        if body is not None:
            statement["next"] = {"block": body}
        body = statement
    top = {"type": "root_when_started", "id": "top", "inputs": {"BODY": {"block": body}}}
    return {"blocks": {"languageVersion": 0, "blocks": [top]}}


def error_of(workspace: object) -> RootlangError:
    with pytest.raises(RootlangError) as caught:
        to_text(workspace)  # type: ignore[arg-type]
    return caught.value


@pytest.mark.parametrize(
    ("workspace", "code", "words"),
    [
        ("not json", "E701", "not JSON"),
        ("[1, 2]", "E701", "not a JSON object"),
        ({"blocks": {"blocks": "no"}}, "E701", "no list of blocks"),
        ({"blocks": {"blocks": [{"id": "a"}]}}, "E701", "without a type"),
        (script({"type": "root_fly", "id": "b7"}), "E702", "`root_fly` (id b7)"),
        (script({"type": "root_move", "id": "m1"}), "E703", "a value in DISTANCE"),
        (script({"type": "root_turn", "id": "t1", "fields": {"DIRECTION": "up"},
                 "inputs": {"ANGLE": {"block": {"type": "root_number"}}}}),
         "E703", "one of left, right in DIRECTION"),
        (script({"type": "root_repeat", "id": "r1",
                 "inputs": {"COUNT": {"block": {"type": "root_number"}}}}),
         "E703", "blocks inside it (BODY)"),
        (script({"type": "root_number", "id": "n1"}), "E703", "it gives a value"),
        (script({"type": "root_say", "id": "s1",
                 "inputs": {"TEXT": {"block": {"type": "root_stop_moving", "id": "x"}}}}),
         "E703", "it gives no value"),
        ({"blocks": {"blocks": [{"type": "root_stop_moving", "id": "loose"}]}},
         "E704", "`root_stop_moving` block (id loose) is lying outside any script"),
        (script({"type": "variables_set", "id": "v", "fields": {"VAR": {"id": "q"}},
                 "inputs": {"VALUE": {"block": {"type": "root_number"}}}}) | {
            "variables": [{"name": "my speed", "id": "q"}]}, "E705", "'my speed'"),
        (script({"type": "root_play", "id": "p",
                 "inputs": {"FREQUENCY": {"block": {"type": "root_note", "id": "nn",
                                                    "fields": {"NOTE": "H9"}}},
                            "DURATION": {"block": {"type": "root_number"}}}}),
         "E705", "the note 'H9'"),
        (script({"type": "root_wait", "id": "w", "inputs": {"DURATION": {"block": {
            "type": "root_time", "id": "t", "fields": {"NUM": "lots", "UNIT": "s"}}}}}),
         "E705", "the number 'lots'"),
        (script({"type": "root_say", "id": "s", "inputs": {"TEXT": {"block": {
            "type": "root_text", "id": "t", "fields": {"TEXT": "two\nlines"}}}}}),
         "E705", "a text is one line"),
        (script({"type": "root_print", "id": "p", "extraState": {"values": -1}}),
         "E703", "a number of values"),
        (script({"type": "root_say", "id": "s", "inputs": {"TEXT": {"block": {
            "type": "root_call_value", "id": "c", "extraState": {"name": "nowhere"}}}}}),
         "E703", "there is no procedure nowhere"),
    ],
)  # fmt: skip
def test_each_mistake_names_its_block_and_the_fix(workspace: object, code: str, words: str) -> None:
    error = error_of(workspace)
    assert error.diagnostics[0].code == code
    assert words in error.diagnostics[0].english


def test_mangled_workspaces_never_crash() -> None:
    """Random edits of a real workspace: a program that reads, or a RootlangError, always."""
    rng = random.Random(7)
    original = to_workspace(SQUARE)
    outcomes = {"text": 0, "error": 0}
    for _ in range(1500):
        workspace = copy.deepcopy(original)
        for _ in range(rng.randint(1, 3)):
            _mangle(workspace, rng)
        try:
            text = to_text(workspace)
        except RootlangError:
            outcomes["error"] += 1
            continue
        outcomes["text"] += 1
        assert format_source(text) == text  # what comes out always reads, and is canonical
    assert outcomes["error"] > 100 and outcomes["text"] > 100


def _mangle(node: Any, rng: random.Random) -> None:
    containers = []

    def walk(value: Any) -> None:
        if isinstance(value, dict | list):
            containers.append(value)
            for child in value.values() if isinstance(value, dict) else value:
                walk(child)

    walk(node)
    target = rng.choice(containers)
    if isinstance(target, dict) and target:
        key = rng.choice(sorted(target))
        target[key] = rng.choice([None, 3, "x", [], {}, -1.5, True, "root_move", {"type": 5}])
    elif isinstance(target, list) and target:
        del target[rng.randrange(len(target))]


def test_the_command_line_says_which_block_and_exits_1(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"blocks": {"blocks": [{"type": "root_turn", "id": "L7"}]}}))
    done = subprocess.run([sys.executable, "-m", "rootlang", "blocks", "--to-text", str(bad)],
                          capture_output=True, text=True, check=False)  # fmt: skip
    assert done.returncode == 1
    assert "`root_turn` block (id L7) is lying outside any script" in done.stderr
    assert "Traceback" not in done.stderr


def test_a_program_that_does_not_parse_gets_its_mistakes_as_json(tmp_path: Path) -> None:
    broken = tmp_path / "broken.root"
    broken.write_text("when started\n    move 10 cm cm\n")
    done = subprocess.run([sys.executable, "-m", "rootlang", "blocks", str(broken)],
                          capture_output=True, text=True, check=False)  # fmt: skip
    assert done.returncode == 1
    mistakes = json.loads(done.stdout)
    assert mistakes[0]["line"] == 2 and mistakes[0]["code"].startswith("E0")


def test_blocks_and_back_on_the_command_line(tmp_path: Path) -> None:
    flower = str(REPO / "programs" / "flower.root")
    command = [sys.executable, "-m", "rootlang", "blocks"]
    made = subprocess.run([*command, flower], capture_output=True, text=True, check=True)
    back = subprocess.run(
        [*command, "--to-text", "-"], input=made.stdout, capture_output=True, text=True, check=True
    )
    assert back.stdout == (REPO / "programs" / "flower.root").read_text(encoding="utf-8")
