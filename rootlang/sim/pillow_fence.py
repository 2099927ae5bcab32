"""The one place that touches Pillow's private C core (``PIL._imaging``): the colour sweep.

The colour sensors sample the floor with Pillow's QUAD transform. Asked through the public
``Image.transform(...).tobytes()`` the Python wrapper costs about four times the sampling itself,
so :func:`sample_quad` asks the C core directly, but only once a probe at import has read exactly
what the public call reads; on any other Pillow it falls back to the public call (same output,
slower). ``tests/sim/test_floor_sweep.py`` checks both agree, and fails loudly if this Pillow
no longer takes the fast path, so a Pillow upgrade cannot slow the simulator down unnoticed.
"""

from __future__ import annotations

from collections.abc import Callable

from PIL import Image
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
