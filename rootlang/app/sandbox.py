"""Run untrusted work in child processes, each under a CPU-time limit and a memory cap.

A class's submissions may loop forever or eat memory; neither may hang or exhaust the machine
that tests them. Each job runs in a child process of its own:

- the memory cap is ``resource.setrlimit(RLIMIT_AS)`` in the child (the address space it already
  has, plus the cap), so a runaway program gets a ``MemoryError`` or dies, never the machine;
- the CPU-time limit is the run's own :class:`~rootlang.runtime.budget.CpuBudget` (the run
  stops itself with a child's message, E220, and the work raises :class:`OverCpuLimit`), with
  ``RLIMIT_CPU`` in the child a little further out (:data:`KERNEL_MARGIN_SECONDS`): the kernel
  ends it with ``SIGXCPU`` if it has computed that long all the same. CPU time, not the wall
  clock, judges "runs forever": on a busy machine a child waits its turn for a core, and that
  waiting is not the program's doing. :func:`cpu_backstop` is the one way to set both, for
  ``rootlang sim``, ``rootlang test`` and the studio's runs alike;
- a wall-clock backstop, far out, is kept by the parent for a child that neither computes nor
  ends (where ``resource`` is missing, it is the only limit); it never blames the program;
- up to ``jobs`` children run at once.

Children are forked where the platform allows it (Linux, macOS), so they share the modules the
parent has already imported and start in milliseconds; elsewhere they are spawned (slower, and
without a memory cap where ``resource`` is missing).
"""

from __future__ import annotations

import contextlib
import enum
import math
import multiprocessing
import os
import signal
import threading
import time
import traceback
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass
from multiprocessing.connection import Connection, wait
from multiprocessing.process import BaseProcess
from typing import Generic, TypeVar

from rootlang.runtime.budget import CpuBudget

Job = TypeVar("Job")
Result = TypeVar("Result")

MEBIBYTE = 1024 * 1024
KERNEL_MARGIN_SECONDS = 5.0
"""Chosen: the kernel's CPU-time limit stands this much further out than a run's own budget,
room for the run to stop itself, stop the robot, run its ``when stopped`` scripts and say so."""
KERNEL_PAUSED_SECONDS = 3_600.0
"""Chosen: while a run is paused the kernel still ends a process that computes an hour of CPU
time (a paused run computes only its page's frames)."""


class OverCpuLimit(Exception):
    """Raised by a job whose run stopped itself at its CPU budget (E220): the parent reports
    it as the CPU-time limit, as when the kernel ends the child."""


@contextlib.contextmanager
def cpu_backstop(seconds: float) -> Iterator[CpuBudget]:
    """The CPU-time backstop of one run, while it runs: the budget to hand the run
    (``run_program``'s ``cpu_budget``; it stops with E220 once ``seconds`` of CPU time are
    used), and the kernel's limit for this process set :data:`KERNEL_MARGIN_SECONDS` further
    out (:func:`cap_cpu`), for a run that stops yielding altogether. Afterwards the kernel's
    limit is what it was, if that was further out: a process that goes on after the run
    (``rootlang.cli.main`` called from Python, a test session) is not ended by it later, in
    whatever it computes then (it was: once it had computed the run's seconds more, SIGXCPU)."""
    before = _soft_cpu_limit()
    cap_cpu(seconds + KERNEL_MARGIN_SECONDS)
    try:
        yield CpuBudget(seconds, on_moved=_kernel_follows)
    finally:
        _lift_cpu_limit(before)


def _kernel_follows(left: float | None) -> None:
    """The kernel's limit follows the budget set aside (a paused run) and taken up again."""
    cap_cpu(KERNEL_PAUSED_SECONDS if left is None else left + KERNEL_MARGIN_SECONDS)


class Status(enum.Enum):
    """How a child ended: with a result, or at one of the limits, or by crashing."""

    OK = "ok"
    CPU_LIMIT = "CPU-time limit"
    WALL_LIMIT = "wall-clock limit"
    MEMORY_LIMIT = "memory limit"
    CRASHED = "crashed"


@dataclass(frozen=True)
class Limits:
    """Per-job limits. ``cpu_seconds`` judges a program that runs forever; ``wall_seconds`` is
    the backstop for a machine too busy to finish; ``memory_mb`` counts on top of what the
    parent process already uses."""

    cpu_seconds: float = 60.0
    wall_seconds: float = 600.0
    memory_mb: int = 512


@dataclass(frozen=True)
class Finished(Generic[Job, Result]):
    index: int
    job: Job
    status: Status
    result: Result | None = None
    detail: str = ""
    wall_seconds: float = 0.0


def run_isolated(
    work: Callable[[Job], Result],
    jobs: Sequence[Job],
    limits: Limits,
    workers: int | None = None,
    context: multiprocessing.context.DefaultContext | None = None,
) -> Iterator[Finished[Job, Result]]:
    """Run ``work(job)`` for every job in child processes; yield each as it finishes.

    ``work`` must be a module-level function (it is pickled where children are spawned, or
    started by a fork server). ``context``: how children start (by default forked, see
    :func:`process_context`); a process with threads of its own passes a fork server's, since
    a child forked from it may hang on a lock another of its threads held at that moment.
    """
    context = context or process_context()
    limit = max(1, workers or os.cpu_count() or 1)
    waiting = list(enumerate(jobs))
    waiting.reverse()
    running: dict[Connection, _Child[Job, Result]] = {}
    try:
        while waiting or running:
            while waiting and len(running) < limit:
                index, job = waiting.pop()
                receiver, sender = context.Pipe(duplex=False)
                process = context.Process(
                    target=_child_main, args=(sender, work, job, limits), daemon=True
                )
                with _ctrl_c_held():  # a child is started and counted, or not started at all
                    process.start()
                    running[receiver] = _Child(index, job, process, time.monotonic())
                sender.close()
            now = time.monotonic()
            next_deadline = min(child.started + limits.wall_seconds for child in running.values())
            for connection in wait(list(running), timeout=max(next_deadline - now, 0.0)):
                assert isinstance(connection, Connection)
                yield running.pop(connection).collect(connection, limits)
            now = time.monotonic()
            for connection, child in list(running.items()):
                if now - child.started >= limits.wall_seconds:
                    del running[connection]
                    child.kill()
                    connection.close()
                    detail = f"{limits.wall_seconds:g} s"
                    yield Finished(
                        child.index, child.job, Status.WALL_LIMIT, None, detail, now - child.started
                    )
    finally:  # Ctrl-C, or the caller stopped early: no child outlives the run
        for connection, child in running.items():
            child.kill()
            connection.close()


@dataclass
class _Child(Generic[Job, Result]):
    index: int
    job: Job
    process: BaseProcess
    started: float

    def collect(self, connection: Connection, limits: Limits) -> Finished[Job, Result]:
        result: Result | None = None
        try:
            status_name, result, detail = connection.recv()
            status = Status(status_name)
        except (EOFError, OSError):  # the child died without a word (a signal, the OOM killer)
            self.process.join()
            if ended_by_cpu_limit(self.process.exitcode):
                status, detail = Status.CPU_LIMIT, f"{limits.cpu_seconds:g} s"
            else:
                status = Status.CRASHED
                detail = f"the worker process ended with exit code {self.process.exitcode}"
        connection.close()
        self.process.join()
        return Finished(
            self.index, self.job, status, result, detail, time.monotonic() - self.started
        )

    def kill(self) -> None:
        self.process.kill()
        self.process.join()


@contextlib.contextmanager
def _ctrl_c_held() -> Iterator[None]:
    """A Ctrl-C waits until the block is done: one that came while a child was being forked,
    before it was counted, would leave it running, unseen, until its wall-clock limit (and
    holding the terminal's output). Only the main thread hears Ctrl-C (elsewhere: as is)."""
    previous = signal.getsignal(signal.SIGINT)
    if threading.current_thread() is not threading.main_thread() or previous is None:
        yield
        return
    came: list[int] = []
    signal.signal(signal.SIGINT, lambda number, frame: came.append(number))
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        if came:
            signal.raise_signal(signal.SIGINT)  # now, with the child counted


def process_context() -> multiprocessing.context.DefaultContext:
    """fork where the system has it (quick, nothing re-imported), else spawn."""
    methods = multiprocessing.get_all_start_methods()
    context: multiprocessing.context.DefaultContext = multiprocessing.get_context(
        "fork" if "fork" in methods else "spawn"
    )  # type: ignore[assignment]  # typeshed: the fork/spawn contexts share this interface
    return context


def _child_main(
    sender: Connection, work: Callable[[Job], Result], job: Job, limits: Limits
) -> None:
    signal.signal(signal.SIGINT, signal.default_int_handler)  # (forked as it was held)
    cap_memory(limits.memory_mb)
    cap_cpu(limits.cpu_seconds + KERNEL_MARGIN_SECONDS)  # (the job's run stops itself first)
    try:
        message: tuple[str, object, str] = (Status.OK.value, work(job), "")
    except MemoryError:
        message = (Status.MEMORY_LIMIT.value, None, f"{limits.memory_mb} MB")
    except OverCpuLimit:
        message = (Status.CPU_LIMIT.value, None, f"{limits.cpu_seconds:g} s")
    except BaseException as error:  # anything else is a crash of the worker, reported as such
        message = (
            Status.CRASHED.value,
            None,
            "".join(traceback.format_exception_only(type(error), error)).strip(),
        )
    sender.send(message)
    sender.close()


def cap_memory(memory_mb: int) -> None:
    try:
        import resource
    except ImportError:  # Windows: no caps
        return
    cap = _address_space_in_use() + memory_mb * MEBIBYTE
    _soft, hard = resource.getrlimit(resource.RLIMIT_AS)
    if hard != resource.RLIM_INFINITY:
        cap = min(cap, hard)
    resource.setrlimit(resource.RLIMIT_AS, (cap, hard))


def cap_cpu(seconds: float) -> None:
    """End this process (``SIGXCPU``, whose default action ends it; no core file is written)
    once it has computed ``seconds`` more of CPU time. Only the soft limit is set, so a worker
    may raise it again once it knows more (a run paced to the wall clock may compute longer).
    Does nothing without ``resource`` (Windows): the wall-clock backstop is the limit there."""
    try:
        import resource
    except ImportError:
        return
    used = resource.getrusage(resource.RUSAGE_SELF)
    soft = math.ceil(used.ru_utime + used.ru_stime + seconds)
    hard = resource.getrlimit(resource.RLIMIT_CPU)[1]
    if hard != resource.RLIM_INFINITY:
        soft = min(soft, hard)
    resource.setrlimit(resource.RLIMIT_CPU, (soft, hard))
    with contextlib.suppress(OSError, ValueError):
        resource.setrlimit(resource.RLIMIT_CORE, (0, resource.getrlimit(resource.RLIMIT_CORE)[1]))


def _soft_cpu_limit() -> int | None:
    """This process's CPU-time limit (the kernel's soft one), None without ``resource``."""
    try:
        import resource
    except ImportError:
        return None
    return resource.getrlimit(resource.RLIMIT_CPU)[0]


def _lift_cpu_limit(to: int | None) -> None:
    """The CPU-time limit back to ``to`` (:func:`_soft_cpu_limit`'s), if that is further out
    than the one now: never nearer (a paced run's limit is further out than its process's)."""
    if to is None:
        return
    import resource

    soft, hard = resource.getrlimit(resource.RLIMIT_CPU)
    if soft != resource.RLIM_INFINITY and (to == resource.RLIM_INFINITY or to > soft):
        resource.setrlimit(resource.RLIMIT_CPU, (to, hard))


def ended_by_cpu_limit(exitcode: int | None) -> bool:
    """Whether a child's exit code says the kernel ended it at its CPU-time limit."""
    xcpu = getattr(signal, "SIGXCPU", None)
    return xcpu is not None and exitcode == -xcpu


def _address_space_in_use() -> int:
    """The bytes of address space this process has mapped now (0 where it can't be read)."""
    try:
        with open("/proc/self/statm") as statm:
            pages = int(statm.read().split()[0])
    except (OSError, ValueError, IndexError):
        return 0
    return pages * os.sysconf("SC_PAGE_SIZE")
