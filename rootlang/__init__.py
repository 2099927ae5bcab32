"""rootlang: a coding language for children that drives iRobot's Root and Create 3 robots.

The public API is what this module re-exports; everything else may change.
"""

from __future__ import annotations

import importlib

__version__ = "0.1.0"

# Importing the package loads nothing else (not even `typing`): the `rootlang` command runs
# this before it can answer Ctrl-C itself (rootlang.__main__), so it must be over at once.
TYPE_CHECKING = False
if TYPE_CHECKING:
    from typing import Any

    from rootlang.app.session import simulate
    from rootlang.blocks import to_text, to_workspace
    from rootlang.checks import CheckedProgram, check, diagnose, load_checked, load_program, parse
    from rootlang.diagnostics import Diagnostic, RootlangError, Span
    from rootlang.formatting import format_source
    from rootlang.protocol import Packet, PacketError, PacketSpec, decode, encode
    from rootlang.robots import RobotModel
    from rootlang.runtime.scheduler import RunResult, run_program
    from rootlang.runtime.transport import RobotInfo, Transport
    from rootlang.sim import (
        Recording,
        SimTransport,
        VirtualRobot,
        World,
        default_world,
        load_world,
    )

# name -> its module, imported on first use: `rootlang check` starts without the runtime,
# the simulator or the protocol table.
_LAZY = {
    "Diagnostic": "rootlang.diagnostics",
    "RootlangError": "rootlang.diagnostics",
    "Span": "rootlang.diagnostics",
    "RobotModel": "rootlang.robots",
    "CheckedProgram": "rootlang.checks",
    "check": "rootlang.checks",
    "diagnose": "rootlang.checks",
    "load_checked": "rootlang.checks",
    "load_program": "rootlang.checks",
    "parse": "rootlang.checks",
    "format_source": "rootlang.formatting",
    "to_text": "rootlang.blocks",
    "to_workspace": "rootlang.blocks",
    "Packet": "rootlang.protocol",
    "PacketError": "rootlang.protocol",
    "PacketSpec": "rootlang.protocol",
    "decode": "rootlang.protocol",
    "encode": "rootlang.protocol",
    "RunResult": "rootlang.runtime.scheduler",
    "run_program": "rootlang.runtime.scheduler",
    "RobotInfo": "rootlang.runtime.transport",
    "Transport": "rootlang.runtime.transport",
    "Recording": "rootlang.sim",
    "SimTransport": "rootlang.sim",
    "VirtualRobot": "rootlang.sim",
    "World": "rootlang.sim",
    "default_world": "rootlang.sim",
    "load_world": "rootlang.sim",
    "simulate": "rootlang.app.session",
}


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'rootlang' has no attribute {name!r}")


__all__ = [
    "CheckedProgram",
    "Diagnostic",
    "Packet",
    "PacketError",
    "PacketSpec",
    "Recording",
    "RobotInfo",
    "RobotModel",
    "RootlangError",
    "RunResult",
    "SimTransport",
    "Span",
    "Transport",
    "VirtualRobot",
    "World",
    "__version__",
    "check",
    "decode",
    "default_world",
    "diagnose",
    "encode",
    "format_source",
    "load_checked",
    "load_program",
    "load_world",
    "parse",
    "run_program",
    "simulate",
    "to_text",
    "to_workspace",
]
