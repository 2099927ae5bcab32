"""`rootlang robot info` and `rootlang robot rename NAME`: small conveniences for one robot."""

from __future__ import annotations

import argparse

from rootlang.app.bluetooth import bluetooth
from rootlang.ble.naming import NAME_BYTES, set_name_packet
from rootlang.ble.select import Chosen
from rootlang.ble.transport import BleakTransport
from rootlang.cli.bluetooth import add_robot_arguments, find_robot
from rootlang.runtime.clock import WallClock
from rootlang.runtime.transport import RobotInfo


def add_arguments(parser: argparse.ArgumentParser) -> None:
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    info = actions.add_parser(
        "info", help="model, serial number, firmware and protocol version",
        description="Connect to a robot and show its model, serial number, firmware, "
        "protocol version, battery and signal.",
    )  # fmt: skip
    add_robot_arguments(info)
    rename = actions.add_parser(
        "rename", help="give the robot a new Bluetooth name",
        description="Give a robot a new Bluetooth name, like: rootlang robot rename Rooty "
        "(the only robot in range or the one you touch, or pick it with --robot OLDNAME).",
    )  # fmt: skip
    rename.add_argument("name", metavar="NAME", help=f"the new name (at most {NAME_BYTES} bytes)")
    add_robot_arguments(rename)


def run(args: argparse.Namespace) -> int:
    clock = WallClock()
    new_name = set_name_packet(args.name) if args.action == "rename" else None

    async def visit() -> tuple[Chosen, RobotInfo]:
        async with bluetooth(args.transport, clock) as backend:
            chosen = await find_robot(args, backend)
            transport = BleakTransport(chosen.device, chosen.robot, backend=backend, clock=clock)
            try:
                info = await transport.connect(lambda _packet: None, lambda _reason: None)
                if new_name is not None:
                    await transport.send(new_name)
            finally:
                await transport.disconnect()
            return chosen, info

    chosen, info = clock.run(visit())
    if new_name is not None:
        print(
            f'Renamed {chosen.robot.describe()} to "{args.name}". '
            "It shows the new name the next time it advertises."
        )
        return 0
    battery = chosen.robot.battery_percent
    for label, value in (
        ("name", info.name or "?"),
        ("model", info.model.display_name),
        ("address", chosen.robot.address),
        ("serial", info.serial),
        ("firmware", info.firmware),
        ("hardware", info.hardware),
        ("protocol", ".".join(map(str, info.protocol_version))),
        ("battery", "?" if battery is None else f"{battery}%"),
        ("signal", f"{chosen.robot.rssi} dBm"),
    ):
        print(f"{label + ':':10} {value}")
    return 0
