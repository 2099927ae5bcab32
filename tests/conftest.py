"""How the suite is spread over pytest-xdist's workers (``pytest -n auto``, README.md).

The tests that take longest (the browser, studio and Bluetooth tests, and any marked ``slow``)
go out first, and a few at a time: xdist hands a worker large shares at the start, and a few
minutes of browser tests were left queued on one worker at the end while the other had
nothing left to do. One worker a core: more were a little quicker (two a core 515 s against
544 s on an idle machine; three for two cores 492 s against 515 s, later), not enough to run the
browser tests under that load.
"""

from __future__ import annotations

import pytest

LONG_WAITING = ("studio", "ble")  # the test folders whose tests wait on browsers and links
TESTS_A_SHARE = 4  # the most tests a worker is handed at once


def pytest_configure(config: pytest.Config) -> None:
    if getattr(config.option, "numprocesses", None):
        config.option.maxschedchunk = TESTS_A_SHARE


def _takes_long(item: pytest.Item) -> bool:
    folder = item.path.parent.name
    return folder in LONG_WAITING or item.get_closest_marker("slow") is not None


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    items.sort(key=lambda item: not _takes_long(item))  # (stable: in order otherwise)
