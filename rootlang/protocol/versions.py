"""Which protocol version a robot's firmware speaks (the spec's two firmware tables, as data).

The BLE transport reads the firmware version from the Device Information service and asks
:func:`protocol_version_for`; commands are then gated with ``PacketSpec.supported_by``.
A firmware newer than the table speaks what the newest listed one does; one between two rows
speaks what the older row does.
"""

from __future__ import annotations

import re

from rootlang.diagnostics import RootlangError
from rootlang.robots import RobotModel

ROOT_FIRMWARE_PROTOCOLS: tuple[tuple[str, tuple[int, int]], ...] = (
    ("1.0", (1, 0)),
    ("1.1", (1, 0)),
    ("1.2", (1, 0)),
    ("1.3", (1, 0)),
    ("1.4", (1, 0)),
    ("1.5", (1, 1)),
    ("1.8", (1, 1)),
    ("1.10", (1, 1)),
    ("1.11", (1, 2)),
    ("2.0", (1, 2)),
    ("2.1", (1, 2)),
    ("2.3", (1, 3)),
    ("2.7", (1, 3)),
)
"""Root main-board firmware -> protocol version (the spec lists exactly these rows)."""

CREATE3_FIRMWARE_PROTOCOLS: tuple[tuple[str, tuple[int, int]], ...] = (
    ("G.0", (1, 3)),
    ("G.1", (1, 3)),
    ("G.2", (1, 4)),
    ("G.3", (1, 5)),
    ("G.4", (1, 5)),
    ("G.5", (1, 5)),
    ("H.1", (1, 5)),
    ("H.2", (1, 5)),
)
"""Create 3 firmware -> protocol version; the spec pairs G.4/H.1 and G.5/H.2 (two product lines)."""

_ROOT_VERSION = re.compile(r"\s*v?(\d+)\.(\d+)")
_CREATE3_VERSION = re.compile(r"\s*([A-Za-z])\.(\d+)")


def _firmware_key(model: RobotModel, firmware: str) -> tuple[int, int] | None:
    if model.is_root:
        match = _ROOT_VERSION.match(firmware)
        return (int(match[1]), int(match[2])) if match else None
    match = _CREATE3_VERSION.match(firmware)
    return (ord(match[1].upper()), int(match[2])) if match else None


def protocol_version_for(model: RobotModel, firmware: str) -> tuple[int, int]:
    """The protocol version (major, minor) that ``model`` with ``firmware`` speaks.

    Raises RootlangError (E510) when the firmware string cannot be read; a transport can then
    fall back to the ``get_versions`` response, which carries the protocol version itself.
    """
    table = ROOT_FIRMWARE_PROTOCOLS if model.is_root else CREATE3_FIRMWARE_PROTOCOLS
    key = _firmware_key(model, firmware)
    if key is None:
        raise RootlangError.of("E510", model=model.display_name, firmware=firmware)
    rows = sorted((_firmware_key(model, name), protocol) for name, protocol in table)
    best = rows[0][1]  # older than every row: the oldest protocol
    for row_key, protocol in rows:
        assert row_key is not None
        if row_key <= key:
            best = protocol
    return best


def max_protocol(model: RobotModel) -> tuple[int, int]:
    """The newest protocol version any firmware of ``model`` speaks."""
    table = ROOT_FIRMWARE_PROTOCOLS if model.is_root else CREATE3_FIRMWARE_PROTOCOLS
    return max(protocol for _, protocol in table)
