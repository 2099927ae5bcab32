"""The keyword tables: each word means one thing in its language, no word is an English
keyword with another meaning, and docs/languages.md shows every row."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rootlang.checks import diagnose
from rootlang.locale.keywords import ASSIGNMENT_TO, KEYWORDS, LANGUAGES, PROCEDURE_TO
from rootlang.locale.translate import english_keywords, local_keywords

DOCS = Path(__file__).resolve().parents[2] / "docs" / "languages.md"
OTHER_LANGUAGES = LANGUAGES[1:]
# English words of the grammar that no table translates (letters, units, functions, spellings)
UNTRANSLATED = frozenset(
    [
        "x",
        "y",
        "z",
        "abs",
        "sin",
        "cos",
        "min",
        "max",
        "mod",
        "rgb",
        "auto",
        "moving",
        "go",
        "colour",
        "forwards",
        "backwards",
        "pen",
        "inches",
        "inch",
        "deg",
        "sec",
        "ms",
        "s",
        "cm",
        "mm",
        "m",
        "hz",
    ]
)
SHARED_ON_PURPOSE = {("es", "y")}  # `and`, and the y axis where an axis goes (docs/languages.md)


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_each_written_word_means_one_english_word(language: str) -> None:
    column = LANGUAGES.index(language)
    meanings: dict[str, set[str]] = {}
    for row in KEYWORDS:
        meanings.setdefault((row[column] or row[0]).casefold(), set()).add(row[0])
    assert {word: found for word, found in meanings.items() if len(found) > 1} == {}
    assert PROCEDURE_TO[language] not in meanings  # it is only `to` at the start of a line


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_no_word_is_an_english_keyword_that_means_something_else(language: str) -> None:
    english = english_keywords() | UNTRANSLATED
    clashes = {
        (language, word)
        for word, meaning in local_keywords(language).items()
        for part in word.split()
        if part in english and part != meaning and part not in meaning.split()
    }
    shared = {(language, ASSIGNMENT_TO[language])} | SHARED_ON_PURPOSE
    assert clashes - shared == set()


def test_every_table_row_is_in_the_docs() -> None:
    text = DOCS.read_text(encoding="utf-8")
    for row in KEYWORDS:
        line = "| " + " | ".join(f"`{cell or row[0]}`" for cell in row) + " |"
        assert line in text, row
    for language in OTHER_LANGUAGES:
        assert f"`{PROCEDURE_TO[language]}`" in text and f"`{ASSIGNMENT_TO[language]}`" in text


def test_the_docs_examples_check_cleanly() -> None:
    examples = re.findall(r"```root\n(.*?)```", DOCS.read_text(encoding="utf-8"), re.DOTALL)
    assert examples
    for example in examples:
        assert diagnose(example, "languages.md") == []
