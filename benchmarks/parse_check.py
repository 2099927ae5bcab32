"""Parse + check time of a generated 10,000-line program (aim ≤ 1 s), the start-up time of
`rootlang check` on a small file (aim ≤ 0.4 s, lark's parser loaded from its cache), and the
CPU time of checking 500 scripts each missing a unit (aim ≤ 2 s: every suggestion is tried in
place, each try reading again only the line it changes, rootlang/verify.py).

    .venv/bin/python benchmarks/parse_check.py
"""

from __future__ import annotations

import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from rootlang.checks import diagnose, load_checked

SMALL = "when started\n    move 10 cm\n    turn left 90 degrees\n"


def generated_program(lines: int = 10_000) -> str:
    """Scripts and procedures using most statement forms, `lines` lines long."""
    out = ["to square size", "    repeat 4", "        move size", "        turn right 90 degrees"]
    body = [
        "    set speed to 5 cm/s",
        "    move 10 cm + 5 mm",
        "    if bumper left pressed and timer > 2 seconds",
        "        turn left 45 degrees",
        "    else",
        "        square 10 cm",
        "    play note C4 for 0.5 seconds",
        '    say "hello"',
        "    drive speed * 2",
    ]
    while len(out) + len(body) + 1 <= lines:
        out.append("when started")
        out.extend(body)
    out.extend(["    stop moving"] * (lines - len(out)))
    return "\n".join(out) + "\n"


def time_parse_check(source: str, rounds: int = 5) -> float:
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        load_checked(source, "big.root")
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def time_startup(rounds: int = 5, subcommand: str = "check") -> float:
    """Median wall time of `rootlang SUBCOMMAND small.root` (lark's parser from its cache)."""
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "small.root"
        path.write_text(SMALL, encoding="utf-8")
        command = [sys.executable, "-m", "rootlang", subcommand, str(path)]
        subprocess.run(command, check=True, capture_output=True)  # warms lark's cache
        times = []
        for _ in range(rounds):
            start = time.perf_counter()
            subprocess.run(command, check=True, capture_output=True)
            times.append(time.perf_counter() - start)
    return statistics.median(times)


def missing_units(scripts: int = 500, lines: int = 1) -> str:
    """``scripts`` scripts, each with one line missing its unit (`move 10`) among ``lines``
    lines that are right."""
    right = ["    turn left 90 degrees", "    set speed to 5 cm/s", '    say "hi"']
    body = [right[n % len(right)] for n in range(lines - 1)]
    return "".join(
        "when started\n" + "\n".join([*body, f"    move {n + 1}"]) + "\n\n" for n in range(scripts)
    )


def time_mistakes(source: str) -> tuple[float, int]:
    """CPU seconds of every diagnostic of ``source`` (suggestions tried), and how many."""
    start = time.process_time()
    found = diagnose(source, "mistakes.root")
    return time.process_time() - start, len(found)


def main() -> None:
    source = generated_program()
    load_checked(SMALL)  # builds the parser once, as a long-running process would
    seconds = time_parse_check(source)
    print(f"parse + check, {source.count(chr(10))} lines: {seconds:.3f} s (aim ≤ 1 s)")
    print(f"rootlang check small.root, start-up: {time_startup():.3f} s (aim ≤ 0.4 s)")
    for lines in (1, 5):
        seconds, found = time_mistakes(missing_units(500, lines))
        print(
            f"check 500 scripts of {lines} line(s), each missing a unit: {seconds:.2f} s of CPU, "
            f"{found} mistakes (aim ≤ 2 s)"
        )


if __name__ == "__main__":
    main()
