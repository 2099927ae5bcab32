"""Levels: switching a 200-block program between Level 1 (picture blocks), Level 2 (word
blocks) and Level 3 (text) in the studio, in real headless Chromium (aim ≤ 0.5 s a switch),
and the server's part of it (text -> Level 1 blocks) on its own.

    .venv/bin/python benchmarks/levels.py
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

from studio_process import served_studio  # (this folder's: the script's own is on sys.path)

from rootlang.blocks import pictures, to_workspace

CHROMIUM = "/usr/bin/chromium"
LINES = (
    "marker down", "move forward 30 cm", "turn right 90 degrees", "light green",
    "play note E4 for 0.5 seconds", "wait 2 seconds", "turn left 90 degrees", "marker up",
)  # fmt: skip


def program(blocks: int) -> str:
    """Scripts of picture blocks' lines, ``blocks`` blocks in all (a hat and its 49 lines)."""
    text: list[str] = []
    for index in range(blocks):
        if index % 50 == 0:
            text.append(("\n" if text else "") + "when started")
        else:
            text.append("    " + LINES[index % len(LINES)])
    return "\n".join(text) + "\n"


def server_part(source: str) -> float:
    times = []
    for _ in range(7):
        start = time.perf_counter()
        pictures.to_pictures(to_workspace(source))
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def browser_part(source: str) -> dict[str, float]:
    from playwright.sync_api import sync_playwright

    with tempfile.TemporaryDirectory() as folder:
        Path(folder, "big.root").write_text(source, encoding="utf-8")
        with served_studio(folder) as (address, _), sync_playwright() as playwright:
            arguments = ["--headless", "--no-sandbox"]
            browser = playwright.chromium.launch(executable_path=CHROMIUM, args=arguments)
            page = browser.new_page(viewport={"width": 1024, "height": 768})
            page.goto(f"{address}/?open=big.root&level=2")
            page.wait_for_function("() => document.getElementById('state').dataset.ready")
            figures: dict[str, list[float]] = {}
            for _ in range(3):
                for level in (1, 2, 3, 2):
                    took = page.evaluate("""async n => {
                            const levels = await import('/static/levels.js');
                            const start = performance.now();
                            await levels.chooseLevel(n);
                            await Blockly.renderManagement.finishQueuedRenders();
                            return (performance.now() - start) / 1000;
                        }""", level)  # fmt: skip
                    figures.setdefault(f"to Level {level}", []).append(took)
            count = page.evaluate("() => Blockly.getMainWorkspace().getAllBlocks(false).length")
            browser.close()
    print(f"  blocks on the workspace at Level 2 (values too): {count}")
    return {name: statistics.median(times) for name, times in figures.items()}


def main() -> None:
    source = program(200)
    _, above = pictures.to_pictures(to_workspace(source))
    assert above == [], above
    print("Levels: a program of 200 picture blocks")
    print(f"  server, text -> Level 1 blocks: {server_part(source) * 1000:.0f} ms")
    for name, seconds in browser_part(source).items():
        print(f"  studio, switch {name}: {seconds * 1000:.0f} ms (aim ≤ 500 ms)")


if __name__ == "__main__":
    main()
