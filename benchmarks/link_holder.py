"""The robot's link outlives the program: the time from SIGKILL of the program's process (mid-
drive, on the virtual robot over bumble's virtual link) to the robot's wheels standing still,
as the virtual robot itself reports it; and whether each stop was confirmed. Then the other
way round: SIGKILL of ``rootlang run`` itself, the link holder, to the virtual robot's wheels
standing still (the robot's own link timeout: it asks its host every second, and ends the link
after 4 s without an answer), and whether the program's process ended too.

Run: ``python benchmarks/link_holder.py [RUNS]`` (default 10; holder kills: a third as many).
"""

from __future__ import annotations

import importlib
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "ble"))
harness = importlib.import_module("test_link_outlives_program")  # the tests' own
holder_killed = importlib.import_module("test_link_holder_killed")


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
    kills = max(1, runs // 3)
    stopped = []
    for _ in range(kills):
        with tempfile.TemporaryDirectory() as folder:
            drove, took, programs = holder_killed.kill_the_holder(Path(folder))
        assert drove and programs  # (kill_the_holder fails if the robot or a process goes on)
        stopped.append(took)
    print(
        f"{kills} SIGKILLs of the link holder mid-drive: wheels still after median"
        f" {statistics.median(stopped):.2f} s (min {min(stopped):.2f}, max {max(stopped):.2f});"
        f" the program's process ended every time"
    )


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 10)
