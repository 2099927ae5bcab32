"""The HTML replay really replays, in headless Chromium: played to the end at 10× the robot is
where the recording ends and all the ink is down; at a chosen moment it is where the recording
says, its light as it was, with the ink drawn so far. The page writes what it shows into
``<output id="state">`` (data attributes); Chromium's virtual time budget runs its timers fast."""

from __future__ import annotations

import itertools
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.runtime.trace import child_view
from rootlang.sim.recording import Recording
from rootlang.sim.render import html_text
from rootlang.sim.render.compose import scene_of
from rootlang.sim.world import default_world
from rootlang.wording.language import ENGLISH, Languages

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(
    CHROMIUM is None, reason="chromium is not installed (apt-get install chromium)"
)

PROGRAM = """when started
    light red
    say "hello"
    marker down
    move 20 cm
    turn left 90 degrees
    light blink green
    move 5 cm
    marker up
"""


def recording() -> Recording:
    checked = load_checked(PROGRAM, "p.root")
    return simulate(checked.program, default_world(), source=PROGRAM)[1]


def page_state(page: Path, tmp_path: Path, fragment: str, budget_ms: int) -> dict[str, str]:
    """Open the page in headless Chromium and read the state it shows after ``budget_ms`` of
    (virtual) time."""
    assert CHROMIUM is not None
    command = [
        CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
        "--no-first-run", "--disable-background-networking", "--disable-component-update",
        "--disable-sync", f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1000,700",
        f"--virtual-time-budget={budget_ms}", "--dump-dom", f"{page.as_uri()}#{fragment}",
    ]  # fmt: skip
    dom = subprocess.run(command, capture_output=True, text=True, timeout=60, check=True).stdout
    match = re.search(r'<output id="state"[^>]*>', dom)
    assert match, dom[-2000:]
    return dict(re.findall(r'data-([a-z]+)="([^"]*)"', match.group(0)))


@pytest.fixture(scope="module")
def run() -> Recording:
    return recording()


def test_played_to_the_end_the_robot_is_where_the_run_ended(run: Recording, tmp_path: Path) -> None:
    page = tmp_path / "replay.html"
    page.write_text(html_text(run), encoding="utf-8")
    budget = run.duration_ms // 10 + 1000  # 10× speed, and a second to spare
    state = page_state(page, tmp_path, "speed=10&play", budget)
    final = run.final_frame
    assert final is not None
    assert state["playing"] == "false"
    assert float(state["t"]) == pytest.approx(run.duration_ms / 1000)
    assert (float(state["x"]), float(state["y"])) == (final.x_mm, final.y_mm)
    assert float(state["h"]) == pytest.approx(final.heading_deg, abs=0.05)
    all_points = sum(len(s.points) for s in scene_of(run).ink)
    assert int(state["ink"]) == all_points


def test_at_a_moment_the_robot_its_light_and_the_ink_are_as_recorded(
    run: Recording, tmp_path: Path
) -> None:
    page = tmp_path / "replay.html"
    page.write_text(html_text(run), encoding="utf-8")
    turning = next(f for f in run.frames if f.heading_ddeg not in (900, 1800) and f.t_ms > 0)
    moment = f"t={turning.t_ms / 1000}"
    state = page_state(page, tmp_path, f"{moment}&probe=1000,1050", 500)
    assert (float(state["x"]), float(state["y"])) == (turning.x_mm, turning.y_mm)
    assert float(state["h"]) == pytest.approx(turning.heading_deg, abs=0.05)
    assert state["led"] == "#ff0000"  # red, not yet blinking green
    assert 0 < int(state["ink"]) < sum(len(s.points) for s in scene_of(run).ink)
    assert int(state["event"]) >= 0  # "says hello" has happened
    assert state["probe"] == "0,0,0"  # the black ink on the first line, drawn above the path
    beside = page_state(page, tmp_path, f"{moment}&probe=1040,1050", 500)
    assert beside["probe"] == "255,255,255"  # the white floor beside it


def test_between_two_frames_the_robot_is_half_way(run: Recording, tmp_path: Path) -> None:
    page = tmp_path / "replay.html"
    page.write_text(html_text(run), encoding="utf-8")
    before, after = next(
        (a, b) for a, b in itertools.pairwise(run.frames) if 900 < b.heading_ddeg < 1800
    )
    state = page_state(page, tmp_path, f"t={(before.t_ms + after.t_ms) / 2000}", 500)
    middle = (before.heading_deg + after.heading_deg) / 2
    assert float(state["h"]) == pytest.approx(middle, abs=0.1)
    assert float(state["x"]) == pytest.approx((before.x_mm + after.x_mm) / 2, abs=0.1)


HOSTILE = "<!--<script>"  # opens a comment and a script inside the page's own <script>


@pytest.mark.parametrize("text", [HOSTILE, "</script><script>alert(1)</script>", "-->&amp;<!--"])
def test_whatever_a_student_says_the_page_still_runs_and_shows_it_as_text(
    text: str, tmp_path: Path
) -> None:
    """Replays are shared between families: a student's text must stay text in the page."""
    source = f'when started\n    say "{text}"\n    print "{text}"\n    move 2 cm\n'
    checked = load_checked(source, "p.root")
    result, run = simulate(checked.program, default_world(), source=source)
    story = child_view(result.trace.entries, source, None, ENGLISH)
    page = tmp_path / "replay.html"
    page.write_text(html_text(run, title=f"{text}.root", story=story), encoding="utf-8")
    state = page_state(page, tmp_path, "t=0.1", 1000)
    assert state.get("t") == "0.100", "the page's script did not run"
    dom = dump_dom(page, tmp_path)
    shown = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
    assert f'<h1 id="title">{shown}.root</h1>' in dom
    assert f"print “{shown}”".replace("“", '"').replace("”", '"') in dom


def test_the_page_names_the_program_lists_the_child_view_and_marks_the_error(
    tmp_path: Path,
) -> None:
    source = (
        "when started\n    light green\n    play note C4 for 0.5 seconds\n"
        "    set none to 0\n    print 1 / none\n"
    )
    checked = load_checked(source, "oops.root")
    result, run = simulate(checked.program, default_world(), source=source)
    story = child_view(result.trace.entries, source, None, ENGLISH)
    page = tmp_path / "replay.html"
    page.write_text(html_text(run, title="oops.root", story=story), encoding="utf-8")
    dom = dump_dom(page, tmp_path, "t=0.1")
    assert '<h1 id="title">oops.root</h1>' in dom
    assert "default: Root RT1" in dom  # the world and robot, under the name
    assert '<span class="what">light green</span>' in dom  # as written: no hex
    assert '<span class="what">play note C4 for 0.5 seconds</span>' in dom  # as written: no Hz
    assert re.search(r'<li data-kind="error" class="error[^"]*">.*line 5.*divide by zero', dom)
    assert '<button id="start" type="button"' in dom  # the big Play (hidden: t= chose a moment)


def test_the_page_speaks_the_language_it_is_written_in(tmp_path: Path) -> None:
    # its own words (buttons, the slider's name, "line 5" in the list) from the studio's words
    # and the catalogue, as `rootlang sim --language nl --html` and a Dutch studio page write it
    source = "when started\n    light green\n    set none to 0\n    print 1 / none\n"
    checked = load_checked(source, "oops.root")
    result, run = simulate(checked.program, default_world(), source=source)
    dutch = Languages(page="nl")
    story = child_view(result.trace.entries, source, None, dutch)
    page = tmp_path / "replay.html"
    page.write_text(html_text(run, story=story, languages=dutch), encoding="utf-8")
    dom = dump_dom(page, tmp_path, "t=0.1")
    assert '<html lang="nl">' in dom
    assert dom.count(">▶ Afspelen</button>") == 2  # the big one on the stage, and the bar's
    assert "<label>Snelheid <select" in dom and 'aria-label="Tijd in de run"' in dom
    assert '<span class="where">regel 4</span>' in dom and "line 4" not in dom


def dump_dom(page: Path, tmp_path: Path, fragment: str = "") -> str:
    assert CHROMIUM is not None
    command = [
        CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run",
        "--disable-background-networking", "--disable-component-update", "--disable-sync",
        f"--user-data-dir={tmp_path / 'profile'}", "--window-size=1000,700",
        "--virtual-time-budget=1000", "--dump-dom", f"{page.as_uri()}#{fragment}",
    ]  # fmt: skip
    return subprocess.run(command, capture_output=True, text=True, timeout=60, check=True).stdout
