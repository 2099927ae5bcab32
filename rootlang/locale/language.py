"""Which language a program is read in and which language messages are shown in.

A program's language is, first, the one a command was given (``--language``), then the one
its opening lines declare (``# language: nl``), else English. Messages follow the command's
``--language``, then the program's declared language, then the system locale (``LC_ALL``,
``LC_MESSAGES``, ``LANG``), else English.
"""

from __future__ import annotations

import os

from rootlang.locale.keywords import LANGUAGES

__all__ = [
    "choose_language",
    "chosen_language",
    "keyword_language",
    "message_language",
    "set_program_language",
]

_state: dict[str, str | None] = {"chosen": None, "program": None}


def choose_language(language: str | None) -> None:
    """The language given on the command line (None: none given)."""
    _state["chosen"] = language


def chosen_language() -> str | None:
    return _state["chosen"]


def set_program_language(language: str | None) -> None:
    """The language the program being worked on declares (for its messages)."""
    _state["program"] = language


def keyword_language() -> str:
    """The language of the program being worked on: what keywords in messages are written in."""
    return _state["chosen"] or _state["program"] or "en"


def message_language() -> str:
    """The language messages are shown in."""
    for language in (_state["chosen"], _state["program"], _system_language()):
        if language in LANGUAGES:
            return language
    return "en"


def _system_language() -> str | None:
    for variable in ("LC_ALL", "LC_MESSAGES", "LANG"):
        value = os.environ.get(variable, "")
        if value:
            return value[:2].lower()
    return None
