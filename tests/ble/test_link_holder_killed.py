"""The link holder's death stops the robot (docs/runtime.md, "The program's own process"):
`rootlang run` itself, the process that holds the robot's link, killed with SIGKILL mid-drive.
The virtual robot lives in this test's process, on a bumble controller whose partner is served
to `rootlang run` as an HCI transport over TCP (as `python -m bumble.apps.controllers` serves
it), so the kill takes the host away and leaves the radio link up, as a dongle's would: the
robot must notice by itself, as a real Root stops when its link drops. And the program's own
process, orphaned, ends: nothing is left running."""

from __future__ import annotations

import asyncio
import os
import signal
import socket
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

from bumble.controller import Controller
from bumble.transport.tcp_server import open_tcp_server_transport_with_socket

from rootlang.ble.virtual.bridge import BleBridge
from rootlang.ble.virtual.peripheral import LINK_TIMEOUT_SECONDS, PROBE_EVERY_SECONDS
from rootlang.ble.virtual.radio import VirtualRadio
from rootlang.ble.virtual.robot import simulated_robot
from rootlang.runtime.clock import WallClock
from rootlang.sim.devices.motors import STILL
from rootlang.sim.transport import SimTransport

DRIVE = "when started\n    drive 10 cm/s\n    wait 60 seconds\n"
BOUND_SECONDS = 60.0  # a bound for a hang, far above the robot's own timeout: never a speed


def _children(pid: int) -> list[int]:
    """The processes whose parent is ``pid`` (Linux's /proc)."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                stat = (entry / "stat").read_text()
            except OSError:
                continue
            if int(stat.rsplit(")", 1)[1].split()[1]) == pid:
                found.append(int(entry.name))
    return found


def _running(pid: int) -> bool:
    """Whether ``pid`` is still a process that runs (a zombie has ended: only unreaped)."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return False
    return stat.rsplit(")", 1)[1].split()[0] != "Z"


async def _until(condition: Callable[[], bool], what: str) -> None:
    async def waiting() -> None:
        while not condition():
            await asyncio.sleep(0.02)

    try:
        await asyncio.wait_for(waiting(), BOUND_SECONDS)
    except asyncio.TimeoutError:
        raise AssertionError(f"{what}: not after {BOUND_SECONDS:g} s") from None


def kill_the_holder(folder: Path) -> tuple[bool, float, list[int]]:
    """Run DRIVE with `rootlang run` (the link holder) in a process of its own, to the virtual
    robot here; once it drives and the robot has heard its host answer twice (a live host
    keeps the link), SIGKILL the holder. Whether it still drove before the kill, the seconds
    from the kill to still wheels, and the program's processes that were still running."""
    (folder / "drive.root").write_text(DRIVE, encoding="utf-8")
    clock = WallClock()
    brain = simulated_robot(name="Held", clock=clock)
    assert isinstance(brain, SimTransport)
    motors = brain.robot.devices.motors

    async def main() -> tuple[bool, float, list[int]]:
        radio = VirtualRadio()
        listening = socket.create_server(("127.0.0.1", 0))
        port = listening.getsockname()[1]
        hci = await open_tcp_server_transport_with_socket(listening)
        Controller("host's", host_source=hci.source, host_sink=hci.sink, link=radio.link)
        bridge = BleBridge(radio.device("Held"), brain, name="Held",
                           scan_response_in_advertisement=True)  # fmt: skip
        peripheral = await bridge.start()
        command = [sys.executable, "-m", "rootlang", "run", "drive.root", "--robot", "Held",
                   "--transport", f"tcp-client:127.0.0.1:{port}"]  # fmt: skip
        holder = subprocess.Popen(
            command, cwd=folder, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL
        )
        programs: list[int] = []
        try:
            await _until(lambda: motors.wanted != STILL, "the robot drives")
            programs.extend(_children(holder.pid))  # the program's own process
            await _until(lambda: peripheral.host_answered >= 2, "the host answers the robot")
            drove = motors.wanted != STILL
            holder.send_signal(signal.SIGKILL)
            killed = time.monotonic()
            holder.wait()
            await _until(lambda: motors.wanted == STILL == motors.wheels, "the robot stops")
            took = time.monotonic() - killed
            await _until(lambda: not any(map(_running, programs)), "the program's process ends")
            return drove, took, programs
        finally:
            holder.kill()
            holder.wait()
            for pid in programs:
                if _running(pid):
                    os.kill(pid, signal.SIGKILL)
            await bridge.stop()
            await hci.close()

    return clock.run(main())


def test_a_killed_link_holder_s_robot_stops_and_no_process_is_left(tmp_path: Path) -> None:
    drove, _seconds, programs = kill_the_holder(tmp_path)  # benchmarks/link_holder.py: them
    assert programs, "the program ran in a process of its own"
    assert drove, "a host that answers keeps its link: the robot drove on until the kill"
    assert LINK_TIMEOUT_SECONDS + PROBE_EVERY_SECONDS < BOUND_SECONDS
