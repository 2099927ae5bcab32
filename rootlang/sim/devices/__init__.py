"""The simulated robot's devices: one class per device of the protocol.

Each owns its state, its command handlers and its sensing, and sees only the small
:class:`~rootlang.sim.devices.base.Context` the robot gives it. A model is the set of devices it
has (:attr:`rootlang.sim.models.ModelSpec.devices`) and their parameters; :class:`Devices` builds
that set for one robot. How to add a device or a packet: docs/simulator.md.
"""

from __future__ import annotations

from collections.abc import Iterator

from rootlang.protocol import Device
from rootlang.sim.devices.accelerometer import Accelerometer
from rootlang.sim.devices.base import Context, Handler, SimDevice
from rootlang.sim.devices.battery import Battery
from rootlang.sim.devices.bumpers import Bumpers
from rootlang.sim.devices.cliff import Cliff
from rootlang.sim.devices.color_sensor import ColorSensor
from rootlang.sim.devices.docking import Docking
from rootlang.sim.devices.general import Connectivity, General
from rootlang.sim.devices.ir_proximity import IrProximity
from rootlang.sim.devices.light_sensors import LightSensors
from rootlang.sim.devices.lights import Lights
from rootlang.sim.devices.marker import Marker
from rootlang.sim.devices.motors import Motors
from rootlang.sim.devices.sound import Sound
from rootlang.sim.devices.touch import Touch

__all__ = ["Context", "Devices", "Handler", "SimDevice"]


class Devices:
    """The devices one robot model has (absent ones are None), built for one robot."""

    def __init__(self, robot: Context, name: str) -> None:
        has = robot.spec.devices.__contains__
        # every model has these (the packet table gives every robot their packets)
        self.general = General(robot, name)
        self.lights = Lights(robot)
        self.sound = Sound(robot)
        self.bumpers = Bumpers(robot)
        self.battery = Battery(robot)
        self.accelerometer = Accelerometer(robot)
        self.touch = Touch(robot)
        # and these some models have
        self.docking = Docking(robot) if has(Device.DOCKING_SENSORS) else None
        self.motors = Motors(robot, self.docking)
        self.color_sensor = ColorSensor(robot) if has(Device.COLOR_SENSOR) else None
        floor = None if self.color_sensor is None else self.color_sensor.floor
        self.marker = Marker(robot, floor) if has(Device.MARKER) else None
        self.ir_proximity = IrProximity(robot) if has(Device.IR_PROXIMITY) else None
        self.light_sensors = LightSensors(robot) if has(Device.LIGHT_SENSORS) else None
        self.cliff = Cliff(robot) if has(Device.CLIFF_SENSOR) else None
        self.connectivity = Connectivity(robot) if has(Device.CONNECTIVITY) else None

    def __iter__(self) -> Iterator[SimDevice]:
        return (device for device in vars(self).values() if isinstance(device, SimDevice))

    def commands(self) -> dict[str, Handler]:
        """Every command the robot acts on, by packet name -> its device's handler."""
        return {name: handler for device in self for name, handler in device.commands().items()}
