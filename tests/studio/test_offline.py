"""The page opens again while the studio is out of reach (static/sw.js, a service worker): the
school's Wi-Fi down, the teacher's laptop asleep. Loaded once, the page is kept; reloaded with
the studio gone, it starts from the answers it last got, and the child's unsaved typing is back
from its draft. What changes anything (a save) waits for the studio, and the page says so."""

from __future__ import annotations

from .browser import Page
from .conftest import RunningStudio


def test_the_page_opens_again_with_the_childs_typing_while_the_studio_is_away(
    page: Page, studio: RunningStudio
) -> None:
    try:
        page.open("square.root")
        page.wait_state("offline", "ready")  # (its first load's answers kept)
        page.type_at_the_end('\nwhen started\n    say "offline"\n')
        page.wait_state("draft", "square.root")
        studio.stop()
        page.page.reload()
        page.wait_state("ready", "yes")  # (started from the kept answers)
        assert 'say "offline"' in page.text() and "repeat 4" in page.text()  # (its draft)
        assert page.js("() => Blockly.getMainWorkspace() !== null")  # (its blocks pane set up)
        page.page.click("#save")
        page.page.wait_for_function(
            "() => document.getElementById('status').classList.contains('error')"
        )
        assert page.state()["draft"] == "square.root"  # (still kept: nothing was saved)
    finally:
        studio.stop()  # (again at the test's end: once is enough)
