"""A class folder to serve, the studio serving it on a free port in a thread of its own, and a
computer that speaks English."""

from __future__ import annotations

import asyncio
import shutil
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

from rootlang.studio.classroom import Classroom
from rootlang.studio.folder import ClassFolder
from rootlang.studio.runs import ClassLimits
from rootlang.studio.server import serve
from rootlang.studio.tls import StudioCertificate

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
CLASS_PROGRAMS = ("square.root", "bumpers.root", "stop_button.root", "touch_drive.root",
                  "bump_and_turn.root")  # fmt: skip


@pytest.fixture
def class_folder(tmp_path: Path) -> Path:
    folder = tmp_path / "class"
    folder.mkdir()
    for name in CLASS_PROGRAMS:
        shutil.copy(PROGRAMS / name, folder / name)
    return folder


class RunningStudio:
    def __init__(
        self,
        folder: Path,
        transport: str | None = None,
        classroom: Classroom | None = None,
        tls: StudioCertificate | None = None,
        limits: ClassLimits | None = None,
        host: str = "127.0.0.1",
        allow_hosts: tuple[str, ...] = (),
        port: int = 0,  # (0: a free one)
    ) -> None:
        self.host = host
        self.port = port
        self.allow_hosts = allow_hosts
        self.folder = folder
        self.transport = transport
        self.classroom = classroom
        self.tls = tls
        self.limits = limits
        self.address = ""
        self._ready = threading.Event()
        self._loop = asyncio.new_event_loop()
        self._task: asyncio.Task[None] | None = None
        self._thread = threading.Thread(target=self._serve, daemon=True)

    def _serve(self) -> None:
        asyncio.set_event_loop(self._loop)

        def ready(address: str) -> None:
            self.address = address.rstrip("/")
            self._ready.set()

        self._task = self._loop.create_task(
            serve(
                ClassFolder(self.folder),
                self.host,
                self.port,
                ready,
                self.transport,
                self.classroom,
                self.tls,
                self.limits,
                self.allow_hosts,
            )
        )
        try:
            self._loop.run_until_complete(self._task)
        except asyncio.CancelledError:
            pass
        finally:
            self._ready.set()
            self._loop.close()

    def start(self) -> RunningStudio:
        self._thread.start()
        assert self._ready.wait(30) and self.address, "the studio did not start"
        return self

    def stop(self) -> None:
        if self._task is not None and not self._loop.is_closed():  # (once: a test may stop it)
            self._loop.call_soon_threadsafe(self._task.cancel)
        self._thread.join(30)


@pytest.fixture
def english_computer(monkeypatch: pytest.MonkeyPatch) -> None:
    """The computer the studio runs on speaks English: a page's language must win over it."""
    for variable in ("LC_ALL", "LC_MESSAGES"):
        monkeypatch.delenv(variable, raising=False)
    monkeypatch.setenv("LANG", "en_US.UTF-8")


@pytest.fixture
def studio(class_folder: Path) -> Iterator[RunningStudio]:
    running = RunningStudio(class_folder).start()
    yield running
    running.stop()


@pytest.fixture
def robot_studio(class_folder: Path) -> Iterator[RunningStudio]:
    """A studio with a robot in range: bumble's virtual robot (rootlang[virtual])."""
    pytest.importorskip("bumble", reason="the virtual robot needs rootlang[virtual]")
    running = RunningStudio(class_folder, transport="virtual").start()
    yield running
    running.stop()
