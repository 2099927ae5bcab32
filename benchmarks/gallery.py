"""How long `rootlang test programs/` takes: the whole gallery against its golden files.

Run: ``.venv/bin/python benchmarks/gallery.py [--jobs N] [--rounds R]``. Runs the gallery R times
(default 3) with N worker processes (default: every core) and prints the best and median wall
time, the number of programs and the simulated time they cover. Aim: <= 20 s on a 2-core machine.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time
from pathlib import Path

from rootlang.app.files import find_programs
from rootlang.testing.runner import Settings, Verdict, run_golden_tests

GALLERY = Path(__file__).resolve().parents[1] / "programs"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    programs = find_programs([GALLERY])
    settings = Settings(workers=args.jobs)
    times: list[float] = []
    for _ in range(args.rounds):
        started = time.perf_counter()
        results = run_golden_tests(programs, settings)
        times.append(time.perf_counter() - started)
        failed = [r.program.name for r in results if r.verdict is not Verdict.PASSED]
        if failed:
            print(f"note: {len(failed)} programs did not pass: {', '.join(failed)}")
    slowest = max(results, key=lambda result: result.seconds)
    simulated = sum(_simulated_seconds(r.produced.text) for r in results if r.produced)
    print(f"programs: {len(programs)} ({args.jobs} worker processes, {os.cpu_count()} cores)")
    best, median = min(times), statistics.median(times)
    print(
        f"rootlang test programs/: best {best:.2f} s, median {median:.2f} s "
        f"over {args.rounds} rounds (aim: <= 20 s)"
    )
    print(
        f"simulated time covered: {simulated:.0f} s "
        f"({simulated / min(times):.0f}x real time over the whole gallery)"
    )
    print(f"slowest program: {slowest.program.name} ({slowest.seconds:.2f} s)")


def _simulated_seconds(golden: str) -> float:
    """The ``at N s`` of a golden file's ``end:`` line (0 for a program with mistakes)."""
    first = golden.split("\n", 1)[0]
    if not first.startswith("end:"):
        return 0.0
    return float(first.rsplit(" at ", 1)[1].split()[0])


if __name__ == "__main__":
    main()
