"""Blocks in five languages: labels from the keyword tables, values kept in English, the
toolbox's categories and the studio page's words from one table."""

from __future__ import annotations

import json
from importlib import resources
from typing import Any

import pytest

from rootlang.blocks import block_definitions, to_text, toolbox
from rootlang.colors import LIGHT_COLORS
from rootlang.locale.blocks import BLOCKLY_MESSAGES, studio_strings
from rootlang.locale.keywords import LANGUAGES
from rootlang.studio.conversions import blocks_to_text, text_to_blocks
from rootlang.wording.language import Languages

OTHER_LANGUAGES = ("nl", "es", "fr", "de")


def _menus(definition: dict[str, Any]) -> list[tuple[str, list[str]]]:
    return [
        (argument["name"], [value for _, value in argument["options"]])
        for key, arguments in definition.items()
        if key.startswith("args")
        for argument in arguments
        if argument["type"] == "field_dropdown"
    ]


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_blocks_keep_their_shape_and_values_and_change_their_labels(language: str) -> None:
    english = {definition["type"]: definition for definition in block_definitions()}
    localized = {definition["type"]: definition for definition in block_definitions(language)}
    assert list(localized) == list(english)
    relabelled = 0
    for block, definition in localized.items():
        assert _menus(definition) == _menus(english[block]), block
        assert definition["message0"].count("%") == english[block]["message0"].count("%")
        relabelled += definition["message0"] != english[block]["message0"]
    assert relabelled > len(english) * 0.6


def test_a_few_blocks_read_as_their_lines_do() -> None:
    def label(language: str, block: str) -> str:
        found = next(d for d in block_definitions(language) if d["type"] == block)
        return str(found["message0"])

    assert label("nl", "root_when_started") == "wanneer gestart"
    assert label("es", "root_set_left_wheel") == "fija rueda izquierda %1"
    assert label("fr", "root_play") == "joue %1 pendant %2"
    assert label("de", "root_repeat_until") == "wiederhole bis %1"
    colours = next(d for d in block_definitions("fr") if d["type"] == "root_color")
    assert colours["args0"][0]["options"][0] == ["rouge", "red"]


@pytest.mark.parametrize("language", LANGUAGES)
def test_the_toolbox_and_the_studio_speak_the_language(language: str) -> None:
    names = [category["name"] for category in toolbox(language)["contents"]]
    strings = studio_strings(language)
    assert names == [strings[f"category.{c['name']}"] for c in toolbox()["contents"]]
    english = json.loads(
        resources.files("rootlang.locale").joinpath("studio.json").read_text("utf-8")
    )
    assert set(english[language]) == set(english["en"])
    if language != "en":
        assert strings["save"] != english["en"]["save"]
    static = resources.files("rootlang").joinpath("studio/static")
    assert static.joinpath(BLOCKLY_MESSAGES[language]).is_file()
    # the stage says a light's colour by the language's own colours' names (narrator.js)
    assert all(strings.get(f"colour_{name}") for name in LIGHT_COLORS), strings


def test_blocks_read_as_text_in_the_language_chosen_on_the_command_line() -> None:
    # the studio started with --language nl: a program without a "# language:" line reads as
    # Dutch blocks, and an edit of its blocks must give Dutch text back, not English
    studio = Languages(chosen="nl")
    dutch = "wanneer gestart\n    beweeg 10 cm\n"
    status, reply, _ = text_to_blocks(studio, json.dumps({"text": dutch}).encode())
    workspace = json.loads(reply)["workspace"]
    assert status == 200 and workspace is not None
    status, reply, _ = blocks_to_text(studio, json.dumps({"workspace": workspace}).encode())
    assert status == 200 and json.loads(reply)["text"] == dutch
    assert to_text(workspace, "en") == "when started\n    move 10 cm\n"
