"""Program files and the files that go with them: finding and reading programs, the world a
program names, and the starter program ``rootlang new`` and the studio's New write.

A program's first comment lines may name the world it is meant for, relative to the program's
own folder. ``rootlang sim``, ``rootlang test`` and the studio all read it (``--world``
overrides it), so a program behaves the same whichever way it is run. Without the line, the
default world is used.

The simulator's world module loads only when a world is looked up, so ``rootlang check``, which
finds and reads programs here, starts without it (``tests/cli/test_start_up.py``).
"""

from __future__ import annotations

import errno
import os
import re
import tempfile
from collections.abc import Iterable
from dataclasses import replace
from pathlib import Path, PurePosixPath, PureWindowsPath
from typing import TYPE_CHECKING

from rootlang.diagnostics import RootlangError, Span, diagnostic, file_problem

if TYPE_CHECKING:
    from rootlang.sim.world import World

PROGRAM_SUFFIX = ".root"
_WORLD_LINE = re.compile(r"#\s*world\s*:\s*(?P<path>\S.*?)\s*$", re.IGNORECASE)

STARTER = """\
# {about}
when started
    light green
    marker down
    repeat 4
        move 10 cm
        turn right 90 degrees
    marker up
    play note C5 for 0.2 seconds
    say "{said}"
"""
"""The program ``rootlang new`` and the studio's New start from, in English (``about``: its
first comment, V076; ``said``: what the robot says, V077). Only `when started`: the program
ends by itself when the square is drawn; a `when bumped` script would keep it waiting for a
bump until the time limit, on every run."""


def starter(name: str, command_line: str, language: str | None) -> str:
    """The starter program wholly in ``language`` (None: English): its keywords, its comment
    and what its robot says (with a `# language:` line that says so). ``name``: its file's
    name without ``.root``; ``command_line``: the file as a shell takes it."""
    from rootlang.wording.catalogue import message
    from rootlang.wording.language import Languages

    languages = Languages(chosen=language or "en")  # (the catalogue's words in that language)
    about = message("V076", {"name": name, "command_line": command_line}, languages)
    said = message("V077", {}, languages)
    text = STARTER.format(about=about, said=said)
    if language is None or language == "en":
        return text
    from rootlang.locale.translate import from_english

    first, rest = text.split("\n", 1)
    return f"{first}\n# language: {language}\n{from_english(rest, language)}"


def find_programs(paths: Iterable[str | Path], *, any_suffix: bool = False) -> list[Path]:
    """Every program named, or found below a named folder (sorted, without duplicates);
    folders whose names start with a dot are skipped. ``hello`` names ``hello.root`` when
    there is no file ``hello`` (as `rootlang new hello` wrote it). A file named outright must
    end in .root (E605) unless ``any_suffix``; a name that is nothing is E601."""
    found: list[Path] = []
    for name in paths:
        path = program_file(Path(name))
        if path.is_dir():
            below = (p for p in path.rglob("*" + PROGRAM_SUFFIX) if p.is_file())
            found.extend(sorted(p for p in below if not _hidden(p.relative_to(path))))
        elif path.is_file():
            if path.suffix != PROGRAM_SUFFIX and not any_suffix:
                raise RootlangError.of("E605", path=str(path))
            found.append(path)
        else:
            raise RootlangError.of("E601", path=str(name))
    return list(dict.fromkeys(found))


def program_file(path: Path) -> Path:
    """``path``, or ``path.root`` when only that exists (``hello`` for hello.root)."""
    if path.suffix == PROGRAM_SUFFIX or not path.name or path.exists():
        return path
    named = path.with_name(path.name + PROGRAM_SUFFIX)
    return named if named.exists() else path


def read_program(path: str, shown_as: str | None = None) -> str:
    """The program's text. ``hello`` reads hello.root when there is no file ``hello`` (as
    `rootlang new hello` wrote it). RootlangError E601 when there is no such file, E614 for a
    folder, E615 when it isn't UTF-8 text, E602 for anything else (like no permission); the
    messages name it ``shown_as`` (default: ``path``)."""
    file, name = program_file(Path(path)), shown_as or path
    if file.is_dir():  # Windows reports reading a folder as PermissionError
        raise RootlangError.of("E614", path=name)
    try:
        source = file.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise RootlangError.of("E601", path=name) from None
    except UnicodeDecodeError:
        raise RootlangError.of("E615", path=name) from None
    except OSError as error:
        raise RootlangError.of("E602", path=name, reason=file_problem(error)) from None
    return source


def write_file(path: str | Path, text: str, code: str = "E622") -> None:
    """Write ``text`` (UTF-8, ``\\n`` line ends) next to ``path``, then swap it in: a crash
    or Ctrl-C never leaves half a file, and a file that can't be written is left as it was.
    RootlangError ``code`` (``path``, ``reason``) when it can't be written."""
    target = Path(path)
    temporary: str | None = None
    try:
        if target.is_dir():  # (before the swap, which would put the file inside it)
            raise IsADirectoryError(errno.EISDIR, "Is a directory", str(target))
        handle, temporary = tempfile.mkstemp(
            dir=target.parent, prefix=f".{target.name}.", suffix=".tmp"
        )
        with os.fdopen(handle, "w", encoding="utf-8", newline="\n") as file:
            file.write(text)
        os.replace(temporary, target)
    except OSError as error:
        raise RootlangError.of(code, path=str(path), reason=file_problem(error)) from None
    finally:
        if temporary is not None and os.path.exists(temporary):
            os.unlink(temporary)


def _hidden(relative: Path) -> bool:
    return any(part.startswith(".") for part in relative.parts)


def world_for(
    program: Path,
    source: str,
    override: str | Path | None = None,
    *,
    names_from: Path | None = None,
) -> World:
    """The world to run a program in: ``override`` (``--world``), else the one the program
    names in its opening comments, else the default world. ``names_from``: a folder every
    file is named relative to in messages (see :func:`shown_path`; default: as given)."""
    from rootlang.sim.world import default_world, load_world  # only when a program runs

    if override:
        return load_world(override, shown_as=shown_path(Path(override), names_from))
    named = named_world(program, source, names_from=names_from)
    if named is None:
        return default_world()
    try:
        return load_world(named, shown_as=shown_path(named, names_from))
    except RootlangError as error:  # a world file that can't be read: said on its line
        where = _world_line(source)
        if where is None:
            raise
        number, column, written = where
        span = Span.point(number, column, len(written))
        file = shown_path(program, names_from)
        placed = [item if item.span.line else replace(item, span=span, file=file)
                  for item in error.diagnostics]  # fmt: skip
        raise RootlangError(placed, source) from None


def shown_path(path: Path, names_from: Path | None) -> str:
    """A file as messages name it: as given (``names_from`` None: the command line's, as the
    person typed it); else to someone who sees only the folder ``names_from`` (a studio's
    page): relative to it (``worlds/arena.toml``), and a file outside it (a world that ships
    with rootlang) by its name alone. Never the server's own path."""
    if names_from is None:
        return str(path)
    for base in (names_from, names_from.resolve()):
        if path.is_relative_to(base):
            return path.relative_to(base).as_posix()
    return path.name


def inside(path: Path, folder: Path, *, directly: bool = False) -> bool:
    """Whether ``path``, every symbolic link followed, is in ``folder`` (followed too):
    anywhere below it, or ``directly`` in it. The one check that keeps what a page or a
    program names (a program, its layout file, a world) from leaving its folder by a link."""
    try:
        real, home = path.resolve(), folder.resolve()
    except (OSError, RuntimeError):  # (a loop of links)
        return False
    if directly:
        return real.parent == home
    return real != home and real.is_relative_to(home)


def named_world(program: Path, source: str, *, names_from: Path | None = None) -> Path | None:
    """The world file named in the program's opening comments, or None.

    The line names a file in the program's own folder (``# world: worlds/arena.toml``) or a
    world by name (``# world: arena``: the folder's ``worlds/arena.toml``, else the built-in
    one). It can't reach outside the folder, not even through a symbolic link: shared programs
    must not read other files. Raises RootlangError E616 for a path leaving the folder, E607
    when nothing is found (naming the program as :func:`shown_path` does)."""
    where = _world_line(source)
    if where is None:
        return None
    number, column, named = where
    # (only a program that names a world loads the worlds: `rootlang check` starts fast)
    from rootlang.sim.world import (
        BUILT_IN_WORLDS,
        world_file_named,
        world_names,
        world_suggestion,
    )

    folder = program.parent
    if _leaves_folder(named):
        code = "E616"
    else:
        inside_file = folder / named
        found = inside_file if inside_file.is_file() else world_file_named(named, folder)
        if found is not None and (found.parent == BUILT_IN_WORLDS or inside(found, folder)):
            return found
        code = "E607" if found is None else "E616"  # (E616: a link leading out)
    span = Span.point(number, column, len(named))
    known = ", ".join(world_names(folder))
    suggestion = world_suggestion(named, folder) if code == "E607" else ""
    found_error = diagnostic(code, span, world=named, known=known, suggestion=suggestion)
    raise RootlangError([found_error.in_file(shown_path(program, names_from))], source)


def _world_line(source: str) -> tuple[int, int, str] | None:
    """The `# world:` line of a program's opening comments: its number, the column of the
    world it names, and what it names."""
    for number, line in enumerate(source.splitlines(), 1):
        stripped = line.strip()
        if stripped and not stripped.startswith("#"):
            return None
        match = _WORLD_LINE.match(stripped)
        if match is not None:
            column = len(line) - len(line.lstrip()) + match.start("path") + 1
            return number, column, match["path"]
    return None


def _leaves_folder(named: str) -> bool:
    """An absolute path, a drive, or a step up (``..``), in either slash."""
    windows = PureWindowsPath(named)
    return (
        PurePosixPath(named).is_absolute()
        or bool(windows.drive or windows.root)
        or ".." in windows.parts
    )
