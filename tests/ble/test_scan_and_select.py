"""Scanning and picking a robot, through bleak's scanner over bumble's virtual link."""

from __future__ import annotations

import asyncio
import dataclasses

import pytest

from rootlang.ble.profile import RobotState
from rootlang.ble.scan import scan, scanning
from rootlang.ble.select import choose_robot
from rootlang.diagnostics import RootlangError
from rootlang.protocol.enums import TouchSensors
from rootlang.robots import RobotModel

from .conftest import classroom, run


def test_scan_reads_name_model_battery_and_signal() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Rooty", RobotModel.RT0)
        create = await room.add_robot("Big One", RobotModel.CREATE3)
        await create.update_state(RobotState(battery_percent=42))
        found = {robot.name: robot for robot in await scan(0.3, room.central.backend)}
        assert set(found) == {"Rooty", "Big One"}
        assert found["Rooty"].model is RobotModel.RT0
        assert found["Big One"].model is RobotModel.CREATE3
        assert found["Big One"].battery_percent == 42
        assert found["Rooty"].battery_percent == 100
        assert found["Rooty"].rssi < 0
        assert found["Rooty"].to_json()["model"] == "RT0"

    run(main)


def test_a_robot_that_is_not_advertising_is_not_listed() -> None:
    async def main() -> None:
        room = await classroom()
        robot = await room.add_robot("Sleepy")
        await robot.device.stop_advertising()
        assert await scan(0.2, room.central.backend) == []

    run(main)


def test_advertised_touch_bumpers_and_cliff_follow_the_robot() -> None:
    async def main() -> None:
        room = await classroom()
        robot = await room.add_robot("Rooty")
        pressed = RobotState(
            touched=TouchSensors.FRONT_LEFT | TouchSensors.REAR_RIGHT,
            left_bumper=True,
            cliff=True,
            battery_percent=7,
        )
        await robot.update_state(pressed)
        async with scanning(room.central.backend) as robots:
            async for seen in robots.heard_within(2.0):
                if seen.state == pressed:
                    break
            else:
                pytest.fail(f"never heard the new state; last: {robots.in_range()}")

    run(main)


def test_the_only_robot_in_range_is_chosen() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Solo", RobotModel.RT1)
        chosen = await choose_robot(backend=room.central.backend, settle=0.2)
        assert chosen.robot.name == "Solo"
        assert chosen.device.address == chosen.robot.address

    run(main)


def test_with_several_robots_the_touched_one_is_chosen() -> None:
    async def main() -> None:
        room = await classroom()
        for name in ("Ada", "Grace", "Linus"):
            await room.add_robot(name)
        told: list[str] = []

        async def touch_grace_later() -> None:
            while not told:  # the student is asked first, then touches
                await asyncio.sleep(0.01)
            grace = room.robots[1]
            await grace.update_state(
                dataclasses.replace(grace.state, touched=TouchSensors.FRONT_RIGHT)
            )

        toucher = asyncio.ensure_future(touch_grace_later())
        chosen = await choose_robot(
            backend=room.central.backend,
            settle=1.0,  # (50 of the robots' advertisements: a busy machine's loop hears all)
            touch_timeout=30,
            tell=lambda said: told.append(said.english),
        )
        await toucher
        assert chosen.robot.name == "Grace"
        assert "I can see 3 robots" in told[0] and "Touch the top" in told[0]

    run(main)


def test_nobody_touching_times_out_and_lists_the_robots() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Ada")
        await room.add_robot("Grace")
        with pytest.raises(RootlangError) as caught:
            # (both heard meanwhile, on a busy machine too: 50 of their advertisements)
            await choose_robot(backend=room.central.backend, settle=0.1, touch_timeout=1.0)
        assert caught.value.diagnostics[0].code == "E404"
        assert '"Ada"' in str(caught.value) and '"Grace"' in str(caught.value)

    run(main)


def test_by_name_or_address() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Ada")
        grace = await room.add_robot("Grace", RobotModel.CREATE3)
        by_name = await choose_robot("grace", backend=room.central.backend, timeout=30)
        assert by_name.robot.model is RobotModel.CREATE3
        address = str(grace.device.random_address).split("/")[0]
        by_address = await choose_robot(address.lower(), backend=room.central.backend, timeout=30)
        assert by_address.robot.name == "Grace"

    run(main)


def test_a_name_not_found_says_what_was_seen() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Ada")
        with pytest.raises(RootlangError) as caught:
            await choose_robot("Gracee", backend=room.central.backend, timeout=0.3)
        assert caught.value.diagnostics[0].code == "E401"
        assert '"Gracee"' in str(caught.value) and '"Ada"' in str(caught.value)

    run(main)


def test_no_robot_at_all_says_what_to_check() -> None:
    async def main() -> None:
        room = await classroom()
        with pytest.raises(RootlangError) as caught:
            await choose_robot(backend=room.central.backend, timeout=0.3)
        assert caught.value.diagnostics[0].code == "E402"
        assert "switched on" in str(caught.value)

    run(main)


def test_cancelling_a_scan_stops_the_scanner() -> None:
    """Ctrl-C while looking for robots: the scan ends, nothing keeps listening."""

    async def main() -> None:
        room = await classroom()
        await room.add_robot("Ada")
        await room.add_robot("Grace")
        # still looking when cancelled, however slow the machine (a short look could end first,
        # with no robot heard yet: E-no-robot instead of the cancel)
        choosing = asyncio.ensure_future(
            choose_robot(backend=room.central.backend, settle=30, touch_timeout=30)
        )
        for _ in range(500):  # until the scan has begun (the loop runs it meanwhile)
            if room.central.device.is_scanning:
                break
            await asyncio.sleep(0.01)
        assert room.central.device.is_scanning
        choosing.cancel()
        with pytest.raises(asyncio.CancelledError):
            await choosing
        assert not room.central.device.is_scanning

    run(main)
