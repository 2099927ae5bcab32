"""Translating a program's keywords between English and another language, word by word.

The parser reads English only. A program written in Dutch, Spanish, French or German is first
translated to English here, line by line, outside strings and comments; names, strings,
comments and layout stay as they are. Each line remembers where each translated word came
from, so error carets still point at the child's own text (:meth:`Translation.source_span`).
``rootlang translate`` and ``rootlang format`` use the reverse step (:func:`from_english`).

Matching is case-insensitive and takes the longest phrase first (``repite hasta que`` before
``repite``); the case of the first letter is kept (``Cuando`` <-> ``When``, ``WHEN`` <->
``CUANDO``). Three places decide between two meanings of one word:

- ``to`` as the first word of a line defines a procedure (``PROCEDURE_TO``);
- ``to`` right after ``set NAME`` gives a variable its value (``ASSIGNMENT_TO``);
- after ``note`` a note name is translated (``do4`` <-> ``C4``); elsewhere it is a name.

Spanish writes ``and`` as ``y``, which is also the y axis: ``y`` is the axis after
``position`` or ``tilt``, and the first ``y`` after ``go to x``; otherwise it is ``and``.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TypeVar

from rootlang import ast
from rootlang.diagnostics import (
    Diagnostic,
    RootlangError,
    Span,
    diagnostic,
    did_you_mean,
    source_lines,
)
from rootlang.locale.keywords import (
    ASSIGNMENT_TO,
    LANGUAGES,
    PROCEDURE_TO,
)
from rootlang.locale.lines import Anchor, from_english, keyword_table, translate_line
from rootlang.wording.language import Languages
from rootlang.wording.shown import Code, Suggestion

__all__ = [
    "Translation",
    "about",
    "declared_language",
    "from_english",
    "lines_in_english",
    "program_language",
    "relocated",
    "suggesting_in_language",
    "to_english",
]

_DECLARATION = re.compile(r"[ \t]*#[ \t]*language[ \t]*:[ \t]*(\S*)[ \t]*", re.IGNORECASE)
_TYPED = ("name", "word", "found", "unit")  # the values that hold the word a child typed
_N = TypeVar("_N", bound=ast.Node)


@dataclass
class Translation:
    """A program's text in English, and for each line where each of its words came from."""

    text: str
    anchors: list[list[Anchor]] = field(default_factory=list)
    """Per line, one for each word that was translated: its column in the English text and in
    the child's text (0-based), and its length in each."""

    def source_column(self, line: int, column: int) -> int:
        """The child's column (1-based) for a column of the English text."""
        if line < 1 or line > len(self.anchors) or column < 1:
            return column
        offset, shift = column - 1, 0
        for english, source, english_length, source_length in self.anchors[line - 1]:
            if english > offset:
                break
            if offset < english + english_length:
                return source + min(offset - english, source_length) + 1
            shift = (source + source_length) - (english + english_length)
        return offset + shift + 1

    def source_span(self, span: Span) -> Span:
        if span.line < 1:
            return span
        return Span(
            span.line,
            self.source_column(span.line, span.column),
            span.end_line,
            self.source_column(span.end_line, span.end_column),
        )


def declared_language(source: str) -> tuple[str, int] | None:
    """The language named by ``# language: xx`` among the opening comment lines, and its
    line; RootlangError E901 for a language rootlang does not know."""
    for number, line in enumerate(source.lstrip("\ufeff").splitlines(), 1):
        if line.strip() and not line.lstrip().startswith("#"):
            return None
        match = _DECLARATION.fullmatch(line)
        if match:
            language = match.group(1).lower()
            if language not in LANGUAGES:
                span = Span(number, match.start(1) + 1, number, match.end(1) + 1)
                raise RootlangError(
                    [diagnostic("E901", span, language=language, known=", ".join(LANGUAGES))],
                    source,
                )
            return language, number
    return None


def about(languages: Languages, source: str) -> Languages:
    """``languages`` for messages about ``source``: they speak the language it declares
    (``# language: nl``) unless told another, and write code in it."""
    try:
        declared = declared_language(source)
    except RootlangError:
        declared = None  # the parser reports the unknown language on its line
    return languages.for_program(declared[0] if declared else None)


def program_language(source: str, language: str | None = None) -> str:
    """The language to read ``source`` in: ``language`` if given (the command's
    ``--language``), else the one the program declares, else English."""
    if language is not None:
        return language
    declared = declared_language(source)
    return declared[0] if declared else "en"


def lines_in_english(
    source: str, numbers: Iterable[int], language: str | None = None
) -> dict[int, str]:
    """Those lines of the program (numbered from 1 as the parser numbers them; those it has)
    with their keywords in English, in whatever language it is written (``language``, else
    the one it declares): what a trace names its scripts by (their header lines), so a
    translation runs with the very same trace. Only these lines are translated (a line
    translates alone: no word depends on another line)."""
    try:
        language = program_language(source, language)
    except RootlangError:  # a language rootlang does not know: its lines as they are
        language = "en"
    lines = source_lines(source)
    return {
        number: to_english(lines[number - 1], language).text
        for number in numbers
        if 0 < number <= len(lines)
    }


def suggesting_in_language(
    found: list[Diagnostic], source: str, language: str | None = None
) -> list[Diagnostic]:
    """Diagnostics whose did-you-mean searches the program's own language (``language``, else
    the one it declares): an English suggestion is shown in that language, and a word close
    to none of the English words is looked up among that language's words (``muevee`` ->
    ``mueve``)."""
    try:
        language = program_language(source, language)
    except RootlangError:
        return found
    if language == "en":
        return found
    numbers = {item.span.line for item in found if "suggestion" in dict(item.values)}
    english = lines_in_english(source, numbers, language)
    return [_suggesting(item, language, english.get(item.span.line)) for item in found]


def _suggesting(item: Diagnostic, language: str, line: str | None) -> Diagnostic:
    """``item`` with its did-you-mean in ``language``. A word found among that language's
    words proposes the line (in English, as ``line`` is) with the word in its place, so it is
    tried in place like every other suggestion (rootlang.verify): `avance 10` is not told
    `avant`, which is a direction, not a command."""
    values = dict(item.values)
    if "suggestion" not in values:
        return item
    english = values["suggestion"]
    rewrite = None
    if isinstance(english, Suggestion):
        word = from_english(english.word, language)
        values["suggestion"] = dataclasses.replace(english, word=word)
    else:
        typed = next((_typed(values[k]) for k in _TYPED if k in values), "")
        local = did_you_mean(typed, _local_words(language)) if len(typed) > 2 else None
        if local is None:
            return item
        meant = to_english(local, language).text
        rewrite = _with_word(line, typed, meant) if line is not None else None
        if rewrite is None:
            return item.without_suggestion()
        values["suggestion"] = Suggestion(local)
    found = dataclasses.replace(item, values=tuple(sorted(values.items())))
    return found.offering(rewrite, item.without_suggestion()) if rewrite else found


def _typed(value: object) -> str:
    """The word a child typed, as a value holds it (quoted code: the code itself)."""
    return value.text if isinstance(value, Code) else str(value)


def _with_word(line: str, typed: str, word: str) -> str | None:
    """``line`` with the word ``typed`` (the first time it stands alone) written ``word``."""
    found = re.search(rf"(?<!\w){re.escape(typed)}(?!\w)", line, re.IGNORECASE)
    if found is None:
        return None
    return (line[: found.start()] + word + line[found.end() :]).strip()


@functools.cache
def _local_words(language: str) -> frozenset[str]:
    table = keyword_table(language)
    return frozenset([*table.to_local.values(), PROCEDURE_TO[language], ASSIGNMENT_TO[language]])


def relocated(node: _N, translation: Translation) -> _N:
    """``node`` (and every node in it) with its spans moved back onto the child's text."""
    changes: dict[str, object] = {}
    for item in dataclasses.fields(node):
        value = getattr(node, item.name)
        moved = _relocated_value(value, translation)
        if moved is not value:
            changes[item.name] = moved
    return dataclasses.replace(node, **changes) if changes else node  # type: ignore[arg-type]


def _relocated_value(value: object, translation: Translation) -> object:
    if isinstance(value, Span):
        moved = translation.source_span(value)
        return value if moved == value else moved
    if isinstance(value, ast.Node):
        return relocated(value, translation)
    if isinstance(value, tuple) and value and isinstance(value[0], (ast.Node, Span, tuple)):
        items = tuple(_relocated_value(element, translation) for element in value)
        same = all(a is b for a, b in zip(items, value, strict=True))
        return value if same else items
    return value


def to_english(source: str, language: str) -> Translation:
    """The program with its keywords in English (``language`` "en": unchanged, and no word
    moved, so no anchors)."""
    if language == "en":
        return Translation(source)
    table = keyword_table(language)
    lines: list[str] = []
    anchors: list[list[Anchor]] = []
    for line in source.split("\n"):
        text, line_anchors = translate_line(line, table, to_english=True)
        lines.append(text)
        anchors.append(line_anchors)
    return Translation("\n".join(lines), anchors)
