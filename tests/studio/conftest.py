"""A class folder to serve, the studio serving it on a free port in a thread of its own, a
computer that speaks English, and a browser's pages on it (browser.py's :class:`Page`)."""

from __future__ import annotations

import asyncio
import shutil
import threading
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

import pytest

from rootlang.studio.classroom import Classroom
from rootlang.studio.folder import ClassFolder
from rootlang.studio.runs import ClassLimits
from rootlang.studio.server import serve
from rootlang.studio.tls import StudioCertificate

if TYPE_CHECKING:
    from .browser import Page

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


# ---- a class ------------------------------------------------------------------------------------

CODE = "123456"  # the teacher's code


def make_class(folder: Path) -> Path:
    """A class folder with a starter for everyone and one task (square: pose and drawing)."""
    (folder / "_start").mkdir(parents=True)
    (folder / "_start" / "hello.root").write_text('when started\n    say "hello"\n', "utf-8")
    task = folder / "_tasks" / "square"
    task.mkdir(parents=True)
    shutil.copy(PROGRAMS / "square.golden", task / "square.golden")
    (task / "square.root").write_text("# draw a square of 10 cm\nwhen started\n", "utf-8")
    (task / "task.toml").write_text('title = "A square"\n', "utf-8")
    return folder


@pytest.fixture
def class_studio(tmp_path: Path) -> Iterator[RunningStudio]:
    folder = make_class(tmp_path / "class")
    running = RunningStudio(folder, classroom=Classroom(ClassFolder(folder), CODE)).start()
    yield running
    running.stop()


# ---- a browser ----------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def browser() -> Iterator[Any]:
    """Debian's chromium, headless, through Playwright (a test module's pages share it)."""
    from .browser import CHROMIUM, CHROMIUM_ARGS

    if not CHROMIUM.exists():
        pytest.skip("needs Debian's chromium at /usr/bin/chromium")
    playwright_api = pytest.importorskip("playwright.sync_api")
    with playwright_api.sync_playwright() as playwright:
        launched = playwright.chromium.launch(executable_path=str(CHROMIUM), args=CHROMIUM_ARGS)
        yield launched
        launched.close()


def _opened(page: Page) -> Iterator[Page]:
    """``page``, closed after its test, which it fails if it asked for anything beyond the
    studio or its script failed."""
    yield page
    assert page.outside == [], "the page asked for something beyond the studio"
    assert page.errors == [], "the page's script failed"
    page.close()


@pytest.fixture
def page(browser: Any, studio: RunningStudio) -> Iterator[Page]:
    from .browser import Page

    yield from _opened(Page(browser, studio))


@pytest.fixture
def tablet(browser: Any, studio: RunningStudio) -> Iterator[Page]:
    """The studio on a tablet: a touch screen (a finger, `pointer: coarse`), tablet-sized."""
    from .browser import TABLET, Page

    yield from _opened(Page(browser, studio, TABLET, touch=True))
