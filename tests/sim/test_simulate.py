"""Programs run through the whole stack on the virtual robot: transport, determinism, CLI."""

from __future__ import annotations

import json
import re
import subprocess
import sys
import time
from pathlib import Path

import pytest

import rootlang.cli.sim
from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.cli import build_parser, main
from rootlang.cli.sim import shows_history
from rootlang.protocol import Packet, decode, encode
from rootlang.runtime.clock import VirtualClock, WallClock
from rootlang.runtime.transport import LinkLost
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import default_world, load_world, parse_world

PROGRAMS = Path(__file__).parents[2] / "programs"

DRAW = """\
when started
    marker down
    repeat 3
        move 10 cm
        turn left 120 degrees
    marker up
    say "done"
    play note C4 for 0.5 seconds
    light green
    print "drew", position x
"""

BUMP = (PROGRAMS / "bump_and_turn.root").read_text(encoding="utf-8")


def _run(source: str, world_text: str = "") -> tuple[str, str]:
    world = parse_world(world_text, "w.toml") if world_text else default_world()
    checked = load_checked(source, "p.root", world.robot.model)
    result, recording = simulate(checked.program, world, source=source)
    return result.trace.text(), json.dumps(recording.to_json())


def test_a_drawing_program_ends_finished_with_its_drawing() -> None:
    checked = load_checked(DRAW, "draw.root")
    result, recording = simulate(checked.program, default_world(), source=DRAW)
    assert result.end == "finished" and result.error is None
    assert result.printed and result.printed[0].startswith("drew")
    (stroke,) = recording.marker_strokes()
    assert stroke.points[0] == stroke.points[-1] or len(stroke.points) >= 4
    assert [s.text for s in recording.said] == ["done"]
    assert recording.notes and round(recording.notes[0].frequency_hz) == 262
    assert recording.lights[-1].rgb == (0, 255, 0)


@pytest.mark.parametrize(
    ("source", "world"),
    [(DRAW, ""), (BUMP, "time_limit = 20\n[floor]\nwidth = 800\nheight = 800")],
    ids=["draw", "bump"],
)
def test_the_same_program_and_world_give_byte_identical_runs(source: str, world: str) -> None:
    first = _run(source, world)
    second = _run(source, world)
    assert first == second
    assert "bump" in first[0] or "marker" in first[1]


def test_the_time_limit_ends_a_program_that_waits_for_events() -> None:
    checked = load_checked(BUMP, "bump.root")
    world = parse_world("time_limit = 8\n[floor]\nwidth = 800\nheight = 800", "w.toml")
    result, recording = simulate(checked.program, world, source=BUMP)
    assert result.end == "time_limit"
    assert result.sim_time_s == pytest.approx(8, abs=0.1)
    assert any(e.text.startswith("bumper") for e in recording.events)


def test_sim_transport_speaks_packets_on_a_virtual_clock() -> None:
    clock = VirtualClock()
    robot = VirtualRobot()
    transport = SimTransport(robot, clock)
    got: list[tuple[float, bytes]] = []

    async def host() -> None:
        info = await transport.connect(lambda data: got.append((clock.now(), data)), print)
        assert info.model.value == "RT1"
        await transport.send(encode("drive_distance", {"distance": 100}, 1))
        await clock.sleep(5)
        await transport.disconnect()

    clock.run(host())
    (when, data) = got[0]
    answer = decode(data, "robot")
    assert isinstance(answer, Packet) and answer.name == "drive_distance_response"
    assert 1.0 < when < 1.7  # delivered soon after it finished, in virtual time
    assert answer["y"] == 100


def test_sim_transport_in_real_time_keeps_pace_with_the_wall_clock() -> None:
    clock = WallClock()
    robot = VirtualRobot()
    transport = SimTransport(robot, clock)

    async def host() -> tuple[float, float, float, float]:
        before_connect = clock.now()
        await transport.connect(lambda data: None, print)
        connected = clock.now()  # the robot's time 0 is between these two
        await transport.send(encode("set_wheel_speeds", {"left": 100, "right": 100}, 1))
        await clock.sleep(0.3)
        leaving = clock.now()
        await transport.disconnect()  # (it catches the world up to the wall first)
        return before_connect, connected, leaving, clock.now()

    started = time.perf_counter()
    before_connect, connected, leaving, ended = clock.run(host())
    wall = time.perf_counter() - started
    assert wall >= 0.29  # it took real time ...
    step = robot.step_ms / 1000  # ... and the world kept pace with it (however busy the machine)
    assert leaving - connected - step <= robot.time <= ended - before_connect
    assert robot.time >= 0.29
    assert robot.world_pose[1] > 1005  # it moved


def test_the_robot_asks_for_disconnect_and_the_host_hears() -> None:
    clock = VirtualClock()
    transport = SimTransport(VirtualRobot(), clock)
    reasons: list[LinkLost] = []

    async def host() -> None:
        await transport.connect(lambda data: None, reasons.append)
        await transport.send(encode("disconnect", {}, 1))
        await clock.sleep(0.1)

    clock.run(host())
    assert reasons == ["the robot ended the connection, as asked"]


def test_cli_sim_prints_the_trace_and_packets(capsys: pytest.CaptureFixture[str]) -> None:
    status = main(["sim", str(PROGRAMS / "square.root"), "--packets"])
    out = capsys.readouterr().out
    assert status == 0
    assert "ended: finished" in out
    packet = re.compile(r"^ *\d+ ms  (->|<-) [0-9a-f]{40}  \w+ #\d+")
    lines = [line for line in out.splitlines() if packet.match(line)]
    assert any(" -> " in line and "drive_distance #" in line for line in lines)
    assert any(" <- " in line and "drive_distance_response #" in line for line in lines)


def test_cli_sim_json_summary(capsys: pytest.CaptureFixture[str]) -> None:
    status = main(["sim", str(PROGRAMS / "square.root"), "--json"])
    summary = json.loads(capsys.readouterr().out)
    assert status == 0
    assert summary["end"] == "finished" and summary["error"] is None
    assert set(summary["pose"]) == {"x_mm", "y_mm", "heading_deg"}
    assert summary["strokes"] and summary["said"] == ["done"]
    for key in ("sim_time_s", "notes", "lights", "printed"):
        assert key in summary


@pytest.mark.parametrize(
    ("options", "kept"),
    [
        ([], False),
        (["--full-trace"], False),
        (["--json"], True),
        (["--packets"], True),
        (["--svg", "p.svg"], True),
        (["--png", "p.png"], True),
        (["--html", "p.html"], True),
    ],
)
def test_cli_sim_keeps_the_robot_history_only_for_options_that_show_it(
    options: list[str], kept: bool
) -> None:
    args = build_parser("sim").parse_args(["sim", "p.root", *options])
    assert shows_history(args) is kept


@pytest.mark.parametrize("options", [[], ["--full-trace"]])
def test_cli_sim_shows_the_same_without_the_history_it_does_not_keep(
    options: list[str], capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """What the plain view and the full trace print is the same whether the robot keeps its
    history or not."""
    program = str(PROGRAMS / "star.root")
    assert main(["sim", program, *options]) == 0
    without = capsys.readouterr().out
    monkeypatch.setattr(rootlang.cli.sim, "shows_history", lambda args: True)
    assert main(["sim", program, *options]) == 0
    assert capsys.readouterr().out == without != ""


def test_a_robot_keeping_no_history_runs_the_same() -> None:
    """The plain view's robot keeps no packet log, frames or stroke points: the run itself (its
    trace, what the colour sensors read of its own ink) is the same."""
    source = (
        "when started\n    marker down\n    repeat 6\n        move 12 cm\n"
        '        turn right 150 degrees\n\nwhen color black seen\n    say "ink"\n'
    )
    checked = load_checked(source, "p.root")
    runs = []
    for keep in (True, False):
        robot = VirtualRobot(default_world(), keep_history=keep)
        result, recording = simulate(checked.program, source=source, robot=robot)
        runs.append((result.trace.text(), robot.world_pose, robot.packet_log, recording))
    (kept_trace, kept_pose, kept_log, kept_drawing), (trace, pose, log, drawing) = runs
    assert trace == kept_trace and pose == kept_pose
    assert "ink" in trace  # (the sensors did read the robot's own line)
    assert kept_log and not log
    assert len(kept_drawing.strokes[0].points) > 2 and len(drawing.strokes[0].points) == 1


def test_cli_sim_uses_the_world_the_program_names_and_robot_override(
    capsys: pytest.CaptureFixture[str],
) -> None:
    main(["sim", str(PROGRAMS / "bump_and_turn.root"), "--json"])
    assert json.loads(capsys.readouterr().out)["world"] == "arena"
    main(["sim", str(PROGRAMS / "square.root"), "--json", "--robot", "RT0"])
    assert json.loads(capsys.readouterr().out)["robot"] == "RT0"


def test_cli_sim_errors_are_messages_not_tracebacks(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["sim", str(tmp_path / "missing.root")]) == 1
    assert "can't find" in capsys.readouterr().err
    program = tmp_path / "p.root"
    program.write_text("when started\n    move 10 cm\n")
    bad_world = tmp_path / "w.toml"
    bad_world.write_text("[floor]\nwidth = -5\n")
    assert main(["sim", str(program), "--world", str(bad_world)]) == 1
    err = capsys.readouterr().err
    assert "floor.width" in err and "Traceback" not in err


def test_cli_sim_with_a_world_file(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    program = tmp_path / "p.root"
    program.write_text("when started\n    move 10 cm\n")
    world = tmp_path / "w.toml"
    world.write_text('name = "mine"\n[robot]\nx = 300\ny = 300\n')
    assert main(["sim", str(program), "--world", str(world), "--json"]) == 0
    summary = json.loads(capsys.readouterr().out)
    assert summary["world"] == "mine" and summary["world_pose"]["y_mm"] == 400
    assert load_world(world).robot.x == 300


def test_docs_example_runs() -> None:
    """The packet-level example in docs/simulator.md, run as written."""
    doc = (Path(__file__).parents[2] / "docs" / "simulator.md").read_text(encoding="utf-8")
    example = doc.split("```python\n", 1)[1].split("```", 1)[0]
    result = subprocess.run(
        [sys.executable, "-c", example], capture_output=True, text=True, timeout=60,
        cwd=Path(__file__).parents[2],
    )  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert "drive_distance_response" in result.stdout


def test_a_resting_robot_still_reports_its_battery() -> None:
    source = "when battery low\n    print battery\n    stop all\n"
    world = parse_world("time_limit = 60\n[robot]\nbattery = 25\nbattery_drain = 60", "w.toml")
    checked = load_checked(source, "p.root")
    result, _ = simulate(checked.program, world, source=source)
    assert result.end == "stopped"
    assert result.printed == ["15%"]
    assert result.sim_time_s == pytest.approx(30, abs=0.1)  # 10 points at 20 % a minute


def test_cli_sim_world_by_name(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["sim", str(PROGRAMS / "square.root"), "--world", "arena", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["world"] == "arena"
    assert main(["sim", str(PROGRAMS / "square.root"), "--world", "arenna"]) == 1
    err = capsys.readouterr().err
    assert "no world called arenna" in err and "arena" in err


def test_cli_sim_picture_flags_fail_clearly_when_they_cannot_write(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    target = tmp_path / "no such folder" / "square.svg"
    assert main(["sim", str(PROGRAMS / "square.root"), "--svg", str(target)]) == 1
    err = capsys.readouterr().err
    assert "picture" in err and "Traceback" not in err


def test_cli_sim_json_reports_mistakes_as_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "oops.root"
    program.write_text("when started\n    mve 10 cm\n", encoding="utf-8")
    assert main(["sim", str(program), "--json"]) == 1
    summary = json.loads(capsys.readouterr().out)
    assert summary["end"] == "mistakes"  # never ran (not "error": a run that stopped with one)
    assert [(e["code"], e["line"], e["column"]) for e in summary["errors"]] == [("E023", 2, 5)]
    assert 'Did you mean "move"?' in summary["errors"][0]["rendered"]


def test_cli_sim_json_gives_a_run_s_error_as_the_studio_does(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = tmp_path / "oops.root"
    program.write_text("when started\n    move 10 cm / 0\n", encoding="utf-8")
    assert main(["sim", str(program), "--json"]) == 1
    summary = json.loads(capsys.readouterr().out)
    assert summary["end"] == "error"
    error = summary["error"]
    assert (error["code"], error["line"], error["file"]) == ("E204", 2, str(program))
    assert "move 10 cm / 0" in error["rendered"] and "^" in error["rendered"]


def test_cli_sim_checks_a_program_once(monkeypatch: pytest.MonkeyPatch) -> None:
    # the session checks it; the run takes the checked program and doesn't check it again
    import rootlang.checks

    runs: list[object] = []
    real_run = rootlang.checks._Checker.run

    def counted(checker: rootlang.checks._Checker) -> rootlang.checks.CheckedProgram:
        runs.append(checker)
        return real_run(checker)

    monkeypatch.setattr(rootlang.checks._Checker, "run", counted)
    assert main(["sim", str(PROGRAMS / "square.root")]) == 0
    assert len(runs) == 1


def test_moves_into_a_wall_end_as_the_robot_reports_them_never_as_silence() -> None:
    # each `move` after the first stall pushes against the wall again: the robot stalls again
    # and answers it so (it used to stay silent, the host sent it again, and the run ended with
    # "The robot didn't answer")
    program = rootlang.load_program("when started\n    repeat 20\n        move 10 cm\n")
    result, _ = rootlang.simulate(program, rootlang.default_world())
    assert result.error is None and result.end == "finished"
    assert result.stats.resent == 0 and result.stats.late_responses == 0
    stalls = [e for e in result.trace.entries if e.text.startswith("motor_stall_event")]
    assert len(stalls) >= 2 * 10  # both wheels, for each move against the wall
