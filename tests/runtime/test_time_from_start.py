"""`rootlang run` counts a run's time from the program's start: finding and connecting to a
robot (seconds on a real one) is not the program's time, in the trace as for `timer`."""

from __future__ import annotations

import asyncio

from rootlang.checks import parse
from rootlang.runtime.clock import VirtualClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import RunResult, run_program
from rootlang.runtime.transport import DisconnectHandler, PacketHandler, RobotInfo

PROGRAM = "when started\n    move 10 cm\n    print timer\n"


class SlowToConnect(LoopbackRobot):
    """A robot that takes 4 s to answer the connection, as a real one found by a scan does."""

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        await asyncio.sleep(4)
        return await super().connect(on_packet, on_disconnect)


def test_the_trace_starts_when_the_program_does_not_when_the_search_did() -> None:
    clock = VirtualClock()
    robot = SlowToConnect(clock)

    async def main() -> RunResult:
        await asyncio.sleep(1)  # scanning for the robot, before the run
        return await run_program(parse(PROGRAM), robot, clock, source=PROGRAM, handle_ctrl_c=False)

    result = clock.run(main())
    entries = result.trace.entries
    assert entries[0].time_ms == 0  # not 5000
    (printed,) = result.printed  # `timer` counts from the same moment
    assert float(printed.split()[0]) < 2
    moved = next(entry for entry in entries if entry.text.startswith("move"))
    assert moved.time_ms == 0 and moved.end_ms is not None and moved.end_ms < 2000
