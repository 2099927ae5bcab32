"""The HTML replay: one self-contained page (inline script, style and data) that plays a run back.

The page is the template ``replay.html`` (shipped as package data) with the run written into it as
JSON: the scene's shapes (the very ones the SVG and PNG draw), the ink and the path with a time
per point, the robot's outline in its own frame, its poses over time and the events. The script
in the template draws them on a canvas with y flipped, so +y points up as in the other pictures.
"""

from __future__ import annotations

import json
import re
from collections.abc import Sequence
from importlib import resources

from rootlang.sim.render.scene import (
    Circle,
    Erase,
    Label,
    Moment,
    Point,
    Polygon,
    Polyline,
    Replay,
    Scene,
    Shape,
)

MIN_FRAME_GAP_S = 0.04  # the replay needs no more than 25 poses a second; it interpolates between


def _q(value: float) -> float:
    """Numbers in the page are rounded to 0.1 (mm, degrees) so it stays small and reproducible."""
    rounded = round(value, 1)
    return 0.0 if rounded == 0 else rounded


def _flat(points: Sequence[Point]) -> list[float]:
    return [_q(v) for point in points for v in point]


def _times(times: Sequence[float]) -> list[float]:
    return [round(t, 3) for t in times]


def shape_data(shape: Shape) -> dict[str, object]:
    if isinstance(shape, Label):
        return {
            "k": "label",
            "at": _flat([shape.at]),
            "text": shape.text,
            "size": shape.size_mm,
            "color": shape.color,
            "anchor": shape.anchor,
        }
    paint = shape.paint
    data: dict[str, object]
    if isinstance(shape, Circle):
        data = {"k": "circle", "c": _flat([shape.center]), "r": _q(shape.radius_mm)}
    elif isinstance(shape, Polygon):
        data = {"k": "polygon", "p": _flat(shape.points)}
    else:
        data = {"k": "line", "p": _flat(shape.points)}
        if shape.times_s:
            data["t"] = _times(shape.times_s)
    data.update({"f": paint.fill, "s": paint.stroke, "w": _q(paint.width_mm)})
    if paint.opacity < 1:
        data["o"] = paint.opacity
    return data


def _ink_data(item: Polyline | Erase) -> dict[str, object]:
    if isinstance(item, Erase):
        return {
            "k": "erase",
            "p": _flat(item.points),
            "t": _times(item.times_s),
            "w": _q(item.width_mm),
        }
    return shape_data(item)


def _frames(moments: Sequence[Moment]) -> tuple[dict[str, list[float]], list[dict[str, str]]]:
    """Column-wise poses, thinned to ``MIN_FRAME_GAP_S`` but keeping every change of light and
    the last pose exactly; LED states are an index into a small table."""
    leds: list[dict[str, str]] = []
    columns: dict[str, list[float]] = {"t": [], "x": [], "y": [], "h": [], "led": []}
    last_t, last_led = -1.0, -1
    for number, moment in enumerate(moments):
        state = {"color": moment.led or "", "mode": moment.led_mode if moment.led else "off"}
        if state not in leds:
            leds.append(state)
        led = leds.index(state)
        final = number == len(moments) - 1
        if not final and led == last_led and moment.t_s - last_t < MIN_FRAME_GAP_S:
            continue
        for key, value in (
            ("t", round(moment.t_s, 3)),
            ("x", _q(moment.x_mm)),
            ("y", _q(moment.y_mm)),
            ("h", _q(moment.heading_deg)),
            ("led", led),
        ):
            columns[key].append(value)
        last_t, last_led = moment.t_s, led
    return columns, leds


def page_data(scene: Scene, replay: Replay) -> dict[str, object]:
    if not replay.moments:
        raise ValueError("a replay needs at least one pose")
    frames, leds = _frames(replay.moments)
    view = scene.view
    return {
        "view": [_q(view.left), _q(view.bottom), _q(view.right), _q(view.top)],
        "background": scene.background,
        "below": [shape_data(s) for s in scene.below],
        "ink": [_ink_data(item) for item in scene.ink],
        "path": shape_data(scene.path) if scene.path else None,
        "overlay": [shape_data(s) for s in scene.overlay],
        "robot": [shape_data(s) for s in replay.robot],
        "led": replay.light_ring,
        "leds": leds,
        "frames": frames,
        "events": [[round(e.t_s, 3), e.text, e.kind, e.line] for e in replay.events],
        "said": [[round(t, 3), text] for t, text in replay.said],
        "title": replay.title,
        "subtitle": scene.title,
    }


# Inside the page's JSON, characters that could end or bend the <script> element (a student's
# `say "<!--<script>"` would otherwise swallow the page's own script) are written as JSON escapes;
# they only ever occur inside JSON strings, where the escape means the same character.
_INERT_IN_SCRIPT = str.maketrans({"<": "\\u003c", ">": "\\u003e", "&": "\\u0026"})


def to_html(scene: Scene, replay: Replay) -> str:
    template = resources.files("rootlang.sim.render").joinpath("replay.html").read_text("utf-8")
    data = json.dumps(page_data(scene, replay), separators=(",", ":"), ensure_ascii=False)
    data = data.translate(_INERT_IN_SCRIPT)
    named = " — ".join(part for part in (replay.title, scene.title) if part)
    title = (named or "rootlang replay").replace("&", "&amp;").replace("<", "&lt;")
    filled = {"__TITLE__": title, "__DATA__": data, "__SHAPES__": shapes_script()}
    # in one pass: nothing filled in is read again
    return re.sub("__TITLE__|__DATA__|__SHAPES__", lambda hole: filled[hole.group(0)], template)


def shapes_script() -> str:
    """``shapes.js``: how a scene's shapes are drawn on a canvas (the replay page inlines it;
    the studio's stage loads it)."""
    return resources.files("rootlang.sim.render").joinpath("shapes.js").read_text("utf-8")
