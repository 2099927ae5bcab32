"""The colour sweep reads off the edge of the floor as white (what a sensor sees past a mat), and
reads what Pillow's public QUAD transform reads."""

from __future__ import annotations

import random

import PIL
import pytest
from PIL import Image

from rootlang.protocol.fields import COLOR_SENSORS
from rootlang.sim import pillow_fence
from rootlang.sim.sensors import FloorRaster, Point
from rootlang.sim.world import parse_world

BLACK_FLOOR = """
[floor]
width = 500
height = 500
color = "black"
"""


def test_off_the_floor_reads_white_and_on_it_the_floor_colour() -> None:
    raster = FloorRaster(parse_world(BLACK_FLOOR, "black.toml"))
    off = raster.sweep(((-300, -300), (-200, -300)), ((-300, -310), (-200, -310)), 3)
    on = raster.sweep(((100, 100), (200, 100)), ((100, 110), (200, 110)), 2)
    edge = raster.sweep(((-50, 100), (50, 100)), ((-50, 110), (50, 110)), 1)
    assert off == bytes(32 * 3)  # 0: white
    assert on == bytes([1] * 32 * 2)  # 1: black
    assert edge[:15] == bytes(15) and edge[-15:] == bytes([1] * 15)


MAT = """
[floor]
width = 600
height = 400
[[mat]]
shape = "circle"
x = 300
y = 200
radius = 120
color = "red"
[[mat]]
shape = "line"
points = [[0, 50], [600, 350]]
width = 3
color = "black"
"""


def test_the_sweep_samples_as_pillows_own_quad_transform_does() -> None:
    # the sweep calls Pillow's C core directly (fast): it must read exactly what the public
    # Image.transform reads for the same quad, on and off the floor, for any number of rows
    raster = FloorRaster(parse_world(MAT, "mat.toml"))
    raster.paint((20, 380), (580, 20), 2, 4)  # a thin blue marker line
    rng = random.Random(7)
    for _ in range(500):
        left = (rng.uniform(-100, 700), rng.uniform(-100, 500))
        before = (left, (left[0] + rng.uniform(-80, 80), left[1] + 60))
        (x0, y0), (x1, y1) = before
        dx, dy = rng.uniform(-130, 130), rng.uniform(-130, 130)
        after = ((x0 + dx, y0 + dy), (x1 + dx + rng.uniform(-9, 9), y1 + dy + rng.uniform(-9, 9)))
        rows = rng.randint(1, 64)
        assert raster.sweep(before, after, rows) == _public_sweep(raster, before, after, rows)


def _public_sweep(
    raster: FloorRaster, before: tuple[Point, Point], after: tuple[Point, Point], rows: int
) -> bytes:
    """The sweep through Pillow's public API: the quad's corners as the sweep makes them."""
    (bl, br), (al, ar) = before, after
    n = COLOR_SENSORS
    gap = ((br[0] - bl[0]) / (2 * (n - 1)), (br[1] - bl[1]) / (2 * (n - 1)))
    move_left = ((al[0] - bl[0]) / (2 * rows), (al[1] - bl[1]) / (2 * rows))
    move_right = ((ar[0] - br[0]) / (2 * rows), (ar[1] - br[1]) / (2 * rows))
    s = raster.scale
    quad: list[float] = []
    for (x, y), side, move in ((bl, -1, move_left), (al, -1, move_left), (ar, 1, move_right),
                               (br, 1, move_right)):  # fmt: skip
        quad += [(x + side * gap[0] + move[0]) * s, (y + side * gap[1] + move[1]) * s]
    sampled = raster.floor.transform(
        (n, rows), Image.Transform.QUAD, quad, Image.Resampling.NEAREST
    )
    return sampled.tobytes()


def test_the_private_fast_path_is_used_only_when_it_reads_as_the_public_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def broken(*_: object) -> bytes:
        raise AttributeError("no such method in this Pillow")

    monkeypatch.setattr(pillow_fence, "core_sample", broken)
    assert pillow_fence.choose_sampler() is pillow_fence.public_sample

    monkeypatch.setattr(pillow_fence, "core_sample", lambda *_: b"\x00" * 20)
    assert pillow_fence.choose_sampler() is pillow_fence.public_sample


def test_this_pillow_takes_the_fast_path() -> None:
    # fails loudly when a Pillow upgrade changes its private C core: the sweep would still read
    # right (the public fallback) but the simulator would be several times slower
    assert pillow_fence.sample_quad is pillow_fence.core_sample, (
        f"Pillow {PIL.__version__}: the fast colour sweep no longer works; see pillow_fence.py"
    )


def test_the_marker_paints_through_the_c_core_as_imagedraw_does() -> None:
    painted = []
    for painter in (pillow_fence.core_painter, pillow_fence.public_painter):
        image = Image.new("L", (120, 90), 0)
        paint = painter(image)
        draw = random.Random(7)  # (the same lines for both)
        for _ in range(300):
            start = (draw.uniform(-10, 130), draw.uniform(-10, 100))
            end = (start[0] + draw.uniform(-9, 9), start[1] + draw.uniform(-9, 9))
            paint((start, end), draw.randint(1, 4), draw.randint(1, 4))
        painted.append(image.tobytes())
    assert painted[0] == painted[1]
    assert len(set(painted[0])) == 5  # (the lines did land: four inks and the floor)


def test_the_private_painter_is_used_only_when_it_paints_as_the_public_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    def missing(image: Image.Image) -> pillow_fence.LinePainter:
        raise AttributeError("no such method in this Pillow")

    monkeypatch.setattr(pillow_fence, "core_painter", missing)
    assert pillow_fence.choose_painter() is pillow_fence.public_painter

    def nothing(points: object, value: int, width: int) -> None:
        pass

    monkeypatch.setattr(pillow_fence, "core_painter", lambda image: nothing)
    assert pillow_fence.choose_painter() is pillow_fence.public_painter


def test_this_pillow_paints_through_the_fast_path() -> None:
    assert pillow_fence.line_painter is pillow_fence.core_painter, (
        f"Pillow {PIL.__version__}: the marker's fast painting no longer works; see pillow_fence.py"
    )
