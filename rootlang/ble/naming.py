"""Naming a class set of robots: touch one, it gets the next name (`Root-07`), lights up and
chirps, and the next one can be touched.

Chrome's chooser (and ``rootlang scan``) lists robots by their Bluetooth name, and thirty
robots all called "Root" can't be told apart; named ``Root-01`` … ``Root-30`` with a matching
sticker, each pupil finds their own. The name is set with the protocol's Set Name packet; a
robot advertises it from its next advertisement on.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rootlang.ble.advertisement import RobotSeen
from rootlang.ble.backend import SYSTEM_BLUETOOTH, BleBackend
from rootlang.ble.scan import scanning
from rootlang.ble.transport import BleakTransport
from rootlang.diagnostics import RootlangError
from rootlang.protocol import PacketError, encode, spec
from rootlang.protocol.enums import LedState
from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock, WallClock

if TYPE_CHECKING:
    from bleak.backends.device import BLEDevice

NAME_BYTES = spec("set_name").field("name").size  # what one Set Name packet holds
TOUCH_TIMEOUT = 60.0  # seconds to wait for the next robot to be touched, then stop
CHIRP_SECONDS = 0.5  # the link stays up while the chirp plays (a robot stops when its host goes)

# "Here I am": a green spin and a rising chirp, the one robot of thirty that does it now.
_HELLO_COLOUR = {"red": 0, "green": 255, "blue": 64}
_HELLO_NOTES = ((784, 120), (1047, 120), (1568, 200))  # G5, C6, G6 (Hz, ms): short, audible


def here_i_am(model: RobotModel | None = None, first_id: int = 0) -> list[bytes]:
    """The packets that make a robot show itself: its light and a chirp."""
    packets = [encode("set_led_animation", {"state": LedState.SPIN, **_HELLO_COLOUR},
                      first_id, model)]  # fmt: skip
    for number, (frequency, duration) in enumerate(_HELLO_NOTES, start=first_id + 1):
        packets.append(encode("play_note", {"frequency": frequency, "duration": duration},
                              number, model))  # fmt: skip
    return packets


def set_name_packet(name: str) -> bytes:
    """Set Name for ``name``; E410 for an empty name or one longer than a packet holds."""
    if not name.strip():  # an unnamed robot could not be picked with --robot
        raise RootlangError.of("E410", name=name, reason="it is empty")
    try:
        return encode("set_name", {"name": name})
    except PacketError as error:
        size = len(name.encode())
        reason = f"it is {size} bytes long; a name can have at most {NAME_BYTES}"
        raise RootlangError.of("E410", name=name, reason=reason) from error


def class_names(prefix: str, first: int, count: int, digits: int) -> list[str]:
    """``Root-01``, ``Root-02`` …: every one checked to fit before any robot is touched."""
    names = [f"{prefix}{number:0{digits}d}" for number in range(first, first + count)]
    for name in names:
        set_name_packet(name)
    return names


@dataclass(frozen=True)
class Named:
    robot: RobotSeen  # as it was seen (its old name)
    name: str


async def rename(
    robot: RobotSeen, device: BLEDevice, name: str, backend: BleBackend, clock: Clock
) -> None:
    """Connect, Set Name, show it (light and chirp), disconnect."""
    transport = BleakTransport(device, robot, backend=backend, clock=clock)
    info = await transport.connect(lambda _packet: None, lambda _reason: None)
    try:
        await transport.send(set_name_packet(name))
        for packet in here_i_am(info.model, first_id=1):
            await transport.send(packet)
        await clock.sleep(CHIRP_SECONDS)
    finally:
        await transport.disconnect()


async def name_class_set(
    names: Iterable[str],
    *,
    backend: BleBackend = SYSTEM_BLUETOOTH,
    clock: Clock | None = None,
    touch_timeout: float = TOUCH_TIMEOUT,
    tell: Callable[[str], None] = lambda text: None,
) -> list[Named]:
    """Each name in turn to the next robot touched (a robot named here is not named again);
    stops when the names run out or nobody touches a robot for ``touch_timeout`` seconds."""
    clock = clock or WallClock()
    done: list[Named] = []
    named: set[str] = set()
    for name in names:
        tell(f"Touch the top of the robot to call {name}.")
        found = None
        async with scanning(backend) as robots:
            async for seen in robots.heard_within(touch_timeout):
                if seen.state is not None and seen.state.is_touched and seen.address not in named:
                    found = seen, robots.devices[seen.address]
                    break
        if found is None:
            tell(f"No robot was touched in {touch_timeout:g} seconds: done.")
            break
        seen, device = found
        await rename(seen, device, name, backend, clock)
        named.add(seen.address)
        done.append(Named(seen, name))
        tell(f"{seen.describe()} is now {name}: it spins green and chirps. Label it {name}.")
    return done
