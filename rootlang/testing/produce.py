"""Produce a program's golden text: check it, run it in the simulator, describe what happened.

This is the work each test child process does (see :mod:`rootlang.testing.runner`); it runs the
same parts ``rootlang check`` and ``rootlang sim`` run, so what a golden file records is what a
student sees.
"""

from __future__ import annotations

from collections.abc import Sequence
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING

from rootlang import ast
from rootlang.app import session
from rootlang.app.files import read_program
from rootlang.app.sandbox import OverCpuLimit, cpu_backstop
from rootlang.diagnostics import Diagnostic, RootlangError, render
from rootlang.locale.translate import about
from rootlang.runtime.budget import CPU_BUDGET_SPENT, UNLIMITED, CpuBudget
from rootlang.runtime.scheduler import EVENT_PACKETS, STOP_BUTTON_EVENT
from rootlang.testing.golden import Ending, GoldenText, add_recording, add_trace, end_line
from rootlang.wording.language import Languages

if TYPE_CHECKING:
    from rootlang.sim.world import World


@dataclass(frozen=True)
class Produced:
    """A program's golden text, with the program line behind each of its lines (0: none)."""

    text: str
    source_lines: tuple[int, ...]
    end: str  # how the run ended ("finished", "time_limit" ...), or "check" for mistakes
    ending: Ending | None = None  # where the robot ended, what it drew (None: it did not run)


def produce(
    program: Path,
    time_limit: float | None = None,
    world: World | None = None,
    *,
    language: str | None = None,
    cpu_seconds: float | None = None,
) -> Produced:
    """Check and run ``program``; ``time_limit`` (simulated seconds) caps its world's limit;
    ``world``, when given, is the one it runs in (a task's: not the one the program names);
    ``language``: the one it is written in (``--language``; by default the one it declares).
    ``cpu_seconds``: the computer's time the run may use (the sandbox's limit); a run that
    uses it up raises :class:`~rootlang.app.sandbox.OverCpuLimit` (reported as that limit).

    Messages name the program by its file name alone, and speak ``language``, else the one the
    program declares, else English (never the computer's locale), so golden files don't depend
    on the folder the tests were started from or the computer they run on."""
    file = program.name
    languages = Languages(chosen=language)
    try:
        source = read_program(str(program), shown_as=file)
    except RootlangError as error:  # what `rootlang check` says about it
        return _check_output(error.diagnostics, "", languages)
    languages = about(languages, source)
    try:
        loaded = session.load(program, source=source, world=world, shown_as=file,
                              language=language)  # fmt: skip
    except session.Mistakes as mistakes:  # what `rootlang check` says: errors and warnings
        return _check_output(mistakes.found, source, languages)
    except RootlangError as error:  # a missing or broken world
        found = [item.in_file(file) for item in error.diagnostics]
        return _check_output(found, source, languages)
    if time_limit is not None:
        loaded = session.with_time_limit(loaded, time_limit)
    checked = loaded.checked
    backstop: AbstractContextManager[CpuBudget] = (
        nullcontext(UNLIMITED) if cpu_seconds is None else cpu_backstop(cpu_seconds)
    )
    with backstop as budget:
        result, recording = session.simulate(
            checked, loaded.world, source=source, cpu_budget=budget
        )
    if result.error is not None and _out_of_memory(result.error):
        raise MemoryError  # the sandbox reports it as the memory cap, not as the program's error
    if result.error is not None and result.error.code == CPU_BUDGET_SPENT:
        raise OverCpuLimit  # the sandbox reports the CPU-time limit (E611), as the kernel's
    golden = GoldenText()
    failure = result.error
    shown = render(failure.in_file(file), source, languages) if failure else None
    golden.add(end_line(result.end, result.sim_time_s, shown), failure.span.line if failure else 0)
    for warning in checked.warnings:
        golden.blank()
        golden.add(render(warning.in_file(file), source, languages), warning.span.line)
    golden.blank()
    add_trace(golden, result.trace.entries, listened_events(checked.program))
    golden.blank()
    add_recording(golden, recording)
    return Produced(golden.text, tuple(golden.source_lines), result.end, Ending.of(recording))


def listened_events(program: ast.Program) -> frozenset[str]:
    """The event packets that can start one of the program's scripts, and the stop button's.
    (Sensors the program only reads stream events too — a colour sensor crossing its own marker
    lines — and those would make golden files long and fragile without saying anything.)"""
    packets = {STOP_BUTTON_EVENT}
    for script in program.scripts:
        if type(script.event) in EVENT_PACKETS:
            packets.add(EVENT_PACKETS[type(script.event)][0])
    return frozenset(packets)


def _out_of_memory(error: Diagnostic) -> bool:
    """The runtime reports a MemoryError as E216 and stops the robot; in a test's child
    process that means the program hit its memory cap."""
    return error.code == "E216"


def _check_output(found: Sequence[Diagnostic], source: str, languages: Languages) -> Produced:
    """Exactly what ``rootlang check`` prints for a program with mistakes."""
    golden = GoldenText()
    for item in found:
        golden.add(render(item, source, languages) + "\n", item.span.line)
    return Produced(golden.text, tuple(golden.source_lines), "check")
