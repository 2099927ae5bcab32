"""The brain a virtual BLE robot serves when none is given.

Until the simulator's packet-level robot is wired in here, this is the runtime's loopback
robot: it answers every command by the packet table, moves in real time with exact motion and
no physics. Either way the BLE side is the same (:class:`rootlang.ble.virtual.bridge.BleBridge`).
"""

from __future__ import annotations

from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock, WallClock
from rootlang.runtime.loopback import LoopbackRobot
from rootlang.runtime.transport import Transport


def simulated_robot(
    model: RobotModel = RobotModel.RT1, name: str = "Virtual Root", clock: Clock | None = None
) -> Transport:
    return LoopbackRobot(clock or WallClock(), model=model, name=name)
