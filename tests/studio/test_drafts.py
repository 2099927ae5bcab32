"""Nothing changes a program behind the child's back, and nothing the child did is lost: edits
not saved yet are kept in the browser within half a second of the first one (steady typing
too), one draft per tab, so two tabs on one program never drop each other's; a tab that is gone
leaves its drafts to the next tab that opens the program; a Save refused because the file was
saved from elsewhere offers "Keep mine as a new program"; a link to a program the folder does
not have makes it, and with no program open the page takes no typing."""

from __future__ import annotations

import time
from pathlib import Path
from typing import Any

import pytest

from rootlang.locale.blocks import studio_strings
from rootlang.locale.keywords import LANGUAGES
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages

from .browser import CHROMIUM, Page
from .conftest import RunningStudio

in_chromium = pytest.mark.skipif(
    not CHROMIUM.exists(), reason="needs Debian's chromium at /usr/bin/chromium"
)
# The drafts this browser keeps (drafts.js): key -> the draft's JSON
DRAFTS = """() => Object.fromEntries(Object.keys(localStorage)
    .filter(key => key.startsWith('rootlang.draft'))
    .map(key => [key, JSON.parse(localStorage.getItem(key))]))"""


def _drafts(tab: Page) -> dict[str, dict[str, Any]]:
    found: dict[str, dict[str, Any]] = tab.js(DRAFTS)
    return found


def _save(tab: Page) -> None:
    saves = int(tab.state().get("saves", "0"))
    tab.page.click("#save")
    tab.wait_state("saves", str(saves + 1))


def _out_of_reach(tab: Page) -> None:
    """The studio never gets this tab's saves: its network has gone (the browser's own offline
    mode, for this tab alone). Not a route that aborts them: a save the test's route had not
    answered yet went through as its tab closed, and the studio had it."""
    devtools = tab.page.context.new_cdp_session(tab.page)
    devtools.send("Network.enable")
    devtools.send(
        "Network.emulateNetworkConditions",
        {"offline": True, "latency": 0, "downloadThroughput": -1, "uploadThroughput": -1},
    )


@in_chromium
def test_steady_typing_is_kept_in_the_browser_without_a_pause(
    page: Page, studio: RunningStudio
) -> None:
    """The child types on and on and the tab crashes right after a key: what was typed up to
    half a second before is back when the program opens again. (Before, a draft was written
    only half a second after the last key, so steady typing kept nothing: this test failed.)"""
    page.open("square.root")
    original = page.text()
    page.type_at_the_end("\n# ")
    typed = ""
    letters = "abcdefghijklmnopqrstuvwxyz"

    def type_until(kept: Any) -> dict[str, Any]:
        """Types a key at a time, never pausing, until a draft that ``kept`` accepts is kept."""
        nonlocal typed
        deadline = time.monotonic() + 20  # (it takes half a second; this only ends a failure)
        while time.monotonic() < deadline:
            letter = letters[len(typed) % len(letters)]
            page.page.keyboard.press(letter)
            typed += letter
            drafts = list(_drafts(page).values())
            if drafts and kept(drafts[0]):
                return drafts[0]
        raise AssertionError(f"no draft kept while {len(typed)} keys were typed without a pause")

    first = type_until(lambda draft: True)
    assert first["text"].startswith(original + "\n# ")
    # steady typing goes on being kept (at least every half second), not only once
    second = type_until(lambda draft: len(draft["text"]) > len(first["text"]))
    page.page.keyboard.press("z")  # the last key, and the tab is gone at once
    typed += "z"
    page.closed_and_opened_again()
    page.open("square.root")
    back = page.text().rstrip("\n")  # (a save by itself may have written it canonically)
    assert (original + "\n# " + typed).startswith(back)
    assert len(back) >= len(second["text"])
    assert "not saved yet are back" in page.page.locator("#status").inner_text()


@in_chromium
def test_two_tabs_on_one_program_never_drop_each_others_draft(
    page: Page, studio: RunningStudio
) -> None:
    """One program in two tabs of one browser: the second tab's edits are kept as its own
    draft, which the first tab's edits and Save leave alone; the second tab crashes, and the
    next tab that opens the program gets its edits back, next to the first tab's saved file.
    (Before, both tabs kept one draft per program, and the first tab's Save dropped it: this
    test failed.)"""
    first = page.open("square.root")
    second = first.another_tab().open("square.root")
    _out_of_reach(second)  # (its saves never arrive: only its draft keeps its work)
    second.type_at_the_end('\nwhen touched\n    say "second"')
    second.wait_state("draft", "square.root")
    first.type_at_the_end('\nwhen touched\n    say "first"')
    first.wait_state("draft", "square.root")
    _save(first)
    saved = (studio.folder / "square.root").read_text(encoding="utf-8")
    assert 'say "first"' in saved and 'say "second"' not in saved
    assert any('say "second"' in draft["text"] for draft in _drafts(first).values())
    second.closed_and_opened_again()  # the second tab crashes
    second.open("square.root")
    kept = studio.folder / "square not saved.root"
    assert 'say "second"' in kept.read_text(encoding="utf-8")  # back, as a program of its own
    assert "square not saved.root" in second.page.locator("#status").inner_text()
    assert (studio.folder / "square.root").read_text(encoding="utf-8") == saved
    assert not any('say "second"' in draft["text"] for draft in _drafts(first).values())
    for tab in (first, second):
        assert tab.outside == [] and tab.errors == []
    second.page.close()


@in_chromium
def test_every_draft_a_gone_tab_left_comes_back(page: Page, studio: RunningStudio) -> None:
    """Two tabs edit one program and both are gone before they could save: the next tab to
    open it gets both back, the newer on the page and the other as a program of its own; a
    live tab's draft is left to it."""
    first = page.open("square.root")
    second = first.another_tab().open("square.root")
    third = first.another_tab().open("square.root")
    for tab, said in ((first, "one"), (second, "two"), (third, "three")):
        _out_of_reach(tab)
        tab.type_at_the_end(f'\nwhen touched\n    say "{said}"')
        tab.wait_state("draft", "square.root")
    first.closed_and_opened_again()
    second.gone()
    first.open("square.root")
    assert 'say "two"' in first.text()  # the newest gone tab's, on the page
    kept = studio.folder / "square not saved.root"
    assert 'say "one"' in kept.read_text(encoding="utf-8")
    assert not (studio.folder / "square not saved 2.root").exists()  # the third tab lives
    assert any('say "three"' in draft["text"] for draft in _drafts(first).values())
    third.page.close()


@in_chromium
def test_a_save_refused_for_a_changed_file_offers_to_keep_mine_as_a_new_program(
    page: Page, studio: RunningStudio
) -> None:
    """E819 names a button the page has: Keep mine as a new program saves what the page shows
    under a fresh name and opens it; the file the other tab saved stays as it is. (Before, the
    message advised saving under another name, which no button did: this test failed.)"""
    first = page.open("square.root")
    second = first.another_tab().open("square.root")
    (studio.folder / "square mine.root").write_text("# taken\n", encoding="utf-8")
    first.type_at_the_end('\nwhen touched\n    say "first"')
    _save(first)
    saved = (studio.folder / "square.root").read_text(encoding="utf-8")
    second.type_at_the_end('\nwhen touched\n    say "second"')
    second.page.click("#save")
    second.page.wait_for_selector("#keep-mine", state="visible")
    told = second.page.locator("#status").inner_text()
    label = second.page.locator("#keep-mine").inner_text()
    assert label == "Keep mine as a new program" and label in told
    second.page.click("#keep-mine")
    second.wait_state("open", "square mine 2.root")  # (a name nobody has: "square mine" is taken)
    mine = (studio.folder / "square mine 2.root").read_text(encoding="utf-8")
    assert 'say "second"' in mine and 'say "first"' not in mine
    assert second.text() == mine and 'say "second"' in second.text()
    assert (studio.folder / "square.root").read_text(encoding="utf-8") == saved
    assert (studio.folder / "square mine.root").read_text(encoding="utf-8") == "# taken\n"
    assert "square mine 2.root" in second.page.locator("#status").inner_text()
    assert not second.page.locator("#keep-mine").is_visible()
    assert second.state()["unsaved"] == ""
    for tab in (first, second):
        assert tab.outside == [] and tab.errors == []
    second.page.close()


@pytest.mark.parametrize("language", LANGUAGES)
def test_e819_names_the_button_the_page_has_in_every_language(language: str) -> None:
    said = message("E819", {"name": "square.root"}, Languages(chosen=language))
    assert studio_strings(language)["keep_mine"] in said


@in_chromium
def test_a_link_to_a_program_the_folder_does_not_have_makes_it(
    page: Page, studio: RunningStudio
) -> None:
    """``?open=dance.root`` for a program the child's folder does not have: the page makes it
    (the starter, as New does) and opens it, so what the child types is saved. (Before, the page
    took typing and blocks, and saved and kept none of it: this test failed.)"""
    page.open("dance.root")
    made = studio.folder / "dance.root"
    assert made.read_text(encoding="utf-8") == page.text()
    assert "made it for you" in page.page.locator("#status").inner_text()
    page.type_at_the_end('\nwhen touched\n    say "mine"')
    page.wait_state("unsaved", "yes")
    page.wait_state("unsaved", "")  # (saved by itself)
    assert 'say "mine"' in made.read_text(encoding="utf-8")


@in_chromium
def test_with_no_program_open_the_page_takes_no_typing(browser: Any, tmp_path: Path) -> None:
    """An empty folder: the page says to press New, and the text takes no typing (it would be
    kept nowhere)."""
    empty = tmp_path / "empty"
    empty.mkdir()
    running = RunningStudio(empty).start()
    try:
        opened = Page(browser, running)
        opened.page.goto(running.address + "/")
        opened.wait_state("ready", "yes")
        assert "New" in opened.page.locator("#status").inner_text()
        opened.type_at_the_end("when started")
        assert opened.text() == ""
        assert opened.js("() => Blockly.getMainWorkspace().isReadOnly()") is True
        assert opened.outside == [] and opened.errors == []
    finally:
        running.stop()
