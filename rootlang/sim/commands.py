"""The firmware's command handlers: what the virtual robot does with each packet, by name.

``HANDLERS`` maps every command of the protocol table to a function of the robot and the packet
(a test checks that none is missing). They are the robot's firmware, split from
:mod:`rootlang.sim.robot` to keep each module readable; they use the robot's internals freely.
The choices made where the spec is silent are in docs/simulator.md.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import TYPE_CHECKING

from rootlang.protocol import (
    Board,
    Device,
    DockResult,
    DockStatus,
    LedState,
    MarkerPosition,
    Packet,
    spec,
)
from rootlang.sim import motion
from rootlang.sim.motion import Leg
from rootlang.sim.recording import LedMode, Note, Said, Tool
from rootlang.sim.sensors import REFLECTANCE, docked_pose, gravity_reading

if TYPE_CHECKING:
    from rootlang.sim.robot import VirtualRobot

MARKER_MOVE_MS = 400  # chosen: the marker/eraser actuator's travel time
NAME_BYTES = spec("set_name").field("name").size  # what a Set Name packet holds


TOOL_POSITIONS: dict[Tool, MarkerPosition] = {
    "up": MarkerPosition.UP,
    "marker": MarkerPosition.MARKER_DOWN,
    "eraser": MarkerPosition.ERASER_DOWN,
}
TOOL_AT: dict[MarkerPosition, Tool] = {position: tool for tool, position in TOOL_POSITIONS.items()}


def tool_position(tool: Tool) -> MarkerPosition:
    return TOOL_POSITIONS[tool]


def _say_ms(text: str) -> int:
    """How long the robot takes to say ``text`` (chosen: 120 ms a letter or digit, 60 ms else)."""
    return max(200, sum(120 if ch.isalnum() else 60 for ch in text))


Handler = Callable[["VirtualRobot", Packet], None]


def _get_versions(robot: VirtualRobot, packet: Packet) -> None:
    board = int(packet["board"])
    s = robot.spec
    if board != Board.MAIN and not s.has_color_sensor:
        robot._ignore(f"get_versions: {robot.model.display_name} has no board {board:#x}")
        return
    major, minor, patch = s.firmware
    robot._respond(
        packet, board=packet["board"], firmware_major=major, firmware_minor=minor,
        hardware_major=s.hardware[0], hardware_minor=s.hardware[1],
        bootloader_major=s.bootloader[0], bootloader_minor=s.bootloader[1],
        protocol_major=s.protocol[0], protocol_minor=s.protocol[1], firmware_patch=patch,
    )  # fmt: skip


def _set_name(robot: VirtualRobot, packet: Packet) -> None:
    # bytes that are not UTF-8 were decoded as U+FFFD (3 bytes each): keep what fits again
    name = str(packet["name"])
    while len(name.encode("utf-8")) > NAME_BYTES:
        name = name[:-1]
    robot.name = name


def _get_name(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, name=robot.name)


def _stop_and_reset(robot: VirtualRobot, packet: Packet) -> None:
    robot._stop_everything(respond=False)
    robot._reset_origin()
    robot._happened("stop and reset")


def _disconnect(robot: VirtualRobot, packet: Packet) -> None:
    robot.disconnect("the robot was asked to disconnect")
    if robot.on_disconnect is not None:
        robot.on_disconnect("the robot ended the connection, as asked")


def _devices_mask(packet: Packet) -> int:
    mask = 0
    for device in packet["devices"]:
        mask |= 1 << int(device)
    return mask


def _enable_events(robot: VirtualRobot, packet: Packet) -> None:
    robot._enabled |= _devices_mask(packet)


def _disable_events(robot: VirtualRobot, packet: Packet) -> None:
    robot._enabled &= ~(_devices_mask(packet) & ~(1 << int(Device.GENERAL)))


def _get_enabled_events(robot: VirtualRobot, packet: Packet) -> None:
    devices = [d for d in range(128) if robot._enabled >> d & 1]
    robot._respond(packet, devices=devices)


def _get_serial_number(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, serial=robot.spec.serial)


def _get_sku(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, sku=robot.spec.sku)


def _clamp(robot: VirtualRobot, speed: int) -> float:
    return float(max(-robot.spec.max_speed, min(robot.spec.max_speed, speed)))


def _set_wheel_speeds(robot: VirtualRobot, packet: Packet) -> None:
    robot._start_movement(None, (_clamp(robot, packet["left"]), _clamp(robot, packet["right"])))


def _set_left_wheel_speed(robot: VirtualRobot, packet: Packet) -> None:
    right = robot._wanted[1] if robot._movement is None else 0.0
    robot._start_movement(None, (_clamp(robot, packet["left"]), right))


def _set_right_wheel_speed(robot: VirtualRobot, packet: Packet) -> None:
    left = robot._wanted[0] if robot._movement is None else 0.0
    robot._start_movement(None, (left, _clamp(robot, packet["right"])))


def _drive_distance(robot: VirtualRobot, packet: Packet) -> None:
    robot._move(packet, [motion.fixed(Leg(float(packet["distance"])))])


def _rotate_angle(robot: VirtualRobot, packet: Packet) -> None:
    robot._move(packet, [motion.fixed(Leg(math.radians(packet["angle"] / 10), 0.0))])


def _drive_arc(robot: VirtualRobot, packet: Packet) -> None:
    angle, radius = math.radians(packet["angle"] / 10), float(packet["radius"])
    robot._move(packet, [motion.fixed(Leg(angle, radius))])


def _navigate_to_position(robot: VirtualRobot, packet: Packet) -> None:
    x, y = robot._world_from_odometry(packet["x"], packet["y"])
    planners = [motion.turn_towards(x, y), motion.drive_to(x, y)]
    if packet["heading"] >= 0:
        oheading = robot._origin[2]
        heading = math.radians(packet["heading"] / 10) - math.pi / 2 + oheading
        planners.append(motion.turn_to(heading))
    robot._move(packet, planners)


def _dock(robot: VirtualRobot, packet: Packet) -> None:
    target = docked_pose(robot.world)
    if target is None or robot._on_dock(robot.physics.pose):
        robot._start_movement(None)
        docked = target is not None
        status = DockStatus.SUCCEEDED if docked else DockStatus.ABORTED
        result = DockResult.DOCKED if docked else DockResult.NOT_DOCKED
        robot._respond(packet, timestamp=robot.now_ms, status=status, result=result)
        return
    x, y, heading = target
    approach = 350.0  # line up this far out, then drive straight on
    ax, ay = x - approach * math.cos(heading), y - approach * math.sin(heading)
    robot._move(
        packet,
        [motion.turn_towards(ax, ay), motion.drive_to(ax, ay), motion.turn_to(heading),
         motion.drive_to(x, y)],
    )  # fmt: skip


def _undock(robot: VirtualRobot, packet: Packet) -> None:
    if not robot._on_dock(robot.physics.pose):
        robot._start_movement(None)
        robot._respond(
            packet, timestamp=robot.now_ms, status=DockStatus.ABORTED, result=DockResult.NOT_DOCKED
        )
        return
    robot._move(packet, [motion.fixed(Leg(-250.0)), motion.fixed(Leg(math.pi, 0.0))])


def _set_gravity_compensation(robot: VirtualRobot, packet: Packet) -> None:
    robot.gravity_compensation = (int(packet["active"]), int(packet["amount"]))
    robot._happened(f"gravity compensation {int(packet['active'])} {packet['amount']}")


def _reset_position(robot: VirtualRobot, packet: Packet) -> None:
    robot._reset_origin()


def _get_position(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, **robot._pose_fields())


def _set_marker_position(robot: VirtualRobot, packet: Packet) -> None:
    tool = TOOL_AT[MarkerPosition(packet["position"])]
    if tool == "eraser" and not robot.spec.has_eraser:
        tool = "up"  # RT0: the actuator moves, but there is no eraser to put down
    if robot._marker_move is not None:  # interrupted: answer at once, from where it is
        old, timer, _ = robot._marker_move
        robot._cancel(timer)
        robot._respond(old, position=tool_position(robot._tool))
    timer = robot._at(robot.now_ms + MARKER_MOVE_MS, robot._marker_arrived)
    robot._marker_move = (packet, timer, tool)


def _set_led_animation(robot: VirtualRobot, packet: Packet) -> None:
    mode = _LED_MODES[LedState(packet["state"])]
    rgb = (int(packet["red"]), int(packet["green"]), int(packet["blue"]))
    robot._set_led(mode, (0, 0, 0) if mode == "off" else rgb)


_LED_MODES: dict[LedState, LedMode] = {
    LedState.OFF: "off",
    LedState.ON: "on",
    LedState.BLINK: "blink",
    LedState.SPIN: "spin",
}


def _get_color_sensor_data(robot: VirtualRobot, packet: Packet) -> None:
    bank, lighting, unit = int(packet["bank"]), int(packet["lighting"]), int(packet["format"])
    values = []
    for color in robot._colors[8 * bank : 8 * bank + 8]:
        red, green, blue = REFLECTANCE[color]
        reflectance = (0.02, red, green, blue, (red + green + blue) / 3)[lighting]
        values.append(round(reflectance * (3300 if unit == 1 else 4095)))
    robot._respond(packet, data=values)


def _play_note(robot: VirtualRobot, packet: Packet) -> None:
    duration = int(packet["duration"])
    if duration == 0:
        robot._stop_sound(respond=True)
        robot._respond(packet)
        return
    frequency = float(packet["frequency"])
    robot._play(packet, duration, Note(robot.now_ms, frequency, duration, frequency))


def _stop_sound(robot: VirtualRobot, packet: Packet) -> None:
    robot._stop_sound(respond=True)


def _say_phrase(robot: VirtualRobot, packet: Packet) -> None:
    text = str(packet["phrase"])
    duration = _say_ms(text)
    robot._play(packet, duration, None)
    robot.recording.said.append(Said(robot.now_ms, text, duration))
    robot._happened(f'said "{text}"')


def _play_sweep(robot: VirtualRobot, packet: Packet) -> None:
    if packet["append"] and robot._sound is not None:
        if robot._pending_sweep is not None:
            robot._respond(robot._pending_sweep)  # only one sweep can wait: the older goes
        robot._pending_sweep = packet
        return
    robot._start_sweep(packet)


def _get_ir_proximity_values(robot: VirtualRobot, packet: Packet) -> None:
    values = robot._ir_values(robot.physics.pose)
    robot._respond(packet, timestamp=robot.now_ms, sensors=values[:6])


def _get_packed_ir_proximity(robot: VirtualRobot, packet: Packet) -> None:
    values = robot._ir_values(robot.physics.pose)
    robot._respond(packet, timestamp=robot.now_ms, state=robot._ir_bits(values), sensors=values)


def _set_ir_event_thresholds(robot: VirtualRobot, packet: Packet) -> None:
    robot._ir_hysteresis = int(packet["hysteresis"])
    robot._ir_thresholds = [int(v) for v in packet["thresholds"]]


def _get_ir_event_thresholds(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, hysteresis=robot._ir_hysteresis, thresholds=robot._ir_thresholds)


def _get_light_values(robot: VirtualRobot, packet: Packet) -> None:
    left, right = robot._eyes(robot.physics.pose)
    robot._respond(packet, timestamp=robot.now_ms, left=left, right=right)


def _get_battery_level(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, timestamp=robot.now_ms, **robot._battery_fields())


def _get_accelerometer(robot: VirtualRobot, packet: Packet) -> None:
    x, y, z = gravity_reading(robot.world, robot.physics.pose[2], *robot._tilt)
    robot._respond(packet, timestamp=robot.now_ms, x=x, y=y, z=z)


def _get_docking_values(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, timestamp=robot.now_ms, **robot._dock_fields())


def _get_ipv4_addresses(robot: VirtualRobot, packet: Packet) -> None:
    robot._respond(packet, wlan0="0.0.0.0", wlan1="0.0.0.0", usb0="0.0.0.0")


def _request_easy_update(robot: VirtualRobot, packet: Packet) -> None:
    robot._ignore("request_easy_update: the simulated robot is not on the Internet")


HANDLERS: dict[str, Handler] = {
    "get_versions": _get_versions,
    "set_name": _set_name,
    "get_name": _get_name,
    "stop_and_reset": _stop_and_reset,
    "disconnect": _disconnect,
    "enable_events": _enable_events,
    "disable_events": _disable_events,
    "get_enabled_events": _get_enabled_events,
    "get_serial_number": _get_serial_number,
    "get_sku": _get_sku,
    "set_wheel_speeds": _set_wheel_speeds,
    "set_left_wheel_speed": _set_left_wheel_speed,
    "set_right_wheel_speed": _set_right_wheel_speed,
    "drive_distance": _drive_distance,
    "rotate_angle": _rotate_angle,
    "set_gravity_compensation": _set_gravity_compensation,
    "reset_position": _reset_position,
    "get_position": _get_position,
    "navigate_to_position": _navigate_to_position,
    "dock": _dock,
    "undock": _undock,
    "drive_arc": _drive_arc,
    "set_marker_position": _set_marker_position,
    "set_led_animation": _set_led_animation,
    "get_color_sensor_data": _get_color_sensor_data,
    "play_note": _play_note,
    "stop_sound": _stop_sound,
    "say_phrase": _say_phrase,
    "play_sweep": _play_sweep,
    "get_ir_proximity_values": _get_ir_proximity_values,
    "get_packed_ir_proximity": _get_packed_ir_proximity,
    "set_ir_event_thresholds": _set_ir_event_thresholds,
    "get_ir_event_thresholds": _get_ir_event_thresholds,
    "get_light_values": _get_light_values,
    "get_battery_level": _get_battery_level,
    "get_accelerometer": _get_accelerometer,
    "get_docking_values": _get_docking_values,
    "get_ipv4_addresses": _get_ipv4_addresses,
    "request_easy_update": _request_easy_update,
}
