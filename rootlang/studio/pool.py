"""Conversions off the event loop: a few worker processes that turn text into blocks and back,
format and check, so the class never waits for one child.

The server's event loop streams every live run; a conversion of a long program takes seconds
of CPU, so none runs on it. Requests go to a lane of worker processes (started from the same
fork server as the runs when the first request comes, then kept warm: the parser and the blocks
are loaded once):

- the **small** lane, one worker per core, for the ordinary requests (a few kB), at the runs'
  priority (measured: a lower one starves the pupils' conversions on a busy computer);
- the **big** lane, one worker at a lower priority (``nice``), for requests over
  :data:`BIG_BYTES`: a 0.9 MB program waits its turn there, never holds up the small lane, and
  gives way to the live runs.

Each request has a time limit (:data:`SECONDS`) and each worker a memory cap: a worker past
either, or one that crashes (a workspace nested too deep for the C stack), is ended and
replaced, and the request gets E818. The request's body travels as bytes and the answer comes
back as JSON text, so the event loop never parses or builds a big JSON itself.
"""

from __future__ import annotations

import asyncio
import contextlib
import gc
import os
import sys
import threading
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess
from typing import Any

from rootlang.diagnostics import RootlangError, diagnostic
from rootlang.studio.runs import CONTEXT, ClassLimits
from rootlang.wording.language import Languages

SECONDS = ClassLimits.conversion_seconds  # a request's time limit (2,000 lines convert in ~1 s)
MEMORY_MB = 1024  # each worker's memory cap, on top of what it has loaded
BIG_BYTES = 64 * 1024  # a request larger than this goes to the big lane
BIG_NICENESS = 10  # the big lane's priority, below the runs and the small lane
STACK_BYTES = 512 * 1024 * 1024  # a worker's thread stack: deep JSON nests deep in C
RECURSION_LIMIT = 200_000
PROCESS_NAME = "rootlang-conversions"  # (a run's worker is told from these by its name)


def worker_main(connection: Connection, niceness: int, memory_mb: int) -> None:
    """A conversion worker: serve jobs on ``connection`` until it closes (in a thread with a
    big stack: Blockly's JSON nests a script's blocks one inside the next)."""
    threading.stack_size(STACK_BYTES)
    thread = threading.Thread(target=_serve, args=(connection, niceness, memory_mb))
    thread.start()
    thread.join()


def _serve(connection: Connection, niceness: int, memory_mb: int) -> None:
    from rootlang.app.sandbox import cap_memory
    from rootlang.jsontree import stack_has_room
    from rootlang.studio.conversions import JOBS, warm_up

    sys.setrecursionlimit(RECURSION_LIMIT)
    stack_has_room()
    warm_up()  # (at full priority: a pupil may be waiting for it)
    gc.freeze()  # (what it loaded stays: a full collection looked at all of it, 16 ms)
    if niceness:
        with contextlib.suppress(OSError):
            os.nice(niceness)
    cap_memory(memory_mb)
    try:
        connection.send(("ready", None))
    except OSError:  # the server stopped meanwhile
        return
    while True:
        try:
            job, arguments, languages = connection.recv()
        except (EOFError, OSError):  # the server is gone, or ended this worker
            return
        try:  # (each job speaks the languages of the request it answers)
            result: tuple[str, Any] = ("ok", JOBS[job](languages, *arguments))
        except MemoryError:
            result = ("memory", None)
        except RecursionError:
            result = ("deep", None)
        connection.send(result)


class _Died(Exception):
    """The worker process ended (killed at a limit, or crashed)."""


@dataclass
class _Worker:
    niceness: int
    memory_mb: int
    connection: Connection = field(init=False)
    process: BaseProcess = field(init=False)

    def __post_init__(self) -> None:
        ours, theirs = CONTEXT.Pipe(duplex=True)
        self.process = CONTEXT.Process(
            target=worker_main, args=(theirs, self.niceness, self.memory_mb), daemon=True,
            name=PROCESS_NAME,
        )  # fmt: skip
        self.process.start()
        theirs.close()
        self.connection = ours

    def ready(self) -> _Worker:
        """Wait until the worker has loaded what it needs (in a thread, never the loop's)."""
        with contextlib.suppress(EOFError, OSError):  # (dead at once: its first job says so)
            self.connection.recv()
        return self

    def exchange(self, message: tuple[str, tuple[Any, ...], Languages]) -> tuple[str, Any]:
        """Send a job and wait for its result (in a thread of the pool's, never the loop's)."""
        try:
            self.connection.send(message)
            result: tuple[str, Any] = self.connection.recv()
        except (EOFError, OSError):
            raise _Died from None
        return result

    def end(self) -> None:
        with contextlib.suppress(OSError, ValueError, AttributeError):
            self.process.kill()
        with contextlib.suppress(OSError):
            self.connection.close()


@dataclass
class _Lane:
    """Workers of one priority; a worker is in ``idle`` when it is ready and has no job (a
    request's time limit never counts a new worker's start). The worker that finished last
    goes first: it has read the lines of the program sent last (kept by
    :func:`rootlang.studio.conversions.lines_read`), and a child typing sends that program
    again with one line changed (a 500-line program: 40 ms a conversion, 120 ms in a worker
    that has not read it)."""

    size: int
    niceness: int
    memory_mb: int
    threads: ThreadPoolExecutor
    idle: asyncio.LifoQueue[_Worker] | None = None
    workers: list[_Worker] = field(default_factory=list)
    closed: bool = False

    def start(self) -> asyncio.LifoQueue[_Worker]:
        if self.idle is None:
            self.idle = asyncio.LifoQueue()
            for _ in range(self.size):
                self._add()
        return self.idle

    async def take(self, closing: asyncio.Event) -> _Worker:
        """A ready worker with no job (E818 if the studio stops meanwhile)."""
        waiting = asyncio.ensure_future(self.start().get())
        stopping = asyncio.ensure_future(closing.wait())
        await asyncio.wait({waiting, stopping}, return_when=asyncio.FIRST_COMPLETED)
        stopping.cancel()
        if not waiting.done():
            waiting.cancel()
            raise _stopped("V084")
        return waiting.result()

    def replace(self, worker: _Worker) -> None:
        worker.end()
        if worker in self.workers:
            self.workers.remove(worker)
        if not self.closed:
            self._add()

    def give_back(self, worker: _Worker) -> None:
        if self.idle is not None and worker in self.workers and not self.closed:
            self.idle.put_nowait(worker)

    def close(self) -> None:
        self.closed = True
        for worker in self.workers:
            worker.end()

    def _add(self) -> None:
        """A new worker, started and waited for in a thread (starting a process waits for the
        fork server: never on the event loop, which streams the runs)."""
        made = asyncio.get_running_loop().run_in_executor(
            self.threads, lambda: _Worker(self.niceness, self.memory_mb).ready()
        )
        made.add_done_callback(self._made)

    def _made(self, made: asyncio.Future[_Worker]) -> None:
        if made.exception() is not None:  # no process (the machine is out of them): none
            return
        worker = made.result()
        if self.closed:
            worker.end()
            return
        self.workers.append(worker)
        self.give_back(worker)


def _stopped(why: str, seconds: str = "", limit: int = 0) -> RootlangError:
    """E818, with why (a V08x: a message within the message, shown in the page's language)."""
    return RootlangError.of("E818", reason=diagnostic(why, seconds=seconds, limit=limit))


def _retrieved(answer: asyncio.Future[Any]) -> None:
    """An answer nobody waits for any more: its end is looked at, so it is not logged."""
    if not answer.cancelled():
        answer.exception()


class ConversionPool:
    """The studio's conversion workers: ``await pool.run("text_to_blocks", languages, body)``."""

    def __init__(
        self, size: int | None = None, *, seconds: float = SECONDS, memory_mb: int = MEMORY_MB
    ) -> None:
        self.size = size or os.cpu_count() or 1
        self.seconds = seconds
        # one thread per worker waits for its answer, so the event loop never does
        self._threads = ThreadPoolExecutor(self.size + 1, thread_name_prefix="conversions")
        self._small = _Lane(self.size, 0, memory_mb, self._threads)
        self._big = _Lane(1, BIG_NICENESS, memory_mb, self._threads)
        self._closing: asyncio.Event | None = None

    def warm_up(self) -> None:
        """Start the workers now (else the first request starts them, and waits)."""
        self._small.start()
        self._big.start()

    async def run(self, job: str, languages: Languages, *arguments: Any, size: int = 0) -> Any:
        """The job's result (its messages in ``languages``), from a worker of the lane for a
        request of ``size`` bytes; RootlangError E818 past the time limit or the memory cap,
        or if the worker crashed."""
        lane = self._big if size > BIG_BYTES else self._small
        if self._closing is None:
            self._closing = asyncio.Event()
        if lane.closed:
            raise _stopped("V084")
        worker = await lane.take(self._closing)
        loop = asyncio.get_running_loop()
        message = (job, arguments, languages)
        answer = loop.run_in_executor(self._threads, worker.exchange, message)
        try:
            status, result = await asyncio.wait_for(asyncio.shield(answer), self.seconds)
        except TimeoutError:
            answer.add_done_callback(_retrieved)  # (it ends with the worker: _Died)
            lane.replace(worker)
            raise _stopped("V080", seconds=f"{self.seconds:g}") from None
        except _Died:
            lane.replace(worker)
            raise _stopped("V083") from None
        except asyncio.CancelledError:  # the page went away: the worker is free once done
            answer.add_done_callback(lambda _: lane.give_back(worker))
            raise
        lane.give_back(worker)
        if status == "memory":
            raise _stopped("V081", limit=lane.memory_mb)
        if status == "deep":
            raise _stopped("V082")
        return result

    def close(self) -> None:
        """End every worker (the server is stopping): a request under way or waiting gets
        E818 now."""
        for lane in (self._small, self._big):
            lane.close()
        if self._closing is not None:
            self._closing.set()
        self._threads.shutdown(wait=False)
