"""Pausing a run in the studio, in a real headless browser with real clicks and keys: a
breakpoint put on a block inside `repeat` from the block's menu, Run, the run paused there with
the loop's round and a variable in the Watch panel and the line lit; Step twice moves the light
through the scripts in the scheduler's order; Resume lets it end."""

from __future__ import annotations

from pathlib import Path

from playwright.sync_api import expect

from .browser import BLOCK, Page
from .test_debugging import PROGRAM


def _watch(page: Page) -> list[str]:
    lines: list[str] = page.page.locator("#watch-lines li").all_inner_texts()
    return lines


def test_a_breakpoint_on_a_block_in_a_loop_then_step_twice_and_resume(
    page: Page, class_folder: Path
) -> None:
    (class_folder / "debug.root").write_text(PROGRAM, encoding="utf-8")
    page.open("debug.root")
    move = page.drawn(f"(await {BLOCK}('L4')).getSvgRoot()")
    page.page.mouse.click(move["x"] + 12, move["y"] + 10, button="right")  # the block's own menu
    page.page.get_by_text("Stop here (breakpoint)").click()
    # (Blockly runs a menu item's action after the menu has closed: wait for its mark)
    expect(page.page.locator(".CodeMirror .breakpoint")).to_have_count(1)
    assert page.js("async () => (await import('/static/debugger.js')).breakpointLines()") == [4]

    assert page.page.locator("#pause").is_hidden()  # (no run: no room taken in the toolbar)
    page.run(speed="0")
    page.wait_state("paused", "4")
    watch = _watch(page)
    assert watch[0] == "`when started`: about to do `move size` (line 4)"
    assert "size = 5 cm (in `when started`)" in watch
    assert "The loop on line 3 is in round 1 of 3." in watch
    assert "paused-line" in page.js(
        "() => document.querySelector('.CodeMirror').CodeMirror.lineInfo(3).bgClass"
    )
    assert page.page.locator("#pause").is_disabled() and page.page.locator("#resume").is_enabled()

    page.page.click("#step")  # the other script's first line: it takes its turn
    page.wait_state("paused", "4,9")
    assert _watch(page)[1] == "`when started`: about to do `wait 0.5 seconds` (line 9)"
    page.page.keyboard.press("Enter")  # Step again, from the keyboard (the focus stayed there)
    page.wait_state("paused", "4,10")
    assert _watch(page)[1] == '`when started`: about to do `print "tick"` (line 10)'
    assert page.page.evaluate("() => document.activeElement.id") == "step"

    page.page.locator(".CodeMirror-gutter-elt .breakpoint").click()  # the breakpoint off
    page.page.click("#resume")
    assert page.wait_ended() == "finished"
    assert page.state()["paused"] == ""
    assert page.page.locator("#pause").is_hidden() and page.page.locator("#step").is_hidden()


LABEL = "() => document.activeElement.getAttribute('aria-label') || ''"


def test_a_breakpoint_from_the_block_menu_by_keys_shows_on_the_block_and_outlasts_save_and_reload(
    page: Page, class_folder: Path
) -> None:
    """Real keys only: Tab onto the blocks, arrows to the `move` block inside `repeat`,
    Shift+F10 opens its menu, Enter on *Stop here*: a red dot on the block (not only in the
    text's margin). A Save that spells the program canonically (its lines rewritten) and a
    reload keep it on its statement, and the run pauses there; the block deleted, it goes."""
    spaced = PROGRAM.replace("set size to", "set size  to").replace('print "done"', 'print  "done"')
    (class_folder / "keys.root").write_text(spaced, encoding="utf-8")
    page.open("keys.root")
    page.page.focus("#run")
    seen = []
    for _ in range(12):  # Tab onto the workspace of blocks
        page.page.keyboard.press("Tab")
        seen.append(page.js(LABEL))
        if "stacks of blocks" in seen[-1]:
            break
    for _ in range(12):  # down the blocks to the move in the loop
        page.page.keyboard.press("ArrowDown")
        seen.append(page.js(LABEL))
        if seen[-1].startswith("move"):
            break
    assert seen[-1].startswith("move"), seen
    page.page.keyboard.press("Shift+F10")  # the block's menu, from the keyboard
    item = page.page.locator(".blocklyContextMenu .blocklyMenuItemHighlight")
    expect(item).to_have_text("Stop here (breakpoint)")
    page.page.keyboard.press("Enter")
    expect(page.page.locator(".CodeMirror .breakpoint")).to_have_count(1)
    _marked_on_line_4(page)

    page.page.click("#save")
    page.wait_state("saves", "1")
    assert "set size to 5 cm" in page.text() and 'print "done"' in page.text()  # rewritten
    _marked_on_line_4(page)

    page.page.reload()
    page.wait_state("ready", "yes")
    page.wait_state("open", "keys.root")
    _marked_on_line_4(page)
    page.run(speed="0")
    page.wait_state("paused", "4")
    page.page.click("#stop")
    assert page.wait_ended() == "stopped"

    # a block deleted takes its breakpoint with it; another one stays on its statement
    page.js("async () => (await import('/static/debugger.js')).toggle(9)")  # `wait 0.5 seconds`
    move = page.drawn(f"(await {BLOCK}('L4')).getSvgRoot()")
    page.page.mouse.click(move["x"] + 12, move["y"] + 10)
    page.page.keyboard.press("Delete")
    page.page.wait_for_function("() => !document.querySelector('.CodeMirror')"
                                ".CodeMirror.getValue().includes('move size')")  # fmt: skip
    expect(page.page.locator(".root-breakpoint-dot")).to_have_count(1)
    assert page.js("async () => (await import('/static/debugger.js')).breakpointLines()") == [8]


def _marked_on_line_4(page: Page) -> None:
    """The breakpoint on line 4, and its mark on line 4's block: a red dot, drawn."""
    expect(page.page.locator(".root-breakpoint-dot")).to_have_count(1)
    assert page.js("async () => (await import('/static/debugger.js')).breakpointLines()") == [4]
    dot = page.drawn(f"(await {BLOCK}('L4')).getSvgRoot().querySelector('.root-breakpoint-dot')")
    assert dot["w"] > 5 and dot["h"] > 5


def test_a_long_press_on_a_block_on_a_tablet_puts_a_breakpoint_on_it(
    tablet: Page, class_folder: Path
) -> None:
    """A finger held on a block (no mouse, no right button) opens the block's menu, as on a
    tablet; a tap on its item puts the breakpoint there."""
    (class_folder / "debug.root").write_text(PROGRAM, encoding="utf-8")
    tablet.open("debug.root")
    tablet.page.click("#tab-blocks")
    move = tablet.drawn(f"(await {BLOCK}('L4')).getSvgRoot()")
    cdp = tablet.page.context.new_cdp_session(tablet.page)
    finger = [{"x": move["x"] + 12, "y": move["y"] + 10, "id": 1, "radiusX": 4, "radiusY": 4}]
    cdp.send("Input.dispatchTouchEvent", {"type": "touchStart", "touchPoints": finger})
    item = tablet.page.get_by_text("Stop here (breakpoint)")
    item.wait_for()  # (the menu opens while the finger is still down: Blockly's long press)
    cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
    cdp.detach()
    box = item.bounding_box()
    assert box is not None
    tablet.page.touchscreen.tap(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    expect(tablet.page.locator(".root-breakpoint-dot")).to_have_count(1)
    assert tablet.js("async () => (await import('/static/debugger.js')).breakpointLines()") == [4]
