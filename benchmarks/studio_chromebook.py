"""The studio on a school Chromebook: how soon can a child use it, and open a long program?

Run: ``.venv/bin/python benchmarks/studio_chromebook.py [--rate 4] [--times 3]``.

Starts ``rootlang studio`` (a separate process) over a folder with one generated program of
200 lines (:func:`studio_frames.long_program`), opens it in headless Chromium (Debian's,
through Playwright) with the CPU slowed ``--rate`` times (Chrome DevTools'
``Emulation.setCPUThrottlingRate``, as on a school Chromebook) and measures, from the start of
the page's navigation, each ``--times`` times in a fresh tab (the browser's cache warm after
the first, as in class):

- **page usable**: the studio ready for the child (its buttons and both panes working), with a
  short program open (``hello.root``, two lines);
- **200 lines' blocks**: the page opened with the program, until its blocks are on the
  workspace, in step with the text (all of them: they are made a few at a time between frames,
  top down, and the page is the child's before that); in brackets, when the page was the
  child's with its first blocks shown, and when the blocks filled the view (a child sees no
  more of them without scrolling);
- **frozen**: the page's longest time without a frame while it did that (``requestAnimationFrame``
  callbacks; a page frozen for a second can't even show its buttons pressed).

Aims: page usable <= 2.5 s; the blocks <= 3 s, the page never frozen for long.
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

from playwright.sync_api import Browser, sync_playwright

sys.path.insert(0, str(Path(__file__).parent))
from studio_frames import CHROMIUM, CHROMIUM_ARGS, long_program

LINES = 200

# When the page said it was ready / had its text's blocks, and its longest time between frames
WATCH = """
window.__load = {ready: 0, seen: 0, synced: 0, longest: 0};
(() => {
  let last = performance.now();
  // the view full of blocks: one of them reaches below its bottom (they come top down)
  const full = () => {
    const blocks = window.Blockly && Blockly.getMainWorkspace();
    if (!blocks || !blocks.getMetricsManager) return false;
    const view = blocks.getMetricsManager().getViewMetrics(true);
    const bottom = view.top + view.height;
    return blocks.getAllBlocks(false).some(block => block.getRelativeToSurfaceXY().y > bottom);
  };
  const tick = () => {
    const now = performance.now();
    window.__load.longest = Math.max(window.__load.longest, now - last);
    last = now;
    if (!window.__load.seen && window.__load.ready && full()) window.__load.seen = now;
    requestAnimationFrame(tick);
  };
  requestAnimationFrame(tick);
  document.addEventListener("DOMContentLoaded", () => {
    const state = document.getElementById("state");
    const seen = () => {
      const load = window.__load;
      if (state.dataset.ready === "yes" && !load.ready) load.ready = performance.now();
      if (state.dataset.textSynced === "yes" && !load.synced
          && Blockly.getMainWorkspace().getAllBlocks(false).length > 0) {
        load.synced = performance.now();
      }
    };
    new MutationObserver(seen).observe(state, {attributes: true});
  });
})();
"""


def opened(browser: Browser, address: str, rate: float) -> dict[str, float]:
    """One page opened at ``address`` in a fresh tab with the CPU ``rate`` times slower: when
    it was ready, had its blocks, and its longest time without a frame meanwhile (s)."""
    page = browser.contexts[0].new_page()
    page.set_default_timeout(120_000)
    page.add_init_script(WATCH)
    cdp = page.context.new_cdp_session(page)
    cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
    page.goto(address)
    wanted = "window.__load.synced" if "long.root" in address else "window.__load.ready"
    page.wait_for_function(f"() => {wanted} > 0")
    figures: dict[str, float] = page.evaluate("() => ({...window.__load})")
    page.close()
    return {name: value / 1000 for name, value in figures.items()}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rate", type=float, default=4.0, help="how many times slower the CPU")
    parser.add_argument("--times", type=int, default=3, help="loads of each page")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch) / "class"
        folder.mkdir()
        program = long_program(LINES - 3)  # (its header: two comments and `when started`)
        (folder / "long.root").write_text(program, encoding="utf-8")
        (folder / "hello.root").write_text('when started\n    say "hello"\n', encoding="utf-8")
        server = subprocess.Popen(
            [sys.executable, "-m", "rootlang", "studio", str(folder), "--port", "0",
             "--no-browser"],
            stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
        )  # fmt: skip
        try:
            assert server.stdout is not None
            found = re.search(r"http://[\d.]+:\d+", server.stdout.readline())
            assert found, "the studio did not say where it serves"
            with sync_playwright() as playwright:
                browser = playwright.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
                browser.new_context(viewport={"width": 1400, "height": 850})
                usable = [opened(browser, found.group(0) + "/?open=hello.root", args.rate)
                          for _ in range(args.times)]  # fmt: skip
                blocks = [opened(browser, found.group(0) + "/?open=long.root", args.rate)
                          for _ in range(args.times)]  # fmt: skip
                browser.close()
        finally:
            server.terminate()
            server.wait(10)
    lines = program.count("\n")
    load = os.getloadavg()[0]
    print(f"CPU {args.rate:g}x slower; {os.cpu_count()} cores, load average {load:.1f}; "
          f"the median of {args.times} loads (the first, then cached)")  # fmt: skip
    for name, loads, key in (("page usable", usable, "ready"),
                             (f"a {lines}-line program's blocks", blocks, "synced")):  # fmt: skip
        each = ", ".join(f"{one[key]:.2f}" for one in loads)
        frozen = max(one["longest"] for one in loads)
        first = ""
        if key == "synced":
            ready = statistics.median(one["ready"] for one in loads)
            seen = statistics.median(one["seen"] for one in loads)
            first = (f" (the page usable with it, its first blocks shown: {ready:.2f} s; "
                     f"the view full of blocks: {seen:.2f} s)")  # fmt: skip
        median = statistics.median(one[key] for one in loads)
        print(f"{name}: {median:.2f} s (each: {each}){first}; "
              f"the longest time without a frame {frozen:.2f} s")  # fmt: skip
    print("aims: page usable <= 2.5 s; the blocks <= 3 s, never frozen")


if __name__ == "__main__":
    main()
