"""Connect time and packet round trip over bleak + bumble's in-process link (no radio).

Measures what the BLE layer itself costs: bleak's API over the bumble central backend, bumble's
virtual controllers, and a virtual robot that echoes each packet back on TX. A real radio adds
its connection interval (7.5-50 ms) on top; these figures are the floor of rootlang's own code.

    .venv/bin/python benchmarks/ble_link.py
"""

from __future__ import annotations

import asyncio
import statistics
import time

from rootlang.ble.select import choose_robot
from rootlang.ble.transport import BleakTransport
from rootlang.ble.virtual.peripheral import RobotIdentity, RobotPeripheral
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.robots import RobotModel

CONNECTS = 20
ROUND_TRIPS = 500


async def measure() -> None:
    radio = VirtualRadio()
    central = await radio.central()
    echo: list[RobotPeripheral] = []
    robot = RobotPeripheral(
        radio.device("Bench"),
        RobotIdentity.for_model(RobotModel.RT1, "Bench"),
        lambda packet: echo[0].send(packet),
        scan_response_in_advertisement=True,
    )
    echo.append(robot)
    await robot.start()

    started = time.perf_counter()
    chosen = await choose_robot("Bench", backend=central.backend)
    found = time.perf_counter() - started

    connect_times: list[float] = []
    for _ in range(CONNECTS):
        transport = BleakTransport(chosen.device, chosen.robot, backend=central.backend)
        heard: asyncio.Queue[bytes] = asyncio.Queue()
        started = time.perf_counter()
        await transport.connect(heard.put_nowait, lambda _reason: None)
        connect_times.append(time.perf_counter() - started)
        await transport.disconnect()

    transport = BleakTransport(chosen.device, chosen.robot, backend=central.backend)
    heard = asyncio.Queue()
    await transport.connect(heard.put_nowait, lambda _reason: None)
    for with_response in (True, False):
        transport.write_with_response = with_response
        trips: list[float] = []
        for number in range(ROUND_TRIPS):
            packet = bytes([number % 256]) * 20
            started = time.perf_counter()
            await transport.send(packet)
            assert await heard.get() == packet
            trips.append(time.perf_counter() - started)
        kind = "with response" if with_response else "without response (paced 15 ms apart)"
        print(
            f"round trip, write {kind}: median {statistics.median(trips) * 1000:.2f} ms, "
            f"p95 {sorted(trips)[int(len(trips) * 0.95)] * 1000:.2f} ms ({ROUND_TRIPS} packets)"
        )
    await transport.disconnect()
    print(f"find by name (scan):   {found * 1000:.1f} ms (advertising every 20 ms)")
    print(
        f"connect (incl. GATT discovery, Device Information, subscribe): "
        f"median {statistics.median(connect_times) * 1000:.1f} ms, "
        f"max {max(connect_times) * 1000:.1f} ms ({CONNECTS} connects)"
    )


if __name__ == "__main__":
    asyncio.run(measure())
