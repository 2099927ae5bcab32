"""A child's work is never lost, tried in real Chromium with real mouse drags (page.mouse) as a
child makes them: a block dragged out of its script stays on the workspace, greyed and out of
the text, through text edits, Run, Save and a reload (undo, in both panes: test_undo.py)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

from rootlang.studio.conversions import MOST_BLOCK_LINES
from rootlang.studio.runs import ClassLimits

from .browser import BLOCK, Page
from .conftest import RunningStudio

BLOCKS = "Blockly.getMainWorkspace()"


def _box(page: Page, text_id: str) -> dict[str, float]:
    """Where the block the text's id names is drawn (its own path: not the blocks under it)."""
    return page.drawn(f"{BLOCK}('{text_id}').pathObject.svgPath")


def _drag(page: Page, start: tuple[float, float], end: tuple[float, float]) -> None:
    mouse = page.page.mouse
    mouse.move(*start)
    mouse.down()
    for step in range(1, 11):  # a hand's drag: many small moves
        f = step / 10
        mouse.move(start[0] + (end[0] - start[0]) * f, start[1] + (end[1] - start[1]) * f)
    mouse.up()


def _type_a_script_at_the_end(page: Page, line: str) -> None:
    """Types a new `when started` script with ``line`` at the end of the text, as a child
    would; returns once the page has its blocks (a print block here)."""
    page.type_at_the_end(f"\nwhen started\n    {line}\n")
    page.wait_state("textSynced", "yes")
    page.page.wait_for_function(
        f"() => {BLOCKS}.getAllBlocks(false).some(b => b.type.includes('print'))", timeout=15000
    )


def _loose_ids(page: Page) -> list[str]:
    ids: list[str] = page.js(f"""() => {BLOCKS}.getTopBlocks(false)
        .filter(b => b.getSvgRoot().classList.contains('root-left-out')).map(b => b.id)""")
    return ids


def _drag_say_out(page: Page, line: str = "L8") -> str:
    """Drags `say "done"` (line 8) out of its script onto empty workspace: its id."""
    box = _box(page, line)
    said: str = page.js(f"async () => {BLOCK}('{line}').id")
    _drag(page, (box["x"] + 6, box["y"] + box["h"] / 2), (box["x"] + 380, box["y"] + 160))
    page.wait_state("blocksSynced", "yes")
    page.wait_state("leftOut", "1")
    return said


def test_a_loose_block_survives_text_edits_run_save_and_reload(
    page: Page, studio: RunningStudio
) -> None:
    page.open("square.root")
    said = _drag_say_out(page)
    assert 'say "done"' not in page.text()  # the text is the complete scripts
    assert _loose_ids(page) == [said]  # kept, greyed
    icon = f"{BLOCKS}.getBlockById('{said}').getIcon(Blockly.icons.IconType.WARNING)"
    page.page.wait_for_function(f"() => !!{icon}", timeout=15000)  # set once the text came back
    warning = page.js(f"() => {icon}.getText()")
    assert "when" in warning  # why, in the child's words, on the block itself
    # a text edit elsewhere: the blocks follow, the loose block stays
    _type_a_script_at_the_end(page, 'print "hi"')
    assert _loose_ids(page) == [said]
    # Run: the text runs, the loose block stays
    page.run()
    assert page.wait_ended() == "finished"
    assert _loose_ids(page) == [said]
    # Save: the file is the text; the loose block is in the sidecar only
    saves = int(page.state().get("saves", "0"))
    page.page.click("#save")
    page.wait_state("saves", str(saves + 1))  # (an autosave may have come before)
    saved = (studio.folder / "square.root").read_text(encoding="utf-8")
    assert saved == page.text().rstrip(" ")  # (but the indentation of the line begun)
    assert 'say "done"' not in saved and 'print "hi"' in saved
    sidecar = json.loads((studio.folder / ".square.root.layout.json").read_text(encoding="utf-8"))
    assert [block["type"] for block in sidecar["loose"]] == ["root_say"]
    # reload: the loose block is back, greyed, where it was left
    where = page.js(f"() => {BLOCKS}.getBlockById('{said}').getRelativeToSurfaceXY()")
    page.page.reload()
    page.wait_state("ready", "yes")
    page.wait_state("open", "square.root")
    page.wait_state("leftOut", "1")
    loose = _loose_ids(page)
    assert len(loose) == 1
    again: dict[str, Any] = page.js(
        f"() => {BLOCKS}.getBlockById('{loose[0]}').getRelativeToSurfaceXY()"
    )
    assert (round(again["x"]), round(again["y"])) == (round(where["x"]), round(where["y"]))
    assert 'say "done"' not in page.text()


def test_a_script_grown_by_typing_does_not_line_up_with_a_loose_block(
    page: Page, studio: RunningStudio
) -> None:
    """A loose block lying where a script's next statement will hang is moved away when a
    statement typed at the script's end reaches it (Blockly's bump: two blocks that line up look
    connected), however the page makes and draws the typed block."""
    (studio.folder / "grow.root").write_text("when started\n    move 10 cm\n", encoding="utf-8")
    page.open("grow.root")
    # (a loose `say` whose top is where a second `move`'s bottom will be: lined up with it once
    # the script has one more statement of the same height)
    loose: str = page.js(f"""() => {{
        const last = {BLOCKS}.getAllBlocks(false).find(b => b.type === 'root_move');
        const say = {BLOCKS}.newBlock('root_say');
        say.initSvg(); say.render();
        const at = last.nextConnection, top = say.previousConnection;
        say.moveBy(at.x - top.x, at.y - top.y + last.height);
        return say.id; }}""")
    page.wait_state("leftOut", "1")
    page.wait_state("blocksSynced", "yes")
    # (the page's frames held: Blockly's own renders after them, which bump too, wait)
    page.js(HOLD_FRAMES)
    page.type_at_the_end("    move 5 cm\n")
    page.wait_state("textSynced", "yes")
    page.page.wait_for_function(
        f"() => {BLOCKS}.getAllBlocks(false).filter(b => b.type === 'root_move').length === 2"
    )
    apart = page.js(f"""() => {{
        const moves = {BLOCKS}.getAllBlocks(false).filter(b => b.type === 'root_move');
        const at = moves[1].nextConnection;
        const top = {BLOCKS}.getBlockById('{loose}').previousConnection;
        return Math.hypot(at.x - top.x, at.y - top.y); }}""")
    page.js(GIVE_FRAMES)
    assert apart > page.js("() => Blockly.config.snapRadius")


def test_a_text_edit_keeps_the_scripts_it_does_not_touch(page: Page) -> None:
    """Ids are the page's own and stable: typing in the text leaves an untouched script's
    blocks as they were (the very blocks, where the child put them)."""
    page.open("square.root")
    _type_a_script_at_the_end(page, 'print "one"')
    before: list[str] = page.js(f"() => {BLOCKS}.getAllBlocks(true).map(b => b.id)")
    page.page.keyboard.press("Control+End")  # (the new line is indented as the one above)
    page.page.keyboard.type('print "two"')  # the new script changes; the square does not
    page.page.wait_for_function(
        f"""() => {BLOCKS}.getAllBlocks(false).filter(b => b.type.includes('print')).length
                 === 2""",
        timeout=15000,
    )
    after: list[str] = page.js(f"() => {BLOCKS}.getAllBlocks(true).map(b => b.id)")
    square: list[str] = page.js(f"async () => {BLOCK}('L2').getDescendants(true).map(b => b.id)")
    assert set(square) <= set(before) and set(square) <= set(after)


def test_a_text_edit_makes_only_the_statement_typed(page: Page) -> None:
    """The page compares the text's blocks before and after the edit (blocks.js fitChanged):
    the new statement is made where it goes, the rest of its script stays the very blocks, and
    no block is loaded again to compare (no hidden workspace). After a block edit of the child's
    the page compares with the live blocks again."""
    page.open("square.root")
    page.wait_state("textSynced", "yes")
    page.js("""() => { window.hidden = 0; const Made = Blockly.Workspace;
        Blockly.Workspace = class extends Made {
            constructor(...options) { super(...options); window.hidden++; } }; }""")
    before: list[str] = page.js(f"async () => {BLOCK}('L2').getDescendants(true).map(b => b.id)")
    page.type_at_the_end('    say "again"')  # (under `say "done"`, in the square's script)
    page.wait_state("textSynced", "yes")
    page.page.wait_for_function(
        f"() => {BLOCKS}.getAllBlocks(false).filter(b => b.type === 'root_say').length === 2"
    )
    assert page.js("() => window.hidden") == 0
    after: list[str] = page.js(f"async () => {BLOCK}('L2').getDescendants(true).map(b => b.id)")
    assert set(before) < set(after)  # the same blocks, and the new one among them
    assert page.js(f"async () => {BLOCK}('L9').getRootBlock().id") == after[0]
    # the child moves a block: the blocks are theirs now, compared as they are at the next edit
    page.js(f"async () => {{ const turn = await {BLOCK}('L6'); turn.unplug(true);"
            " turn.moveBy(300, 100); }")  # fmt: skip
    page.wait_state("blocksSynced", "yes")
    page.type_at_the_end('    say "and again"')
    page.wait_state("textSynced", "yes")
    page.page.wait_for_function(
        f"() => {BLOCKS}.getAllBlocks(false).filter(b => b.type === 'root_say').length === 3"
    )
    assert page.js("() => window.hidden") >= 1


def test_typing_while_the_blocks_are_on_their_way_to_the_text_is_kept(page: Page) -> None:
    """The blocks' text comes back while the child types: the typed lines stay, the blocks'
    lines join them (the answer is held back here until the typing is done, and the typing's
    own round is made to finish first, as a busy computer may have it)."""
    page.open("square.root")
    held: list[Any] = []

    def hold(route: Any) -> None:
        held.append(route)

    page.page.route("**/api/text*", hold)
    box = _box(page, "L8")
    said: str = page.js(f"async () => {BLOCK}('L8').id")
    with page.page.expect_request("**/api/text*", timeout=15000):  # (0.1 s after the drop)
        _drag(page, (box["x"] + 6, box["y"] + box["h"] / 2), (box["x"] + 380, box["y"] + 160))
    for _ in range(100):  # its route comes right after it (each round trip lets it in)
        if held:
            break
        page.js("() => 0")
    assert held, "the blocks' text was asked for"
    page.type_at_the_end('\nwhen started\n    print "hi"\n')
    page.js("async () => (await import('/static/sync.js')).textChanged()")  # the text's round
    page.page.unroute("**/api/text*", hold)
    for route in held:
        route.continue_()
    page.wait_state("blocksSynced", "yes")
    page.wait_state("textSynced", "yes")
    text = page.text()
    assert 'print "hi"' in text and 'say "done"' not in text and "repeat 4" in text
    assert _loose_ids(page) == [said]
    assert page.js(f"() => {BLOCKS}.getBlocksByType('root_print', false).length") == 1


def test_two_edits_of_one_text_made_at_once_are_put_together(page: Page) -> None:
    """The page's merge, over many random pairs of edits of different lines: both are kept;
    edits of the same lines are refused (never one written over the other). (Lines here are
    all different: where lines repeat, another reading of the same edits is as right.)"""
    page.open("square.root")
    outcome: dict[str, int] = page.js(r"""async () => {
        const {mergeEdits} = await import('/static/textmerge.js');
        let seed = 7;
        const random = n => { seed = (seed * 1103515245 + 12345) % 2147483648; return seed % n; };
        let made = 0;
        const lines = (n, who) => Array.from({length: n}, () => who + ' ' + made++);
        const counts = {merged: 0, wrong: 0};
        for (let i = 0; i < 2000; i++) {
            const base = [...lines(random(12), 'base'), 'the end'];  // (a text is a line or more)
            const n = base.length - 1;
            const cut = random(n + 1);                    // ours before the cut, theirs after
            const oFrom = random(cut + 1), oTo = oFrom + random(cut - oFrom + 1);
            const tFrom = cut + random(n - cut + 1), tTo = tFrom + random(n - tFrom + 1);
            const oNew = lines(random(3), 'ours'), tNew = lines(random(3), 'theirs');
            const ours = [...base.slice(0, oFrom), ...oNew, ...base.slice(oTo)];
            const theirs = [...base.slice(0, tFrom), ...tNew, ...base.slice(tTo)];
            const both = [...base.slice(0, oFrom), ...oNew, ...base.slice(oTo, tFrom), ...tNew,
                          ...base.slice(tTo)];
            const merged = mergeEdits(base.join('\n'), ours.join('\n'), theirs.join('\n'));
            counts[merged === both.join('\n') ? 'merged' : 'wrong']++;
        }
        counts.sameLines = mergeEdits('a\nb\nc', 'a\nB\nc', 'a\nb2\nc') === null ? 1 : 0;
        return counts;
    }""")
    assert outcome == {"merged": 2000, "wrong": 0, "sameLines": 1}


def _empty_workspace(page: Page) -> tuple[float, float]:
    box: dict[str, float] = page.js("""() => {
        const r = document.getElementById('blocks').getBoundingClientRect();
        return {x: r.left + r.width * 0.55, y: r.top + r.height * 0.85};
    }""")
    return box["x"], box["y"]


def _button(page: Page, block: str, which: int) -> dict[str, float]:
    """The centre of a block's + (0) or − (1) button, as drawn."""
    box = page.drawn(f"{block}.getInput('ROOT_TAIL').fieldRow[{which}].getSvgRoot()")
    return {"x": box["x"] + box["w"] / 2, "y": box["y"] + box["h"] / 2}


def _click_button(page: Page, text_id: str, which: int) -> None:
    """Clicks a block's + (0) or − (1) button with the mouse."""
    box = _button(page, f"{BLOCK}('{text_id}')", which)
    page.page.mouse.click(box["x"], box["y"])


def test_plus_and_minus_keep_the_values_already_plugged_in(
    page: Page, studio: RunningStudio
) -> None:
    program = 'when started\n    print "a", "b"\n'
    (studio.folder / "values.root").write_text(program, encoding="utf-8")
    page.open("values.root")
    values = f"""async () => {{
        const print = {BLOCK}('L2') || {BLOCKS}.getBlocksByType('root_print', false)[0];
        const shown = [];
        for (let i = 0; print.getInput('ARG' + i); i++) {{
            const value = print.getInput('ARG' + i).connection.targetBlock();
            shown.push(value ? value.getFieldValue('TEXT') : null);
        }}
        return shown;
    }}"""
    _click_button(page, "L2", 0)  # +
    page.page.wait_for_function(f"() => {BLOCKS}.getBlocksByType('root_print', false)[0]"
                                ".getInput('ARG2') !== null", timeout=15000)  # fmt: skip
    assert page.js(values) == ["a", "b", None]
    page.wait_state("blocksSynced", "yes")
    shadows = f"() => {BLOCKS}.getTopBlocks(false).filter(b => b.isShadow()).length"
    page.page.mouse.click(*_empty_workspace(page))
    print_id: str = page.js(f"() => {BLOCKS}.getBlocksByType('root_print', false)[0].id")
    printed = f"{BLOCKS}.getBlockById('{print_id}')"
    box = _button(page, printed, 1)
    page.page.mouse.click(box["x"], box["y"])  # −: the empty last slot goes
    page.page.wait_for_function(f"() => !{printed}.getInput('ARG2')", timeout=15000)
    page.wait_state("blocksSynced", "yes")  # the text has followed before the next click
    before = box["x"]
    box = _button(page, printed, 1)
    assert box["x"] < before - 5  # the buttons moved left with the slot
    page.page.mouse.click(box["x"], box["y"])  # − again: "b" goes, "a" stays
    page.page.wait_for_function(f"() => !{BLOCKS}.getBlockById('{print_id}').getInput('ARG1')",
                                timeout=15000)  # fmt: skip
    assert page.js(values.replace(f"{BLOCK}('L2') ||", "")) == ["a"]
    assert page.js(shadows) == 0  # no undeletable loose shadow
    page.page.wait_for_function(
        "() => document.querySelector('.CodeMirror').CodeMirror.getValue()"
        ".includes('print \"a\"\\n')",
        timeout=15000,
    )
    assert page.text() == 'when started\n    print "a"\n'


def test_a_runs_mistake_stays_listed_through_a_save(page: Page, studio: RunningStudio) -> None:
    """A save (the child's, or the autosave after an edit) leaves the panes in step as they
    are: the mistake the run found stays in the list until the child edits."""
    (studio.folder / "zero.root").write_text("when started\n    move 10 cm / 0\n", encoding="utf-8")
    page.open("zero.root")
    page.run()
    assert page.wait_ended() == "error"
    told = page.page.locator("#problems li.error").first.inner_text()
    saves = int(page.state().get("saves", "0"))
    page.page.click("#save")
    page.wait_state("saves", str(saves + 1))
    assert page.page.locator("#problems li.error").first.inner_text() == told


# --- a program too long to convert in time --------------------------------------------------------


def test_a_program_too_long_to_convert_in_time_opens_as_text_only(
    browser: Any, class_folder: Path
) -> None:
    """The conversion runs past the studio's time limit (E818; lowered here, so a 4,900-line
    program passes it as a 0.9 MB one passes the usual 10 s): the program opens as text only,
    the blocks pane says why, no other program's blocks stay, typing works without tying up
    the class's workers, and Save writes exactly the text shown."""
    long = "when started\n" + "".join(
        ("    move 10 cm\n", "    turn right 90 degrees\n", '    say "hi"\n')[n % 3]
        for n in range(4_900)
    )
    (class_folder / "long.root").write_text(long, encoding="utf-8")
    slow = RunningStudio(class_folder, limits=ClassLimits(conversion_seconds=0.5)).start()
    page = Page(browser, slow)
    asked: list[str] = []
    page.page.on("request", lambda request: asked.append(request.url))
    try:
        page.open("square.root")
        assert page.js(f"() => {BLOCKS}.getAllBlocks(false).length") > 0
        page.page.select_option("#program", "long.root")  # the child opens it from the list
        page.wait_state("open", "long.root")
        assert page.state()["textOnly"] == "yes"
        why = page.page.locator("#text-only")
        assert why.is_visible() and "too long to show as blocks" in why.inner_text()
        assert page.page.locator("#status").inner_text() == why.inner_text()
        assert not page.page.locator("#blocks").is_visible()
        assert page.js(f"() => {BLOCKS}.getAllBlocks(false).length") == 0  # not square's
        assert page.text() == long
        conversions = sum("/api/blocks" in url for url in asked)
        page.type_at_the_end('    say "the end"')
        assert page.text() == long + '    say "the end"'
        page.wait_state("textSynced", "yes")
        saves = int(page.state().get("saves", "0"))
        with page.page.expect_request(lambda r: r.method == "PUT") as asked_to_save:
            page.page.click("#save")
        page.wait_state("saves", str(saves + 1))
        assert asked_to_save.value.post_data_json["as_written"] is True  # (not sent to format)
        saved = (class_folder / "long.root").read_text(encoding="utf-8")
        assert saved == page.text() == long + '    say "the end"'
        assert not (class_folder / ".long.root.layout.json").exists()  # no blocks of another's
        assert sum("/api/blocks" in url for url in asked) == conversions  # none sent for nothing
        assert page.errors == [] and page.outside == []
    finally:
        page.close()
        slow.stop()


# --- blocks back from text only: the loose blocks kept in the layout come back with them --------

LONG_PART = "# the long part\n"


def _save(page: Page) -> None:
    saves = int(page.state().get("saves", "0"))
    page.page.click("#save")
    page.wait_state("saves", str(saves + 1))


def _loose_in_sidecar(folder: Path, name: str) -> list[str]:
    sidecar = json.loads((folder / f".{name}.layout.json").read_text(encoding="utf-8"))
    return [block["type"] for block in sidecar["loose"]]


def _shorten(page: Page) -> None:
    """The child selects the long part (from its first line to the end) and deletes it."""
    page.page.click(".CodeMirror")
    page.js(
        """(first) => {
            const editor = document.querySelector('.CodeMirror').CodeMirror;
            const from = editor.getValue().split('\\n').indexOf(first);
            editor.setSelection({line: from, ch: 0}, {line: editor.lastLine() + 1, ch: 0});
        }""",
        LONG_PART.rstrip("\n"),
    )
    page.page.keyboard.press("Delete")
    assert LONG_PART not in page.text()
    page.wait_state("textOnly", "")


def _loose_blocks_come_back_from_text_only(page: Page, folder: Path, long_part: str) -> None:
    """square.root with `say "done"` dragged out is made too long for blocks, in the page
    and then on disk (it opens as text only, its loose block in its layout only), and
    shortened again: each time its blocks come back with the loose block, once, and every
    Save, text only or not, keeps it in the layout."""
    page.open("square.root")
    _drag_say_out(page)
    short = page.text()
    says = f"() => {BLOCKS}.getBlocksByType('root_say', false).length"
    # made too long in the page at once (a paste), saved as text only: the loose block just
    # made (not saved yet) is in the layout, as the page last showed it
    page.js(
        """(part) => {
            const editor = document.querySelector('.CodeMirror').CodeMirror;
            editor.replaceRange(part, {line: editor.lastLine() + 1, ch: 0}, undefined, 'paste');
        }""",
        long_part,
    )
    page.wait_state("textOnly", "yes")
    _save(page)
    assert _loose_in_sidecar(folder, "square.root") == ["root_say"]
    # shortened: the blocks it showed come back, the loose block once
    _shorten(page)
    page.wait_state("textSynced", "yes")
    assert page.text() == short
    assert len(_loose_ids(page)) == 1 and page.js(says) == 1
    _save(page)
    assert _loose_in_sidecar(folder, "square.root") == ["root_say"]
    # too long on disk: it opens as text only, its loose block only in the layout; shortened,
    # the blocks come back with the loose block where it was left, and a Save keeps it
    (folder / "square.root").write_text(short + long_part, encoding="utf-8")
    page.page.reload()
    page.wait_state("ready", "yes")
    page.wait_state("open", "square.root")
    assert page.state()["textOnly"] == "yes"
    assert page.js(says) == 0  # (not shown yet: text only)
    _shorten(page)
    page.wait_state("leftOut", "1")
    page.wait_state("textSynced", "yes")
    assert page.text() == short
    assert len(_loose_ids(page)) == 1 and page.js(says) == 1
    assert page.js(f"() => {BLOCKS}.getTopBlocks(false).length") == 2  # the square's script too
    _save(page)
    assert _loose_in_sidecar(folder, "square.root") == ["root_say"]
    assert (folder / "square.root").read_text(encoding="utf-8") == short
    assert page.errors == [] and page.outside == []


def test_loose_blocks_come_back_when_a_program_too_long_to_convert_is_shortened(
    browser: Any, class_folder: Path
) -> None:
    """Text only because its conversion ran past the time limit (E818, lowered here as above)."""
    long_part = (
        LONG_PART
        + "when started\n"
        + "".join(
            ("    move 10 cm\n", "    turn right 90 degrees\n", '    say "hi"\n')[n % 3]
            for n in range(4_900)
        )
    )
    slow = RunningStudio(class_folder, limits=ClassLimits(conversion_seconds=0.5)).start()
    page = Page(browser, slow)
    try:
        _loose_blocks_come_back_from_text_only(page, class_folder, long_part)
    finally:
        page.close()
        slow.stop()


def test_loose_blocks_come_back_when_a_program_too_long_for_blocks_is_shortened(
    page: Page, studio: RunningStudio
) -> None:
    """Text only because it has more lines than blocks are shown for (E817: comment lines
    here, quick to check)."""
    long_part = LONG_PART + "# a note\n" * MOST_BLOCK_LINES
    _loose_blocks_come_back_from_text_only(page, studio.folder, long_part)


def test_a_kept_block_the_page_cannot_show_stays_in_the_layout(
    page: Page, studio: RunningStudio
) -> None:
    """A loose block in the layout that this studio can't put back (a block of a newer
    studio's, or a spoilt one) is never shown half made, and a Save keeps it as it was."""
    newer = {"type": "root_from_a_newer_studio", "id": "kept", "x": 40, "y": 400}
    half = {"type": "root_say", "id": "half", "x": 40, "y": 500,
            "inputs": {"TEXT": {"block": {"type": "root_from_a_newer_studio"}}}}  # fmt: skip
    sidecar = studio.folder / ".square.root.layout.json"
    sidecar.write_text(json.dumps({"top": {}, "loose": [newer, half]}), encoding="utf-8")
    page.open("square.root")
    page.wait_state("textSynced", "yes")
    assert page.js(f"() => {BLOCKS}.getTopBlocks(false).length") == 1  # the square's script only
    _drag_say_out(page)
    _save(page)
    kept = json.loads(sidecar.read_text(encoding="utf-8"))["loose"]
    assert kept[:2] == [newer, half] and [b["type"] for b in kept[2:]] == ["root_say"]
    assert page.errors == []


# A long program's blocks are made a few at a time between the page's frames (blocks.js), and
# the page is the child's meanwhile. The page's frames held back (its requestAnimationFrame
# callbacks kept, and given back later), the making waits after its first slice, on any
# computer, however fast: the child's keys and drag come while the blocks are still being made.
HOLD_FRAMES = """() => { window.heldFrames = []; window.givenFrame = window.requestAnimationFrame;
    window.requestAnimationFrame = callback => { window.heldFrames.push(callback); return 0; }; }"""
GIVE_FRAMES = """() => { window.requestAnimationFrame = window.givenFrame;
    window.heldFrames.forEach(callback => window.requestAnimationFrame(callback)); }"""
# The blocks as text (the server's conversion of the workspace as it is): the blocks are the text
BLOCKS_AS_TEXT = f"""async () => (await (await import('/static/api.js')).toText(
    {{workspace: Blockly.serialization.workspaces.save({BLOCKS}),
      name: document.getElementById('state').dataset.open}})).text"""


def _while_blocks_are_made(page: Page, name: str) -> None:
    """Opens ``name`` from the chooser as a child would, its frames held: once the page is the
    child's, its blocks still being made."""
    page.js(HOLD_FRAMES)
    page.page.select_option("#program", name)
    page.wait_state("open", name)
    assert page.state().get("blocksMaking") == "yes" and page.state()["editable"] == "yes"


def _in_step(page: Page) -> None:
    """The page's frames given back (held by HOLD_FRAMES), then the panes in step."""
    page.js(GIVE_FRAMES)
    _blocks_are_the_text(page)


def _blocks_are_the_text(page: Page) -> None:
    page.page.wait_for_function("""() => { const s = document.getElementById('state').dataset;
        return s.blocksMaking !== 'yes' && s.textSynced === 'yes' && s.blocksSynced !== 'no'
               && !s.history.endsWith('+'); }""", timeout=60000)  # (the edit a step)  # fmt: skip
    # every line a block, every block a line (but the indentation a new line begins with, where
    # the typing left the cursor: no line yet)
    assert page.js(BLOCKS_AS_TEXT) == page.text().rstrip(" ")


def test_typing_and_dragging_while_the_blocks_are_made_lose_nothing(
    page: Page, studio: RunningStudio
) -> None:
    """Real keys in the text, then a real drag of the script, each while a 200-line program's
    blocks are still being made: the text keeps every line and the typing, the blocks end up
    the text's, the drag moves the whole script, and a Save writes the text."""
    body = [f"        move {1 + n % 3} cm" if n % 2 else f"        turn right {5 + n % 7} degrees"
            for n in range(196)]  # fmt: skip
    program = "\n".join(["# long", "when started", "    marker down", "    repeat 3", *body])
    (studio.folder / "long.root").write_text(program + "\n", encoding="utf-8")
    page.open("square.root")
    cdp = page.page.context.new_cdp_session(page.page)
    cdp.send("Emulation.setCPUThrottlingRate", {"rate": 4})  # (a school Chromebook)
    _while_blocks_are_made(page, "long.root")
    made = page.js(f"() => {BLOCKS}.getAllBlocks(false).length")
    page.type_at_the_end('\nwhen started\n    say "typed meanwhile"\n')
    assert page.state().get("blocksMaking") == "yes"  # (the keys came before the blocks)
    _in_step(page)
    assert page.text().rstrip(" ") == program + '\n\nwhen started\n    say "typed meanwhile"\n'
    assert page.js(f"() => {BLOCKS}.getAllBlocks(false).length") > made
    _save(page)
    saved = (studio.folder / "long.root").read_text(encoding="utf-8")
    assert saved == page.text().rstrip(" ")  # (but the indentation of the line begun)
    typed = saved  # (the program opened again: as saved)
    # a drag of the long script while its blocks are made: the rest are made at the first touch
    page.page.select_option("#program", "square.root")
    page.wait_state("open", "square.root")
    _while_blocks_are_made(page, "long.root")
    hat = f"{BLOCKS}.getTopBlocks(true)[0]"
    box = page.js(f"""() => {{ const r = {hat}.pathObject.svgPath.getBoundingClientRect();
        return {{x: r.left, y: r.top}}; }}""")  # (drawn by the first slice)
    start = (box["x"] + 8, box["y"] + 8)
    page.page.mouse.move(*start)
    assert page.state().get("blocksMaking") == "yes"
    page.page.mouse.down()
    page.js(GIVE_FRAMES)
    for step in range(1, 11):
        page.page.mouse.move(start[0] + 12 * step, start[1] + 6 * step)
    page.page.mouse.up()
    page.wait_state("blocksSynced", "yes", timeout_ms=60000)
    _in_step(page)
    assert page.text() == typed  # the text as it was: only the blocks' place changed
    moved = page.drawn(f"{hat}.pathObject.svgPath")
    assert (round(moved["x"] - box["x"]), round(moved["y"] - box["y"])) == (120, 60)
    assert page.errors == []


# Each block's place and size on the workspace, in the order Blockly lists them
GEOMETRY = f"""() => {BLOCKS}.getAllBlocks(true).map(block => {{
    const xy = block.getRelativeToSurfaceXY();
    return [block.type, Math.round(xy.x), Math.round(xy.y), block.width, block.height]; }})"""


def test_blocks_made_a_slice_at_a_time_are_drawn_as_blockly_draws_them_whole(
    page: Page, studio: RunningStudio
) -> None:
    """The making draws again only blocks that changed (and what holds them in an input):
    every block of a long program, nested and with expressions, stands and measures exactly as
    when Blockly draws the whole workspace again itself."""
    nested = []
    for n in range(30):
        nested += [f"    repeat {2 + n % 3}", f"        move {n + 1} cm * 2",
                   "        if touch front left pressed", '            say "a"', "        else",
                   f"            turn right {n} degrees", "    wait 0.1 seconds"]  # fmt: skip
    bumped = ["when bumped", "    repeat 2", "        repeat 2", "            move n cm"]
    program = "\n".join(["when started", "    set n to 1", *nested, "", *bumped, ""])
    (studio.folder / "nested.root").write_text(program, encoding="utf-8")
    page.open("square.root")
    cdp = page.page.context.new_cdp_session(page.page)
    cdp.send("Emulation.setCPUThrottlingRate", {"rate": 4})  # (so it takes many slices)
    _while_blocks_are_made(page, "nested.root")
    _in_step(page)
    made = page.js(GEOMETRY)
    assert len(made) > 300
    page.js(f"() => {BLOCKS}.render()")  # (Blockly's own drawing of every block)
    assert page.js(GEOMETRY) == made


def test_a_variable_typed_or_changed_in_the_text_is_that_variable_on_the_blocks(
    page: Page, studio: RunningStudio
) -> None:
    """A statement typed with a variable, and a variable changed for another in a line, are
    those variables on the blocks (the blocks once made every such variable a new `i`, `j`...,
    and a change of one for another left the block as it was)."""
    program = "when started\n    set n to 1\n    set m to 5\n    move n cm\n"
    (studio.folder / "two.root").write_text(program, encoding="utf-8")
    page.open("two.root")
    _blocks_are_the_text(page)
    page.type_at_the_end("    change m by n\n")  # a statement typed, with both variables
    _blocks_are_the_text(page)
    assert page.text().rstrip(" ") == program + "    change m by n\n"
    for key in ("ArrowUp", "ArrowUp", "End", "Backspace", "Backspace", "Backspace", "Backspace"):
        page.page.keyboard.press(key)  # `move n cm` -> `move `
    page.page.keyboard.type("m cm")  # `move m cm`: m for n, the line otherwise the same
    _blocks_are_the_text(page)
    assert "    move m cm\n" in page.text()
    names = page.js(f"() => {BLOCKS}.getVariableMap().getAllVariables().map(v => v.getName())")
    assert sorted(names) == ["m", "n"]


def test_a_save_keeps_the_indentation_of_the_line_the_child_has_begun(
    page: Page, studio: RunningStudio
) -> None:
    """Enter indents the new line; the child stops to think, and the autosave writes the
    canonical text (no spaces on an empty line): the line's indentation and the cursor stay,
    so the next words go into the script (they went to the line's start, out of it)."""
    page.open("square.root")
    page.type_at_the_end('\nwhen touched\n    say "a"\n')  # (the cursor after 4 spaces)
    page.wait_state("saves", "1")  # the autosave, the keys' focus still in the text
    page.page.keyboard.type('say "b"')
    assert page.text().endswith('when touched\n    say "a"\n    say "b"')
    saved = (studio.folder / "square.root").read_text(encoding="utf-8")
    assert saved.endswith('when touched\n    say "a"\n')  # (canonical: no spaces kept)
