"""Going back in time in the studio, in a real headless browser with real clicks and keys: a run
paused at a breakpoint, its slider moved back to 5 s with the keyboard shows the pose
`rootlang sim --until 5` gives, the script's line lit and the loop's round; once the run has
finished, a click on a side of the square drawn goes to when it was drawn and lights the
`move` that drew it, and a click on a line of the trace lights that line's statement."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

from playwright.sync_api import expect

from .browser import BLOCK, Page

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"
POSE = re.compile(r"The robot is at x (-?[\d.]+) cm, y (-?[\d.]+) cm, heading (\d+)°")


def _until(seconds: float) -> list[str]:
    """What `rootlang sim --until` says of the square at ``seconds``: where its script is and
    its values (a process of its own: the browser's driver has this one's event loop)."""
    said = subprocess.run(
        [sys.executable, "-m", "rootlang", "sim", str(PROGRAMS / "square.root"),
         "--until", str(seconds)],
        capture_output=True, text=True, check=True, timeout=120,
    ).stdout  # fmt: skip
    return [line.strip() for line in said.split(f"After {seconds:.1f} s:", 1)[1].splitlines()]


def _pose(lines: list[str]) -> tuple[float, float, int]:
    [found] = [match for line in lines if (match := POSE.fullmatch(line.rstrip(".")))]
    return float(found[1]), float(found[2]), int(found[3])


def _watch(page: Page) -> list[str]:
    lines: list[str] = page.page.locator("#watch-lines li").all_inner_texts()
    return lines


def _slide_to(page: Page, tenths: int) -> None:
    """The slider to ``tenths`` of a second, from the keyboard: Home, then the arrow keys."""
    page.page.keyboard.press("Home")
    for _ in range(tenths):
        page.page.keyboard.press("ArrowRight")
    page.wait_state("moment", f"{tenths / 10:.1f}")


def _line_class(page: Page, line: int) -> str:
    found: str = page.js(
        "line => document.querySelector('.CodeMirror').CodeMirror.lineInfo(line - 1).bgClass || ''",
        line,
    )
    return found


def test_the_slider_goes_back_to_5_s_and_a_stroke_lights_its_move(page: Page) -> None:
    said = _until(5.0)
    page.open("square.root")
    page.js("async () => (await import('/static/debugger.js')).toggle(7)")  # `marker up`
    page.run(speed="0")
    page.wait_state("paused", "7")
    slider = page.page.locator("#time")
    expect(slider).to_be_visible()
    assert slider.get_attribute("aria-valuetext") == "9.4 s of 9.4 s"
    box = slider.bounding_box()
    assert box is not None
    page.page.mouse.click(box["x"] + box["width"] - 2, box["y"] + box["height"] / 2)  # its end
    page.wait_state("timeline", "yes")
    _slide_to(page, 50)
    watch = _watch(page)
    assert watch[0] == said[1] == "`when started`: waiting for `move 10 cm` to end (line 5)"
    assert "The loop on line 4 is in round 3 of 4." in watch
    assert _pose(watch) == _pose(said) == (10.0, 10.0, 270)
    assert watch == said[1:]  # every value, as `rootlang sim --until 5` says them
    assert "paused-line" in _line_class(page, 5) and "paused-line" not in _line_class(page, 7)
    assert slider.get_attribute("aria-valuetext") == "5.0 s of 9.4 s"
    assert page.page.evaluate("() => document.activeElement.id") == "time"

    page.page.locator(".CodeMirror-gutter-elt .breakpoint").click()  # the breakpoint off
    page.page.click("#resume")
    assert page.wait_ended() == "finished"
    expect(slider).to_be_visible()
    assert slider.get_attribute("aria-valuetext") == "10.3 s of 10.3 s"

    # a click on the square's first side (world mm: it starts at 1000, 1000 and goes up)
    point = page.js("""async () => {
        const stage = (await import('/static/runs.js')).stage, to = stage.transform;
        const dpr = window.devicePixelRatio || 1, box = stage.canvas.getBoundingClientRect();
        return {x: box.left + (to.a * 1000 + to.e) / dpr, y: box.top + (to.d * 1050 + to.f) / dpr};
    }""")
    page.page.mouse.click(point["x"], point["y"])
    page.wait_state("madeBy", "5")
    expect(page.page.locator("#watch")).to_be_visible()  # the values then, the run over
    assert _watch(page)[0] == "`when started`: waiting for `move 10 cm` to end (line 5)"
    assert "The loop on line 4 is in round 1 of 4." in _watch(page)
    assert "made-line" in _line_class(page, 5)
    assert 0.4 < float(page.state()["moment"]) < 1.63  # (the first `move`: 400 ms to 1630 ms)
    assert page.js(f"async () => (await {BLOCK}('L5')).pathObject.svgPath.classList.value")
    glowing = page.js(
        f"async () => (await {BLOCK}('L5')).pathObject.svgPath.classList.contains('root-running')"
    )
    assert glowing

    page.page.click("#after summary")  # What happened: a click on a `turn` line
    page.page.locator("#trace li", has_text="turn right 90 degrees").first.click()
    page.wait_state("madeBy", "6")
    assert "made-line" in _line_class(page, 6) and "made-line" not in _line_class(page, 5)
