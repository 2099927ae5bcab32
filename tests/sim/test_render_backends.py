"""The SVG and PNG back ends draw a scene faithfully: colours where the shapes are, y up, ink
erased only where the eraser went and only ink drawn before it."""

from __future__ import annotations

import io
import xml.etree.ElementTree as ET

from PIL import Image

from rootlang.sim.render.png import to_png
from rootlang.sim.render.scene import (
    Box,
    Circle,
    Erase,
    Label,
    Paint,
    Polygon,
    Polyline,
    Scene,
    dashes,
    nice_length,
    rounded_rectangle,
)
from rootlang.sim.render.svg import number, to_svg

SVG = "{http://www.w3.org/2000/svg}"
MAT = Polygon(((0, 0), (200, 0), (200, 100), (0, 100)), Paint(fill="#00ff00"))


def _scene() -> Scene:
    """A 200 × 200 mm view: a green mat on the lower half, a red line along y = 50 partly erased,
    then a blue line drawn across the erased part afterwards, and a label."""
    return Scene(
        view=Box(0, 0, 200, 200),
        background="#ffffff",
        below=(MAT,),
        ink=(
            Polyline(((20, 50), (180, 50)), Paint(stroke="#ff0000", width_mm=8)),
            Erase(((90, 20), (90, 80)), width_mm=30),
            Polyline(((100, 30), (100, 70)), Paint(stroke="#0000ff", width_mm=8)),
        ),
        robot=(Circle((100, 150), 20, Paint(fill="#000000")),),
        overlay=(Label((10, 190), "10 cm", 8, "#000000"),),
    )


def _pixel(png: bytes, x_mm: float, y_mm: float, px_per_mm: float = 1.0) -> tuple[int, ...]:
    image = Image.open(io.BytesIO(png))
    pixel = image.getpixel((int(x_mm * px_per_mm), int((200 - y_mm) * px_per_mm)))
    assert isinstance(pixel, tuple)
    return pixel


def test_png_has_the_scene_size_and_colours_with_y_up() -> None:
    png = to_png(_scene(), px_per_mm=1.0)
    assert Image.open(io.BytesIO(png)).size == (200, 200)
    assert _pixel(png, 40, 50) == (255, 0, 0)  # red ink, not erased
    assert _pixel(png, 40, 90) == (0, 255, 0)  # the mat is low (y up)
    assert _pixel(png, 40, 150) == (255, 255, 255)
    assert _pixel(png, 100, 150) == (0, 0, 0)  # the robot is high


def test_the_eraser_clears_earlier_ink_but_not_the_mat_or_later_ink() -> None:
    png = to_png(_scene(), px_per_mm=1.0)
    assert _pixel(png, 85, 50) == (0, 255, 0)  # red erased: the mat shows
    assert _pixel(png, 100, 50) == (0, 0, 255)  # blue came after the eraser


def test_png_is_deterministic() -> None:
    assert to_png(_scene()) == to_png(_scene())


def test_svg_is_well_formed_and_flips_y() -> None:
    root = ET.fromstring(to_svg(_scene(), px_per_mm=1.0))
    assert root.get("viewBox") == "0 -200 200 200"
    assert (root.get("width"), root.get("height")) == ("200", "200")
    red, blue = (
        p for p in root.iter(f"{SVG}polyline") if p.get("stroke") in ("#ff0000", "#0000ff")
    )
    assert red.get("points") == "20,-50 180,-50"
    assert blue.get("stroke") == "#0000ff"
    text = next(root.iter(f"{SVG}text"))
    assert text.text == "10 cm" and text.get("y") == "-190"


def test_svg_masks_only_the_ink_drawn_before_the_eraser() -> None:
    root = ET.fromstring(to_svg(_scene()))
    mask = next(root.iter(f"{SVG}mask"))
    assert mask.get("id") == "erased1"
    ink = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "ink")
    masked, after = list(ink)
    assert masked.get("mask") == "url(#erased1)"
    assert [p.get("stroke") for p in masked] == ["#ff0000"]
    assert after.get("stroke") == "#0000ff"


def test_svg_is_deterministic_and_quantised() -> None:
    assert to_svg(_scene()) == to_svg(_scene())
    assert number(1.04) == "1" and number(-0.04) == "0" and number(12.25) == "12.2"
    assert number(-3.5) == "-3.5" and number(100.0) == "100"


def test_dashes_cover_the_line_with_gaps() -> None:
    pieces = dashes([(0, 0), (10, 0), (10, 10)], dash_mm=4, gap_mm=2)
    expected = [((0, 0), (4, 0)), ((6, 0), (10, 0)), ((10, 2), (10, 6)), ((10, 8), (10, 10))]
    assert [*pieces[:3], pieces[-1]] == expected


def test_rounded_rectangle_stays_inside_its_box() -> None:
    points = rounded_rectangle(149, 134, 38)
    assert max(x for x, _ in points) == 74.5 and min(y for _, y in points) == -67.0
    assert all(abs(x) <= 74.5 + 1e-9 and abs(y) <= 67 + 1e-9 for x, y in points)


def test_nice_length_picks_round_numbers() -> None:
    assert [nice_length(v) for v in (480, 1999, 20, 7)] == [200.0, 1000.0, 20.0, 5.0]
