"""How the suite is spread over pytest-xdist's workers (``pytest -n auto``, README.md).

Most of the suite's time is spent waiting (for a browser page, a studio, a Bluetooth link, a
program's process), so ``-n auto`` starts two workers a core. The tests that wait longest (the
browser, studio and Bluetooth tests, and any marked ``slow``) go out first: left to the end,
one of them ran alone on a worker while the others had nothing left to do.
"""

from __future__ import annotations

import os

import pytest

WORKERS_A_CORE = 2
MOST_WORKERS = 8  # (each may hold a browser: memory, not cores, bounds them beyond this)
LONG_WAITING = ("studio", "ble")  # the test folders whose tests wait on browsers and links


@pytest.hookimpl(optionalhook=True)  # (pytest-xdist's hook: the suite runs without it too)
def pytest_xdist_auto_num_workers(config: pytest.Config) -> int:
    return min(MOST_WORKERS, WORKERS_A_CORE * (os.cpu_count() or 1))


def _waits_long(item: pytest.Item) -> bool:
    folder = item.path.parent.name
    return folder in LONG_WAITING or item.get_closest_marker("slow") is not None


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    items.sort(key=lambda item: not _waits_long(item))  # (stable: in order otherwise)
