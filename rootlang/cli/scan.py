"""`rootlang scan`: list the robots in range (name, model, battery, signal, address)."""

from __future__ import annotations

import argparse
import json

from rootlang.app.bluetooth import bluetooth
from rootlang.ble.advertisement import RobotSeen
from rootlang.ble.scan import scan
from rootlang.cli.bluetooth import add_transport_argument
from rootlang.cli.numbers import positive_seconds
from rootlang.runtime.clock import WallClock

DEFAULT_SECONDS = 5.0


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "--timeout",
        type=positive_seconds,
        metavar="SECONDS",
        default=DEFAULT_SECONDS,
        help="how long to listen (default: %(default)g)",
    )
    parser.add_argument("--json", action="store_true", help="print the list as JSON")
    add_transport_argument(parser)


def run(args: argparse.Namespace) -> int:
    clock = WallClock()

    async def listen() -> list[RobotSeen]:
        async with bluetooth(args.transport, clock) as backend:
            return await scan(args.timeout, backend)

    robots = clock.run(listen())
    if args.json:
        print(json.dumps([robot.to_json() for robot in robots], indent=2))
    else:
        print(table(robots) if robots else f"No robots found in {args.timeout:g} seconds.")
    return 0


def table(robots: list[RobotSeen]) -> str:
    rows = [("NAME", "MODEL", "BATTERY", "SIGNAL", "ADDRESS")] + [
        (
            robot.name or "?",
            robot.model_name,
            "?" if robot.battery_percent is None else f"{robot.battery_percent}%",
            f"{robot.rssi} dBm",
            robot.address,
        )
        for robot in robots
    ]
    widths = [max(len(row[column]) for row in rows) for column in range(len(rows[0]))]
    return "\n".join(
        "  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)).rstrip()
        for row in rows
    )
