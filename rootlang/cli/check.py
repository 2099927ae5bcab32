"""`rootlang check [PATH...] [--json] [--robot RT0|RT1|Create3]`: find mistakes without running.

A PATH is a program (``hello`` for hello.root) or a folder, whose .root files are all checked;
without one, every program in this folder and below it is.

Exit 0 when no file has errors (warnings are fine), 1 otherwise. ``--json`` prints one list of
objects with ``file, line, column, end_line, end_column, code, severity, message``.
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from rootlang.app.files import find_programs, named_world, read_program, world_for
from rootlang.checks import diagnose
from rootlang.cli.programs import robot_model, show_diagnostics, shown_folder, summing_up
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic
from rootlang.locale.translate import about
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "paths", metavar="PATH", nargs="*", default=["."],
        help="programs, or folders to check every .root file in (default: this folder)",
    )  # fmt: skip
    parser.add_argument("--json", action="store_true", help="print the mistakes as JSON")
    parser.add_argument(
        "--robot",
        type=robot_model,
        metavar="MODEL",
        help="also warn about what this robot lacks: RT0, RT1 or Create3",
    )


@dataclass(frozen=True)
class _Checked:
    """What one program, or one path that names none, came to."""

    mistakes: Sequence[Diagnostic]
    languages: Languages  # its messages'
    source: str = ""  # the program as read ("" if it can't be, or a path names none)
    program: bool = False  # a program was found there (it counts as checked)


def run(args: argparse.Namespace) -> int:
    checked: list[_Checked] = []
    for path in args.paths:
        try:
            programs = find_programs([path], any_suffix=True)
        except RootlangError as error:  # one missing path does not stop the others' checks
            checked.append(_Checked(error.diagnostics, args.languages))
            continue
        if not programs:
            missing = diagnostic("E609", paths=shown_folder(path))
            checked.append(_Checked([missing], args.languages))
        checked.extend(_check_file(str(program), args) for program in programs)
    found = [(item, where) for where in checked for item in where.mistakes]
    count = sum(where.program for where in checked)
    if args.json:
        import json

        shown = [item.to_json(where.languages) for item, where in found]
        print(json.dumps(shown, indent=2, ensure_ascii=False))
    else:
        for item, where in found:
            show_diagnostics([item], where.source, where.languages)
        if not found:  # in the programs' language, when they all speak one
            spoken = {where.languages for where in checked}
            print(message("V098", {"checked": count}, summing_up(args.languages, spoken)))
        else:  # after many messages, what they came to in one line (on stdout, as above)
            errors = sum(item.severity == "error" for item, _ in found)
            counted = {"errors": errors, "warnings": len(found) - errors, "checked": count}
            spoken = {where.languages for _, where in found}
            print(message("V090", counted, summing_up(args.languages, spoken)))
    return 1 if any(item.severity == "error" for item, _ in found) else 0


def _check_file(path: str, args: argparse.Namespace) -> _Checked:
    """One program's mistakes, each told in its language (the one it declares, unless the
    command gives one)."""
    try:
        source = read_program(path)
    except RootlangError as error:  # one unreadable file does not stop the others' checks
        unread = [item.in_file(path) for item in error.diagnostics]
        return _Checked(unread, args.languages, program=True)
    found = diagnose(source, path, args.robot, args.language)
    try:  # a `# world:` line `rootlang sim` would refuse (its world file read, too)
        if named_world(Path(path), source) is not None:
            world_for(Path(path), source)
    except RootlangError as error:
        found = sorted([*found, *error.diagnostics], key=lambda item: (item.span, item.code))
    return _Checked(found, about(args.languages, source), source, program=True)
