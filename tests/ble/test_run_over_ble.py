"""Whole programs run by the runtime over the bleak transport, bumble's link and a virtual robot.

The robot's brain is the runtime's loopback robot (it answers by the packet table in real
time), served over BLE by the bridge; the host side is exactly what `rootlang run` uses.
"""

from __future__ import annotations

import asyncio
import os
import signal
import subprocess
import sys
from pathlib import Path

import pytest

from rootlang.ble.select import choose_robot
from rootlang.ble.transport import BleakTransport
from rootlang.ble.virtual.bridge import BleBridge
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.checks import parse
from rootlang.runtime.clock import WallClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import RunResult, run_program

SQUARE = """\
when started
    repeat 4 times
        move 2 cm
        turn right 90 degrees
    print "done"
"""
LONG_DRIVE = """\
when started
    move 500 cm
"""


def run_over_ble(
    source: str, *, act: str = "", drop: frozenset[str] = frozenset()
) -> tuple[RunResult, LoopbackRobot]:
    """Runs ``source``; ``act`` ("drop link", "ctrl-c") happens once the robot drives."""
    clock = WallClock()
    brain = LoopbackRobot(clock, drop=set(drop))

    async def main() -> RunResult:
        radio = VirtualRadio()
        central = await radio.central()
        bridge = BleBridge(
            radio.device("Rooty"), brain, name="Rooty", scan_response_in_advertisement=True
        )
        await bridge.start()
        chosen = await choose_robot("Rooty", backend=central.backend, timeout=30)
        transport = BleakTransport(chosen.device, chosen.robot, backend=central.backend)

        async def happen() -> None:
            while "drive_distance" not in brain.names_received():  # (however slow the start)
                await asyncio.sleep(0.01)
            if act == "drop link":
                assert bridge.peripheral is not None
                await bridge.peripheral.drop_connection()
            elif act == "ctrl-c":
                os.kill(os.getpid(), signal.SIGINT)

        events = asyncio.ensure_future(happen()) if act else None
        try:
            return await run_program(parse(source), transport, clock, source=source, time_limit=20)
        finally:
            if events is not None:
                events.cancel()
            await bridge.stop()

    return clock.run(asyncio.wait_for(main(), 120)), brain  # (a hang's bound, never a speed)


def test_a_whole_program_runs_over_ble() -> None:
    result, brain = run_over_ble(SQUARE)
    assert result.end == "finished", result.error
    assert result.printed == ["done"]
    assert result.robot is not None and result.robot.name == "Rooty"
    names = brain.names_received()
    assert names.count("drive_distance") == 4 and names.count("rotate_angle") == 4


def test_a_link_lost_in_the_middle_of_a_move_stops_the_run_with_a_message() -> None:
    result, brain = run_over_ble(LONG_DRIVE, act="drop link")
    assert result.end == "disconnected"
    assert result.error is not None and result.error.code == "E207"
    assert "went out of range" in result.error.english
    assert "drive_distance" in brain.names_received()
    # The virtual robot, like a real one, stops by itself when its host is gone.
    assert brain.names_received()[-1] == "stop_and_reset"
    assert not brain.is_moving()


def test_ctrl_c_during_a_move_stops_the_robot_then_closes_the_link() -> None:
    result, brain = run_over_ble(LONG_DRIVE, act="ctrl-c")
    assert result.interrupted
    assert "stop_and_reset" in brain.names_received()
    assert not brain.is_moving()


def test_a_robot_that_never_answers_times_out_with_a_message() -> None:
    result, _ = run_over_ble(
        "when started\n    marker down\n", drop=frozenset({"set_marker_position"})
    )
    assert result.error is not None and result.error.code == "E203"
    assert "didn't answer" in result.error.english


@pytest.mark.slow
def test_rootlang_run_exits_cleanly_on_ctrl_c(tmp_path: Path) -> None:
    program = tmp_path / "long.root"
    program.write_text(LONG_DRIVE)
    command = [sys.executable, "-m", "rootlang", "run", str(program), "--transport", "virtual"]
    live = {**os.environ, "PYTHONUNBUFFERED": "1"}  # (each line of the trace as it comes)
    process = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=live
    )
    try:
        assert process.stderr is not None and process.stdout is not None
        assert "Connecting to" in process.stderr.readline()
        for line in process.stdout:  # connected and driving once the trace is at the move
            if "move 500 cm" in line:
                break
        process.send_signal(signal.SIGINT)
        _, errors = process.communicate(timeout=60)
    finally:
        process.kill()
    assert process.returncode == 130, errors
    assert "Traceback" not in errors
    assert "Stopped (Ctrl-C)." in errors
