"""`rootlang test [PATH ...]`: run programs in the simulator and compare with their golden files."""

from __future__ import annotations

import argparse
import sys
import time

from rootlang.diagnostics import RootlangError
from rootlang.testing.files import find_programs, golden_path
from rootlang.testing.runner import (
    Progress,
    Settings,
    Verdict,
    default_workers,
    run_golden_tests,
    summary,
)
from rootlang.testing.sandbox import Limits


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.description = (
        "Run each program in the simulator, in the world its `# world:` line names, and compare "
        "what it did (its trace, where the robot ended, what it drew, how it ended) with the "
        "golden file next to it (spiral.root -> spiral.golden). A program with mistakes is "
        "compared with what `rootlang check` says about it."
    )
    parser.add_argument(
        "paths", metavar="PATH", nargs="*", default=["."],
        help="programs, or folders to search for .root files (default: this folder)",
    )
    parser.add_argument(
        "--update", action="store_true",
        help="save each program's output as its new golden file (read the diff before committing)",
    )
    parser.add_argument(
        "--jobs", "-j", type=int, metavar="N", default=default_workers(),
        help="programs to run at once (default: the number of CPU cores, here %(default)s)",
    )
    limits = Limits()
    parser.add_argument(
        "--time-limit", type=float, metavar="SECONDS", default=None,
        help="stop each program after this much simulated time (default: its world's limit)",
    )
    parser.add_argument(
        "--wall-limit", type=float, metavar="SECONDS", default=limits.wall_seconds,
        help="stop a program that takes longer than this in real time (default: %(default)g)",
    )
    parser.add_argument(
        "--memory-limit", type=int, metavar="MB", default=limits.memory_mb,
        help="stop a program that needs more memory than this (default: %(default)s MB)",
    )


def run(args: argparse.Namespace) -> int:
    programs = find_programs(args.paths)
    if not programs:
        named = ["this folder" if path in (".", "./") else path for path in args.paths]
        raise RootlangError.of("E609", paths=", ".join(named))
    settings = Settings(
        update=args.update,
        time_limit=args.time_limit,
        limits=Limits(wall_seconds=args.wall_limit, memory_mb=args.memory_limit),
        workers=max(1, args.jobs),
    )
    progress = Progress(len(programs), sys.stderr)
    started = time.monotonic()
    results = run_golden_tests(programs, settings, progress.show)
    for result in results:
        if result.verdict is Verdict.UPDATED:
            print(f"updated {golden_path(result.program)}")
        elif not result.verdict.ok:
            print(f"\n{result.headline}")
            print(result.report)
    print(summary(results, time.monotonic() - started))
    return 0 if all(result.verdict.ok for result in results) else 1
