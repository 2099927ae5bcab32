"""The scheduler: scripts as coroutines on one event loop, events, messages, and stopping.

One :class:`Scheduler` runs one program on one robot client (LANGUAGE.md §6):

- all ``when started`` scripts start together, in source order; scripts that become ready at
  the same instant run in source order (asyncio's ready queue is first-in first-out, and the
  clock breaks timer ties by creation order);
- event scripts fire on the edge — an event packet's arrival, or a condition turning true
  (checked every :data:`CONDITION_PERIOD_SECONDS`) — and a trigger is ignored while its script
  is still running; two scripts for one event both run;
- every stop path (the robot's stop button, Ctrl-C, ``stop all``, a run-time error, the time
  limit, a lost link) goes through :meth:`Scheduler.request_stop`, which cancels every script in
  the same loop turn; then the robot gets Stop and Reset, ``when stopped`` scripts run (2 s at
  most, no motion), and the link is closed.
"""

from __future__ import annotations

import asyncio
import contextlib
import enum
import random
import signal
import sys
from collections import deque
from collections.abc import Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

from rootlang import ast, forms
from rootlang.checks import STOPPED_SCRIPT_LIMIT, CheckedProgram, check
from rootlang.diagnostics import (
    NO_SPAN,
    Diagnostic,
    RootlangError,
    Span,
    diagnostic,
    seconds_text,
)
from rootlang.locale.translate import lines_in_english
from rootlang.protocol import Packet
from rootlang.protocol.enums import BumperState, LightState, SensorColor, StallCause
from rootlang.runtime.budget import UNLIMITED, CpuBudget
from rootlang.runtime.client import (
    ClientStats,
    Pose,
    RobotClient,
    SensorState,
)
from rootlang.runtime.clock import Clock
from rootlang.runtime.interpreter import (
    CONDITION_PERIOD_SECONDS,
    SENSOR_PACKETS,
    Frame,
    Interpreter,
    ScriptStopped,
    bumper_pressed,
    color_seen,
    touch_sensors,
)
from rootlang.runtime.stops import Connected, End, Failed, RunEnded, StoppedBy, StopReason
from rootlang.runtime.trace import Trace, TraceEntry
from rootlang.runtime.transport import LinkLost, RobotInfo, Transport
from rootlang.units import Value

WHEN_STOPPED_SECONDS = STOPPED_SCRIPT_LIMIT  # the checks warn (W103) by the same limit
RUN_RECURSION_LIMIT = 2_000  # Python frames: room for the interpreter's own budget (E215) and
# what runs it; never the limit a program meets (docs/runtime.md, "Depth")
BATTERY_LOW_PERCENT = 20
SENT_MESSAGES_KEPT = 20  # chosen: the last messages sent, for a debugger's watch (a loop may send
# thousands)

# The packet each robot event script listens to (the robot lacks the sensor if it lacks it),
# and that sensor as the checks name it (both from rootlang/forms.py).
EVENT_PACKETS: dict[type[ast.Event], tuple[str, str]] = {
    event: (source.packet, source.feature) for event, source in forms.EVENTS.items()
}
STOP_BUTTON_EVENT = "stop_project_event"


@dataclass
class RunResult:
    """How a run went: the one result every caller of :func:`run_program` gets."""

    end: End
    trace: Trace
    error: Diagnostic | None
    printed: list[str]
    sim_time_s: float
    stats: ClientStats
    pose: Pose | None
    stopped_by: StoppedBy
    """What stopped the run: `stop all`, Ctrl-C, the robot's stop button ..."""
    robot: RobotInfo | None = None

    @property
    def interrupted(self) -> bool:
        """Stopped by Ctrl-C (the command line exits with 130)."""
        return self.stopped_by.reason is StopReason.CTRL_C


@dataclass
class SentMessage:
    """A message a script sent (the debugger's watch shows them)."""

    message: str
    by: str  # the sending script's label
    waiting: bool  # its sender waits for the scripts it started, and they have not all ended


@dataclass
class ScriptRun:
    """One script of the program, and whether it is running now."""

    index: int
    script: ast.Script
    label: str
    task: asyncio.Task[None] | None = None
    active: bool = False


class Scheduler:
    def __init__(
        self,
        checked: CheckedProgram,
        client: RobotClient,
        *,
        source: str = "",
        on_print: Callable[[str], None] | None = None,
        seed: int = 0,
        budget: CpuBudget = UNLIMITED,
    ) -> None:
        program = checked.program
        self.budget = budget
        self.program = program
        self.client = client
        self.clock: Clock = client.clock
        self.trace: Trace = client.trace
        self.source = source
        self.on_print = on_print
        self.random = random.Random(seed)
        self.procedures: Mapping[str, ast.Procedure] = checked.procedures
        self.shared_names = checked.shared_variables
        self.shared: dict[str, Value] = {}
        self.printed_lines: list[str] = []
        self.sent_messages: deque[SentMessage] = deque(maxlen=SENT_MESSAGES_KEPT)
        self.error: Diagnostic | None = None
        self.interpreter = Interpreter(self)
        # scripts named by their header lines in English, alike in every language
        numbers = [script.span.line for script in program.scripts]
        headers = lines_in_english(source, numbers, program.language)
        self.runs = [
            ScriptRun(index, script, _label(index, script, headers))
            for index, script in enumerate(program.scripts, 1)
        ]
        # event packet name -> its scripts, each with its edge test
        self._listeners: dict[str, list[tuple[ScriptRun, EdgeTest]]] = {}
        for run in self.runs:
            event = run.script.event
            if isinstance(event, ast.RobotEvent):
                listener = (run, edge_test(event))
                self._listeners.setdefault(EVENT_PACKETS[type(event)][0], []).append(listener)
        self._stop: RunEnded | None = None
        self._stopped = asyncio.Event()
        self._changed: asyncio.Future[None] | None = None
        self._started_at = 0.0
        self.started = False  # connected, the scripts started: the run's time counts from here
        self._connecting: asyncio.Task[Any] | None = None  # the run, while it connects
        self._background: list[asyncio.Task[None]] = []

    # ---- what the interpreter asks of the scheduler ------------------------------------------

    def elapsed(self) -> float:
        return self.clock.now() - self._started_at

    def state_changed(self) -> asyncio.Future[None]:
        """A future that completes at the next sensor event."""
        if self._changed is None or self._changed.done():
            self._changed = asyncio.get_running_loop().create_future()
        return self._changed

    async def send_message(self, message: str, wait: bool) -> None:
        started = [
            task
            for run in self.runs
            if isinstance(run.script.event, ast.MessageReceived)
            and run.script.event.message.lower() == message.lower()
            and (task := self._start(run)) is not None
        ]
        me = asyncio.current_task()
        by = next((run.label for run in self.runs if run.task is me), "")
        sent = SentMessage(message, by, wait and bool(started))
        self.sent_messages.append(sent)
        await asyncio.sleep(0)
        if sent.waiting:
            try:
                await asyncio.wait(started)
            finally:
                sent.waiting = False

    def stop_other_scripts(self) -> None:
        me = asyncio.current_task()
        for run in self.runs:
            if run.active and run.task is not None and run.task is not me:
                run.task.cancel()

    def stop_all(self) -> None:
        self.request_stop("stopped", StoppedBy(StopReason.STOP_ALL))

    def printed(self, text: str, frame: Frame, node: ast.Node) -> None:
        self.printed_lines.append(text)
        self.trace.add("print", f'"{text}"', script=frame.script, line=node.span.line)
        if self.on_print is not None:
            self.on_print(text)

    @property
    def ending(self) -> bool:
        """Whether the run has been asked to stop (its scripts are being cancelled, or are)."""
        return self._stop is not None

    async def stopping(self) -> None:
        """Until the run is asked to stop."""
        await self._stopped.wait()

    # ---- running -----------------------------------------------------------------------------

    async def run(self, time_limit: float | None = None) -> RunResult:
        loop = asyncio.get_running_loop()
        self._connecting = asyncio.current_task()  # (a stop meanwhile cancels it)
        try:
            info = await self.client.connect()
        except asyncio.CancelledError:
            if self._stop is None:  # our caller gave up on us
                raise
            _uncancel(self._connecting)
            return await self._never_connected()
        finally:
            self._connecting = None
        self.budget.start()
        self._started_at = self.clock.now()
        self.started = True
        self.trace.starts_at(self._started_at)  # the trace's time is `timer`'s: from here
        version = ".".join(map(str, info.protocol_version))
        connected = Connected(info.model.display_name, version)
        self.trace.add("run", connected.english(), record=connected)
        self.client.on_event = self._on_event
        self.client.on_disconnect = lambda reason: self._lost(reason)
        limit = None
        if time_limit is not None:
            limit = loop.call_later(time_limit, self._time_is_up, time_limit)
        try:
            self._leave_out_scripts_for_missing_sensors()
            for run in self.runs:
                if isinstance(run.script.event, ast.Started):
                    self._start(run)
            conditions = [
                r for r in self.runs if isinstance(r.script.event, ast.ConditionBecomesTrue)
            ]
            if conditions:
                self._background.append(loop.create_task(self._watch_conditions(conditions)))
            self._check_finished()
        except RootlangError as error:
            self._fail(error)
        try:
            await self._stopped.wait()
        except asyncio.CancelledError:  # our caller gave up on us: still stop the robot
            self.request_stop("stopped", StoppedBy(StopReason.CANCELLED))
            await self._shut_down(info)
            raise
        finally:
            if limit is not None:
                limit.cancel()
        return await self._shut_down(info)

    def request_stop(self, end: End, by: StoppedBy) -> None:
        """Stop the run: every script is cancelled now, in this loop turn (first reason wins)."""
        if self._stop is not None:
            return
        self._stop = RunEnded(end, by)
        if self._connecting is not None:  # (a robot may take seconds to answer: not waited for)
            self._connecting.cancel()
        for task in self._background:
            task.cancel()
        for run in self.runs:
            if run.task is not None and not run.task.done():
                run.task.cancel()
        self._stopped.set()

    def _time_is_up(self, seconds: float) -> None:
        self.request_stop("time_limit", StoppedBy(StopReason.TIME_LIMIT, seconds=seconds))

    def _lost(self, reason: LinkLost) -> None:
        if self.error is None:
            self._record_error(RootlangError.of("E207", reason=reason))
        self.request_stop("disconnected", StoppedBy.link(reason))

    def _fail(self, error: RootlangError, script: str = "") -> None:
        self._record_error(error, script)
        self.request_stop("error", StoppedBy(StopReason.RUN_ERROR))

    def _record_error(self, error: RootlangError, script: str = "") -> None:
        if self.error is not None or not error.diagnostics:
            return
        self.error = error.diagnostics[0].in_file(self.program.file)
        text = f"{self.error.code} {self.error.english}"
        failed = Failed(self.error)
        self.trace.add("error", text, script=script, line=self.error.span.line, record=failed)

    async def _shut_down(self, info: RobotInfo) -> RunResult:
        assert self._stop is not None
        stop = self._stop
        tasks = [run.task for run in self.runs if run.task is not None] + self._background
        await asyncio.gather(*tasks, return_exceptions=True)
        final_pose = self.client.state.pose
        if self.client.connected:
            await self._stop_robot()
            if stop.end in ("stopped", "time_limit", "error"):
                await self._run_when_stopped()
        ignored = self.client.stats.ignored()
        if ignored:
            self.trace.add("run", f"ignored {ignored}")
        self.trace.add("run", stop.english(), record=stop)
        await self._quietly(self.client.disconnect())
        return RunResult(
            end=stop.end,
            trace=self.trace,
            error=self.error,
            printed=self.printed_lines,
            sim_time_s=self.clock.now(),
            stats=self.client.stats,
            pose=final_pose,
            stopped_by=stop.by,
            robot=info,
        )

    async def _never_connected(self) -> RunResult:
        """The run stopped while connecting (Ctrl-C): the link under way is closed, no script
        has run, the robot was never sent a command."""
        assert self._stop is not None
        stop = self._stop
        await self._quietly(self.client.disconnect())
        self.trace.starts_at(self.clock.now())  # (its time: none of it ran)
        self.trace.add("run", stop.english(), record=stop)
        return RunResult(
            end=stop.end, trace=self.trace, error=self.error, printed=self.printed_lines,
            sim_time_s=self.clock.now(), stats=self.client.stats, pose=None, stopped_by=stop.by,
        )  # fmt: skip

    async def _stop_robot(self) -> None:
        """Stop and Reset goes out first, at once, then is confirmed (see RobotClient.reset);
        if it never is, closing the link stops the robot too."""
        await self._quietly(self.client.stop_robot())

    async def _quietly(self, step: Any) -> None:
        """Shutting down goes on whatever a step raises: the robot must still be stopped."""
        with contextlib.suppress(RootlangError, OSError, asyncio.TimeoutError):
            await step

    async def _run_when_stopped(self) -> None:
        runs = [run for run in self.runs if isinstance(run.script.event, ast.Stopped)]
        tasks = [
            asyncio.get_running_loop().create_task(self._run_script(run, may_move=False))
            for run in runs
        ]
        for run, task in zip(runs, tasks, strict=True):
            run.task, run.active = task, True
        if not tasks:
            return
        _, late = await asyncio.wait(tasks, timeout=WHEN_STOPPED_SECONDS)
        for task in late:
            task.cancel()
        if late:
            late_error = diagnostic("E212", seconds=seconds_text(WHEN_STOPPED_SECONDS))
            self.trace.add("error", late_error.english, record=Failed(late_error))
            await asyncio.gather(*late, return_exceptions=True)

    # ---- scripts -----------------------------------------------------------------------------

    def _start(self, run: ScriptRun) -> asyncio.Task[None] | None:
        if run.active or self._stop is not None:
            return None  # a script's own trigger is ignored while it runs
        run.active = True
        task = run.task = asyncio.get_running_loop().create_task(self._run_script(run))
        task.add_done_callback(lambda _: self._never_ran(run, task))
        return run.task

    def _never_ran(self, run: ScriptRun, task: asyncio.Task[None]) -> None:
        """A task cancelled before its first step (`stop other scripts` before it ran) never
        reaches its own ``finally``: mark its script as ended here, or the run would wait."""
        if run.task is task and run.active:
            run.active = False
            self._check_finished()

    async def _run_script(self, run: ScriptRun, *, may_move: bool = True) -> None:
        line = run.script.span.line
        self.trace.add("start", run.label, script=run.label, line=line)
        how = "finished"
        try:
            await self.interpreter.run_block(run.script.body, Frame(run.label, may_move=may_move))
        except ScriptStopped:
            how = "stopped"
        except asyncio.CancelledError:
            how = "cancelled"
            raise
        except RootlangError as error:
            how = "error"
            self._fail(error, run.label)
        except Exception as error:  # a bug of ours: still stop the robot, and say so plainly
            how = "error"
            self._fail(_unexpected(error, run.script.span), run.label)
        finally:
            run.active = False
            self.trace.add("end", how, script=run.label, line=line)
            self._check_finished()

    def _check_finished(self) -> None:
        if self._stop is not None or any(run.active for run in self.runs):
            return
        if not any(_waits_for_robot(run.script.event) for run in self.runs):
            self.request_stop("finished", StoppedBy(StopReason.FINISHED))

    def _leave_out_scripts_for_missing_sensors(self) -> None:
        """A script whose event needs a sensor the robot lacks never runs, as the check's warning
        (W101) says; the rest of the program runs as usual."""
        self.runs = [run for run in self.runs if self._robot_has_sensors(run.script.event)]
        for listeners in self._listeners.values():
            listeners[:] = [listener for listener in listeners if listener[0] in self.runs]

    def _robot_has_sensors(self, event: ast.Event) -> bool:
        needed = EVENT_PACKETS.get(type(event))
        if needed is not None and not self.client.supports(needed[0]):
            return False
        reads = [node for node in ast.walk(event) if isinstance(node, ast.SensorRead)]
        packets = [SENSOR_PACKETS.get(read.sensor) for read in reads]
        return all(packet is None or self.client.supports(packet) for packet in packets)

    async def _watch_conditions(self, runs: list[ScriptRun]) -> None:
        was_true = dict.fromkeys((run.index for run in runs), False)
        try:
            while True:
                for run in runs:
                    event = run.script.event
                    assert isinstance(event, ast.ConditionBecomesTrue)
                    frame = Frame(run.label)
                    now_true = await self.interpreter.condition(event, event.condition, frame)
                    if now_true and not was_true[run.index]:
                        self._start(run)
                    was_true[run.index] = now_true
                await self.clock.sleep(CONDITION_PERIOD_SECONDS)
        except RootlangError as error:
            self._fail(error, "conditions")
        except Exception as error:  # a bug of ours: every `when <condition>` would go quiet
            self._fail(_unexpected(error), "conditions")

    # ---- events from the robot ---------------------------------------------------------------

    def _on_event(self, packet: Packet, before: SensorState, after: SensorState) -> None:
        try:
            self._dispatch(packet, before, after)
        except Exception as error:  # a bug of ours must not leave the robot running
            self._fail(_unexpected(error))

    def _dispatch(self, packet: Packet, before: SensorState, after: SensorState) -> None:
        name = packet.spec.name
        self.trace.add("event", event_text(packet), packet=packet.name)
        changed = self._changed
        if changed is not None and not changed.done():
            changed.set_result(None)
        if name == STOP_BUTTON_EVENT:
            self.request_stop("stopped", StoppedBy(StopReason.ROBOT_STOP_BUTTON))
            return
        for run, fires in self._listeners.get(name, ()):
            if fires(packet, before, after):
                self._start(run)


def _flipped(before: int, after: int, pressed: bool) -> int:
    """The bits newly set (``pressed``), or newly cleared, from ``before`` to ``after``."""
    return after & ~before if pressed else before & ~after


EdgeTest = Callable[[Packet, SensorState, SensorState], bool]
"""Whether an event packet (with the sensor state before and after it) starts a script."""


def edge_test(event: ast.RobotEvent) -> EdgeTest:
    """The test whether a packet of the event's own kind (``EVENT_PACKETS``) is the edge that
    starts a script with this header; made once per script, asked at every such packet. Every
    robot event has its case: mypy --strict rejects a new one left out (``assert_never``)."""
    match event:
        case ast.BumperEvent(side="any", pressed=pressed):  # any one bumper newly pressed

            def any_bumper(packet: Packet, before: SensorState, after: SensorState) -> bool:
                return bool(_flipped(before.bumpers, after.bumpers, pressed) & BumperState.BOTH)

            return any_bumper
        case ast.BumperEvent(side=side, pressed=pressed):

            def bumper(packet: Packet, before: SensorState, after: SensorState) -> bool:
                now = bumper_pressed(after.bumpers, side)
                return now == pressed and bumper_pressed(before.bumpers, side) != now

            return bumper
        case ast.TouchEvent(sensor=sensor, pressed=pressed):
            mask = touch_sensors(sensor)

            def touch(packet: Packet, before: SensorState, after: SensorState) -> bool:
                return bool(_flipped(before.touch, after.touch, pressed) & mask)

            return touch
        case ast.ColorSeen(zone=zone, color=color):
            seen = color_seen(zone, color)
            return lambda packet, before, after: seen(after.colors) and not seen(before.colors)
        case ast.LightEvent(state=name):
            state = LightState[forms.LIGHT_STATE.meaning(name)]
            return lambda packet, before, after: (
                after.light_state is state and before.light_state is not state
            )
        case ast.CliffEvent(detected=detected):
            return lambda packet, before, after: (
                after.cliff == detected and before.cliff != detected
            )
        case ast.StalledEvent():
            return lambda packet, before, after: bool(packet.fields["cause"] != StallCause.NO_STALL)
        case ast.BatteryLowEvent():
            return lambda packet, before, after: bool(
                packet.fields["percent"] < BATTERY_LOW_PERCENT
            )
        case ast.ObstacleSeen(side=side):
            bits = [1 << sensor for sensor in forms.OBSTACLE_SIDE.meaning(side)]

            def obstacle(packet: Packet, before: SensorState, after: SensorState) -> bool:
                newly = after.ir_triggered & ~before.ir_triggered
                return any(newly & bit for bit in bits)

            return obstacle
        case ast.DockEvent(docked=docked):
            return lambda packet, before, after: after.docked == docked and before.docked != docked
        case _:
            ast.assert_never(event)


def _waits_for_robot(event: ast.Event) -> bool:
    """Scripts started by the robot or by a condition keep a program waiting (§6.6)."""
    return type(event) in EVENT_PACKETS or isinstance(event, ast.ConditionBecomesTrue)


def _label(index: int, script: ast.Script, headers: Mapping[int, str]) -> str:
    header = headers.get(script.span.line, "").strip().rstrip(":").strip()
    return f"{index}:{' '.join(header.split()) or type(script.event).__name__}"


def event_text(packet: Packet) -> str:
    """An event for the trace: its name and fields (no timestamp), values quantised."""
    shown = []
    for name, value in packet.fields.items():
        if name == "timestamp":
            continue
        shown.append(f"{name}={_field_text(value)}")
    return " ".join([packet.name, *shown])


COLOR_LETTERS = {
    SensorColor.WHITE: "W",
    SensorColor.BLACK: "K",  # not B: that is blue (K for black, as in CMYK)
    SensorColor.RED: "R",
    SensorColor.GREEN: "G",
    SensorColor.BLUE: "B",
}
_COLOR_TRANSLATION = bytes.maketrans(bytes(COLOR_LETTERS), "".join(COLOR_LETTERS.values()).encode())


def color_letters(colors: Sequence[SensorColor]) -> str:
    """The colour under each sensor, one letter each (WWKKRR...), as the trace's events write
    them: by a translate table (~20 of these a second)."""
    return bytes(colors).translate(_COLOR_TRANSLATION).decode()


def _field_text(value: object) -> str:
    if isinstance(value, tuple) and value and isinstance(value[0], SensorColor):
        return color_letters(value)
    if isinstance(value, tuple):
        return ",".join(str(item) for item in value)
    if isinstance(value, enum.Enum):
        return str(value.name)
    return str(value)


# ---- the one run entry point ----------------------------------------------------------------


class Inside(Protocol):
    """What looks inside a run as it goes (the debugger, :mod:`rootlang.runtime.debugger`)."""

    def attach(self, scheduler: Scheduler) -> None: ...


async def run_program(
    program: CheckedProgram | ast.Program,
    transport: Transport,
    clock: Clock,
    *,
    source: str = "",
    time_limit: float | None = None,
    on_print: Callable[[str], None] | None = None,
    seed: int = 0,
    handle_ctrl_c: bool = True,
    on_trace: Callable[[TraceEntry], None] | None = None,
    debugger: Inside | None = None,
    cpu_budget: CpuBudget = UNLIMITED,
) -> RunResult:
    """Run a program on a robot (real, simulated or loopback) until it ends or is stopped.

    ``program`` is best a :class:`~rootlang.checks.CheckedProgram`; a bare syntax tree is
    checked first (RootlangError with every error, before connecting to the robot).

    Must run on ``clock``'s loop (``clock.run(run_program(...))``, or :func:`run`). Ctrl-C
    (SIGINT) stops the run like the robot's stop button; the robot is stopped on every path.
    ``on_trace`` sees each trace entry as it is added (to show the run live); a ``debugger``
    may pause it, step it and look inside (:mod:`rootlang.runtime.debugger`). ``cpu_budget``:
    the computer's time the run may use (E220 once it is used up; unlimited by default).
    """
    checked = program if isinstance(program, CheckedProgram) else check(program)
    client = RobotClient(transport, clock, Trace(clock.now, on_trace))
    scheduler = Scheduler(
        checked, client, source=source, on_print=on_print, seed=seed, budget=cpu_budget
    )
    if debugger is not None:
        debugger.attach(scheduler)
    loop = asyncio.get_running_loop()
    handled = handle_ctrl_c and _handle_ctrl_c(loop, scheduler)
    try:
        with _deep_enough_for_calls():
            return await scheduler.run(time_limit)
    finally:
        if handled:
            loop.remove_signal_handler(signal.SIGINT)


@contextlib.contextmanager
def _deep_enough_for_calls() -> Iterator[None]:
    """Python's recursion limit, raised for the run to hold the interpreter's own budget
    (:data:`~rootlang.runtime.interpreter.RUN_STACK_LIMIT` coroutines, E215) above whatever
    runs it: procedures called for their value nest in Python's stack."""
    before = sys.getrecursionlimit()
    sys.setrecursionlimit(max(before, RUN_RECURSION_LIMIT))
    try:
        yield
    finally:
        sys.setrecursionlimit(before)


def run(
    program: CheckedProgram | ast.Program, transport: Transport, clock: Clock, **options: Any
) -> RunResult:
    """:func:`run_program` on a new event loop driven by ``clock``."""
    return clock.run(run_program(program, transport, clock, **options))


def _uncancel(task: asyncio.Task[Any] | None) -> None:
    """A cancel the task has taken in and dealt with is taken back (Python 3.11 counts them:
    a count left over would turn the task's later timeouts into cancels)."""
    if task is not None and hasattr(task, "uncancel"):
        task.uncancel()


def _handle_ctrl_c(loop: asyncio.AbstractEventLoop, scheduler: Scheduler) -> bool:
    try:
        loop.add_signal_handler(
            signal.SIGINT, scheduler.request_stop, "stopped", StoppedBy(StopReason.CTRL_C)
        )
    except (NotImplementedError, RuntimeError, ValueError):  # not the main thread, or Windows
        return False
    return True


def _unexpected(error: Exception, span: Span = NO_SPAN) -> RootlangError:
    """An exception the runtime did not expect: a bug of ours (E699), or memory run out
    outside a statement — still the program's doing (E216, as inside one)."""
    code = "E216" if isinstance(error, MemoryError) else "E699"
    return RootlangError.of(code, span, error=repr(error))
