"""The bleak transport against virtual robots: connect, Device Information, writes, disconnects."""

from __future__ import annotations

import asyncio

import pytest

from rootlang.ble.select import choose_robot
from rootlang.ble.transport import LOST_CONNECTION, BleakTransport
from rootlang.diagnostics import RootlangError
from rootlang.robots import RobotModel
from rootlang.runtime.transport import LinkLost, RobotInfo

from .conftest import Classroom, classroom, run


def packet(number: int) -> bytes:
    return bytes([number]) * 20


async def connected(
    room: Classroom, name: str, **options: object
) -> tuple[BleakTransport, RobotInfo, asyncio.Queue[bytes], list[LinkLost]]:
    chosen = await choose_robot(name, backend=room.central.backend, timeout=30)
    transport = BleakTransport(
        chosen.device,
        chosen.robot,
        backend=room.central.backend,
        **options,  # type: ignore[arg-type]
    )
    heard: asyncio.Queue[bytes] = asyncio.Queue()
    lost: list[LinkLost] = []
    info = await transport.connect(heard.put_nowait, lost.append)
    return transport, info, heard, lost


@pytest.mark.parametrize(
    ("model", "firmware", "protocol"),
    [(RobotModel.RT1, "2.7", (1, 3)), (RobotModel.CREATE3, "G.5", (1, 5))],
)
def test_connect_reads_device_information(
    model: RobotModel, firmware: str, protocol: tuple[int, int]
) -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Rooty", model)
        transport, info, _, _ = await connected(room, "Rooty")
        assert info == RobotInfo(
            model, "Rooty", f"{model.value}000000001", firmware, "1.0", protocol
        )
        await transport.disconnect()

    run(main)


@pytest.mark.parametrize("with_response", [True, False])
def test_packets_arrive_in_order_both_ways(with_response: bool) -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Rooty")
        transport, _, heard, _ = await connected(room, "Rooty", write_with_response=with_response)
        for number in range(30):
            await transport.send(packet(number))
        echoes = [await asyncio.wait_for(heard.get(), 2) for _ in range(30)]
        assert room.logs[0].received == [packet(n) for n in range(30)]
        assert echoes == [packet(n) for n in range(30)]
        await transport.disconnect()
        await transport.disconnect()  # twice is fine

    run(main)


def test_a_packet_must_be_20_bytes() -> None:
    async def main() -> None:
        room = await classroom()
        await room.add_robot("Rooty")
        transport, _, _, _ = await connected(room, "Rooty")
        with pytest.raises(ValueError):
            await transport.send(b"\x00" * 19)
        assert room.logs[0].received == []
        await transport.disconnect()

    run(main)


def test_a_robot_that_drops_the_link_is_reported_once() -> None:
    async def main() -> None:
        room = await classroom()
        robot = await room.add_robot("Rooty")
        transport, _, _, lost = await connected(room, "Rooty")
        await transport.send(packet(1))
        await robot.drop_connection()
        while not lost:  # (run's deadline ends a loss never reported)
            await asyncio.sleep(0.01)
        assert lost == [LOST_CONNECTION]
        assert not transport.is_connected
        with pytest.raises(ConnectionError):
            await transport.send(packet(2))
        await transport.disconnect()
        assert lost == [LOST_CONNECTION]  # closing afterwards is not a second report

    run(main)


def test_our_own_disconnect_is_not_reported_as_lost() -> None:
    async def main() -> None:
        room = await classroom()
        robot = await room.add_robot("Rooty")
        transport, _, _, lost = await connected(room, "Rooty")
        await transport.disconnect()
        await asyncio.sleep(0.05)
        assert lost == []
        assert robot.connection is None

    run(main)


def test_a_robot_that_never_acknowledges_a_write_times_out() -> None:
    async def main() -> None:
        room = await classroom()
        robot = await room.add_robot("Stuck")
        stuck: asyncio.Future[None] = asyncio.get_running_loop().create_future()

        async def never_done(_packet: bytes) -> None:
            await stuck

        robot.on_packet = never_done
        transport, _, _, _ = await connected(room, "Stuck", write_timeout=0.3)
        with pytest.raises(TimeoutError, match="didn't acknowledge"):
            await transport.send(packet(1))
        await transport.disconnect()

    run(main)


def test_a_robot_that_is_not_there_fails_to_connect_with_a_message() -> None:
    async def main() -> None:
        room = await classroom()
        transport = BleakTransport(
            "F0:00:00:00:0F:0F", backend=room.central.backend, connect_timeout=0.3
        )
        with pytest.raises(RootlangError) as caught:
            await transport.connect(lambda _packet: None, lambda _reason: None)
        assert caught.value.diagnostics[0].code == "E405"
        assert "F0:00:00:00:0F:0F" in str(caught.value)
        assert not room.central.device.is_le_connecting

    run(main)


def test_robot_state_characteristic_is_readable_after_connecting() -> None:
    async def main() -> None:
        from bleak import BleakClient

        from rootlang.ble.profile import ROBOT_STATE, RobotState

        room = await classroom()
        robot = await room.add_robot("Rooty")
        await robot.update_state(RobotState(battery_percent=55, right_bumper=True))
        chosen = await choose_robot("Rooty", backend=room.central.backend, timeout=30)
        async with BleakClient(chosen.device, backend=room.central.backend.client) as client:
            state = RobotState.from_bytes(bytes(await client.read_gatt_char(ROBOT_STATE)))
        assert state == RobotState(battery_percent=55, right_bumper=True)

    run(main)
