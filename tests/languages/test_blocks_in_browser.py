"""Blocks in each language in real Blockly (headless Chromium, Debian's package): the labels
and menus show the language, Blockly's own blocks speak it through its msg file, and a
workspace saved by Blockly still gives the same program. With ROOTLANG_SCREENSHOTS=1 it also
refreshes the picture in docs/languages.md."""

from __future__ import annotations

import json
import os
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from blocks.test_in_browser import CHROMIUM, PAGE, _without_positions, blocks_site

from rootlang.blocks import block_definitions, to_text, to_workspace, toolbox
from rootlang.formatting import format_source
from rootlang.locale.blocks import BLOCKLY_MESSAGES
from rootlang.locale.translate import from_english

REPO = Path(__file__).resolve().parents[2]
PROGRAMS = [REPO / "programs" / name for name in ("flower.root", "line_follower.root")]
# a word each language's labels show, and what Blockly's own `if` block says in it
EXPECTED = {
    "nl": ("wanneer", "als"),
    "es": ("cuando", "si"),
    "fr": ("quand", "si"),
    "de": ("wenn", "falls"),
}
playwright = pytest.importorskip("playwright.sync_api", reason="Playwright for Python is missing")
pytestmark = [
    pytest.mark.skipif(
        CHROMIUM is None, reason="chromium is not installed (apt-get install chromium)"
    ),
    pytest.mark.slow,
]


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    """The blocks page once per language (``nl.html`` ...), served on 127.0.0.1."""
    pages = {}
    for language in EXPECTED:
        page = PAGE.replace("blockly/msg/en.js", BLOCKLY_MESSAGES[language].replace("vendor/", ""))
        page = page.replace("__DEFINITIONS__", json.dumps(block_definitions(language)))
        pages[f"{language}.html"] = page.replace("__TOOLBOX__", json.dumps(toolbox(language)))
    with blocks_site(tmp_path_factory.mktemp("site"), pages) as address:
        yield address


@pytest.fixture(scope="module")
def browser(site: str) -> Iterator[Any]:
    with playwright.sync_playwright() as driver:
        launched = driver.chromium.launch(
            executable_path=CHROMIUM,
            args=["--headless", "--no-sandbox", "--disable-gpu", "--no-first-run"],
        )
        yield launched
        launched.close()


@pytest.mark.parametrize("language", sorted(EXPECTED))
def test_blocks_show_the_language_and_still_give_the_same_program(
    browser: Any, site: str, language: str, tmp_path: Path
) -> None:
    page = browser.new_page(viewport={"width": 1100, "height": 800})
    problems: list[str] = []
    page.on("pageerror", lambda error: problems.append(str(error)))
    page.on(
        "console",
        lambda message: problems.append(message.text) if message.type == "error" else None,
    )

    def only_this_site(route: Any) -> None:
        if route.request.url.startswith(site):
            route.continue_()
        else:
            problems.append(route.request.url)
            route.abort()

    page.route("**/*", only_this_site)
    page.goto(site + f"{language}.html")
    page.wait_for_function("typeof window.roundTrip === 'function'")
    word, if_word = EXPECTED[language]
    for program in PROGRAMS:
        source = from_english(program.read_text(encoding="utf-8"), language)
        workspace = to_workspace(source, program.name, language=language)
        saved = page.evaluate("state => window.roundTrip(state)", workspace)
        assert _without_positions(saved) == _without_positions(workspace)
        declared = f"# language: {language}\n"
        assert declared + to_text(saved, language) == format_source(declared + source)
        shown = page.evaluate(
            "() => [...document.querySelectorAll('.blocklyText')].map(t => t.textContent)"
        )
        words = " ".join(shown).split()
        assert word in words, shown
    assert if_word in words  # line_follower has an `if`: Blockly's own block, from its msg file
    assert problems == []
    if language == "nl" and os.environ.get("ROOTLANG_SCREENSHOTS"):
        flower = from_english((REPO / "programs" / "flower.root").read_text("utf-8"), "nl")
        page.evaluate("state => window.roundTrip(state)", to_workspace(flower, language="nl"))
        page.screenshot(
            path=str(REPO / "docs" / "languages-blocks-nl.png"),
            clip={"x": 0, "y": 0, "width": 760, "height": 540},
        )
    page.close()
