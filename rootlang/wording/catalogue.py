"""Messages in the child's language: the one catalogue (:mod:`rootlang.messages`, English)
and its translations, one JSON file a language in ``rootlang/locale/messages/``, keyed by the
same codes with the same ``{placeholders}``. A code not translated yet is shown in English.
:func:`message` is handed the :class:`~rootlang.wording.language.Languages` to speak (nothing is
ambient): the message in their message language, each value as its type says
(:mod:`rootlang.wording.shown`): words that describe (:class:`Described`, the words of a
:class:`Phrase`) in the message's language, whole, as the catalogue translates them; code
(:class:`Code`, the code in a :class:`Phrase`) with their program's keywords; any other value
(a name, a path, a number, a reason) as it is. Nothing is looked for inside a value's text.

Why JSON keyed by code, not gettext ``.po`` files: the codes are already the catalogue's keys
(gettext keys a translation by its English text, so every English rewording would orphan it),
the placeholders stay Python's ``{name}``, and it needs no tool to compile (docs/languages.md).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Mapping
from typing import Any, Protocol, runtime_checkable

from rootlang.messages import MESSAGES
from rootlang.wording.language import Languages
from rootlang.wording.shown import Code, Described, InUnit, Phrase, Suggestion, Write

__all__ = ["Spoken", "message", "translations", "writes_code_with"]

DID_YOU_MEAN = ' Did you mean "{word}"?'  # a suggestion as the catalogue writes it


CodeIn = Callable[[str, str], str]
"""How English code is written in a language: ``(code, language) -> code``."""


def _as_written(code: str, language: str) -> str:
    return code


_code_in: list[CodeIn] = [_as_written]


def writes_code_with(code_in: CodeIn) -> None:
    """Hand the catalogue how code is written in each language: the keyword tables
    (:func:`rootlang.locale.lines.from_english`, which hands itself in when it loads) stand
    above the forms, far above the messages. Until then code stays as written: English, as a
    program read in another language has loaded them."""
    _code_in[0] = code_in


def from_english(code: str, language: str) -> str:
    return _code_in[0](code, language)


@runtime_checkable
class Spoken(Protocol):
    """A value that is itself a message (a diagnostic given as another's reason): shown in
    the same languages as the message it is part of."""

    def shown(self, languages: Languages) -> str: ...


def message(code: str, values: Mapping[str, object], languages: Languages) -> str:
    """The message for ``code`` in the language ``languages`` show messages in, the code in it
    in their program's language."""
    english = MESSAGES[code]
    language = languages.messages
    table = {} if language == "en" else translations(language)
    template: str | None = table.get(code)
    if template is None:
        return english.format(
            **{name: _english(value, languages) for name, value in values.items()}
        )
    keywords = languages.keywords
    shown = {
        name: value.shown(languages)
        if isinstance(value, Spoken)
        else _shown(value, keywords, language)
        for name, value in values.items()
    }
    return template.format(**shown)


def _english(value: object, languages: Languages) -> object:
    """A value as an English message shows it (a message in it in the same languages)."""
    return value.shown(languages) if isinstance(value, Spoken) else value


@functools.cache
def translations(language: str) -> dict[str, Any]:
    """Code -> message in ``language``; also ``_did_you_mean`` (the suggestion's sentence),
    ``_values`` (whole values: "an angle") and ``_phrases`` (parts of values: " or ")."""
    import json  # (only for a language other than English: start-up)
    from importlib import resources

    folder = resources.files("rootlang.locale").joinpath("messages")
    text = folder.joinpath(f"{language}.json").read_text("utf-8")
    loaded: dict[str, Any] = json.loads(text)
    return loaded


def _shown(value: object, keywords: str, language: str) -> object:
    """A value as a message shows it: a suggestion's sentence, a kind of value ("an angle") and
    words that describe in the message's language; code (:class:`Code`, and the code in a
    :class:`Phrase`) with its keywords in the program's language; any other value as it is."""
    if isinstance(value, Suggestion):
        said = translations(language).get("_did_you_mean", DID_YOU_MEAN)
        wrote = _write_shown(value.write, keywords, language) if value.write else ""
        return said.format(word=from_english(value.word, keywords)) + wrote
    if isinstance(value, Write):
        return _write_shown(value, keywords, language)
    if isinstance(value, InUnit):
        in_unit = _words(language).get("{kind} in {unit}", "{kind} in {unit}")
        return in_unit.format(kind=_part_shown(value.kind, keywords, language), unit=value.unit)
    if isinstance(value, Code | Described | Phrase):
        return _part_shown(value, keywords, language)
    return value  # a name the child gave, a path, a number, a reason


def _part_shown(part: str | Code | Described | Phrase, keywords: str, language: str) -> str:
    """Words in the message's language (a whole value or phrase the catalogue knows, else a
    phrase's parts; words it doesn't know in English), code in the program's."""
    if isinstance(part, Code):
        code = from_english(part.text, keywords)
        return f"`{code}`" if part.quoted else code
    english = str(part)
    known = _words(language).get(english)
    if known is not None:
        return known
    if isinstance(part, Phrase):
        return "".join(_part_shown(inner, keywords, language) for inner in part.parts)
    return english


def _write_shown(write: Write, keywords: str, language: str) -> str:
    """ " Write: `...`" (or the lines under " Write these lines:"), the code in the program's
    language."""
    lines = [from_english(line, keywords) for line in write.lines]
    if len(lines) == 1:
        return _part_shown(" Write: ", keywords, language) + f"`{lines[0]}`"
    return _part_shown(" Write these lines:", keywords, language) + "".join(
        f"\n    {line}" for line in lines
    )


@functools.cache
def _words(language: str) -> dict[str, str]:
    """English words -> ``language``'s: the catalogue's ``_values`` (whole values: "an
    angle", "add") and ``_phrases`` (parts of a phrase: "the end of the line", " or ")."""
    table = translations(language)
    words: dict[str, str] = {**table.get("_phrases", {}), **table.get("_values", {})}
    return words
