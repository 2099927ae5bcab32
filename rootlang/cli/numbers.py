"""Number options for the command line: an absurd value is a usage error, never a crash.

``float("nan")``, ``inf``, 0 and negative numbers all pass ``type=float``; a limit or timeout of
any of them makes no sense (a wall limit of nan stopped nothing, one of -1 everything), so
argparse is told to refuse them with a message saying what is wanted.
"""

from __future__ import annotations

import argparse
import math


def positive_seconds(text: str) -> float:
    """A number of seconds above 0 (not infinity, not nan)."""
    try:
        seconds = float(text)
    except ValueError:
        seconds = math.nan
    if not math.isfinite(seconds) or seconds <= 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of seconds above 0")
    return seconds


def positive_megabytes(text: str) -> int:
    """A whole number of megabytes above 0."""
    try:
        megabytes = int(text)
    except ValueError:
        megabytes = 0
    if megabytes <= 0:
        raise argparse.ArgumentTypeError(f"{text!r} is not a whole number of megabytes above 0")
    return megabytes
