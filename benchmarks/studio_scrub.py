"""How fast the studio's time slider scrubs a 10-minute run, in headless Chromium.

    .venv/bin/python benchmarks/studio_scrub.py [--minutes 10] [--updates 200]

Starts ``rootlang studio`` (as a teacher would) over a folder with one program: simulator.py's
drawing (stars, marker down, forever, two scripts listening for colours) on its colour mat, in
a world whose time limit is ``--minutes``. A page (Debian's ``chromium``, 1400x850) runs it as
fast as it goes to its end, then moves the slider ``--updates`` times across the whole run (each
move an ``input`` event, as the arrow keys and the mouse make): the stage drawn at that moment,
the scripts' lines lit in both panes, the Watch panel and the trace's line. Prints

- the moves a second with each move painted before the next (the next animation frame), and
- each move's own script time (median and p95, ms),

first as the computer is, then with the CPU slowed 4x (DevTools' CPU throttling, as a school's
old laptop). Aim: >= 20 moves a second, both ways.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
from pathlib import Path
from typing import Any

from simulator import DRAWING, MAT_WORLD  # (this folder's: the script's own is on sys.path)
from studio_process import served_studio

CHROMIUM = "/usr/bin/chromium"
AIM_PER_SECOND = 20
SCRUB = """async updates => {
    const slider = document.getElementById('time'), top = Number(slider.max);
    const frame = () => new Promise(done => requestAnimationFrame(() => done(null)));
    const own = [];
    await frame();
    const start = performance.now();
    for (let i = 0; i < updates; i++) {
        const began = performance.now();
        slider.value = String(((i * 7919) % updates) / updates * top);   // all over the run
        slider.dispatchEvent(new Event('input', {bubbles: true}));
        own.push(performance.now() - began);
        await frame();
    }
    return {seconds: (performance.now() - start) / 1000, own: own};
}"""


def scrub(page: Any, updates: int) -> tuple[float, float, float]:
    """Moves a second (each painted), and the median and p95 of a move's own time (ms)."""
    done: dict[str, Any] = page.evaluate(SCRUB, updates)
    own = sorted(done["own"])
    return updates / done["seconds"], statistics.median(own), own[int(0.95 * (len(own) - 1))]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--minutes", type=float, default=10.0)
    parser.add_argument("--updates", type=int, default=200)
    options = parser.parse_args()
    from playwright.sync_api import sync_playwright

    with tempfile.TemporaryDirectory() as folder:
        world = MAT_WORLD.replace('name = "drawing mat"', f"time_limit = {options.minutes * 60:g}")
        Path(folder, "long.toml").write_text('name = "long drawing mat"\n' + world, "utf-8")
        Path(folder, "long.root").write_text("# world: long.toml\n" + DRAWING, "utf-8")
        with served_studio(folder) as (address, _), sync_playwright() as playwright:
            browser = playwright.chromium.launch(executable_path=CHROMIUM,
                                                 args=["--headless", "--no-sandbox"])  # fmt: skip
            page = browser.new_page(viewport={"width": 1400, "height": 850})
            page.goto(f"{address}/?open=long.root")
            page.wait_for_function("() => document.getElementById('state').dataset.ready")
            page.select_option("#speed", "0")
            page.click("#run")
            page.wait_for_function("() => document.getElementById('state').dataset.ended",
                                   timeout=300_000)  # fmt: skip
            page.click("#time")
            page.wait_for_function("() => document.getElementById('state').dataset.timeline")
            length = float(page.eval_on_selector("#time", "slider => slider.max"))
            ink = page.evaluate("""async () => (await import('/static/runs.js')).stage.data.ink
                .reduce((points, stroke) => points + stroke.p.length / 2, 0)""")
            ended = page.eval_on_selector("#state", "e => e.dataset.ended")
            print(
                f"a run of {length:.0f} s ({ended}), {ink} points of ink; "
                f"{options.updates} moves of the slider all over it"
            )
            cdp = page.context.new_cdp_session(page)
            for rate in (1, 4):
                cdp.send("Emulation.setCPUThrottlingRate", {"rate": rate})
                per_second, median, p95 = scrub(page, options.updates)
                print(
                    f"  CPU {'as it is' if rate == 1 else f'slowed {rate}x':<10}: "
                    f"{per_second:5.1f} moves a second, painted (aim >= {AIM_PER_SECOND}); "
                    f"a move's own time {median:5.1f} ms median, {p95:5.1f} ms p95"
                )
            browser.close()


if __name__ == "__main__":
    main()
