"""The studio on a slow school Chromebook: the page's CPU slowed 4x (Chrome DevTools'
``Emulation.setCPUThrottlingRate``, as ``benchmarks/studio_chromebook.py`` measures its speed),
a child's work is all kept. What a slow machine changes is the order things finish in: keys
come faster than the blocks are made, a run starts while the text is still on its way to the
blocks. Nothing here is timed (the benchmark does that); every wait is for what the page says
(its ``#state``), with room for a slowed page on a busy computer."""

from __future__ import annotations

import json
from typing import Any

from rootlang import ast
from rootlang.checks import parse
from rootlang.studio.complete import complete_text

from .browser import WAIT_MS, Page
from .conftest import RunningStudio

SLOWER = 4  # a school Chromebook (benchmarks/studio_chromebook.py)
SLOW_WAIT_MS = 3 * WAIT_MS  # a slowed page on a busy computer: room, never a measure
# (as JSON text: a long script's blocks nest deeper than Playwright carries objects)
WORKSPACE = (
    "() => JSON.stringify(Blockly.serialization.workspaces.save(Blockly.common.getMainWorkspace()))"
)


def slowed(page: Page) -> Page:
    """``page`` with its CPU slowed :data:`SLOWER` times, from now on."""
    session = page.page.context.new_cdp_session(page.page)
    session.send("Emulation.setCPUThrottlingRate", {"rate": SLOWER})
    return page


def open_slowly(page: Page, name: str) -> None:
    page.page.goto(f"{page.studio.address}/?open={name}", timeout=SLOW_WAIT_MS)
    page.wait_state("ready", "yes", SLOW_WAIT_MS)
    page.wait_state("open", name, SLOW_WAIT_MS)


def in_step(page: Page) -> ast.Program:
    """The program the text pane holds, once the blocks have caught up: the blocks read as
    the same program (the studio's own conversion, as Save makes it)."""
    page.wait_state("textSynced", "yes", SLOW_WAIT_MS)
    text = page.text()
    workspace: dict[str, Any] = json.loads(page.js(WORKSPACE))
    made, left_out = complete_text(workspace)
    assert left_out == [], left_out
    program = parse(text, "typed.root")
    assert ast.same_tree(made.program, program), (made.text, text)
    return program


def test_on_a_slow_chromebook_typing_running_and_saving_lose_nothing(
    page: Page, studio: RunningStudio
) -> None:
    slowed(page)
    open_slowly(page, "square.root")
    square = page.text()
    # a new script typed as fast as the keys go, and Run pressed before the blocks follow
    page.type_at_the_end("\nwhen bumped\n")
    page.page.keyboard.press("Tab")
    page.page.keyboard.type('say "ouch"\nlight red\n')
    typed = square.rstrip("\n") + '\n\nwhen bumped\n    say "ouch"\n    light red\n    '
    assert page.text() == typed
    page.page.click("#run")
    page.wait_state("running", "yes", SLOW_WAIT_MS)
    # typing while it runs (back in the text: Run gave Stop the focus): every key kept, in the
    # text and then on the blocks
    page.type_at_the_end("print 1\n")
    page.page.keyboard.press("Shift+Tab")
    page.page.keyboard.type("# typed while it ran\n")
    page.page.click("#stop")  # (its `when bumped` would wait for a bump till the time limit)
    assert page.wait_ended(SLOW_WAIT_MS) == "stopped"
    typed += "print 1\n# typed while it ran\n"
    assert page.text() == typed
    program = in_step(page)
    # saved, and opened again: the same program
    page.page.click("#save")
    page.wait_state("saved", "square.root", SLOW_WAIT_MS)
    saved = (studio.folder / "square.root").read_text(encoding="utf-8")
    assert ast.same_tree(parse(saved, "square.root"), program), saved
    page.page.reload(timeout=SLOW_WAIT_MS)
    page.wait_state("open", "square.root", SLOW_WAIT_MS)
    assert page.text() == saved
    assert ast.same_tree(in_step(page), program)


LONG = "when started\n    marker down\n    repeat 4\n" + "".join(
    f"        move {1 + i % 3} cm\n        turn right {5 + i % 7} degrees\n" for i in range(60)
)


def test_on_a_slow_chromebook_a_long_program_keeps_the_keys_typed_while_its_blocks_come(
    page: Page, studio: RunningStudio
) -> None:
    (studio.folder / "long.root").write_text(LONG, encoding="utf-8")
    slowed(page)
    open_slowly(page, "long.root")
    # typed at once, while the 123 lines' blocks may still be on their way
    page.type_at_the_end('    say "done"\n')
    typed = LONG + '    say "done"\n'
    assert page.text().rstrip(" ") == typed
    program = in_step(page)
    assert ast.same_tree(program, parse(typed, "long.root"))
    blocks: int = page.js("() => Blockly.getMainWorkspace().getAllBlocks(false).length")
    assert blocks >= LONG.count("\n") + 1  # (a block a line at least: each move's, each turn's)
