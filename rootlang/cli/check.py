"""`rootlang check FILE... [--json] [--robot RT0|RT1|Create3]`: find mistakes without running.

Exit 0 when no file has errors (warnings are fine), 1 otherwise. ``--json`` prints one list of
objects with ``file, line, column, end_line, end_column, code, severity, message``.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from rootlang.checks import diagnose
from rootlang.diagnostics import Diagnostic, diagnostic, render
from rootlang.robots import RobotModel

SUMMARY = "find mistakes in programs without running them"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("files", metavar="FILE", nargs="+", help="a .root program")
    parser.add_argument("--json", action="store_true", help="print the mistakes as JSON")
    parser.add_argument(
        "--robot",
        type=RobotModel.from_name,
        metavar="MODEL",
        help="also warn about what this robot lacks: RT0, RT1 or Create3",
    )


def run(args: argparse.Namespace) -> int:
    found: list[tuple[Diagnostic, str]] = []
    for path in args.files:
        found.extend(_check_file(path, args.robot))
    if args.json:
        print(json.dumps([item.to_json() for item, _ in found], indent=2, ensure_ascii=False))
    else:
        for item, source in found:
            print(render(item, source) + "\n", file=sys.stderr)
        if not found:
            print(f"No mistakes found in {_plural(len(args.files))}.")
    return 1 if any(item.severity == "error" for item, _ in found) else 0


def _check_file(path: str, robot: RobotModel | None) -> list[tuple[Diagnostic, str]]:
    try:
        source = Path(path).read_text(encoding="utf-8")
    except FileNotFoundError:
        return [(diagnostic("E601", path=path).in_file(path), "")]
    except (OSError, UnicodeDecodeError) as error:
        return [(diagnostic("E602", path=path, reason=str(error)).in_file(path), "")]
    return [(item, source) for item in diagnose(source, path, robot)]


def _plural(count: int) -> str:
    return "1 file" if count == 1 else f"{count} files"
