"""A studio page in a real headless browser (Debian's chromium through Playwright), as the
studio's browser tests drive it: the fixtures that open one are in conftest.py."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

from .conftest import RunningStudio

CHROMIUM = Path("/usr/bin/chromium")
playwright_api = pytest.importorskip("playwright.sync_api")
# The live block the text's line (or expression) is now: block ids are the page's own, not lines
BLOCK = "(await import('/static/blocks.js')).liveBlock"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--no-first-run"]  # fmt: skip
TABLET = {"width": 1024, "height": 768}
# The tab's id (drafts.js), and whether the browser has let its tab's Web Lock go
TAB_ID = "() => sessionStorage.getItem('rootlang.tab') || ''"
TAB_LET_GO = """async tab => !((await navigator.locks.query()).held || [])
    .some(lock => lock.name === 'rootlang.tab ' + tab)"""
CONSOLE_KEPT = 30  # the page's last console lines kept, to say why a wait never ended
WAIT_MS = 120_000
"""How long a page's wait may last: room for a busy computer (two test workers and their
browsers on two cores), never a measure of speed (benchmarks/ has those)."""


class Page:
    """A studio page, counting every request that is not to the studio's own address."""

    def __init__(
        self, browser: Any, studio: RunningStudio, viewport: dict[str, int] | None = None,
        touch: bool = False, *, context: Any = None,
    ) -> None:  # fmt: skip
        self.studio = studio
        self.outside: list[str] = []
        self.errors: list[str] = []
        if context is None:  # (a browser of its own: its cookies and storage)
            context = browser.new_context(
                viewport=viewport or {"width": 1400, "height": 850}, has_touch=touch
            )
            context.set_default_timeout(WAIT_MS)
        self.page = context.new_page()
        self._watch()

    def another_tab(self) -> Page:
        """A second tab in this page's browser: its cookies and localStorage, its own
        sessionStorage."""
        return Page(None, self.studio, context=self.page.context)

    def _watch(self) -> None:
        self.console: list[str] = []  # the page's last words to its console (for a failure)
        self.page.route("**/*", self._route)
        self.page.on("pageerror", lambda error: self.errors.append(str(error)))
        self.page.on("console", self._heard)

    def _heard(self, message: Any) -> None:
        self.console = [*self.console[-(CONSOLE_KEPT - 1) :], f"{message.type}: {message.text}"]

    def type_at_the_end(self, text: str) -> None:
        """Types ``text`` at the end of the text pane, key by key, as a child would."""
        self.page.click(".CodeMirror")
        self.page.keyboard.press("Control+End")
        self.page.keyboard.type(text)

    def close(self) -> None:
        self.page.context.close()

    def closed_and_opened_again(self) -> None:
        """The tab gone without a word (:meth:`gone`), then a new one in the same browser: its
        cookies and storage stay. Open a page in it next."""
        context = self.page.context
        self.page = self.gone(context.new_page())  # (the context's viewport)
        self._watch()

    def gone(self, after: Any = None) -> Any:
        """The tab gone without a word (a crash, a lid shut, "Leave" on leaving), once the
        browser knows it: it lets the tab's Web Lock go (how the next tab tells a gone tab's
        drafts from a live one's, drafts.js) a moment after the tab closed, later on a busy
        computer. Waited for in ``after`` (a new tab of this browser, given back; else one
        made for it and closed), at a file of the studio's (its Web Locks are the studio's)."""
        tab = self.page.evaluate(TAB_ID) if self.page.url.startswith(self.studio.address) else ""
        self.page.close(run_before_unload=False)
        watcher = after or self.page.context.new_page()
        if tab:
            watcher.goto(f"{self.studio.address}/static/studio.css")
            watcher.wait_for_function(TAB_LET_GO, arg=tab)
        if after is None:
            watcher.close()
        return watcher

    def _route(self, route: Any) -> None:
        if route.request.url.startswith(self.studio.address + "/"):
            route.continue_()
        else:
            self.outside.append(route.request.url)
            route.abort()

    def open(self, name: str, language: str = "") -> Page:
        chosen = f"&language={language}" if language else ""
        self.page.goto(f"{self.studio.address}/?open={name}{chosen}")
        self.wait_state("ready", "yes")
        self.wait_state("open", name)
        # (the page is the child's once its first blocks are made; the rest come between frames)
        self.page.wait_for_function(
            "() => document.getElementById('state').dataset.blocksMaking !== 'yes'"
        )
        return self

    def state(self) -> dict[str, str]:
        data: dict[str, str] = self.page.eval_on_selector("#state", "e => ({...e.dataset})")
        return data

    def wait_state(self, key: str, value: str, timeout_ms: int = WAIT_MS) -> None:
        try:
            self.page.wait_for_function(
                "([key, value]) => document.getElementById('state').dataset[key] === value",
                arg=[key, value], timeout=timeout_ms,
            )  # fmt: skip
        except playwright_api.TimeoutError as waited:
            raise AssertionError(self.said(f"the page's {key} never became {value!r}")) from waited

    def said(self, what: str) -> str:
        """``what`` went wrong, with what the page says of itself: its address, its state, its
        script's errors and its last console lines (a wait that never ends tells why)."""
        try:
            state: object = self.state()
        except playwright_api.Error as error:
            state = f"(unreadable: {error})"
        return "\n".join([what, f"at {self.page.url}", f"state: {state}",
                          f"errors: {self.errors}", *self.console])  # fmt: skip

    def text(self) -> str:
        text: str = self.page.evaluate(
            "() => document.querySelector('.CodeMirror').CodeMirror.getValue()"
        )
        return text

    def js(self, script: str, arg: Any = None) -> Any:
        return self.page.evaluate(script, arg)

    def drawn(self, element: str) -> dict[str, float]:
        """Where ``element`` (JavaScript naming a block's SVG element) is drawn, once Blockly has
        drawn its queued frame: a part made a moment ago sits at the block's corner until then,
        and a child only ever clicks what is drawn."""
        box: dict[str, float] = self.page.evaluate(f"""async () => {{
            await Blockly.renderManagement.finishQueuedRenders();
            const r = ({element}).getBoundingClientRect();
            return {{x: r.left, y: r.top, w: r.width, h: r.height}};
        }}""")
        return box

    def run(self, speed: str = "0", world: str = "") -> None:
        if not self.page.locator("#speed").is_visible():  # (Level 1: a grown-up's to choose)
            self.page.click("#grown-ups")
        self.page.select_option("#speed", speed)
        self.page.select_option("#world", world)
        # (begun, or begun and over already: a short run as fast as it goes can end between
        # two looks at the page, and `running` is then never seen "yes")
        self.page.evaluate("() => { document.getElementById('state').dataset.ended = ''; }")
        self.page.click("#run")
        self.page.wait_for_function(
            """() => { const state = document.getElementById('state').dataset;
                return state.running === 'yes' || (state.ended || '') !== ''; }"""
        )

    def wait_ended(self, timeout_ms: int = WAIT_MS) -> str:
        self.page.wait_for_function(
            "() => (document.getElementById('state').dataset.ended || '') !== ''",
            timeout=timeout_ms,
        )
        return self.state()["ended"]
