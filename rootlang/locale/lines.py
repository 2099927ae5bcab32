"""Translating the keywords of a line between English and another language: the word-level
step of :mod:`rootlang.locale.translate`, which needs only the keyword tables (the messages'
catalogue is handed it, to show code in a message in the program's language).
"""

from __future__ import annotations

import functools
import re
import unicodedata
from dataclasses import dataclass

from rootlang.locale.keywords import ASSIGNMENT_TO, KEYWORDS, LANGUAGES, NOTE_NAMES, PROCEDURE_TO
from rootlang.wording.catalogue import writes_code_with

__all__ = ["Anchor", "KeywordTable", "from_english", "keyword_table", "translate_line"]

_NOTE = re.compile(r"([^\W\d_]+?)(#|b)?([0-9])", re.IGNORECASE)
_SPACES = re.compile(r"[ \t]+")
_AXIS_AFTER = frozenset({"position", "tilt"})
Anchor = tuple[int, int, int, int]
"""A translated word: its column in the English text and in the child's text (0-based), and
its length in each."""


@dataclass(frozen=True)
class KeywordTable:
    """One language's words, both ways, and the patterns that find them in a line."""

    language: str
    to_local: dict[str, str]
    to_english: dict[str, str]
    english_tokens: re.Pattern[str]
    local_tokens: re.Pattern[str]
    notes_to_local: dict[tuple[str, str], str]
    notes_to_english: dict[str, tuple[str, str]]


def from_english(source: str, language: str) -> str:
    """The English program with its keywords in ``language``."""
    if language == "en":
        return source
    table = keyword_table(language)
    return "\n".join(
        translate_line(line, table, to_english=False)[0] for line in source.split("\n")
    )


def translate_line(line: str, table: KeywordTable, *, to_english: bool) -> tuple[str, list[Anchor]]:
    pattern = table.local_tokens if to_english else table.english_tokens
    out: list[str] = []
    anchors: list[Anchor] = []
    english_words: list[str] = []
    width = 0
    after_go_to = False
    for match in pattern.finditer(line):
        text = match.group()
        kind = match.lastgroup
        result = text
        if kind in ("phrase", "word", "sharp"):
            key = _SPACES.sub(" ", text).casefold()
            english, result = _word(key, text, table, english_words, after_go_to, to_english)
            if english == "go to":
                after_go_to = True
            elif english == "y":
                after_go_to = False
            english_words.extend(english.split())
        if result != text:
            anchors.append((width, match.start(), len(result), len(text)))
        out.append(result)
        width += len(result)
    return "".join(out), anchors


def _word(
    key: str,
    text: str,
    table: KeywordTable,
    english_words: list[str],
    after_go_to: bool,
    to_english: bool,
) -> tuple[str, str]:
    """(the English of the word, the word written in the target language)."""
    language = table.language
    first_word = not english_words
    assignment = len(english_words) == 2 and english_words[0] == "set"
    if english_words and english_words[-1] == "note" and _NOTE.fullmatch(key):
        note = _note(text, table, to_english)
        if note is not None:
            return key, note
    if to_english:
        if first_word and key == PROCEDURE_TO[language]:
            return "to", _with_case(text, "to")
        if assignment and key == ASSIGNMENT_TO[language]:
            return "to", _with_case(text, "to")
        if key == "y" and language == "es":
            axis = (english_words and english_words[-1] in _AXIS_AFTER) or after_go_to
            return ("y", text) if axis else ("and", _with_case(text, "and"))
        english = table.to_english.get(key)
        return (english, _with_case(text, english)) if english else (key, text)
    if key == "to" and first_word:
        return "to", _with_case(text, PROCEDURE_TO[language])
    if key == "to" and assignment:
        return "to", _with_case(text, ASSIGNMENT_TO[language])
    local = table.to_local.get(key)
    return (key, _with_case(text, local)) if local else (key, text)


def _note(text: str, table: KeywordTable, to_english: bool) -> str | None:
    match = _NOTE.fullmatch(text)
    if match is None:
        return None
    name, accidental, octave = match.group(1), match.group(2) or "", match.group(3)
    key = (name.casefold(), accidental.lower())
    if to_english:
        english = table.notes_to_english.get(name.casefold() + accidental.lower())
        if english is None:
            return None
        return _with_case(name, english[0]) + english[1] + octave
    local = table.notes_to_local.get(key)
    return None if local is None else _with_case(name, local) + octave


def _with_case(source: str, target: str) -> str:
    """``target`` in the case of ``source``: all capitals, a capital first letter, or as is."""
    letters = [c for c in source if c.isalpha()]
    if len(letters) > 1 and all(c.isupper() for c in letters):
        return target.upper()
    if source[:1].isupper():
        return target[:1].upper() + target[1:]
    return target


@functools.cache
def keyword_table(language: str) -> KeywordTable:
    column = LANGUAGES.index(language)
    to_local: dict[str, str] = {}
    to_english: dict[str, str] = {}
    for row in KEYWORDS:
        english, local = row[0], row[column] or row[0]
        to_local.setdefault(english, local)
        to_english.setdefault(local, english)
    for alias, english in _aliases(to_english).items():
        to_english.setdefault(alias, english)
    extra = [PROCEDURE_TO[language], ASSIGNMENT_TO[language]]  # both read as "to"
    notes_to_local = _notes(language)
    notes_to_english = {local: english for english, local in notes_to_local.items()}
    return KeywordTable(
        language,
        to_local,
        to_english,
        _tokens(list(to_local)),
        _tokens([*to_english, *extra]),
        notes_to_local,
        notes_to_english,
    )


def _notes(language: str) -> dict[tuple[str, str], str]:
    """(English letter, accidental) -> the note's name and accidental in ``language``."""
    names = NOTE_NAMES.get(language, {})
    table = {}
    for letter in "cdefgab":
        for accidental in ("", "#", "b"):
            table[(letter, accidental)] = names.get(letter, letter) + accidental
    if language == "de":  # English B is German H; English Bb is German B
        table[("b", "")], table[("b", "b")] = "h", "b"
    return table


def _aliases(words: dict[str, str]) -> dict[str, str]:
    """Spellings a child may type for a word: without accents (``posicion``), with ``ss`` and
    ``ae`` for ``ß`` and ``ä``, with a straight or a curly apostrophe. An alias that would
    stand for two different words is left out, and so is one of one or two letters (French
    ``à`` without its accent is ``a``, a common name)."""
    found: dict[str, set[str]] = {}
    for word, english in words.items():
        spellings = {
            _without_accents(word),
            _without_accents(_german_spelling(word)),
            word.replace("'", "\u2019"),
        }
        for spelling in spellings - {word}:
            found.setdefault(spelling, set()).add(english)
    return {
        alias: next(iter(meanings))
        for alias, meanings in found.items()
        if len(meanings) == 1 and alias not in words and len(alias) > 2
    }


def _without_accents(word: str) -> str:
    decomposed = unicodedata.normalize("NFD", word)
    return "".join(c for c in decomposed if not unicodedata.combining(c))


def _german_spelling(word: str) -> str:
    for letter, spelling in (("ß", "ss"), ("ä", "ae"), ("ö", "oe"), ("ü", "ue")):
        word = word.replace(letter, spelling)
    return word


def _tokens(phrases: list[str]) -> re.Pattern[str]:
    """A line's tokens: strings, hex colours, notes with ``#``, comments, the table's phrases
    (longest first), other words, and any other character."""
    ordered = sorted(set(phrases), key=len, reverse=True)
    alternatives = "|".join(r"[ \t]+".join(map(re.escape, p.split())) for p in ordered)
    return re.compile(
        r'(?P<string>"[^"\n]*"?|“[^”\n]*”?)'
        r"|(?P<hex>#[0-9a-f]{6}(?!\w))"
        r"|(?P<sharp>[^\W\d_]+#[0-9](?!\w))"
        r"|(?P<comment>#.*)"
        rf"|(?P<phrase>(?<!\w)(?:{alternatives})(?![\w'’]))"
        r"|(?P<word>[\w'’]+)"
        r"|(?P<other>.)",
        re.IGNORECASE,
    )


writes_code_with(from_english)  # code in a message, in the program's language
