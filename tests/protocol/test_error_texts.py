"""Packet errors read as people write values: no Python internals, no crash on odd bytes."""

from __future__ import annotations

import pytest

from rootlang.diagnostics import RootlangError
from rootlang.protocol import encode


def _message(name: str, fields: dict[str, object]) -> str:
    with pytest.raises(RootlangError) as caught:
        encode(name, fields, 1)
    return caught.value.diagnostics[0].english


def test_text_that_is_not_utf8_is_a_range_error_not_a_crash() -> None:
    message = _message("set_name", {"name": "\udcff"})  # how a command line passes byte 0xff
    assert message.startswith("set_name: name must be")
    assert "\\udcff" in message


@pytest.mark.parametrize(
    ("name", "fields", "shown"),
    [
        ("enable_events", {"devices": frozenset({999})}, "not 999."),
        ("enable_events", {"devices": [1, 999]}, "not 1, 999."),
        ("drive_distance", {"distance": (0,)}, "not 0."),
    ],
)
def test_range_messages_show_values_without_python_syntax(
    name: str, fields: dict[str, object], shown: str
) -> None:
    message = _message(name, fields)
    assert message.endswith(shown), message
    assert "frozenset" not in message and "(" not in message.split("not")[-1]
