"""Picking the robot to connect to: by name or address, the only one in range, or by touch.

With several robots in a classroom, the student touches the top of the one they want: robots
advertise their touch sensors (the Robot State bits), so the touched one identifies itself
before anyone connects. Every wait has a deadline, and when nothing matches the message says
what was seen, so a typo in a name or a robot that is off is easy to tell apart.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable
from dataclasses import dataclass
from typing import TYPE_CHECKING

from rootlang.ble.advertisement import RobotSeen
from rootlang.ble.backend import SYSTEM_BLUETOOTH, BleBackend
from rootlang.ble.scan import RobotScanner, scanning
from rootlang.diagnostics import Diagnostic, RootlangError, diagnostic, seconds_text

if TYPE_CHECKING:
    from bleak.backends.device import BLEDevice

FIND_TIMEOUT = 10.0
"""Seconds to look for a robot before saying none was found."""
TOUCH_TIMEOUT = 60.0
"""Seconds a student has to touch the robot they want."""
SETTLE_SECONDS = 1.5
"""Listening time after the first robot is heard, so every robot in range can be heard once."""


@dataclass(frozen=True)
class Chosen:
    device: BLEDevice
    robot: RobotSeen


async def choose_robot(
    wanted: str | None = None,
    *,
    backend: BleBackend = SYSTEM_BLUETOOTH,
    timeout: float = FIND_TIMEOUT,
    touch_timeout: float = TOUCH_TIMEOUT,
    settle: float = SETTLE_SECONDS,
    tell: Callable[[Diagnostic], None] = lambda said: None,
) -> Chosen:
    """The robot called ``wanted`` (name or address), else the only one, else the touched one
    (``tell`` is told to ask for a touch, to show it in the asker's language)."""
    async with scanning(backend) as robots:
        if wanted:
            return await _by_name(robots, wanted, timeout)
        return await _by_touch(robots, timeout, touch_timeout, settle, tell)


async def _by_name(robots: RobotScanner, wanted: str, timeout: float) -> Chosen:
    key = wanted.strip().casefold()
    async for seen in robots.heard_within(timeout):
        if key in (seen.name.strip().casefold(), seen.address.casefold()):
            return Chosen(robots.devices[seen.address], seen)
    in_range = robots.in_range()
    if not in_range:
        raise RootlangError.of("E402", seconds=seconds_text(timeout))
    raise RootlangError.of(
        "E401", wanted=wanted, seconds=seconds_text(timeout), robots=_robot_list(in_range)
    )


async def _by_touch(
    robots: RobotScanner,
    timeout: float,
    touch_timeout: float,
    settle: float,
    tell: Callable[[Diagnostic], None],
) -> Chosen:
    first = await anext(robots.heard_within(timeout), None)
    if first is None:
        raise RootlangError.of("E402", seconds=seconds_text(timeout))
    if first.state and first.state.is_touched:
        return Chosen(robots.devices[first.address], first)
    async for seen in robots.heard_within(settle):
        if seen.state and seen.state.is_touched:
            return Chosen(robots.devices[seen.address], seen)
    in_range = robots.in_range()
    if len(in_range) == 1:
        only = in_range[0]
        return Chosen(robots.devices[only.address], only)
    tell(diagnostic("E403", count=len(in_range), robots=_robot_list(in_range)))
    async for seen in robots.heard_within(touch_timeout):
        if seen.state and seen.state.is_touched:
            return Chosen(robots.devices[seen.address], seen)
    raise RootlangError.of(
        "E404", seconds=seconds_text(touch_timeout), robots=_robot_list(robots.in_range())
    )


def _robot_list(robots: Iterable[RobotSeen]) -> str:
    return ", ".join(robot.describe() for robot in robots)
