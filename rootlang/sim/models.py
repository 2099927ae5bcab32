"""The simulated robot models: sizes, speeds, sensors and what each one says about itself.

Sources (see DESIGN.md §4): root-docs drawings for Root's size, wheels, marker, eraser, colour and
cliff sensors; create3_docs for the Create 3. Numbers that are not published are marked "chosen"
and explained in docs/simulator.md.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

from rootlang.protocol import Device
from rootlang.protocol.table import ERASERS, devices_of
from rootlang.robots import RobotModel
from rootlang.sim.world import TOUCH_SENSOR_NAMES


@dataclass(frozen=True)
class ModelSpec:
    """One robot model: its build, how it moves, its devices, and what it says about itself."""

    model: RobotModel
    # body (mm); a Root is a rounded box, a Create 3 a disc (``length == width == diameter``)
    length: float
    width: float
    round_body: bool
    wheel_base: float  # centre to centre
    wheel_diameter: float
    max_speed: float  # mm/s per wheel
    acceleration: float  # mm/s² per wheel
    # its devices' parameters (which devices it has, and its eraser, are the packet table's)
    touch_sensors: tuple[str, ...]  # the names it has, from world.TOUCH_SENSOR_NAMES
    cliff_ahead: float  # mm ahead of the centre
    bumper_half_angle: float  # degrees either side of straight ahead that the bumper covers
    # what it says about itself
    protocol: tuple[int, int]
    firmware: tuple[int, int, int]  # major, minor, patch (Create 3's major is the letter's code)
    firmware_text: str
    hardware: tuple[int, int]
    bootloader: tuple[int, int]
    serial: str  # exactly 12 characters
    sku: str
    default_name: str
    battery_mv: tuple[int, int]  # empty .. full

    @property
    def devices(self) -> frozenset[Device]:
        """The protocol's devices it has: those of the packets the table gives it."""
        return devices_of(self.model)

    @property
    def has_eraser(self) -> bool:
        """On the marker's actuator."""
        return self.model in ERASERS


ROOT_TOUCH = TOUCH_SENSOR_NAMES

_RT1 = ModelSpec(
    model=RobotModel.RT1,
    length=149.0, width=134.0, round_body=False, wheel_base=102.0, wheel_diameter=31.7,
    max_speed=100.0,
    acceleration=400.0,  # chosen: 0.25 s from standstill to full speed
    touch_sensors=ROOT_TOUCH,
    cliff_ahead=51.0, bumper_half_angle=90.0,
    protocol=(1, 3), firmware=(2, 7, 0), firmware_text="2.7", hardware=(1, 0), bootloader=(1, 0),
    serial="RT1SIMULATED", sku="RT1-SIM", default_name="Root",
    battery_mv=(3300, 4200),  # one Li-ion cell
)  # fmt: skip

MODELS: dict[RobotModel, ModelSpec] = {
    RobotModel.RT0: replace(
        _RT1,
        model=RobotModel.RT0,
        serial="RT0SIMULATED",
        sku="RT0-SIM",
    ),
    RobotModel.RT1: _RT1,
    RobotModel.CREATE3: ModelSpec(
        model=RobotModel.CREATE3,
        length=342.0,
        width=342.0,
        round_body=True,
        wheel_base=235.0,
        wheel_diameter=72.0,
        max_speed=306.0,
        acceleration=900.0,
        touch_sensors=TOUCH_SENSOR_NAMES[:2],  # buttons 1 and 2: front left, front right
        cliff_ahead=160.0,
        bumper_half_angle=80.0,
        protocol=(1, 5),
        firmware=(ord("G"), 5, 0),
        firmware_text="G.5",
        hardware=(1, 0),
        bootloader=(1, 0),
        serial="Ci3SIMULATED",
        sku="Ci3-SIM",
        default_name="Create 3",
        battery_mv=(12000, 16800),  # four Li-ion cells
    ),
}

# Positions of things on a Root, in mm from the centre of rotation (forward, left).
COLOR_SENSOR_AHEAD = 33.0
COLOR_SENSOR_SPAN = 86.0  # sensor 0 is leftmost, sensor 31 rightmost
ERASER_BEHIND = 31.0
ERASER_WIDTH = 89.0
MARKER_WIDTH = 3.0  # chosen: a felt-tip line
EYE_AHEAD, EYE_SIDE = 60.0, 30.0  # chosen: the light sensors behind Root's "eyes"

# Create 3's IR proximity sensors, left to right, in degrees from straight ahead (left positive).
IR_ANGLES = (65.0, 38.0, 20.0, 3.0, -14.0, -34.0, -65.0)
IR_RANGE = 300.0  # chosen: beyond this the sensor sees nothing (0 counts)
DOCK_OFFSET = 200.0  # chosen: a docked Create 3's centre is this far in front of the dock


def spec_for(model: RobotModel) -> ModelSpec:
    return MODELS[model]
