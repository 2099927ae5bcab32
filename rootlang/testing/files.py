"""Program files and the files that go with them.

- ``spiral.root`` keeps its golden file next to it: ``spiral.golden``.
- A program's first comment lines may name the world it is meant for, relative to the program's
own folder. ``rootlang sim`` and ``rootlang test`` both read it (``--world`` overrides it), so a
program behaves the same whichever way it is run. Without the line, the default world is used.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from pathlib import Path
from typing import TYPE_CHECKING

from rootlang.diagnostics import RootlangError, Span, diagnostic

if TYPE_CHECKING:
    from rootlang.sim.world import World

PROGRAM_SUFFIX = ".root"
GOLDEN_SUFFIX = ".golden"
_WORLD_LINE = re.compile(r"#\s*world\s*:\s*(?P<path>\S.*?)\s*$", re.IGNORECASE)


def golden_path(program: Path) -> Path:
    """Where a program's golden file lives: next to it, ``.root`` replaced by ``.golden``."""
    return program.with_suffix(GOLDEN_SUFFIX)


def find_programs(paths: Iterable[str | Path]) -> list[Path]:
    """Every ``.root`` file named, or found below a named folder (sorted, without duplicates);
    folders whose names start with a dot are skipped."""
    found: list[Path] = []
    for name in paths:
        path = Path(name)
        if path.is_dir():
            below = (p for p in path.rglob("*" + PROGRAM_SUFFIX) if p.is_file())
            found.extend(sorted(p for p in below if not _hidden(p.relative_to(path))))
        elif path.is_file():
            if path.suffix != PROGRAM_SUFFIX:
                raise RootlangError.of("E605", path=str(path))
            found.append(path)
        else:
            raise RootlangError.of("E601", path=str(path))
    return list(dict.fromkeys(found))


def _hidden(relative: Path) -> bool:
    return any(part.startswith(".") for part in relative.parts)


def world_for(program: Path, source: str, override: str | Path | None = None) -> World:
    """The world to run a program in: ``override`` (``--world``), else the one the program
    names in its opening comments, else the default world."""
    from rootlang.sim.world import default_world, load_world  # only when a program runs

    if override:
        return load_world(override)
    named = named_world(program, source)
    return default_world() if named is None else load_world(named)


def named_world(program: Path, source: str) -> Path | None:
    """The world file named in the program's opening comments, or None.

    Raises RootlangError (E607) when the named file does not exist."""
    for number, line in enumerate(source.splitlines(), 1):
        stripped = line.strip()
        if stripped and not stripped.startswith("#"):
            return None
        match = _WORLD_LINE.match(stripped)
        if match:
            world = program.parent / match["path"]
            if not world.is_file():
                column = line.index(match["path"]) + 1
                span = Span.point(number, column, len(match["path"]))
                found = diagnostic("E607", span, world=match["path"]).in_file(str(program))
                raise RootlangError([found], source)
            return world
    return None
