"""Every Root program as Blockly blocks, and back to the very same text.

- :func:`to_workspace` — a program's text as a Blockly workspace (Blockly's JSON serialization);
- :func:`to_text` — a workspace back to the program, in canonical form
  (``to_text(to_workspace(t)) == format_source(t)`` for every program that parses);
- :func:`block_definitions`, :func:`toolbox` — the blocks and the toolbox, for the browser;
  ``root_blocks.js`` (package data, :data:`SCRIPT`) registers the two mutators they use.

How blocks and text correspond: docs/blocks.md.
"""

from __future__ import annotations

from importlib import resources

from rootlang.blocks.blocks_to_text import to_text
from rootlang.blocks.definitions import block_definitions, toolbox
from rootlang.blocks.text_to_blocks import to_workspace

__all__ = ["SCRIPT", "block_definitions", "script_text", "to_text", "to_workspace", "toolbox"]

SCRIPT = "root_blocks.js"
"""The browser half of the blocks (a file in this package)."""


def script_text() -> str:
    """``root_blocks.js``, an ES module: after Blockly, ``install(Blockly, definitions)``."""
    return resources.files("rootlang.blocks").joinpath(SCRIPT).read_text("utf-8")
