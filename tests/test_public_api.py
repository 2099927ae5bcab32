"""The package's public API: every name in ``rootlang.__all__`` is there, and the heavy parts
load only when first used (so `rootlang check` starts fast)."""

from __future__ import annotations

import subprocess
import sys

import pytest

import rootlang


@pytest.mark.parametrize("name", rootlang.__all__)
def test_every_public_name_resolves(name: str) -> None:
    assert getattr(rootlang, name) is not None


def test_an_unknown_name_is_an_attribute_error() -> None:
    with pytest.raises(AttributeError, match="no_such_thing"):
        rootlang.no_such_thing  # noqa: B018 - the attribute access is the test


def test_importing_rootlang_loads_no_parser_simulator_or_bluetooth() -> None:
    heavy = (
        "lark", "pymunk", "bleak", "PIL", "crcmod", "rootlang.sim", "rootlang.runtime",
        "logging", "json",  # only the protocol's event ids log; messages are Python (English)
    )  # fmt: skip
    script = f"import sys, rootlang; print([m for m in {heavy!r} if m in sys.modules])"
    loaded = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True)
    assert loaded.stdout.strip() == "[]", loaded.stderr


def test_the_api_runs_a_program_in_the_simulator() -> None:
    program = rootlang.load_program("when started\n    move 10 cm\n")
    result, _ = rootlang.simulate(program, rootlang.default_world())
    assert result.error is None and result.end == "finished"
