"""The robot's link outlives the program (docs/runtime.md, "The program's own process"): the
program runs in a process of its own; killed with SIGKILL mid-drive, the process that holds the
link stops the robot — checked on the virtual robot itself, over bumble's virtual link."""

from __future__ import annotations

import asyncio
import os
import signal
import time

from rootlang.app import link, session
from rootlang.app.link import RelayTransport
from rootlang.ble.select import choose_robot
from rootlang.ble.transport import BleakTransport
from rootlang.ble.virtual.radio import in_process_classroom
from rootlang.ble.virtual.robot import simulated_robot
from rootlang.diagnostics import diagnostic
from rootlang.runtime.clock import WallClock
from rootlang.sim.devices.motors import STILL
from rootlang.sim.transport import SimTransport

DRIVE = "when started\n    drive 10 cm/s\n    wait 30 seconds\n"
SHORT = "when started\n    move 2 cm\n"


def _run(transport: RelayTransport, program: session.Program) -> int:
    """The program's process (forked: module-level, as the CLI's)."""
    clock = WallClock()
    result = clock.run(session.run_on_robot(program, transport, clock, handle_ctrl_c=False))
    return 0 if result.error is None else 1


def _hold(source: str, kill: bool) -> tuple[link.Held, bool, float, list[tuple[float, float]]]:
    """Run ``source`` apart; with ``kill``, SIGKILL the program once the wheels turn. How it
    ended, whether the robot's wheels stand still at the end, the seconds from the kill to
    still wheels, and the wheel speeds the robot had while the program ran."""
    program = session.load("drive.root", source=source, on_robot=True)
    apart = link.start_program(_run, program)
    clock = WallClock()
    brain = simulated_robot(name="Apart", clock=clock)
    assert isinstance(brain, SimTransport)
    motors = brain.robot.devices.motors
    seen: list[tuple[float, float]] = []

    def wanted() -> tuple[float, float]:
        """The wheel speeds the robot's motors are asked for now."""
        return motors.wanted

    async def main() -> tuple[link.Held, float]:
        async with in_process_classroom(brain=brain, name="Apart", clock=clock) as central:
            chosen = await choose_robot("Apart", backend=central.backend, timeout=5)
            transport = BleakTransport(
                chosen.device, chosen.robot, backend=central.backend, clock=clock
            )
            serving = asyncio.ensure_future(apart.serve(transport, clock, "Apart"))
            took = 0.0
            if kill:
                while wanted() == STILL:  # until the program has the robot driving
                    assert not serving.done(), "the program ended before it drove"
                    await asyncio.sleep(0.01)
                seen.append(wanted())
                assert apart.process.pid is not None
                os.kill(apart.process.pid, signal.SIGKILL)
                killed = time.monotonic()
                while wanted() != STILL:
                    await asyncio.sleep(0.001)
                took = time.monotonic() - killed
            held = await asyncio.wait_for(serving, 30)
            return held, took

    try:
        held, took = clock.run(asyncio.wait_for(main(), 60))
    finally:
        apart.kill()
    return held, wanted() == STILL and motors.wheels == STILL, took, seen


def test_a_killed_program_s_robot_is_stopped_by_the_link_holder() -> None:
    # (how soon the wheels are still: benchmarks/link_holder.py; here, that they are)
    held, still, _took, seen = _hold(DRIVE, kill=True)
    assert seen and seen[0] != STILL  # it was driving when killed
    assert held.died and held.how == "SIGKILL"
    assert held.stopped  # the robot confirmed the Stop and Reset
    assert still  # on the virtual robot itself
    shown = diagnostic(held.code, how=held.how).english
    assert shown == "The program stopped all of a sudden (SIGKILL), so I stopped the robot."


def test_a_program_that_ends_closes_the_link_itself() -> None:
    held, still, _, _ = _hold(SHORT, kill=False)
    assert not held.died and held.exitcode == 0
    assert still
