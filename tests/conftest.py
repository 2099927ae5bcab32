"""Each test starts and ends with no language chosen (rootlang.cli.main and read_program set it
for the rest of the command, in the tests' one thread), so none leaks into other tests."""

from __future__ import annotations

from collections.abc import Iterator

import pytest

from rootlang.locale.language import choose_language, set_program_language


@pytest.fixture(autouse=True)
def no_language_left_over() -> Iterator[None]:
    choose_language(None)
    set_program_language(None)
    yield
    choose_language(None)
    set_program_language(None)
