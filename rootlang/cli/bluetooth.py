"""What the robot commands (`scan`, `run`, `robot`) share: the options naming the Bluetooth
and the robot, and finding the robot.

Not a subcommand itself. ``--transport SPEC`` swaps the computer's Bluetooth for bumble
(:func:`rootlang.app.bluetooth.bluetooth`).
"""

from __future__ import annotations

import argparse
import sys

from rootlang.ble.backend import BleBackend
from rootlang.ble.select import FIND_TIMEOUT, Chosen, choose_robot
from rootlang.cli.numbers import positive_seconds
from rootlang.diagnostics import Diagnostic


def add_transport_argument(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--transport",
        metavar="SPEC",
        default=None,
        help="use bumble on this HCI transport instead of this computer's Bluetooth, e.g. "
        "usb:0 or tcp-client:127.0.0.1:6402; `virtual` starts a simulated robot in this "
        "process (needs rootlang[virtual])",
    )


def add_robot_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--robot",
        metavar="NAME|ADDRESS",
        default=None,
        help="the robot to use; without it: the only robot in range, or the one you touch",
    )
    parser.add_argument(
        "--timeout",
        type=positive_seconds,
        metavar="SECONDS",
        default=FIND_TIMEOUT,
        help="how long to look for the robot (default: %(default)g)",
    )
    add_transport_argument(parser)


def tell(text: str) -> None:
    print(text, file=sys.stderr, flush=True)


async def find_robot(args: argparse.Namespace, backend: BleBackend) -> Chosen:
    def told(said: Diagnostic) -> None:
        tell(said.shown(args.languages))

    return await choose_robot(args.robot, backend=backend, timeout=args.timeout, tell=told)
