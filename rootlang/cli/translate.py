"""`rootlang translate FILE --to LANGUAGE [-o OUT]`: rewrite a program's keywords in another
language, keeping its names, strings, comments and layout.

The program is read in its own language (``--language``, or its ``# language: xx`` line,
else English); a ``# language:`` line is rewritten to name the new language, or added as the
first line, so the translation runs as it is. The translation
is checked by translating it back: if that does not give the same program (a name of the
program is a word of the new language), nothing is written and E902 names the word.
"""

from __future__ import annotations

import argparse
import difflib
import re
import sys

from rootlang.app.files import read_program, write_file
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
    translated = translate(source, args.to, args.file, args.language)
    if args.output:
        write_file(args.output, translated)
    else:
        sys.stdout.write(translated)
    return 0


def translate(source: str, language: str, file: str = "", written_in: str | None = None) -> str:
    """``source`` (in ``written_in``, else as :func:`program_language` decides) with its
    keywords in ``language``; RootlangError E902 if that would change what it means."""
    english = to_english(source, program_language(source, written_in)).text
    translated = from_english(english, language)
    back = to_english(translated, language).text
    if back != english and not _same_program(english, back):
        raise RootlangError([_changed_name(english, back, language).in_file(file)], source)
    return _with_declaration(translated, language)


def _same_program(english: str, back: str) -> bool:
    """The translation reads back as the same program, if not the same text: another spelling
    of a word (`pen` comes back as `marker`, `stop   moving` as `stop moving`)."""
    if _words(english) == _words(back):
        return True
    from rootlang import ast
    from rootlang.checks import parse

    try:
        return ast.same_tree(parse(english, "", "en"), parse(back, "", "en"))
    except RootlangError:  # a program with mistakes: only the same words will do
        return False


def _words(text: str) -> list[list[str]]:
    return [line.lower().split() for line in text.split("\n")]


def _with_declaration(source: str, language: str) -> str:
    """The translation with its `# language:` line naming its language (added as the first
    line when it had none, after a byte order mark: the mark must stay first), so that it
    runs as it is."""
    declared = declared_language(source)
    if declared is None:
        mark = "\ufeff" if source.startswith("\ufeff") else ""
        body = source[len(mark) :]
        return source if language == "en" else f"{mark}# language: {language}\n{body}"
    lines = source.split("\n")
    number = declared[1]
    lines[number - 1] = re.sub(
        r"(language[ \t]*:[ \t]*)\S+", rf"\g<1>{language}", lines[number - 1], count=1
    )
    return "\n".join(lines)


def _changed_name(english: str, back: str, language: str) -> Diagnostic:
    """E902 on the first word that reads back as something else: a name of the program that
    is a word of ``language``."""
    lines_back = back.split("\n")
    for number, (line, line_back) in enumerate(
        zip(english.split("\n"), lines_back, strict=False), 1
    ):
        words = list(_WORD.finditer(line))
        words_back = [word.group().lower() for word in _WORD.finditer(line_back)]
        matcher = difflib.SequenceMatcher(a=[w.group().lower() for w in words], b=words_back)
        changed = next((i1 for tag, i1, _, _, _ in matcher.get_opcodes() if tag != "equal"), None)
        if changed is None or changed >= len(words):
            continue
        word = words[changed]
        span = Span(number, word.start() + 1, number, word.end() + 1)
        return diagnostic("E902", span, language=LANGUAGE_NAMES[language], name=word.group())
    return diagnostic("E902", Span(1, 1, 1, 2), language=LANGUAGE_NAMES[language], name="?")
