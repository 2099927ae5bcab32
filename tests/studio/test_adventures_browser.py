"""Adventures in real Chromium: a pupil at Level 1 on a tablet, by a finger, picks "Draw a
square" from the list of their level's adventures, sees and hears its goal, checks the starter
and hears a hint (never the answer), fixes it with a number key, runs it, passes the check and
moves on; drags the pen into "Draw a line" and passes; the teacher's page shows who has done
which. The list and the goal meet WCAG AA (axe-core) and are reached by the keyboard. At home
(no class), a child does the same with a mouse, their progress kept in the folder."""

from __future__ import annotations

import json
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from rootlang.studio.classroom import Classroom
from rootlang.studio.folder import ClassFolder
from rootlang.studio.lessons import PROGRESS_FILE

from .browser import CHROMIUM, TABLET, Page
from .conftest import CODE, RunningStudio, make_class
from .test_accessibility import AXE, axe_violations
from .test_class_browser import ClassPage
from .test_levels_browser import LISTEN, _below, _drag_from_toolbox, _pick_number, _tap

pytestmark = pytest.mark.skipif(
    not CHROMIUM.exists(), reason="needs Debian's chromium at /usr/bin/chromium"
)
SQUARE = "04-draw-a-square"


@pytest.fixture
def level_1_class(tmp_path: Path) -> Iterator[RunningStudio]:
    folder = make_class(tmp_path / "class")
    classroom = Classroom(ClassFolder(folder), CODE, level=1)
    running = RunningStudio(folder, classroom=classroom).start()
    yield running
    running.stop()


def _tablet(browser: Any, studio: RunningStudio) -> ClassPage:
    """A pupil's tablet: a touch screen, tablet-sized, its speech kept by the test."""
    page = ClassPage(browser, studio, TABLET, touch=True)
    page.page.add_init_script(LISTEN)
    return page


def test_a_pre_reader_takes_an_adventure_gets_a_hint_passes_and_the_teacher_sees_it(
    browser: Any, level_1_class: RunningStudio
) -> None:
    mia, miss = _tablet(browser, level_1_class), ClassPage(browser, level_1_class)
    miss.as_teacher()
    mia.join("Mia", "hello.root")
    mia.wait_state("level", "1")
    # the list: Level 1's adventures, each a picture of its goal
    _tap(mia, "document.getElementById('adventures-open')")
    mia.page.wait_for_selector("#adventure-list[open]")
    cards = mia.js("() => [...document.querySelectorAll('.adventure-card')]"
                   ".map(e => e.dataset.adventure)")  # fmt: skip
    assert len(cards) == 6 and SQUARE in cards
    if AXE.exists():
        assert axe_violations(mia) == [], "the list of adventures"
    _tap(mia, f"document.querySelector('[data-adventure=\"{SQUARE}\"]')")
    mia.wait_state("open", f"{SQUARE}.root")
    mia.wait_state("adventure", SQUARE)
    goal = "Draw a square: four sides, all the same."
    assert mia.js("() => document.getElementById('adventure-picture').alt") == goal
    assert mia.js("() => window.spoken.at(-1)") == [goal, "en"]  # said aloud at Level 1
    assert (level_1_class.folder / "Mia" / f"{SQUARE}.root").is_file()  # the starter, hers
    # the starter checked: a hint, in the child's terms, said aloud too
    _tap(mia, "document.getElementById('check')")
    mia.wait_state("checked", "failed")
    hint = "Your drawing has 3 sides, but the goal's has 4."
    assert mia.js("() => document.getElementById('check-said').textContent") == hint
    assert mia.js("() => window.spoken.at(-1)") == [hint, "en"]
    assert mia.js("() => document.getElementById('adventure-next').hidden")
    if AXE.exists():
        assert axe_violations(mia) == [], "an adventure's goal and its hint"
    # fixed with the number key of the picture block's loop, run, checked: done
    _pick_number(mia, "pic_repeat", "4")
    assert "repeat 4\n" in mia.text()
    mia.run()
    assert mia.wait_ended() == "finished"
    _tap(mia, "document.getElementById('check')")
    mia.wait_state("checked", "passed")
    assert mia.js("() => document.getElementById('check-said').textContent") == (
        "Well done: your robot did it!"
    )
    mia.wait_state("adventuresPassed", SQUARE)
    # the teacher's page: Mia has done the square (kept in her folder for next time)
    miss.wait_state("adventures", f"Mia:{SQUARE}=passed")
    row = miss.js("() => [...document.querySelectorAll('#progress tr')].at(-1).textContent")
    assert row.startswith("Mia") and row.endswith("1 / 6")
    assert '"04-draw-a-square": true' in (level_1_class.folder / "Mia" / PROGRESS_FILE).read_text()
    # on to the next one, by the keyboard
    mia.page.focus("#adventure-next")
    mia.page.keyboard.press("Enter")
    mia.wait_state("adventure", "05-traffic-light")
    assert mia.state()["checked"] == ""  # (the square's "passed" is not the next one's)
    # "Draw a line": built on by a finger, the pen dragged from the toolbox into the script
    _tap(mia, "document.getElementById('adventures-open')")
    mia.page.wait_for_selector("#adventure-list[open]")
    _tap(mia, "document.querySelector('[data-adventure=\"03-draw-a-line\"]')")
    mia.wait_state("adventure", "03-draw-a-line")
    _drag_from_toolbox(mia, "✎", "pic_pen_down", _below(mia, "pic_when_started", "BODY"))
    assert mia.text() == "when started\n    marker down\n    move forward 45 cm\n"
    _tap(mia, "document.getElementById('check')")
    mia.wait_state("checked", "passed")
    miss.wait_state("adventures", f"Mia:{SQUARE}=passed+03-draw-a-line=passed")
    # the list by the keyboard: it opens on its first adventure, Escape closes it
    mia.page.focus("#adventures-open")
    mia.page.keyboard.press("Enter")
    mia.page.wait_for_selector("#adventure-list[open]")
    assert mia.js("() => document.activeElement.dataset.adventure") == "01-go-forward"
    mia.page.keyboard.press("Escape")
    mia.page.wait_for_selector("#adventure-list:not([open])", state="attached")
    for page in (mia, miss):
        assert page.outside == [] and page.errors == []
        page.close()


def _click_number(page: Page, block_type: str, number: str) -> None:
    """A mouse's click on a picture block's number, then on the number's big key."""
    field = f"Blockly.getMainWorkspace().getBlocksByType('{block_type}')[0].getField('N')"
    box = page.js(f"() => {{ const r = {field}.getSvgRoot().getBoundingClientRect();"
                  " return [r.left + r.width / 2, r.top + r.height / 2]; }")  # fmt: skip
    page.page.mouse.click(*box)
    page.page.click(f".blocklyMenuItem img[alt='{number}']")
    page.wait_state("blocksSynced", "yes")


def test_a_child_at_home_takes_adventures_and_their_progress_stays_in_the_folder(
    browser: Any, studio: RunningStudio
) -> None:
    """The one-person studio (no class): the same adventures, Check, hints and Next; what the
    child has passed kept in the studio's folder for the next day."""
    child = Page(browser, studio)
    child.page.add_init_script(LISTEN)
    child.page.goto(f"{studio.address}/?level=1&open=square.root")
    child.wait_state("ready", "yes")
    child.page.wait_for_selector("#adventures-open")
    assert child.js("() => document.getElementById('check').hidden")  # (not an adventure's)
    child.page.click("#adventures-open")
    child.page.wait_for_selector("#adventure-list[open]")
    cards = child.js("() => [...document.querySelectorAll('.adventure-card')]"
                     ".map(e => e.dataset.adventure)")  # fmt: skip
    assert cards[0] == "01-go-forward" and len(cards) == 6
    child.page.click(".adventure-card[data-adventure='01-go-forward']")
    child.wait_state("adventure", "01-go-forward")
    goal = "Go forward three robot lengths, to the green ring."
    assert child.js("() => document.getElementById('adventure-goal').textContent") == goal
    assert child.js("() => window.spoken.at(-1)") == [goal, "en"]
    assert (studio.folder / "01-go-forward.root").is_file()  # the starter, in the folder
    child.page.click("#check")
    child.wait_state("checked", "failed")
    hint = child.js("() => document.getElementById('check-said').textContent")
    assert "short" in hint and child.js("() => window.spoken.at(-1)") == [hint, "en"]
    _click_number(child, "pic_forward", "3")
    assert child.text() == "when started\n    move forward 45 cm\n"
    child.page.click("#check")
    child.wait_state("checked", "passed")
    kept = json.loads((studio.folder / PROGRESS_FILE).read_text(encoding="utf-8"))
    assert kept == {"01-go-forward": True}
    child.page.click("#adventure-next")
    child.wait_state("adventure", "02-round-the-corner")
    # the next day: the page opens again, the first adventure shows as done
    child.page.goto(f"{studio.address}/?level=1")
    child.wait_state("ready", "yes")
    child.page.wait_for_selector("#adventures-open")
    child.page.focus("#adventures-open")
    child.page.keyboard.press("Enter")
    child.page.wait_for_selector("#adventure-list[open]")
    card = "document.querySelector('.adventure-card[data-adventure=\"01-go-forward\"]')"
    child.page.wait_for_function(f"() => {card}.getAttribute('aria-label') === 'Go forward: done'")
    assert child.outside == [] and child.errors == []
    child.close()
