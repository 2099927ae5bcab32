"""WCAG 2.1 AA on every page of the studio, in real headless Chromium and in all five languages:
axe-core (pinned in ``tools/js``, injected by the test only: nothing of it is shipped) finds no
violation on the studio page, the pupil's page and the teacher's page, in each state a child or
a teacher sees (a run finished, the trace open, a pupil opened, the replay); the words on every
block (the workspace's and every toolbox category's) are at least 4.5:1 on their block.
"""

from __future__ import annotations

import shutil
from collections.abc import Iterator
from itertools import pairwise
from pathlib import Path
from typing import Any

import pytest

from rootlang.adventures import BUILT_IN
from rootlang.forms import Category
from rootlang.locale.blocks import studio_strings
from rootlang.locale.keywords import LANGUAGE_NAMES

from .browser import BLOCK, CHROMIUM, Page
from .conftest import RunningStudio
from .test_class_browser import ClassPage
from .test_classroom import SQUARE
from .test_debugging import PROGRAM

AXE = (
    Path(__file__).resolve().parents[2]
    / "tools"
    / "js"
    / "node_modules"
    / "axe-core"
    / "axe.min.js"
)
pytestmark = [
    pytest.mark.skipif(
        not CHROMIUM.exists(), reason="needs Debian's chromium at /usr/bin/chromium"
    ),
    pytest.mark.skipif(
        not AXE.exists(), reason="axe-core is not installed: run `npm ci --prefix tools/js`"
    ),
]
WCAG_AA = ["wcag2a", "wcag2aa", "wcag21a", "wcag21aa"]
TEXT_CONTRAST = 4.5  # WCAG 2.1 AA, 1.4.3: text (blocks' words are not large text)


def luminance(colour: tuple[float, float, float]) -> float:
    """WCAG's relative luminance of an sRGB colour (0-255 each)."""

    def linear(channel: float) -> float:
        c = channel / 255
        return c / 12.92 if c <= 0.04045 else ((c + 0.055) / 1.055) ** 2.4

    r, g, b = colour
    return 0.2126 * linear(r) + 0.7152 * linear(g) + 0.0722 * linear(b)


def contrast(one: tuple[float, float, float], other: tuple[float, float, float]) -> float:
    light, dark = sorted((luminance(one), luminance(other)), reverse=True)
    return (light + 0.05) / (dark + 0.05)


def hex_colour(text: str) -> tuple[float, float, float]:
    return (int(text[1:3], 16), int(text[3:5], 16), int(text[5:7], 16))


def axe_violations(page: Page) -> list[str]:
    """What axe-core finds against WCAG 2.1 A and AA on the page as it is now (evaluated through
    the DevTools protocol: the studio's Content-Security-Policy admits no script of the test's)."""
    if not page.js("() => typeof axe !== 'undefined'"):
        page.js(AXE.read_text(encoding="utf-8") + "\n;0")
    found: list[str] = page.js(
        """async tags => (await axe.run(document, {runOnly: tags})).violations
            .flatMap(v => v.nodes.map(n => v.id + " " + n.target.join(" ") + ": "
                + n.any.concat(n.all, n.none).map(c => c.message).join("; ")))""",
        WCAG_AA,
    )
    return found


# Every word drawn on a block (or a toolbox's button), with its colour and the colour behind it:
# the block's own, or a field's box on it (drawn with its opacity over the block). axe can't tell
# what is behind SVG text, so the test composes it as Blockly draws it.
BLOCK_WORDS = """root => [...root.querySelectorAll("text.blocklyText")]
    .filter(t => /[\\p{L}\\p{N}]/u.test(t.textContent) && t.getBBox().width > 0)
    .map(t => {
      const rgb = c => (c.match(/[\\d.]+/g) || []).slice(0, 3).map(Number);
      const block = t.closest(".blocklyBlock"), button = t.closest(".blocklyFlyoutButton");
      const shape = block ? block.querySelector(":scope > path.blocklyPath")
                          : button.querySelector(":scope > .blocklyFlyoutButtonBackground");
      let behind = rgb(getComputedStyle(shape).fill);
      const box = t.parentElement.querySelector(":scope > rect");
      if (box && getComputedStyle(box).fill !== "none") {
        const a = Number(getComputedStyle(box).fillOpacity), over = rgb(getComputedStyle(box).fill);
        behind = behind.map((c, i) => a * over[i] + (1 - a) * c);
      }
      // a block the text leaves out is greyed (CSS's grayscale(1) of both); a faded one is drawn
      // with its opacity over the workspace's white
      let opacity = 1;
      for (let e = t; e && e.tagName !== "svg"; e = e.parentElement) {
        opacity *= Number(getComputedStyle(e).opacity);
      }
      const seen = c => (t.closest(".root-left-out")
        ? Array(3).fill(0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]) : c)
        .map(v => opacity * v + (1 - opacity) * 255);
      return [t.textContent, seen(rgb(getComputedStyle(t).fill)), seen(behind)];
    })"""


def words_below_contrast(page: Page) -> tuple[int, list[str]]:
    """How many words the blocks show (the workspace's and each toolbox category's), and those
    under 4.5:1 on their block."""
    seen: list[list[Any]] = page.js(f"""async () => {{
        const words = {BLOCK_WORDS};
        const workspace = Blockly.getMainWorkspace(), toolbox = workspace.getToolbox();
        const all = words(workspace.getCanvas());
        for (const item of toolbox.getToolboxItems().filter(i => i.isSelectable())) {{
            toolbox.setSelectedItem(item);
            await Blockly.renderManagement.finishQueuedRenders();
            all.push(...words(workspace.getFlyout().getWorkspace().getParentSvg()));
        }}
        toolbox.clearSelection();
        return all;
    }}""")
    low = [
        f"{text!r} {contrast(tuple(fg), tuple(bg)):.2f}:1"
        for text, fg, bg in seen
        if contrast(tuple(fg), tuple(bg)) < TEXT_CONTRAST
    ]
    return len(seen), low


def test_every_category_colour_carries_white_words() -> None:
    white = (255.0, 255.0, 255.0)
    low = {c.label: round(contrast(hex_colour(c.colour), white), 2) for c in Category}
    assert {name: ratio for name, ratio in low.items() if ratio < TEXT_CONTRAST} == {}


@pytest.fixture
def page(browser: Any, studio: RunningStudio) -> Iterator[Page]:
    opened = Page(browser, studio)
    yield opened
    assert opened.outside == [], "the page asked for something beyond the studio"
    assert opened.errors == [], "the page's script failed"
    opened.close()


def test_the_studio_meets_wcag_aa_in_every_language(page: Page, browser: Any) -> None:
    for language in LANGUAGE_NAMES:
        page.open("square.root", language)
        assert axe_violations(page) == [], language
        if language == "en":  # (the colours are the same in every language)
            page.js(f"async () => {{ const said = await {BLOCK}('L8');"
                    " said.unplug(); said.moveBy(300, 100); }")  # fmt: skip
            page.wait_state("leftOut", "1")  # a loose block (greyed) too
            count, low = words_below_contrast(page)
            assert count > 100 and low == []
        page.page.select_option("#speed", "0")
        page.page.click("#run")
        page.wait_state("ended", "finished")
        page.page.click("#after summary")  # the trace open
        assert axe_violations(page) == [], f"{language}, after a run"
    # the replay of the last run (German, as the page): it meets AA too, speaks German, and says
    # the events it passes as it plays, in the child's words as the trace shows them
    trace = page.page.inner_text("#after")
    address = page.page.get_attribute("#replay", "href")
    html = page.js("a => fetch(a).then(r => r.text())", address)
    # (the studio sends it as a download: the test opens it as the file a child opens, in a
    # browser of its own: the studio page's service worker would answer for the file)
    replay = Page(browser, page.studio)
    replay.page.route(
        "**/the-replay.html", lambda route: route.fulfill(body=html, content_type="text/html")
    )
    replay.page.goto(replay.studio.address + "/the-replay.html")
    assert axe_violations(replay) == [], "the replay"
    german = studio_strings("de")
    assert replay.page.get_attribute("html", "lang") == "de"
    assert replay.page.inner_text("#play") == german["replay_play"] == "▶ Abspielen"
    assert replay.page.get_attribute("#slider", "aria-label") == german["replay_time"]
    assert german["speed"] in replay.page.inner_text("#controls")
    wheres = replay.page.eval_on_selector_all(
        "#events .where", "all => all.map(e => e.textContent)"
    )
    assert "Zeile 2" in wheres
    whats = replay.page.eval_on_selector_all("#events .what", "all => all.map(e => e.textContent)")
    assert whats and all(what.strip() in trace for what in whats)
    replay.page.focus("#play")
    replay.page.keyboard.press("Enter")
    assert replay.page.inner_text("#play") == german["pause"]
    replay.page.wait_for_function("() => document.getElementById('heard').textContent !== ''")
    assert replay.page.get_attribute("#heard", "aria-live") == "polite"
    assert replay.page.inner_text("#heard").split(". ")[0].strip() in trace
    assert replay.errors == [] and replay.outside == []
    replay.close()


# At Level 1, the buttons a child uses (with the key of their words) are pictures alone
PICTURED = {"#run": "run", "#stop": "stop", "#check": "check", "#adventures-open": "adventures",
            "[data-nose]": "nose", "[data-touch='front left']": "front_left",
            "[data-bump='left']": "bumper_left", "[data-bump='left right']": "both"}  # fmt: skip
GROWN_UPS = ("#program", "#new", "#rename", "#save", "#world", "#speed", "#robot", "#scan",
             "#connect-robot", "#language")  # fmt: skip
SHOWN = """s => { const e = document.querySelector(s);
    const r = e.getBoundingClientRect(); return r.width > 0 && r.height > 0; }"""


def test_a_pre_reader_finds_pictures_at_level_1_and_the_grown_ups_find_their_controls(
    page: Page, class_folder: Path
) -> None:
    """In every language: at Level 1 Run, Stop, the robot's buttons, Check and the adventures
    are pictures, no words to read (the words are their names and tooltips); the grown-ups'
    controls wait behind a button, reached by the keyboard, and the page meets WCAG AA."""
    starter = "01-go-forward.root"  # (an adventure's program: Check shows)
    shutil.copy(BUILT_IN / "01-go-forward" / starter, class_folder / starter)
    for language in LANGUAGE_NAMES:
        page.page.goto(f"{page.studio.address}/?level=1&open={starter}&language={language}")
        page.wait_state("ready", "yes")
        page.page.wait_for_selector("#check:not([hidden])")
        strings = studio_strings(language)
        for selector, key in PICTURED.items():
            found = page.js(
                """s => { const e = document.querySelector(s), p = e.querySelector('.picture');
                    return [e.innerText.trim(), p.getBoundingClientRect().width,
                            e.getAttribute('aria-label'), e.title]; }""",
                selector,
            )
            words, width, name, tip = found
            assert words == "" and width >= 32, (language, selector, found)  # a picture alone
            assert name and tip == name, (language, selector, found)
            if language != "en":  # (English's names say more than its words: "Touch front left")
                assert name in strings[key], (language, selector, found)
        for selector in GROWN_UPS:
            assert not page.js(SHOWN, selector), (language, selector)
        assert axe_violations(page) == [], f"{language}, Level 1"
    # the grown-ups' controls by the keyboard: the first thing Tab reaches, Enter shows them
    page.page.focus(".brand")
    page.page.keyboard.press("Tab")
    assert page.js("() => document.activeElement.id") == "grown-ups"
    page.page.keyboard.press("Enter")
    assert page.js("() => document.activeElement.getAttribute('aria-expanded')") == "true"
    assert all(page.js(SHOWN, selector) for selector in GROWN_UPS)
    page.page.keyboard.press("Tab")
    assert page.js("() => document.activeElement.id") == "program"
    assert axe_violations(page) == [], "Level 1, the grown-ups' controls shown"
    # at Level 2 the words are back, and the controls never went away
    page.page.click("#level-2")
    page.wait_state("level", "2")
    assert page.page.locator("#run").inner_text().strip() == strings["run"]
    assert not page.page.locator("#grown-ups").is_visible()
    assert all(page.js(SHOWN, selector) for selector in GROWN_UPS)


# Debugging's program with a loop long enough that the breakpoint set after the pause is always
# met again, however late a busy machine's click lands (its three rounds were over before one
# CI machine's pause)
PAUSED_PROGRAM = PROGRAM.replace("repeat 3\n", "repeat 100\n")
assert PAUSED_PROGRAM != PROGRAM


def test_pausing_a_run_meets_wcag_aa(page: Page, class_folder: Path) -> None:
    # Pause, Step and Resume and the Watch panel, each state they show in (axe leaves a disabled
    # button out: Pause is checked while the run goes on, Step and Resume while it is paused)
    (class_folder / "debug.root").write_text(PAUSED_PROGRAM, encoding="utf-8")
    page.open("debug.root")
    page.run(speed="1")
    page.page.wait_for_function("() => document.querySelectorAll('#watch-lines li').length > 0")
    assert page.page.locator("#pause").is_enabled()
    assert axe_violations(page) == [], "a run going on, its values watched"
    page.page.click("#pause")
    page.page.wait_for_function("() => !document.getElementById('resume').disabled")
    assert axe_violations(page) == [], "a run paused"
    page.js("async () => (await import('/static/debugger.js')).toggle(4)")  # `move size`
    first = page.page.inner_text("#status")  # ("Paused at 1.2 s": the next pause says its time)
    page.page.click("#resume")  # on to the breakpoint: `size` has changed since the pause
    page.page.wait_for_function(  # paused again (the live Watch marks changes as it goes too)
        """(first) => !document.getElementById('resume').disabled
            && document.getElementById('status').innerText !== first
            && !document.getElementById('time-travel').hidden
            && document.querySelector('#watch-lines li.changed')""",
        arg=first,
    )
    assert axe_violations(page) == [], "a run paused at a breakpoint, a value changed"
    page.page.focus("#time")  # back in time: the slider, its moment and the trace's line lit
    page.wait_state("timeline", "yes")
    page.page.keyboard.press("Home")
    page.page.keyboard.press("ArrowRight")
    page.wait_state("moment", "0.1")
    page.page.click("#after summary")
    assert axe_violations(page) == [], "a paused run gone back in time"
    page.page.click("#stop")
    assert page.wait_ended() == "stopped"


def test_the_class_pages_meet_wcag_aa_in_every_language(
    browser: Any,
    class_studio: RunningStudio,
) -> None:
    anna, miss, visitor = (ClassPage(browser, class_studio) for _ in range(3))
    anna.join("Anna")  # in the class, with a run the teacher's page shows (its trace too)
    assert axe_violations(anna) == [], "the studio in a class"
    anna.type_program(SQUARE)
    anna.page.select_option("#speed", "0")
    anna.page.click("#run")
    anna.wait_state("ended", "finished")
    miss.as_teacher()
    for language in LANGUAGE_NAMES:
        visitor.page.goto(f"{class_studio.address}/?language={language}")
        visitor.page.wait_for_function("l => document.documentElement.lang === l", arg=language)
        assert axe_violations(visitor) == [], f"{language}: the pupil's page"
        miss.page.goto(f"{class_studio.address}/teacher?language={language}")
        miss.wait_state("ready", "yes")
        miss.page.wait_for_function(
            "() => (document.getElementById('state').dataset.pupils || '').includes('Anna')"
        )
        miss.page.click("[data-pupil='Anna']")  # a pupil opened
        miss.page.wait_for_function("() => document.getElementById('state').dataset.shownText")
        assert axe_violations(miss) == [], f"{language}: the teacher's page"
    for person in (anna, miss, visitor):
        assert person.outside == [] and person.errors == []
        person.close()


FOCUSED = """() => { const e = document.activeElement;
    return e === document.body ? "" : e.id || e.getAttribute("aria-label") || e.tagName; }"""
# the text pane's own input (CodeMirror's hidden textarea: the text has the focus)
IN_TEXT = "() => document.activeElement.closest('.CodeMirror') !== null"


def press_until(page: Page, key: str, wanted: str, presses: int = 60) -> list[str]:
    """Presses ``key`` until the focus is on ``wanted`` (an id); the focus's places on the way."""
    seen: list[str] = []
    for _ in range(presses):
        page.page.keyboard.press(key)
        if page.js(IN_TEXT):  # the text keeps Tab (it indents): Escape, then Tab, leaves it
            seen.append("text")
            page.page.keyboard.press("Escape")
            page.page.keyboard.press(key)
        seen.append(page.js(FOCUSED))
        if seen[-1] == wanted:
            return seen
    raise AssertionError(f"{key} never reached #{wanted}: {seen[:30]}")


ANNOUNCE_GAP_MS = 1500  # narrator.js: at most one announcement in this long
# what the stage's live region says, and when (ms)
# What the live region says, and when the page's announcer decided to say it: the time it took
# last (it takes the time as it speaks; the observer runs right after, in the same task's
# microtasks), not the time the observer runs, which a busy machine may delay
HEARD = """() => { window.heard = [];
    const now = performance.now.bind(performance);
    let taken = 0;
    performance.now = () => (taken = now());
    new MutationObserver(() => window.heard.push([document.getElementById("heard").textContent,
                                                 taken]))
        .observe(document.getElementById("heard"), {childList: true, characterData: true,
                                                     subtree: true}); }"""


def test_a_child_writes_runs_stops_and_saves_with_the_keyboard_alone(
    page: Page, studio: RunningStudio
) -> None:
    page.open("square.root")
    # into the text and out again: Tab indents there, Escape then Tab leaves (a hint says so)
    press_until(page, "Tab", "program")
    forwards = press_until(page, "Tab", "program", presses=80)  # the page round
    assert "text" in forwards and "output" in forwards, ", ".join(forwards)
    assert all(
        any(control in place for place in forwards)
        for control in [
            "Touch front left",
            "Press the nose button",
            "bumper left",
            "both bumpers",
            "bumper right",
        ]
    ), forwards
    backwards = press_until(page, "Shift+Tab", "program", presses=80)
    assert "text" in backwards and "Touch back right" in backwards and "output" in backwards, (
        ", ".join(backwards)
    )
    # a program typed: into the text by Tab alone, all of it replaced
    while not page.js(IN_TEXT):
        page.page.keyboard.press("Tab")
    assert page.page.locator("#text-hint").is_visible()
    page.page.keyboard.press("Control+A")
    page.page.keyboard.type("when started\n")
    page.page.keyboard.press("Tab")  # (Tab indents)
    page.page.keyboard.type('say "hi"\nrepeat 400\n')
    page.page.keyboard.press("Tab")
    page.page.keyboard.type("light green\nmove 2 cm\nlight blue\nmove 2 cm\n")
    assert page.text().startswith('when started\n    say "hi"\n    repeat 400\n        light')
    page.page.keyboard.press("Escape")
    assert "Tab" in page.page.locator("#text-hint").inner_text()
    page.page.keyboard.press("Shift+Tab")
    assert not page.js(IN_TEXT)
    # run: the focus goes to Stop; stop: back to Run
    press_until(page, "Shift+Tab", "run")
    page.js(HEARD)
    page.page.keyboard.press("Enter")
    page.wait_state("running", "yes")
    assert page.js(FOCUSED) == "stop"
    # the stage speaks, politely, in the child's words: at most once in 1.5 s, the rest together
    page.page.wait_for_function(
        "() => ['green', 'blue'].every(c => window.heard.map(([text]) => text).join().includes(c))",
        timeout=20000,
    )
    heard: list[list[Any]] = page.js("() => window.heard")
    said = ". ".join(text for text, _ in heard)
    assert "said “hi”" in said and "the light turned green" in said and "moving" in said, said
    assert "the light turned blue" in said, said
    gaps = [later - earlier for (_, earlier), (_, later) in pairwise(heard)]
    assert min(gaps) >= ANNOUNCE_GAP_MS - 50, gaps  # (timer slack)
    assert page.page.get_attribute("#heard", "aria-live") == "polite"
    assert "The robot on its world: x" in (page.page.get_attribute("#canvas", "aria-label") or "")
    # a bumper pressed from the keyboard: said too; then back to Stop
    press_until(page, "Tab", "bumper left")
    page.page.keyboard.press("Enter")
    page.page.wait_for_function(
        "() => window.heard.some(([text]) => text.includes('bumped on the left'))", timeout=20000
    )
    # paused, stepped and resumed from the keyboard: the focus goes on from the button that
    # took the place of the one pressed (Pause's to Step, Resume's to Pause)
    press_until(page, "Shift+Tab", "pause")
    page.page.keyboard.press("Enter")
    page.page.wait_for_function("() => !document.getElementById('resume').disabled")
    assert page.js(FOCUSED) == "step"
    was = page.state().get("paused", "")
    page.page.keyboard.press("Enter")  # a step: paused again at the next line
    page.page.wait_for_function(  # (the step taken: Resume was still on before the studio heard)
        """(was) => !document.getElementById('resume').disabled
            && document.getElementById('state').dataset.paused !== was""",
        arg=was,
    )
    press_until(page, "Tab", "resume")
    page.page.keyboard.press("Enter")
    page.page.wait_for_function("() => document.activeElement.id === 'pause'")
    press_until(page, "Shift+Tab", "stop")
    page.page.keyboard.press("Enter")
    page.wait_state("ended", "stopped")
    assert page.js(FOCUSED) == "run"
    # a run that ends while the focus is on Step (hidden then): the focus goes to Run
    page.page.keyboard.press("Enter")
    page.wait_state("running", "yes")
    press_until(page, "Tab", "pause")
    page.page.keyboard.press("Enter")
    page.page.wait_for_function("() => document.activeElement.id === 'step'")
    page.js("() => document.getElementById('stop').click()")  # (the focus stays on Step)
    page.wait_state("ended", "stopped")
    assert page.js(FOCUSED) == "run"
    # saved: the Save button, from the keyboard
    press_until(page, "Shift+Tab", "save")
    saves = int(page.state().get("saves", "0"))
    page.page.keyboard.press("Enter")
    page.wait_state("saves", str(saves + 1))
    # (the page: what was saved, and the indentation of the line begun, kept for the next words)
    assert (studio.folder / "square.root").read_text(encoding="utf-8") == page.text().rstrip(" ")
