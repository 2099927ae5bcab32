"""500 random workspaces made by real Blockly 13 (headless Chromium, the vendored Blockly and
root_blocks.js): scripts built from the toolbox's own blocks, values plugged in, loose blocks,
and comments of every kind (on statement blocks, on value blocks, on the workspace; empty,
starting with `#`, several lines, spaces, Unicode). Each as Blockly saves it either becomes a
program (a fixed point of `format`, with every comment line in it, that comes back through
Blockly as the same text) or is refused with an E70x — never text rootlang can't read.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from typing import Any

import pytest

from rootlang.blocks import block_definitions, to_text, to_workspace, toolbox
from rootlang.diagnostics import RootlangError
from rootlang.formatting import format_source

from .test_in_browser import CHROMIUM, blocks_site, playwright

pytestmark = [
    pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed"),
    pytest.mark.slow,
]
WORKSPACES = 500
BATCH = 50

PAGE = """<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Blockly-made workspaces</title></head>
<body style="margin:0">
<div id="blocks" style="width:1000px;height:700px"></div>
<script src="blockly/blockly_compressed.js"></script>
<script src="blockly/blocks_compressed.js"></script>
<script src="blockly/msg/en.js"></script>
<script type="module">
  import {install, attach} from "./root_blocks.js";
  const toolbox = __TOOLBOX__;
  install(Blockly, __DEFINITIONS__);
  const workspace = Blockly.inject("blocks", {toolbox: toolbox, media: "blockly/media/"});
  attach(workspace, toolbox);
  const items = toolbox.contents.flatMap(category => category.contents || [])
    .filter(item => item.kind === "block").map(({kind, ...block}) => block);
  // each toolbox block's kind, as Blockly builds it
  const kinds = {hat: [], statement: [], value: []};
  for (const item of items) {
    const block = Blockly.serialization.blocks.append(item, workspace);
    const kind = block.outputConnection ? "value" : block.previousConnection ? "statement" : "hat";
    if (item.type !== "root_procedure") kinds[kind].push(item);
  }
  workspace.clear();
  const COMMENTS = ["draw it", "#x", "# heading", "", " leading space", "##", "two\\nlines",
    "ünïcode ☃", "a\\n\\nb", "   ", "#", "trailing  ", "# #x", "\\tTab", "x\\n#\\ny"];

  window.makeWorkspaces = function (first, count) {
    const made = [];
    for (let seed = first; seed < first + count; seed++) made.push(makeWorkspace(seed));
    return made;
  };

  function makeWorkspace(seed) {
    let state = seed * 2654435761 >>> 0;
    const random = () => {  // mulberry32
      state = (state + 0x6D2B79F5) >>> 0;
      let t = state;
      t = Math.imul(t ^ (t >>> 15), t | 1);
      t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
      return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
    const pick = list => list[Math.floor(random() * list.length)];
    const make = item => Blockly.serialization.blocks.append(item, workspace);
    const comment = block => { if (random() < 0.3) block.setCommentText(pick(COMMENTS)); };
    workspace.clear();
    const variable = workspace.getVariableMap().createVariable(pick(["count", "size", "speed"]));

    function plugValues(block, depth) {
      for (const input of block.inputList) {
        const connection = input.connection;
        if (!connection || connection.type !== Blockly.ConnectionType.INPUT_VALUE) continue;
        if (depth < 2 && random() < 0.3) {
          const value = random() < 0.15
            ? make({type: "variables_get", fields: {VAR: {id: variable.getId()}}})
            : make(pick(kinds.value));
          try { connection.connect(value.outputConnection); }
          catch (error) { value.dispose(); continue; }
          plugValues(value, depth + 1);
        }
        const target = connection.targetBlock();
        if (target && !target.isShadow()) comment(target);
      }
    }

    function statement(depth) {
      const roll = random();
      const block = roll < 0.08
        ? make({type: "variables_set", fields: {VAR: {id: variable.getId()}},
                inputs: {VALUE: {shadow: {type: "root_number", fields: {NUM: 3}}}}})
        : roll < 0.12 ? make({type: "root_print", extraState: {values: Math.floor(random() * 3)}})
        : roll < 0.14 ? make({type: "root_say", inputs: {TEXT: {block: {type: "root_join",
                                extraState: {values: Math.floor(random() * 3)}}}}})
        : make(pick(kinds.statement));
      plugValues(block, 0);
      comment(block);
      for (const input of block.inputList) {
        if (input.connection && input.connection.type === Blockly.ConnectionType.NEXT_STATEMENT
            && depth < 2 && random() < 0.85) {
          chain(input.connection, depth + 1, 1 + Math.floor(random() * 3));
        }
      }
      return block;
    }

    function chain(connection, depth, length) {
      for (let i = 0; i < length; i++) {
        const block = statement(depth);
        connection.connect(block.previousConnection);
        connection = block.nextConnection;
        if (!connection) return;
      }
    }

    for (let script = 0; script < 1 + Math.floor(random() * 3); script++) {
      const hat = make(pick(kinds.hat));
      hat.moveBy(20, 20 + script * 400);
      plugValues(hat, 0);
      comment(hat);
      const body = hat.inputList.find(input => input.connection
        && input.connection.type === Blockly.ConnectionType.NEXT_STATEMENT);
      if (body && random() < 0.95) chain(body.connection, 1, 1 + Math.floor(random() * 4));
    }
    if (random() < 0.08) statement(1).moveBy(600, 40);  // a loose block
    if (random() < 0.4) {
      Blockly.serialization.workspaceComments.append(
        {text: pick(COMMENTS), x: 500, y: 20, width: 200, height: 100}, workspace);
    }
    return Blockly.serialization.workspaces.save(workspace);
  }

  window.roundTrip = function (saved) {
    workspace.clear();
    Blockly.serialization.workspaces.load(saved, workspace);
    return Blockly.serialization.workspaces.save(workspace);
  };
</script>
</body></html>
"""


@pytest.fixture(scope="module")
def made_page(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Any]:
    page_html = PAGE.replace("__DEFINITIONS__", json.dumps(block_definitions()))
    page_html = page_html.replace("__TOOLBOX__", json.dumps(toolbox()))
    root = tmp_path_factory.mktemp("made")
    with (
        blocks_site(root, {"index.html": page_html}) as address,
        playwright.sync_playwright() as driver,
    ):
        browser = driver.chromium.launch(
            executable_path=CHROMIUM, args=["--headless", "--no-sandbox", "--disable-gpu"]
        )
        page = browser.new_page()
        problems: list[str] = []
        page.on("pageerror", lambda error: problems.append(str(error)))
        page.goto(address)
        page.wait_for_function("typeof window.makeWorkspaces === 'function'")
        yield page, problems
        browser.close()


def comment_lines(saved: dict[str, Any]) -> list[str]:
    """Every non-blank line of every comment a workspace holds, stripped."""
    found: list[str] = []

    def walk(value: object) -> None:
        if isinstance(value, dict):
            comment = value.get("icons", {}).get("comment") if "type" in value else None
            if isinstance(comment, dict):
                found.extend(str(comment.get("text", "")).split("\n"))
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)

    walk(saved.get("blocks", {}))
    for comment in saved.get("workspaceComments", []):
        found.extend(str(comment.get("text", "")).split("\n"))
    return [line.strip().lstrip("#").strip() for line in found if line.strip().lstrip("#").strip()]


def test_500_blockly_made_workspaces_round_trip_with_their_comments(made_page: Any) -> None:
    page, problems = made_page
    outcomes: dict[str, int] = {}
    kinds = {"on value blocks": 0, "on the workspace": 0}
    for first in range(0, WORKSPACES, BATCH):
        for saved in page.evaluate("([a, b]) => makeWorkspaces(a, b)", [first, BATCH]):
            kinds["on the workspace"] += bool(saved.get("workspaceComments"))
            kinds["on value blocks"] += _comments_on_values(saved)
            try:
                text = to_text(saved)
            except RootlangError as error:
                code = error.diagnostics[0].code
                assert code.startswith("E70") and code != "E707", error  # refused, never unreadable
                outcomes[code] = outcomes.get(code, 0) + 1
                continue
            outcomes["text"] = outcomes.get("text", 0) + 1
            assert format_source(text) == text  # a fixed point of format
            written = [line.strip() for line in text.split("\n")]
            for line in comment_lines(saved):  # every comment line reaches the text
                assert any(line in shown for shown in written if shown.startswith("#")), line
            back = page.evaluate("saved => roundTrip(saved)", to_workspace(text))
            assert to_text(back) == text  # and comes back through Blockly as the same text
    assert problems == []
    assert outcomes.get("text", 0) >= WORKSPACES // 2, outcomes
    assert kinds["on value blocks"] >= 50 and kinds["on the workspace"] >= 50, kinds


def _comments_on_values(saved: dict[str, Any]) -> int:
    """Comments on blocks plugged into a value input (not shadows)."""
    count = 0

    def walk(block: dict[str, Any], is_value: bool) -> None:
        nonlocal count
        if is_value and "comment" in block.get("icons", {}):
            count += 1
        for name, connection in block.get("inputs", {}).items():
            for key, child in connection.items():
                statement = name in ("BODY", "ELSE") or name.startswith("DO")
                walk(child, not statement and key == "block")
        following = block.get("next", {}).get("block")
        if following:
            walk(following, False)

    for top in saved.get("blocks", {}).get("blocks", []):
        walk(top, False)
    return count
