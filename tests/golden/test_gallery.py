"""The whole gallery passes: `rootlang test programs/` (every program and mistake, against its
golden file), the very command a teacher runs."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from rootlang.cli import main

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"


@pytest.mark.skipif(sys.platform == "win32", reason="needs fork and resource")
def test_every_program_in_the_gallery_matches_its_golden_file(
    capsys: pytest.CaptureFixture[str],
) -> None:
    status = main(["test", str(PROGRAMS)])
    output = capsys.readouterr().out
    assert status == 0, output
    assert " passed" in output and "failed" not in output


def test_every_program_has_a_golden_file() -> None:
    programs = sorted(PROGRAMS.glob("**/*.root"))
    assert programs
    assert [p for p in programs if not p.with_suffix(".golden").is_file()] == []
