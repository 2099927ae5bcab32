"""Levels in real Chromium on a tablet, by a finger: a child who can't read builds "draw a
square" from Level 1's picture blocks alone (CDP touch drags, number buttons tapped), runs
it, hears what blocks mean, opens the same program at Level 2 and 3 and back; a line with no
picture keeps the program above Level 1, marked on its block in the page's language."""

from __future__ import annotations

from typing import Any

from .browser import Page
from .conftest import RunningStudio
from .test_child_sees import _touch_drag

BLOCKS = "Blockly.getMainWorkspace()"
SQUARE = (
    "when started\n"
    "    marker down\n"
    "    repeat 4\n"
    "        move forward 15 cm\n"
    "        turn right 90 degrees\n"
)
# What the page says aloud: kept by the test (a headless browser has no voices)
LISTEN = """
window.spoken = [];
if (window.speechSynthesis) speechSynthesis.speak = u => window.spoken.push([u.text, u.lang]);
"""


def _tap(page: Page, script: str) -> None:
    """A finger's tap on the middle of what ``script`` (JavaScript, an element) names."""
    box = page.js(f"() => {{ const r = ({script}).getBoundingClientRect();"
                  " return [r.left + r.width / 2, r.top + r.height / 2]; }")  # fmt: skip
    page.page.touchscreen.tap(*box)


def _screen(connection: str) -> str:
    """JavaScript: where a block connection is on the screen, as [x, y]."""
    return (f"(() => {{ const c = {connection}; const p = Blockly.utils.svgMath"
            f".wsToScreenCoordinates(c.getSourceBlock().workspace, new Blockly.utils.Coordinate"
            f"(c.x, c.y)); return [p.x, p.y]; }})()")  # fmt: skip


def _drag_from_toolbox(page: Page, sign: str, block_type: str, to: tuple[float, float]) -> None:
    """Opens the toolbox category named by ``sign`` and drags its ``block_type`` block by a
    finger so that its top (its previous connection, or a hat's corner) lands at ``to``."""
    _tap(page, f"[...document.querySelectorAll('.blocklyToolboxCategory')]"
               f".find(e => e.textContent.trim() === '{sign}')")  # fmt: skip
    page.page.wait_for_function(f"() => {BLOCKS}.getFlyout().isVisible()")
    flyout = f"{BLOCKS}.getFlyout().getWorkspace().getBlocksByType('{block_type}')[0]"
    corner = "(r => [r.left, r.top])(b.getSvgRoot().getBoundingClientRect())"  # a hat's
    top_of = f"b.previousConnection ? {_screen('b.previousConnection')} : {corner}"
    top = page.js(f"async () => {{ await Blockly.renderManagement.finishQueuedRenders();"
                  f" const b = {flyout}; return {top_of}; }}")  # fmt: skip
    grab = (top[0] + 10, top[1] + 12)
    before = page.js(f"() => {BLOCKS}.getAllBlocks(false).length")
    _touch_drag(page, grab, (to[0] + 10, to[1] + 12))
    page.page.wait_for_function(f"() => {BLOCKS}.getAllBlocks(false).length > {before}")
    page.wait_state("blocksSynced", "yes")


def _below(page: Page, block_type: str, where: str = "next") -> tuple[float, float]:
    """Where a block dropped under the live ``block_type`` block goes (in its body: "BODY")."""
    live = f"{BLOCKS}.getBlocksByType('{block_type}')[0]"
    connection = (
        f"{live}.nextConnection" if where == "next" else f"{live}.getInput('{where}').connection"
    )
    spot: list[float] = page.js(
        f"async () => {{ await Blockly.renderManagement.finishQueuedRenders();"
        f" return {_screen(connection)}; }}"
    )
    return spot[0], spot[1]


def _pick_number(page: Page, block_type: str, number: str) -> None:
    _tap(page, f"{BLOCKS}.getBlocksByType('{block_type}')[0].getField('N').getSvgRoot()")
    page.page.wait_for_selector(".blocklyMenuItem")
    _tap(page, f"[...document.querySelectorAll('.blocklyMenuItem img')]"
               f".find(e => e.alt === '{number}')")  # fmt: skip
    page.page.wait_for_function(  # (the text follows a moment after)
        "n => document.querySelector('.CodeMirror').CodeMirror.getValue().includes(` ${n}\\n`)",
        arg=number,
    )
    page.wait_state("blocksSynced", "yes")


def _types(page: Page) -> list[str]:
    found: list[str] = page.js(f"() => {BLOCKS}.getAllBlocks(true).map(b => b.type)")
    return found


def test_a_pre_reader_draws_a_square_with_picture_blocks_and_sees_it_at_every_level(
    tablet: Page, studio: RunningStudio
) -> None:
    (studio.folder / "mine.root").write_text("", encoding="utf-8")
    tablet.page.add_init_script(LISTEN)
    tablet.page.goto(f"{studio.address}/?open=mine.root&level=1")
    tablet.wait_state("ready", "yes")
    assert tablet.state()["level"] == "1"
    assert tablet.js("() => document.getElementById('text-pane').offsetParent === null")
    # the toolbox: picture blocks only, numbers the only words on them
    categories = tablet.js("""() => [...document.querySelectorAll('.blocklyToolboxCategory')]
        .map(e => e.textContent.trim())""")
    assert categories == ["⚑", "⬆", "✎", "☀", "♪", "⟳"]
    _drag_from_toolbox(tablet, "⚑", "pic_when_started", (200, 250))
    _drag_from_toolbox(tablet, "✎", "pic_pen_down", _below(tablet, "pic_when_started", "BODY"))
    _drag_from_toolbox(tablet, "⟳", "pic_repeat", _below(tablet, "pic_pen_down"))
    _drag_from_toolbox(tablet, "⬆", "pic_forward", _below(tablet, "pic_repeat", "BODY"))
    _drag_from_toolbox(tablet, "⬆", "pic_turn_right", _below(tablet, "pic_forward"))
    _pick_number(tablet, "pic_repeat", "4")
    assert tablet.text() == SQUARE
    assert all(kind.startswith("pic_") for kind in _types(tablet))
    # a block touched says what it does, aloud and in words for the grown-ups
    _tap(tablet, f"{BLOCKS}.getBlocksByType('pic_forward')[0].pathObject.svgPath")
    assert tablet.state()["said"] == "Go forward 1 robot length"
    assert tablet.js("() => document.getElementById('level-says').textContent") == (
        "Go forward 1 robot length"
    )
    assert tablet.js("() => window.spoken.at(-1)") == ["Go forward 1 robot length", "en"]
    _tap(tablet, "[...document.querySelectorAll('.blocklyToolboxCategory')]"
                 ".find(e => e.textContent.trim() === '☀')")  # fmt: skip
    tablet.page.wait_for_function(f"() => {BLOCKS}.getFlyout().isVisible()")
    light = tablet.js(f"""() => {{  // (a mouse pointing at it, on a tablet with a mouse)
        const r = {BLOCKS}.getFlyout().getWorkspace().getBlocksByType('pic_light')[0]
            .pathObject.svgPath.getBoundingClientRect();
        return [r.left + 10, r.top + r.height / 2];
    }}""")
    tablet.page.mouse.move(*light)
    assert tablet.js("() => window.spoken.at(-1)") == ["Light: red", "en"]  # (in the toolbox)
    # a number is a key as big as a finger (its digits 4.5:1: tests/blocks/test_pictures.py)
    key = tablet.js(f"""() => {{
        const r = {BLOCKS}.getBlocksByType('pic_repeat')[0].getField('N').getSvgRoot()
            .getBoundingClientRect();
        return [r.width, r.height];
    }}""")
    assert min(key) >= 44, key
    start = tablet.state()
    tablet.run()
    assert tablet.wait_ended() == "finished"
    end = tablet.state()
    assert int(end["strokes"]) >= 1  # drawn, round a square, back where it started
    assert abs(float(end["x"]) - float(start["x"])) < 5 and abs(float(end["h"]) - 90) < 2
    # the same program at Level 2, 3 and back: the text as it was, byte for byte
    _tap(tablet, "document.getElementById('level-2')")
    tablet.wait_state("level", "2")
    assert not any(kind.startswith("pic_") for kind in _types(tablet))
    assert "root_move_direction" in _types(tablet) and tablet.text() == SQUARE
    _tap(tablet, "document.getElementById('level-3')")
    tablet.wait_state("level", "3")
    assert tablet.js("() => document.getElementById('blocks-pane').offsetParent === null")
    assert tablet.text() == SQUARE
    _tap(tablet, "document.getElementById('level-1')")
    tablet.wait_state("level", "1")
    assert sorted(_types(tablet)) == sorted(
        ["pic_when_started", "pic_pen_down", "pic_repeat", "pic_forward", "pic_turn_right"]
    )
    assert tablet.text() == SQUARE


def test_a_line_with_no_picture_keeps_the_program_up_and_says_which(
    tablet: Page, studio: RunningStudio
) -> None:
    text = "when started\n    move forward 10 cm\n    turn right 90 degrees\n"
    (studio.folder / "mixed.root").write_text(text, encoding="utf-8")
    tablet.page.goto(f"{studio.address}/?open=mixed.root&level=3&language=nl")
    tablet.wait_state("ready", "yes")
    _tap(tablet, "document.getElementById('level-1')")
    tablet.wait_state("keptUp", "L2")
    assert tablet.state()["level"] == "2"  # shown as words: Level 1 can't, the block says why
    warning: Any = tablet.js(
        "async () => (await import('/static/blocks.js')).liveBlock('L2').getIcon('warning')"
        ".getText()"
    )
    assert "geen plaatje" in warning  # (a Dutch page says it in Dutch)
    assert tablet.text() == text
