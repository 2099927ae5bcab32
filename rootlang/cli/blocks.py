"""`rootlang blocks FILE.root` / `rootlang blocks --to-text FILE.json`: programs as blocks.

The first prints a program as a Blockly workspace (Blockly's JSON serialization); a program
that does not parse gets its mistakes instead, as `rootlang check --json` prints them, and
exit 1. ``--to-text`` reads a workspace (``-``: standard input) and prints the program in
canonical form; a workspace that can't be a program gets a message naming the block at fault,
after its code (E70x, listed in docs/blocks.md).
``--definitions`` prints the block definitions and the toolbox, for a page of your own.
``--level 1`` shows Level 1's picture blocks instead (``--to-text`` reads them at any level):
each picture block is one line; a line with no picture stays a word block (docs/levels.md).
How blocks and text correspond: docs/blocks.md.
"""

from __future__ import annotations

import argparse
import json
import sys

from rootlang.app.files import read_program
from rootlang.diagnostics import RootlangError, file_problem


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", nargs="?", help="a .root program (or - for stdin)")
    parser.add_argument(
        "--to-text",
        metavar="WORKSPACE",
        help="print the program a workspace JSON file shows (- reads standard input)",
    )
    parser.add_argument(
        "--definitions", action="store_true", help="print the block definitions and toolbox"
    )
    parser.add_argument(
        "--level",
        type=int,
        choices=(1, 2),
        default=2,
        help="1: picture blocks where a line has one (for pre-readers), 2: word blocks",
    )


def run(args: argparse.Namespace) -> int:
    from rootlang import blocks, jsontree  # the parser loads only when it is needed
    from rootlang.blocks import pictures
    from rootlang.locale.translate import about

    language = args.language or "en"  # --language: labels and text in that language
    if args.definitions:
        shown = (
            {"definitions": pictures.picture_definitions(language),
             "toolbox": pictures.picture_toolbox()}
            if args.level == 1
            else {"definitions": blocks.block_definitions(language),
                  "toolbox": blocks.toolbox(language)}
        )  # fmt: skip
        print(json.dumps(shown, indent=1, ensure_ascii=False))
        return 0
    if args.to_text is not None:
        workspace = sys.stdin.read() if args.to_text == "-" else _read_json(args.to_text)
        try:
            sys.stdout.write(blocks.to_text(workspace, args.language))
        except RootlangError as error:  # with its code: E70x is what to look up in docs
            for item in error.diagnostics:
                print(f"{item.code}: {item.shown(args.languages)}", file=sys.stderr)
            return 1
        return 0
    if args.file is None:
        raise RootlangError.of("E601", path="(no program given: rootlang blocks FILE.root)")
    source = sys.stdin.read() if args.file == "-" else read_program(args.file)
    try:
        workspace = blocks.to_workspace(source, args.file, args.language)
    except RootlangError as error:
        languages = about(args.languages, source)
        found = [d.to_json(languages) for d in error.diagnostics]
        print(json.dumps(found, indent=2, ensure_ascii=False))
        return 1
    if args.level == 1:
        workspace, _ = pictures.to_pictures(workspace)
    print(jsontree.dumps(workspace, indent=1, ensure_ascii=False))  # deep: a long script
    return 0


def _read_json(path: str) -> str:
    try:
        with open(path, encoding="utf-8") as file:
            return file.read()
    except FileNotFoundError:
        raise RootlangError.of("E601", path=path) from None
    except (OSError, UnicodeDecodeError) as error:
        raise RootlangError.of("E602", path=path, reason=file_problem(error)) from None
