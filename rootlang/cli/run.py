"""`rootlang run FILE`: run a program on a real robot over Bluetooth.

Finds the robot (``--robot NAME|ADDRESS``, the only one in range, or the one the student
touches), connects with the bleak transport and runs the program in real time. The runtime's
one entry point handles every way a run ends; on each, the robot gets Stop and Reset while the
link is up, and the link is closed. ``--sim`` runs in the simulator when no robot is found.

While it runs, the child's view of the run is shown as it happens (the same lines `rootlang sim`
prints: scripts starting, the commands as written, what was said and printed, errors), ending
with how the run ended.
"""

from __future__ import annotations

import argparse
import sys

from rootlang.app import link, session
from rootlang.app.bluetooth import bluetooth
from rootlang.app.link import RelayTransport
from rootlang.ble.transport import BleakTransport
from rootlang.cli import EXIT_FAILED
from rootlang.cli.bluetooth import add_robot_arguments, find_robot, tell
from rootlang.cli.programs import exit_code, live_view, show_diagnostics
from rootlang.diagnostics import RootlangError, diagnostic, render
from rootlang.locale.translate import about
from rootlang.robots import RobotModel
from rootlang.runtime.clock import WallClock
from rootlang.wording.language import Languages

NOT_FOUND = frozenset({"E401", "E402", "E404", "E407"})
"""No robot to run on: with --sim, these fall back to the simulator."""


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("file", metavar="FILE", help="the program (.root)")
    add_robot_arguments(parser)
    parser.add_argument(
        "--sim",
        action="store_true",
        help="run in the simulator instead when no robot is found",
    )
    parser.add_argument(
        "--fast-writes",
        action="store_true",
        help="send packets without waiting for the robot to acknowledge each (paced instead)",
    )


def run(args: argparse.Namespace) -> int:
    program = session.load(args.file, on_robot=True, language=args.language)
    languages = about(args.languages, program.source)  # its messages speak its language
    show_diagnostics(program.warnings, program.source, languages)
    # the program runs in a process of its own, started before Bluetooth is: if it dies, this
    # process, which holds the link, stops the robot (rootlang/app/link.py)
    apart = link.start_program(_program_main, program, args.file, languages)
    clock = WallClock()

    async def hold_the_link() -> link.Held:
        async with bluetooth(args.transport, clock) as backend:
            chosen = await find_robot(args, backend)
            tell(f"Connecting to {chosen.robot.describe()} ...")
            # a program with `when` scripts waits for events until stopped: say how
            button = "power" if chosen.robot.model is RobotModel.CREATE3 else "nose"
            tell(f"To stop the program, press the robot's {button} button, or Ctrl-C here.")
            transport = BleakTransport(
                chosen.device,
                chosen.robot,
                backend=backend,
                clock=clock,
                write_with_response=not args.fast_writes,
            )
            return await apart.serve(transport, clock, chosen.robot.describe())

    try:
        held = clock.run(hold_the_link())
    except RootlangError as error:
        apart.kill()
        if args.sim and error.diagnostics[0].code in NOT_FOUND:
            tell(error.render(languages) + "\nRunning it in the simulator instead.")
            return _run_in_simulator(session.in_its_world(program, args.file), languages)
        print(error.render(languages), file=sys.stderr)  # (as `main` would, in its language)
        return EXIT_FAILED
    except BaseException:
        apart.kill()
        raise
    if held.died:
        print(render(diagnostic(held.code, how=held.how), "", languages), file=sys.stderr)
        return EXIT_FAILED
    return held.exitcode if held.exitcode is not None else EXIT_FAILED


def _program_main(
    transport: RelayTransport, program: session.Program, path: str, languages: Languages
) -> int:
    """The program's process: the run on the robot the link holder relays, shown live."""
    clock = WallClock()
    live = live_view(program.source, program.checked.program, languages)
    try:
        result = clock.run(session.run_on_robot(program, transport, clock, on_trace=live))
    except RootlangError as error:  # the link could not be made: said as `main` says it
        print(error.render(languages), file=sys.stderr)
        return EXIT_FAILED
    return exit_code(result, program.source, path, languages)


def _run_in_simulator(program: session.Program, languages: Languages) -> int:
    live = live_view(program.source, program.checked.program, languages)
    result, _ = session.simulate(
        program.checked, program.world, source=program.source, handle_ctrl_c=True, on_trace=live
    )
    return exit_code(result, program.source, program.file, languages)
