"""A run's budget of the computer's time (CPU time), the backstop that ends every run.

A simulated run ends at its world's time limit, in the robot's time. But a program can keep
the computer busy without the robot's time moving on much (a thousand scripts each repeating
``wait 0 seconds``: every round of a loop lasts 10 ms of the robot's time, and a round of so
many scripts costs the computer more than that), so the robot's time limit comes late or
never. :class:`CpuBudget` counts this process's CPU time from the run's start; once the run
has used it all, the interpreter stops the run at the line it is running with a run-time error
(E220, in the child's words, ``when stopped`` scripts run and the robot is stopped as on any
error). CPU time, not the wall clock: on a busy computer a run waits its turn for a core, and
that is not the program's doing.

``rootlang sim``, ``rootlang test`` and the studio's runs all get theirs from
:func:`rootlang.app.sandbox.cpu_backstop` (which also sets the kernel's own limit a little
further out, for a run that stops yielding altogether).
"""

from __future__ import annotations

import contextlib
import time
from collections.abc import Callable, Iterator

CPU_BUDGET_SPENT = "E220"
"""The run-time error of a run that used up its budget."""
CHECKED_EVERY = 1024
"""Rounds of the interpreter between two readings of the CPU time (a reading is a system
call): a thousandth of a second of a busy run or less."""


class CpuBudget:
    """``seconds`` of this process's CPU time for one run (None: no limit). ``read`` gives the
    process's CPU seconds (:func:`time.process_time`; tests count with their own)."""

    def __init__(
        self,
        seconds: float | None,
        read: Callable[[], float] = time.process_time,
        on_moved: Callable[[float | None], None] | None = None,
    ) -> None:
        self.seconds = seconds
        self._read = read
        self._on_moved = on_moved
        self._until: float | None = None
        self._rounds = 0

    def start(self) -> None:
        """The run starts: its CPU time counts from now."""
        if self.seconds is not None:
            self._until = self._read() + self.seconds

    def spent(self) -> bool:
        """Asked at every round of the interpreter: whether the run has used its budget (read
        every :data:`CHECKED_EVERY` rounds)."""
        if self._until is None:
            return False
        self._rounds += 1
        if self._rounds < CHECKED_EVERY:
            return False
        self._rounds = 0
        return self._read() >= self._until

    @contextlib.contextmanager
    def set_aside(self) -> Iterator[None]:
        """What the process computes inside doesn't count: a paused run's page still gets its
        frames, however long the child looks. ``on_moved`` hears None on the way in (no limit
        for now) and the CPU seconds left on the way out (for the kernel's own limit)."""
        if self._until is None:
            yield
            return
        before = self._read()
        if self._on_moved is not None:
            self._on_moved(None)
        try:
            yield
        finally:
            now = self._read()
            self._until += now - before
            if self._on_moved is not None:
                self._on_moved(self._until - now)

    @property
    def shown(self) -> str:
        """The budget as a message names it: "60 s"."""
        return f"{self.seconds or 0:g} s"


UNLIMITED = CpuBudget(None)
