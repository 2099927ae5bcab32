"""Device 2, marker and eraser (Root): the actuator, and the lines they leave.

The marker paints into the floor the colour sensors read (if the model has them), and every line
is kept as a :class:`~rootlang.sim.recording.Stroke` for pictures.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from rootlang.protocol import MarkerPosition, Packet
from rootlang.sim.devices.base import Context, Handler, Pose, SimDevice
from rootlang.sim.models import ERASER_BEHIND, ERASER_WIDTH, MARKER_WIDTH
from rootlang.sim.recording import Stroke, Tool
from rootlang.sim.sensors import FloorRaster, body_point, sensor_color

MARKER_MOVE_MS = 400  # chosen: the marker/eraser actuator's travel time
STRAIGHT_MM = 0.5  # a stroke point this near the line through its neighbours is dropped

TOOL_POSITIONS: dict[Tool, MarkerPosition] = {
    "up": MarkerPosition.UP,
    "marker": MarkerPosition.MARKER_DOWN,
    "eraser": MarkerPosition.ERASER_DOWN,
}
TOOL_AT: dict[MarkerPosition, Tool] = {position: tool for tool, position in TOOL_POSITIONS.items()}

Point = tuple[float, float]


class Marker(SimDevice):
    def __init__(self, robot: Context, floor: FloorRaster | None) -> None:
        super().__init__(robot)
        self.floor = floor  # None: nothing reads the floor, so nothing is painted into it
        self.tool: Tool = "up"
        self._ink = sensor_color(robot.world.robot.marker_color)  # what colour sensors see of it
        self._move: tuple[Packet, int, Tool] | None = None  # request, its timer, where to
        self._stroke: Stroke | None = None
        self._tip: Point = (0.0, 0.0)  # where the marker (or the eraser's middle) last was
        self._eraser_bar: tuple[Point, Point] = ((0.0, 0.0), (0.0, 0.0))  # its ends, last time

    def commands(self) -> Mapping[str, Handler]:
        return {"set_marker_position": self._set_marker_position}

    def stop(self) -> None:
        """The actuator stops where it is (no answer)."""
        if self._move is not None:
            self.robot.cancel(self._move[1])
            self._move = None

    def draw(self, pose: Pose) -> None:
        """The tool down has come to ``pose``: the line (or the wiped strip) up to there."""
        if self.tool == "up" or self._stroke is None:
            return
        if self.tool == "marker":
            point = (pose[0], pose[1])
            if self.floor is not None:
                self.floor.paint(self._tip, point, MARKER_WIDTH, self._ink)
        else:
            point = body_point(pose, -ERASER_BEHIND, 0)
            if self.floor is not None:
                old, new = self._eraser_bar, _eraser_ends(pose)
                self.floor.erase((old[0], old[1], new[1], new[0]))
                self._eraser_bar = new
        self._tip = point
        self._add_stroke_point(point)

    def _set_marker_position(self, packet: Packet) -> None:
        robot = self.robot
        tool = TOOL_AT[MarkerPosition(packet["position"])]
        if tool == "eraser" and not robot.spec.has_eraser:
            tool = "up"  # RT0: the actuator moves, but there is no eraser to put down
        if self._move is not None:  # interrupted: answer at once, from where it is
            old, timer, _ = self._move
            robot.cancel(timer)
            robot.respond(old, position=TOOL_POSITIONS[self.tool])
        timer = robot.at(robot.now_ms + MARKER_MOVE_MS, self._arrived)
        self._move = (packet, timer, tool)

    def _arrived(self) -> None:
        assert self._move is not None
        packet, _, tool = self._move
        self._move = None
        self._set_tool(tool)
        self.robot.respond(packet, position=TOOL_POSITIONS[tool])

    def _set_tool(self, tool: Tool) -> None:
        if tool == self.tool:
            return
        robot = self.robot
        robot.sense_floor()  # the old tool's stroke up to here
        self.tool = tool
        self._stroke = None
        pose = robot.physics.pose
        if tool != "up":
            color = robot.world.robot.marker_color if tool == "marker" else robot.world.floor_color
            width = MARKER_WIDTH if tool == "marker" else ERASER_WIDTH
            self._stroke = Stroke(tool, color.hex, round(width), robot.now_ms)
            robot.recording.strokes.append(self._stroke)
            tip = (pose[0], pose[1]) if tool == "marker" else body_point(pose, -ERASER_BEHIND, 0)
            self._eraser_bar = _eraser_ends(pose)
            self._tip = tip
            self._add_stroke_point(tip)
        robot.record_frame(force=True)

    def _add_stroke_point(self, point: Point) -> None:
        assert self._stroke is not None
        points = self._stroke.points
        if not self.robot.keep_history and points:
            return
        new = (round(point[0]), round(point[1]))
        if points and new == points[-1]:
            return
        if len(points) >= 2 and _collinear(points[-2], points[-1], new):
            points[-1] = new
        else:
            points.append(new)


def _eraser_ends(pose: Pose) -> tuple[Point, Point]:
    half = ERASER_WIDTH / 2
    return body_point(pose, -ERASER_BEHIND, half), body_point(pose, -ERASER_BEHIND, -half)


def _collinear(a: tuple[int, int], b: tuple[int, int], c: tuple[int, int]) -> bool:
    """True when b lies on the straight line from a to c (within ``STRAIGHT_MM``)."""
    length = math.dist(a, c)
    if length == 0:
        return True
    cross = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    dot = (b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1])
    return abs(cross) / length <= STRAIGHT_MM and 0 <= dot <= length * length
