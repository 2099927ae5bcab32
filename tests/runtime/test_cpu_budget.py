"""Every run ends: a run that keeps the computer busy stops itself once it has used its budget
of CPU time (E220 at the line it is running), the robot stopped and `when stopped` run, as on
any run-time error. The CPU time here is counted by the test itself (each reading 0.1 s more),
so the run stops at the same place on every machine."""

from __future__ import annotations

import itertools

from rootlang.checks import parse
from rootlang.runtime.budget import CHECKED_EVERY, CpuBudget
from rootlang.runtime.clock import VirtualClock
from rootlang.runtime.interpreter import LOOP_ROUND_SECONDS
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import RunResult, run_program
from rootlang.wording.language import Languages

BUSY = """when started
    set n to 0
    send "go"
when message "go" received
    forever
        change n by 1
        wait 0 seconds
when stopped
    print "stopped"
"""


def busy_run(budget: CpuBudget, time_limit: float = 1_000.0) -> tuple[RunResult, LoopbackRobot]:
    clock = VirtualClock()
    robot = LoopbackRobot(clock)
    result = clock.run(
        run_program(
            parse(BUSY),
            robot,
            clock,
            source=BUSY,
            time_limit=time_limit,
            handle_ctrl_c=False,
            cpu_budget=budget,
        )
    )
    return result, robot


def counted(step: float = 0.1) -> CpuBudget:
    """One second of 'CPU time' that grows by ``step`` at each reading."""
    readings = itertools.count()
    return CpuBudget(1.0, read=lambda: next(readings) * step)


def test_a_busy_program_stops_itself_at_its_cpu_budget_with_a_message() -> None:
    result, robot = busy_run(counted())
    assert result.end == "error"
    assert result.error is not None and result.error.code == "E220"
    assert result.error.span.line in (5, 6, 7)  # in the busy loop
    assert result.error.english.startswith("This program kept the computer busy for 1 s")
    assert "without waiting?" in result.error.english
    assert result.printed == ["stopped"]  # `when stopped` ran
    assert "stop_and_reset" in [p.packet.name for p in robot.received]
    # ten readings of the CPU time, one every CHECKED_EVERY steps of the interpreter; each
    # round of the loop is LOOP_ROUND_SECONDS of the robot's time and three steps (two lines,
    # its end)
    steps = round(result.sim_time_s / LOOP_ROUND_SECONDS) * 3
    assert 9 * CHECKED_EVERY < steps <= 10 * CHECKED_EVERY + 3
    assert result.sim_time_s < 1_000  # long before the time limit


def test_the_message_speaks_the_childs_language() -> None:
    result, _ = busy_run(counted())
    assert result.error is not None
    said = {code: result.error.shown(Languages(chosen=code)) for code in ("nl", "es", "fr", "de")}
    assert said["nl"].startswith("Dit programma hield de computer 1 s van zijn tijd bezig")
    assert said["es"].startswith("Este programa tuvo ocupado al ordenador 1 s")
    assert said["fr"].startswith("Ce programme a occupé l'ordinateur pendant 1 s")
    assert said["de"].startswith("Dieses Programm hat den Computer 1 s seiner Zeit")


def test_a_run_within_its_budget_is_untouched() -> None:
    # a budget never used up changes nothing: the same run, to its time limit
    within, _ = busy_run(CpuBudget(1e9), time_limit=0.5)
    unlimited, _ = busy_run(CpuBudget(None), time_limit=0.5)
    assert within.end == unlimited.end == "time_limit"
    assert within.trace.text() == unlimited.trace.text()


def test_time_set_aside_does_not_count_and_the_kernel_follows() -> None:
    """A paused run: what the process computes meanwhile (the page's frames) is not the
    program's; the kernel's limit is lifted while it lasts and follows what is left after."""
    now = [0.0]
    heard: list[float | None] = []
    budget = CpuBudget(10.0, read=lambda: now[0], on_moved=heard.append)
    budget.start()
    now[0] = 4.0
    with budget.set_aside():
        now[0] = 100.0  # an hour's pause, and its frames
    assert heard == [None, 6.0]
    now[0] = 105.9
    assert not any(budget.spent() for _ in range(CHECKED_EVERY))
    now[0] = 106.0
    assert any(budget.spent() for _ in range(CHECKED_EVERY))


def test_a_paused_run_is_not_stopped_for_the_time_its_pause_took() -> None:
    from rootlang.runtime.debugger import Debugger, Go, Pause

    now = [0.0]
    budget = CpuBudget(1.0, read=lambda: now[0])
    pauses: list[Pause] = []

    def on_pause(pause: Pause) -> Go:
        pauses.append(pause)
        now[0] += 5.0  # the child looks for a long time: five budgets' worth
        return Go.RESUME

    clock = VirtualClock()
    result = clock.run(
        run_program(
            parse(BUSY),
            LoopbackRobot(clock),
            clock,
            source=BUSY,
            time_limit=0.5,
            handle_ctrl_c=False,
            cpu_budget=budget,
            debugger=Debugger(on_pause, breakpoints={6}),
        )
    )
    assert pauses, "the run never paused"
    assert result.end != "error", result.error  # (counted, the pause alone spent it all)
