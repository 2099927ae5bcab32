"""A real robot goes back to advertising when its host leaves, and serves the next host: the
virtual robot too, whether the host asked it to disconnect (packet 0/6) or just went away."""

from __future__ import annotations

import asyncio

import pytest

from rootlang.ble.backend import BleBackend
from rootlang.ble.scan import scan
from rootlang.ble.select import choose_robot
from rootlang.ble.transport import BleakTransport
from rootlang.ble.virtual.bridge import BleBridge
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.ble.virtual.robot import simulated_robot
from rootlang.protocol import decode, encode
from rootlang.runtime.clock import WallClock
from rootlang.sim.transport import SimTransport


async def _ask_versions(backend: BleBackend) -> tuple[str, BleakTransport]:
    """Connect as a new host and ask the robot something: the name of its answer."""
    chosen = await choose_robot("Again", backend=backend, timeout=30)  # (found: at once)
    transport = BleakTransport(chosen.device, chosen.robot, backend=backend)
    answers: asyncio.Queue[bytes] = asyncio.Queue()
    await transport.connect(answers.put_nowait, lambda _reason: None)
    await transport.send(encode("get_versions", {"board": 0xA5}, 1))
    packet = decode(await asyncio.wait_for(answers.get(), 30), "robot")
    return packet.name, transport


async def _heard_once_advertising(backend: BleBackend) -> str:
    """The names heard once a robot advertises again: a busy machine may take some scans."""
    while True:  # (the test's deadline ends a robot that never comes back)
        names = [robot.name for robot in await scan(0.5, backend)]
        if names:
            return ",".join(names)


@pytest.mark.parametrize("leaving", ["disconnect packet", "link dropped"])
def test_the_virtual_robot_serves_the_next_host(leaving: str) -> None:
    clock = WallClock()

    async def main() -> tuple[list[str], bool]:
        radio = VirtualRadio()
        central = await radio.central()
        brain = simulated_robot(name="Again", clock=clock)
        assert isinstance(brain, SimTransport)
        bridge = BleBridge(
            radio.device("Again"),
            brain,
            name="Again",
            scan_response_in_advertisement=True,
        )
        await bridge.start()
        seen = []
        try:
            for _ in range(2):
                answer, transport = await _ask_versions(central.backend)
                seen.append(answer)
                assert brain.robot.connected
                if leaving == "disconnect packet":
                    await transport.send(encode("disconnect", {}, 2))
                    while brain.robot.connected:  # until the robot itself got it
                        await asyncio.sleep(0.01)
                await transport.disconnect()
                seen.append(await _heard_once_advertising(central.backend))
            return seen, bridge.brain_gone.done()
        finally:
            await bridge.stop()

    seen, gone = clock.run(asyncio.wait_for(main(), 120))  # (a hang's bound, never a speed)
    assert not gone
    assert seen == ["get_versions_response", "Again"] * 2
