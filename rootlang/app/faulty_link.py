"""Gallery programs on the simulator behind a faulty link, judged against a clean run.

The promise (docs/runtime.md, "A lossy link"): on a link that loses, damages, repeats and
delays packets, the robot is stopped at the end of every run, and every run either ends where
the clean run ends (the same place as the robot client judges one: within 5 mm and 3°, the same
way) or ends with a clear error. Used by a seeded test and by ``benchmarks/faulty_link.py``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from rootlang.app.session import Program, Simulation
from rootlang.app.session import load as load_program
from rootlang.protocol.behaviour import same_place
from rootlang.runtime.clock import Clock
from rootlang.runtime.faults import FaultRates, FaultyTransport
from rootlang.runtime.scheduler import RunResult
from rootlang.runtime.transport import Transport
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport

STILL_CHECK_SECONDS = 1.0  # the robot, left alone this long at the end, must not move
CLEAR_ERRORS = frozenset(("E203", "E207", "E208"))  # what a bad link may end a run with


@dataclass(frozen=True)
class Outcome:
    """How one run went, next to the clean run of the same program."""

    program: str
    seed: int
    end: str
    error: str  # the error's code, or ""
    stopped: bool  # the robot stood still at the end, with the link still open
    same_place: bool  # it ended where the clean run ended
    same_end: bool  # and the same way (finished, time limit ..., the same error if any)

    @property
    def correct(self) -> bool:
        return self.same_place and self.same_end

    @property
    def clear_error(self) -> bool:
        return self.error in CLEAR_ERRORS

    @property
    def kept_promise(self) -> bool:
        return self.stopped and (self.correct or self.clear_error)


class Watch:
    """Notes, before the simulated robot's link closes, whether the robot was left standing
    still (closing the link stops a robot too, so it must be asked first)."""

    def __init__(self, robot: VirtualRobot) -> None:
        self.robot = robot
        self.stopped = True
        self.world_pose: tuple[float, float, float] = (0.0, 0.0, 0.0)

    def __call__(self) -> None:
        before = self.robot.world_pose
        self.robot.advance(STILL_CHECK_SECONDS)
        self.stopped = _same(before, self.robot.world_pose)
        self.world_pose = before


def load(path: Path) -> Program:
    """A gallery program in its world (messages name it by its file's name)."""
    return load_program(path, shown_as=path.name)


def run_once(program: Program, seed: int | None, rate: float = 0.1) -> tuple[RunResult, Watch]:
    """Run ``program`` in its world; ``seed`` None: on a clean link."""

    def faulty(inner: SimTransport, clock: Clock) -> Transport:
        assert seed is not None
        rates = FaultRates(rate=rate)
        return FaultyTransport(inner, clock, seed=seed, to_robot=rates, to_host=rates)

    simulation = Simulation(program.world, link=None if seed is None else faulty)
    watch = Watch(simulation.robot)
    simulation.sim_transport.on_closing = watch
    run = simulation.run(program.checked, source=program.source)
    return simulation.clock.run(run), watch


def judge(programs: Iterable[Program], runs: int, rate: float = 0.1) -> list[Outcome]:
    """``runs`` faulty runs shared round the programs (seeds 0, 1, 2 ...), each judged."""
    chosen = list(programs)
    clean = {program.file: run_once(program, None) for program in chosen}
    outcomes = []
    for seed in range(runs):
        program = chosen[seed % len(chosen)]
        result, watched = run_once(program, seed, rate)
        clean_result, clean_watched = clean[program.file]
        outcomes.append(
            Outcome(
                program=program.file,
                seed=seed,
                end=result.end,
                error=_code(result),
                stopped=watched.stopped,
                same_place=_same(watched.world_pose, clean_watched.world_pose),
                same_end=(result.end, _code(result)) == (clean_result.end, _code(clean_result)),
            )
        )
    return outcomes


def _code(result: RunResult) -> str:
    return result.error.code if result.error else ""


def _same(a: tuple[float, float, float], b: tuple[float, float, float]) -> bool:
    """Two of the simulator's world poses (mm, mm, radians) are one place."""
    return same_place((a[0], a[1], math.degrees(a[2])), (b[0], b[1], math.degrees(b[2])))
