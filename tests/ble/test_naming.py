"""`rootlang robots name`: a class set named by touching each robot in turn, over bleak's real
API on bumble's virtual link, to virtual robots (the simulator behind the Root's GATT, as
`rootlang virtual-robot` serves it), which apply Set Name to what they advertise."""

from __future__ import annotations

import asyncio
import dataclasses

import pytest

from rootlang.ble.naming import class_names, name_class_set
from rootlang.ble.scan import scan
from rootlang.ble.virtual.bridge import BleBridge
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.cli import main
from rootlang.diagnostics import RootlangError
from rootlang.protocol.enums import TouchSensors
from rootlang.runtime.clock import WallClock
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.testing.web_bluetooth import packet_name


def test_two_touched_robots_get_the_next_names_and_show_it() -> None:
    clock = WallClock()
    told: list[str] = []

    async def main_() -> tuple[list[str], list[str], list[list[str]]]:
        radio = VirtualRadio()
        central = await radio.central()
        bridges = []
        for name in ("Root", "Root", "Root"):  # a class set fresh from the box
            robot = VirtualRobot(keep_history=True)
            robot.name = name
            bridge = BleBridge(radio.device(name), SimTransport(robot, clock),
                               name=name, scan_response_in_advertisement=True)  # fmt: skip
            await bridge.start()
            bridges.append(bridge)

        async def touch(index: int) -> None:
            peripheral = bridges[index].peripheral
            assert peripheral is not None
            await peripheral.update_state(
                dataclasses.replace(peripheral.state, touched=TouchSensors.FRONT_LEFT)
            )

        async def teacher() -> None:
            await asyncio.sleep(0.3)
            await touch(2)  # the third robot first
            while len(told) < 3:
                await asyncio.sleep(0.02)
            await touch(0)  # the third still touched: it is named already, not again

        touching = asyncio.ensure_future(teacher())
        done = await name_class_set(class_names("Root-", 7, 3, 2), backend=central.backend,
                                    clock=clock, touch_timeout=3, tell=told.append)  # fmt: skip
        await touching
        seen: list[str] = []
        while len(seen) < 3:  # (a busy machine may hear them over more than one scan)
            seen = sorted(robot.name for robot in await scan(0.5, central.backend))
        heard = []
        for bridge in bridges:
            brain = bridge.brain
            assert isinstance(brain, SimTransport)
            heard.append([packet_name(record.data) for record in brain.robot.packet_log
                          if record.direction == "->"])  # fmt: skip
        for bridge in bridges:
            await bridge.stop()
        return [n.name for n in done], seen, heard

    named, seen, heard = clock.run(asyncio.wait_for(main_(), 120))  # (a hang's bound)
    assert named == ["Root-07", "Root-08"]
    assert seen == ["Root", "Root-07", "Root-08"]
    assert "set_led_animation" in heard[2] and "play_note" in heard[2]  # it showed itself
    assert heard[1] == []  # the one never touched was left alone
    assert "No robot was touched in 3 seconds" in told[-1]


def test_names_that_do_not_fit_are_refused_before_any_robot_is_touched() -> None:
    with pytest.raises(RootlangError) as refused:
        class_names("Robots-of-class-", 1, 30, 2)
    assert refused.value.diagnostics[0].code == "E410"
    assert class_names("R", 9, 2, 2) == ["R09", "R10"]


def test_the_cli_says_so_when_a_name_is_too_long(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["robots", "name", "--prefix", "x" * 15, "--transport", "virtual"]) == 1
    assert "at most 16" in capsys.readouterr().err
