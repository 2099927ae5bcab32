"""PNG back end: draws a :class:`~rootlang.sim.render.scene.Scene` with Pillow.

The picture is drawn at ``SUPERSAMPLE`` times its size and reduced by box averaging, which
anti-aliases every edge without any extra dependency. Image y points down, so a world point
(x, y) lands at ``((x - left) * k, (top - y) * k)``: world +y points up, as in the SVG. The marker's
ink is drawn on a layer of its own, so an eraser sweep clears the ink but never the mat under it.
"""

from __future__ import annotations

import io
from collections.abc import Sequence

from PIL import Image, ImageDraw, ImageFont

from rootlang.sim.render.scene import (
    Circle,
    Erase,
    Label,
    Point,
    Polygon,
    Polyline,
    Scene,
    Shape,
    shape_points,
)

DEFAULT_PX_PER_MM = 0.5
SUPERSAMPLE = 3
_ANCHORS = {"start": "ls", "middle": "ms", "end": "rs"}
_CLEAR = (0, 0, 0, 0)


class _Canvas:
    """An RGBA image plus the mm → pixel mapping of the scene's view."""

    def __init__(self, scene: Scene, px_per_mm: float) -> None:
        self.scale = px_per_mm * SUPERSAMPLE
        self.left, self.top = scene.view.left, scene.view.top
        self.size = (
            round(scene.view.width * px_per_mm) * SUPERSAMPLE,
            round(scene.view.height * px_per_mm) * SUPERSAMPLE,
        )

    def pixel(self, point: Point, offset: tuple[int, int] = (0, 0)) -> tuple[float, float]:
        return (
            (point[0] - self.left) * self.scale - offset[0],
            (self.top - point[1]) * self.scale - offset[1],
        )

    def width(self, mm: float) -> int:
        return max(1, round(mm * self.scale))

    def draw(self, image: Image.Image, shape: Shape) -> None:
        """Draw a shape; a translucent one goes through a small layer so it blends once."""
        if isinstance(shape, Label) or shape.paint.opacity >= 1:
            self._draw(ImageDraw.Draw(image), shape, (0, 0))
            return
        opacity = shape.paint.opacity
        box = self._pixel_box(shape, image.size)
        if box is None:
            return
        x0, y0, x1, y1 = box
        layer = Image.new("RGBA", (x1 - x0, y1 - y0), _CLEAR)
        self._draw(ImageDraw.Draw(layer), shape, (x0, y0))
        layer.putalpha(layer.getchannel("A").point(lambda a: round(a * opacity)))
        image.alpha_composite(layer, dest=(x0, y0))

    def erase(self, image: Image.Image, sweep: Erase) -> None:
        self._line(ImageDraw.Draw(image), sweep.points, _CLEAR, self.width(sweep.width_mm), (0, 0))

    def _pixel_box(
        self, shape: Polygon | Polyline | Circle, size: tuple[int, int]
    ) -> tuple[int, int, int, int] | None:
        pixels = [self.pixel(p) for p in shape_points(shape)]
        margin = self.width(shape.paint.width_mm) + 2
        x0 = max(0, int(min(x for x, _ in pixels)) - margin)
        y0 = max(0, int(min(y for _, y in pixels)) - margin)
        x1 = min(size[0], int(max(x for x, _ in pixels)) + margin + 1)
        y1 = min(size[1], int(max(y for _, y in pixels)) + margin + 1)
        return (x0, y0, x1, y1) if x1 > x0 and y1 > y0 else None

    def _draw(self, draw: ImageDraw.ImageDraw, shape: Shape, offset: tuple[int, int]) -> None:
        if isinstance(shape, Label):
            font = ImageFont.load_default(size=self.width(shape.size_mm))
            draw.text(
                self.pixel(shape.at, offset),
                shape.text,
                fill=shape.color,
                font=font,
                anchor=_ANCHORS[shape.anchor],
            )
            return
        paint = shape.paint
        outline = self.width(paint.width_mm) if paint.stroke else 0
        if isinstance(shape, Polyline):
            if paint.stroke:
                self._line(draw, shape.points, paint.stroke, outline, offset)
        elif isinstance(shape, Polygon):
            draw.polygon(
                [self.pixel(p, offset) for p in shape.points],
                fill=paint.fill,
                outline=paint.stroke,
                width=outline,
            )
        else:
            x, y = self.pixel(shape.center, offset)
            r = shape.radius_mm * self.scale
            draw.ellipse(
                (x - r, y - r, x + r, y + r), fill=paint.fill, outline=paint.stroke, width=outline
            )

    def _line(
        self,
        draw: ImageDraw.ImageDraw,
        points: Sequence[Point],
        color: str | tuple[int, int, int, int],
        width: int,
        offset: tuple[int, int],
    ) -> None:
        pixels = [self.pixel(p, offset) for p in points]
        if len(pixels) > 1:
            draw.line(pixels, fill=color, width=width, joint="curve")
        radius = width / 2
        for x, y in (pixels[0], pixels[-1]) if pixels else ():  # round caps
            draw.ellipse((x - radius, y - radius, x + radius, y + radius), fill=color)


def to_png(scene: Scene, px_per_mm: float = DEFAULT_PX_PER_MM) -> bytes:
    canvas = _Canvas(scene, px_per_mm)
    image = Image.new("RGBA", canvas.size, scene.background)
    for shape in (*scene.below, *([scene.path] if scene.path else [])):
        canvas.draw(image, shape)
    ink = Image.new("RGBA", canvas.size, _CLEAR)
    for item in scene.ink:
        if isinstance(item, Erase):
            canvas.erase(ink, item)
        else:
            canvas.draw(ink, item)
    image.alpha_composite(ink)
    for shape in (*scene.robot, *scene.overlay):
        canvas.draw(image, shape)
    small = image.reduce(SUPERSAMPLE).convert("RGB")
    out = io.BytesIO()
    small.save(out, format="PNG")
    return out.getvalue()
