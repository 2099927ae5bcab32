"""The packet table: every command, response and event of the Root BLE protocol, as data.

Transcribed from iRobot's "Root Robot Bluetooth Low Energy Protocol Documentation" (CC BY 4.0;
a copy is in ``tests/protocol/data/``), in the spec's order, device by device. Encoding,
decoding, validation, ``rootlang packet list``, the docs and the simulator's dispatch all read
this table; nothing else in rootlang knows a device or command number.

Robots: the spec marks whole devices as unsupported on some robots; those marks are copied here.
Where it says nothing, rootlang adds what the hardware makes plain (RT0 has no colour or cliff
sensor; gravity compensation is for a Root driving on a whiteboard) — see ``docs/protocol.md``.
Minimum protocol versions are the spec's notes (1.4, 1.5); everything else is 1.0.
"""

from __future__ import annotations

import functools

from rootlang.protocol.behaviour import (
    DOCKS,
    MARKER_MOVE,
    NOTE,
    RESET_POSITION,
    STOP,
    WHEELS,
    Actuator,
    Behaviour,
    Role,
    Tells,
    WhenSilent,
    arc_end,
    arcs,
    drive_end,
    drive_rest,
    drives,
    movement,
    navigate_end,
    navigates,
    same_goal,
    says,
    sound,
    turn_end,
    turn_rest,
    turns,
)
from rootlang.protocol.enums import (
    Board,
    BumperState,
    ColorBank,
    ColorFormat,
    ColorLighting,
    Device,
    DockContacts,
    DockResult,
    DockStatus,
    GravityCompensation,
    LedState,
    LightState,
    MarkerPosition,
    ModulationType,
    Motor,
    StallCause,
)
from rootlang.protocol.fields import FieldSpec, FieldType
from rootlang.protocol.specs import (
    CREATE3_ONLY,
    NOT_RT0,
    PAYLOAD_BYTES,
    ROOT_ROBOTS,
    RT1_ONLY,
    PacketSpec,
    choice,
    command,
    event,
    int8,
    int16,
    int32,
    reply,
    special,
    text,
    timestamp,
    uint8,
    uint16,
    uint16_array,
    uint32,
)
from rootlang.robots import RobotModel

# --- field groups that several packets share ---------------------------------------------

ROOT_WHEEL_SPEED = (-100, 100)
CREATE3_WHEEL_SPEED = (-306, 306)  # create3_docs: the Create 3's top speed is 306 mm/s


def _wheel_speed(name: str, side: str) -> FieldSpec:
    return int32(
        name,
        f"{side} wheel speed; positive is forwards",
        "mm/s",
        *ROOT_WHEEL_SPEED,
        robot_ranges={RobotModel.CREATE3: CREATE3_WHEEL_SPEED},
    )


_POSE = (
    timestamp(),
    int32("x", "x coordinate; +x is to the robot's right at its starting pose", "mm"),
    int32("y", "y coordinate; +y is straight ahead at its starting pose", "mm"),
    int16(
        "heading",
        "orientation, 0-3599; the robot starts at 900 (90 degrees)",
        "decidegrees",
        0,
        3599,
    ),
)

_DOCK_ACTION = (
    timestamp(),
    choice("status", DockStatus, "the ROS 2 action status", FieldType.INT8),
    choice("result", DockResult, "whether the robot is docked afterwards", FieldType.INT8),
)

_VERSIONS = (
    choice("board", Board, "which board the versions are for"),
    uint8("firmware_major", "firmware version, major number"),
    uint8("firmware_minor", "firmware version, minor number"),
    uint8("hardware_major", "hardware version, major number"),
    uint8("hardware_minor", "hardware version, minor number"),
    uint8("bootloader_major", "bootloader version, major number"),
    uint8("bootloader_minor", "bootloader version, minor number"),
    uint8("protocol_major", "protocol version, major number"),
    uint8("protocol_minor", "protocol version, minor number"),
    uint8("firmware_patch", "firmware version, patch number"),
)


def _ir_value(doc: str) -> str:
    return f"{doc}, in counts (0-4095)"


_IR_THRESHOLDS = (
    uint16("hysteresis", "counts below a threshold before a falling edge triggers", "counts"),
    uint16_array("thresholds", 7, _ir_value("threshold of each of sensors 0-6"), "counts", 0, 4095),
)

_PACKED_IR = (
    timestamp(),
    uint8("state", "bit n set while IR sensor n is past its threshold"),
    special("sensors", FieldType.PACKED_IR, _ir_value("reflected IR of sensors 0-6"), "counts"),
)

_LIGHT_LEVELS = (
    uint16("left", "left eye's ambient light level", "decipercent", 0, 1000),
    uint16("right", "right eye's ambient light level", "decipercent", 0, 1000),
)

_BATTERY = (
    timestamp(),
    uint16("voltage", "battery voltage", "mV"),
    uint8("percent", "battery charge", "%", 0, 100),
)

_DOCKING = (
    timestamp(),
    choice("contacts", DockContacts, "whether the robot touches the dock's contacts"),
    uint8("ir_sensor_0", "character received on IR sensor 0 (Create 3: the halo)"),
    uint8("ir_sensor_1", "character received on IR sensor 1 (Create 3: front docking sensor)"),
    uint8("ir_sensor_2", "character received on IR sensor 2 (unused on Create 3)"),
)

_IPV4 = (
    special("wlan0", FieldType.IPV4, "IPv4 address of wlan0"),
    special("wlan1", FieldType.IPV4, "IPv4 address of wlan1"),
    special("usb0", FieldType.IPV4, "IPv4 address of usb0"),
)

WITNESS_FIELDS = {
    "start_frequency": 440_000, "end_frequency": 440_000, "duration": 60_000, "attack": 0,
    "release": 0, "volume": 0, "modulation_type": ModulationType.DISABLED,
    "modulation_rate": 0, "append": 0,
}  # fmt: skip
"""The witness (Role.WITNESS): a silent sweep that would play for a minute."""
FILLER_FIELDS = {"devices": ()}
"""The filler (Role.FILLER): the events of no device."""
HALT_FIELDS = {"left": 0, "right": 0}
"""Both wheels at rest (Role.WHEELS): a pause stops the robot so."""

_DEVICES = special("devices", FieldType.DEVICES, "the device numbers (0-127) this is about")
_ROBOT_NAME = text("name", 16, "the robot's BLE advertising name, UTF-8")

# --- the table ----------------------------------------------------------------------------

GENERAL, MOTORS, MARKER = Device.GENERAL, Device.MOTORS, Device.MARKER
IR, LIGHT, DOCKING = Device.IR_PROXIMITY, Device.LIGHT_SENSORS, Device.DOCKING_SENSORS
BATTERY, NET = Device.BATTERY, Device.CONNECTIVITY

PACKETS: tuple[PacketSpec, ...] = (
    # Device 0 - General
    *command(
        GENERAL,
        0,
        "get_versions",
        "Ask for a board's firmware, hardware and protocol versions.",
        choice("board", Board, "which board to ask about"),
        response=reply("The versions of the board asked about.", *_VERSIONS),
    ),
    *command(GENERAL, 1, "set_name", "Set a new BLE advertising name.", _ROBOT_NAME),
    *command(
        GENERAL,
        2,
        "get_name",
        "Ask for the BLE advertising name.",
        response=reply("The robot's BLE advertising name.", _ROBOT_NAME),
    ),
    *command(
        GENERAL,
        3,
        "stop_and_reset",
        "Stop the robot at once and cancel pending actions (the app's stop button).",
        behaviour=STOP,
        role=Role.STOP,
    ),
    *command(GENERAL, 6, "disconnect", "Ask the robot to end the BLE connection now."),
    *command(
        GENERAL,
        7,
        "enable_events",
        "Turn on events from these devices (1 = enable).",
        _DEVICES,
        role=Role.FILLER,
    ),
    *command(
        GENERAL,
        9,
        "disable_events",
        "Turn off events from these devices (1 = disable; device 0 cannot be disabled).",
        _DEVICES,
    ),
    *command(
        GENERAL,
        11,
        "get_enabled_events",
        "Ask which devices have events enabled.",
        response=reply("The devices whose events are enabled.", _DEVICES),
    ),
    *command(
        GENERAL,
        14,
        "get_serial_number",
        "Ask for the product serial number.",
        response=reply(
            "The product serial number.", text("serial", 12, "the serial number, 12 bytes of UTF-8")
        ),
    ),
    *command(
        GENERAL,
        15,
        "get_sku",
        "Ask for the product SKU.",
        response=reply(
            "The product SKU.",
            text("sku", 16, "the SKU, UTF-8"),
            errata="The spec prints the SKU as bytes 3:19; byte 19 is the "
            "checksum, so it is bytes 3:18 (16 bytes).",
        ),
    ),
    *event(
        GENERAL,
        4,
        "stop_project_event",
        "Stop the running project (Root's nose button, Create 3's power button).",
    ),
    # Device 1 - Motors
    *command(
        MOTORS,
        4,
        "set_wheel_speeds",
        "Set both wheels' speeds.",
        _wheel_speed("left", "left"),
        _wheel_speed("right", "right"),
        behaviour=WHEELS,
        role=Role.WHEELS,
    ),
    *command(
        MOTORS,
        6,
        "set_left_wheel_speed",
        "Set the left wheel's speed only.",
        _wheel_speed("left", "left"),
        behaviour=WHEELS,
    ),
    *command(
        MOTORS,
        7,
        "set_right_wheel_speed",
        "Set the right wheel's speed only.",
        _wheel_speed("right", "right"),
        behaviour=WHEELS,
    ),
    *command(
        MOTORS,
        8,
        "drive_distance",
        "Drive straight for a distance.",
        int32("distance", "positive is forwards", "mm"),
        response=reply("Finished driving (or interrupted by a newer movement).", *_POSE),
        behaviour=movement(drives, drive_end, drive_rest),
    ),
    *command(
        MOTORS,
        12,
        "rotate_angle",
        "Turn in place by an angle.",
        int32("angle", "positive is clockwise", "decidegrees"),
        response=reply("Finished turning (or interrupted by a newer movement).", *_POSE),
        behaviour=movement(turns, turn_end, turn_rest),
    ),
    *command(
        MOTORS,
        13,
        "set_gravity_compensation",
        "Set how much the robot corrects for gravity when driving on a wall.",
        choice("active", GravityCompensation, "when compensation is on"),
        uint16("amount", "correction, 0-1000 (default 500)", "decipercent", 0, 1000),
        robots=ROOT_ROBOTS,
    ),
    *command(
        MOTORS,
        15,
        "reset_position",
        "Reset the estimated position to (0, 0), heading 90 degrees.",
        behaviour=RESET_POSITION,
    ),
    *command(
        MOTORS,
        16,
        "get_position",
        "Ask for the estimated position and heading.",
        response=reply("The estimated position and heading.", *_POSE),
        role=Role.WHERE,
    ),
    *command(
        MOTORS,
        17,
        "navigate_to_position",
        "Drive to a point, optionally ending at a heading.",
        int32("x", "x coordinate of the goal", "mm"),
        int32("y", "y coordinate of the goal", "mm"),
        int16(
            "heading",
            "final heading 0-3599, or -1 to let the robot choose",
            "decidegrees",
            -1,
            3599,
        ),
        response=reply("Finished navigating (or interrupted by a newer movement).", *_POSE),
        min_protocol=(1, 4),
        behaviour=movement(navigates, navigate_end, same_goal),
    ),
    *command(
        MOTORS,
        19,
        "dock",
        "Drive onto the dock.",
        response=reply("Docking finished.", *_DOCK_ACTION),
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
        behaviour=DOCKS,
    ),
    *command(
        MOTORS,
        20,
        "undock",
        "Drive off the dock.",
        response=reply(
            "Undocking finished.",
            *_DOCK_ACTION,
            errata="The spec prints this response as command 19; it is 20, the "
            "Undock command's number (a response repeats its request's "
            "first three bytes).",
        ),
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
        behaviour=DOCKS,
    ),
    *command(
        MOTORS,
        27,
        "drive_arc",
        "Drive along an arc given by an angle and a radius.",
        int32("angle", "positive is clockwise", "decidegrees"),
        int32("radius", "positive turns about a point to the robot's right", "mm"),
        response=reply("Finished the arc (or interrupted by a newer movement).", *_POSE),
        behaviour=movement(arcs, arc_end, turn_rest),
    ),
    *event(
        MOTORS,
        29,
        "motor_stall_event",
        "A motor stalled.",
        timestamp(),
        choice("motor", Motor, "which motor"),
        choice("cause", StallCause, "why it stalled"),
        role=Role.STALL,
    ),
    # Device 2 - Marker/Eraser
    *command(
        MARKER,
        0,
        "set_marker_position",
        "Move the marker/eraser actuator.",
        choice("position", MarkerPosition, "where to put the marker and eraser"),
        response=reply(
            "The actuator finished moving (or a newer marker command came).",
            choice("position", MarkerPosition, "where they are now"),
        ),
        robots=ROOT_ROBOTS,
        behaviour=MARKER_MOVE,
    ),
    # Device 3 - LED lights
    *command(
        Device.LEDS,
        2,
        "set_led_animation",
        "Set the light ring's animation and colour.",
        choice("state", LedState, "the animation"),
        uint8("red", "red brightness, 0 (off) to 255"),
        uint8("green", "green brightness, 0 (off) to 255"),
        uint8("blue", "blue brightness, 0 (off) to 255"),
    ),
    # Device 4 - Color sensor
    *command(
        Device.COLOR_SENSOR,
        1,
        "get_color_sensor_data",
        "Ask for raw readings of one bank of 8 colour sensors.",
        choice("bank", ColorBank, "which 8 sensors, left to right"),
        choice("lighting", ColorLighting, "the illumination while measuring"),
        choice("format", ColorFormat, "the unit of the readings"),
        response=reply(
            "Readings of the 8 sensors asked for, leftmost first.",
            uint16_array("data", 8, "readings in the format asked for"),
        ),
        robots=RT1_ONLY,
    ),
    *event(
        Device.COLOR_SENSOR,
        2,
        "color_sensor_event",
        "The colour under one of the 32 colour sensors changed.",
        special("colors", FieldType.COLORS, "colour under sensors 0-31, left to right"),
        robots=RT1_ONLY,
        tells=Tells.COLORS,
    ),
    # Device 5 - Sound
    *command(
        Device.SOUND,
        0,
        "play_note",
        "Play a frequency on the buzzer.",
        uint32("frequency", "the note's frequency", "Hz"),
        uint16("duration", "how long; 0 stops the note playing", "ms"),
        response=reply("Finished the note (or interrupted by a newer sound)."),
        behaviour=NOTE,
    ),
    *command(
        Device.SOUND,
        1,
        "stop_sound",
        "Stop any sound at once.",
        behaviour=Behaviour(Actuator.SOUND),
    ),
    *command(
        Device.SOUND,
        4,
        "say_phrase",
        "Speak text in robot language.",
        text("phrase", 16, "the text, at most 16 bytes of UTF-8"),
        response=reply("Finished speaking (or interrupted by a newer sound)."),
        behaviour=sound(says),
    ),
    *command(
        Device.SOUND,
        5,
        "play_sweep",
        "Sweep linearly from one frequency to another.",
        uint32("start_frequency", "frequency at the start", "mHz"),
        uint32("end_frequency", "frequency at the end", "mHz"),
        uint16("duration", "length of the sweep", "ms"),
        uint8("attack", "ramp-up time; attack + release <= duration", "ms"),
        uint8("release", "ramp-down time; attack + release <= duration", "ms"),
        uint8("volume", "0 (silent) to 255 (loudest)"),
        choice("modulation_type", ModulationType, "the property modulated while playing"),
        uint8("modulation_rate", "modulation rate", "Hz"),
        uint8("append", "non-zero: start after the playing sweep instead of interrupting"),
        response=reply("Finished the sweep (or interrupted by a newer sound)."),
        behaviour=NOTE,
        role=Role.WITNESS,
    ),
    # Device 11 - IR proximity (Create 3)
    *command(
        IR,
        1,
        "get_ir_proximity_values",
        "Ask for the leftmost six IR proximity sensors' values, with a timestamp.",
        response=reply(
            "The six leftmost IR proximity values.",
            timestamp(),
            uint16_array("sensors", 6, _ir_value("reflected IR of sensors 0-5"), "counts", 0, 4095),
        ),
        robots=CREATE3_ONLY,
        min_protocol=(1, 4),
    ),
    *command(
        IR,
        2,
        "get_packed_ir_proximity",
        "Ask for all seven IR proximity sensors' values and states, packed.",
        response=reply(
            "All seven IR proximity values and their states.", *_PACKED_IR, tells=Tells.IR
        ),
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
    ),
    *command(
        IR,
        3,
        "set_ir_event_thresholds",
        "Set the IR proximity event thresholds and the shared hysteresis.",
        *_IR_THRESHOLDS,
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
    ),
    *command(
        IR,
        4,
        "get_ir_event_thresholds",
        "Ask for the IR proximity event thresholds and the shared hysteresis.",
        response=reply("The IR proximity event thresholds and hysteresis.", *_IR_THRESHOLDS),
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
    ),
    *event(
        IR,
        0,
        "ir_proximity_event",
        "An IR proximity sensor crossed its threshold.",
        *_PACKED_IR,
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
        tells=Tells.IR,
    ),
    # Device 12 - Bumpers
    *event(
        Device.BUMPERS,
        0,
        "bumper_event",
        "A bumper was pressed or released.",
        timestamp(),
        choice("state", BumperState, "which bumpers are pressed now"),
        tells=Tells.BUMPERS,
    ),
    # Device 13 - Light sensors (Root)
    *command(
        LIGHT,
        1,
        "get_light_values",
        "Ask for the ambient light sensors' values.",
        response=reply(
            "The ambient light levels.", timestamp(), *_LIGHT_LEVELS, tells=Tells.LIGHT_LEVELS
        ),
        robots=ROOT_ROBOTS,
    ),
    *event(
        LIGHT,
        0,
        "light_event",
        "The ambient light seen by the robot's eyes changed.",
        timestamp(),
        choice("state", LightState, "which eyes see light"),
        *_LIGHT_LEVELS,
        robots=ROOT_ROBOTS,
        tells=Tells.LIGHT,
    ),
    # Device 14 - Battery
    *command(
        BATTERY,
        1,
        "get_battery_level",
        "Ask for the battery level.",
        response=reply("The battery level.", *_BATTERY, tells=Tells.BATTERY),
    ),
    *event(
        BATTERY,
        0,
        "battery_level_event",
        "The battery level dropped by more than 10%.",
        *_BATTERY,
        tells=Tells.BATTERY,
    ),
    # Device 16 - Accelerometer
    *command(
        Device.ACCELEROMETER,
        1,
        "get_accelerometer",
        "Ask for the accelerometer's values.",
        response=reply(
            "The acceleration along each axis.",
            timestamp(),
            int16("x", "acceleration along x", "milli-g"),
            int16("y", "acceleration along y", "milli-g"),
            int16("z", "acceleration along z", "milli-g"),
            tells=Tells.ACCELERATION,
        ),
    ),
    # Device 17 - Touch sensors
    *event(
        Device.TOUCH_SENSORS,
        0,
        "touch_sensor_event",
        "A top touch sensor changed.",
        timestamp(),
        special(
            "state",
            FieldType.HIGH_NIBBLE,
            "touched sensors (Create 3: button 1 is FRONT_LEFT, button 2 FRONT_RIGHT)",
        ),
        tells=Tells.TOUCH,
    ),
    # Device 19 - Docking sensors (Create 3)
    *command(
        DOCKING,
        1,
        "get_docking_values",
        "Ask for the docking sensors' values.",
        response=reply("The docking contacts and IR sensors.", *_DOCKING, tells=Tells.DOCKED),
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
    ),
    *event(
        DOCKING,
        0,
        "docking_sensor_event",
        "A docking contact or IR sensor changed.",
        *_DOCKING,
        robots=CREATE3_ONLY,
        min_protocol=(1, 5),
        tells=Tells.DOCKED,
    ),
    # Device 20 - Cliff sensor
    *event(
        Device.CLIFF_SENSOR,
        0,
        "cliff_event",
        "The cliff sensor found or lost a cliff.",
        timestamp(),
        uint8("cliff", "0: no cliff; anything else: over a cliff"),
        uint16("sensor", "the cliff sensor's value", "mV"),
        uint16("threshold", "the cliff sensor's threshold", "mV"),
        robots=NOT_RT0,
        tells=Tells.CLIFF,
    ),
    # Device 100 - Connectivity (Create 3)
    *command(
        NET,
        1,
        "get_ipv4_addresses",
        "Ask for the IPv4 address of each network interface.",
        response=reply(
            "The IPv4 address of each interface.",
            *_IPV4,
            errata="The spec prints this response's id as Inc.; it is Req. "
            "(the request's id), as for every response.",
        ),
        robots=CREATE3_ONLY,
    ),
    *command(
        NET,
        2,
        "request_easy_update",
        "Ask the robot to download and install the newest firmware, if online.",
        robots=CREATE3_ONLY,
    ),
    *event(
        NET,
        0,
        "ipv4_change_event",
        "A network interface's IPv4 address changed.",
        *_IPV4,
        robots=CREATE3_ONLY,
    ),
    *event(
        NET,
        3,
        "easy_update_event",
        "Progress of an easy update.",
        timestamp(),
        special("stage", FieldType.CHAR, "'d' downloading, 'i' installing"),
        int8("percent", "progress of this stage, or -1 after an error", "%", -1, 100),
        robots=CREATE3_ONLY,
    ),
)


ERASERS: frozenset[RobotModel] = RT1_ONLY
"""The robots whose marker actuator holds an eraser too: an RT0 takes ``ERASER_DOWN`` but has
no eraser to put down."""


@functools.cache
def devices_of(robot: RobotModel) -> frozenset[Device]:
    """The devices ``robot`` has: those of the packets it knows."""
    return frozenset(packet.device for packet in PACKETS if robot in packet.robots)


def _check_table() -> None:
    """Mistakes in the table fail at import, before any packet is built from it."""
    names = [p.name for p in PACKETS]
    assert len(names) == len(set(names)), "packet names must be unique"
    keys = [(p.sender, p.device, p.command) for p in PACKETS]
    assert len(keys) == len(set(keys)), "(sender, device, command) must be unique"
    for packet in PACKETS:
        assert packet.payload_size <= PAYLOAD_BYTES, f"{packet.name}: payload over 16 bytes"
        assert len(set(packet.field_names)) == len(packet.fields), f"{packet.name}: field names"
        if packet.behaviour.when_silent in (WhenSilent.BY_POSE, WhenSilent.DONE, WhenSilent.RESEND):
            assert packet.response is not None, f"{packet.name}: its silence needs an answer"
    roles = [p.role for p in PACKETS if p.role is not None]
    assert sorted(roles, key=str) == sorted(Role, key=str), "each role is one packet's"


_check_table()
_ROLES = {packet.role: packet for packet in PACKETS if packet.role is not None}


def by_role(role: Role) -> PacketSpec:
    """The packet the client needs for ``role``."""
    return _ROLES[role]
