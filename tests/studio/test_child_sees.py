"""What a child sees and hears, in real Chromium: the robot on the stage as soon as a program
opens, `play note` played through Web Audio (muted by the pupil, or by the teacher for the
class), `say` as a bubble by the robot, a status line that goes once its problem is fixed, a
Dutch page's New and colours in Dutch, and a tablet's controls big enough for a finger, with
a block dragged by touch (CDP touch events, as a finger makes them)."""

from __future__ import annotations

from typing import Any

import pytest

from rootlang.app.session import world_of
from rootlang.sim.robot import VirtualRobot

from .browser import BLOCK, Page
from .conftest import RunningStudio

BLOCKS = "Blockly.getMainWorkspace()"
FINGER_PX = 44


def _start_pose(studio: RunningStudio, name: str, world: str | None = None) -> tuple[int, int]:
    """Where a run of the program starts, as the simulator puts the robot (not the page)."""
    path = studio.folder / name
    frame = VirtualRobot(world_of(path, path.read_text(encoding="utf-8"), world)).recording
    first = frame.frames[-1]
    return first.x_mm, first.y_mm


def _colours_drawn(page: Page) -> int:
    counted: int = page.js("""() => {
        const canvas = document.getElementById('canvas');
        const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
        const seen = new Set();
        for (let i = 0; i < data.length; i += 16) {
            seen.add(data[i] << 16 | data[i + 1] << 8 | data[i + 2]);
        }
        return seen.size;
    }""")
    return counted


def test_the_robot_is_on_the_stage_before_any_run(page: Page, studio: RunningStudio) -> None:
    page.open("square.root")
    page.wait_state("stage", "start")
    state = page.state()
    assert (round(float(state["x"])), round(float(state["y"]))) == _start_pose(
        studio, "square.root"
    )
    assert _colours_drawn(page) > 3  # the world and the robot are drawn, not a blank canvas
    assert "ended" not in state or state["ended"] == ""  # (no run)
    # another world chosen: the robot where a run in it starts
    arena = _start_pose(studio, "square.root", "arena")
    page.page.select_option("#world", "arena")
    page.page.wait_for_function(
        "([x, y]) => { const s = document.getElementById('state').dataset;"
        " return s.stage === 'start' && Math.round(s.x) === x && Math.round(s.y) === y; }",
        arg=list(arena),
        timeout=15000,
    )


def test_notes_are_heard_said_words_are_a_bubble_and_mute_silences(
    page: Page, studio: RunningStudio
) -> None:
    program = 'when started\n    play note C5 for 0.2 seconds\n    say "hello there"\n'
    (studio.folder / "sing.root").write_text(program, encoding="utf-8")
    page.open("sing.root")
    assert page.state()["muted"] == "no"
    page.run(speed="2")
    assert page.wait_ended() == "finished"
    state = page.state()
    assert state["notes"] == "1" and state["lastNote"] == "523.0"  # C5 (whole Hz, as the robot)
    bubble = page.page.locator("#speech")
    assert bubble.is_visible() and bubble.inner_text() == "hello there"
    # the bubble is by the robot: its tail above the robot's centre on the canvas
    robot_x: float = page.js("""() => {
        const s = document.getElementById('state').dataset;
        return Number(s.bubbleX);
    }""")
    box = bubble.bounding_box()
    canvas = page.page.locator("#canvas").bounding_box()
    assert box is not None and canvas is not None
    assert box["x"] - canvas["x"] <= robot_x <= box["x"] - canvas["x"] + box["width"] + 1
    # the pupil mutes: the next run's note is not played
    assert _sign(page, "#mute") == ("sound-on", "Sound", "Sound: Mute the robot's sounds")
    page.page.click("#mute")
    page.wait_state("muted", "yes")
    assert _sign(page, "#mute") == ("sound-off", "Muted", "Muted: Let the robot's sounds be heard")
    assert page.js(f"() => {EMOJI}.test(document.body.innerText)") is False
    page.run(speed="2")
    assert page.wait_ended() == "finished"
    assert page.state()["notes"] == "1"
    page.page.click("#mute")  # (kept in this browser: back as it was)
    page.wait_state("muted", "no")


# an emoji: many school computers (and headless Chromium) have no font for it (an empty box)
EMOJI = r"/[\u{1F000}-\u{1FAFF}\u{FE0F}]/u"


def _sign(page: Page, button: str) -> tuple[str, str, str]:
    """A button's sign (drawn: an SVG the size of its words), its words and its name."""
    drawn: dict[str, Any] = page.js(f"""() => {{
        const button = document.querySelector('{button}'), sign = button.querySelector('svg.sign');
        const r = sign.getBoundingClientRect();
        return {{sign: sign.dataset.sign, size: Math.min(r.width, r.height),
                 shapes: sign.querySelectorAll('path').length,
                 text: button.innerText.trim(), label: button.getAttribute('aria-label')}};
    }}""")
    assert drawn["size"] >= 14 and drawn["shapes"] == 2
    return drawn["sign"], drawn["text"], drawn["label"]


def test_the_status_line_goes_once_its_problem_is_fixed(page: Page) -> None:
    page.open("square.root")
    page.type_at_the_end("\nwhen started\n    mvoe 10 cm")
    page.page.wait_for_function(
        "() => Number(document.getElementById('state').dataset.errors) > 0", timeout=15000
    )
    page.page.click("#run")
    page.wait_state("statusAbout", "mistakes")
    assert page.page.locator("#status").inner_text() == "Fix the mistakes first (they are marked)."
    page.page.click(".CodeMirror")  # (the click on Run took the keyboard)
    page.page.keyboard.press("Control+End")
    for _ in "mvoe 10 cm":
        page.page.keyboard.press("Backspace")
    page.page.keyboard.type("move 10 cm")
    page.wait_state("statusAbout", "")
    assert page.page.locator("#status").inner_text() == "Ready."


def test_new_on_a_dutch_page_is_dutch_and_coloured_in_dutch(
    page: Page, studio: RunningStudio
) -> None:
    page.open("square.root", language="nl")
    page.page.once("dialog", lambda dialog: dialog.accept("dans"))
    page.page.click("#new")
    page.wait_state("open", "dans.root")
    text = page.text()
    assert "# language: nl\nwanneer gestart\n" in text and "herhaal 4" in text
    assert text.startswith("# dans.root: mijn eerste programma") and '"Ik heb een vierkant' in text
    assert (studio.folder / "dans.root").read_text(encoding="utf-8") == text
    page.wait_state("errors", "0")  # it is a program, as the English starter is
    coloured = page.js("""() => Object.fromEntries(['keyword', 'def', 'builtin', 'atom', 'number']
        .map(kind => [kind, [...document.querySelectorAll('.CodeMirror .cm-' + kind)]
                              .map(e => e.textContent.trim())]))""")
    assert {"wanneer", "herhaal"} <= set(coloured["keyword"])
    assert "gestart" in coloured["def"]
    assert {"beweeg", "draai"} <= set(coloured["builtin"])
    assert "groen" in coloured["atom"]
    assert "10 cm" in coloured["number"]


# --- a tablet -------------------------------------------------------------------------------------


def test_every_control_is_big_enough_for_a_finger(tablet: Page, studio: RunningStudio) -> None:
    program = 'when started\n    print "a", "b"\n    turn right 90 degrees\n'
    (studio.folder / "values.root").write_text(program, encoding="utf-8")
    tablet.open("values.root")
    assert tablet.js("() => matchMedia('(pointer: coarse)').matches")
    small = tablet.js(f"""() => [...document.querySelectorAll('button, select')]
        .filter(e => e.offsetParent !== null)
        .map(e => [e.id || e.textContent.trim(), e.getBoundingClientRect()])
        .filter(([, r]) => Math.round(r.width) < {FINGER_PX} || Math.round(r.height) < {FINGER_PX})
        .map(([name, r]) => name + ' ' + Math.round(r.width) + 'x' + Math.round(r.height))""")
    assert small == []
    buttons = tablet.js(f"""async () => {BLOCK}('L2').getInput('ROOT_TAIL').fieldRow
        .map(f => f.getSvgRoot().getBoundingClientRect())
        .map(r => [Math.round(r.width), Math.round(r.height)])""")
    assert len(buttons) == 2 and all(min(size) >= FINGER_PX for size in buttons), buttons
    categories = tablet.js("""() => [...document.querySelectorAll('.blocklyToolboxCategory')]
        .map(e => e.getBoundingClientRect().height)""")
    assert categories and round(min(categories)) >= FINGER_PX
    # a menu on a block, opened by a finger's tap: each choice as tall as a finger
    where = tablet.js(f"""async () => {{
        const field = {BLOCK}('L3').inputList.flatMap(i => i.fieldRow)
            .find(f => f instanceof Blockly.FieldDropdown);
        const r = field.getSvgRoot().getBoundingClientRect();
        return [r.left + r.width / 2, r.top + r.height / 2];
    }}""")
    tablet.page.touchscreen.tap(*where)
    tablet.page.wait_for_selector(".blocklyMenuItem")
    heights = tablet.js("""() => [...document.querySelectorAll('.blocklyMenuItem')]
        .map(e => e.getBoundingClientRect().height)""")
    assert heights and round(min(heights)) >= FINGER_PX  # (43.99998: a sub-pixel layout)


def _touch_drag(page: Page, start: tuple[float, float], end: tuple[float, float]) -> None:
    """A finger's drag, as the touch screen reports it (CDP touch events, not a mouse)."""
    cdp = page.page.context.new_cdp_session(page.page)

    def touch(kind: str, x: float, y: float) -> None:
        points = [] if kind == "touchEnd" else [{"x": x, "y": y, "id": 1, "radiusX": 4,
                                                  "radiusY": 4, "force": 1}]  # fmt: skip
        cdp.send("Input.dispatchTouchEvent", {"type": kind, "touchPoints": points})

    touch("touchStart", *start)
    for step in range(1, 16):
        f = step / 15
        touch("touchMove", start[0] + (end[0] - start[0]) * f, start[1] + (end[1] - start[1]) * f)
    touch("touchEnd", *end)
    cdp.detach()


def _box(page: Page, text_id: str) -> dict[str, float]:
    """Where the block the text's id names is drawn (its own path: not the blocks under it)."""
    return page.drawn(f"{BLOCK}('{text_id}').pathObject.svgPath")


def test_a_block_dragged_by_a_finger_out_and_back_loses_nothing(
    tablet: Page, studio: RunningStudio
) -> None:
    tablet.open("square.root")
    original = tablet.text()
    count = f"() => {BLOCKS}.getAllBlocks(false).length"
    blocks = tablet.js(count)
    said: str = tablet.js(f"async () => {BLOCK}('L8').id")
    box = _box(tablet, "L8")
    grab = (box["x"] + 8, box["y"] + box["h"] / 2)
    away = (grab[0] + 60, grab[1] + 200)  # (empty workspace below the script)
    _touch_drag(tablet, grab, away)
    tablet.wait_state("blocksSynced", "yes")
    tablet.wait_state("leftOut", "1")
    assert 'say "done"' not in tablet.text()  # out of the script: out of the text, kept
    assert tablet.js(f"() => !!{BLOCKS}.getBlockById('{said}')")
    # and back under the block it was under, by the same finger
    above = _box(tablet, "L7")
    loose = tablet.drawn(f"{BLOCKS}.getBlockById('{said}').pathObject.svgPath")
    start = (loose["x"] + 8, loose["y"] + loose["h"] / 2)
    _touch_drag(tablet, start, (above["x"] + 8, above["y"] + above["h"] * 1.5))
    tablet.wait_state("blocksSynced", "yes")
    tablet.wait_state("leftOut", "0")
    assert tablet.text() == original  # the text is as it was: nothing lost, nothing added
    assert tablet.js(count) == blocks
    assert tablet.js(f"() => {BLOCKS}.getBlockById('{said}').getParent() !== null")


@pytest.mark.parametrize("size", [(1024, 768), (768, 1024)], ids=["landscape", "portrait"])
def test_a_tablet_shows_the_blocks_or_the_text_with_room_and_the_stage_too(
    browser: Any, studio: RunningStudio, size: tuple[int, int]
) -> None:
    """On a tablet the blocks and the text take turns in one place (two tabs, tapped with a
    finger), each with room to work in; the stage stays in sight beside them (below them,
    upright); nothing runs off the screen, and every control is a finger's size."""
    width, height = size
    tablet = Page(browser, studio, {"width": width, "height": height}, touch=True)
    try:
        tablet.open("square.root")
        tablet.page.wait_for_selector("#check-said", state="attached")  # (at home: adventures)
        box = tablet.js("""() => Object.fromEntries(
            ['pane-tabs', 'blocks-pane', 'text-pane', 'stage-pane', 'canvas', 'tab-text']
            .map(id => {
                const e = document.getElementById(id), r = e.getBoundingClientRect();
                return [id, {left: r.left, top: r.top, right: r.right, bottom: r.bottom,
                             width: r.width, height: r.height,
                             seen: getComputedStyle(e).visibility === 'visible'}];
            }))""")
        assert box["pane-tabs"]["height"] >= FINGER_PX
        assert box["blocks-pane"]["seen"] and not box["text-pane"]["seen"]  # the blocks first
        edit, stage = box["blocks-pane"], box["stage-pane"]
        assert box["text-pane"] == {**edit, "seen": False}  # one place, taken in turn
        assert edit["width"] >= 0.6 * width and edit["height"] >= 0.45 * height  # room
        if width > height:
            assert edit["right"] <= stage["left"] + 1  # the stage beside ...
        else:
            assert edit["bottom"] <= stage["top"] + 1  # ... or below
        canvas = box["canvas"]
        assert canvas["width"] >= 250 and canvas["height"] >= 250  # the robot in sight
        assert canvas["bottom"] <= height and canvas["right"] <= width
        assert tablet.js("() => document.documentElement.scrollWidth") <= width
        # a finger's tap on the Text tab: the text, as wide as the blocks were
        tab = box["tab-text"]
        tablet.page.touchscreen.tap(tab["left"] + tab["width"] / 2, tab["top"] + tab["height"] / 2)
        tablet.wait_state("pane", "text")
        seen = tablet.js("""() => ['blocks-pane', 'text-pane'].map(id =>
            getComputedStyle(document.getElementById(id)).visibility === 'visible')""")
        assert seen == [False, True]
        lines = tablet.page.locator(".CodeMirror").bounding_box()
        assert lines is not None and lines["width"] >= 0.6 * width - 2
        # a mistake typed: the Text tab says so, also while the blocks are shown
        dot = "() => getComputedStyle(document.getElementById('tab-text'), '::after').content"
        assert tablet.js(dot) in ("none", "normal")
        tablet.type_at_the_end("mvoe 10 cm")
        tablet.page.wait_for_function(
            "() => document.getElementById('state').dataset.errors !== '0'", timeout=15000
        )
        assert "●" in tablet.js(dot)
        assert tablet.page.get_attribute("#tab-text", "aria-label") == (
            "Text (it has mistakes to fix)"
        )
        small = tablet.js(f"""() => [...document.querySelectorAll('button, select')]
            .filter(e => e.checkVisibility({{visibilityProperty: true}}))
            .map(e => [e.id || e.textContent.trim(), e.getBoundingClientRect()])
            .filter(([, r]) => Math.min(Math.round(r.width), Math.round(r.height)) < {FINGER_PX})
            .map(([name, r]) => name + ' ' + Math.round(r.width) + 'x' + Math.round(r.height))""")
        assert small == []
        assert tablet.errors == [] and tablet.outside == []
    finally:
        tablet.close()


def test_a_wide_screen_shows_blocks_text_and_stage_side_by_side(page: Page) -> None:
    page.open("square.root")
    assert not page.page.locator("#pane-tabs").is_visible()
    lefts = page.js("""() => ['blocks-pane', 'text-pane', 'stage-pane'].map(id =>
        document.getElementById(id).getBoundingClientRect().left)""")
    assert lefts == sorted(lefts) and lefts[1] - lefts[0] > 300 and lefts[2] - lefts[1] > 300
