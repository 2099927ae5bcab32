"""The text of a workspace's complete scripts, and which top blocks are left out and why.

While a child works with blocks, the workspace is their state: a block lying loose, or a script
not finished yet (an empty slot), is part of it, but not of the program. The text follows the
scripts that make a program; every other top block is *left out* — kept on the workspace (the
page greys it and says why on the very block) and in the layout sidecar, never in the text.

How: the whole workspace is tried first (the usual case: one conversion). A refusal names the
block at fault (its id); the top block holding it is left out and the rest tried again. A
refusal that names no block (blocks nested too deep, text that would not read back) is tried
script by script, each with the procedures it may call.
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from dataclasses import dataclass
from typing import Any

from rootlang.blocks.blocks_to_text import Converted, convert
from rootlang.diagnostics import Diagnostic, RootlangError

MAX_ROUNDS = 64  # a workspace with more loose blocks than this is tried script by script
PROCEDURE = "root_procedure"


@dataclass(frozen=True)
class LeftOut:
    """A top block that is not in the text: its id, and the block (inside it) at fault."""

    top_id: str
    diagnostic: Diagnostic


def complete_text(
    workspace: Mapping[str, Any], language: str | None = None
) -> tuple[Converted, list[LeftOut]]:
    """The text of the workspace's complete scripts (with the program it reads back as; its
    keywords in ``language``, else the one it declares) and the top blocks left out. Raises
    the workspace's own error when it is not a workspace at all (E701)."""
    try:
        return convert(workspace, language), []
    except RootlangError:
        tops = _top_blocks(workspace)
        if not tops:  # not a workspace, or nothing to leave out: its own error
            raise
    kept = list(tops)
    left: list[LeftOut] = []
    for _ in range(MAX_ROUNDS):
        try:
            return convert(_with(workspace, kept), language), left
        except RootlangError as error:
            found = error.diagnostics[0]
            at_fault = _top_holding(kept, dict(found.values).get("id"))
            if at_fault is None:
                break
            kept.remove(at_fault)
            left.append(LeftOut(str(at_fault.get("id", "")), found))
    return _one_by_one(workspace, tops, language)


def _one_by_one(
    workspace: Mapping[str, Any], tops: list[dict[str, Any]], language: str | None
) -> tuple[Converted, list[LeftOut]]:
    procedures = [top for top in tops if top.get("type") == PROCEDURE]
    kept: list[dict[str, Any]] = []
    left: list[LeftOut] = []
    for top in tops:
        context = [top] + [p for p in procedures if p is not top]
        try:
            convert(_with(workspace, context, comments=False), language)
            kept.append(top)
        except RootlangError as error:
            left.append(LeftOut(str(top.get("id", "")), error.diagnostics[0]))
    try:
        return convert(_with(workspace, kept), language), left
    except RootlangError as error:  # together they still don't make a program: none is kept
        return convert(_with(workspace, []), language), [
            LeftOut(str(t.get("id", "")), error.diagnostics[0]) for t in kept
        ] + left


def _top_blocks(workspace: Mapping[str, Any]) -> list[dict[str, Any]]:
    blocks = workspace.get("blocks")
    tops = blocks.get("blocks") if isinstance(blocks, Mapping) else None
    return [top for top in tops if isinstance(top, dict)] if isinstance(tops, list) else []


def _with(
    workspace: Mapping[str, Any], tops: list[dict[str, Any]], comments: bool = True
) -> dict[str, Any]:
    blocks = workspace.get("blocks")
    inner = dict(blocks) if isinstance(blocks, Mapping) else {"languageVersion": 0}
    inner["blocks"] = tops
    whole = dict(workspace, blocks=inner)
    if not comments:
        whole.pop("workspaceComments", None)
    return whole


def _top_holding(tops: list[dict[str, Any]], block_id: object) -> dict[str, Any] | None:
    if not isinstance(block_id, str):
        return None
    return next((top for top in tops if block_id in set(_ids(top))), None)


def _ids(block: Mapping[str, Any]) -> Iterator[str]:
    """The ids of a block and every block inside it or under it (Blockly's JSON), walked with
    a list of its own: a long script's ``next`` chain is deeper than Python's stack."""
    todo = [block]
    while todo:
        current = todo.pop()
        if isinstance(current.get("id"), str):
            yield current["id"]
        inputs = current.get("inputs")
        for slot in inputs.values() if isinstance(inputs, Mapping) else ():
            for part in ("block", "shadow"):
                inner = slot.get(part) if isinstance(slot, Mapping) else None
                if isinstance(inner, Mapping):
                    todo.append(inner)
        after = current.get("next")
        inner = after.get("block") if isinstance(after, Mapping) else None
        if isinstance(inner, Mapping):
            todo.append(inner)
