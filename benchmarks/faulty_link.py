"""Faulty-link figures: gallery programs on the simulator behind a link with 10 % faults.

Run: ``.venv/bin/python benchmarks/faulty_link.py [RUNS]`` (600 runs: about a minute). Prints,
for the programs whose outcome their commands fix (the seeded test's set) and, apart, for those
whose outcome depends on timing (they drive by time, or end close to their world's time limit):
how many runs left the robot standing still at the end (aim: all), how many were right (ended
where the clean run ended, within 5 mm and 3 degrees, the same way), how many ended with a
clear error, and how many did neither (aim for the first set: none).
"""

from __future__ import annotations

import sys
import time
from collections import Counter
from pathlib import Path

from rootlang.app.faulty_link import Outcome, judge, load

PROGRAMS = Path(__file__).parents[1] / "programs"
JUDGED = (
    "square", "dance", "star", "messages", "long_say", "go_to", "units", "countdown", "dice",
    "factorial", "divide_by_zero", "busy_loop",
)  # fmt: skip
# They drive by time, or end close to their world's time limit (recovering lost answers takes
# seconds): how right they end up depends on when packets arrive.
TIMED = ("wheels", "stop_all", "when_condition", "spiral", "polygons", "tree", "flower")


def report(title: str, outcomes: list[Outcome], seconds: float) -> None:
    runs = len(outcomes)
    stopped = sum(outcome.stopped for outcome in outcomes)
    correct = sum(outcome.correct for outcome in outcomes)
    errors = Counter(outcome.error for outcome in outcomes if outcome.clear_error)
    neither = [outcome for outcome in outcomes if not outcome.kept_promise]
    print(f"{title}: {runs} runs in {seconds:.1f} s")
    print(f"  robot stopped at the end: {stopped}/{runs} ({100 * stopped / runs:.1f} %)")
    print(f"  right (same place and end): {correct}/{runs}")
    print(f"  clear error: {sum(errors.values())} {dict(errors)}")
    print(f"  neither: {len(neither)} {Counter(outcome.program for outcome in neither)}")


def main() -> None:
    runs = int(sys.argv[1]) if len(sys.argv) > 1 else 600
    for title, names in (
        ("judged gallery programs", JUDGED),
        ("programs that drive by time", TIMED),
    ):
        started = time.perf_counter()
        outcomes = judge([load(PROGRAMS / f"{name}.root") for name in names], runs, rate=0.1)
        report(title, outcomes, time.perf_counter() - started)


if __name__ == "__main__":
    main()
