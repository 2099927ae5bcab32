"""A long program running: does the studio page stay smooth, on a fast computer and a slow one?

Run: ``.venv/bin/python benchmarks/studio_frames.py [--seconds 8] [--rate 4] [--times 5]
[--profile]``.

Starts ``rootlang studio`` (a separate process) over a folder with one generated program of
500 statements (marker down, then a walk of moves and turns, over and over), opens the studio
in headless Chromium (Debian's, through Playwright), presses Run at real time and, once the run
streams, measures for ``--seconds`` at full speed and then with the CPU slowed ``--rate``
times (Chrome DevTools' ``Emulation.setCPUThrottlingRate``, as on a school Chromebook):

- **page**: the page's frames a second (``requestAnimationFrame`` callbacks; 60 when idle);
- **stage**: the frames a second in which the stage shows a new picture (the stage canvas drawn
  since the page's frame before), against the frames the run's worker made and the page got
  (a page that falls behind is sent its waiting frames merged into one);
- **typing → blocks**: from the last key of a statement typed at the end of the text to the
  blocks having it, drawn (the median of ``--times`` at each speed; the run goes on
  meanwhile): the page's wait before it asks (0.1 s), the server's conversion of the 500
  lines, and the page fitting the new block in;
- **the main thread's time** in each second, by kind (DevTools' ``Performance.getMetrics``):
  script, style, layout, and all of it.

Aims: page >= 30 frames a second at full speed; at 4x, the stage >= 20 new pictures a second;
typing -> blocks <= 200 ms. With ``--profile``, a CPU profile of the page (Chrome DevTools'
``Profiler``) while it runs at full speed: the functions that took the most time, by itself.
With ``--trace``, Chromium's own trace of the page's main thread at 4x (its tasks by kind:
script, paint, layers, ...; what the profile calls "(program)").
"""

from __future__ import annotations

import argparse
import json
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path
from typing import Any

from playwright.sync_api import CDPSession, Page, sync_playwright

CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
                 "--disable-component-update", "--no-first-run"]  # fmt: skip
STATEMENTS = 500
THROTTLE = 4  # (as a school Chromebook: --rate)
TYPINGS = 5  # (--times)
WORLD = "worlds/long.toml"  # the default floor, with time for the measuring (60 s by default)

# Counted in the page, from outside the studio's code: its frames, and the frames in which the
# stage canvas was drawn again (its background is filled once a picture).
COUNTERS = """
window.__frames = {ticks: 0, painted: 0, drawn: 0, seen: 0, key: 0, synced: 0, asked: 0,
                  answered: 0};
(() => {
  const get = window.fetch;
  window.fetch = function (address, ...rest) {
    if (!String(address).includes("/api/blocks")) return get.call(this, address, ...rest);
    window.__frames.asked = performance.now();
    return get.call(this, address, ...rest).then(response => {
      window.__frames.answered = performance.now();
      return response;
    });
  };
  const fill = CanvasRenderingContext2D.prototype.fillRect;
  CanvasRenderingContext2D.prototype.fillRect = function (...args) {
    if (this.canvas.id === "canvas") window.__frames.drawn++;
    return fill.apply(this, args);
  };
  const tick = () => {
    const f = window.__frames;
    f.ticks++;
    if (f.drawn !== f.seen) { f.painted++; f.seen = f.drawn; }
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
  document.addEventListener("keydown", () => { window.__frames.key = performance.now(); }, true);
  document.addEventListener("DOMContentLoaded", () => {
    const state = document.getElementById("state");
    new MutationObserver(() => {
      if (state.dataset.textSynced !== "yes") return;
      requestAnimationFrame(() => { window.__frames.synced = performance.now(); });
    }).observe(state, {attributes: true, attributeFilter: ["data-text-synced"]});
  });
})();
"""


def long_program(statements: int = STATEMENTS) -> str:
    """``statements`` statements: marker down, repeat forever, then moves and turns (a wobbly
    circle, so the robot stays on its floor and the running line changes every moment)."""
    lines = ["# a long program: the studio's frames while it runs", f"# world: {WORLD}",
             "when started", "    marker down", "    repeat forever"]  # fmt: skip
    for i in range(statements - 2):
        if i % 2 == 0:
            lines.append(f"        move {1 + i % 3} cm")
        else:
            lines.append(f"        turn right {5 + i % 7} degrees")
    return "\n".join(lines) + "\n"


class Stream:
    """The run's frames as the page's socket gets them (counted here, not in the page)."""

    def __init__(self) -> None:
        self.got: list[tuple[float, int]] = []  # when, the frame's number in its run

    def heard(self, payload: str | bytes) -> None:
        if isinstance(payload, str) and payload.startswith('{"type": "frame"'):
            found = re.search(r'"n": (\d+)', payload)
            self.got.append((time.monotonic(), int(found.group(1)) if found else 0))

    def between(self, began: float, ended: float) -> tuple[int, int]:
        """Frames the worker made, and the page got, in that time."""
        inside = [n for when, n in self.got if began <= when <= ended]
        return (inside[-1] - inside[0] + 1 if inside else 0), len(inside)


# Chrome DevTools' Performance metrics: the page's main thread's time, by what it did (s)
SPENT = {"ScriptDuration": "script", "RecalcStyleDuration": "style", "LayoutDuration": "layout",
         "TaskDuration": "all"}  # fmt: skip


def measure(page: Page, cdp: CDPSession, stream: Stream, seconds: float) -> dict[str, float]:
    page.evaluate("() => { const f = window.__frames; f.ticks = 0; f.painted = 0; }")
    before = metrics(cdp)
    began = time.monotonic()
    page.wait_for_timeout(seconds * 1000)
    counted: dict[str, int] = page.evaluate("() => ({...window.__frames})")
    ended = time.monotonic()
    after = metrics(cdp)
    made, got = stream.between(began, ended)
    wall = ended - began
    figures = {"page": counted["ticks"] / wall, "painted": counted["painted"] / wall,
               "made": made / wall, "got": got / wall}  # fmt: skip
    figures.update({name: (after[name] - before[name]) / wall for name in SPENT.values()})
    return figures


def metrics(cdp: CDPSession) -> dict[str, float]:
    found: Any = cdp.send("Performance.getMetrics")
    return {SPENT[m["name"]]: m["value"] for m in found["metrics"] if m["name"] in SPENT}


def typing_to_blocks(page: Page, times: int = TYPINGS) -> list[dict[str, float]]:
    """From the last key of a statement typed at the end to its block, drawn (ms): in all, the
    wait before the page asks, the answer's coming (the server's conversion), the rest."""
    took: list[dict[str, float]] = []
    for i in range(times):
        before = page.evaluate("() => Blockly.getMainWorkspace().getAllBlocks(false).length")
        page.click(".CodeMirror")
        page.keyboard.press("Control+End")
        page.keyboard.press("Home")
        page.keyboard.press("Shift+End")
        page.keyboard.type(f'    print "typed {i}"\n', delay=40)
        page.wait_for_function(
            """(before) => window.__frames.synced > window.__frames.key
                 && Blockly.getMainWorkspace().getAllBlocks(false).length > before""",
            arg=before,
        )
        took.append(
            page.evaluate(
                """() => { const f = window.__frames;
                return {all: f.synced - f.key, wait: f.asked - f.key,
                        answer: f.answered - f.asked, fit: f.synced - f.answered}; }"""
            )
        )
        page.wait_for_timeout(300)
    return took


def typing_figures(typed: list[dict[str, float]]) -> str:
    """The typings' medians: in all, and its parts (ms)."""
    median = {part: statistics.median(t[part] for t in typed) for part in typed[0]}
    return (
        f"typing -> blocks {median['all']:.0f} ms (median of {len(typed)}, max "
        f"{max(t['all'] for t in typed):.0f} ms: the wait before asking {median['wait']:.0f}, "
        f"the answer {median['answer']:.0f}, fitting and drawing {median['fit']:.0f})"
    )


def profile(page: Page, seconds: float) -> list[tuple[float, str]]:
    """The page's functions that took the most time by themselves while it ran (ms, where)."""
    cdp = page.context.new_cdp_session(page)
    cdp.send("Profiler.enable")
    cdp.send("Profiler.setSamplingInterval", {"interval": 200})
    cdp.send("Profiler.start")
    page.wait_for_timeout(seconds * 1000)
    found: Any = cdp.send("Profiler.stop")
    nodes = {node["id"]: node for node in found["profile"]["nodes"]}
    parents = {child: node["id"] for node in nodes.values() for child in node.get("children", [])}

    def named(node: int) -> str:
        frame = nodes[node]["callFrame"]
        where = f"{frame['functionName'] or '(anonymous)'} {frame['url'].rsplit('/', 1)[-1]}"
        return f"{where}:{frame['lineNumber'] + 1}"

    spent: Counter[str] = Counter()
    deltas = found["profile"]["timeDeltas"]
    for sample, delta in zip(found["profile"]["samples"], deltas, strict=True):
        # (the browser's own functions, such as a layout forced by a script: with their callers)
        where, node = named(sample), sample
        while nodes[node]["callFrame"]["url"] == "" and node in parents and len(where) < 200:
            node = parents[node]
            where += " < " + named(node)
        spent[where] += delta / 1000
    return [(ms, where) for where, ms in spent.most_common(25)]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seconds", type=float, default=8.0, help="each measurement's length")
    parser.add_argument("--profile", action="store_true", help="where the page's time goes")
    parser.add_argument("--trace", action="store_true", help="the main thread's tasks, slowed")
    parser.add_argument("--rate", type=float, default=THROTTLE, help="times slower the CPU")
    parser.add_argument("--times", type=int, default=TYPINGS, help="typings at each speed")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        folder.mkdir()
        (folder / "long.root").write_text(long_program(), encoding="utf-8")
        (folder / WORLD).parent.mkdir()
        (folder / WORLD).write_text("time_limit = 3600\n", encoding="utf-8")
        server = subprocess.Popen(
            [sys.executable, "-m", "rootlang", "studio", str(folder), "--port", "0",
             "--no-browser"],
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,  # (its run, killed)
        )  # fmt: skip
        try:
            assert server.stdout is not None
            found = re.search(r"http://[\d.]+:\d+", server.stdout.readline())
            assert found, "the studio did not say where it serves"
            run(found.group(0), args.seconds, args.profile, args.trace, args.rate, args.times)
        finally:
            server.terminate()
            server.wait(10)


def main_thread_tasks(trace: bytes, seconds: float) -> list[tuple[float, str]]:
    """The renderer main thread's own time in each second, by the kind of trace event (ms):
    each complete event's duration less its children's."""
    events = json.loads(trace)["traceEvents"]
    main = "CrRendererMain"
    names = {(e["pid"], e["tid"]) for e in events
             if e.get("name") == "thread_name" and e["args"]["name"] == main}  # fmt: skip
    spans = sorted(
        (e["ts"], e["ts"] + e["dur"], e["name"]) for e in events
        if e.get("ph") == "X" and "dur" in e and (e["pid"], e["tid"]) in names
    )  # fmt: skip
    own: Counter[str] = Counter()
    open_spans: list[tuple[float, str]] = []  # (end, name) of the spans around this one
    for start, end, name in spans:
        while open_spans and open_spans[-1][0] <= start:
            open_spans.pop()
        if open_spans:
            own[open_spans[-1][1]] -= end - start
        own[name] += end - start
        open_spans.append((end, name))
    return [(us / 1000 / seconds, name) for name, us in own.most_common(15)]


def run(address: str, seconds: float, profiling: bool, tracing: bool = False,
        rate: float = THROTTLE, times: int = TYPINGS) -> None:  # fmt: skip
    with sync_playwright() as playwright:
        browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        page = browser.new_context(viewport={"width": 1400, "height": 850}).new_page()
        page.set_default_timeout(180_000)  # (a page 4 times slower, and busy, answers late)
        page.add_init_script(COUNTERS)
        stream = Stream()
        page.on("websocket", lambda socket: socket.on("framereceived", stream.heard))
        page.goto(f"{address}/?open=long.root")
        state = "document.getElementById('state').dataset"
        page.wait_for_function(f"() => {state}.ready === 'yes' && {state}.textSynced === 'yes'",
                               timeout=60000)  # fmt: skip
        cdp = page.context.new_cdp_session(page)
        cdp.send("Performance.enable")
        idle = measure(page, cdp, stream, 2)
        page.select_option("#speed", "1")
        page.click("#run")
        page.wait_for_function(f"() => Number({state}.t || 0) > 1", timeout=60000)
        if profiling:
            for ms, where in profile(page, seconds):
                print(f"{ms:8.1f} ms  {where}")
            return
        if tracing:
            cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
            page.wait_for_timeout(1000)
            timeline = ["devtools.timeline", "toplevel", "disabled-by-default-devtools.timeline"]
            browser.start_tracing(page=page, categories=timeline)
            page.wait_for_timeout(seconds * 1000)
            for ms, name in main_thread_tasks(browser.stop_tracing(), seconds):
                print(f"{ms:8.1f} ms a second  {name}")
            return
        fast = measure(page, cdp, stream, seconds)
        cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
        slow = measure(page, cdp, stream, seconds)
        typed_slow = typing_to_blocks(page, times)
        cdp.send("Emulation.setCPUThrottlingRate", {"rate": 1})
        typed_fast = typing_to_blocks(page, times)
        ended = page.evaluate(f"() => {state}.ended")
        browser.close()
    print(f"a {STATEMENTS}-statement program running at real time, {seconds:.0f} s each; "
          f"{os.cpu_count()} cores, load average {os.getloadavg()[0]:.1f}")  # fmt: skip
    print(f"idle page (before the run): {idle['page']:.0f} frames a second")
    for name, figures, typed in (("full speed", fast, typed_fast),
                                 (f"CPU {rate:g}x slower", slow, typed_slow)):  # fmt: skip
        print(f"{name}: page {figures['page']:.1f} frames a second; stage painted "
              f"{figures['painted']:.1f} a second, of {figures['got']:.1f} frames got "
              f"({figures['made']:.1f} made by the run); {typing_figures(typed)}")  # fmt: skip
        print("    the page's main thread, busy in each second: " + ", ".join(
            f"{name} {figures[name] * 1000:.0f} ms" for name in SPENT.values()))  # fmt: skip
    print("aims: page >= 30 at full speed; painted >= 20 at 4x; typing -> blocks <= 200 ms")
    if ended:
        print(f"(the run ended before the measuring did: {json.dumps(ended)})")


if __name__ == "__main__":
    main()
