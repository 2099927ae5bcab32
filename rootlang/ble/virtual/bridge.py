"""Serve any packet-speaking robot as a BLE peripheral: the virtual robot's brain and face joined.

The brain is a :class:`~rootlang.runtime.transport.Transport` seen from the robot's side: the
simulator's transport (a virtual robot in a pymunk world), the loopback robot, or anything
else that speaks the 20-byte packets. The face is a :class:`RobotPeripheral`. Packets written
to RX go to the brain (the write is acknowledged once the brain has taken the packet); packets
from the brain go out on TX. The bridge also reads the brain's touch, bumper, cliff and
battery events to keep the advertised Robot State current (that is what lets a student pick a
virtual robot by touching it), and, like a real robot, stops when its host goes away — or asks
to be disconnected (packet 0/6: the robot takes it, and the link is ended here) — and
advertises again for the next host (the robot connects again).
"""

from __future__ import annotations

import asyncio
import contextlib
import dataclasses

from bumble.device import Device

from rootlang.ble.profile import RobotState
from rootlang.ble.virtual.peripheral import (
    TEST_ADVERTISING_INTERVAL_MS,
    RobotIdentity,
    RobotPeripheral,
)
from rootlang.protocol import Packet, PacketError, decode, encode
from rootlang.protocol.enums import BumperState, TouchSensors
from rootlang.runtime.transport import LinkLost, Transport


class BleBridge:
    """``brain`` served over Bluetooth by ``device``; call :meth:`start`, then :meth:`stop`."""

    def __init__(
        self,
        device: Device,
        brain: Transport,
        *,
        name: str | None = None,
        scan_response_in_advertisement: bool = False,
        advertising_interval_ms: float = TEST_ADVERTISING_INTERVAL_MS,
    ) -> None:
        self.device = device
        self.brain = brain
        self.name = name
        self._merge = scan_response_in_advertisement
        self._interval = advertising_interval_ms
        self.peripheral: RobotPeripheral | None = None
        self.brain_gone = asyncio.get_running_loop().create_future()
        self._leaving = False  # the host asked the robot to disconnect (packet 0/6)
        self._brain_linked = True

    async def start(self) -> RobotPeripheral:
        info = await self.brain.connect(self._from_brain, self._brain_lost)
        identity = RobotIdentity.for_model(info.model, self.name or info.name or "Virtual Root")
        if info.serial or info.firmware:
            identity = dataclasses.replace(
                identity,
                serial=info.serial or identity.serial,
                firmware=info.firmware or identity.firmware,
                hardware=info.hardware or identity.hardware,
            )
        self.peripheral = RobotPeripheral(
            self.device,
            identity,
            self._to_brain,
            scan_response_in_advertisement=self._merge,
            advertising_interval_ms=self._interval,
        )
        self.peripheral.on_host_gone = self._host_gone
        self.peripheral.on_host_connected = self._host_connected
        await self.peripheral.start()
        return self.peripheral

    async def stop(self) -> None:
        if self.peripheral is not None:
            await self.peripheral.stop()
        await self.brain.disconnect()

    async def _to_brain(self, packet: bytes) -> None:
        with contextlib.suppress(PacketError):
            request = decode(packet, sender="host")
            if isinstance(request, Packet) and request.name == "set_name" and self.peripheral:
                # The name lives in the BLE stack: advertised from the next advertisement on.
                self.peripheral.identity = dataclasses.replace(
                    self.peripheral.identity, name=str(request.fields["name"])
                )
            if isinstance(request, Packet) and request.name == "disconnect" and self.peripheral:
                # The robot takes it (it stops, and is no longer connected) and the BLE stack
                # ends the link, as a real robot's does; the robot itself stays on and
                # advertises for the next host, which connects to it again.
                self._leaving = True
                await self.brain.send(packet)
                self.peripheral.in_background(self.peripheral.drop_connection())
                return
        await self.brain.send(packet)

    def _from_brain(self, packet: bytes) -> None:
        peripheral = self.peripheral
        if peripheral is None:
            return
        peripheral.send(packet)
        try:
            decoded = decode(packet, sender="robot")
        except PacketError:
            return  # a damaged packet changes no state; the host sees it and ignores it
        state = robot_state_after(peripheral.state, decoded)
        if state != peripheral.state:
            peripheral.in_background(peripheral.update_state(state))

    def _brain_lost(self, reason: LinkLost) -> None:
        if self._leaving:  # it ended its link as the host asked: the next host reconnects it
            self._brain_linked = False
            return
        if not self.brain_gone.done():
            self.brain_gone.set_result(reason)

    def _host_connected(self) -> None:
        """A host after one that asked the robot to disconnect: the robot connects again."""
        if self.peripheral is not None and not self._brain_linked:
            self._leaving = False
            self._brain_linked = True
            self.peripheral.in_background(self._relink())

    async def _relink(self) -> None:
        await self.brain.connect(self._from_brain, self._brain_lost)

    def _host_gone(self) -> None:
        """A real robot stops when its host disconnects; so does a virtual one."""
        if self.peripheral is not None:
            self.peripheral.in_background(self.brain.send(encode("stop_and_reset")))


def robot_state_after(state: RobotState, packet: object) -> RobotState:
    """The Robot State bits after one packet from the robot (events that change them)."""
    if not isinstance(packet, Packet):
        return state
    fields = packet.fields
    if packet.name == "touch_sensor_event":
        return dataclasses.replace(state, touched=TouchSensors(int(fields["state"])))
    if packet.name == "bumper_event":
        bumpers = BumperState(int(fields["state"]))
        return dataclasses.replace(
            state,
            left_bumper=bumpers in (BumperState.LEFT, BumperState.BOTH),
            right_bumper=bumpers in (BumperState.RIGHT, BumperState.BOTH),
        )
    if packet.name == "cliff_event":
        return dataclasses.replace(state, cliff=bool(fields["cliff"]))
    if packet.name in ("battery_level_event", "get_battery_level_response"):
        return dataclasses.replace(state, battery_percent=int(fields["percent"]))
    return state
