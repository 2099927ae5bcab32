"""`rootlang robots name`: name a class set of robots `Root-01`, `Root-02` … by touching each.

Touch the top of a robot: it gets the next name (the protocol's Set Name), spins green and
chirps, and you stick the matching label on it; then the next. Chrome's chooser and
``rootlang scan`` then list names a child can read. docs/studio.md has the ten-minute recipe.
"""

from __future__ import annotations

import argparse

from rootlang.app.bluetooth import bluetooth
from rootlang.ble.naming import NAME_BYTES, TOUCH_TIMEOUT, class_names, name_class_set
from rootlang.cli.bluetooth import add_transport_argument, tell
from rootlang.cli.numbers import positive_seconds
from rootlang.runtime.clock import WallClock


def add_arguments(parser: argparse.ArgumentParser) -> None:
    actions = parser.add_subparsers(dest="action", metavar="ACTION", required=True)
    name = actions.add_parser(
        "name", help="name a class set: touch each robot in turn (Root-01, Root-02, ...)",
        description="Name a class set of robots: touch the top of each robot in turn; it gets "
        "the next name (Root-01, Root-02, ...), spins green and chirps, so you can label it. "
        f"A name holds at most {NAME_BYTES} bytes.",
    )  # fmt: skip
    name.add_argument("--prefix", default="Root-", help="the names' start (default: Root-)")
    name.add_argument("--first", type=int, default=1, metavar="N",
                      help="the first robot's number (default: 1)")  # fmt: skip
    name.add_argument("--count", type=int, default=30, metavar="N",
                      help="how many robots to name at most (default: 30)")  # fmt: skip
    name.add_argument("--digits", type=int, default=2, metavar="N",
                      help="digits in each number, 07 rather than 7 (default: 2)")  # fmt: skip
    name.add_argument(
        "--timeout", type=positive_seconds, default=TOUCH_TIMEOUT, metavar="SECONDS",
        help="stop when no robot has been touched for this long (default: %(default)g)",
    )  # fmt: skip
    add_transport_argument(name)


def run(args: argparse.Namespace) -> int:
    names = class_names(args.prefix, args.first, max(args.count, 0), max(args.digits, 1))
    clock = WallClock()

    async def name_them() -> int:
        async with bluetooth(args.transport, clock) as backend:
            done = await name_class_set(
                names, backend=backend, clock=clock, touch_timeout=args.timeout, tell=tell
            )
        return len(done)

    try:
        count = clock.run(name_them())
    except KeyboardInterrupt:
        print("Stopped.")
        return 0
    print(f"Named {count} robot{'' if count == 1 else 's'}.")
    return 0
