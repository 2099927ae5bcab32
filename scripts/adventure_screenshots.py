#!/usr/bin/env python3
"""The pictures of adventures in docs/levels.md: a pupil's list of Level 1's adventures, an
adventure's goal with the hint of a first check, and the teacher's table (a class studio at
Level 1, on a tablet-sized page, through Playwright and Debian's chromium).

    .venv/bin/python scripts/adventure_screenshots.py   # writes docs/adventures-*.png
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from pathlib import Path

DOCS = Path(__file__).resolve().parents[1] / "docs"
READY = "() => document.getElementById('state').dataset.ready === 'yes'"


def main() -> None:
    from playwright.sync_api import sync_playwright

    with tempfile.TemporaryDirectory() as folder:
        studio = subprocess.Popen(
            [sys.executable, "-m", "rootlang", "studio", folder, "--class", "--level", "1",
             "--port", "0", "--no-browser"],
            stdout=subprocess.PIPE, text=True,
        )  # fmt: skip
        try:
            assert studio.stdout is not None
            address = re.search(r"http://[0-9.:]+", studio.stdout.readline())
            code = re.search(r"code (\d+)", studio.stdout.readline())
            assert address and code, "the studio did not say where it serves, or the code"
            with sync_playwright() as playwright:
                browser = playwright.chromium.launch(
                    executable_path="/usr/bin/chromium", args=["--headless", "--no-sandbox"]
                )
                pupil = browser.new_page(viewport={"width": 1024, "height": 700})
                pupil.goto(address.group(0))
                pupil.fill("#name", "Mia")
                with pupil.expect_navigation():
                    pupil.click("#join button")
                pupil.wait_for_function(READY)
                pupil.click("#adventures-open")
                pupil.wait_for_selector("#adventure-list[open]")
                pupil.wait_for_timeout(300)
                pupil.screenshot(path=str(DOCS / "adventures-list.png"))
                pupil.click("[data-adventure='04-draw-a-square']")
                pupil.wait_for_function(
                    "() => document.getElementById('state').dataset.adventure !== ''"
                )
                pupil.click("#check")
                pupil.wait_for_function(
                    "() => document.getElementById('state').dataset.checked === 'failed'"
                )
                pupil.screenshot(path=str(DOCS / "adventures-goal.png"))
                teacher = browser.new_page(viewport={"width": 1024, "height": 700})
                teacher.goto(address.group(0) + "/teacher")
                teacher.fill("#code", code.group(1))
                teacher.click("#login button")
                teacher.wait_for_selector("#progress:not([hidden]) td")
                teacher.locator("#progress").screenshot(path=str(DOCS / "adventures-teacher.png"))
                for name in ("list", "goal", "teacher"):
                    print(f"wrote docs/adventures-{name}.png")
                browser.close()
        finally:
            studio.terminate()
            studio.wait()


if __name__ == "__main__":
    main()
