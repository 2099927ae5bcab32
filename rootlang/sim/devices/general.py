"""Device 0, general: versions, name, serial and SKU, stop-and-reset, disconnect, event switches;
and device 100, connectivity (a Create 3's network, which the simulated robot does not have)."""

from __future__ import annotations

from collections.abc import Mapping

from rootlang.protocol import Board, Device, Packet, spec
from rootlang.sim.devices.base import Context, Handler, SimDevice

NAME_BYTES = spec("set_name").field("name").size  # what a Set Name packet holds
ALL_DEVICES = (1 << 128) - 1  # spec: events are on for every device after connecting
ALWAYS_ON = 1 << int(Device.GENERAL)  # spec: the general device's events cannot be disabled
NO_ADDRESS = "0.0.0.0"  # chosen: the simulated Create 3 is on no network


class General(SimDevice):
    def __init__(self, robot: Context, name: str) -> None:
        super().__init__(robot)
        self.name = name
        self.enabled = ALL_DEVICES  # one bit per device whose events the host wants

    def commands(self) -> Mapping[str, Handler]:
        return {
            "get_versions": self._get_versions,
            "set_name": self._set_name,
            "get_name": self._get_name,
            "stop_and_reset": self._stop_and_reset,
            "disconnect": self._disconnect,
            "enable_events": self._enable_events,
            "disable_events": self._disable_events,
            "get_enabled_events": self._get_enabled_events,
            "get_serial_number": self._get_serial_number,
            "get_sku": self._get_sku,
        }

    def allows(self, device_bit: int) -> bool:
        """Whether the host wants events of the device with this bit."""
        return bool(self.enabled & device_bit)

    def nose_pressed(self) -> None:
        """The nose button (Create 3: power button): the project stops, and the host hears."""
        robot = self.robot
        robot.happened("nose button")
        robot.stop_everything(respond=False)
        robot.reset_origin()
        robot.event("stop_project_event")

    def _get_versions(self, packet: Packet) -> None:
        board = int(packet["board"])
        s = self.robot.spec
        if board != Board.MAIN and Device.COLOR_SENSOR not in s.devices:
            self.robot.ignore(f"get_versions: {s.model.display_name} has no board {board:#x}")
            return
        major, minor, patch = s.firmware
        self.robot.respond(
            packet, board=packet["board"], firmware_major=major, firmware_minor=minor,
            hardware_major=s.hardware[0], hardware_minor=s.hardware[1],
            bootloader_major=s.bootloader[0], bootloader_minor=s.bootloader[1],
            protocol_major=s.protocol[0], protocol_minor=s.protocol[1], firmware_patch=patch,
        )  # fmt: skip

    def _set_name(self, packet: Packet) -> None:
        # bytes that are not UTF-8 were decoded as U+FFFD (3 bytes each): keep what fits again
        name = str(packet["name"])
        while len(name.encode("utf-8")) > NAME_BYTES:
            name = name[:-1]
        self.name = name

    def _get_name(self, packet: Packet) -> None:
        self.robot.respond(packet, name=self.name)

    def _stop_and_reset(self, packet: Packet) -> None:
        # what it cancels gets its finished response, as from a robot (iRobot's SDK waits for
        # a Drive Distance's answer after a Stop and Reset; the runtime's stop is confirmed so)
        self.robot.stop_everything(respond=True)
        self.robot.reset_origin()
        self.robot.happened("stop and reset")

    def _disconnect(self, packet: Packet) -> None:
        self.robot.end_connection("the robot was asked to disconnect")

    def _enable_events(self, packet: Packet) -> None:
        self.enabled |= _devices_mask(packet)

    def _disable_events(self, packet: Packet) -> None:
        self.enabled &= ~(_devices_mask(packet) & ~ALWAYS_ON)

    def _get_enabled_events(self, packet: Packet) -> None:
        devices = [d for d in range(ALL_DEVICES.bit_length()) if self.enabled >> d & 1]
        self.robot.respond(packet, devices=devices)

    def _get_serial_number(self, packet: Packet) -> None:
        self.robot.respond(packet, serial=self.robot.spec.serial)

    def _get_sku(self, packet: Packet) -> None:
        self.robot.respond(packet, sku=self.robot.spec.sku)


def _devices_mask(packet: Packet) -> int:
    mask = 0
    for device in packet["devices"]:
        mask |= 1 << int(device)
    return mask


class Connectivity(SimDevice):
    def commands(self) -> Mapping[str, Handler]:
        return {
            "get_ipv4_addresses": self._get_ipv4_addresses,
            "request_easy_update": self._request_easy_update,
        }

    def _get_ipv4_addresses(self, packet: Packet) -> None:
        self.robot.respond(packet, wlan0=NO_ADDRESS, wlan1=NO_ADDRESS, usb0=NO_ADDRESS)

    def _request_easy_update(self, packet: Packet) -> None:
        self.robot.ignore("request_easy_update: the simulated robot is not on the Internet")
