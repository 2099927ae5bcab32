"""`rootlang test [PATH ...]`: run programs in the simulator and compare with their golden files."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from rootlang.app.files import find_programs
from rootlang.app.sandbox import Limits
from rootlang.cli.numbers import positive_megabytes, positive_seconds
from rootlang.cli.programs import shown_folder
from rootlang.diagnostics import RootlangError, diagnostic
from rootlang.testing import golden_path
from rootlang.testing.reports import junit_xml, report_text, shard, write_report
from rootlang.testing.runner import (
    Progress,
    Settings,
    Verdict,
    default_workers,
    run_golden_tests,
    summary,
)
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Run each program in the simulator, in the world its `# world:` line names, and compare "
        "what it did (its trace, where the robot ended, what it drew, how it ended) with the "
        "golden file next to it (spiral.root -> spiral.golden). A program with mistakes is "
        "compared with what `rootlang check` says about it."
    )
    parser.add_argument(
        "paths",
        metavar="PATH",
        nargs="*",
        default=["."],
        help="programs, or folders to search for .root files (default: this folder)",
    )
    parser.add_argument(
        "--update",
        action="store_true",
        help="save each program's output as its new golden file (read the diff before committing)",
    )
    parser.add_argument(
        "--jobs",
        "-j",
        type=int,
        metavar="N",
        default=default_workers(),
        help="programs to run at once (default: the number of CPU cores, here %(default)s)",
    )
    limits = Limits()
    parser.add_argument(
        "--time-limit",
        type=positive_seconds,
        metavar="SECONDS",
        default=None,
        help="stop each program after this much simulated time (default: its world's limit)",
    )
    parser.add_argument(
        "--cpu-limit",
        type=positive_seconds,
        metavar="SECONDS",
        default=limits.cpu_seconds,
        help="stop a program that computes longer than this: CPU time, so a busy computer "
        "can't make a program fail (default: %(default)g)",
    )
    parser.add_argument(
        "--wall-limit",
        type=positive_seconds,
        metavar="SECONDS",
        default=limits.wall_seconds,
        help="give up on a test not finished after this much real time, as a computer too "
        "busy to finish it, not the program's fault (default: %(default)g)",
    )
    parser.add_argument(
        "--memory-limit",
        type=positive_megabytes,
        metavar="MB",
        default=limits.memory_mb,
        help="stop a program that needs more memory than this (default: %(default)s MB)",
    )
    parser.add_argument(
        "--junit",
        metavar="FILE",
        help="also write the results as JUnit XML (read by CI systems and GitHub Classroom)",
    )
    parser.add_argument(
        "--report",
        metavar="FILE",
        help="also write one row per program (outcome, time, first difference) to FILE, "
        "as JSON or CSV by its ending (.json, .csv)",
    )
    parser.add_argument(
        "--shard",
        type=shard_option,
        metavar="K/N",
        help="test only share K of N (1/4, 2/4 ...): run N machines, one share each, to "
        "spread many programs; every machine splits them the same way",
    )


def shard_option(text: str) -> tuple[int, int]:
    """``K/N`` for ``--shard``: share K (1 to N) of N."""
    index, _, count = text.partition("/")
    if index.isdigit() and count.isdigit() and 1 <= int(index) <= int(count):
        return int(index), int(count)
    # (read before the command knows its languages: the system locale's)
    raise argparse.ArgumentTypeError(diagnostic("E620", text=text).shown(Languages.of_command()))


def run(args: argparse.Namespace) -> int:
    programs = find_programs(args.paths)
    if not programs:
        raise RootlangError.of("E609", paths=", ".join(map(shown_folder, args.paths)))
    if args.report:
        report_text([], Path(args.report).suffix.lower())  # a wrong kind of file: say so first
    if args.shard:
        programs = shard(programs, *args.shard)
    settings = Settings(
        update=args.update,
        time_limit=args.time_limit,
        limits=Limits(
            cpu_seconds=args.cpu_limit, wall_seconds=args.wall_limit, memory_mb=args.memory_limit
        ),
        workers=max(1, args.jobs),
        languages=args.languages,
    )
    progress = Progress(len(programs), sys.stderr)
    started = time.monotonic()
    results = run_golden_tests(programs, settings, progress.show)
    languages = args.languages
    for result in results:
        if result.verdict is Verdict.UPDATED:
            print(message("V114", {"golden": str(golden_path(result.program))}, languages))
        elif not result.verdict.ok:
            print(f"\n{result.shown_headline(languages)}")
            print(result.report)
    print(summary(results, time.monotonic() - started, languages))
    if args.junit:
        write_report(args.junit, junit_xml(results))
    if args.report:
        write_report(args.report, report_text(results, Path(args.report).suffix.lower()))
    return 0 if all(result.verdict.ok for result in results) else 1
