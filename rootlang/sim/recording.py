"""What a simulated run leaves behind, for pictures, replays and summaries.

Everything here is quantised as the protocol quantises it — whole millimetres, decidegrees (as
``heading_ddeg``) and whole milliseconds — so the same program and world give byte-identical files
on any machine. Positions are world millimetres (see :mod:`rootlang.sim.world`): x right, y up,
headings counterclockwise from +x.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Literal, NamedTuple

from rootlang.robots import RobotModel
from rootlang.sim.world import World

Tool = Literal["up", "marker", "eraser"]
LedMode = Literal["off", "on", "blink", "spin"]
IntPoint = tuple[int, int]


class Frame(NamedTuple):  # one every 50 ms of a run: small, and quick to make
    """The robot at one moment (taken every ``FRAME_INTERVAL_MS`` while it moves, and on change)."""

    t_ms: int
    x_mm: int
    y_mm: int
    heading_ddeg: int  # decidegrees, 0-3599, counterclockwise from +x
    tool: Tool
    led_mode: LedMode
    led_rgb: tuple[int, int, int]

    @property
    def heading_deg(self) -> float:
        return self.heading_ddeg / 10


FrameState = tuple[int, int, int, Tool, LedMode, tuple[int, int, int]]
"""A frame's fields after its time: what it shows."""


@dataclass
class Stroke:
    """A polyline the marker drew (``kind="marker"``) or the eraser wiped (``kind="eraser"``)."""

    kind: Literal["marker", "eraser"]
    color: str  # "#rrggbb" (the eraser's is the floor's colour)
    width_mm: int
    t_ms: int  # when it started
    points: list[IntPoint] = field(default_factory=list)


@dataclass(frozen=True)
class Said:
    """Something the robot said, and for how long."""

    t_ms: int
    text: str
    duration_ms: int


@dataclass(frozen=True)
class Note:
    """A note (``end_hz == frequency_hz``) or a sweep, as played (cut short when interrupted)."""

    t_ms: int
    frequency_hz: float
    duration_ms: int
    end_hz: float


@dataclass(frozen=True)
class LightChange:
    """The robot's lights changed to ``mode``, in ``rgb``."""

    t_ms: int
    mode: LedMode
    rgb: tuple[int, int, int]


@dataclass(frozen=True)
class Happening:
    """Something to show on a replay's timeline: "bumper left", "cliff", "touch front left"."""

    t_ms: int
    text: str


FRAME_INTERVAL_MS = 50


@dataclass
class Recording:
    """What a run showed, for its pictures and replay: frames, strokes, sounds, lights, events."""

    world: World
    model: RobotModel
    frames: list[Frame] = field(default_factory=list)
    strokes: list[Stroke] = field(default_factory=list)
    said: list[Said] = field(default_factory=list)
    notes: list[Note] = field(default_factory=list)
    lights: list[LightChange] = field(default_factory=list)
    events: list[Happening] = field(default_factory=list)

    @property
    def duration_ms(self) -> int:
        return self.frames[-1].t_ms if self.frames else 0

    @property
    def final_frame(self) -> Frame | None:
        return self.frames[-1] if self.frames else None

    def path(self) -> list[IntPoint]:
        """The robot's centre over the run, as a polyline (consecutive duplicates removed)."""
        points: list[IntPoint] = []
        for frame in self.frames:
            point = (frame.x_mm, frame.y_mm)
            if not points or points[-1] != point:
                points.append(point)
        return points

    def marker_strokes(self) -> list[Stroke]:
        return [stroke for stroke in self.strokes if stroke.kind == "marker"]

    def to_json(self) -> dict[str, Any]:
        """A plain, deterministic dictionary of the whole recording (for files and replays)."""
        return {
            "world": self.world.name,
            "model": self.model.value,
            "frames": [
                [f.t_ms, f.x_mm, f.y_mm, f.heading_ddeg, f.tool, f.led_mode, list(f.led_rgb)]
                for f in self.frames
            ],
            "strokes": [
                {
                    "kind": s.kind,
                    "color": s.color,
                    "width_mm": s.width_mm,
                    "t_ms": s.t_ms,
                    "points": [list(p) for p in s.points],
                }
                for s in self.strokes
            ],
            "said": [
                {"t_ms": s.t_ms, "text": s.text, "duration_ms": s.duration_ms} for s in self.said
            ],
            "notes": [
                {
                    "t_ms": n.t_ms,
                    "frequency_hz": n.frequency_hz,
                    "duration_ms": n.duration_ms,
                    "end_hz": n.end_hz,
                }
                for n in self.notes
            ],
            "lights": [{"t_ms": c.t_ms, "mode": c.mode, "rgb": list(c.rgb)} for c in self.lights],
            "events": [{"t_ms": e.t_ms, "text": e.text} for e in self.events],
        }


def quantise_heading(radians: float) -> int:
    """Radians counterclockwise from +x -> whole decidegrees in 0..3599."""
    return round(math.degrees(radians) * 10) % 3600
