"""A lossy link: the robot always stops, and every run is right or ends with a clear error."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from rootlang.app import session
from rootlang.app.faulty_link import judge, load, run_once
from rootlang.checks import parse
from rootlang.runtime.client import timeout_for
from rootlang.runtime.clock import VirtualClock
from rootlang.runtime.faults import FaultRates, FaultyTransport
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import RunResult, run_program
from rootlang.runtime.trace import Outcome

PROGRAMS = Path(__file__).parents[2] / "programs"
# Gallery programs whose outcome the program's commands fix (distances, turns, go to): on a
# link that delays packets, how far timed wheel driving (`drive ... wait ...`) goes can't be.
JUDGED = (
    "square", "dance", "star", "messages", "long_say", "go_to", "units", "countdown", "dice",
    "factorial", "divide_by_zero", "busy_loop",
)  # fmt: skip
RUNS = 504


@pytest.mark.slow
def test_at_ten_percent_faults_every_run_stops_the_robot_and_is_right_or_a_clear_error() -> None:
    outcomes = judge([load(PROGRAMS / f"{name}.root") for name in JUDGED], RUNS, rate=0.1)
    assert len(outcomes) >= 500
    assert all(outcome.stopped for outcome in outcomes)
    broken = [outcome for outcome in outcomes if not outcome.kept_promise]
    assert broken == []
    assert sum(outcome.correct for outcome in outcomes) >= 0.9 * RUNS


def test_the_same_seed_gives_the_same_faults_and_the_same_trace() -> None:
    program = load(PROGRAMS / "square.root")
    first, _ = run_once(program, seed=7)
    second, _ = run_once(program, seed=7)
    assert first.trace.to_json() == second.trace.to_json()


def test_a_faulty_link_drops_corrupts_repeats_and_delays() -> None:
    clock = VirtualClock()
    robot = LoopbackRobot(clock)
    link = FaultyTransport(robot, clock, seed=1, to_robot=FaultRates(rate=1.0))
    program = load(PROGRAMS / "square.root")
    clock.run(run_program(program.checked, link, clock, source=program.source, time_limit=20,
                          handle_ctrl_c=False))  # fmt: skip
    counts = link.to_robot.counts
    assert counts.packets >= 4
    assert min(counts.dropped, counts.corrupted, counts.duplicated, counts.delayed) > 0
    assert counts.dropped + counts.corrupted + counts.duplicated + counts.delayed == counts.packets


class _LosesFirst(LoopbackRobot):
    """A loopback robot whose link loses the first packet of one command (by device, command)."""

    lose: bytes = bytes((0, 3))  # Stop and Reset
    lost = 0

    async def send(self, packet: bytes) -> None:
        if packet[:2] == self.lose and not self.lost:
            self.lost += 1
            return
        await super().send(packet)


def _run(source: str, robot: LoopbackRobot, clock: VirtualClock) -> RunResult:
    program = parse(textwrap.dedent(source).strip() + "\n")
    return clock.run(run_program(program, robot, clock, time_limit=30, handle_ctrl_c=False))


def test_stop_and_reset_is_sent_again_until_its_witness_is_answered() -> None:
    clock = VirtualClock()
    robot = _LosesFirst(clock)
    result = _run(
        """
        when started
            move 10 cm
            drive 5 cm/s
            wait 1 second
        """,
        robot,
        clock,
    )
    assert robot.lost == 1
    names = robot.names_received()
    # the first stop was lost: its witness (a silent sweep the stop would have cut short)
    # was not answered, so both went out again; the second was, and the pose is read after
    assert names[-4:] == ["play_sweep", "play_sweep", "stop_and_reset", "get_position"]
    assert robot.wheel_speeds == (0, 0)
    assert result.end == "finished" and result.pose is not None
    assert result.pose.y_mm > 0  # the pose before the stop, not the reset one


def test_a_lost_stop_is_never_confirmed_by_a_robot_still_at_its_start() -> None:
    # `drive 5 cm/s` on the spot: the robot's pose says the start, stop or no stop (the old
    # confirmation, a Get Position at the start pose, took the lost stop as arrived)
    clock = VirtualClock()
    robot = _LosesFirst(clock)
    _run("when started\n    drive 5 cm/s\n", robot, clock)
    assert robot.lost == 1
    assert robot.names_received().count("stop_and_reset") == 1  # sent again: it arrived
    assert robot.wheel_speeds == (0, 0)


def test_reset_position_is_confirmed_by_the_pose_and_sent_again_when_lost() -> None:
    clock = VirtualClock()
    robot = _LosesFirst(clock)
    robot.lose = bytes((1, 15))  # Reset Position
    printed: list[str] = []
    program = parse("when started\n    move 10 cm\n    reset position\n    print position y\n")
    clock.run(run_program(program, robot, clock, on_print=printed.append, handle_ctrl_c=False))
    assert robot.lost == 1
    assert robot.names_received().count("reset_position") == 1  # the one that arrived
    assert printed == ["0 cm"]


@pytest.mark.parametrize(("acknowledged", "copies"), [(False, 3), (True, 1)])
def test_wheel_speeds_go_out_three_times_unless_the_link_acknowledges_writes(
    acknowledged: bool, copies: int
) -> None:
    clock = VirtualClock()
    robot = LoopbackRobot(clock)
    robot.acknowledges_writes = acknowledged
    _run("when started\n    drive 5 cm/s\n    wait 1 second\n", robot, clock)
    sent = [p.packet for p in robot.received if p.packet.name == "set_wheel_speeds"]
    assert len(sent) == copies
    assert len({packet.id for packet in sent}) == copies  # own ids: none dropped as a repeat


class _LosesFirstAnswer(LoopbackRobot):
    """A loopback robot that moves, but whose first movement answer is lost on the way back."""

    lost = 0

    def deliver(self, data: bytes) -> None:
        if data[:2] == bytes((1, 8)) and not self.lost:  # Drive Distance's answer
            self.lost += 1
            return
        super().deliver(data)


def test_a_lost_movement_answer_is_made_good_by_the_pose_without_moving_again() -> None:
    clock = VirtualClock()
    robot = _LosesFirstAnswer(clock)
    result = _run("when started\n    move 10 cm\n    print position y\n", robot, clock)
    assert robot.lost == 1
    assert robot.names_received().count("drive_distance") == 1  # not sent again
    assert result.printed == ["10 cm"]
    move = next(e for e in result.trace.of_kind("command") if e.text == "move 100 mm")
    assert move.outcome is Outcome.DONE and "answer lost" in move.detail
    assert result.stats.recovered == 1
    assert result.sim_time_s < timeout_for("drive_distance", {"distance": 100})


def test_drive_then_end_on_a_lossy_link_never_leaves_the_robot_driving() -> None:
    # the program ends at once with the wheels turning: only a confirmed Stop and Reset stops
    # them, and the robot never leaves its start pose for long (the old confirmation's blind
    # spot: ~9 % of such runs left the robot driving); each seed its own faults
    program = session.load("drive.root", source="when started\n    drive 5 cm/s\n")
    left = [seed for seed in range(150) if not run_once(program, seed, rate=0.1)[1].stopped]
    assert left == []
