"""`rootlang new NAME`: write a starter program to begin from."""

from __future__ import annotations

import argparse
import shlex
from pathlib import Path

from rootlang.app.files import starter
from rootlang.diagnostics import RootlangError
from rootlang.wording.catalogue import message


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "name",
        metavar="NAME",
        help="the new program's name, like `dance` (writes dance.root in this folder)",
    )


def run(args: argparse.Namespace) -> int:
    path = Path(args.name)
    if path.suffix != ".root":
        path = path.with_name(path.name + ".root")
    if path.exists():
        raise RootlangError.of("E604", path=str(path))
    if not path.parent.is_dir():
        raise RootlangError.of("E608", path=str(path.parent))
    # (with --language nl: the starter's keywords in Dutch)
    text = starter(path.stem, shlex.quote(path.name), args.language)
    path.write_text(text, encoding="utf-8")
    picture = path.with_suffix(".svg")
    # quoted as a shell needs it, so "my dance" can be pasted as it is shown
    wrote = message("V060", {"path": str(path), "picture": str(picture)}, args.languages)
    print(f"{wrote}\n    rootlang sim {shlex.quote(str(path))} --svg {shlex.quote(str(picture))}")
    return 0
