"""Every ```root example in docs/language.md parses and checks cleanly."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from rootlang.checks import diagnose

DOC = Path(__file__).parents[2] / "docs" / "language.md"
EXAMPLES = re.findall(r"```root\n(.*?)```", DOC.read_text(encoding="utf-8"), re.DOTALL)


def test_the_reference_has_examples() -> None:
    assert len(EXAMPLES) >= 8


@pytest.mark.parametrize("example", EXAMPLES)
def test_example_is_clean(example: str) -> None:
    errors = [d for d in diagnose(example, "language.md") if d.severity == "error"]
    assert errors == []
