"""The sandbox runs work in child processes under a CPU-time limit, a wall-clock backstop and a
memory cap."""

from __future__ import annotations

import contextlib
import io
import itertools
import os
import signal
import sys
import time
from multiprocessing.process import BaseProcess
from pathlib import Path

import pytest

from rootlang.app.sandbox import Limits, Status, cpu_backstop, run_isolated
from rootlang.cli import main

resource = pytest.importorskip("resource")
PROGRAMS = Path(__file__).resolve().parents[2] / "programs"

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="needs fork and resource")


def _work(job: str) -> str:
    if job == "loop":
        while True:
            pass
    if job == "sleep":
        time.sleep(1.5)
        return "SLEPT"
    if job == "hang":
        time.sleep(60)
    if job == "memory":
        text = "x"
        while True:
            text += text
    if job == "raise":
        raise ValueError("bad job")
    if job == "exit":
        os._exit(3)
    if job.startswith("slow:"):
        started = time.monotonic()
        time.sleep(0.1)
        with open(job[5:], "a") as log:
            log.write(f"{started} {time.monotonic()}\n")
    return job.upper()


Outcome = tuple[Status, object, str]


def _run(jobs: list[str], limits: Limits, workers: int = 2) -> dict[str, Outcome]:
    finished = run_isolated(_work, jobs, limits, workers)
    return {f.job: (f.status, f.result, f.detail) for f in finished}


def test_results_come_back_from_every_child() -> None:
    results = _run(["a", "b", "c"], Limits(wall_seconds=10))
    assert results == {job: (Status.OK, job.upper(), "") for job in "abc"}


def test_a_child_past_the_cpu_time_limit_is_stopped_and_the_others_finish() -> None:
    # the wall-clock backstop far out: the kernel ends the loop at its limit and the margin a
    # run has to stop itself (6 to 7 s of CPU time), which a busy machine gives slowly
    results = _run(["loop", "a"], Limits(cpu_seconds=1, wall_seconds=300))
    assert results["loop"] == (Status.CPU_LIMIT, None, "1 s")
    assert results["a"] == (Status.OK, "A", "")


def test_waiting_is_not_computing_only_the_wall_clock_backstop_ends_a_child_that_hangs() -> None:
    results = _run(["sleep", "hang"], Limits(cpu_seconds=1, wall_seconds=3))
    assert results["sleep"] == (Status.OK, "SLEPT", "")  # 1.5 s of wall time, no CPU time
    assert results["hang"] == (Status.WALL_LIMIT, None, "3 s")


def test_a_child_past_the_memory_cap_is_stopped() -> None:
    results = _run(["memory"], Limits(wall_seconds=20, memory_mb=100))
    assert results["memory"][0] is Status.MEMORY_LIMIT
    assert results["memory"][2] == "100 MB"


def test_a_crashing_child_is_reported_with_its_reason() -> None:
    results = _run(["raise", "exit"], Limits(wall_seconds=10))
    assert results["raise"] == (Status.CRASHED, None, "ValueError: bad job")
    assert results["exit"][0] is Status.CRASHED
    assert "exit code 3" in results["exit"][2]


def test_no_more_children_run_at_once_than_asked(tmp_path: Path) -> None:
    log = tmp_path / "times"
    jobs = [f"slow:{log}"] * 3
    assert [f.status for f in run_isolated(_work, jobs, Limits(), workers=1)] == [Status.OK] * 3
    spans = sorted(tuple(map(float, line.split())) for line in log.read_text().splitlines())
    assert len(spans) == 3
    assert all(earlier[1] <= later[0] for earlier, later in itertools.pairwise(spans))


def test_a_ctrl_c_the_moment_a_child_is_forked_leaves_no_child_running(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Ctrl-C timed to land just after a child is forked, before the parent has counted it
    (a busy machine makes that moment long): the child is still ended with the run. It was
    left computing, unseen, until its wall-clock limit, holding the terminal's output open."""
    forked: list[BaseProcess] = []
    start = BaseProcess.start

    def start_then_ctrl_c(process: BaseProcess) -> None:
        start(process)
        forked.append(process)
        os.kill(os.getpid(), signal.SIGINT)  # the child exists: Ctrl-C now

    monkeypatch.setattr(BaseProcess, "start", start_then_ctrl_c)
    with pytest.raises(KeyboardInterrupt):
        list(run_isolated(_work, ["hang"], Limits(wall_seconds=60)))
    (child,) = forked
    child.join(10)
    assert not child.is_alive()


def test_the_kernels_cpu_time_limit_is_the_runs_only_while_it_runs() -> None:
    """`rootlang sim` called from Python (as tests do) leaves this process's CPU-time limit as
    it was. It once stayed the run's: a test session was ended (SIGXCPU) in whatever test it
    ran once it had computed 65 s more than at its last `rootlang sim`."""
    before = resource.getrlimit(resource.RLIMIT_CPU)
    with contextlib.redirect_stdout(io.StringIO()):
        assert main(["sim", str(PROGRAMS / "square.root")]) == 0
    assert resource.getrlimit(resource.RLIMIT_CPU) == before
    with cpu_backstop(1.0):  # the kernel's backstop while the run runs
        assert resource.getrlimit(resource.RLIMIT_CPU)[0] != resource.RLIM_INFINITY
    assert resource.getrlimit(resource.RLIMIT_CPU) == before


def test_a_limit_nearer_than_the_runs_is_not_put_back() -> None:
    """A process capped before the run (a sandbox's child, a studio run's worker) keeps the
    run's limit if its own was nearer: a run paced to the wall clock computes longer than the
    process was first given, and must not be ended the moment it finishes."""
    before = resource.getrlimit(resource.RLIMIT_CPU)
    if before[1] != resource.RLIM_INFINITY:
        pytest.skip("this process has a hard CPU-time limit")
    used = resource.getrusage(resource.RUSAGE_SELF)
    now = int(used.ru_utime + used.ru_stime)
    try:
        resource.setrlimit(resource.RLIMIT_CPU, (now + 10_000, before[1]))
        with cpu_backstop(1.0):
            pass
        assert resource.getrlimit(resource.RLIMIT_CPU)[0] == now + 10_000  # further out: back
        resource.setrlimit(resource.RLIMIT_CPU, (now + 100, before[1]))
        with cpu_backstop(1_000.0):
            pass
        assert resource.getrlimit(resource.RLIMIT_CPU)[0] >= now + 1_000  # the run's stays
    finally:
        resource.setrlimit(resource.RLIMIT_CPU, before)
