"""Run a program on a virtual robot in a world: the one place that wires the pieces together.

The very scheduler, robot client and protocol code of ``rootlang run`` drive the robot; only the
transport differs. Virtual time by default (deterministic); ``realtime=True`` paces the world to
the wall clock.
"""

from __future__ import annotations

from collections.abc import Callable

from rootlang import ast
from rootlang.checks import CheckedProgram
from rootlang.runtime.clock import Clock, VirtualClock, WallClock
from rootlang.runtime.scheduler import RunResult, run_program
from rootlang.runtime.trace import TraceEntry
from rootlang.sim.recording import Recording
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import World, default_world


def simulate(
    program: CheckedProgram | ast.Program,
    world: World | None = None,
    *,
    source: str = "",
    robot: VirtualRobot | None = None,
    realtime: bool = False,
    on_print: Callable[[str], None] | None = None,
    handle_ctrl_c: bool = False,
    on_trace: Callable[[TraceEntry], None] | None = None,
) -> tuple[RunResult, Recording]:
    """Run ``program`` in ``world`` (or on ``robot``, already placed in its world) until it ends
    or the world's time limit; returns the run's result and the robot's recording."""
    robot = robot or VirtualRobot(world or default_world())
    clock: Clock = WallClock() if realtime else VirtualClock()
    transport = SimTransport(robot, clock)
    result = clock.run(
        run_program(
            program, transport, clock, source=source, time_limit=robot.world.time_limit,
            on_print=on_print, handle_ctrl_c=handle_ctrl_c, on_trace=on_trace,
        )
    )  # fmt: skip
    return result, robot.finish()
