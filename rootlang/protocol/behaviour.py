"""How a command behaves on the robot, as its row of the packet table says: the actuator it
uses, what its silence means, how long it takes and where it leaves the robot.

The robot client reads this and nothing else about a command (docs/runtime.md, "A lossy
link"); the loopback robot of the tests reads the actuators too. Nothing here knows a packet's
name: the table gives each command its behaviour.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

Fields = Mapping[str, Any]
Place = tuple[float, float, float]
"""Where a robot stands: x and y in mm, heading in degrees (90 = facing +y at the start)."""

START: Place = (0.0, 0.0, 90.0)
"""Where a robot stands after a reset (and when it starts)."""


class Actuator(enum.Enum):
    """What a command drives: a newer command on one actuator interrupts the older one, on the
    robot and in the client's wait."""

    MOTION = "motion"
    MARKER = "marker"
    SOUND = "sound"


class WhenSilent(enum.Enum):
    """What to do when a command's answer does not come (or, for a command the robot never
    answers, how the host makes sure it arrived)."""

    GIVE_UP = "an error"
    """Nothing tells what happened: a run-time error (E203). An unanswered command is sent once."""
    RESEND = "sent again"
    """The same however often it is asked for: send it again."""
    BY_POSE = "judged by the pose"
    """A movement: at its end it was done (the answer was lost), at its start it never
    arrived (send it again), anywhere else an error."""
    DONE = "done all the same"
    """It has ended by now, heard or not: go on."""
    REPEAT = "sent more than once where writes are not acknowledged"
    """Never answered and nothing reports it: on a link that doesn't acknowledge writes it
    goes out several times (the robot does the same again)."""
    CONFIRM = "sent again until the robot shows it arrived"
    """Never answered: sent until the robot shows it arrived (it puts the robot at START)."""


@dataclass(frozen=True)
class Way:
    """The way a command takes: ``along_mm`` driven, ``turned_degrees`` turned (while driving
    when ``at_once``, an arc; else one after the other) and ``seconds`` of its own (a note)."""

    along_mm: float = 0.0
    turned_degrees: float = 0.0
    seconds: float = 0.0
    at_once: bool = False


@dataclass(frozen=True)
class Behaviour:
    """One command's behaviour; the default is a command that moves nothing and is trusted."""

    actuator: Actuator | None = None
    when_silent: WhenSilent = WhenSilent.GIVE_UP
    takes: Callable[[Fields], Way] | None = None
    """The way it takes, from its fields (None: no time to speak of)."""
    ends_at: Callable[[Place, Fields], Place] | None = None
    """Where it leaves a robot that starts at a place (None: where it was)."""
    sets_wheels: bool = False
    """It sets wheel speeds that go on moving the robot after it was sent."""
    stops: bool = False
    """It stops everything the robot does (and ends every actuator's command)."""
    rest: Callable[[Fields, Place, Place], Fields | None] | None = None
    """A movement cut short by a pause: the fields that finish it from where the robot
    stopped, given where it started and where it stopped (None: nothing left; a behaviour
    without one is not finished)."""

    def described(self) -> str:
        """In words, for the packet reference ("" for a trusted command)."""
        told = []
        if self.actuator is not None:
            told.append(f"uses the {self.actuator.value} actuator (a newer command there ends it)")
        if self.stops:
            told.append("stops everything the robot does")
        if self.resets:
            told.append("puts the position back at the start")
        if self.sets_wheels:
            told.append("sets wheels that go on turning")
        if self.when_silent is not WhenSilent.GIVE_UP:
            told.append(f"when the robot is silent: {self.when_silent.value}")
        return "; ".join(told)

    def way(self, fields: Fields) -> Way:
        return Way() if self.takes is None else self.takes(fields)

    def end(self, start: Place, fields: Fields) -> Place:
        return start if self.ends_at is None else self.ends_at(start, fields)

    @property
    def moves(self) -> bool:
        return self.actuator is Actuator.MOTION

    @property
    def resets(self) -> bool:
        """It puts the robot's position back at START (the robot never answers it)."""
        return self.when_silent is WhenSilent.CONFIRM


TRUSTED = Behaviour()


# --- the ways and ends the table's commands take --------------------------------------------


def drives(fields: Fields) -> Way:
    return Way(along_mm=abs(fields["distance"]))


def turns(fields: Fields) -> Way:
    return Way(turned_degrees=abs(fields["angle"] / 10.0))


def arcs(fields: Fields) -> Way:
    degrees = abs(fields["angle"] / 10.0)
    return Way(math.radians(degrees) * abs(fields["radius"]), degrees, at_once=True)


def navigates(fields: Fields) -> Way:
    """Turn towards the point, drive there (twice as far: it may not go straight), then face."""
    return Way(along_mm=math.hypot(fields["x"], fields["y"]) * 2, turned_degrees=360.0)


def lasts(seconds: float) -> Callable[[Fields], Way]:
    return lambda fields: Way(seconds=seconds)


def plays(fields: Fields) -> Way:
    return Way(seconds=fields["duration"] / 1000.0)


SAY_SECONDS_PER_BYTE = 0.3


def says(fields: Fields) -> Way:
    return Way(seconds=len(str(fields["phrase"]).encode()) * SAY_SECONDS_PER_BYTE)


def drive_end(start: Place, fields: Fields) -> Place:
    x, y, heading = start
    ahead = math.radians(heading)
    distance = float(fields["distance"])
    return (x + distance * math.cos(ahead), y + distance * math.sin(ahead), heading)


def turn_end(start: Place, fields: Fields) -> Place:
    """Clockwise is positive."""
    x, y, heading = start
    return (x, y, (heading - fields["angle"] / 10.0) % 360)


def arc_end(start: Place, fields: Fields) -> Place:
    """Clockwise about a point ``radius`` mm to the robot's right."""
    x, y, heading = start
    clockwise = math.radians(fields["angle"] / 10.0)
    right = math.radians(heading - 90.0)
    radius = float(fields["radius"])
    cx, cy = x + radius * math.cos(right), y + radius * math.sin(right)
    dx, dy = x - cx, y - cy
    cos, sin = math.cos(-clockwise), math.sin(-clockwise)
    end_heading = (heading - math.degrees(clockwise)) % 360
    return (cx + dx * cos - dy * sin, cy + dx * sin + dy * cos, end_heading)


def navigate_end(start: Place, fields: Fields) -> Place:
    """Turn towards the point, drive there, then face the heading asked for (if any)."""
    x, y, heading = start
    to_x, to_y, facing = float(fields["x"]), float(fields["y"]), fields["heading"]
    if facing >= 0:
        return (to_x, to_y, facing / 10.0)
    if math.hypot(to_x - x, to_y - y) >= 1:
        heading = math.degrees(math.atan2(to_y - y, to_x - x)) % 360
    return (to_x, to_y, heading)


def reset_end(start: Place, fields: Fields) -> Place:
    return START


def drive_rest(fields: Fields, start: Place, now: Place) -> Fields | None:
    """The distance still to drive, along the heading it started at."""
    ahead = math.radians(start[2])
    gone = (now[0] - start[0]) * math.cos(ahead) + (now[1] - start[1]) * math.sin(ahead)
    left = round(fields["distance"] - gone)
    return {**fields, "distance": left} if left * fields["distance"] > 0 else None


def turn_rest(fields: Fields, start: Place, now: Place) -> Fields | None:
    """The angle still to turn (a turn or an arc, its radius kept), from the heading: within
    the circle it was in when it stopped (a heading can't tell how many circles were done)."""
    angle = fields["angle"]
    clockwise = (start[2] - now[2]) % 360.0 if angle > 0 else (now[2] - start[2]) % 360.0
    left = round(abs(angle) - clockwise * 10.0)
    if left <= 0:
        return None
    return {**fields, "angle": left if angle > 0 else -left}


def same_goal(fields: Fields, start: Place, now: Place) -> Fields | None:
    """A movement to a place (or onto the dock): the same again, which goes there from anywhere."""
    return dict(fields)


SAME_PLACE_MM = 5.0
SAME_HEADING_DEGREES = 3.0


def same_place(a: Place, b: Place) -> bool:
    """Whether two places are one, within what odometry and rounding blur (5 mm, 3°)."""
    turned = abs((a[2] - b[2] + 180.0) % 360.0 - 180.0)
    return math.hypot(a[0] - b[0], a[1] - b[1]) <= SAME_PLACE_MM and turned <= SAME_HEADING_DEGREES


def movement(
    takes: Callable[[Fields], Way],
    ends_at: Callable[[Place, Fields], Place],
    rest: Callable[[Fields, Place, Place], Fields | None],
) -> Behaviour:
    """A movement the robot answers when done: judged by the pose when the answer is lost,
    and finished from where it stopped after a pause."""
    return Behaviour(Actuator.MOTION, WhenSilent.BY_POSE, takes, ends_at, rest=rest)


def sound(takes: Callable[[Fields], Way] | None = None) -> Behaviour:
    """A sound: once its time is up it has ended, heard or not."""
    return Behaviour(Actuator.SOUND, WhenSilent.DONE, takes)


NOTE = sound(plays)
"""A note or a sweep, playing for its duration (a paused run says which is playing)."""
WHEELS = Behaviour(Actuator.MOTION, WhenSilent.REPEAT, sets_wheels=True)
DOCKS = Behaviour(Actuator.MOTION, takes=lasts(120.0), rest=same_goal)
MARKER_MOVE = Behaviour(Actuator.MARKER, WhenSilent.RESEND)
STOP = Behaviour(when_silent=WhenSilent.CONFIRM, ends_at=reset_end, stops=True)
RESET_POSITION = Behaviour(when_silent=WhenSilent.CONFIRM, ends_at=reset_end)


class Role(enum.Enum):
    """The few packets the client needs by what they are for, not by what they do."""

    WHERE = "where"
    """Asks where the robot is (a movement's lost answer is judged by it)."""
    STOP = "stop"
    """Stops the robot: what every way a run ends sends."""
    WITNESS = "witness"
    """Sent just before a stop, which cuts it short: its answer says the stop arrived."""
    FILLER = "filler"
    """Does nothing and answers nothing: takes packet id 0, which a robot always obeys."""
    STALL = "stall"
    """Says a motor stalled: the movement under way ends there."""
    WHEELS = "wheels"
    """Sets both wheels' speeds: a pause stops them (both 0), and sets them going again."""


class Tells(enum.Enum):
    """Which of the robot's readings an event or a response tells (the client keeps them);
    every packet with a pose (x, y, heading) tells the pose too."""

    BUMPERS = "bumpers"
    TOUCH = "touch sensors"
    COLORS = "colours"
    LIGHT = "light state and levels"
    LIGHT_LEVELS = "light levels"
    CLIFF = "cliff"
    BATTERY = "battery"
    DOCKED = "docked"
    IR = "IR proximity"
    ACCELERATION = "acceleration"
