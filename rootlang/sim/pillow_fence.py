"""The one place that touches Pillow's private C core (``PIL._imaging``): the colour sweep and
the marker's ink.

The colour sensors sample the floor with Pillow's QUAD transform. Asked through the public
``Image.transform(...).tobytes()`` the Python wrapper costs about four times the sampling itself,
so :func:`sample_quad` asks the C core directly; and the marker paints a short line into the
floor at every reading, where ``ImageDraw.line`` costs twice its own C call, which
:data:`line_painter` makes directly. Each only once a probe at import has seen exactly what the
public call gives; on any other Pillow the public call is used (same output, slower).
``tests/sim/test_floor_sweep.py`` checks both agree, and fails loudly if this Pillow no longer
takes the fast paths, so a Pillow upgrade cannot slow the simulator down unnoticed.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from PIL import Image, ImageDraw
from PIL import _imaging as pillow_core  # (Pillow always has it; what it offers may change)

Quad = tuple[float, float, float, float, float, float, float, float]
"""Upper left, lower left, lower right, upper right corners (x, y) in raster pixels."""

NEAREST = Image.Resampling.NEAREST
NO_FILL = 1  # the C core's flag: leave what lies off the image as the new image's 0


def public_sample(floor: Image.Image, size: tuple[int, int], quad: Quad) -> bytes:
    """Pillow's public QUAD transform; no fill colour, so what lies off the floor reads 0."""
    return floor.transform(size, Image.Transform.QUAD, quad, NEAREST).tobytes()


def core_sample(floor: Image.Image, size: tuple[int, int], quad: Quad) -> bytes:
    """The same sampling asked of Pillow's C core (a private API)."""
    (n, rows), (x0, y0, sw_x, sw_y, se_x, se_y, ne_x, ne_y) = size, quad
    across, down = 1.0 / n, 1.0 / rows
    bilinear = (  # the quad as the bilinear map Image.transform makes of it
        x0, (ne_x - x0) * across, (sw_x - x0) * down, (se_x - sw_x - ne_x + x0) * across * down,
        y0, (ne_y - y0) * across, (sw_y - y0) * down, (se_y - sw_y - ne_y + y0) * across * down,
    )  # fmt: skip
    box = (0, 0, n, rows)
    sampled = pillow_core.new("L", size)
    sampled.transform(box, floor.im, Image.Transform.QUAD, bilinear, NEAREST, NO_FILL)
    encoder = pillow_core.raw_encoder("L", "L")
    encoder.setimage(sampled, box)
    _, done, data = encoder.encode(n * rows)  # all of it at once
    encoder.cleanup()
    if not done:
        raise RuntimeError("Pillow's raw encoder stopped early")
    return bytes(data)


QuadSampler = Callable[[Image.Image, tuple[int, int], Quad], bytes]


def choose_sampler() -> QuadSampler:
    """The C-core path when this Pillow has it and it agrees with the public call, else public."""
    probe = Image.new("L", (9, 7))
    probe.putdata(range(63))
    quad: Quad = (-0.7, 0.2, 1.1, 6.6, 7.2, 6.9, 9.8, -0.4)  # partly off the probe, skewed
    try:
        if core_sample(probe, (5, 4), quad) == public_sample(probe, (5, 4), quad):
            return core_sample
    except Exception:  # another Pillow's private API: fall back to the public one
        pass
    return public_sample


sample_quad: QuadSampler = choose_sampler()
"""Sample ``floor`` over ``quad`` into ``size`` (sensors x rows) bytes, nearest pixel."""


LinePainter = Callable[[Sequence[tuple[float, float]], int, int], None]
"""Paint a polyline (pixel coordinates) in a grey level, so many pixels wide (no round joints)."""


def public_painter(image: Image.Image) -> LinePainter:
    draw = ImageDraw.Draw(image)

    def paint(points: Sequence[tuple[float, float]], value: int, width: int) -> None:
        draw.line(points, fill=value, width=width)

    return paint


def core_painter(image: Image.Image) -> LinePainter:
    """``ImageDraw.line``'s own C call (a private API), the grey level as its ink."""
    draw_lines: LinePainter = ImageDraw.Draw(image).draw.draw_lines
    return draw_lines


def choose_painter() -> Callable[[Image.Image], LinePainter]:
    """The C-core painter when this Pillow has it and it paints as the public one, else public."""
    lines = [((1.5, 1.2), (17.8, 9.6)), ((18.2, 2.1), (3.3, 16.7)), ((9.0, 0.4), (9.4, 0.6))]
    drawn = []
    for painter in (core_painter, public_painter):
        image = Image.new("L", (20, 18), 1)
        try:
            paint = painter(image)
            for value, width in ((2, 1), (3, 3), (4, 2), (0, 5)):
                for line in lines:
                    paint(line, value, width)
        except Exception:  # another Pillow's private API: fall back to the public one
            return public_painter
        drawn.append(image.tobytes())
    return core_painter if drawn[0] == drawn[1] else public_painter


line_painter: Callable[[Image.Image], LinePainter] = choose_painter()
"""A painter for this image (see the module's docstring)."""
