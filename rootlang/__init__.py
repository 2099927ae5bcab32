"""rootlang: a coding language for children that drives iRobot's Root and Create 3 robots.

The public API is what this module re-exports; everything else may change.
"""

from __future__ import annotations

__version__ = "0.1.0"

from rootlang.diagnostics import Diagnostic, RootlangError, Span
from rootlang.robots import RobotModel
from rootlang.runtime.transport import RobotInfo, Transport

__all__ = [
    "Diagnostic",
    "RobotInfo",
    "RobotModel",
    "RootlangError",
    "Span",
    "Transport",
    "__version__",
]
