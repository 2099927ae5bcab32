"""The HTML replay: one self-contained page (inline script, style and data) that plays a run back.

The page is the template ``replay.html`` (shipped as package data) with the run written into it as
JSON: the scene's shapes (the very ones the SVG and PNG draw), the ink and the path with a time
per point, the robot's outline in its own frame, its poses over time and the events. The script
in the template draws them on a canvas with y flipped, so +y points up as in the other pictures.
"""

from __future__ import annotations

import base64
import json
import re
from collections.abc import Sequence
from importlib import resources
from typing import Literal, TypedDict, TypeVar

from rootlang.sim.render.scene import (
    Circle,
    Erase,
    Label,
    Moment,
    Paint,
    Point,
    Polygon,
    Polyline,
    Replay,
    Scene,
)
from rootlang.sim.render.scene import Shape as SceneShape
from rootlang.wording.language import ENGLISH, Languages

MIN_FRAME_GAP_S = 0.04  # the replay needs no more than 25 poses a second; it interpolates between


# --- the page's data: these types are the contract with viewer.js and replay.js (written for them
# as page_data.d.ts by `python -m rootlang.studio.messages`) ---


class LabelShape(TypedDict):
    """Text at a point (world mm), ``size`` mm high."""

    k: Literal["label"]
    at: list[float]
    text: str
    size: float
    color: str
    anchor: str  # "start", "middle" or "end"


class _Painted(TypedDict):
    f: str | None  # fill
    s: str | None  # stroke
    w: float  # stroke width, mm


class _Faded(TypedDict, total=False):
    o: float  # opacity (1 when absent)


class _Timed(TypedDict, total=False):
    t: list[float]  # the time of each point (s): ink and the path


class CircleShape(_Painted, _Faded):
    """A circle: centre ``c`` [x, y] and radius ``r`` (mm)."""

    k: Literal["circle"]
    c: list[float]
    r: float


class PathShape(_Painted, _Faded, _Timed):
    """A polygon or a polyline: ``p`` flat [x0, y0, x1, y1, ...] mm."""

    k: Literal["polygon", "line"]
    p: list[float]


class EraseInk(TypedDict):
    """Where the eraser went: what ink is under it is wiped."""

    k: Literal["erase"]
    p: list[float]
    t: list[float]
    w: float


Shape = LabelShape | CircleShape | PathShape
_P = TypeVar("_P", CircleShape, PathShape)


class LedState(TypedDict):
    color: str
    mode: str  # "off", "on", "blink", "spin"


class Frames(TypedDict):
    """The robot's poses, column by column: time (s), x, y (mm), heading (deg, anticlockwise
    from +x) and the light (an index into ``leds``)."""

    t: list[float]
    x: list[float]
    y: list[float]
    h: list[float]
    led: list[int]


class PageData(TypedDict):
    """A run as the replay page (and the studio's stage) draws it: world mm, y up."""

    view: list[float]  # left, bottom, right, top
    background: str
    below: list[Shape]
    ink: list[PathShape | EraseInk]
    path: PathShape | None
    overlay: list[Shape]
    robot: list[Shape]  # in the robot's own frame
    led: int  # which of the robot's shapes is its light ring
    leds: list[LedState]
    frames: Frames
    events: list[tuple[float, str, str, int]]  # time s, text, kind, program line (or 0)
    said: list[tuple[float, str]]
    title: str
    subtitle: str


def _q(value: float) -> float:
    """Numbers in the page are rounded to 0.1 (mm, degrees) so it stays small and reproducible."""
    rounded = round(value, 1)
    return 0.0 if rounded == 0 else rounded


def _flat(points: Sequence[Point]) -> list[float]:
    return [_q(v) for point in points for v in point]


def _times(times: Sequence[float]) -> list[float]:
    return [round(t, 3) for t in times]


def shape_data(shape: SceneShape) -> Shape:
    if isinstance(shape, Label):
        return {
            "k": "label",
            "at": _flat([shape.at]),
            "text": shape.text,
            "size": shape.size_mm,
            "color": shape.color,
            "anchor": shape.anchor,
        }
    if isinstance(shape, Circle):
        paint = shape.paint
        circle: CircleShape = {
            "k": "circle", "c": _flat([shape.center]), "r": _q(shape.radius_mm),
            "f": paint.fill, "s": paint.stroke, "w": _q(paint.width_mm),
        }  # fmt: skip
        return _faded(circle, paint)
    return _path_data(shape)


def _faded(data: _P, paint: Paint) -> _P:
    if paint.opacity < 1:
        data["o"] = paint.opacity
    return data


def _path_data(shape: Polygon | Polyline) -> PathShape:
    kind: Literal["polygon", "line"] = "polygon" if isinstance(shape, Polygon) else "line"
    paint = shape.paint
    data: PathShape = {
        "k": kind, "p": _flat(shape.points),
        "f": paint.fill, "s": paint.stroke, "w": _q(paint.width_mm),
    }  # fmt: skip
    if isinstance(shape, Polyline) and shape.times_s:
        data["t"] = _times(shape.times_s)
    return _faded(data, paint)


def _ink_data(item: Polyline | Erase) -> PathShape | EraseInk:
    if isinstance(item, Erase):
        return {
            "k": "erase",
            "p": _flat(item.points),
            "t": _times(item.times_s),
            "w": _q(item.width_mm),
        }
    return _path_data(item)


def _frames(moments: Sequence[Moment]) -> tuple[Frames, list[LedState]]:
    """Column-wise poses, thinned to ``MIN_FRAME_GAP_S`` but keeping every change of light and
    the last pose exactly; LED states are an index into a small table."""
    leds: list[LedState] = []
    columns: Frames = {"t": [], "x": [], "y": [], "h": [], "led": []}
    last_t, last_led = -1.0, -1
    for number, moment in enumerate(moments):
        state: LedState = {
            "color": moment.led or "", "mode": moment.led_mode if moment.led else "off"
        }  # fmt: skip
        if state not in leds:
            leds.append(state)
        led = leds.index(state)
        final = number == len(moments) - 1
        if not final and led == last_led and moment.t_s - last_t < MIN_FRAME_GAP_S:
            continue
        columns["t"].append(round(moment.t_s, 3))
        columns["x"].append(_q(moment.x_mm))
        columns["y"].append(_q(moment.y_mm))
        columns["h"].append(_q(moment.heading_deg))
        columns["led"].append(led)
        last_t, last_led = moment.t_s, led
    return columns, leds


def page_data(scene: Scene, replay: Replay) -> PageData:
    if not replay.moments:
        raise ValueError("a replay needs at least one pose")
    frames, leds = _frames(replay.moments)
    view = scene.view
    return {
        "view": [_q(view.left), _q(view.bottom), _q(view.right), _q(view.top)],
        "background": scene.background,
        "below": [shape_data(s) for s in scene.below],
        "ink": [_ink_data(item) for item in scene.ink],
        "path": _path_data(scene.path) if scene.path else None,
        "overlay": [shape_data(s) for s in scene.overlay],
        "robot": [shape_data(s) for s in replay.robot],
        "led": replay.light_ring,
        "leds": leds,
        "frames": frames,
        "events": [(round(e.t_s, 3), e.text, e.kind, e.line) for e in replay.events],
        "said": [(round(t, 3), text) for t, text in replay.said],
        "title": replay.title,
        "subtitle": scene.title,
    }


# Inside the page's JSON, characters that could end or bend the <script> element (a student's
# `say "<!--<script>"` would otherwise swallow the page's own script) are written as JSON escapes;
# they only ever occur inside JSON strings, where the escape means the same character.
_INERT_IN_SCRIPT = str.maketrans({"<": "\\u003c", ">": "\\u003e", "&": "\\u0026"})


def to_html(scene: Scene, replay: Replay, languages: Languages = ENGLISH) -> str:
    """The replay page, its own words in the language ``languages`` show messages in."""
    template = _package_text("replay.html")
    data = json.dumps(page_data(scene, replay), separators=(",", ":"), ensure_ascii=False)
    data = data.translate(_INERT_IN_SCRIPT)
    words = page_words(languages)
    named = " — ".join(part for part in (replay.title, scene.title) if part)
    shown = json.dumps(words, ensure_ascii=False).translate(_INERT_IN_SCRIPT)
    filled = {"__TITLE__": _escaped(named or words["page"]), "__DATA__": data,
              "__IMPORTS__": _viewer_import_map(), "__REPLAY__": _package_text("replay.js"),
              "__LANG__": languages.messages, "__WORDS__": shown,
              "__PLAY__": _escaped(words["play"]), "__SPEED__": _escaped(words["speed"]),
              "__TIME__": _escaped(words["time"]).replace('"', "&quot;")}  # fmt: skip
    # in one pass: nothing filled in is read again
    return re.sub("__[A-Z]+__", lambda hole: filled.get(hole.group(0), hole.group(0)), template)


def page_words(languages: Languages) -> dict[str, str]:
    """The replay page's own words (its buttons, its list's "line 4"): the studio's, the
    catalogue's, in the language ``languages`` show messages in."""
    from rootlang.locale.blocks import studio_strings  # (only when a page is written)
    from rootlang.wording.catalogue import message

    strings = studio_strings(languages.messages)
    return {"play": strings["replay_play"], "pause": strings["pause"],
            "speed": strings["speed"], "time": strings["replay_time"],
            "page": strings["replay_page"],
            "line": message("V007", {"line": "{line}"}, languages)}  # fmt: skip


def _escaped(text: str) -> str:
    return text.replace("&", "&amp;").replace("<", "&lt;")


def _package_text(name: str) -> str:
    return resources.files("rootlang.sim.render").joinpath(name).read_text("utf-8")


def _viewer_import_map() -> str:
    """The page is one file: replay.js's ``import ... from "./viewer.js"`` (and
    ``"./announce.js"``, ``"./moment.js"``) finds the module (the studio's stage uses the same
    files) in the page itself, as a data: address."""
    modules = {}
    for name in ("viewer.js", "announce.js", "moment.js"):
        text = base64.b64encode(_package_text(name).encode("utf-8")).decode("ascii")
        modules[f"./{name}"] = f"data:text/javascript;base64,{text}"
    return json.dumps({"imports": modules})
