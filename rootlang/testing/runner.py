"""Golden-output testing of programs: run each in the simulator, compare with its golden file.

:func:`run_golden_tests` is the one runner behind ``rootlang test`` and the pytest plugin. Each
program runs in a child process of its own (see :mod:`rootlang.app.sandbox`) under a
simulated time limit, a CPU-time limit and a memory cap, so a class's submissions can't hang
or exhaust the machine; hitting each limit is its own outcome. A far wall-clock backstop ends a
test the machine was too busy to finish, and says so without blaming the program.
"""

from __future__ import annotations

import difflib
import enum
import itertools
import os
import time
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, TextIO

from rootlang.app.sandbox import Finished, Limits, Status, run_isolated
from rootlang.diagnostics import Diagnostic, diagnostic, render, source_lines
from rootlang.testing import golden_path
from rootlang.testing.produce import Produced, produce
from rootlang.wording.catalogue import message
from rootlang.wording.language import ENGLISH, Languages


class Verdict(enum.Enum):
    PASSED = "passed"
    UPDATED = "updated"
    FAILED = "failed"
    MISSING = "no golden file"
    CPU_LIMIT = "over the CPU-time limit"
    WALL_LIMIT = "not finished in time (the computer was too busy)"
    MEMORY_LIMIT = "over the memory cap"
    CRASHED = "crashed"

    @property
    def ok(self) -> bool:
        return self in (Verdict.PASSED, Verdict.UPDATED)

    def shown(self, languages: Languages) -> str:
        """The outcome in words (``value`` is the English, which reports keep)."""
        return message(_VERDICT_CODES[self], {}, languages)


_VERDICT_CODES = dict(
    zip(Verdict, ("V100", "V101", "V102", "V103", "V104", "V105", "V106", "V107"), strict=True)
)


@dataclass(frozen=True)
class Settings:
    """How to test: ``time_limit`` caps each world's own simulated time limit (seconds);
    ``languages``: the command's, which its reports speak (a golden file speaks only the
    language the command gives or the program declares, never the computer's: the same on
    every computer)."""

    update: bool = False
    time_limit: float | None = None
    limits: Limits = field(default_factory=Limits)
    workers: int | None = None
    languages: Languages = ENGLISH


@dataclass(frozen=True)
class ProgramResult:
    program: Path
    verdict: Verdict
    report: str = ""  # what to show a person: the diff, or which limit was hit
    produced: Produced | None = None
    seconds: float = 0.0
    first_difference: str = ""  # one line: where the output first differs, or the problem

    @property
    def headline(self) -> str:
        """One line that says what happened: ``FAILED spiral.root: its output differs ...``."""
        return self.shown_headline(ENGLISH)

    def shown_headline(self, languages: Languages) -> str:
        """:attr:`headline` as ``languages`` say it."""
        program = str(self.program)
        if self.verdict.ok:
            return f"{self.verdict.shown(languages).upper()} {program}"
        if self.verdict is Verdict.WALL_LIMIT:  # the machine's doing, not the program's
            return message("V112", {"program": program}, languages)
        if self.verdict is Verdict.FAILED:
            golden = str(golden_path(self.program))
            return message("V111", {"program": program, "golden": golden}, languages)
        reason = self.verdict.shown(languages)
        return message("V110", {"program": program, "reason": reason}, languages)


@dataclass(frozen=True)
class _Job:
    program: Path
    time_limit: float | None
    language: str | None  # the command's --language
    cpu_seconds: float | None = None  # the run's CPU budget (the sandbox's limit)


def run_golden_tests(
    programs: Sequence[Path],
    settings: Settings,
    on_result: Callable[[int, ProgramResult], None] | None = None,
) -> list[ProgramResult]:
    """Test every program (in parallel); results come back in the order of ``programs``."""
    chosen = settings.languages.chosen
    cpu = settings.limits.cpu_seconds
    jobs = [_Job(program, settings.time_limit, chosen, cpu) for program in programs]
    results: list[ProgramResult | None] = [None] * len(jobs)
    for done, finished in enumerate(_run(jobs, settings), 1):
        result = _judge(finished, settings)
        results[finished.index] = result
        if on_result is not None:
            on_result(done, result)
    return [result for result in results if result is not None]


def _run(jobs: Sequence[_Job], settings: Settings) -> Iterator[Finished[_Job, Produced]]:
    return run_isolated(_produce_job, jobs, settings.limits, settings.workers)


def _produce_job(job: _Job) -> Produced:
    return produce(job.program, job.time_limit, language=job.language, cpu_seconds=job.cpu_seconds)


def unfinished(
    program: Path, finished: Finished[Any, Produced], languages: Languages
) -> ProgramResult | None:
    """The result of a run stopped at a limit or crashed (its report as ``languages`` show
    it); None for one that has its output."""
    stopped = why_unfinished(finished)
    if stopped is None:
        return None
    verdict, found = stopped
    seconds = finished.wall_seconds
    told = found.shown(languages)
    return ProgramResult(program, verdict, render(found, "", languages), None, seconds, told)


def why_unfinished(finished: Finished[Any, Produced]) -> tuple[Verdict, Diagnostic] | None:
    """Which limit stopped a run, or that it crashed, and the message that says so; None for
    a run that has its output."""
    if finished.status is Status.OK and finished.result is not None:
        return None
    verdict, code = {
        Status.CPU_LIMIT: (Verdict.CPU_LIMIT, "E611"),
        Status.WALL_LIMIT: (Verdict.WALL_LIMIT, "E621"),
        Status.MEMORY_LIMIT: (Verdict.MEMORY_LIMIT, "E612"),
    }.get(finished.status, (Verdict.CRASHED, "E613"))
    return verdict, diagnostic(code, limit=finished.detail, reason=finished.detail)


def _judge(finished: Finished[_Job, Produced], settings: Settings) -> ProgramResult:
    program, update, languages = finished.job.program, settings.update, settings.languages
    seconds = finished.wall_seconds
    stopped = unfinished(program, finished, languages)
    if stopped is not None or finished.result is None:
        assert stopped is not None
        return stopped
    produced = finished.result
    golden = golden_path(program)
    expected = _read(golden)
    if expected == produced.text:
        return ProgramResult(program, Verdict.PASSED, "", produced, seconds)
    if update:
        golden.write_text(produced.text, encoding="utf-8")
        return ProgramResult(program, Verdict.UPDATED, "", produced, seconds)
    if expected is None:
        missing = diagnostic("E606", golden=str(golden))
        told = missing.shown(languages)
        shown = render(missing, "", languages)
        return ProgramResult(program, Verdict.MISSING, shown, produced, seconds, told)
    report = mismatch_report(program, golden, expected, produced, languages)
    first = first_difference(expected, produced.text)
    return ProgramResult(program, Verdict.FAILED, report, produced, seconds, first)


def _read(path: Path) -> str | None:
    try:
        return path.read_text(encoding="utf-8")
    except FileNotFoundError:
        return None


def mismatch_report(
    program: Path, golden: Path, expected: str, produced: Produced, languages: Languages = ENGLISH
) -> str:
    """A unified diff, led by the program line behind the first line that differs (its words
    as ``languages`` say them)."""
    old, new = expected.splitlines(), produced.text.splitlines()
    parts: list[str] = []
    line = first_source_line(old, new, produced.source_lines)
    if line:
        lines = source_lines(program.read_text(encoding="utf-8"))
        text = lines[line - 1].rstrip() if line <= len(lines) else ""
        parts.append(message("V115", {"line": line, "program": program.name}, languages))
        parts.append(f"    {line:>4} | {text}")
    labels = message("V116", {"golden": str(golden)}, languages), message("V117", {}, languages)
    diff = difflib.unified_diff(old, new, *labels, lineterm="")
    parts.extend(diff)
    return "\n".join(parts)


def first_difference(expected: str, produced: str) -> str:
    """The first line where this run's output and the golden file part, on one line (for
    reports a machine reads): ``line 4: expected '...', got '...'``."""
    old, new = expected.splitlines(), produced.splitlines()
    for number, (want, got) in enumerate(itertools.zip_longest(old, new), 1):
        if want != got:
            return f"line {number}: expected {_shown(want)}, got {_shown(got)}"
    return ""


def _shown(line: str | None) -> str:
    return "the end of the file" if line is None else repr(line.strip())


def first_source_line(old: list[str], new: list[str], source_lines: Sequence[int]) -> int:
    """The program line behind the first line of this run's output that differs and comes
    from a program line (the ``end:`` line, say, differs too but comes from none); 0: none."""
    matcher = difflib.SequenceMatcher(None, old, new, autojunk=False)
    for tag, _i1, _i2, j1, j2 in matcher.get_opcodes():
        if tag == "equal":
            continue
        for index in range(j1, max(j2, j1 + 1)):
            if index < len(source_lines) and source_lines[index]:
                return source_lines[index]
    return 0


@dataclass
class Progress:
    """A single progress line, rewritten in place on a terminal (silent elsewhere)."""

    total: int
    stream: TextIO
    started: float = field(default_factory=time.monotonic)
    failed: int = 0

    def show(self, done: int, result: ProgramResult) -> None:
        if not result.verdict.ok:
            self.failed += 1
        if not self.stream.isatty():
            return
        width = 30
        bar = "#" * (width * done // max(self.total, 1))
        failed = f", {self.failed} failed" if self.failed else ""
        line = f"[{bar:.<{width}}] {done}/{self.total}{failed}  {result.program.name}"
        self.stream.write("\r" + line[:WIDTH].ljust(WIDTH))
        if done == self.total:
            self.stream.write("\r" + " " * WIDTH + "\r")
        self.stream.flush()


WIDTH = 79


def summary(
    results: Sequence[ProgramResult], seconds: float, languages: Languages = ENGLISH
) -> str:
    """The last lines of a run of tests: how many ended how, and what to do next."""
    counts: dict[Verdict, int] = {}
    for result in results:
        counts[result.verdict] = counts.get(result.verdict, 0) + 1
    parts = [f"{count} {verdict.shown(languages)}" for verdict, count in counts.items()]
    outcomes = ", ".join(parts) if parts else message("V121", {}, languages)
    said = {"count": len(results), "seconds": f"{seconds:.1f}", "outcomes": outcomes}
    text = message("V118" if len(results) == 1 else "V119", said, languages)
    timed_out = sum(1 for r in results if r.produced is not None and r.produced.end == "time_limit")
    if timed_out:
        text += " " + message("V120", {"count": timed_out}, languages)
    if counts.get(Verdict.MISSING) or counts.get(Verdict.FAILED):
        text += "\n" + message("V122", {}, languages)
    return text


def default_workers() -> int:
    return os.cpu_count() or 1
