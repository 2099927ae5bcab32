"""The robot's link outlives the program: the time from SIGKILL of the program's process (mid-
drive, on the virtual robot over bumble's virtual link) to the robot's wheels standing still,
as the virtual robot itself reports it; and whether each stop was confirmed.

Run: ``python benchmarks/link_holder.py [RUNS]`` (default 10).
"""

from __future__ import annotations

import importlib
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "ble"))
harness = importlib.import_module("test_link_outlives_program")  # the test's own


def main(runs: int) -> None:
    times, confirmed = [], 0
    for _ in range(runs):
        held, still, took, _ = harness._hold(harness.DRIVE, kill=True)
        assert still and held.died
        times.append(took * 1000)
        confirmed += held.stopped
    print(
        f"{runs} SIGKILLs mid-drive: wheels still after median {statistics.median(times):.1f} ms"
        f" (min {min(times):.1f}, max {max(times):.1f}); stop confirmed {confirmed}/{runs}"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
