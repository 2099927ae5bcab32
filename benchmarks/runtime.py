"""Runtime figures: event-to-command latency, CPU while a move runs, virtual-time throughput.

Run: ``.venv/bin/python benchmarks/runtime.py`` (about 15 s). Prints:

1. host overhead from an event packet arriving to the handler's first command packet leaving,
   over the loopback robot on the wall clock (median and 99th percentile; aim: median <= 1 ms);
2. host CPU time while a 10-second move runs on the wall clock (aim: <= 2 % of a core);
3. virtual-time throughput: 100 scripts x 1,000 commands each, commands per second of host time.
"""

from __future__ import annotations

import asyncio
import statistics
import time

from rootlang.checks import parse
from rootlang.protocol import BumperState, Packet
from rootlang.runtime.clock import Clock, VirtualClock, WallClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.scheduler import RunResult, run_program

EVENTS = 2000


def event_latency() -> list[float]:
    """Seconds from a bumper event handed to the host to the handler's command at the robot."""
    source = "when bumped\n    light red\n"
    clock = WallClock()
    robot = LoopbackRobot(clock)
    latencies: list[float] = []

    async def main() -> None:
        loop = asyncio.get_running_loop()
        command_out: asyncio.Future[float] = loop.create_future()

        def on_send(packet: Packet) -> None:
            if packet.name == "set_led_animation" and not command_out.done():
                command_out.set_result(time.perf_counter())

        robot.on_send = on_send
        run = asyncio.ensure_future(run_program(parse(source), robot, clock, source=source))
        await clock.sleep(0.05)  # connected, scripts set up
        for _ in range(EVENTS):
            command_out = loop.create_future()
            sent = time.perf_counter()
            robot.emit("bumper_event", {"state": BumperState.LEFT})
            latencies.append(await command_out - sent)
            robot.emit("bumper_event", {"state": BumperState.NONE})
            await clock.sleep(0.0005)  # let the script end, so the next bump fires it again
        robot.emit("stop_project_event")
        await run

    clock.run(main())
    return latencies


def cpu_during_move() -> tuple[float, float]:
    """(wall seconds, CPU seconds) for a program whose one move takes 10 s on the loopback."""
    source = "when started\n    move 100 cm\n"
    clock = WallClock()
    robot = LoopbackRobot(clock)
    wall, cpu = time.perf_counter(), time.process_time()
    run(clock, source, robot)
    return time.perf_counter() - wall, time.process_time() - cpu


def virtual_throughput(scripts: int = 100, commands: int = 1000) -> tuple[int, float, float]:
    """(commands sent, host seconds, virtual seconds) for many scripts of many commands."""
    source = "".join(
        f"when started\n    repeat {commands}\n        light rgb {i} 0 0\n" for i in range(scripts)
    )
    clock = VirtualClock()
    robot = LoopbackRobot(clock)
    started = time.perf_counter()
    result = run(clock, source, robot)
    return result.stats.commands_sent, time.perf_counter() - started, result.sim_time_s


def run(clock: Clock, source: str, robot: LoopbackRobot) -> RunResult:
    return clock.run(run_program(parse(source), robot, clock, source=source))


def main() -> None:
    latencies = sorted(event_latency())
    median = statistics.median(latencies) * 1000
    p99 = latencies[int(len(latencies) * 0.99) - 1] * 1000
    print(f"event in -> first command out ({EVENTS} events, loopback, wall clock):")
    print(f"  median {median:.3f} ms, p99 {p99:.3f} ms, max {latencies[-1] * 1000:.3f} ms")

    wall, cpu = cpu_during_move()
    print(f"host CPU during a 10 s move (wall clock): {cpu * 1000:.1f} ms CPU in {wall:.2f} s")
    print(f"  = {100 * cpu / wall:.3f} % of one core")

    sent, host_seconds, virtual_seconds = virtual_throughput()
    print("virtual time, 100 scripts x 1,000 commands:")
    print(
        f"  {sent} commands in {host_seconds:.2f} s of host time "
        f"({sent / host_seconds:,.0f} commands/s), {virtual_seconds:.3f} s of virtual time"
    )


if __name__ == "__main__":
    main()
