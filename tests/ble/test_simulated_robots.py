"""The simulator's virtual robots served over BLE: touch one to pick it, run a program on it."""

from __future__ import annotations

import asyncio

from rootlang.ble.select import choose_robot
from rootlang.ble.transport import BleakTransport
from rootlang.ble.virtual.bridge import BleBridge
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.ble.virtual.robot import simulated_robot
from rootlang.checks import parse
from rootlang.robots import RobotModel
from rootlang.runtime.clock import WallClock
from rootlang.runtime.scheduler import RunResult, run_program
from rootlang.sim.world import parse_world

TOUCHED_SOON = """\
name = "touched soon"
[[stimulus]]
at = 0.4
action = "touch"
sensors = ["front left"]
duration = 3
"""


def test_the_robot_a_student_touches_in_the_simulator_is_chosen() -> None:
    clock = WallClock()
    told: list[str] = []

    async def main() -> str:
        radio = VirtualRadio()
        central = await radio.central()
        bridges = []
        for name in ("Ada", "Grace", "Linus"):
            world = parse_world(TOUCHED_SOON) if name == "Linus" else None
            brain = simulated_robot(RobotModel.RT1, name, clock, world)
            bridge = BleBridge(
                radio.device(name), brain, name=name, scan_response_in_advertisement=True
            )
            await bridge.start()
            bridges.append(bridge)
        try:
            chosen = await choose_robot(
                backend=central.backend,
                settle=0.1,
                touch_timeout=3,
                tell=lambda said: told.append(said.english),
            )
            return chosen.robot.name
        finally:
            for bridge in bridges:
                await bridge.stop()

    assert clock.run(asyncio.wait_for(main(), 10)) == "Linus"
    assert told and "3 robots" in told[0]


def test_a_program_drives_the_simulated_robot_over_ble() -> None:
    source = 'when started\n    move 5 cm\n    turn left 90 degrees\n    print "there"\n'
    clock = WallClock()

    async def main() -> RunResult:
        radio = VirtualRadio()
        central = await radio.central()
        brain = simulated_robot(RobotModel.CREATE3, "Big One", clock)
        bridge = BleBridge(
            radio.device("Big One"), brain, name="Big One", scan_response_in_advertisement=True
        )
        await bridge.start()
        try:
            chosen = await choose_robot("Big One", backend=central.backend, timeout=30)
            transport = BleakTransport(chosen.device, chosen.robot, backend=central.backend)
            return await run_program(
                parse(source), transport, clock, source=source, time_limit=10, handle_ctrl_c=False
            )
        finally:
            await bridge.stop()

    result = clock.run(asyncio.wait_for(main(), 15))
    assert result.end == "finished", result.error
    assert result.printed == ["there"]
    assert result.robot is not None and result.robot.model is RobotModel.CREATE3
    assert result.robot.protocol_version == (1, 5)
    assert result.pose is not None
    assert round(result.pose.heading_degrees) % 360 == 180
