"""`rootlang virtual-robot`: a simulated robot any Bluetooth host can connect to.

Runs on a bumble HCI transport (a USB Bluetooth dongle ``usb:0``, or a virtual controller such
as ``tcp-client:127.0.0.1:6402``) in real time, with the Root's GATT services and advertisement,
so the Root Coding app, rootlang itself or any other BLE host sees a robot. Needs the optional
extra: ``pip install 'rootlang[virtual]'``.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from rootlang.cli.bluetooth import tell
from rootlang.cli.programs import robot_model
from rootlang.diagnostics import RootlangError
from rootlang.runtime.clock import WallClock

REAL_RADIO_ADVERTISING_MS = 100.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--transport",
        metavar="SPEC",
        default="usb:0",
        help="bumble HCI transport, e.g. usb:0 or tcp-client:127.0.0.1:6402 (default: %(default)s)",
    )
    parser.add_argument("--name", default="Virtual Root", help="the advertised name")
    parser.add_argument(
        "--model",
        default="RT1",
        type=robot_model,
        help="RT0, RT1 or Create3 (default: %(default)s)",
    )
    parser.add_argument(
        "--one-packet",
        action="store_true",
        help="advertise name and robot state in the advertising packet too: bumble's virtual "
        "controllers (python -m bumble.apps.controllers) deliver no scan responses",
    )
    parser.add_argument(
        "--world",
        metavar="W",
        default=None,
        help="the world the robot lives in: a .toml file or a world's name, like arena "
        "(default: the simulator's empty arena)",
    )


def run(args: argparse.Namespace) -> int:
    try:
        from rootlang.ble.virtual.bridge import BleBridge
        from rootlang.ble.virtual.radio import open_hci_device
        from rootlang.ble.virtual.robot import simulated_robot
        from rootlang.sim.world import load_world_option
    except ImportError as error:
        raise RootlangError.of("E408") from error
    clock = WallClock()

    async def serve() -> str:
        world = load_world_option(args.world, Path.cwd()) if args.world else None
        async with open_hci_device(args.transport, args.name, robot=True) as device:
            bridge = BleBridge(
                device,
                simulated_robot(args.model, args.name, clock, world),
                name=args.name,
                scan_response_in_advertisement=args.one_packet,
                advertising_interval_ms=REAL_RADIO_ADVERTISING_MS,
            )
            await bridge.start()
            tell(
                f'Advertising {args.model.display_name} "{args.name}" on {args.transport}. '
                "Press Ctrl-C to stop."
            )
            try:
                return str(await bridge.brain_gone)
            finally:
                await bridge.stop()

    tell(f"The robot stopped: {clock.run(serve())}.")
    return 0
