"""The robot commands in-process over `--transport virtual`, and what the bridge does for them."""

from __future__ import annotations

import asyncio
import json
from pathlib import Path

import pytest

from rootlang.ble.scan import scan
from rootlang.ble.select import choose_robot
from rootlang.ble.transport import UNACKNOWLEDGED_WRITE_GAP, BleakTransport
from rootlang.ble.virtual.radio import in_process_classroom
from rootlang.cli import main
from rootlang.protocol import encode
from rootlang.runtime.clock import WallClock

from .conftest import classroom, run


def test_scan_json_lists_the_virtual_robot(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["scan", "--transport", "virtual", "--timeout", "0.3", "--json"]) == 0
    robots = json.loads(capsys.readouterr().out)
    assert [(r["name"], r["model"], r["battery"]) for r in robots] == [("Virtual Root", "RT1", 100)]


def test_robot_info_shows_device_information(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robot", "info", "--transport", "virtual"]) == 0
    shown = capsys.readouterr().out
    assert (
        "model:     Root RT1" in shown and "protocol:  1.3" in shown and "firmware:  2.7" in shown
    )


def test_a_name_too_long_is_refused_before_connecting(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robot", "rename", "x" * 17, "--transport", "virtual"]) == 1
    assert "at most 16" in capsys.readouterr().err


def test_a_renamed_robot_advertises_its_new_name() -> None:
    clock = WallClock()

    async def rename_then_scan() -> list[str]:
        async with in_process_classroom(clock=clock) as central:
            chosen = await choose_robot(backend=central.backend, settle=0.1)
            transport = BleakTransport(chosen.device, chosen.robot, backend=central.backend)
            await transport.connect(lambda _packet: None, lambda _reason: None)
            await transport.send(encode("set_name", {"name": "Zed"}))
            await transport.disconnect()
            return [robot.name for robot in await scan(0.3, central.backend)]

    assert clock.run(asyncio.wait_for(rename_then_scan(), 10)) == ["Zed"]


def test_writes_without_response_are_paced() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Rooty")
        chosen = await choose_robot("Rooty", backend=room.central.backend, timeout=30)
        transport = BleakTransport(
            chosen.device, chosen.robot, backend=room.central.backend, write_with_response=False
        )
        await transport.connect(lambda _packet: None, lambda _reason: None)
        loop = asyncio.get_running_loop()
        started = loop.time()
        for number in range(10):
            await transport.send(bytes([number]) * 20)
        elapsed = loop.time() - started
        await transport.disconnect()
        assert elapsed >= 9 * UNACKNOWLEDGED_WRITE_GAP * 0.95
        assert room.logs[0].received == [bytes([n]) * 20 for n in range(10)]

    run(main)


def test_run_with_sim_falls_back_to_the_simulator_when_no_robot_is_found(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "hello.root"
    program.write_text('when started\n    move 5 cm\n    print "hello"\n')
    assert main(["run", str(program), "--sim", "--timeout", "0.3"]) == 0
    captured = capsys.readouterr()
    shown = [line.split(None, 2)[-1] for line in captured.out.splitlines()]  # without the time
    assert shown == [
        "line 1    when started",
        "line 2        move 5 cm",
        'line 3        print "hello"',
        "the end: every script finished",
    ]
    assert "Running it in the simulator instead." in captured.err


def test_run_without_sim_says_no_robot_was_found(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "hello.root"
    program.write_text('when started\n    print "hello"\n')
    assert main(["run", str(program), "--robot", "Nobody", "--timeout", "0.3"]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""  # nothing ran
    # Here (no radio) Bluetooth itself is missing; with a radio, no robot called Nobody is found.
    assert "I can't use Bluetooth" in captured.err or '"Nobody"' in captured.err
