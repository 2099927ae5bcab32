"""Statements and expressions: what one line of a script does, and what a value is.

The :class:`Interpreter` walks the AST of one running script. Robot commands go to the
:class:`~rootlang.runtime.client.RobotClient`; everything about scripts as a whole (starting
others, messages, stopping) goes to the scheduler through the small :class:`Runtime` protocol.

Yield points (LANGUAGE.md §6.4): every robot command awaits the robot (or at least one loop
turn), every ``wait`` sleeps on the clock, and every loop round lasts at least
:data:`LOOP_ROUND_SECONDS` — so a ``forever`` with nothing in it lets virtual time move on and
never starves other scripts, events or the stop button.
"""

from __future__ import annotations

import asyncio
import math
import random
from collections import Counter
from collections.abc import Awaitable, Callable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any, Protocol

from rootlang import ast, forms
from rootlang.checks import (
    MOTION,
    SENSOR_FEATURES,
    expect_argument,
    expect_condition,
    unsupported_action,
)
from rootlang.colors import NAMED_COLORS, SENSOR_COLORS, Color
from rootlang.diagnostics import NO_SPAN, RootlangError, Span
from rootlang.protocol import (
    GravityCompensation,
    LedState,
    MarkerPosition,
    ModulationType,
    Packet,
    spec,
)
from rootlang.protocol.enums import BumperState, TouchSensors
from rootlang.runtime.budget import CPU_BUDGET_SPENT, CpuBudget
from rootlang.runtime.client import RESET_ATTEMPTS, Origin, Pose, RobotClient
from rootlang.units import (
    Kind,
    Quantity,
    UnitError,
    Value,
    apply_binary,
    apply_function,
    apply_unary,
    apply_unit,
    function_kind,
    kind_of,
    show,
)
from rootlang.wording.shown import Code, Described

LOOP_ROUND_SECONDS = 0.01
"""Every round of a loop lasts at least this long (see the module docstring)."""
CONDITION_PERIOD_SECONDS = 0.05
"""``wait until`` and ``when <condition>`` check their condition 20 times a second."""
MAX_CALL_DEPTH = 100
RUN_STACK_LIMIT = 800
"""The most coroutines a running script may have inside each other before a procedure call,
counted by the interpreter itself (E215): blocks and statement calls nest on the interpreter's
own list, so only expressions and procedures called for their value use Python's stack. With
a statement's own expression (at most :data:`rootlang.ast.NESTING_LIMIT` deep) on top, that
stays near 1,000 coroutines: under half of a 1 MB stack on every supported Python
(docs/runtime.md, "Depth")."""
CALL_FRAMES = 6
"""Coroutines a value call adds to the ``level`` of its expression: the statement's runner,
``quantity``/``argument`` (or ``condition``), ``evaluate`` of the call, ``call`` and
``run_block`` (counted as if every statement had them all)."""
SAY_BYTES = spec("say_phrase").field("phrase").size  # what one Say packet holds
DEFAULT_SWEEP_VOLUME = 255

# The packet that tells each sensor's value (from rootlang/forms.py): the robot lacks the
# sensor when it lacks the packet (named as the checks name it: SENSOR_FEATURES).
SENSOR_PACKETS: dict[ast.SensorKind, str] = {
    kind: sensor.packet for kind, sensor in forms.SENSORS.items() if sensor.packet is not None
}
IR_FULL_SCALE = 4095


# A packet field's unit as the child writes it: (unit, how many of the field's units make one).
CHILD_UNITS: dict[str, tuple[str, float]] = {
    "ms": ("seconds", 1000),
    "decipercent": ("%", 10),
    "decidegrees": ("degrees", 10),
    "mm": ("cm", 10),
    "mm/s": ("cm/s", 10),
}
# Fields with no unit in the packet table, written by the child in one.
FIELD_UNITS: dict[tuple[str, str], tuple[str, float]] = {
    ("play_sweep", "volume"): ("%", DEFAULT_SWEEP_VOLUME / 100),
}


# A field's name as the child knows the thing (the rest are their own words: volume, duration).
FIELD_WORDS = {
    "amount": "gravity compensation",
    "left": "left wheel's speed",
    "right": "right wheel's speed",
}


def _child_unit(packet: str, field: str, unit: str | None) -> tuple[str, float] | None:
    return FIELD_UNITS.get((packet, field)) or CHILD_UNITS.get(unit or "")


def _in(value: int, per: float, unit: str) -> str:
    """A packet's value as the child would write it: 1275 of 255 a 100 % is 500 %."""
    return f"{round(value / per, 3):g} {unit}"


class ScriptStopped(Exception):
    """``stop this script``: ends the running script (not an error)."""


class _Returned(Exception):
    def __init__(self, value: Value | None) -> None:
        super().__init__()
        self.value = value


@dataclass
class Frame:
    """One running script (or procedure call inside it): its name and its local variables."""

    script: str
    local: dict[str, Value] = field(default_factory=dict)
    depth: int = 0
    """Procedure calls around this one (E206 past :data:`MAX_CALL_DEPTH`)."""
    may_move: bool = True
    """False in ``when stopped`` scripts."""
    stack: int = 0
    """Coroutines of the script's task inside each other where this call began (E215 past
    :data:`RUN_STACK_LIMIT`)."""
    procedure: str = ""
    """The procedure this call runs ("" for the script's own frame)."""

    def origin(self, node: ast.Node, *, part: bool = False) -> Origin:
        return Origin(self.script, node.span, part)


class Runtime(Protocol):
    """What the interpreter needs from the scheduler."""

    client: RobotClient
    shared: dict[str, Value]
    shared_names: frozenset[str]
    procedures: Mapping[str, ast.Procedure]
    random: random.Random
    budget: CpuBudget

    def elapsed(self) -> float: ...

    def state_changed(self) -> Awaitable[None]: ...

    async def send_message(self, message: str, wait: bool) -> None: ...

    def stop_other_scripts(self) -> None: ...

    def stop_all(self) -> None: ...

    def printed(self, text: str, frame: Frame, node: ast.Node) -> None: ...


@dataclass
class _Running:
    """One block being run, on :meth:`Interpreter.run_block`'s own list (not Python's stack)."""

    statements: Iterator[ast.Statement]
    frame: Frame
    loop: ast.Repeat | ast.Forever | ast.RepeatUntil | ast.While | None = None
    """The loop this block is one round of."""
    rounds: int = 0  # rounds still to run (``repeat``)
    started: float = 0.0  # when this round started
    procedure: bool = False  # a procedure's body: ``return`` ends here


def error_at(node: ast.Node, code: str, **values: object) -> RootlangError:
    return RootlangError.of(code, node.span, **values)


def unit_error_at(span: Span, error: UnitError) -> RootlangError:
    return RootlangError.of(error.code, span, **error.values)


StatementHook = Callable[[ast.Statement, Frame, Sequence[_Running]], Awaitable[None] | None]
"""Told as each statement begins, with the blocks running around it (the debugger's); what it
gives back, if anything, is awaited before the statement runs (a pause on a robot)."""


class Interpreter:
    def __init__(self, runtime: Runtime) -> None:
        self.runtime = runtime
        self.client = runtime.client
        self.clock = runtime.client.clock
        self.on_statement: StatementHook | None = None
        self.budget = runtime.budget

    # ---- blocks ---------------------------------------------------------------------------

    async def run_block(self, block: ast.Block, frame: Frame) -> Value | None:
        """Run ``block`` with everything inside it: the blocks of ``if`` and loops, and the
        procedures called as statements, go on this method's own list instead of Python's
        stack, so a program's blocks can nest as deep as its text allows (docs/runtime.md,
        "Depth"). Gives the value of the ``return`` that ended it, if any."""
        stack = [_Running(iter(block), frame, procedure=True)]
        while stack:
            top = stack[-1]
            statement = next(top.statements, None)
            if self.budget.spent():  # the computer's time for the run is used up (E220)
                where = statement or top.loop
                span = NO_SPAN if where is None else where.span
                ran = f"{self.runtime.elapsed():.1f} s"
                raise RootlangError.of(CPU_BUDGET_SPENT, span, limit=self.budget.shown, ran=ran)
            try:
                if statement is None:  # the block is done: the loop it belongs to goes on?
                    stack.pop()
                    if top.loop is not None and await self._next_round(top):
                        stack.append(top)
                    continue
                if self.on_statement is not None:
                    held = self.on_statement(statement, top.frame, stack)
                    if held is not None:
                        await held
                opened = await self.statement(statement, top.frame)
            except _Returned as returned:
                while not stack.pop().procedure:
                    pass
                if not stack:
                    return returned.value
                continue
            except MemoryError:  # the program's own doing (text doubled in a loop): say so
                where = statement or top.loop
                assert where is not None
                raise error_at(where, "E216") from None
            if opened is not None:
                stack.append(opened)
        return None

    def _round(
        self, loop: ast.Repeat | ast.Forever | ast.RepeatUntil | ast.While, frame: Frame,
        rounds: int = 1,
    ) -> _Running | None:  # fmt: skip
        if rounds <= 0:
            return None
        return _Running(iter(loop.body), frame, loop, rounds, self.clock.now())

    async def _next_round(self, running: _Running) -> bool:
        """The end of one round of a loop (at least :data:`LOOP_ROUND_SECONDS` long): whether
        another round starts."""
        if self.clock.now() < running.started + LOOP_ROUND_SECONDS:
            await self.clock.sleep_until(running.started + LOOP_ROUND_SECONDS)
        else:
            await self.clock.sleep(0)
        loop, frame = running.loop, running.frame
        assert loop is not None
        if isinstance(loop, ast.Repeat):
            running.rounds -= 1
            if running.rounds <= 0:
                return False
        elif isinstance(loop, ast.While):
            if not await self.condition(loop, loop.condition, frame):
                return False
        elif isinstance(loop, ast.RepeatUntil) and await self.condition(
            loop, loop.condition, frame
        ):
            return False
        running.statements = iter(loop.body)
        running.started = self.clock.now()
        return True

    async def statement(self, statement: ast.Statement, frame: Frame) -> _Running | None:
        """Run one statement; a block statement gives the block it opens (``run_block`` runs
        it). Every statement type has its case: mypy --strict rejects a new one left out."""
        node = ast.statement(statement)
        match node:  # (the statements loops run most often first: cases are tried in turn)
            case ast.SetVariable():
                await self._set_variable(node, frame)
            case ast.ChangeVariable():
                await self._change_variable(node, frame)
            case ast.If():
                return await self._if(node, frame)
            case ast.CallProcedure():
                return await self._call_statement(node, frame)
            case ast.Return():
                await self._return(node, frame)
            case ast.Wait():
                await self._wait(node, frame)
            case ast.Repeat():
                return await self._repeat(node, frame)
            case ast.While():
                return await self._while(node, frame)
            case ast.RepeatUntil():
                return await self._repeat_until(node, frame)
            case ast.Forever():
                return await self._forever(node, frame)
            case ast.Print():
                await self._print(node, frame)
            case ast.Move():
                await self._move(node, frame)
            case ast.Turn():
                await self._turn(node, frame)
            case ast.Arc():
                await self._arc(node, frame)
            case ast.GoTo():
                await self._go_to(node, frame)
            case ast.SetWheels():
                await self._set_wheels(node, frame)
            case ast.Drive():
                await self._drive(node, frame)
            case ast.StopMoving():
                await self._stop_moving(node, frame)
            case ast.ResetPosition():
                await self._reset_position(node, frame)
            case ast.Dock():
                await self._dock(node, frame)
            case ast.SetGravityCompensation():
                await self._gravity(node, frame)
            case ast.Tool():
                await self._tool(node, frame)
            case ast.Light():
                await self._light(node, frame)
            case ast.PlayNote():
                await self._play_note(node, frame)
            case ast.PlaySweep():
                await self._play_sweep(node, frame)
            case ast.Say():
                await self._say(node, frame)
            case ast.StopSound():
                await self._stop_sound(node, frame)
            case ast.WaitUntil():
                await self._wait_until(node, frame)
            case ast.Stop():
                await self._stop(node, frame)
            case ast.Send():
                await self._send(node, frame)
            case _:
                ast.assert_never(node)
        return None

    # ---- robot commands --------------------------------------------------------------------

    async def command(
        self, name: str, fields: dict[str, Any], frame: Frame, node: ast.Node, text: str,
        *, part: bool = False,
    ) -> Packet | None:  # fmt: skip
        if isinstance(node, MOTION) and not frame.may_move:  # the checks' rule, met late
            raise error_at(node, "E117")  # (a `when stopped` script calling a procedure)
        if unsupported_action(node, self.client.model) is not None:  # the checks' W102 rule
            raise error_at(
                node, "E201", robot=self.client.model.display_name, command=Code(text, quoted=False)
            )
        self._check_ranges(name, fields, node, text)
        origin = frame.origin(node, part=part)  # part: `go to` as turn, move, turn
        return await self.client.command(name, fields, origin, trace_text=text)

    def _check_ranges(self, name: str, fields: dict[str, Any], node: ast.Node, text: str) -> None:
        model = self.client.model
        for field_spec in spec(name).fields:
            allowed = field_spec.range_for(model)
            value = fields.get(field_spec.name)
            if allowed is None or not isinstance(value, int):
                continue
            low, high = allowed
            child = _child_unit(name, field_spec.name, field_spec.unit)
            if not low <= value <= high and child is not None:  # said in the child's units
                unit, per = child
                what = FIELD_WORDS.get(field_spec.name, field_spec.name.replace("_", " "))
                raise error_at(node, "E217", what=Described(what),
                               low=_in(low, per, unit), high=_in(high, per, unit),
                               value=_in(value, per, unit))  # fmt: skip
            if not low <= value <= high:
                unit = f" {field_spec.unit}" if field_spec.unit else ""
                raise error_at(
                    node,
                    "E205",
                    command=Code(text, quoted=False),
                    value=f"{value}{unit}",
                    robot=model.display_name,
                    allowed=f"{low} to {high}{unit}",
                )

    async def _move(self, node: ast.Move, frame: Frame) -> None:
        distance = await self.quantity(node, "distance", frame)
        mm = round(-distance.value if node.backward else distance.value)
        await self.command("drive_distance", {"distance": mm}, frame, node, f"move {mm} mm")

    async def _turn(self, node: ast.Turn, frame: Frame) -> None:
        angle = await self.quantity(node, "angle", frame)
        await self._rotate(angle.value if node.direction == "right" else -angle.value, frame, node)

    async def _rotate(
        self, clockwise_degrees: float, frame: Frame, node: ast.Node, *, part: bool = False
    ) -> None:
        decidegrees = round(clockwise_degrees * 10)
        side = "right" if decidegrees >= 0 else "left"
        text = f"turn {side} {_degrees(abs(decidegrees))}"
        await self.command("rotate_angle", {"angle": decidegrees}, frame, node, text, part=part)

    async def _arc(self, node: ast.Arc, frame: Frame) -> None:
        angle = await self.quantity(node, "angle", frame)
        radius = await self.quantity(node, "radius", frame)
        sign = 1 if node.direction == "right" else -1
        fields = {"angle": sign * round(angle.value * 10), "radius": sign * round(radius.value)}
        text = f"arc {node.direction} {_degrees(abs(fields['angle']))} radius {fields['radius']} mm"
        await self.command("drive_arc", fields, frame, node, text)

    async def _go_to(self, node: ast.GoTo, frame: Frame) -> None:
        x = round((await self.quantity(node, "x", frame)).value)
        y = round((await self.quantity(node, "y", frame)).value)
        facing: float | None = None
        if node.facing is not None:
            facing = (await self.quantity(node, "facing", frame)).value % 360
        text = f"go to x {x} mm y {y} mm" + ("" if facing is None else f" facing {round(facing)}°")
        if self.client.supports("navigate_to_position"):
            heading = -1 if facing is None else round(facing * 10) % 3600
            fields = {"x": x, "y": y, "heading": heading}
            await self.command("navigate_to_position", fields, frame, node, text)
            return
        # No Navigate on this robot's protocol: turn towards the point, drive, then face (a
        # child's view shows the statement once: the commands after the first are its parts).
        pose = await self.pose(frame, node)
        dx, dy = x - pose.x_mm, y - pose.y_mm
        distance = math.hypot(dx, dy)
        if distance >= 1:
            target = math.degrees(math.atan2(dy, dx))
            await self._rotate(_clockwise(pose.heading_degrees, target), frame, node)
            mm = round(distance)
            move = f"move {mm} mm"
            await self.command("drive_distance", {"distance": mm}, frame, node, move, part=True)
        if facing is not None:
            pose = await self.pose(frame, node)
            turn = _clockwise(pose.heading_degrees, facing)
            await self._rotate(turn, frame, node, part=distance >= 1)

    async def pose(self, frame: Frame, node: ast.Node) -> Pose:
        """The robot's pose, asked for afresh when the robot can tell it."""
        if self.client.supports("get_position"):
            await self.client.read("get_position", frame.origin(node), "get position")
        return self.client.state.pose

    async def _set_wheels(self, node: ast.SetWheels, frame: Frame) -> None:
        speeds: dict[str, int] = {}
        for side in ("left", "right"):
            if getattr(node, side) is not None:
                speeds[side] = round((await self.quantity(node, side, frame)).value)
        if len(speeds) == 2:
            name = "set_wheel_speeds"
        else:
            name = "set_left_wheel_speed" if "left" in speeds else "set_right_wheel_speed"
        text = "set wheels " + " ".join(f"{side} {value} mm/s" for side, value in speeds.items())
        await self.command(name, speeds, frame, node, text)

    async def _drive(self, node: ast.Drive, frame: Frame) -> None:
        speed = round((await self.quantity(node, "speed", frame)).value)
        fields = {"left": speed, "right": speed}
        await self.command("set_wheel_speeds", fields, frame, node, f"drive {speed} mm/s")

    async def _stop_moving(self, node: ast.StopMoving, frame: Frame) -> None:
        fields = {"left": 0, "right": 0}
        await self.command("set_wheel_speeds", fields, frame, node, "stop moving")

    async def _reset_position(self, node: ast.ResetPosition, frame: Frame) -> None:
        origin = frame.origin(node)
        confirmable = self.client.supports("get_position")
        if not await self.client.reset("reset_position", origin, "reset position") and confirmable:
            raise error_at(
                node, "E213", command=Code("reset position", quoted=False), tries=RESET_ATTEMPTS
            )

    async def _dock(self, node: ast.Dock, frame: Frame) -> None:
        word = "dock" if node.docking else "undock"
        await self.command(word, {}, frame, node, word)

    async def _gravity(self, node: ast.SetGravityCompensation, frame: Frame) -> None:
        percent = 50.0
        if node.amount is not None:
            amount = await self.quantity(node, "amount", frame)
            percent = amount.value
        active = {
            "on": GravityCompensation.ON,
            "off": GravityCompensation.OFF,
            "auto": GravityCompensation.MARKER_DOWN,
        }[node.mode]
        fields = {"active": active, "amount": round(percent * 10)}
        text = f"set gravity compensation {node.mode} {round(percent)}%"
        await self.command("set_gravity_compensation", fields, frame, node, text)

    async def _tool(self, node: ast.Tool, frame: Frame) -> None:
        if not node.down:
            position = MarkerPosition.UP
        elif node.tool == "marker":
            position = MarkerPosition.MARKER_DOWN
        else:
            position = MarkerPosition.ERASER_DOWN
        text = f"{node.tool} {'down' if node.down else 'up'}"
        await self.command("set_marker_position", {"position": position}, frame, node, text)

    async def _light(self, node: ast.Light, frame: Frame) -> None:
        color = Color(0, 0, 0)
        if node.color is not None:
            value = await self.argument(node, "color", frame)
            assert isinstance(value, Color)
            color = value
        state = {
            "on": LedState.ON,
            "off": LedState.OFF,
            "blink": LedState.BLINK,
            "spin": LedState.SPIN,
        }[node.mode]
        red, green, blue = color.rgb
        fields = {"state": state, "red": red, "green": green, "blue": blue}
        text = "light off" if node.mode == "off" else f"light {node.mode} {color}"
        await self.command("set_led_animation", fields, frame, node, text)

    async def _play_note(self, node: ast.PlayNote, frame: Frame) -> None:
        frequency = await self.quantity(node, "frequency", frame)
        duration = await self.quantity(node, "duration", frame)
        hz, ms = round(frequency.value), round(duration.value * 1000)
        fields = {"frequency": hz, "duration": ms}
        await self.command("play_note", fields, frame, node, f"play {hz} Hz for {ms} ms")

    async def _play_sweep(self, node: ast.PlaySweep, frame: Frame) -> None:
        start = await self.quantity(node, "start", frame)
        end = await self.quantity(node, "end", frame)
        duration = await self.quantity(node, "duration", frame)
        volume = DEFAULT_SWEEP_VOLUME
        if node.volume is not None:
            percent = await self.quantity(node, "volume", frame)
            volume = round(percent.value * DEFAULT_SWEEP_VOLUME / 100)
        ms = round(duration.value * 1000)
        fields: dict[str, Any] = {
            "start_frequency": round(start.value * 1000),
            "end_frequency": round(end.value * 1000),
            "duration": ms,
            "attack": 0,
            "release": 0,
            "volume": volume,
            "modulation_type": ModulationType.DISABLED,
            "modulation_rate": 0,
            "append": 0,
        }
        text = f"play sweep from {round(start.value)} Hz to {round(end.value)} Hz for {ms} ms"
        await self.command("play_sweep", fields, frame, node, text)

    async def _say(self, node: ast.Say, frame: Frame) -> None:
        text = show(await self.evaluate(node.text, frame))
        for part in split_phrase(text, SAY_BYTES):
            await self.command("say_phrase", {"phrase": part}, frame, node, f'say "{part}"')

    async def _stop_sound(self, node: ast.StopSound, frame: Frame) -> None:
        await self.command("stop_sound", {}, frame, node, "stop sound")

    # ---- waiting and control ---------------------------------------------------------------

    async def _wait(self, node: ast.Wait, frame: Frame) -> None:
        seconds = (await self.quantity(node, "duration", frame)).value
        await self.clock.sleep(seconds)

    async def _wait_until(self, node: ast.WaitUntil, frame: Frame) -> None:
        while not await self.condition(node, node.condition, frame):
            changed = asyncio.ensure_future(self.runtime.state_changed())
            try:
                await asyncio.wait({changed}, timeout=CONDITION_PERIOD_SECONDS)
            finally:
                changed.cancel()

    async def _repeat(self, node: ast.Repeat, frame: Frame) -> _Running | None:
        count = await self.quantity(node, "count", frame)
        if count.value < 0 or count.value != int(count.value):
            raise error_at(node.count, "E211", value=str(count))
        return self._round(node, frame, int(count.value))

    async def _forever(self, node: ast.Forever, frame: Frame) -> _Running | None:
        return self._round(node, frame)

    async def _repeat_until(self, node: ast.RepeatUntil, frame: Frame) -> _Running | None:
        if await self.condition(node, node.condition, frame):
            return None
        return self._round(node, frame)

    async def _while(self, node: ast.While, frame: Frame) -> _Running | None:
        if not await self.condition(node, node.condition, frame):
            return None
        return self._round(node, frame)

    async def _if(self, node: ast.If, frame: Frame) -> _Running | None:
        for branch in node.branches:
            if await self.condition(branch, branch.condition, frame):
                return _Running(iter(branch.body), frame)
        if node.otherwise is not None:
            return _Running(iter(node.otherwise), frame)
        return None

    async def _stop(self, node: ast.Stop, frame: Frame) -> None:
        if node.target == "this script":
            raise ScriptStopped
        if node.target == "other scripts":
            self.runtime.stop_other_scripts()
            await asyncio.sleep(0)
            return
        self.runtime.stop_all()
        await asyncio.sleep(0)  # the scheduler cancels this script too
        raise ScriptStopped

    async def _send(self, node: ast.Send, frame: Frame) -> None:
        message = show(await self.argument(node, "message", frame))
        await self.runtime.send_message(message, node.wait)

    async def _print(self, node: ast.Print, frame: Frame) -> None:
        values = [show(await self.evaluate(value, frame)) for value in node.values]
        self.runtime.printed(" ".join(values), frame, node)

    # ---- variables and procedures ----------------------------------------------------------

    def _store(self, name: str, value: Value, frame: Frame) -> None:
        if name in self.runtime.shared_names and name not in frame.local:
            self.runtime.shared[name] = value
        else:
            frame.local[name] = value

    async def _set_variable(self, node: ast.SetVariable, frame: Frame) -> None:
        self._store(node.name, await self.evaluate(node.value, frame), frame)

    async def _change_variable(self, node: ast.ChangeVariable, frame: Frame) -> None:
        current = self._lookup(node.name, frame, node)
        by = await self.evaluate(node.by, frame)
        self._store(node.name, self._binary("+", current, by, node.span), frame)

    async def _call_statement(self, node: ast.CallProcedure, frame: Frame) -> _Running:
        procedure, inner = await self._enter(node.name, node.arguments, frame, node, 0)
        return _Running(iter(procedure.body), inner, procedure=True)

    async def _return(self, node: ast.Return, frame: Frame) -> None:
        value = None if node.value is None else await self.evaluate(node.value, frame)
        raise _Returned(value)

    async def call(
        self, name: str, arguments: tuple[ast.Expression, ...], frame: Frame, node: ast.Node,
        level: int = 0,
    ) -> Value | None:  # fmt: skip
        """Call a procedure for its value, from inside an expression ``level`` deep."""
        procedure, inner = await self._enter(name, arguments, frame, node, level)
        try:
            return await self.run_block(procedure.body, inner)
        except RecursionError:  # only an AST the parser never saw can get this deep
            raise error_at(node, "E215", name=name, depth=inner.depth) from None

    async def _enter(
        self, name: str, arguments: tuple[ast.Expression, ...], frame: Frame, node: ast.Node,
        level: int,
    ) -> tuple[ast.Procedure, Frame]:  # fmt: skip
        """The procedure and its new frame, with the arguments' values in it; E206 and E215
        when the calls around it already go too deep."""
        procedure = self.runtime.procedures[name]  # the checks made sure it exists (E101)
        if frame.depth >= MAX_CALL_DEPTH:
            raise error_at(node, "E206", name=name, limit=MAX_CALL_DEPTH)
        stack = frame.stack + level + CALL_FRAMES
        if stack > RUN_STACK_LIMIT:
            raise error_at(node, "E215", name=name, depth=frame.depth + 1)
        values = [await self.evaluate(argument, frame, level + 3) for argument in arguments]
        local = {
            parameter.name: value
            for parameter, value in zip(procedure.parameters, values, strict=True)
        }
        return procedure, Frame(frame.script, local, frame.depth + 1, frame.may_move, stack, name)

    # ---- expressions -----------------------------------------------------------------------

    async def argument(self, node: ast.Statement, field: str, frame: Frame) -> Value:
        """Evaluate the expression in ``field`` of a command and check it is the kind the
        command needs, with the checks' own rule (:func:`~rootlang.checks.expect_argument`):
        a mistake only the run can see reads like one ``rootlang check`` finds."""
        expression = getattr(node, field)
        value = await self.evaluate(expression, frame)
        try:
            expect_argument(node, field, kind_of(value))
        except UnitError as error:
            raise unit_error_at(expression.span, error) from None
        return value

    async def quantity(self, node: ast.Statement, field: str, frame: Frame) -> Quantity:
        """:meth:`argument` for a field that needs a number (with or without a unit)."""
        value = await self.argument(node, field, frame)
        assert isinstance(value, Quantity)
        return value

    async def condition(self, owner: ast.Node, expression: ast.Expression, frame: Frame) -> bool:
        """Evaluate the condition of ``owner`` (``if``, ``while``, ``when`` ...): true or false."""
        value = await self.evaluate(expression, frame)
        try:
            expect_condition(owner, kind_of(value))
        except UnitError as error:
            raise unit_error_at(expression.span, error) from None
        return bool(value)

    async def evaluate(self, expression: ast.Expression, frame: Frame, level: int = 0) -> Value:
        """The value of ``expression``, evaluated ``level`` coroutines deep inside the
        statement's own (counted for E215, see :data:`RUN_STACK_LIMIT`)."""
        node = ast.expression(expression)
        match node:
            case ast.Literal(value=value):
                return value
            case ast.Variable(name=name):
                return self._lookup(name, frame, node)
            case ast.Binary():
                left = await self.evaluate(node.left, frame, level + 1)
                right = await self.evaluate(node.right, frame, level + 1)
                return self._binary(node.op, left, right, node.span)
            case ast.Unary():
                operand = await self.evaluate(node.operand, frame, level + 1)
                try:
                    return finite(apply_unary(node.op, operand), node.span)
                except UnitError as error:
                    raise unit_error_at(node.span, error) from None
            case ast.WithUnit():
                return await self._with_unit(node, frame, level + 1)
            case ast.FunctionCall():
                return await self._function(node, frame, level + 1)
            case ast.ProcedureCall(name=name, arguments=arguments):
                returned = await self.call(name, arguments, frame, node, level)
                if returned is None:
                    raise error_at(node, "E107", name=name)
                return returned
            case ast.SensorRead():
                return await self.sensor(node, frame)
            case _:
                ast.assert_never(node)

    def _lookup(self, name: str, frame: Frame, node: ast.Node) -> Value:
        if name in frame.local:
            return frame.local[name]
        if name in self.runtime.shared:
            return self.runtime.shared[name]
        raise error_at(node, "E209", name=name)

    def _binary(self, op: str, left: Value, right: Value, span: Span) -> Value:
        try:
            return finite(apply_binary(op, left, right), span)
        except UnitError as error:
            raise unit_error_at(span, error) from None
        except ZeroDivisionError:
            raise RootlangError.of("E204", span) from None

    async def _with_unit(self, expression: ast.WithUnit, frame: Frame, level: int) -> Value:
        value = await self.evaluate(expression.operand, frame, level + 1)
        try:
            return finite(apply_unit(expression.unit, value), expression.span)
        except UnitError as error:
            raise unit_error_at(expression.span, error) from None

    async def _function(self, expression: ast.FunctionCall, frame: Frame, level: int) -> Value:
        arguments = [
            await self.evaluate(argument, frame, level + 1) for argument in expression.arguments
        ]
        try:
            if expression.function == "random":
                return finite(self._random(arguments, expression), expression.span)
            return finite(apply_function(expression.function, arguments), expression.span)
        except UnitError as error:
            raise unit_error_at(expression.span, error) from None

    def _random(self, arguments: list[Value], node: ast.Node) -> Value:
        function_kind("random", [kind_of(argument) for argument in arguments])
        low, high = arguments
        assert isinstance(low, Quantity) and isinstance(high, Quantity)
        if low.value > high.value:
            raise error_at(node, "E210", low=str(low), high=str(high))
        if low.shown == int(low.shown) and high.shown == int(high.shown):
            return low.with_shown(self.runtime.random.randint(int(low.shown), int(high.shown)))
        return low.with_value(self.runtime.random.uniform(low.value, high.value))

    # ---- sensors ---------------------------------------------------------------------------

    def require_sensor(self, sensor: ast.SensorKind, node: ast.Node) -> None:
        needed = SENSOR_PACKETS.get(sensor)
        if needed is not None and not self.client.supports(needed):
            robot = self.client.model.display_name
            raise error_at(node, "E202", robot=robot, sensor=SENSOR_FEATURES[sensor])

    async def sensor(self, node: ast.SensorRead, frame: Frame) -> Value:
        self.require_sensor(node.sensor, node)
        state = self.client.state
        where = node.where or ""
        kind = node.sensor
        if kind is ast.SensorKind.BUMPER:
            return bumper_pressed(state.bumpers, where)
        if kind is ast.SensorKind.TOUCH:
            return bool(state.touch & touch_sensors(where))
        if kind is ast.SensorKind.COLOR:
            return majority_color(state.colors, forms.COLOR_ZONE.meaning(where))
        if kind is ast.SensorKind.TIMER:
            return Quantity(self.runtime.elapsed(), Kind.TIME, "seconds")
        if kind is ast.SensorKind.POSITION:
            pose = await self.pose(frame, node)
            return Quantity(pose.x_mm if where == "x" else pose.y_mm, Kind.LENGTH, "cm")
        if kind is ast.SensorKind.HEADING:
            pose = await self.pose(frame, node)
            return Quantity(pose.heading_degrees, Kind.ANGLE, "degrees")
        if kind is ast.SensorKind.CLIFF:
            return state.cliff
        if kind is ast.SensorKind.DOCKED:
            return state.docked
        # The rest send no events: ask the robot.
        await self.client.read(
            SENSOR_PACKETS[kind], frame.origin(node), f"read {SENSOR_FEATURES[kind]}"
        )
        state = self.client.state
        if kind is ast.SensorKind.LIGHT:
            left, right = state.light_percent
            return Quantity(left if where == "left" else right, Kind.PERCENT, "%")
        if kind is ast.SensorKind.BATTERY:
            return Quantity(state.battery_percent or 0.0, Kind.PERCENT, "%")
        if kind is ast.SensorKind.TILT:
            axis = "xyz".index(where)
            return Quantity.number(state.acceleration_g[axis])
        if kind is ast.SensorKind.OBSTACLE:  # the strongest reflection on that side
            sides = forms.OBSTACLE_SIDE.meaning(where)
            strongest = max(state.ir_values[index] for index in sides)
            return Quantity(100.0 * strongest / IR_FULL_SCALE, Kind.PERCENT, "%")
        ast.assert_never(kind)  # mypy --strict: every sensor has its reading above


def finite(value: Value, span: Span) -> Value:
    """``value``, unless it is a number too big to be one (infinity, or not a number, as
    repeated multiplication reaches): then error E214 at the expression that made it."""
    if isinstance(value, Quantity) and not math.isfinite(value.value):
        raise RootlangError.of("E214", span)
    return value


def bumper_pressed(state: BumperState, side: str) -> bool:
    """Whether the bumpers a program's side names are pressed (all of one group its meaning
    gives: ``both`` the two together, ``any`` either one)."""
    groups = forms.BUMPER_SIDE.meaning(side)
    return any(all(state & BumperState[name] for name in group) for group in groups)


def touch_sensors(sensor: str) -> TouchSensors:
    """The bits of the touch sensors a program's choice names (``any``: all four)."""
    bits = TouchSensors.NONE
    for name in forms.TOUCH_SENSOR.meaning(sensor):
        bits |= TouchSensors[name]
    return bits


def color_seen(zone: str, color: str) -> Callable[[tuple[int, ...]], bool]:
    """The test whether ``color`` is under the zone: any of its sensors (all 32 for
    ``everywhere``); made once, asked at every colour event."""
    wanted = SENSOR_COLORS.index(color)
    sensors = forms.COLOR_ZONE.meaning(zone)
    start, stop = sensors.start, sensors.stop  # the zones are runs of neighbours
    if zone == "everywhere":
        return lambda colors: (seen := colors[start:stop]).count(wanted) == len(seen)
    return lambda colors: wanted in colors[start:stop]


def majority_color(colors: tuple[int, ...], sensors: range) -> Color:
    counts = Counter(int(colors[index]) for index in sensors)
    best = max(sorted(counts), key=lambda nibble: counts[nibble])  # ties: the lower nibble
    return NAMED_COLORS[SENSOR_COLORS[best]]


def split_phrase(text: str, limit: int) -> list[str]:
    """Split text into pieces of at most ``limit`` UTF-8 bytes, on word boundaries when it can."""
    pieces: list[str] = []
    current = ""
    for word in text.split(" "):
        candidate = f"{current} {word}" if current else word
        if len(candidate.encode()) <= limit:
            current = candidate
            continue
        if current:
            pieces.append(current)
        current = ""
        while len(word.encode()) > limit:  # a word longer than a packet: cut it
            cut = limit
            while len(word[:cut].encode()) > limit:
                cut -= 1
            pieces.append(word[:cut])
            word = word[cut:]
        current = word
    if current or not pieces:
        pieces.append(current)
    return pieces


def _clockwise(heading: float, target: float) -> float:
    """Degrees to turn clockwise (negative: counter-clockwise) from one heading to another."""
    return -((target - heading + 180.0) % 360.0 - 180.0)


def _degrees(decidegrees: int) -> str:
    return f"{round(decidegrees / 10)}°"
