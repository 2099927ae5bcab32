"""What the robot commands (`scan`, `run`, `robot`) share: which Bluetooth, which robot.

Not a subcommand itself. ``--transport SPEC`` swaps the computer's Bluetooth for bumble on an
HCI transport (a USB dongle ``usb:0``, a virtual controller ``tcp-client:127.0.0.1:6402``); the
spec ``virtual`` starts a simulated robot inside this process, on bumble's virtual link, so the
whole Bluetooth path can be tried with no robot and no radio.
"""

from __future__ import annotations

import argparse
import contextlib
import sys
from collections.abc import AsyncIterator

from rootlang.ble.backend import SYSTEM_BLUETOOTH, BleBackend
from rootlang.ble.select import FIND_TIMEOUT, Chosen, choose_robot
from rootlang.cli.numbers import positive_seconds
from rootlang.diagnostics import RootlangError
from rootlang.runtime.clock import Clock

IN_PROCESS = "virtual"


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


@contextlib.asynccontextmanager
async def bluetooth(spec: str | None, clock: Clock) -> AsyncIterator[BleBackend]:
    """The bleak backend to use while inside the block (``clock`` runs the loop)."""
    if spec is None:
        yield SYSTEM_BLUETOOTH
        return
    try:
        from rootlang.ble.virtual import radio
    except ImportError as error:
        raise RootlangError.of("E408") from error
    if spec == IN_PROCESS:
        async with radio.in_process_classroom(clock=clock) as central:
            yield central.backend
        return
    async with radio.hci_central(spec) as central:
        yield central.backend


async def find_robot(args: argparse.Namespace, backend: BleBackend) -> Chosen:
    return await choose_robot(args.robot, backend=backend, timeout=args.timeout, tell=tell)
