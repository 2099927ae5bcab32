"""`rootlang sim` starts fast (benchmarks/simulator.py times it): it loads only what running a
program needs, and the collector skips what start-up made. Checked in a new `rootlang` process,
as a student runs it; a failure here names what crept back in, not a time."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

# What running a correct program in the simulator never needs: the parser's error messages and
# suggestions, package data by importlib.resources, pictures, blocks, the studio, Bluetooth; and
# Pillow and the TOML reader, as the program draws nothing and runs in the default world.
NOT_NEEDED = (
    "rootlang.grammar.errors",
    "rootlang.grammar.suggest",
    "rootlang.grammar.words",
    "importlib.resources",
    "zipfile",
    "rootlang.sim.render",
    "rootlang.blocks",
    "rootlang.studio",
    "aiohttp",
    "rootlang.ble",
    "bleak",
    "PIL",
    "tomllib",
)

# `python -c REPORT report.json ARGS...`: runs `rootlang ARGS` as the command does, then writes
# what it ended with and had loaded to report.json (its output is the program's).
REPORT = """\
import gc, sys
from rootlang.__main__ import entry
report_file, sys.argv = sys.argv[1], ["rootlang", *sys.argv[2:]]
code = entry()
report = {"code": code, "modules": sorted(sys.modules), "collecting": gc.isenabled(),
          "frozen": gc.get_freeze_count()}
import json
with open(report_file, "w", encoding="utf-8") as file:
    json.dump(report, file)
"""


def run_rootlang(tmp_path: Path, *args: str) -> dict[str, object]:
    """Run `rootlang ARGS` as its own process; what it ended with and what it had loaded."""
    report_file = tmp_path / "report.json"
    done = subprocess.run(
        [sys.executable, "-c", REPORT, str(report_file), *args],
        capture_output=True, text=True, timeout=120, cwd=tmp_path,
    )  # fmt: skip
    assert done.returncode == 0, done.stderr
    report: dict[str, object] = json.loads(report_file.read_text(encoding="utf-8"))
    return report


# What checking a correct program never needs: running it (the runtime, the simulator), the
# parser's error messages and suggestions, JSON (only `--json` prints it), and decimal (only a
# fraction's canonical text needs it).
NOT_NEEDED_TO_CHECK = (
    "asyncio", "rootlang.runtime.scheduler", "rootlang.runtime.trace", "rootlang.sim", "pymunk",
    "PIL", "rootlang.grammar.errors", "rootlang.grammar.suggest", "json", "decimal",
)  # fmt: skip


@pytest.mark.parametrize(
    ("command", "evidence", "not_needed"),
    [("sim", "rootlang.app.session", NOT_NEEDED), ("check", "lark", NOT_NEEDED_TO_CHECK)],
)
def test_a_command_loads_only_what_it_needs(
    tmp_path: Path, command: str, evidence: str, not_needed: tuple[str, ...]
) -> None:
    (tmp_path / "hello.root").write_text("when started\n    move 1 cm\n", encoding="utf-8")
    report = run_rootlang(tmp_path, command, "hello.root")
    assert report["code"] == 0
    modules = report["modules"]
    assert isinstance(modules, list)
    assert evidence in modules  # it did its work (ran the program, read it)
    loaded = [name for name in not_needed if name in modules]
    assert loaded == [], f"rootlang {command} loaded {loaded}: import them where they are needed"


def test_the_collector_runs_once_started_and_skips_what_start_up_made(tmp_path: Path) -> None:
    # rootlang.__main__ pauses the cycle collector while the command loads; rootlang.cli must
    # resume it (a paused collector would let a long run's garbage pile up).
    report = run_rootlang(tmp_path, "new", "hello")
    assert report["code"] == 0
    assert report["collecting"] is True
    frozen = report["frozen"]
    assert isinstance(frozen, int) and frozen > 10_000
