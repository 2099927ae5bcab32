"""A pytest plugin: test a folder of ``.root`` programs against their golden files with ``pytest``.

Installed with rootlang (entry point ``pytest11``) but off until asked for, so it never collects
or slows down anything by surprise. Turn it on in a teacher's repository with either::

    pytest --rootlang                   # on the command line, or
    [pytest]                            # in pytest.ini (or [tool.pytest.ini_options])
    rootlang = true

Then every ``name.root`` that has a ``name.golden`` next to it is one test item, run by the same
runner as ``rootlang test`` (same limits, same report on a mismatch). ``--rootlang-update``
rewrites the golden files instead. Use ``pytest -n auto`` (pytest-xdist) to run in parallel.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import pytest

from rootlang.app.files import PROGRAM_SUFFIX
from rootlang.diagnostics import diagnostic
from rootlang.testing import golden_path

if TYPE_CHECKING:
    from rootlang.testing.runner import ProgramResult


def pytest_addoption(parser: pytest.Parser) -> None:
    group = parser.getgroup("rootlang", "testing rootlang programs")
    group.addoption(
        "--rootlang",
        action="store_true",
        default=False,
        help="collect .root programs that have .golden files and test them in the simulator",
    )
    group.addoption(
        "--rootlang-update",
        action="store_true",
        default=False,
        help="with --rootlang: write each program's output as its golden file",
    )
    parser.addini(
        "rootlang",
        "collect .root programs with .golden files (true/false)",
        type="bool",
        default=False,
    )


def _active(config: pytest.Config) -> bool:
    return bool(config.getoption("rootlang") or config.getini("rootlang"))


# programs seen but not collected: a teacher who forgot `rootlang test --update` is told so
_WITHOUT_GOLDEN = pytest.StashKey[list[Path]]()


def pytest_collect_file(parent: pytest.Collector, file_path: Path) -> pytest.Collector | None:
    if file_path.suffix != PROGRAM_SUFFIX or not _active(parent.config):
        return None
    if golden_path(file_path).is_file():
        program: RootProgram = RootProgram.from_parent(parent, path=file_path)
        return program
    parent.config.stash.setdefault(_WITHOUT_GOLDEN, []).append(file_path)
    return None


def pytest_terminal_summary(
    terminalreporter: pytest.TerminalReporter, config: pytest.Config
) -> None:
    without_golden: list[Path] = config.stash.get(_WITHOUT_GOLDEN, [])
    for program in sorted(without_golden):
        missing = diagnostic("E606", golden=golden_path(program).name).english
        terminalreporter.write_line(f"not tested: {program.name}: {missing}")


class RootProgram(pytest.File):
    def collect(self) -> list[pytest.Item]:
        return [GoldenItem.from_parent(self, name=self.path.name)]


class GoldenFailure(Exception):
    def __init__(self, result: ProgramResult) -> None:
        super().__init__(result.report)
        self.result = result


class GoldenItem(pytest.Item):
    def runtest(self) -> None:
        # Imported here, not at the top: the plugin loads in every pytest run, the simulator
        # only when a program is really tested.
        from rootlang.testing.runner import Settings, run_golden_tests

        settings = Settings(update=bool(self.config.getoption("rootlang_update")), workers=1)
        (result,) = run_golden_tests([self.path], settings)
        if not result.verdict.ok:
            raise GoldenFailure(result)

    def repr_failure(
        self, excinfo: pytest.ExceptionInfo[BaseException], style: object = None
    ) -> str:
        if isinstance(excinfo.value, GoldenFailure):
            result = excinfo.value.result
            return f"{result.headline}\n{result.report}"
        return str(super().repr_failure(excinfo))

    def reportinfo(self) -> tuple[Path, int, str]:
        return self.path, 0, f"rootlang program {self.path.name}"
