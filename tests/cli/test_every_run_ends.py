"""Every run ends: `rootlang sim` and `rootlang test` of a program that keeps the computer busy
(fifty scripts repeating `wait 0 seconds`, in a world whose time limit never comes) stop it
at their CPU-time limit with a message in the child's language, never running on unseen. A
tiny limit, so the tests don't depend on how fast the machine is. In processes of their own:
the limit is also the kernel's, for the whole process."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="CPU-time limits need resource")

BUSY = (
    "# world: worlds/endless.toml\nwhen started\n    set v to 0\n"
    + "".join(f'    send "go {n}"\n' for n in range(50))
    + "".join(
        f'when message "go {n}" received\n    forever\n        change v by 1\n'
        "        wait 0 seconds\n"
        for n in range(50)
    )
)


def busy_program(folder: Path) -> Path:
    (folder / "worlds").mkdir()
    (folder / "worlds" / "endless.toml").write_text("time_limit = 100000\n", encoding="utf-8")
    program = folder / "busy.root"
    program.write_text(BUSY, encoding="utf-8")
    return program


def rootlang(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    command = [sys.executable, "-m", "rootlang", *args]
    return subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=300)


def test_sim_stops_a_busy_program_at_its_cpu_limit_with_a_message(tmp_path: Path) -> None:
    busy_program(tmp_path)
    ran = rootlang("sim", "busy.root", "--cpu-limit", "0.2", "--language", "de", cwd=tmp_path)
    assert ran.returncode == 1, ran.stderr
    assert "Dieses Programm hat den Computer 0.2 s seiner Zeit beschäftigt" in ran.stderr
    assert "busy.root, Zeile " in ran.stderr  # at the line it was running
    assert ran.stdout.strip()  # the child's view of the run so far


def test_sim_json_says_the_run_stopped_at_its_cpu_limit(tmp_path: Path) -> None:
    busy_program(tmp_path)
    ran = rootlang("sim", "busy.root", "--cpu-limit", "0.2", "--json", cwd=tmp_path)
    assert '"end": "error"' in ran.stdout and '"code": "E220"' in ran.stdout


def test_test_reports_a_busy_program_over_its_cpu_limit(tmp_path: Path) -> None:
    busy_program(tmp_path)
    (tmp_path / "busy.golden").write_text("", encoding="utf-8")
    ran = rootlang("test", "busy.root", "--cpu-limit", "0.2", "--jobs", "1", cwd=tmp_path)
    assert ran.returncode == 1
    assert "still computing after 0.2 s of the computer's time" in ran.stdout + ran.stderr
