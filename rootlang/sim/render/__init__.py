"""Pictures of a simulated run: a still SVG or PNG, and a self-contained HTML replay.

A :class:`~rootlang.sim.recording.Recording` becomes one :class:`~rootlang.sim.render.scene.Scene`
(:mod:`~rootlang.sim.render.compose`), a list of primitive shapes that each back end draws
(:mod:`~rootlang.sim.render.svg`, :mod:`~rootlang.sim.render.png`,
:mod:`~rootlang.sim.render.html`), so the pictures agree. World millimetres, y up: the picture
shows the protocol's start heading (90°) pointing up the page. The same recording always gives
byte-identical files.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from rootlang.runtime.trace import ViewLine
from rootlang.sim.recording import Recording
from rootlang.sim.render import html, png, svg
from rootlang.sim.render.compose import replay_of, scene_of
from rootlang.sim.render.scene import Scene
from rootlang.wording.language import ENGLISH, Languages

__all__ = ["html_text", "png_bytes", "svg_text", "write_html", "write_png", "write_svg"]

PICTURE_PX = 800  # the longer side of a picture, unless a scale (pixels per mm) is given


def _px_per_mm(scene: Scene, scale: float | None) -> float:
    return scale or PICTURE_PX / max(scene.view.width, scene.view.height)


def svg_text(recording: Recording, scale: float | None = None) -> str:
    """The run as an SVG document (``scale``: its displayed pixels per millimetre)."""
    scene = scene_of(recording)
    return svg.to_svg(scene, _px_per_mm(scene, scale))


def png_bytes(recording: Recording, scale: float | None = None) -> bytes:
    """The run as a PNG image, ``scale`` pixels per millimetre."""
    scene = scene_of(recording)
    return png.to_png(scene, _px_per_mm(scene, scale))


def html_text(
    recording: Recording,
    *,
    title: str = "",
    story: Sequence[ViewLine] | None = None,
    languages: Languages = ENGLISH,
) -> str:
    """The run as one HTML page that replays it (no other files, no network). ``title`` names
    the program; ``story`` is the child's view of the run, listed beside the replay (without
    it, the list shows what the recording tells); the page's own words in ``languages``'."""
    return html.to_html(scene_of(recording), replay_of(recording, title, story), languages)


def write_svg(recording: Recording, path: str | Path, scale: float | None = None) -> None:
    Path(path).write_bytes(svg_text(recording, scale).encode("utf-8"))


def write_png(recording: Recording, path: str | Path, scale: float | None = None) -> None:
    Path(path).write_bytes(png_bytes(recording, scale))


def write_html(
    recording: Recording,
    path: str | Path,
    *,
    title: str = "",
    story: Sequence[ViewLine] | None = None,
    languages: Languages = ENGLISH,
) -> None:
    page = html_text(recording, title=title, story=story, languages=languages)
    Path(path).write_bytes(page.encode("utf-8"))
