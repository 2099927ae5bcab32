"""Which language a program is read in and which language messages are shown in.

A program's language is, first, the one a command was given (``--language``), then the one
its opening lines declare (``# language: nl``), else English. Messages follow a studio page's
language (the one the page asks in), then the command's ``--language``, then the program's
declared language, then the system locale (``LC_ALL``, ``LC_MESSAGES``, ``LANG``), else English.
Code quoted in a message is written in the program's language whatever the message's is.

The choices are a context variable, not a global: a command sets them once for its run, and the
studio's server, speaking to many pages at once, gives each request its own (:func:`speaking`),
so two pages in two languages never see each other's.
"""

from __future__ import annotations

import contextlib
import dataclasses
import os
from collections.abc import Iterator
from contextvars import ContextVar
from dataclasses import dataclass

from rootlang.locale.keywords import LANGUAGES

__all__ = [
    "NONE_GIVEN",
    "Languages",
    "choose_language",
    "chosen_language",
    "current_languages",
    "for_page",
    "keyword_language",
    "message_language",
    "set_program_language",
    "speaking",
]


@dataclass(frozen=True)
class Languages:
    """The languages in force (None: not given)."""

    chosen: str | None = None  # the command line's: programs are read in it, messages shown in it
    program: str | None = None  # the program being worked on declares it (`# language: nl`)
    page: str | None = None  # a studio page's: its messages are shown in it, nothing is read in it


NONE_GIVEN = Languages()  # programs read in English, messages in the system locale's
_LANGUAGES: ContextVar[Languages] = ContextVar("rootlang_languages", default=NONE_GIVEN)


def current_languages() -> Languages:
    """The languages in force here (to hand to a worker process, which starts with none)."""
    return _LANGUAGES.get()


@contextlib.contextmanager
def speaking(languages: Languages) -> Iterator[None]:
    """``languages`` within the block, in this context alone (a request's own task and what it
    starts); the ones before come back after it."""
    token = _LANGUAGES.set(languages)
    try:
        yield
    finally:
        _LANGUAGES.reset(token)


def for_page(language: str | None) -> Languages:
    """The languages in force, with messages in a page's ``language`` (one rootlang does not
    know is passed over, as the system locale's is)."""
    return dataclasses.replace(_LANGUAGES.get(), page=language)


def choose_language(language: str | None) -> None:
    """The language given on the command line (None: none given)."""
    _LANGUAGES.set(dataclasses.replace(_LANGUAGES.get(), chosen=language))


def chosen_language() -> str | None:
    return _LANGUAGES.get().chosen


def set_program_language(language: str | None) -> None:
    """The language the program being worked on declares (for its messages)."""
    _LANGUAGES.set(dataclasses.replace(_LANGUAGES.get(), program=language))


def keyword_language() -> str:
    """The language of the program being worked on: what keywords in messages are written in."""
    languages = _LANGUAGES.get()
    return languages.chosen or languages.program or "en"


def message_language() -> str:
    """The language messages are shown in."""
    languages = _LANGUAGES.get()
    for language in (languages.page, languages.chosen, languages.program, _system_language()):
        if language in LANGUAGES:
            return language
    return "en"


def _system_language() -> str | None:
    for variable in ("LC_ALL", "LC_MESSAGES", "LANG"):
        value = os.environ.get(variable, "")
        if value:
            return value[:2].lower()
    return None
