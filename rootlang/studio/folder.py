"""The class folder: the only place the studio reads and writes.

Programs are the ``.root`` files directly in the folder. Each may have a layout sidecar,
``.NAME.root.layout.json`` (hidden, so the folder still looks like a folder of programs), that
keeps where the child put each top-level block, keyed by the script's order and header text.
The text file is the source of truth: a sidecar that no longer matches is simply ignored.

Names come from the browser, so every one is checked before it touches the disk: a plain file
name ending in ``.root`` (no folders, no ``..``, no absolute paths), and the resolved path must
still be inside the folder (a symlink pointing out is refused).

A Save never writes one program over another: each program has a **version** (a hash of its
bytes) that the page got when it opened it, and a Save that brings another version than the
file now has (another tab or another pupil saved meanwhile) is refused (E819). Before a file is
overwritten, what it held is kept in ``.rootlang-history/NAME.root/`` (the last
:data:`KEPT_VERSIONS`, named by the time they were replaced), for a teacher to restore.
"""

from __future__ import annotations

import hashlib
import json
import re
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from rootlang.app.files import inside
from rootlang.diagnostics import RootlangError, file_problem
from rootlang.studio.messages import ProgramFileJson

PROGRAM_SUFFIX = ".root"
SIDECAR_SUFFIX = ".layout.json"
HISTORY = ".rootlang-history"
KEPT_VERSIONS = 20  # per program: a lesson's worth of Saves
# Letters (any script), digits, spaces, dashes and underscores: a name a child types.
_NAME = re.compile(r"[\w][\w \-]{0,63}\.root", re.UNICODE)


@dataclass(frozen=True)
class ProgramFile:
    name: str
    size: int
    modified: float

    def to_json(self) -> ProgramFileJson:
        return {"name": self.name, "size": self.size, "modified": self.modified}


def version_of(text: str) -> str:
    """A program's version as the page keeps it: a hash of its bytes."""
    return hashlib.sha256(text.encode("utf-8")).hexdigest()[:16]


class ClassFolder:
    def __init__(self, root: Path, clock: Callable[[], float] = time.time) -> None:
        if not root.is_dir():
            raise RootlangError.of("E807", path=str(root))
        self.root = root.resolve()
        self.clock = clock  # names the kept versions

    def programs(self) -> list[ProgramFile]:
        found = []
        for path in sorted(self.root.glob("*" + PROGRAM_SUFFIX)):
            if path.is_file() and _NAME.fullmatch(path.name) and self._inside(path):
                stat = path.stat()
                found.append(ProgramFile(path.name, stat.st_size, stat.st_mtime))
        return found

    def read(self, name: str) -> str:
        path = self.path_of(name)
        if not path.is_file():
            raise RootlangError.of("E802", name=name)
        try:
            return path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError) as error:
            raise RootlangError.of("E808", name=name, reason=file_problem(error)) from None

    def write(self, name: str, text: str) -> None:
        path = self.path_of(name)
        try:
            path.write_text(text, encoding="utf-8")
        except OSError as error:
            raise RootlangError.of("E808", name=name, reason=file_problem(error)) from None

    def save(self, name: str, text: str, version: str | None) -> str:
        """Write ``text`` over the program the page opened at ``version`` (None: whatever the
        file holds, as a tool without a page may), keeping what it held; the new version.
        E819 when the file is no longer the version the page opened."""
        path = self.path_of(name)
        old = self.read(name) if path.is_file() else None
        if version is not None and old is not None and version != version_of(old):
            raise RootlangError.of("E819", name=name)  # (a file gone meanwhile is written back)
        if old is not None and old != text:
            self._keep(name, old)
        self.write(name, text)
        return version_of(text)

    def history(self, name: str) -> list[Path]:
        """The kept versions of a program, oldest first."""
        folder = self._history_folder(name)
        if folder is None or not folder.is_dir():
            return []
        return sorted(path for path in folder.glob("*" + PROGRAM_SUFFIX) if path.is_file())

    def _keep(self, name: str, text: str) -> None:
        folder = self._history_folder(name)
        if folder is None:  # the history folder is a link out of the class folder: none kept
            return
        kept = self.history(name)
        if kept and kept[-1].read_text(encoding="utf-8", errors="replace") == text:
            return
        stamp = time.strftime("%Y-%m-%d %H-%M-%S", time.localtime(self.clock()))
        path, count = folder / f"{stamp}{PROGRAM_SUFFIX}", 1
        while path.exists():  # two Saves in one second
            count += 1
            path = folder / f"{stamp} ({count}){PROGRAM_SUFFIX}"
        try:
            folder.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
            for old in self.history(name)[:-KEPT_VERSIONS]:
                old.unlink()
        except OSError as error:
            raise RootlangError.of("E808", name=name, reason=file_problem(error)) from None

    def _history_folder(self, name: str) -> Path | None:
        """``.rootlang-history/NAME.root/``, or None if a link leads it out of the folder."""
        base = self.root / HISTORY
        folder = base / self.path_of(name).name
        for part in (base, folder):
            if part.is_symlink() or (part.exists() and not part.is_dir()):
                return None
        return folder

    def create(self, name: str, text: str) -> None:
        """A new program: E803 if ``name`` is taken, even by a file made a moment ago (the file
        is made only if it is not there: two pages asking at once never share one)."""
        path = self.path_of(name)
        try:
            with path.open("x", encoding="utf-8") as made:
                made.write(text)
        except FileExistsError:
            raise RootlangError.of("E803", name=name) from None
        except OSError as error:
            raise RootlangError.of("E808", name=name, reason=file_problem(error)) from None

    def rename(self, old: str, new: str) -> None:
        source, target = self.path_of(old), self.path_of(new)
        if not source.is_file():
            raise RootlangError.of("E802", name=old)
        if target.exists():
            raise RootlangError.of("E803", name=new)
        source.rename(target)
        sidecar = self._sidecar(old)
        if sidecar.is_file():
            sidecar.rename(self._sidecar(new))
        kept, moved = self._history_folder(old), self._history_folder(new)
        if kept is not None and moved is not None and kept.is_dir() and not moved.exists():
            kept.rename(moved)

    def read_layout(self, name: str) -> dict[str, object]:
        sidecar = self._sidecar(name)
        if not self._inside(sidecar):  # a symlink pointing out of the folder: not followed
            return {}
        try:
            data = json.loads(sidecar.read_text(encoding="utf-8"))
        except (OSError, ValueError):  # none yet, or spoilt: the blocks are simply stacked
            return {}
        return data if isinstance(data, dict) else {}

    def write_layout(self, name: str, layout: dict[str, object]) -> None:
        self.path_of(name)  # the program's name is checked like any other
        text = json.dumps(layout, indent=1, sort_keys=True, ensure_ascii=False)
        sidecar = self._sidecar(name)
        if not self._inside(sidecar):  # a symlink pointing out of the folder: not followed
            raise RootlangError.of(
                "E808", name=name, reason="its layout file is outside the folder"
            )
        try:
            sidecar.write_text(text + "\n", encoding="utf-8")
        except OSError as error:
            raise RootlangError.of("E808", name=name, reason=file_problem(error)) from None

    def path_of(self, name: str) -> Path:
        """The file for a program name from the browser; E801 for anything but a plain
        ``NAME.root`` inside the folder."""
        if not isinstance(name, str) or not _NAME.fullmatch(name) or name != name.strip():
            raise RootlangError.of("E801", name=str(name)[:80])
        path = self.root / name
        if not self._inside(path):
            raise RootlangError.of("E801", name=name)
        return path

    def _sidecar(self, name: str) -> Path:
        return self.path_of(name).with_name("." + name + SIDECAR_SUFFIX)

    def _inside(self, path: Path) -> bool:
        """Whether ``path`` (following symlinks) is a file directly in the folder."""
        return inside(path, self.root, directly=True)


def built_in_worlds() -> dict[str, Path]:
    """The worlds that ship with rootlang (if this build ships any), by name."""
    from importlib import resources

    try:
        folder = Path(str(resources.files("rootlang").joinpath("worlds")))
    except (ModuleNotFoundError, TypeError):
        return {}
    return {path.stem: path for path in sorted(folder.glob("*.toml"))} if folder.is_dir() else {}


def folder_worlds(folder: ClassFolder) -> dict[str, Path]:
    """The class folder's own worlds (``worlds/*.toml``), by name; they win over built-in ones."""
    below = folder.root / "worlds"
    if not below.is_dir() or not inside(below, folder.root, directly=True):  # a link out
        return {}
    return {
        path.stem: path
        for path in sorted(below.glob("*.toml"))
        if path.is_file() and inside(path, below, directly=True)
    }
