"""The robot's link outlives the program: the program runs in a process of its own, apart from
the one that holds the robot's link, and if it dies the link holder stops the robot.

A program can kill the process it runs in — a crash deep in Python or a library, the operating
system's out-of-memory killer, a ``kill -9`` — and then nothing in that process can stop the
robot. So on a robot (``rootlang run``, the studio's robot runs) the work is split in two:

- the **program's process** runs the runtime as always, on a :class:`RelayTransport`: each
  packet goes over a pipe to the link holder, each packet from the robot comes back the same
  way (a write is answered once the robot has it, when the link acknowledges writes);
- the **link holder** (the process that started it: :func:`start_program`, then
  :meth:`ProgramProcess.serve`) holds the Bluetooth link and relays. When the program's process
  ends with the link still open — it died, whatever the cause — the holder stops the robot
  itself, with the runtime's own confirmed Stop and Reset (:meth:`RobotClient.stop_robot`, on
  a client that takes over the open link), and closes the link. :class:`Held` says what
  happened, for the child's message (E218, or E219 when the robot never confirmed the stop).

The program's process is forked where the platform can (it starts at once, with the program
already checked); elsewhere it is spawned (its arguments are pickled). It is started *before*
the holder opens Bluetooth, so no Bluetooth thread is ever forked. Each side reads the pipe in
a thread of its own and hands what comes to its event loop, and writes from a thread of its own
too, so a program busy computing never blocks the holder, nor a flood of sensor events the
program.
"""

from __future__ import annotations

import asyncio
import contextlib
import itertools
import os
import signal
import sys
from collections.abc import Callable, Coroutine
from dataclasses import dataclass
from multiprocessing.connection import Connection
from multiprocessing.process import BaseProcess
from typing import Any

from rootlang.app.pipe import Pipe
from rootlang.app.sandbox import process_context
from rootlang.diagnostics import RootlangError
from rootlang.runtime.client import RobotClient
from rootlang.runtime.clock import Clock
from rootlang.runtime.trace import Trace
from rootlang.runtime.transport import (
    DisconnectHandler,
    LinkLost,
    PacketHandler,
    RobotInfo,
    Transport,
)

CONNECT_SECONDS = 60.0  # the holder opens the link when the program asks; finding takes time
DISCONNECT_SECONDS = 10.0
CTRL_C_GRACE_S = 5.0  # after Ctrl-C the program stops the robot itself; if it hangs: ended
_EXIT_INTERRUPTED = 130

ProgramMain = Callable[..., int]
"""The program's side: ``main(transport, *args) -> exit code``, module-level (it may be
pickled), run in the program's process on the :class:`RelayTransport` it is given."""


class RelayTransport(Transport):
    """The robot as the program's process has it: through the link holder (see the module)."""

    def __init__(self, connection: Connection) -> None:
        self._connection = connection
        self._pipe: Pipe | None = None
        self._on_packet: PacketHandler | None = None
        self._on_disconnect: DisconnectHandler | None = None
        self._numbers = itertools.count(1)
        self._waiting: dict[int, asyncio.Future[str | None]] = {}
        self._connected: asyncio.Future[Any] | None = None
        self._closed: asyncio.Future[None] | None = None
        self.description = ""
        """The robot as the holder describes it (its model and name), once connected."""

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        loop = asyncio.get_running_loop()
        self._on_packet, self._on_disconnect = on_packet, on_disconnect
        self._connected = loop.create_future()
        self._pipe = Pipe(self._connection, loop, self._message, "rootlang-link")
        self._pipe.send(("connect",))
        kind, *data = await asyncio.wait_for(self._connected, CONNECT_SECONDS)
        if kind == "failed":
            diagnostics, source = data
            raise RootlangError(diagnostics, source)
        info, acknowledges, self.description = data
        self.acknowledges_writes = acknowledges
        return info  # type: ignore[no-any-return]

    async def send(self, packet: bytes) -> None:
        if self._pipe is None or self._pipe.gone:
            raise ConnectionError("the link's process has gone")
        number = next(self._numbers)
        answer = self._waiting[number] = asyncio.get_running_loop().create_future()
        self._pipe.send(("send", number, bytes(packet)))
        try:
            failure = await answer
        finally:
            self._waiting.pop(number, None)
        if failure is not None:
            raise ConnectionError(failure)

    async def disconnect(self) -> None:
        pipe = self._pipe
        if pipe is None or pipe.gone or self._closed is not None:
            return
        self._closed = asyncio.get_running_loop().create_future()
        pipe.send(("disconnect",))
        with contextlib.suppress(asyncio.TimeoutError):
            await asyncio.wait_for(asyncio.shield(self._closed), DISCONNECT_SECONDS)
        pipe.close()

    def _message(self, message: Any) -> None:
        if message is None:  # the holder has gone, and the link with it
            self._fail("the link's process has gone")
            return
        kind, *data = message
        if kind == "packet" and self._on_packet is not None:
            self._on_packet(data[0])
        elif kind in ("connected", "failed") and self._connected is not None:
            if not self._connected.done():
                self._connected.set_result(message)
        elif kind == "sent":
            number, failure = data
            answer = self._waiting.get(number)
            if answer is not None and not answer.done():
                answer.set_result(failure)
        elif kind == "lost":
            self._fail(data[0])
        elif kind == "disconnected" and self._closed is not None and not self._closed.done():
            self._closed.set_result(None)

    def _fail(self, reason: str) -> None:
        for answer in self._waiting.values():
            if not answer.done():
                answer.set_result(reason)
        if self._closed is not None and not self._closed.done():
            self._closed.set_result(None)
        if self._connected is not None and not self._connected.done():
            self._connected.set_exception(ConnectionError(reason))
        if self._on_disconnect is not None:
            handler, self._on_disconnect = self._on_disconnect, None
            handler(reason)


@dataclass(frozen=True)
class Held:
    """How the program's process ended, as the link holder saw it."""

    exitcode: int | None
    died: bool
    """It ended with the link still open (killed, crashed, out of memory ...): the holder
    stopped the robot."""
    stopped: bool = True
    """Whether the robot confirmed that stop (when it died with a link open)."""

    @property
    def how(self) -> str:
        """How the process ended, as a signal's or exit code's name (the same in every
        language): ``SIGKILL``, ``SIGSEGV``, ``exit code 1``."""
        code = self.exitcode
        if code is not None and code < 0:
            with contextlib.suppress(ValueError):
                return signal.Signals(-code).name
            return f"signal {-code}"
        return f"exit code {code}"

    @property
    def code(self) -> str:
        """The catalogue's message for it: E218 (stopped), E219 (not confirmed)."""
        return "E218" if self.stopped else "E219"


def start_program(main: ProgramMain, *args: Any) -> ProgramProcess:
    """Start the program's process now (before any Bluetooth: see the module), waiting for
    the link; ``main(RelayTransport, *args)`` runs there."""
    context = process_context()
    ours, theirs = context.Pipe(duplex=True)
    process = context.Process(
        target=_program_process, args=(theirs, ours, main, args), name="rootlang-program",
        daemon=True,
    )  # fmt: skip
    process.start()
    theirs.close()
    return ProgramProcess(process, ours)


def _program_process(
    connection: Connection, holders: Connection, main: ProgramMain, args: tuple[Any, ...]
) -> None:
    """The program's process: its exit code is ``main``'s. It closes its copy of the holder's
    end of the pipe (forked with it), so the holder's death, however it dies, ends the pipe:
    the run ends as on a lost link and the process with it, never left behind orphaned."""
    holders.close()
    try:
        code = main(RelayTransport(connection), *args)
    except KeyboardInterrupt:  # Ctrl-C before the runtime took it over
        code = _EXIT_INTERRUPTED
    sys.stdout.flush()
    sys.exit(code)


class ProgramProcess:
    """The program's process, seen from the link holder."""

    def __init__(self, process: BaseProcess, connection: Connection) -> None:
        self.process = process
        self._connection = connection
        self._inner: Transport | None = None
        self._piped = False
        self._linked = False  # the robot's link is open (the program asked, and hasn't closed it)
        self._sends: asyncio.Queue[tuple[int, bytes]] | None = None
        self._on_packet: PacketHandler = lambda data: None
        self._on_lost: DisconnectHandler = lambda reason: None

    def kill(self) -> None:
        """End it now (the holder found no robot, or is itself stopping)."""
        if self.process.is_alive():
            self.process.kill()
        self.process.join()
        if not self._piped:
            self._connection.close()

    async def serve(
        self, inner: Transport, clock: Clock, description: str = "", *, open_: bool = False
    ) -> Held:
        """Relay between the program and ``inner`` (a robot's transport, not yet connected)
        until the program's process ends; stop the robot if it ends with the link open."""
        loop = asyncio.get_running_loop()
        self._inner = inner
        self._sends = asyncio.Queue()
        ended: asyncio.Future[None] = loop.create_future()
        info: list[RobotInfo] = []
        tasks: set[asyncio.Task[None]] = set()

        def later(work: Coroutine[Any, Any, None]) -> None:
            task = loop.create_task(work)
            tasks.add(task)
            task.add_done_callback(tasks.discard)

        def message(received: Any) -> None:
            if received is None:
                if not ended.done():
                    ended.set_result(None)
                return
            kind, *data = received
            if kind == "connect":
                later(connect())
            elif kind == "send":
                assert self._sends is not None
                self._sends.put_nowait((data[0], data[1]))
            elif kind == "disconnect":
                later(disconnect())

        def packet(data: bytes) -> None:
            self._on_packet(data)

        def lost(reason: LinkLost) -> None:
            self._linked = False
            self._on_lost(reason)

        self._on_packet = lambda data: pipe.send(("packet", data))
        self._on_lost = lambda reason: pipe.send(("lost", reason))

        async def connect() -> None:
            try:
                info.append(await inner.connect(packet, lost))
            except RootlangError as error:
                pipe.send(("failed", list(error.diagnostics), error.source))
                return
            except Exception as error:  # a Bluetooth stack's own error: a link not made
                pipe.send(("failed", RootlangError.of("E208", reason=str(error)).diagnostics, ""))
                return
            self._linked = True
            pipe.send(("connected", info[0], inner.acknowledges_writes, description))

        async def disconnect() -> None:
            await self._drain()
            self._linked = False
            with contextlib.suppress(Exception):  # closing a link that went is no error
                await inner.disconnect()
            pipe.send(("disconnected",))

        async def relay() -> None:
            assert self._sends is not None
            while True:
                number, data = await self._sends.get()
                try:
                    await inner.send(data)
                    failure = None
                except Exception as error:  # the link failed: the program's client says so
                    failure = f"{error}" or type(error).__name__
                pipe.send(("sent", number, failure))
                self._sends.task_done()

        # what the program says is heard only from here (a Ctrl-C before this leaves no
        # message to land on a half-set-up holder)
        pipe = Pipe(self._connection, loop, message, "rootlang-link")
        self._piped = True  # (the pipe closes the connection once done with it)
        relaying = loop.create_task(relay())
        interrupted = _CtrlC(loop, self)
        try:
            await ended
            await self._drain()
        finally:
            relaying.cancel()
            for task in tasks:  # (a link still being made for a program that has ended)
                task.cancel()
            # ended here, each closing what it opened, not left to the loop's closing (where a
            # connect cut short printed Python's own "Task was destroyed" and a traceback)
            await asyncio.gather(relaying, *tasks, return_exceptions=True)
            interrupted.close()
            pipe.close()
        await loop.run_in_executor(None, self.process.join)
        if not self._linked:
            return Held(self.process.exitcode, died=False)
        stopped = await self._stop_robot(info[0], clock)
        return Held(self.process.exitcode, died=True, stopped=stopped)

    async def _drain(self) -> None:
        """Wait until the packets the program sent have gone out."""
        if self._sends is not None:
            await self._sends.join()

    async def _stop_robot(self, info: RobotInfo, clock: Clock) -> bool:
        """The program died with the link open: stop the robot as the runtime would (a client
        of our own takes the link over), then close the link."""
        assert self._inner is not None
        client = RobotClient(self._inner, clock, Trace(clock.now))
        self._on_packet, self._on_lost = client.adopt(info)
        try:
            return await client.stop_robot()
        except (RootlangError, OSError, asyncio.TimeoutError):
            return False
        finally:
            self._linked = False
            with contextlib.suppress(Exception):
                await self._inner.disconnect()


class _CtrlC:
    """While the holder serves, Ctrl-C is the program's (its runtime stops the robot, and
    `when stopped` runs): the holder passes it on (a terminal sends it to both processes, a
    `kill -INT` to the holder alone; a second one changes nothing) and ends a program that
    has not ended :data:`CTRL_C_GRACE_S` later (then it stops the robot itself)."""

    def __init__(self, loop: asyncio.AbstractEventLoop, program: ProgramProcess) -> None:
        self._loop = loop
        self._program = program
        self._timer: asyncio.TimerHandle | None = None
        try:
            loop.add_signal_handler(signal.SIGINT, self._pressed)
            self._installed = True
        except (NotImplementedError, RuntimeError, ValueError):  # not the main thread, Windows
            self._installed = False

    def _pressed(self) -> None:
        process = self._program.process
        if process.is_alive() and process.pid is not None:
            with contextlib.suppress(ProcessLookupError):
                os.kill(process.pid, signal.SIGINT)
        if self._timer is None:
            self._timer = self._loop.call_later(CTRL_C_GRACE_S, self._too_late)

    def _too_late(self) -> None:
        if self._program.process.is_alive():
            self._program.process.kill()

    def close(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
        if self._installed:
            self._loop.remove_signal_handler(signal.SIGINT)
