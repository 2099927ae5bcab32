"""What recording a run for going back in time costs the simulator: its speed with and without.

    .venv/bin/python benchmarks/timeline.py [--minutes 10]

The studio's runs are simulated with a debugger attached (Pause, Step, breakpoints) and, for
its time slider, a :class:`~rootlang.runtime.timeline.Timeline` recording their moments
(rootlang/runtime/timeline.py). Each of simulator.py's programs runs both ways through the
whole stack on a virtual clock: (a) the drawing on a colour mat and (b) bump-and-turn in the
arena, ``--minutes`` of simulated time each, and (c) its busy loops, a minute each (a new
value every statement: the most a run can ask of the recording). Prints each one's real-time
factor both ways, and the time spent in the recording's own code (each way into it timed in
a third run, less what timing costs) as a share of the run's: what the recording costs (aim:
<= 10 % of the simulator's speed; the speeds with and without, a few runs each, differ by more
than that on a busy computer), how many moments it kept and the size of what a page is sent
of them.

Times are this process's CPU seconds, best of seven (as simulator.py's, but taken in turns).
"""

from __future__ import annotations

import argparse
import gc
import json
import math
import time
from collections.abc import Callable
from dataclasses import replace
from typing import Any

from simulator import BUSY, BUSY_SECONDS, programs  # (this folder's)

from rootlang.app.session import keep_moments, simulate
from rootlang.checks import load_checked
from rootlang.runtime.debugger import Debugger, Recorder
from rootlang.runtime.timeline import Timeline
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import World, default_world
from rootlang.wording.language import ENGLISH

AIM_PERCENT = 10.0
REPEATS = 7


class Stopwatch:
    """The time spent in the recording's own code during a run: each way into it (a statement
    begins, a trace entry, a sensor state, the world moving on) timed, less what timing a call
    that does nothing costs (measured first)."""

    def __init__(self) -> None:
        self.seconds = 0.0
        self.calls = 0
        self.idle = 0.0
        idle = self.timed(lambda *_: None)
        start = time.perf_counter()
        for _ in range(100_000):
            idle()
        self.idle = (time.perf_counter() - start) / 100_000
        self.seconds, self.calls = 0.0, 0

    def timed(self, hook: Callable[..., None]) -> Callable[..., None]:
        def timed_hook(*arguments: Any) -> None:
            start = time.perf_counter()
            hook(*arguments)
            self.seconds += time.perf_counter() - start
            self.calls += 1

        return timed_hook

    @property
    def spent(self) -> float:
        return max(0.0, self.seconds - self.calls * self.idle)


def one_run(
    checked: Any, source: str, world: World, recording: bool, watch: Stopwatch | None = None
) -> tuple[float, float, Timeline | None]:
    """Simulated seconds, CPU seconds, and the run's timeline (if recorded); ``watch`` times
    the recording's own code."""
    timeline = Timeline() if recording else None
    robot = VirtualRobot(world)
    recorder: Recorder | None = timeline
    on_trace = None if timeline is None else timeline.seen
    if timeline is not None:
        keep_moments(robot, timeline)
        if watch is not None:
            assert robot.on_advanced is not None
            robot.on_advanced = watch.timed(robot.on_advanced)
            on_trace = watch.timed(timeline.seen)
            recorder = TimedRecorder(timeline, watch)
            # (and its look as a change has lasted, which the run's clock calls)
            setattr(timeline, "_look", watch.timed(timeline._look))  # noqa: B010
    gc.collect()
    start = time.process_time()
    result, _ = simulate(
        checked.program, source=source, robot=robot,
        debugger=Debugger(recorder=recorder), on_trace=on_trace,
    )  # fmt: skip
    elapsed = time.process_time() - start
    assert result.error is None, result.error
    return result.sim_time_s, elapsed, timeline


class TimedRecorder:
    """A timeline whose ways in from the debugger and the robot client are timed."""

    def __init__(self, timeline: Timeline, watch: Stopwatch) -> None:
        self.timeline = timeline
        self.watch = watch
        self.begins = watch.timed(timeline.begins)

    def attach(self, debugger: Debugger, scheduler: Any) -> None:
        self.timeline.attach(debugger, scheduler)
        client = scheduler.client
        client.on_state = self.watch.timed(client.on_state)


def compared(source: str, world: World) -> tuple[float, float, float, float, Timeline]:
    """Simulated seconds; the best CPU seconds without and with recording (runs taken in
    turns: a machine busy for a while slows both alike), and the least time spent in the
    recording's own code; a recorded run's timeline."""
    checked = load_checked(source, "bench.root", world.robot.model)
    plain = recorded = spent = math.inf
    for _ in range(REPEATS):
        simulated, seconds, _ = one_run(checked, source, world, recording=False)
        plain = min(plain, seconds)
        simulated, seconds, timeline = one_run(checked, source, world, recording=True)
        recorded = min(recorded, seconds)
        watch = Stopwatch()
        one_run(checked, source, world, recording=True, watch=watch)
        spent = min(spent, watch.spent)
    assert timeline is not None
    return simulated, plain, recorded, spent, timeline


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    seconds = parser.parse_args().minutes * 60
    busy_world = replace(default_world(), time_limit=BUSY_SECONDS)
    runs = [
        *programs(seconds),
        *((f"(c) {label}", source, busy_world) for label, source in BUSY.items()),
    ]
    busy = f"(c): {BUSY_SECONDS:.0f} s"
    print(f"best of {REPEATS} runs each, in turns; (a), (b): {seconds:.0f} s simulated, {busy}")
    worst = 0.0
    for label, source, world in runs:
        simulated, plain, recorded, spent, timeline = compared(source, world)
        cost = 100 * (recorded - plain) / plain
        inside = 100 * spent / plain
        worst = max(worst, inside)
        kept = len(timeline.program.times) + len(timeline.robot.times) + len(timeline.poses.times)
        shared = len({id(state) for state in timeline.program.values})
        size = len(json.dumps(timeline.to_json(ENGLISH), separators=(",", ":")))
        print(
            f"{label:<44} {simulated / plain:6.0f}x real time, "
            f"recorded {simulated / recorded:6.0f}x ({cost:+5.1f} %); in the recording's "
            f"code {inside:4.1f} % ({kept} moments, {shared} program states, "
            f"{size / 1e3:.0f} kB to a page)"
        )
    print(
        f"most time in the recording's code: {worst:.1f} % of a run's (aim: <= {AIM_PERCENT:.0f} %"
        " of the simulator's speed; the speeds with and without differ by more than that from "
        "run to run on a busy computer)"
    )


if __name__ == "__main__":
    main()
