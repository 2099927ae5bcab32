"""The examples in the protocol package's docstrings run as written."""

from __future__ import annotations

import doctest

import pytest

import rootlang.protocol
import rootlang.protocol.ids


@pytest.mark.parametrize(
    "module", [rootlang.protocol, rootlang.protocol.ids], ids=lambda m: m.__name__
)
def test_docstring_examples(module: object) -> None:
    result = doctest.testmod(module, verbose=False)  # type: ignore[arg-type]
    assert result.attempted > 0
    assert result.failed == 0
