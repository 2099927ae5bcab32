"""A program's session: load it with its world; simulate it; run it on a robot; the outcome as JSON.

What ``rootlang sim``, ``rootlang run``, ``rootlang test``, the studio's worker, the faulty-link
tools and the benchmarks share, so a program is read, checked and run the same way whichever of
them runs it:

- :func:`load` — a :class:`Program`: its text, checked once, and the world
  it runs in (``--world``, else its ``# world:`` line, else the default world);
- :class:`Simulation` — the one wiring of a simulated run: a virtual robot in the world, a
  clock (virtual by default) and the transport between them (optionally wrapped: a faulty
  link); :func:`simulate` runs one to the end;
- :func:`run_on_robot` — the same run on a robot's transport, in real time;
- :func:`outcome_json` — how a run went, the one JSON shape of ``rootlang sim --json``, the
  studio and the robot's link holder.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from rootlang import ast
from rootlang.app.files import read_program, shown_path, world_for
from rootlang.checks import CheckedProgram, parse_and_check
from rootlang.diagnostics import Diagnostic, RootlangError, render
from rootlang.robots import RobotModel
from rootlang.runtime.budget import UNLIMITED, CpuBudget
from rootlang.runtime.client import Pose
from rootlang.runtime.clock import Clock, VirtualClock, WallClock
from rootlang.runtime.debugger import Debugger
from rootlang.runtime.scheduler import RunResult, run_program
from rootlang.runtime.timeline import Timeline
from rootlang.runtime.trace import TraceEntry
from rootlang.runtime.transport import Transport
from rootlang.sim.devices.motors import odometry_from
from rootlang.sim.recording import Recording
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import World, default_world, load_world_option
from rootlang.wording.language import Languages

Link = Callable[[SimTransport, Clock], Transport]
"""What stands between the runtime and the simulated robot (default: nothing), e.g. a faulty
link (:class:`~rootlang.runtime.faults.FaultyTransport`)."""


@dataclass
class Mistakes(RootlangError):
    """A program that doesn't check: its errors, as any RootlangError, and ``found``: every
    diagnostic, warnings too, in source order (what ``rootlang check`` prints)."""

    found: Sequence[Diagnostic] = field(default=(), repr=False)


@dataclass(frozen=True)
class Program:
    """A program ready to run: its text, checked once (for the world's robot model), the world
    it runs in (None for a robot: its model is known only once connected), and its file as
    messages name it."""

    file: str
    source: str
    checked: CheckedProgram
    world: World | None

    @property
    def warnings(self) -> Sequence[Diagnostic]:
        return self.checked.warnings


def load(
    path: str | Path,
    *,
    source: str | None = None,
    world: str | World | None = None,
    model: RobotModel | None = None,
    shown_as: str | None = None,
    names_from: Path | None = None,
    on_robot: bool = False,
    language: str | None = None,
) -> Program:
    """Read and check the program at ``path`` (``hello`` reads hello.root; ``source``: its text
    is this instead, as in the studio's editor), in ``world`` (a ``--world`` option: a .toml
    file, or a world's name found next to the program first; or a world already loaded, a
    task's), else the world its ``# world:``
    line names, else the default; ``model`` overrides the world's robot. ``on_robot``: for a
    robot, no world (checked for ``model``, else for any robot). ``shown_as`` names the file in
    messages (default: ``path``); ``names_from``: a folder every file (the program, its
    world) is named relative to in messages, as a studio's page sees them
    (:func:`~rootlang.app.files.shown_path`); ``language``: the one it is written in
    (``--language``; by default the one it declares). RootlangError with every mistake (the
    file, the world), or :class:`Mistakes` (the program)."""
    file = shown_as or shown_path(Path(path), names_from)
    if source is None:
        source = read_program(str(path), shown_as=file)
    if on_robot:
        return Program(file, source, _checked(source, file, model, language), None)
    chosen = (world if isinstance(world, World)
              else world_of(Path(path), source, world, names_from=names_from))  # fmt: skip
    if model is not None:
        chosen = chosen.with_model(model)
    return Program(file, source, _checked(source, file, chosen.robot.model, language), chosen)


def _checked(
    source: str, file: str, model: RobotModel | None, language: str | None
) -> CheckedProgram:
    """The program parsed and checked (once), or :class:`Mistakes`."""
    checked, found = parse_and_check(source, file, model, language=language)
    errors = [d for d in found if d.severity == "error"]
    if errors or checked is None:
        raise Mistakes(errors, source, found)
    return checked


def in_its_world(program: Program, path: str | Path) -> Program:
    """A program loaded for a robot, in the world its ``# world:`` line names (``rootlang run
    --sim`` when no robot is found); not checked again."""
    return replace(program, world=world_of(Path(path), program.source, None))


def world_of(
    program: Path, source: str, option: str | None, *, names_from: Path | None = None
) -> World:
    """``option`` (``--world``: a file, or a world's name, the program's ``worlds`` folder
    first, then rootlang's own), else the world the program names, else the default; the
    files named in messages as :func:`~rootlang.app.files.shown_path` names them."""
    if option is None:
        return world_for(program, source, names_from=names_from)
    return load_world_option(option, program.parent, lambda file: shown_path(file, names_from))


class Simulation:
    """One simulated run's parts, wired once: a virtual robot in the world, a clock (virtual
    unless given one) and the transport between them, optionally behind a ``link``. Callers
    that need the parts while the run goes (the studio's stimuli, a sampling thread) take
    them from here; :meth:`run` runs the program on them (on :attr:`clock`'s loop)."""

    def __init__(
        self,
        world: World | None = None,
        *,
        robot: VirtualRobot | None = None,
        clock: Clock | None = None,
        link: Link | None = None,
    ) -> None:
        self.robot = robot or VirtualRobot(world or default_world())
        self.clock: Clock = clock or VirtualClock()
        self.sim_transport = SimTransport(self.robot, self.clock)
        self.transport: Transport = (
            self.sim_transport if link is None else link(self.sim_transport, self.clock)
        )

    async def run(
        self,
        program: CheckedProgram | ast.Program,
        *,
        source: str = "",
        on_print: Callable[[str], None] | None = None,
        on_trace: Callable[[TraceEntry], None] | None = None,
        handle_ctrl_c: bool = False,
        debugger: Debugger | None = None,
        cpu_budget: CpuBudget = UNLIMITED,
    ) -> RunResult:
        """Run ``program`` until it ends, reaches the world's time limit or has used its
        ``cpu_budget`` of the computer's time (E220: :func:`rootlang.app.sandbox.cpu_backstop`).
        A ``debugger`` is told where the robot is by :meth:`robot_pose`, unless it knows
        another way."""
        if debugger is not None and debugger.pose is None:
            debugger.pose = self.robot_pose
        return await run_program(
            program, self.transport, self.clock, source=source,
            time_limit=self.robot.world.time_limit, on_print=on_print,
            handle_ctrl_c=handle_ctrl_c, on_trace=on_trace, debugger=debugger,
            cpu_budget=cpu_budget,
        )  # fmt: skip

    def robot_pose(self) -> Pose:
        """Where the robot reckons it is, as Get Position would say it now (the world moved
        on lazily: at most one sensor reading ago while it moves)."""
        return reckoned_pose(self.robot)


def keep_moments(robot: VirtualRobot, timeline: Timeline) -> None:
    """Have ``timeline`` (a debugger's recorder, told each trace entry) keep where ``robot``
    reckons it is too, each time its world moves on: what a pause then says. (Kept as the
    world has it, and reckoned only when shown: the world moves on at every sensor reading.)"""
    motors = robot.devices.motors
    last: list[object] = [None]  # the world's pose last kept

    def advanced() -> None:
        world = robot.world_pose
        if world is last[0]:  # (unmoved: the same tuple)
            timeline.moved_on()
            return
        last[0] = world
        timeline.reckoned((motors.origin, world))

    timeline.pose_of = _reckoned_from
    robot.on_advanced = advanced


def _reckoned_from(kept: Any) -> Pose:
    origin, world = kept
    x, y, decidegrees = odometry_from(origin, world)
    return Pose(x, y, decidegrees / 10)


def reckoned_pose(robot: VirtualRobot) -> Pose:
    """Where ``robot`` reckons it is, as Get Position would say it now."""
    x, y, decidegrees = robot.pose
    return Pose(x, y, decidegrees / 10)


def simulate(
    program: CheckedProgram | ast.Program,
    world: World | None = None,
    *,
    source: str = "",
    robot: VirtualRobot | None = None,
    realtime: bool = False,
    clock: Clock | None = None,
    link: Link | None = None,
    on_print: Callable[[str], None] | None = None,
    handle_ctrl_c: bool = False,
    on_trace: Callable[[TraceEntry], None] | None = None,
    debugger: Debugger | None = None,
    cpu_budget: CpuBudget = UNLIMITED,
) -> tuple[RunResult, Recording]:
    """Run ``program`` in ``world`` (or on ``robot``, already placed in its world) until it ends
    or the world's time limit; returns the run's result and the robot's recording. Virtual
    time unless ``realtime`` (the wall clock) or another ``clock``. A bare syntax tree is
    checked first; a :class:`CheckedProgram` is not checked again."""
    if clock is None and realtime:
        clock = WallClock()
    simulation = Simulation(world, robot=robot, clock=clock, link=link)
    result = simulation.clock.run(
        simulation.run(
            program, source=source, on_print=on_print, on_trace=on_trace,
            handle_ctrl_c=handle_ctrl_c, debugger=debugger, cpu_budget=cpu_budget,
        )
    )  # fmt: skip
    return result, simulation.robot.finish()


async def run_on_robot(
    program: Program,
    transport: Transport,
    clock: Clock,
    *,
    on_print: Callable[[str], None] | None = None,
    on_trace: Callable[[TraceEntry], None] | None = None,
    handle_ctrl_c: bool = True,
    debugger: Debugger | None = None,
) -> RunResult:
    """Run ``program`` on a robot's ``transport`` in real time, until it ends or is stopped
    (no time limit: as on the robot itself); a ``debugger`` may pause it (one that answers
    later: the robot's link goes on meanwhile). The link is closed on the way out."""
    try:
        return await run_program(
            program.checked, transport, clock, source=program.source, on_print=on_print,
            handle_ctrl_c=handle_ctrl_c, on_trace=on_trace, debugger=debugger,
        )  # fmt: skip
    finally:
        await transport.disconnect()  # already closed by the runtime: then a no-op


def with_time_limit(program: Program, seconds: float) -> Program:
    """``program`` in its world with the time limit capped at ``seconds`` (``rootlang test``)."""
    assert program.world is not None, "a program loaded for a robot has no world"
    world = replace(program.world, time_limit=min(program.world.time_limit, seconds))
    return replace(program, world=world)


def diagnostic_json(item: Diagnostic, source: str, languages: Languages) -> dict[str, object]:
    """A diagnostic as the outcome carries it: `rootlang check --json`'s fields and the
    rendered text (source line and caret), as ``languages`` show them."""
    return dict(item.to_json(languages), rendered=render(item, source, languages))


def mistakes_json(error: RootlangError, file: str, languages: Languages) -> dict[str, object]:
    """The outcome of a program that never ran: its mistakes (or its world's)."""
    found = [d.in_file(d.file or file) if file else d for d in error.diagnostics]
    errors = [diagnostic_json(d, error.source, languages) for d in found]
    return {"end": "mistakes", "errors": errors}


def outcome_json(
    program: Program,
    result: RunResult,
    languages: Languages,
    recording: Recording | None = None,
    robot: VirtualRobot | None = None,
) -> dict[str, object]:
    """How a run went, as JSON: ``end``, ``stopped_by``, ``sim_time_s``, ``robot`` (its model),
    ``world``; ``pose``, the robot's own estimate when the program ended (as ``position x`` and
    ``heading`` read it; asked afresh when the run finished or reached its time limit), not
    after the runtime's final Stop and Reset zeroed it; ``printed``, ``error`` and
    ``warnings`` (as :func:`diagnostic_json`, as ``languages`` show them). From the simulator
    (``recording``, ``robot``) also ``world_pose`` and the ``strokes`` in world millimetres,
    ``said``, ``notes`` and ``lights``; on a robot those are None or empty and ``world`` is None."""
    pose: dict[str, object] | None = None
    if result.pose is not None:
        p = result.pose
        pose = {
            "x_mm": round(p.x_mm), "y_mm": round(p.y_mm),
            "heading_deg": round(p.heading_degrees, 1),
        }  # fmt: skip
    elif robot is not None:  # no answer from the robot at all: the simulator knows
        x, y, tenths = robot.pose
        pose = {"x_mm": x, "y_mm": y, "heading_deg": tenths / 10}
    model, error = (robot.model.value if robot is not None else None), result.error
    if model is None and result.robot is not None:
        model = result.robot.model.value
    outcome: dict[str, object] = {
        "end": result.end,
        **result.stopped_by.outcome(),
        "sim_time_s": round(result.sim_time_s, 3),
        "robot": model,
        "world": program.world.name if robot is not None and program.world else None,
        "pose": pose,
        "world_pose": None,
        "strokes": [],
        "said": [],
        "notes": [],
        "lights": [],
        "printed": list(result.printed),
        "error": None if error is None else diagnostic_json(error, program.source, languages),
        "warnings": [diagnostic_json(w, program.source, languages) for w in program.warnings],
    }
    if recording is not None:
        final = recording.final_frame
        recorded = recording.to_json()
        if final is not None:
            outcome["world_pose"] = {
                "x_mm": final.x_mm, "y_mm": final.y_mm, "heading_deg": final.heading_deg
            }  # fmt: skip
        outcome["strokes"] = [s for s in recorded["strokes"] if len(s["points"]) > 1]
        outcome["said"] = [s.text for s in recording.said]
        outcome["notes"] = recorded["notes"]
        outcome["lights"] = recorded["lights"]
    return outcome
