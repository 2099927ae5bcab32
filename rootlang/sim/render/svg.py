"""SVG back end: writes a :class:`~rootlang.sim.render.scene.Scene` as an SVG document.

One SVG user unit is one millimetre. SVG's y axis points down, so every point is written as
``(x, -y)``: the picture shows world +y (the robot's starting heading, 90°) pointing up, and the
view box is ``left, -top, width, height``. Numbers are rounded to 0.1 mm and elements keep the
scene's order, so the same run always gives byte-identical SVG.
"""

from __future__ import annotations

from collections.abc import Sequence
from xml.sax.saxutils import escape, quoteattr

from rootlang.sim.render.scene import (
    Circle,
    Erase,
    Label,
    Paint,
    Point,
    Polygon,
    Polyline,
    Scene,
    Shape,
)

DEFAULT_PX_PER_MM = 0.5


def number(value: float) -> str:
    """A number rounded to 0.1 with no trailing zeros (and never ``-0``)."""
    text = f"{value:.1f}".rstrip("0").rstrip(".")
    return "0" if text in ("-0", "") else text


def _points(points: Sequence[Point]) -> str:
    return " ".join(f"{number(x)},{number(-y)}" for x, y in points)


def _paint(paint: Paint) -> str:
    parts = [f'fill="{paint.fill or "none"}"']
    if paint.stroke:
        parts.append(f'stroke="{paint.stroke}" stroke-width="{number(paint.width_mm)}"')
    if paint.opacity < 1:
        parts.append(f'opacity="{paint.opacity:.2f}"')
    return " ".join(parts)


_LINE = 'stroke-linecap="round" stroke-linejoin="round"'


def shape_element(shape: Shape) -> str:
    if isinstance(shape, Polygon):
        return f'<polygon points="{_points(shape.points)}" {_paint(shape.paint)}/>'
    if isinstance(shape, Polyline):
        return f'<polyline points="{_points(shape.points)}" {_paint(shape.paint)} {_LINE}/>'
    if isinstance(shape, Circle):
        x, y = shape.center
        return (
            f'<circle cx="{number(x)}" cy="{number(-y)}" r="{number(shape.radius_mm)}" '
            f"{_paint(shape.paint)}/>"
        )
    return _label(shape)


def _label(label: Label) -> str:
    x, y = label.at
    return (
        f'<text x="{number(x)}" y="{number(-y)}" font-size="{number(label.size_mm)}" '
        f'font-family="sans-serif" text-anchor="{label.anchor}" fill="{label.color}">'
        f"{escape(label.text)}</text>"
    )


def _ink(scene: Scene) -> tuple[list[str], list[str]]:
    """The ink elements and the masks they need. Each run of eraser sweeps becomes a mask over
    everything drawn before it, so ink drawn afterwards stays and the mat is never erased."""
    view = scene.view
    drawn: list[str] = []
    masks: list[str] = []
    sweeps: list[Erase] = []

    def close_mask() -> None:
        nonlocal drawn
        if sweeps and drawn:
            name = f"erased{len(masks) + 1}"
            cuts = "".join(
                f'<polyline points="{_points(s.points)}" fill="none" stroke="black" '
                f'stroke-width="{number(s.width_mm)}" {_LINE}/>'
                for s in sweeps
            )
            masks.append(
                f'<mask id="{name}" maskUnits="userSpaceOnUse" x="{number(view.left)}" '
                f'y="{number(-view.top)}" width="{number(view.width)}" '
                f'height="{number(view.height)}"><rect x="{number(view.left)}" '
                f'y="{number(-view.top)}" width="{number(view.width)}" '
                f'height="{number(view.height)}" fill="white"/>{cuts}</mask>'
            )
            drawn = [f'<g mask="url(#{name})">', *drawn, "</g>"]
        sweeps.clear()

    for item in scene.ink:
        if isinstance(item, Erase):
            sweeps.append(item)
        else:
            close_mask()
            drawn.append(shape_element(item))
    close_mask()
    return drawn, masks


def to_svg(scene: Scene, px_per_mm: float = DEFAULT_PX_PER_MM) -> str:
    view = scene.view
    ink, masks = _ink(scene)
    lines = [
        '<?xml version="1.0" encoding="UTF-8"?>',
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{number(view.width * px_per_mm)}" '
        f'height="{number(view.height * px_per_mm)}" '
        f'viewBox="{number(view.left)} {number(-view.top)} {number(view.width)} '
        f'{number(view.height)}">',
        "<!-- rootlang: 1 unit = 1 mm; y is flipped (SVG y = -world y), so +y points up -->",
        f"<title>{escape(scene.title)}</title>" if scene.title else "",
        f"<defs>{''.join(masks)}</defs>" if masks else "",
        f'<rect x="{number(view.left)}" y="{number(-view.top)}" width="{number(view.width)}" '
        f'height="{number(view.height)}" fill="{scene.background}"/>',
        _group("world", [shape_element(s) for s in scene.below]),
        _group("path", [shape_element(scene.path)] if scene.path else []),
        _group("ink", ink),
        _group("robot", [shape_element(s) for s in scene.robot]),
        _group("overlay", [shape_element(s) for s in scene.overlay]),
        "</svg>",
    ]
    return "\n".join(line for line in lines if line) + "\n"


def _group(name: str, elements: list[str]) -> str:
    if not elements:
        return ""
    return "\n".join([f"<g id={quoteattr(name)}>", *elements, "</g>"])
