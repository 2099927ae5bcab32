"""`rootlang format FILE... [--check]`: rewrite programs in canonical form.

Canonical form (docs/language.md, "How programs are written"): four spaces a level, keywords
in lower case, values and brackets written one way, comments and blank lines kept. A file that
does not parse is left as it is and its mistakes are shown (exit 1). ``--check`` changes
nothing and exits 1 when a file would change; ``-`` reads a program from standard input and
writes the formatted program to standard output.
"""

from __future__ import annotations

import argparse
import sys

from rootlang.app.files import read_program, write_file
from rootlang.cli import show_error
from rootlang.cli.programs import show_diagnostics, summing_up
from rootlang.diagnostics import RootlangError, diagnostic, render
from rootlang.locale.translate import about
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages


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
            try:
                write_file(path, formatted)
            except RootlangError as error:
                show_error(error, spoken[-1])
                failed += 1
                continue
            print(message("V061", {"path": path}, spoken[-1]))
            changed += 1
    if args.files != ["-"] and not args.check:
        counted = {"changed": changed, "unchanged": unchanged}
        print(message("V062", counted, summing_up(args.languages, spoken)))
    return 1 if failed or (args.check and changed) else 0
