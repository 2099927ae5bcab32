#!/usr/bin/env python3
"""The pictures in docs/levels.md: the studio at Level 1, 2 and 3, each with its toolbox open,
on a tablet-sized page (Debian's chromium, through Playwright).

    .venv/bin/python scripts/level_screenshots.py     # writes docs/levels-1.png ... -3.png
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

DOCS = Path(__file__).resolve().parents[1] / "docs"
SQUARE = """when started
    marker down
    repeat 4
        move forward 30 cm
        turn right 90 degrees
    marker up
    light green
    play note C4 for 0.5 seconds
"""
OPEN = {  # level -> the toolbox category shown open
    1: "⬆",
    2: "Motion",
    3: "",
}


def main() -> None:
    from playwright.sync_api import sync_playwright

    with tempfile.TemporaryDirectory() as folder:
        Path(folder, "square.root").write_text(SQUARE, encoding="utf-8")
        studio = subprocess.Popen(
            [sys.executable, "-m", "rootlang", "studio", folder, "--port", "0", "--no-browser"],
            stdout=subprocess.PIPE, text=True,
        )  # fmt: skip
        try:
            assert studio.stdout is not None
            address = ""
            while not address:
                found = re.search(r"http://[0-9.:]+", studio.stdout.readline())
                address = found.group(0) if found else ""
            with sync_playwright() as playwright:
                arguments = ["--headless", "--no-sandbox"]
                browser = playwright.chromium.launch(executable_path="/usr/bin/chromium",
                                                     args=arguments)  # fmt: skip
                page = browser.new_page(viewport={"width": 1024, "height": 640})
                for level, category in OPEN.items():
                    page.goto(f"{address}/?open=square.root&level={level}")
                    page.wait_for_function(
                        "() => document.getElementById('state').dataset.ready === 'yes'"
                    )
                    if category:  # (the scripts moved out from under the open toolbox)
                        page.evaluate("""() => Blockly.getMainWorkspace().getTopBlocks(false)
                            .forEach(block => block.moveBy(300, 0))""")
                        page.locator(".blocklyToolboxCategory", has_text=category).first.click()
                        page.wait_for_timeout(400)
                    if level == 1:  # a finger on the forward block: what it does, in words
                        page.locator(".blocklyFlyout .blocklyDraggable").first.hover()
                        page.wait_for_timeout(200)
                    page.screenshot(path=str(DOCS / f"levels-{level}.png"))
                    print(f"wrote docs/levels-{level}.png")
                browser.close()
        finally:
            studio.terminate()
            studio.wait()


if __name__ == "__main__":
    main()
