"""Blocks and the studio in the child's language.

The block definitions and the toolbox are made in English (:mod:`rootlang.blocks`); here their
labels are translated with the keyword tables, so a block reads as its line of text does in
that language (``wanneer gestart``, ``zet linkerwiel``). Only what a child reads changes: each
menu item keeps its English value, so blocks convert to text exactly as in English. Blockly's
own strings (the ``if`` block, variables) come from its ``msg/<language>.js`` files, and the
page's own strings and the toolbox's category names from ``studio.json`` here.
"""

from __future__ import annotations

import functools
import json
from importlib import resources
from typing import Any

from rootlang import forms
from rootlang.forms import Category
from rootlang.locale.keywords import (
    ASSIGNMENT_TO,
    COLOURS,
    CONTROL,
    FUNCTION_WORDS,
    LANGUAGES,
    PROCEDURE_TO,
    UNIT_WORDS,
    VALUES,
    Row,
)
from rootlang.locale.translate import from_english
from rootlang.units import UNITS

__all__ = [
    "BLOCKLY_MESSAGES",
    "localized_blocks",
    "localized_toolbox",
    "studio_strings",
    "syntax_words",
]

JSON = dict[str, Any]

BLOCKLY_MESSAGES = {language: f"vendor/blockly/msg/{language}.js" for language in LANGUAGES}
"""Blockly's own translations of its built-in blocks, under the studio's static folder (the
studio's setup names the page's one to it)."""


def localized_blocks(definitions: list[JSON], language: str) -> list[JSON]:
    """Block definitions with their labels and menu items in ``language``."""
    if language == "en":
        return definitions
    return [_localized_block(definition, language) for definition in definitions]


def localized_toolbox(toolbox: JSON, language: str) -> JSON:
    """The toolbox with its categories named in ``language``."""
    if language == "en":
        return toolbox
    strings = studio_strings(language)
    categories = [
        {**entry, "name": strings.get(f"category.{entry['name']}", entry["name"])}
        for entry in toolbox["contents"]
    ]
    return {**toolbox, "contents": categories}


@functools.cache
def _all_studio_strings() -> dict[str, dict[str, str]]:
    text = resources.files("rootlang.locale").joinpath("studio.json").read_text("utf-8")
    loaded: dict[str, dict[str, str]] = json.loads(text)
    return loaded


def studio_strings(language: str) -> dict[str, str]:
    """The studio page's words in ``language`` (English for any not translated)."""
    strings = _all_studio_strings()
    return {**strings["en"], **strings.get(language, {})}


def _localized_block(definition: JSON, language: str) -> JSON:
    localized = dict(definition)
    for key, value in definition.items():
        if key.startswith("message") and isinstance(value, str):
            localized[key] = from_english(value, language)
        elif key.startswith("args") and isinstance(value, list):
            localized[key] = [_localized_argument(argument, language) for argument in value]
    return localized


def _localized_argument(argument: JSON, language: str) -> JSON:
    if argument.get("type") != "field_dropdown":
        return argument
    options = [[from_english(label, language), value] for label, value in argument["options"]]
    return {**argument, "options": options}


# The text pane's colours (CodeMirror's token names): a form's words by its toolbox category
# (the first form a word is in), the others by their keyword table
_FORM_KINDS = {
    Category.CONTROL: "keyword",
    Category.PROCEDURES: "keyword",
    Category.MESSAGES: "keyword",
    Category.EVENTS: "def",
    Category.SENSORS: "operator",
}  # motion, drawing, lights and sound: "builtin"


def _coloured() -> dict[str, list[Row]]:
    kinds: dict[str, list[Row]] = {
        "keyword": [*CONTROL],
        "def": [],
        "builtin": [*FUNCTION_WORDS],
        "operator": [*VALUES],
        "atom": [*COLOURS],
        "unit": [*UNIT_WORDS],
    }
    seen: set[str] = set()
    for form in forms.every_form():
        for said in form.said():
            if said.english not in seen:
                seen.add(said.english)
                kinds[_FORM_KINDS.get(form.category, "builtin")].append(said.row)
    return kinds


@functools.cache
def syntax_words(language: str) -> dict[str, list[str]]:
    """The words the text pane colours, by kind, as a program in ``language`` writes them (its
    own and English's, which stay valid in every language), longest first so a phrase wins over
    its first word; ``unit`` also has the unit symbols, coloured after a number only."""
    column = LANGUAGES.index(language) if language in LANGUAGES else 0
    kinds: dict[str, set[str]] = {}
    for kind, rows in _coloured().items():
        kinds[kind] = {row[0] for row in rows} | {row[column] or row[0] for row in rows}
    for own in (PROCEDURE_TO, ASSIGNMENT_TO):
        kinds["keyword"].add(own.get(language, "to"))
    kinds["unit"] |= {unit.name for unit in UNITS.values()}
    return {
        kind: sorted(words, key=lambda word: (-len(word), word)) for kind, words in kinds.items()
    }
