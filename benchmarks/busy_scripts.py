"""Busy scripts run above real time: 50 scripts started by messages (``send``/``when message
received``), each repeating ``change v by 1`` and ``wait 0 seconds`` forever, simulated to their
world's time limit as ``rootlang sim`` runs them. Prints the robot's seconds simulated per
second of CPU time and of wall-clock time (aim: >= 10x real time). Each round of a loop lasts
10 ms of the robot's time (docs/runtime.md, "Yields"), so a simulated second is 5,000 rounds
of the fifty scripts.

Measured (2-core shared machine, load 2-3, 20 s simulated): 18.0x real time in CPU. With the
1 ms rounds the language had before, 2.0x: each round is two turns of asyncio's loop for its
script (``wait 0``, then the round's end), and those turns alone cost more than the robot's
millisecond for fifty scripts.

Run: ``python benchmarks/busy_scripts.py [SIMULATED_SECONDS]`` (default 5).
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

from rootlang.app import session

SCRIPTS = 50


def busy_program(seconds: float) -> str:
    started = "".join(f'    send "go {n}"\n' for n in range(SCRIPTS))
    scripts = "".join(
        f'when message "go {n}" received\n    forever\n        change v by 1\n'
        "        wait 0 seconds\n"
        for n in range(SCRIPTS)
    )
    return f"# world: worlds/busy.toml\nwhen started\n    set v to 0\n{started}{scripts}"


def main(seconds: float) -> None:
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        (folder / "worlds").mkdir()
        (folder / "worlds" / "busy.toml").write_text(f"time_limit = {seconds}\n")
        (folder / "busy.root").write_text(busy_program(seconds))
        program = session.load(folder / "busy.root")
        assert program.world is not None
        cpu, wall = time.process_time(), time.perf_counter()
        result, _ = session.simulate(program.checked, program.world, source=program.source)
        cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    assert result.end == "time_limit", result.end
    print(
        f"{SCRIPTS} busy scripts, {result.sim_time_s:g} s of the robot's time: {cpu:.2f} s of"
        f" CPU ({result.sim_time_s / cpu:.1f}x real time), {wall:.2f} s wall clock"
        f" ({result.sim_time_s / wall:.1f}x)"
    )


if __name__ == "__main__":
    main(float(sys.argv[1]) if len(sys.argv) > 1 else 5.0)
