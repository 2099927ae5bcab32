"""Absurd limits and timeouts on the command line are usage errors (exit 2), never a crash."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

SQUARE = Path(__file__).parents[2] / "programs" / "square.root"


@pytest.mark.parametrize(
    "option",
    [
        ["--wall-limit", "nan"], ["--wall-limit", "inf"], ["--wall-limit", "0"],
        ["--wall-limit", "-1"], ["--memory-limit", "0"], ["--memory-limit", "-5"],
        ["--time-limit", "-1"], ["--time-limit", "nan"],
    ],
)  # fmt: skip
def test_rootlang_test_refuses_absurd_limits(option: list[str], tmp_path: Path) -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rootlang", "test", *option, str(SQUARE)],
        capture_output=True, text=True, timeout=60, cwd=tmp_path,
    )  # fmt: skip
    assert done.returncode == 2
    assert "above 0" in done.stderr
    assert "Traceback" not in done.stderr and "E699" not in done.stderr


def test_sensible_numbers_pass() -> None:
    from rootlang.cli.numbers import positive_megabytes, positive_seconds

    assert positive_seconds("2.5") == 2.5
    assert positive_megabytes("512") == 512
