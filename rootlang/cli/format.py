"""`rootlang format FILE... [--check]`: rewrite programs in canonical form.

Canonical form (docs/language.md, "How programs are written"): four spaces a level, keywords
in lower case, values and brackets written one way, comments and blank lines kept. A file that
does not parse is left as it is and its mistakes are shown (exit 1). ``--check`` changes
nothing and exits 1 when a file would change; ``-`` reads a program from standard input and
writes the formatted program to standard output.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

from rootlang.app.files import read_program
from rootlang.cli.programs import show_diagnostics, summing_up
from rootlang.diagnostics import RootlangError, diagnostic, render
from rootlang.locale.catalogue import message
from rootlang.locale.language import Languages
from rootlang.locale.translate import about


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", metavar="FILE", nargs="+", help="a .root program, or - for stdin")
    parser.add_argument(
        "--check", action="store_true", help="change nothing; exit 1 if a file would change"
    )


def run(args: argparse.Namespace) -> int:
    from rootlang.formatting import format_source  # the parser loads only when it is needed

    failed = changed = unchanged = 0
    spoken: list[Languages] = []  # each program's languages, for the last line
    for path in args.files:
        try:
            source = sys.stdin.read() if path == "-" else read_program(path)
            formatted = format_source(source, "<stdin>" if path == "-" else path, args.language)
        except RootlangError as error:
            show_diagnostics(error.diagnostics, error.source, about(args.languages, error.source))
            failed += 1
            continue
        spoken.append(about(args.languages, source))
        if path == "-":
            if args.check:
                changed += formatted != source
            else:
                sys.stdout.write(formatted)
            continue
        if formatted == source:
            unchanged += 1
        elif args.check:
            told = render(diagnostic("E706", path=path), "", spoken[-1])
            print(told, file=sys.stderr)
            changed += 1
        else:
            _replace(Path(path), formatted)
            print(message("V061", {"path": path}, spoken[-1]))
            changed += 1
    if args.files != ["-"] and not args.check:
        counted = {"changed": changed, "unchanged": unchanged}
        print(message("V062", counted, summing_up(args.languages, spoken)))
    return 1 if failed or (args.check and changed) else 0


def _replace(path: Path, text: str) -> None:
    """Write next to the file, then swap it in: a crash or Ctrl-C never leaves half a file."""
    handle, temporary = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(handle, "w", encoding="utf-8", newline="\n") as file:
            file.write(text)
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise
