"""The generated blocks in real Blockly, in headless Chromium (Debian's package).

Every gallery program's workspace loads into Blockly 13 with no warning, serialises back to
the same workspace, and that gives the same text again; the toolbox opens; no request leaves
localhost. Skips with a reason when chromium or Playwright is missing (`.ci/run` installs
chromium). With ROOTLANG_SCREENSHOTS=1 it also refreshes the picture in docs/blocks.md.
"""

from __future__ import annotations

import contextlib
import functools
import http.server
import json
import os
import shutil
import threading
from collections.abc import Iterator
from importlib import resources
from pathlib import Path
from typing import Any

import pytest

from rootlang.blocks import block_definitions, script_text, to_text, to_workspace, toolbox
from rootlang.formatting import format_source

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
REPO = Path(__file__).resolve().parents[2]
GALLERY = sorted(path for path in (REPO / "programs").glob("*.root"))
playwright = pytest.importorskip("playwright.sync_api", reason="Playwright for Python is missing")
pytestmark = [
    pytest.mark.skipif(
        CHROMIUM is None, reason="chromium is not installed (apt-get install chromium)"
    ),
    pytest.mark.slow,
]

PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>rootlang blocks</title></head>
<body style="margin:0">
<div id="blocks" style="width:1100px;height:800px"></div>
<script src="blockly/blockly_compressed.js"></script>
<script src="blockly/blocks_compressed.js"></script>
<script src="blockly/msg/en.js"></script>
<script type="module">
  import {install, attach} from "./root_blocks.js";
  const definitions = __DEFINITIONS__;
  const toolbox = __TOOLBOX__;
  install(Blockly, definitions);
  const workspace = Blockly.inject("blocks", {toolbox: toolbox, media: "blockly/media/",
                                             renderer: "zelos", trashcan: true});
  attach(workspace, toolbox);
  window.roundTrip = function (state) {
    workspace.clear();
    Blockly.serialization.workspaces.load(state, workspace);
    return Blockly.serialization.workspaces.save(workspace);
  };
</script>
</body></html>
"""


@contextlib.contextmanager
def blocks_site(root: Path, pages: dict[str, str]) -> Iterator[str]:
    """A static site on 127.0.0.1: these pages (file name -> HTML), the vendored Blockly and
    root_blocks.js; its address."""
    vendor = resources.files("rootlang").joinpath("studio/static/vendor/blockly")
    shutil.copytree(str(vendor), root / "blockly")
    (root / "root_blocks.js").write_text(script_text(), encoding="utf-8")
    for name, html in pages.items():
        (root / name).write_text(html, encoding="utf-8")
    handler = functools.partial(_QuietHandler, directory=str(root))
    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    try:
        yield f"http://127.0.0.1:{server.server_address[1]}/"
    finally:
        server.shutdown()


@pytest.fixture(scope="module")
def site(tmp_path_factory: pytest.TempPathFactory) -> Iterator[str]:
    page = PAGE.replace("__DEFINITIONS__", json.dumps(block_definitions()))
    page = page.replace("__TOOLBOX__", json.dumps(toolbox()))
    with blocks_site(tmp_path_factory.mktemp("site"), {"index.html": page}) as address:
        yield address


class _QuietHandler(http.server.SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        pass


@pytest.fixture(scope="module")
def browser_page(site: str) -> Iterator[tuple[Any, list[str], list[str]]]:
    with playwright.sync_playwright() as driver:
        browser = driver.chromium.launch(
            executable_path=CHROMIUM,
            args=[
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--disable-background-networking",
                "--disable-component-update",
                "--no-first-run",
            ],
        )
        page = browser.new_page(viewport={"width": 1100, "height": 800})
        messages: list[str] = []
        outside: list[str] = []
        page.on("console", lambda message: messages.append(f"{message.type}: {message.text}"))
        page.on("pageerror", lambda error: messages.append(f"pageerror: {error}"))

        def route(request_route: Any) -> None:
            url = request_route.request.url
            if url.startswith(site) or url.startswith("data:"):
                request_route.continue_()
            else:
                outside.append(url)
                request_route.abort()

        page.route("**/*", route)
        page.goto(site)
        page.wait_for_function("typeof window.roundTrip === 'function'")
        yield page, messages, outside
        browser.close()


@pytest.mark.parametrize("path", GALLERY, ids=lambda path: path.name)
def test_every_gallery_program_round_trips_through_real_blockly(
    browser_page: tuple[Any, list[str], list[str]], path: Path
) -> None:
    page, messages, outside = browser_page
    source = path.read_text(encoding="utf-8")
    workspace = to_workspace(source, path.name)
    saved = page.evaluate("state => window.roundTrip(state)", workspace)
    problems = [m for m in messages if not m.startswith(("log:", "debug:", "info:"))]
    assert problems == []
    assert outside == []
    assert _without_positions(saved) == _without_positions(workspace)
    assert to_text(saved) == format_source(source)


def test_a_program_of_comments_only_round_trips_as_a_workspace_comment(
    browser_page: tuple[Any, list[str], list[str]],
) -> None:
    page, messages, _ = browser_page
    source = "# a plan for later\n\n# first the square\n"
    saved = page.evaluate("state => window.roundTrip(state)", to_workspace(source))
    assert to_text(saved) == source
    assert [m for m in messages if m.startswith(("error", "warning", "pageerror"))] == []


def test_the_toolbox_opens_every_category_and_its_blocks_work_as_they_are(
    browser_page: tuple[Any, list[str], list[str]],
) -> None:
    page, messages, outside = browser_page
    names = page.evaluate(
        """() => {
            const toolbox = Blockly.getMainWorkspace().getToolbox();
            const shown = [];
            for (const item of toolbox.getToolboxItems()) {
                toolbox.setSelectedItem(item);
                shown.push(item.getName ? item.getName() : "");
            }
            return shown;
        }"""
    )
    assert names[:3] == ["Events", "Motion", "Drawing"] and "Procedures" in names
    assert [m for m in messages if m.startswith(("error", "warning", "pageerror"))] == []
    assert outside == []


def test_the_procedures_category_offers_a_call_for_each_procedure(
    browser_page: tuple[Any, list[str], list[str]],
) -> None:
    page, messages, _ = browser_page
    polygons = (REPO / "programs" / "polygons.root").read_text(encoding="utf-8")
    page.evaluate("state => window.roundTrip(state)", to_workspace(polygons))
    offered = page.evaluate(
        """() => {
            const workspace = Blockly.getMainWorkspace();
            const toolbox = workspace.getToolbox();
            const category = toolbox.getToolboxItems().find(i => i.getName() === "Procedures");
            toolbox.setSelectedItem(category);
            const shown = workspace.getFlyout().getWorkspace().getTopBlocks(true);
            return shown.map(block => [block.type,
                JSON.stringify(block.saveExtraState ? block.saveExtraState() : null)]);
        }"""
    )
    assert ["root_call", '{"name":"polygon","values":2}'] in offered
    assert offered[0][0] == "root_procedure"
    assert [m for m in messages if m.startswith(("error", "warning", "pageerror"))] == []


def test_a_picture_of_the_flower_as_blocks(
    browser_page: tuple[Any, list[str], list[str]], tmp_path: Path
) -> None:
    page, _, _ = browser_page
    flower = (REPO / "programs" / "flower.root").read_text(encoding="utf-8")
    page.evaluate("state => window.roundTrip(state)", to_workspace(flower))
    picture = tmp_path / "flower-blocks.png"
    page.locator(".blocklyMainBackground").first.wait_for()
    page.screenshot(path=str(picture), clip={"x": 0, "y": 0, "width": 760, "height": 540})
    assert picture.stat().st_size > 5_000  # a real picture, not a blank page
    if os.environ.get("ROOTLANG_SCREENSHOTS"):
        shutil.copy(picture, REPO / "docs" / "blocks-flower.png")


def _without_positions(workspace: dict[str, Any]) -> dict[str, Any]:
    """Blockly moves top blocks to where they fit; everything else must be the same."""
    copy: dict[str, Any] = json.loads(json.dumps(workspace))
    for block in copy.get("blocks", {}).get("blocks", []):
        block.pop("x", None)
        block.pop("y", None)
    return copy
