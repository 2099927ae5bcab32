"""Ctrl-C at any moment of a command is a clean stop (docs/architecture.md, the command line):
"Stopped (Ctrl-C)." and exit code 130, never a traceback, and a robot left standing still.

Each command runs as its own process, as a student runs it, and gets a real SIGINT. Where in
start-up it lands is made certain, not left to the machine's speed: a harness sends it at the
Nth module the command imports once rootlang's code runs (an audit hook sees each import), at
a spread of N over the whole start-up; later moments are reached by waiting on what the
command prints. What comes before rootlang's first line (Python's own start-up, the
launcher's ``import re``) is Python's, as docs/architecture.md says.
"""

from __future__ import annotations

import importlib.util
import json
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

# `python -c HARNESS report.json N ARGS...`: `rootlang ARGS` as the launcher runs it, with a
# SIGINT at the Nth import from the moment rootlang handles Ctrl-C (never, for N = 0). At exit
# it writes how many imports there were, and whether each robot the run made stands still.
HARNESS = """\
import atexit, gc, json, os, signal, sys
report_file, at, sys.argv = sys.argv[1], int(sys.argv[2]), ["rootlang", *sys.argv[3:]]
ours = os.getpid()  # the program's own process (forked) is not this one
seen = {"imports": 0, "started": False}

def hook(event, args):
    if event != "import" or os.getpid() != ours:
        return
    if not seen["started"]:
        if signal.getsignal(signal.SIGINT) is signal.default_int_handler:
            return  # rootlang's code has not begun
        seen["started"] = True
    seen["imports"] += 1
    if seen["imports"] == at:
        os.kill(ours, signal.SIGINT)

def robots_still():
    sim = sys.modules.get("rootlang.sim.transport")
    if sim is None:
        return []
    from rootlang.sim.devices.motors import STILL
    robots = [o for o in gc.get_objects() if isinstance(o, sim.SimTransport)]
    return [o.robot.devices.motors.wheels == STILL for o in robots]

def report():
    if os.getpid() == ours:
        with open(report_file, "w", encoding="utf-8") as file:
            json.dump({"imports": seen["imports"], "still": robots_still()}, file)

atexit.register(report)
sys.addaudithook(hook)
from rootlang.__main__ import entry
sys.exit(entry())
"""

# Before the harness: a robot that takes a minute to answer the connect (which says when the
# program has begun waiting for it)
SLOW_ROBOT = """\
import asyncio, sys
from rootlang.ble import transport
connect = transport.BleakTransport.connect
async def slowly(self, *args, **kwargs):
    print("(the robot is slow to answer)", file=sys.stderr, flush=True)
    await asyncio.sleep(60)
    return await connect(self, *args, **kwargs)
transport.BleakTransport.connect = slowly
"""
NEEDS_BUMBLE = pytest.mark.skipif(
    importlib.util.find_spec("bumble") is None,
    reason="the virtual robot needs the optional extra: rootlang[virtual]",
)
DRIVE = "when started\n    drive 10 cm/s\n    wait 30 seconds\n"
COMMANDS = {
    "sim": ["sim", "drive.root"],
    "check": ["check", "drive.root"],
    "test": ["test", "drive.root"],
    "run": ["run", "drive.root", "--transport", "virtual"],
}


def _start(
    tmp_path: Path, at: int, args: list[str], *, live: bool = False, slow_robot: bool = False
) -> subprocess.Popen[str]:
    """The harness running ``rootlang args``; ``live``: stdout's lines come as printed;
    ``slow_robot``: the robot takes a minute to answer the connect."""
    (tmp_path / "drive.root").write_text(DRIVE, encoding="utf-8")
    (tmp_path / "drive.golden").write_text("", encoding="utf-8")
    (tmp_path / "short.root").write_text("when started\n    move 1 cm\n", encoding="utf-8")
    harness = SLOW_ROBOT + HARNESS if slow_robot else HARNESS
    command = [sys.executable, "-c", harness, str(tmp_path / "report.json"), str(at), *args]
    pipe = subprocess.PIPE
    environment = {**os.environ, "PYTHONUNBUFFERED": "1"} if live else None
    return subprocess.Popen(
        command, cwd=tmp_path, stdout=pipe, stderr=pipe, text=True, env=environment
    )


def _report(tmp_path: Path) -> dict[str, object]:
    report: dict[str, object] = json.loads((tmp_path / "report.json").read_text("utf-8"))
    return report


def _assert_stopped_cleanly(run: subprocess.Popen[str], errors: str, tmp_path: Path) -> None:
    assert "Traceback" not in errors, errors
    assert run.returncode == 130, errors
    assert errors.strip().endswith("Stopped (Ctrl-C)."), errors
    still = _report(tmp_path)["still"]
    assert isinstance(still, list) and all(still), "the robot was left driving"


@pytest.mark.parametrize(
    "name", [pytest.param(name, marks=NEEDS_BUMBLE if name == "run" else ()) for name in COMMANDS]
)
def test_ctrl_c_anywhere_in_start_up_is_a_clean_stop(name: str, tmp_path: Path) -> None:
    args = COMMANDS[name]
    # how many imports the command makes, run to its end (`sim` and `run` on a program that
    # ends at once; `test` runs its 30 simulated seconds, and fails: the golden file is empty)
    ends = args if name in ("check", "test") else [args[0], "short.root", *args[2:]]
    counting = _start(tmp_path, 0, ends)
    _, errors = counting.communicate(timeout=60)
    assert counting.returncode == (1 if name == "test" else 0), errors
    imports = _report(tmp_path)["imports"]
    assert isinstance(imports, int) and imports > 20, imports
    spread = sorted({1, 2, 3, 5, imports // 8, imports // 3, imports // 2, imports - 1})
    for at in spread:
        run = _start(tmp_path, at, args)
        _, errors = run.communicate(timeout=60)
        _assert_stopped_cleanly(run, f"at import {at} of {imports}:\n{errors}", tmp_path)


@NEEDS_BUMBLE
@pytest.mark.parametrize("when", ["connecting", "driving"])
def test_ctrl_c_while_rootlang_run_connects_or_drives_stops_the_robot(
    when: str, tmp_path: Path
) -> None:
    run = _start(tmp_path, 0, COMMANDS["run"], live=True)
    assert run.stderr is not None and run.stdout is not None
    assert "Connecting to" in run.stderr.readline()
    if when == "driving":  # once the trace is past the drive (a 0.5 s wait saw a busy connect)
        for line in run.stdout:
            if "drive 10 cm/s" in line:
                break
    run.send_signal(signal.SIGINT)
    _, errors = run.communicate(timeout=60)
    _assert_stopped_cleanly(run, errors, tmp_path)


def test_ctrl_c_after_the_command_is_done_changes_nothing(tmp_path: Path) -> None:
    (tmp_path / "square.root").write_text("when started\n    move 1 cm\n", encoding="utf-8")
    script = HARNESS.replace("sys.exit(entry())", "code = entry()\nos.kill(ours, signal.SIGINT)\n"
                             "print('still here', flush=True)\nsys.exit(code)")  # fmt: skip
    command = [
        sys.executable,
        "-c",
        script,
        str(tmp_path / "report.json"),
        "0",
        "sim",
        "square.root",
    ]
    done = subprocess.run(command, cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert (done.returncode, done.stderr) == (0, "")
    assert done.stdout.endswith("still here\n")


@NEEDS_BUMBLE
def test_ctrl_c_while_a_robot_takes_its_time_to_connect_stops_at_once(tmp_path: Path) -> None:
    """The connect under way is given up (a robot may take seconds to answer): the run was
    left waiting for it, and the link holder ended it after 5 s with a -9 (exit code 247)."""
    run = _start(tmp_path, 0, COMMANDS["run"], live=True, slow_robot=True)
    assert run.stderr is not None
    for line in run.stderr:  # (the program's own connect: the link holder's is done)
        if "slow to answer" in line:
            break
    run.send_signal(signal.SIGINT)
    output, errors = run.communicate(timeout=30)  # (the robot answers after 60 s)
    _assert_stopped_cleanly(run, errors, tmp_path)
    assert "0.0 s" in output and "stopped by Ctrl-C" in output, output
