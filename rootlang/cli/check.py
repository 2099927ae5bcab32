"""`rootlang check [PATH...] [--json] [--robot RT0|RT1|Create3]`: find mistakes without running.

A PATH is a program (``hello`` for hello.root) or a folder, whose .root files are all checked;
without one, every program in this folder and below it is.

Exit 0 when no file has errors (warnings are fine), 1 otherwise. ``--json`` prints one list of
objects with ``file, line, column, end_line, end_column, code, severity, message``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rootlang.app.files import find_programs, named_world, read_program, world_for
from rootlang.checks import diagnose
from rootlang.cli.programs import robot_model, show_diagnostics, shown_folder
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic
from rootlang.locale.catalogue import message
from rootlang.locale.language import Languages
from rootlang.locale.translate import about
from rootlang.robots import RobotModel


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


def run(args: argparse.Namespace) -> int:
    found: list[tuple[Diagnostic, str]] = []
    sources: list[str] = []  # each program checked, as read
    checked = 0
    for path in args.paths:
        try:
            programs = find_programs([path], any_suffix=True)
        except RootlangError as error:  # one missing path does not stop the others' checks
            found.extend((item, "") for item in error.diagnostics)
            continue
        if not programs:
            found.append((diagnostic("E609", paths=shown_folder(path)), ""))
        for program in programs:
            source, mistakes = _check_file(str(program), args.robot, args.language)
            sources.append(source)
            found.extend(mistakes)
        checked += len(programs)
    # each program's messages in its own language (the one it declares, if no other is given)
    languages = {source: about(args.languages, source) for _, source in found}
    if args.json:
        import json

        shown = [item.to_json(languages[source]) for item, source in found]
        print(json.dumps(shown, indent=2, ensure_ascii=False))
    else:
        for item, source in found:
            show_diagnostics([item], source, languages[source])
        if not found:  # in the programs' language, when they all speak one
            spoken = {about(args.languages, source) for source in sources}
            print(message("V098", {"checked": checked}, _summing_up(args.languages, spoken)))
        else:  # after many messages, what they came to in one line (on stdout, as above)
            errors = sum(item.severity == "error" for item, _ in found)
            counted = {"errors": errors, "warnings": len(found) - errors, "checked": checked}
            print(message("V090", counted, _summing_up(args.languages, set(languages.values()))))
    return 1 if any(item.severity == "error" for item, _ in found) else 0


def _summing_up(command: Languages, programs: set[Languages]) -> Languages:
    """The languages of the last line: the programs' when they all speak one, else the
    command's."""
    return programs.pop() if len(programs) == 1 else command


def _check_file(
    path: str, robot: RobotModel | None, language: str | None
) -> tuple[str, list[tuple[Diagnostic, str]]]:
    """The program as read ("" if it can't be), and its mistakes each with that text."""
    try:
        source = read_program(path)
    except RootlangError as error:  # one unreadable file does not stop the others' checks
        return "", [(item.in_file(path), "") for item in error.diagnostics]
    found = [(item, source) for item in diagnose(source, path, robot, language)]
    try:  # a `# world:` line `rootlang sim` would refuse (its world file read, too)
        if named_world(Path(path), source) is not None:
            world_for(Path(path), source)
    except RootlangError as error:
        found = sorted([*found, *((item, source) for item in error.diagnostics)],
                       key=lambda pair: (pair[0].span, pair[0].code))  # fmt: skip
    return source, found
