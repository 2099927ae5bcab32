"""Lossless for real: every comment a workspace can hold reaches the text and back, the text
`--to-text` gives is always a fixed point of `format`, and no block combination gives text
rootlang can't read (it is refused with an E70x that says its code)."""

from __future__ import annotations

import json
import subprocess
import sys
from typing import Any

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rootlang.blocks import block_definitions, to_text, to_workspace, toolbox
from rootlang.blocks.text_to_blocks import bubble_line, comment_from_bubble
from rootlang.diagnostics import RootlangError
from rootlang.formatting import format_source

from .programs import random_program

JSON = dict[str, Any]
# Every line break a text box, an editor or Python's splitlines knows, and control characters
LINE_BREAKS = ["\r", "\r\n", "\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029"]
COMMENT_TEXT = st.text(
    alphabet=st.characters(
        blacklist_categories=("Cs", "Cc", "Zl", "Zp"), blacklist_characters="\x85"
    ),
    max_size=12,
)


def workspace(*tops: JSON, comments: list[str] | None = None) -> JSON:
    found: JSON = {"blocks": {"languageVersion": 0, "blocks": list(tops)}}
    if comments is not None:
        found["workspaceComments"] = [
            {"id": f"w{index}", "x": 0, "y": 0, "text": text} for index, text in enumerate(comments)
        ]
    return found


def started(*statements: JSON, comment: str | None = None) -> JSON:
    body: JSON | None = None
    for statement in reversed(statements):
        statement = dict(statement)
        if body is not None:
            statement["next"] = {"block": body}
        body = statement
    top: JSON = {"type": "root_when_started", "id": "top"}
    if body is not None:
        top["inputs"] = {"BODY": {"block": body}}
    return with_comment(top, comment)


def with_comment(block: JSON, comment: str | None) -> JSON:
    if comment is not None:
        block["icons"] = {"comment": {"text": comment, "pinned": False}}
    return block


def move(
    centimetres: float = 10, comment: str | None = None, value_comment: str | None = None
) -> JSON:
    value = with_comment(
        {"type": "root_length", "fields": {"NUM": centimetres, "UNIT": "cm"}}, value_comment
    )
    return with_comment({"type": "root_move", "inputs": {"DISTANCE": {"shadow": value}}}, comment)


def fixed_point(text: str) -> str:
    assert format_source(text) == text
    assert to_text(json.loads(json.dumps(to_workspace(text)))) == text
    return text


# ---- comments ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "comment", ["#", "# x", "##x", "# #x", "#  two spaces", "# ## heading", "# \ttab", "# ü ☃"]
)
def test_every_canonical_comment_round_trips_on_its_own_and_at_a_line_end(comment: str) -> None:
    for source in (
        f"when started\n    {comment}\n    move 10 cm\n",
        f"when started\n    move 10 cm  {comment}\n",
        f"{comment}\nwhen started\n    move 10 cm\n",
        f"when started\n    move 10 cm\n    {comment}\n",
    ):
        assert fixed_point(source) == source


@given(st.lists(COMMENT_TEXT, min_size=1, max_size=4))
@settings(max_examples=300, deadline=None)
def test_a_bubble_holds_any_lines_and_the_text_is_a_fixed_point(lines: list[str]) -> None:
    bubble = "\n".join(lines)
    text = to_text(workspace(started(move(comment=bubble))))
    fixed_point(text)
    # each line of the bubble is a comment line above the block, as the bubble shows it
    shown = [bubble_line(line.strip()) for line in text.split("\n")[1 : 1 + len(lines)]]
    assert shown == [bubble_line(comment_from_bubble(line)) for line in lines]
    assert [comment_from_bubble(line) for line in shown] == [
        comment_from_bubble(line) for line in lines
    ]


def test_a_bubble_line_starting_with_a_hash_comes_back_as_it_was() -> None:
    text = to_text(workspace(started(move(comment="#x\n x\n##"))))
    assert text == "when started\n    ##x\n    # x\n    ###\n    move 10 cm\n"
    bubble = to_workspace(text)["blocks"]["blocks"][0]["inputs"]["BODY"]["block"]["icons"]
    assert bubble["comment"]["text"] == "#x\nx\n##"


def test_an_empty_comment_is_kept_in_the_data_not_in_an_empty_bubble() -> None:
    """Blockly saves no bubble whose text is empty: the empty `#` lives in the block's data."""
    source = "when started\n    #\n    move 10 cm  #\n"
    block = to_workspace(source)["blocks"]["blocks"][0]["inputs"]["BODY"]["block"]
    assert "icons" not in block
    assert json.loads(block["data"]) == {"before": ["e"], "eole": [0]}
    assert fixed_point(source) == source


def test_comments_on_value_blocks_go_above_their_line() -> None:
    inner = with_comment({"type": "root_number", "fields": {"NUM": 2}}, "two")
    times = {
        "type": "root_arithmetic",
        "fields": {"OP": "*"},
        "inputs": {
            "A": {"block": inner},
            "B": {"shadow": {"type": "root_number", "fields": {"NUM": 3}}},
        },
    }
    set_block = {
        "type": "variables_set",
        "fields": {"VAR": {"id": "v"}},
        "inputs": {"VALUE": {"block": with_comment(times, "six")}},
    }
    found = workspace(started(move(comment="own", value_comment="ten cm"), set_block))
    found["variables"] = [{"name": "x", "id": "v"}]
    text = to_text(found)
    assert text == (
        "when started\n    # own\n    # ten cm\n    move 10 cm\n    # six\n    # two\n"
        "    set x to 2 * 3\n"
    )
    fixed_point(text)


def test_comments_on_an_if_s_conditions_go_above_their_branch() -> None:
    condition = with_comment({"type": "root_boolean", "fields": {"BOOL": "true"}}, "always")
    other = with_comment({"type": "root_boolean", "fields": {"BOOL": "false"}}, "never")
    branch = {
        "type": "controls_if",
        "extraState": {"elseIfCount": 1},
        "inputs": {
            "IF0": {"block": condition},
            "DO0": {"block": move()},
            "IF1": {"block": other},
            "DO1": {"block": move(20)},
        },
    }
    text = to_text(workspace(started(branch)))
    assert text == (
        "when started\n    # always\n    if true\n        move 10 cm\n    # never\n"
        "    else if false\n        move 20 cm\n"
    )
    fixed_point(text)


def test_workspace_comments_open_the_program_as_written() -> None:
    text = to_text(workspace(started(move()), comments=["plan\n\n#x\n# y\n#", ""]))
    assert text == "# plan\n\n# x\n# y\n#\n\nwhen started\n    move 10 cm\n"
    fixed_point(text)


@pytest.mark.parametrize("separator", LINE_BREAKS)
def test_a_line_break_inside_a_comment_or_text_is_refused(separator: str) -> None:
    """Written out, it would start a line of program of its own (a second script!)."""
    sneaky = f"hi{separator}when started{separator}    move 100 cm"
    cases = [
        workspace(started(move()), comments=[sneaky]),
        workspace(started(move(comment=sneaky))),
        workspace(started(move(value_comment=sneaky))),
        workspace(started({"type": "root_say", "inputs": {
            "TEXT": {"shadow": {"type": "root_text", "fields": {"TEXT": sneaky}}}}})),
    ]  # fmt: skip
    for case in cases:
        with pytest.raises(RootlangError) as caught:
            to_text(case)
        assert caught.value.diagnostics[0].code == "E705"


@pytest.mark.parametrize("separator", ["\x0b", "\x0c", "\x85", "\u2028", "\u2029"])
def test_a_program_holding_a_line_break_other_than_a_line_end_is_refused(
    separator: str,
) -> None:
    for source in (
        f'when started\n    say "a{separator}b"\n',
        f"when started\n    move 1 cm  # a{separator}b\n",
    ):
        with pytest.raises(RootlangError) as caught:
            format_source(source)
        assert [d.code for d in caught.value.diagnostics] == ["E012"]


# ---- blocks that would make text rootlang can't read ---------------------------------------


def test_a_join_with_no_values_is_refused() -> None:
    join = {"type": "root_join", "extraState": {"values": 0}}
    say = {"type": "root_say", "inputs": {"TEXT": {"block": join}}}
    with pytest.raises(RootlangError) as caught:
        to_text(workspace(started(say)))
    assert caught.value.diagnostics[0].code == "E703"
    assert "at least one value" in caught.value.diagnostics[0].english


def test_a_when_condition_that_reads_as_an_event_gives_that_event() -> None:
    condition = {"type": "root_sensor_bumper", "fields": {"WHERE": "left"}}
    hat = {"type": "root_when_condition", "inputs": {
        "CONDITION": {"block": condition}, "BODY": {"block": move()}}}  # fmt: skip
    assert fixed_point(to_text(workspace(hat))) == "when bumper left pressed\n    move 10 cm\n"


def toolbox_blocks() -> list[JSON]:
    found: list[JSON] = []
    for category in toolbox()["contents"]:
        found.extend(item for item in category.get("contents", []) if item["kind"] == "block")
    return found


KINDS = {definition["type"]: definition for definition in block_definitions()}


@pytest.mark.parametrize("item", toolbox_blocks(), ids=lambda item: item["type"])
def test_every_toolbox_block_as_it_comes_gives_text_format_keeps(item: JSON) -> None:
    block = {key: value for key, value in item.items() if key != "kind"}
    definition = KINDS.get(block["type"], {"previousStatement": None})  # controls_if
    for name in ("BODY", "DO0"):  # a body the block needs, as a child would give it
        if any(argument.get("name") == name for argument in _arguments(definition)):
            block.setdefault("inputs", {})[name] = {"block": {"type": "root_stop_moving"}}
    if block["type"] == "controls_if":
        block.setdefault("inputs", {})["DO0"] = {"block": {"type": "root_stop_moving"}}
    if "output" in definition:  # a value: said
        tops = [started({"type": "root_say", "inputs": {"TEXT": {"block": block}}})]
    elif "previousStatement" in definition:
        tops = [started(block)]
    else:  # a hat, or a `to` block (and a script calling nothing)
        tops = [block, started({"type": "root_stop_moving"})]
    fixed_point(to_text(workspace(*tops)))


def _arguments(definition: JSON) -> list[JSON]:
    return [
        argument
        for key, value in definition.items()
        if key.startswith("args")
        for argument in value
        if isinstance(argument, dict) and argument.get("type") == "input_statement"
    ]


# ---- 1,000 random programs with comments of every kind ------------------------------------


@st.composite
def programs_with_comments(draw: st.DrawFn) -> str:
    lines = random_program(draw(st.integers(0, 10**6))).rstrip("\n").split("\n")
    for _ in range(draw(st.integers(0, 6))):
        at = draw(st.integers(0, len(lines)))
        text = draw(COMMENT_TEXT)
        if draw(st.booleans()) and at < len(lines) and lines[at].strip():
            lines[at] += "  #" + text  # at the end of a line (after one already there: part of it)
        else:
            lines.insert(at, " " * draw(st.sampled_from([0, 4, 8, 2])) + "#" + text)
    return "\n".join(lines) + "\n"


@pytest.mark.slow  # (~40 s: sent out first, so it never ends a run alone)
@given(programs_with_comments())
@settings(max_examples=1000, deadline=None, suppress_health_check=[HealthCheck.too_slow])
def test_a_thousand_random_programs_with_comments_round_trip(source: str) -> None:
    canonical = format_source(source)
    assert format_source(canonical) == canonical
    assert to_text(json.loads(json.dumps(to_workspace(source)))) == canonical


# ---- the command line ----------------------------------------------------------------------


def test_to_text_errors_show_their_code(tmp_path: Any) -> None:
    loose = workspace(started(move()), move())
    path = tmp_path / "loose.json"
    path.write_text(json.dumps(loose), encoding="utf-8")
    done = subprocess.run(
        [sys.executable, "-m", "rootlang", "blocks", "--to-text", str(path)],
        capture_output=True, text=True, check=False,
    )  # fmt: skip
    assert done.returncode == 1
    assert done.stderr.startswith("E704: The `root_move` block")
    assert "Traceback" not in done.stderr
