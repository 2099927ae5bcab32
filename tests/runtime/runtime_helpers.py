"""Running small `.root` programs on the loopback robot in virtual time."""

from __future__ import annotations

import asyncio
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from rootlang.checks import parse
from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock, VirtualClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import RunResult, run_program

Happening = tuple[float, Callable[[LoopbackRobot], object]]
"""At this many seconds into the run, do this to the robot."""


@dataclass
class Ran:
    result: RunResult
    robot: LoopbackRobot

    @property
    def printed(self) -> list[str]:
        return self.result.printed

    def print_times(self) -> list[tuple[int, str]]:
        """(ms, text) of each print; the trace shows the text in quotes."""
        return [(e.time_ms, e.text[1:-1]) for e in self.result.trace.of_kind("print")]


def run_root(
    source: str,
    *,
    model: RobotModel = RobotModel.RT1,
    protocol: tuple[int, int] | None = None,
    time_limit: float | None = 30.0,
    happenings: tuple[Happening, ...] = (),
    ctrl_c: bool = False,
    clock: Clock | None = None,
    **robot_options: Any,
) -> Ran:
    """Parse and run ``source`` (dedented) on a loopback robot; return the result and robot."""
    text = textwrap.dedent(source).strip("\n") + "\n"
    program = parse(text)
    clock = clock or VirtualClock()
    if protocol is None:
        protocol = (1, 5) if model is RobotModel.CREATE3 else (1, 3)
    robot = LoopbackRobot(clock, model=model, protocol_version=protocol, **robot_options)

    async def main() -> RunResult:
        loop = asyncio.get_running_loop()
        for seconds, action in happenings:
            loop.call_later(seconds, action, robot)
        return await run_program(
            program, robot, clock, source=text, time_limit=time_limit, handle_ctrl_c=ctrl_c
        )

    return Ran(clock.run(main()), robot)
