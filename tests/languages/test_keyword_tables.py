"""The keyword tables: each word means one thing in its language, no word is an English
keyword with another meaning, and docs/languages.md shows every row."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rootlang import forms
from rootlang.checks import diagnose
from rootlang.locale.keywords import (
    ASSIGNMENT_TO,
    KEYWORDS,
    LANGUAGES,
    PROCEDURE_TO,
    TABLE_END,
    TABLE_START,
    with_table,
)
from rootlang.locale.translate import to_english

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
# every English word of the tables, `to`, and the grammar's words no table translates
ENGLISH = frozenset(word for row in KEYWORDS for word in row[0].split()) | {"to"} | UNTRANSLATED
SHARED_ON_PURPOSE = {("es", "y")}  # `and`, and the y axis where an axis goes (docs/languages.md)


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_each_written_word_means_one_english_word(language: str) -> None:
    column = LANGUAGES.index(language)
    meanings: dict[str, set[str]] = {}
    for row in KEYWORDS:
        meanings.setdefault((row[column] or row[0]).casefold(), set()).add(row[0])
    assert {word: found for word, found in meanings.items() if len(found) > 1} == {}
    assert PROCEDURE_TO[language] not in meanings  # it is only `to` at the start of a line


def _written_in(language: str) -> dict[str, str]:
    """Each word or phrase of the tables as ``language`` writes it -> its English."""
    column = LANGUAGES.index(language)
    words: dict[str, str] = {}
    for row in KEYWORDS:
        words.setdefault(row[column] or row[0], row[0])
    words[PROCEDURE_TO[language]] = "to"
    words.setdefault(ASSIGNMENT_TO[language], "to")
    return words


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_no_word_is_an_english_keyword_that_means_something_else(language: str) -> None:
    clashes = {
        (language, word)
        for word, meaning in _written_in(language).items()
        for part in word.split()
        if part in ENGLISH and part != meaning and part not in meaning.split()
    }
    shared = {(language, ASSIGNMENT_TO[language])} | SHARED_ON_PURPOSE
    assert clashes - shared == set()


@pytest.mark.parametrize("language", OTHER_LANGUAGES)
def test_an_english_keyword_means_itself_in_every_language(language: str) -> None:
    # English keywords stay valid in every language: no word of it, nor a spelling of one
    # without its accents (`posicion`), reads an English keyword as another word
    misread = {
        (language, word, to_english(word, language).text)
        for word in ENGLISH
        if to_english(word, language).text != word
    }
    assert {found[:2] for found in misread} - SHARED_ON_PURPOSE == set(), misread


def test_the_docs_keyword_table_is_generated_from_the_tables() -> None:
    text = DOCS.read_text(encoding="utf-8")
    assert TABLE_START in text and TABLE_END in text
    assert with_table(text) == text, "run: python -m rootlang.locale"
    for row in KEYWORDS:  # every row, a form's too
        assert "| " + " | ".join(f"`{cell or row[0]}`" for cell in row) + " |" in text, row


def test_the_docs_examples_check_cleanly() -> None:
    examples = re.findall(r"```root\n(.*?)```", DOCS.read_text(encoding="utf-8"), re.DOTALL)
    assert examples
    for example in examples:
        assert diagnose(example, "languages.md") == []


def test_every_word_of_every_form_has_its_translations() -> None:
    # a form's words are translated where the form is written (forms.Said: the keyword tables
    # read them from there), or are written as in English in every language, or are a word of
    # the tables no form has (`and` in `send "go" and wait`)
    untranslated = set()
    for form in forms.every_form():
        for part in form.parts:
            if isinstance(part, forms.Word):
                written = [part.text]
            elif isinstance(part, forms.Choice):
                written = [words for _, words in part.options]
            else:
                continue
            untranslated |= {(form.block, word) for text in written for word in text.split()}
    assert {(block, word) for block, word in untranslated if word not in ENGLISH} == set()
    # and the tables hold each form's words once, as its form writes them
    rows = {row[0]: row for row in KEYWORDS}
    for form in forms.every_form():
        assert all(rows[said.english] == said.row for said in form.said()), form.block
