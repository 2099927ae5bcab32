"""Level 1: every picture block is one rootlang line, and goes through Level 2 and text and
back byte for byte; a line with no picture keeps the program above Level 1 and is named."""

from __future__ import annotations

import json
from typing import Any

import pytest

from rootlang.blocks import pictures, to_text, to_workspace
from rootlang.blocks.names import FORMS_BY_BLOCK
from rootlang.formatting import format_source
from rootlang.locale.keywords import LANGUAGES

EVERY_LINE = [
    (picture, value, count) for picture in pictures.PICTURES for value, count in picture.choices()
]


def _program(line: str) -> str:
    if line.startswith("when "):
        return f"{line}\n    wait 1 second\n"
    if line.startswith("repeat"):
        return f"when started\n    {line}\n        wait 1 second\n"
    return f"when started\n    {line}\n"


@pytest.mark.parametrize(("picture", "value", "count"), EVERY_LINE,
                         ids=[f"{p.block}-{v}-{c}" for p, v, c in EVERY_LINE])  # fmt: skip
def test_each_picture_block_is_one_line_and_round_trips(
    picture: pictures.Picture, value: str, count: int
) -> None:
    text = _program(picture.line(value, count))
    assert format_source(text) == text  # the line is written as rootlang writes it
    level1, above = pictures.to_pictures(to_workspace(text))
    assert above == []
    blocks = json.dumps(level1)
    assert picture.block in blocks
    assert to_text(level1) == text  # Level 1 -> text
    assert json.dumps(pictures.to_pictures(to_workspace(to_text(level1)))[0]) == blocks
    words = pictures.to_words(level1)  # Level 1 -> Level 2 -> text
    assert not any(block["type"].startswith("pic_") for block in _blocks(words))
    own = _blocks(words)[0 if text.startswith(picture.line(value, count)) else 1]
    assert own["type"] in FORMS_BY_BLOCK  # the picture's word block, from rootlang.forms
    assert to_text(words) == text


def _blocks(workspace: dict[str, Any]) -> list[dict[str, Any]]:
    found: list[dict[str, Any]] = []

    def walk(block: dict[str, Any]) -> None:
        found.append(block)
        for connection in [*block.get("inputs", {}).values(), block.get("next", {})]:
            for child in connection.values():
                walk(child)

    for top in workspace["blocks"]["blocks"]:
        walk(top)
    return found


def test_a_square_at_level_1_with_comments_and_blank_lines_kept() -> None:
    text = (
        "# a square\n"
        "when started\n"
        "    marker down\n"
        "    repeat 4\n"
        "        move forward 30 cm  # two robot lengths\n"
        "\n"
        "        turn right 90 degrees\n"
        "    marker up\n"
    )
    level1, above = pictures.to_pictures(to_workspace(text))
    assert above == []
    types = [block["type"] for block in _blocks(level1)]
    assert types == ["pic_when_started", "pic_pen_down", "pic_repeat", "pic_forward",
                     "pic_turn_right", "pic_pen_up"]  # fmt: skip
    assert to_text(level1) == text


def test_lines_with_no_picture_keep_the_program_above_level_1() -> None:
    text = 'when started\n    move forward 10 cm\n    turn right 90 degrees\n    say "hi"\n'
    level1, above = pictures.to_pictures(to_workspace(text))
    assert sorted(above) == ["L2", "L4"]  # the blocks of lines 2 and 4: the page marks them
    assert [block["type"] for block in _blocks(level1)][:4] == [
        "pic_when_started",
        "root_move_direction",
        "root_length",
        "pic_turn_right",
    ]
    assert to_text(level1) == text


def test_numbers_and_white_on_every_picture_block_reach_4_5_to_1() -> None:
    from rootlang.blocks.drawings import INK, PAPER

    assert pictures.contrast(INK, PAPER) >= 4.5  # a number key's digits
    for definition in pictures.picture_definitions():
        assert pictures.contrast(definition["colour"], "#ffffff") >= 4.5, definition["type"]


def test_a_step_is_one_robot_length() -> None:
    from rootlang.robots import RobotModel
    from rootlang.sim.models import MODELS

    assert round(MODELS[RobotModel.RT1].length / 10) == pictures.ROBOT_LENGTH_CM


@pytest.mark.parametrize("language", LANGUAGES)
def test_every_picture_block_says_what_it_does_in_each_language(language: str) -> None:
    own = pictures._meanings_file()[language]
    for picture in pictures.PICTURES:
        said = own[picture.block]
        assert said["words"], picture.block
        if picture.counted:
            assert "{n}" in said["words"] and said["one"], picture.block
        if len(picture.variants) > 1:
            assert "{what}" in said["words"], picture.block
            assert set(said["what"]) >= {v.value for v in picture.variants}, picture.block
