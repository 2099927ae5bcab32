"""A busy machine can't make a program fail: "runs forever" is judged by CPU time.

The machine is made busy for real: seven processes spin on one core, and the test's own
children are held to that core too, so a program gets an eighth of it (load 7 on a machine of
one core). The CPU-time limit is set from the program's own run on the idle machine (twice its
wall-clock time, an upper bound of its CPU time), so the program needs well under the limit on
any machine, fast or slow, but at an eighth of a core about four times the limit in wall-clock
time: judged by the wall clock (as `rootlang test` once did) it would fail.
"""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

from rootlang.app.sandbox import Limits
from rootlang.testing.runner import Settings, Verdict, run_golden_tests

pytestmark = pytest.mark.skipif(
    not hasattr(os, "sched_setaffinity"), reason="needs Linux's sched_setaffinity"
)

BUSY = 7  # the load
SPIN = "import os, sys\nos.sched_setaffinity(0, {int(sys.argv[1])})\nwhile True:\n    pass\n"
# a busy loop (no robot command, no wait) and a script that ends the run after 200 s of
# simulated time (20,000 rounds of the loop)
PROGRAM = """\
when started
    set spins to 0
    forever
        if spins > 1000000
            print "many"
        change spins by 1

when timer > 200 seconds
    stop all
"""


@contextmanager
def busy_core(core: int) -> Iterator[None]:
    """``BUSY`` processes spinning on ``core``, and this process held to it meanwhile."""
    spinners = [subprocess.Popen([sys.executable, "-c", SPIN, str(core)]) for _ in range(BUSY)]
    before = os.sched_getaffinity(0)
    try:
        os.sched_setaffinity(0, {core})
        time.sleep(0.2)  # the spinners have started spinning
        yield
    finally:
        os.sched_setaffinity(0, before)
        for spinner in spinners:
            spinner.kill()
        for spinner in spinners:
            spinner.wait()


def test_a_program_passes_on_a_machine_at_load_7(tmp_path: Path) -> None:
    program = tmp_path / "spinner.root"
    program.write_text(PROGRAM, encoding="utf-8")
    roomy = Limits(cpu_seconds=60, wall_seconds=120)
    (alone,) = run_golden_tests([program], Settings(update=True, limits=roomy, workers=1))
    assert alone.verdict is Verdict.UPDATED  # the golden file, on an idle machine
    # twice what the program took alone: its CPU time is under that on any machine, while an
    # eighth of a core takes about eight times as long (even if the idle run was slowed 3x)
    limits = Limits(cpu_seconds=2 * alone.seconds, wall_seconds=120)
    core = min(os.sched_getaffinity(0))
    with busy_core(core):
        (busy,) = run_golden_tests([program], Settings(limits=limits, workers=1))
    assert busy.verdict is Verdict.PASSED, busy.report
    # the load was real: the run took longer than the CPU-time limit in wall-clock time
    assert busy.seconds > limits.cpu_seconds, (alone.seconds, busy.seconds)
