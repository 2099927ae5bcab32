"""`rootlang translate FILE --to LANGUAGE [-o OUT]`: rewrite a program's keywords in another
language, keeping its names, strings, comments and layout.

The program is read in its own language (``--language``, or its ``# language: xx`` line,
else English); a ``# language:`` line is rewritten to name the new language. The translation
is checked by translating it back: if that does not give the same program (a name of the
program is a word of the new language), nothing is written and E902 names the word.
"""

from __future__ import annotations

import argparse
import re
import sys

from rootlang.cli.programs import read_program
from rootlang.diagnostics import Diagnostic, RootlangError, Span, diagnostic
from rootlang.locale.keywords import LANGUAGE_NAMES, LANGUAGES
from rootlang.locale.translate import (
    declared_language,
    from_english,
    program_language,
    to_english,
)

_WORD = re.compile(r"\w+")


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="a .root program")
    parser.add_argument(
        "--to", required=True, choices=LANGUAGES, metavar="LANGUAGE",
        help="the language to write it in: " + ", ".join(LANGUAGES),
    )  # fmt: skip
    parser.add_argument("-o", "--output", metavar="OUT", help="write here (default: the screen)")


def run(args: argparse.Namespace) -> int:
    source = read_program(args.file)
    translated = translate(source, args.to, args.file)
    if args.output:
        with open(args.output, "w", encoding="utf-8", newline="\n") as file:
            file.write(translated)
    else:
        sys.stdout.write(translated)
    return 0


def translate(source: str, language: str, file: str = "", written_in: str | None = None) -> str:
    """``source`` (in ``written_in``, else as :func:`program_language` decides) with its
    keywords in ``language``; RootlangError E902 if that would change what it means."""
    english = to_english(source, program_language(source, written_in)).text
    translated = from_english(english, language)
    back = to_english(translated, language).text
    if back != english:
        raise RootlangError([_changed_name(english, back, language).in_file(file)], source)
    return _with_declaration(translated, language)


def _with_declaration(source: str, language: str) -> str:
    declared = declared_language(source)
    if declared is None:
        return source
    lines = source.split("\n")
    number = declared[1]
    lines[number - 1] = re.sub(
        r"(language[ \t]*:[ \t]*)\S+", rf"\g<1>{language}", lines[number - 1], count=1
    )
    return "\n".join(lines)


def _changed_name(english: str, back: str, language: str) -> Diagnostic:
    for number, (line, line_back) in enumerate(
        zip(english.split("\n"), back.split("\n"), strict=True), 1
    ):
        if line == line_back:
            continue
        for word in _WORD.finditer(line):
            if not re.search(rf"(?<!\w){re.escape(word.group())}(?!\w)", line_back):
                span = Span(number, word.start() + 1, number, word.end() + 1)
                return diagnostic(
                    "E902", span, language=LANGUAGE_NAMES[language], name=word.group()
                )
    return diagnostic("E902", language=LANGUAGE_NAMES[language], name="?")
