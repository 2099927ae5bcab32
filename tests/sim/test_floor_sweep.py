"""The colour sweep reads off the edge of the floor as white (what a sensor sees past a mat)."""

from __future__ import annotations

from rootlang.sim.sensors import FloorRaster
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
