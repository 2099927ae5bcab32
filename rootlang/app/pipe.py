"""One end of a pipe to another process, on an event loop, that never blocks the loop.

A :class:`multiprocessing.connection.Connection` reads and writes whole messages, blocking: a
big message (a run's replay) read on the loop holds it until the other process has written all
of it, and a write to a process that doesn't read (a run busy computing) holds it until that
process reads. So each end reads in a thread of its own and hands each message to the loop,
and writes from a thread of its own too. The connection is closed once both threads are done
(never while one of them may still use it: its number could be reused meanwhile).
"""

from __future__ import annotations

import asyncio
import contextlib
import queue
import threading
from collections.abc import Callable
from multiprocessing.connection import Connection
from typing import Any


class Pipe:
    """What comes is handed to ``on_message`` on ``loop`` (None once the other side has gone,
    or the pipe is closed), what is sent goes out in order from a thread."""

    def __init__(
        self,
        connection: Connection,
        loop: asyncio.AbstractEventLoop,
        on_message: Callable[[Any], None],
        name: str = "rootlang-pipe",
    ) -> None:
        self._connection = connection
        self._loop = loop
        self._on_message = on_message
        self._outbox: queue.SimpleQueue[Any] = queue.SimpleQueue()
        self._threads_left = 2
        self._lock = threading.Lock()
        self.gone = False
        for target, role in ((self._read, "reader"), (self._write, "writer")):
            threading.Thread(target=target, name=f"{name}-{role}", daemon=True).start()

    def send(self, message: Any) -> None:
        self._outbox.put(message)

    def close(self) -> None:
        """Nothing more to send: the writer ends once what was sent has gone out. (The
        reader ends when the other side closes its end.)"""
        self._outbox.put(None)

    def _read(self) -> None:
        while True:
            try:
                message = self._connection.recv()
            except (EOFError, OSError):
                message = None
            with contextlib.suppress(RuntimeError):  # the loop has closed: nobody to tell
                self._loop.call_soon_threadsafe(self._hand_over, message)
            if message is None:
                self._done()
                return

    def _hand_over(self, message: Any) -> None:
        if message is None:
            self.gone = True
        self._on_message(message)

    def _write(self) -> None:
        while (message := self._outbox.get()) is not None:
            try:
                self._connection.send(message)
            except (OSError, ValueError):  # the other side has gone: its reader says so
                break
        self._done()

    def _done(self) -> None:
        with self._lock:
            self._threads_left -= 1
            last = self._threads_left == 0
        if last:
            self._connection.close()
