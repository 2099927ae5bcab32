"""`rootlang studio [FOLDER]`: blocks, text and the simulator side by side, in the browser.

Serves the studio page for the class folder (default: this one) and opens a browser at it.
Binds to 127.0.0.1, so only this computer can use it, unless ``--host`` says otherwise
(``--host 0.0.0.0`` lets a class on the same network join, each browser on its own). Ctrl-C
stops the server and every run.
"""

from __future__ import annotations

import argparse
import asyncio
import webbrowser
from pathlib import Path

from rootlang.cli.bluetooth import add_transport_argument
from rootlang.studio.runs import RUNS_PER_CORE, ClassLimits, default_runs

DEFAULT_PORT = 8765


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "folder", metavar="FOLDER", nargs="?", default=".",
        help="the class folder: its .root programs are the ones the studio lists and saves "
        "(default: this folder)",
    )  # fmt: skip
    parser.add_argument(
        "--port", type=int, default=DEFAULT_PORT, metavar="N",
        help=f"the port to serve on (default: {DEFAULT_PORT}; 0 picks a free one)",
    )  # fmt: skip
    parser.add_argument(
        "--host", default="127.0.0.1", metavar="H",
        help="the address to listen on (default: 127.0.0.1, this computer only; "
        "0.0.0.0 for a class on the same network)",
    )  # fmt: skip
    parser.add_argument(
        "--allow-host", action="append", default=[], metavar="NAME",
        help="also answer pages that ask for the studio by NAME (a name your school's network "
        "gives this computer, or a proxy's); its own names and addresses are answered anyway",
    )  # fmt: skip
    parser.add_argument(
        "--class", dest="as_class", action="store_true",
        help="a class: each pupil types their name and works in a folder of their own; the "
        "teacher's page is /teacher (on by itself when --host is not this computer's)",
    )  # fmt: skip
    parser.add_argument(
        "--level", type=int, choices=(1, 2, 3), default=2,
        help="the level the page opens at, 1 picture blocks (for children who can't read "
        "yet), 2 word blocks, 3 text (docs/levels.md); with --class, the pupils' pages: the "
        "teacher's page changes it, for the class or one pupil",
    )  # fmt: skip
    parser.add_argument(
        "--https", action="store_true",
        help="serve over TLS with a certificate rootlang makes for this computer's LAN names "
        "(kept in your config folder): pupils' browsers then may link their robots over Web "
        "Bluetooth (see docs/studio.md for making their browsers trust it)",
    )  # fmt: skip
    parser.add_argument(
        "--runs-at-once", type=_at_least_one, default=None, metavar="N",
        help="runs at once on this computer; more wait their turn, their pages say so "
        f"(default: {RUNS_PER_CORE} per processor core, {default_runs()} here)",
    )  # fmt: skip
    parser.add_argument(
        "--runs-per-pupil", type=_at_least_one, default=ClassLimits.runs_each, metavar="N",
        help="in a class, runs at once for each pupil: a new one replaces their oldest "
        f"(default: {ClassLimits.runs_each})",
    )  # fmt: skip
    parser.add_argument(
        "--no-browser", action="store_true", help="don't open a browser, just print the address"
    )
    add_transport_argument(parser)


def _at_least_one(text: str) -> int:
    number = int(text)  # (argparse says "invalid _at_least_one value" for a ValueError)
    if number < 1:
        raise argparse.ArgumentTypeError(f"{number} is not 1 or more")
    return number


def run(args: argparse.Namespace) -> int:
    from rootlang.studio.classroom import Classroom
    from rootlang.studio.folder import ClassFolder
    from rootlang.studio.server import LOOPBACK_NAMES, serve

    folder = ClassFolder(Path(args.folder))
    tls = None
    if args.https:
        from rootlang.studio.tls import studio_certificate

        tls = studio_certificate(args.host)
    as_class = args.as_class or args.host not in LOOPBACK_NAMES
    limits = ClassLimits(runs=args.runs_at_once or default_runs(), runs_each=args.runs_per_pupil)
    classroom = Classroom(folder, level=args.level) if as_class else None

    def ready(address: str) -> None:
        if classroom is None and args.level != 2:  # (at home: the page opens at the level)
            address += f"?level={args.level}"
        print(f"rootlang studio is serving {folder.root} at {address}", flush=True)
        if classroom is not None:
            print(f"The teacher's page: {address}teacher (code {classroom.code}; "
                  "don't show it to the class)", flush=True)  # fmt: skip
        if tls is not None:
            print(
                f"Its certificate (for {', '.join(tls.names)}) is signed by {tls.authority}: "
                "install that on pupils' devices (docs/studio.md). It can vouch for these "
                f"names only, and lasts until {tls.expires:%Y-%m-%d}.",
                flush=True,
            )
            if tls.made_now:
                print("That file is new: devices that had an older one need this one.",
                      flush=True)  # fmt: skip
            elif tls.ending_soon:
                print(f"It ends on {tls.expires:%Y-%m-%d}: then a new one is made, for the "
                      "devices to install again.", flush=True)  # fmt: skip
            print(f"SPKI fingerprint (sha256, base64): {tls.spki_sha256}", flush=True)
        print("Press Ctrl-C to stop it.", flush=True)
        if not args.no_browser:
            webbrowser.open(address)

    try:
        asyncio.run(
            serve(folder, args.host, args.port, ready, args.transport, classroom, tls, limits,
                  allow_hosts=tuple(args.allow_host), warm=True, languages=args.languages)
        )  # fmt: skip
    except KeyboardInterrupt:
        print("Stopped the studio.", flush=True)
    return 0
