"""Blocks: text -> blocks -> text for a 1,000-line program (aim ≤ 0.3 s), and the start-up
time of `rootlang blocks FILE` on a small program (aim ≤ 0.4 s, lark's parser from its cache).

    .venv/bin/python benchmarks/blocks.py
"""

from __future__ import annotations

import json
import statistics
import sys
import time
from collections.abc import Callable
from pathlib import Path

from rootlang.blocks import to_text, to_workspace
from rootlang.formatting import format_source

sys.path.insert(0, str(Path(__file__).parent))
from parse_check import SMALL, generated_program, time_startup  # shared with parse_check.py


def median_time(work: Callable[[], object], rounds: int = 7) -> float:
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    source = format_source(generated_program(910))  # about 1,000 lines in canonical form
    to_text(to_workspace(SMALL))  # builds the parser once, as the studio's server would
    workspace = to_workspace(source)
    wire = json.dumps(workspace)
    assert to_text(json.loads(wire)) == source
    lines = source.count("\n")
    there = median_time(lambda: to_workspace(source))
    back = median_time(lambda: to_text(json.loads(wire)))
    both = median_time(lambda: to_text(json.loads(json.dumps(to_workspace(source)))))
    print(f"text -> blocks, {lines} lines: {there:.3f} s")
    print(f"blocks -> text, {lines} lines: {back:.3f} s")
    print(f"text -> blocks -> text (with JSON), {lines} lines: {both:.3f} s (aim ≤ 0.3 s)")
    print(f"workspace JSON: {len(wire) / 1024:.0f} KiB")
    startup = time_startup(subcommand="blocks")
    print(f"rootlang blocks small.root, start-up: {startup:.3f} s (aim ≤ 0.4 s)")


if __name__ == "__main__":
    main()
