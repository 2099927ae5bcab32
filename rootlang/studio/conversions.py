"""The studio's conversions, as a conversion worker process runs them (:mod:`.pool`).

Each takes a request's body as it came (bytes: the server never parses a page's workspace
itself, so a deep or huge one costs the event loop nothing) and gives ``(status, JSON text)``
to send back as it is: text → blocks with the checks' diagnostics, blocks → text, and the
canonical text a Save writes. Each is handed the languages of the request that asks (its
messages speak them; a program is read in the studio's ``--language``, else its own). A
program longer than :data:`MOST_BLOCK_LINES` lines opens as text only (E817): thousands of
blocks are more than a page can show usefully.
"""

from __future__ import annotations

import contextlib
import importlib
import json
from collections.abc import Callable
from typing import TYPE_CHECKING, Any, cast

from rootlang import jsontree
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic, render
from rootlang.studio import messages as m
from rootlang.wording.language import ENGLISH, Languages

if TYPE_CHECKING:
    from rootlang.grammar import LinesRead

MOST_BLOCK_LINES = 5_000
Seen = tuple[str, str, list[Diagnostic]]
"""A program as a conversion saw it (name, text, its mistakes): the teacher's page shows it,
in the teacher's language."""
Reply = tuple[int, str, Seen | None]


def diagnostic_json(item: Diagnostic, source: str, languages: Languages) -> m.DiagnosticJson:
    """A diagnostic as the page gets it: its fields and the rendered message, in
    ``languages``."""
    # (Diagnostic.to_json's keys; the contract test checks they are the type's)
    shown = dict(item.to_json(languages), rendered=render(item, source, languages))
    return cast(m.DiagnosticJson, shown)


def error_json(found: RootlangError | Diagnostic, languages: Languages) -> m.ErrorsReply:
    diagnostics = found.diagnostics if isinstance(found, RootlangError) else [found]
    return {"errors": [diagnostic_json(item, "", languages) for item in diagnostics]}


def request_object(body: bytes) -> dict[str, Any]:
    """A request's JSON object (E805 for anything else)."""
    try:
        data = jsontree.loads(body.decode("utf-8"))  # a long script's workspace nests deep
    except (ValueError, UnicodeDecodeError):
        raise RootlangError.of("E805", reason="it is not JSON") from None
    if not isinstance(data, dict):
        raise RootlangError.of("E805", reason="it is not a JSON object")
    return data


def text_field(data: dict[str, Any], name: str) -> str:
    value = data.get(name)
    if not isinstance(value, str):
        raise RootlangError.of("E805", reason=f"it has no text `{name}`")
    return value


def blocks_module() -> Any:
    """:mod:`rootlang.blocks` (the block definitions and the block/text conversion), or None
    in a build without it."""
    try:
        return importlib.import_module("rootlang.blocks")
    except ModuleNotFoundError:
        return None


MOST_LINES_KEPT = 20_000
_lines_read: LinesRead | None = None


def lines_read() -> LinesRead:
    """The lines this worker read before (a child typing sends their program again and again,
    one line changed: only that line is read again), forgotten past :data:`MOST_LINES_KEPT`."""
    global _lines_read
    from rootlang.grammar import LinesRead

    if _lines_read is None or len(_lines_read.lines) > MOST_LINES_KEPT:
        _lines_read = LinesRead()
    return _lines_read


def checked(text: str, name: str, languages: Languages, *, read: bool = False) -> list[Diagnostic]:
    """The checks' diagnostics of a program, read in ``languages``' (its own, or the
    studio's). ``read``: its lines were all read without a mistake just now (by
    :func:`lines_read`), so they are taken from there (a broken line's fix is looked for only
    in a full reading)."""
    from rootlang.checks import parse_and_check

    found = parse_and_check(text, name, language=languages.chosen,
                            lines_read=lines_read() if read else None)[1]  # fmt: skip
    return found


def diagnostics_json(
    found: list[Diagnostic], text: str, languages: Languages
) -> list[m.DiagnosticJson]:
    """A program's diagnostics as a page gets them, with code in them as the program writes
    it."""
    from rootlang.locale.translate import about

    shown = about(languages, text)
    return [diagnostic_json(item, text, shown) for item in found]


def format_text(languages: Languages, text: str, name: str) -> str:
    """The canonical text (as ``rootlang.formatting`` writes it); text that does not parse is
    kept as the child wrote it."""
    try:
        formatting = importlib.import_module("rootlang.formatting")
    except ModuleNotFoundError:
        return text
    try:
        formatted: str = formatting.format_source(text, name, languages.chosen)
    except RootlangError:
        return text
    return formatted


def _replying(
    make: Callable[[dict[str, Any], Languages], tuple[Any, Seen]],
    body: bytes,
    languages: Languages,
) -> Reply:
    try:
        reply, seen = make(request_object(body), languages)
    except RootlangError as error:
        return 400, json.dumps(error_json(error, languages), ensure_ascii=False), None
    return 200, jsontree.dumps(reply, ensure_ascii=False), seen


def text_to_blocks(languages: Languages, body: bytes) -> Reply:
    """``{"text", "name"}`` → ``{"workspace", "diagnostics"}``; the workspace is None when
    the text does not parse (the page keeps its blocks), and when the program is too long
    for blocks ``text_only`` says so (E817)."""
    return _replying(_text_to_blocks, body, languages)


def _text_to_blocks(data: dict[str, Any], languages: Languages) -> tuple[m.BlocksReply, Seen]:
    text, name = text_field(data, "text"), str(data.get("name", ""))
    blocks = blocks_module()
    reply: m.BlocksReply = {"workspace": None, "diagnostics": []}
    lines = text.count("\n") + (not text.endswith("\n"))
    if blocks is None:
        pass
    elif lines > MOST_BLOCK_LINES:
        too_long = diagnostic("E817", lines=lines, most=MOST_BLOCK_LINES)
        reply["text_only"] = diagnostic_json(too_long, "", languages)
    else:
        with contextlib.suppress(RootlangError):  # not parsed: the page's blocks stay as they were
            reply["workspace"] = blocks.to_workspace(text, name, languages.chosen, lines_read())
        if reply["workspace"] is not None and data.get("level") == 1:
            reply["workspace"], reply["above"] = _pictures(reply["workspace"])
    found = checked(text, name, languages, read=reply["workspace"] is not None)
    reply["diagnostics"] = diagnostics_json(found, text, languages)
    return reply, (name, text, found)


def _pictures(workspace: dict[str, Any]) -> tuple[dict[str, Any], list[str]]:
    """Level 1's blocks: picture blocks where a line has one, and the blocks that have none."""
    from rootlang.blocks.pictures import to_pictures

    return to_pictures(workspace)


def blocks_to_text(languages: Languages, body: bytes) -> Reply:
    """``{"workspace", "name"}`` → ``{"text", "workspace", "diagnostics", "left_out"}``: the
    text of the complete scripts, the text's own blocks (as ``text_to_blocks`` gives them: the
    page learns which of its blocks is which line from them, in this one request), and the top
    blocks left out of it (loose, or not finished) and why; E70x when the blocks can't be a
    workspace, E809 in a build without blocks."""
    return _replying(_blocks_to_text, body, languages)


def _blocks_to_text(data: dict[str, Any], languages: Languages) -> tuple[m.TextReply, Seen]:
    blocks = blocks_module()
    if blocks is None:
        raise RootlangError.of("E809")
    workspace = data.get("workspace")
    if not isinstance(workspace, dict):
        raise RootlangError.of("E805", reason="it has no `workspace` object")
    from rootlang.studio.complete import complete_text

    made, left_out = complete_text(workspace, languages.chosen)
    text, name = made.text, str(data.get("name", ""))
    found = checked(text, name, languages)
    reply: m.TextReply = {
        "text": text, "workspace": made.text_workspace() if data.get("level") != 1
        else _pictures(made.text_workspace())[0],
        "diagnostics": diagnostics_json(found, text, languages),
        "left_out": [
            {"top": left.top_id, "block": str(dict(left.diagnostic.values).get("id") or ""),
             "diagnostic": diagnostic_json(left.diagnostic, "", languages)}
            for left in left_out
        ],
    }  # fmt: skip
    return reply, (name, text, found)


def stage(languages: Languages, program_path: str, text: str, world_path: str) -> Reply:
    """The stage before a run: the world a run of ``text`` would have (``world_path``, else
    the one its ``# world:`` line names, else the default) with the robot at its start pose,
    as a run's ``started`` message draws it. The text need not be right: only its world
    line is read."""
    from pathlib import Path

    from rootlang.app.session import world_of
    from rootlang.sim.robot import VirtualRobot
    from rootlang.studio.worker import stage_of

    try:
        program = Path(program_path)  # (its folder's files named as the page knows them)
        world = world_of(program, text, world_path or None, names_from=program.parent)
    except RootlangError as error:
        return 400, json.dumps(error_json(error, languages), ensure_ascii=False), None
    reply: m.StageData = stage_of(VirtualRobot(world).recording, world)
    return 200, json.dumps(reply, ensure_ascii=False), None


JOBS: dict[str, Callable[..., Any]] = {
    "text_to_blocks": text_to_blocks,
    "blocks_to_text": blocks_to_text,
    "format_text": format_text,
    "stage": stage,
}
"""What a conversion worker can be asked to do, by name."""


def warm_up() -> None:
    """Load the parser, the checks and the blocks once, so no pupil's request pays for it."""
    text_to_blocks(ENGLISH, b'{"text": "when started\\n    move 10 cm\\n", "name": ""}')
