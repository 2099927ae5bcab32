"""Which language a program is read in and which languages its messages are shown in.

A program's language is, first, the one a command was given (``--language``), then the one
its opening lines declare (``# language: nl``), else English. Messages follow a studio page's
language (the one the page asks in), then the command's ``--language``, then the program's
declared language, then the system locale (``LC_ALL``, ``LC_MESSAGES``, ``LANG``), else English.
Code quoted in a message is written in the program's language whatever the message's is.

These choices are a value, :class:`Languages`, handed to whatever shows a message (a
diagnostic, a line of the child's view, how a run ended): the command decides it once from its
options, the system locale (:meth:`Languages.of_command`) and the program it reads
(:func:`rootlang.locale.translate.about`); the studio's server from the command's and each
page's language (:meth:`Languages.for_page`), and hands it to its workers in their jobs. Records
(diagnostics, trace entries) hold no words until one of these shows them, so two pages in two
languages served at once never see each other's, and nothing is ambient.
"""

from __future__ import annotations

import dataclasses
import os
from collections.abc import Mapping
from dataclasses import dataclass

__all__ = ["ENGLISH", "LANGUAGES", "LANGUAGE_NAMES", "Languages", "system_language"]

LANGUAGES: tuple[str, ...] = ("en", "nl", "es", "fr", "de")
"""English, Dutch, Spanish, French and German: the languages a program may be written in and
messages are shown in."""

LANGUAGE_NAMES: dict[str, str] = {
    "en": "English",
    "nl": "Nederlands",
    "es": "Español",
    "fr": "Français",
    "de": "Deutsch",
}


@dataclass(frozen=True)
class Languages:
    """The languages in force (None: not given)."""

    chosen: str | None = None  # the command line's: programs are read in it, messages shown in it
    program: str | None = None  # the program being worked on declares it (`# language: nl`)
    page: str | None = None  # a studio page's: its messages are shown in it, nothing is read in it
    system: str | None = None  # the system locale's, read once by the command

    @classmethod
    def of_command(
        cls, chosen: str | None = None, environment: Mapping[str, str] | None = None
    ) -> Languages:
        """A command's: its ``--language`` (None: none given) and the system locale's."""
        return cls(chosen=chosen, system=system_language(environment))

    @property
    def keywords(self) -> str:
        """The program's language: what keywords (code) in messages are written in."""
        return self.chosen or self.program or "en"

    @property
    def messages(self) -> str:
        """The language messages are shown in."""
        for language in (self.page, self.chosen, self.program, self.system):
            if language in LANGUAGES:
                return language
        return "en"

    def for_page(self, language: str | None) -> Languages:
        """These, with messages in a page's ``language`` (one rootlang does not know is passed
        over, as the system locale's is)."""
        return dataclasses.replace(self, page=language)

    def for_program(self, language: str | None) -> Languages:
        """These, for a program that declares ``language`` (None: none)."""
        return dataclasses.replace(self, program=language)


ENGLISH = Languages()  # programs read and messages shown in English: the trace's and tests'


def system_language(environment: Mapping[str, str] | None = None) -> str | None:
    """The system locale's language (``fr`` for ``LANG=fr_FR.UTF-8``), None if none is set."""
    environment = os.environ if environment is None else environment
    for variable in ("LC_ALL", "LC_MESSAGES", "LANG"):
        value = environment.get(variable, "")
        if value:
            return value[:2].lower()
    return None
