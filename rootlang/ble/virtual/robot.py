"""The brain of a virtual BLE robot: the simulator's packet-speaking robot, on the wall clock.

The BLE side (:class:`rootlang.ble.virtual.bridge.BleBridge`) only needs a
:class:`~rootlang.runtime.transport.Transport`; this one is the simulator's
:class:`~rootlang.sim.transport.SimTransport` around a :class:`~rootlang.sim.robot.VirtualRobot`
in a world (scripted touches in the world are advertised, so touch-to-select works too).
"""

from __future__ import annotations

from rootlang.robots import RobotModel
from rootlang.runtime.clock import Clock, WallClock
from rootlang.runtime.transport import Transport
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.transport import SimTransport
from rootlang.sim.world import World


def simulated_robot(
    model: RobotModel | None = None,
    name: str | None = None,
    clock: Clock | None = None,
    world: World | None = None,
) -> Transport:
    """A virtual robot in ``world`` (default: the simulator's empty arena), in real time."""
    robot = VirtualRobot(world, model=model)
    if name:
        robot.name = name
    return SimTransport(robot, clock or WallClock())
