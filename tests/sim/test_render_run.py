"""Pictures of real simulated runs: what the robot drew is where the picture shows it, in its
colour; the same run gives the same bytes; ``rootlang sim --svg/--png/--html`` write them."""

from __future__ import annotations

import io
import re
import xml.etree.ElementTree as ET
from functools import cache
from importlib import resources
from pathlib import Path

import pytest
from PIL import Image

from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.cli import main
from rootlang.sim.recording import Recording
from rootlang.sim.render import html_text, png_bytes, svg_text
from rootlang.sim.render.compose import scene_of, straighten, timed
from rootlang.sim.render.scene import Erase, Polyline
from rootlang.sim.world import World, default_world, parse_world

PROGRAMS = Path(__file__).parents[2] / "programs"
SVG = "{http://www.w3.org/2000/svg}"

SQUARE = """when started
    marker down
    repeat 4
        move 10 cm
        turn right 90 degrees
    marker up
    say "done"
"""

ERASE = """when started
    marker down
    move 20 cm
    marker up
    turn left 180 degrees
    eraser down
    move 10 cm
    eraser up
"""

RED_MARKER = parse_world('[robot]\nmodel = "RT1"\nx = 500\ny = 500\nmarker_color = "red"\n')


def run(source: str, world: World | None = None) -> Recording:
    world = world or default_world()
    checked = load_checked(source, "p.root", world.robot.model)
    return simulate(checked.program, world, source=source)[1]


@cache
def square() -> Recording:
    return run(SQUARE, RED_MARKER)


def test_the_svg_shows_the_square_in_the_markers_colour_with_y_up() -> None:
    root = ET.fromstring(svg_text(square()))
    ink = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "ink")
    (line,) = list(ink)
    assert line.get("stroke") == "#ff0000"
    corners = [tuple(map(float, p.split(","))) for p in (line.get("points") or "").split()]
    # starts at (500, 500) facing up, turns right: up, right, down, left (SVG y = -world y)
    assert corners == [(500, -500), (500, -600), (600, -600), (600, -500), (500, -500)]
    robot = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "robot")
    assert len(list(robot)) == 3  # body, light ring, heading arrow


def test_the_picture_is_byte_identical_for_the_same_run() -> None:
    again = run(SQUARE, RED_MARKER)
    assert svg_text(square()) == svg_text(again)
    assert png_bytes(square()) == png_bytes(again)
    assert html_text(square()) == html_text(again)


def test_the_png_has_the_marker_colour_on_the_stroke_and_floor_elsewhere() -> None:
    scene = scene_of(square())
    scale = 1.0
    image = Image.open(io.BytesIO(png_bytes(square(), scale=scale))).convert("RGB")
    assert image.size == (round(scene.view.width * scale), round(scene.view.height * scale))

    def pixel(x_mm: float, y_mm: float) -> tuple[int, int, int]:
        x = int((x_mm - scene.view.left) * scale)
        y = int((scene.view.top - y_mm) * scale)
        red, green, blue = image.getpixel((x, y))  # type: ignore[misc]
        return (red, green, blue)

    red, green, blue = pixel(600, 550)  # the right side of the square (the robot is not there)
    assert (red, green, blue) == (255, 0, 0)  # red ink, over the faint path
    assert pixel(585, 585) == (255, 255, 255)  # inside the square, clear of the robot: the floor


def test_eraser_sweeps_are_in_the_scene_after_the_ink_they_erase() -> None:
    scene = scene_of(run(ERASE))
    kinds = [type(item) for item in scene.ink]
    assert kinds == [Polyline, Erase]
    marker, eraser = scene.ink
    assert marker.times_s[0] < marker.times_s[-1] <= eraser.times_s[0]


def test_ink_times_follow_the_tool_along_the_line() -> None:
    tips = [(0.0, 0.0), (0.0, 0.0), (50.0, 0.0), (100.0, 0.0)]
    times = timed([(0.0, 0.0), (100.0, 0.0)], tips, [0.0, 1.0, 2.0, 3.0])
    assert times == (0.0, 3.0)  # the end when the tool got there; the start when it began
    assert timed([(0.0, 0.0), (50.0, 0.0), (100.0, 0.0)], tips, [0.0, 1.0, 2.0, 3.0])[1] == 2.0


def test_a_create3_is_drawn_as_a_342_mm_disc() -> None:
    world = default_world().with_model(default_world().robot.model.from_name("Create3"))
    root = ET.fromstring(svg_text(run("when started\n    move 10 cm\n", world)))
    robot = next(g for g in root.iter(f"{SVG}g") if g.get("id") == "robot")
    body = robot[0]
    assert body.tag == f"{SVG}circle" and body.get("r") == "171"


def test_the_html_replay_is_self_contained() -> None:
    page = html_text(square())
    assert not re.search(r"""(src|href)\s*=|https?://(?!www\.w3\.org/2000/svg)|@import""", page)
    assert '"#ff0000"' in page and "done" in page


@pytest.mark.parametrize("kind", ["svg", "png", "html"])
def test_rootlang_sim_writes_each_picture(tmp_path: Path, kind: str) -> None:
    target = tmp_path / f"square.{kind}"
    assert main(["sim", str(PROGRAMS / "square.root"), f"--{kind}", str(target)]) == 0
    data = target.read_bytes()
    if kind == "png":
        assert Image.open(io.BytesIO(data)).format == "PNG"
    elif kind == "svg":
        assert ET.fromstring(data).tag == f"{SVG}svg"
    else:
        assert data.startswith(b"<!DOCTYPE html>")


def test_straighten_keeps_only_the_corners() -> None:
    line = [(0.0, 0.0), (10.0, 0.0), (20.0, 0.3), (30.0, 0.0), (30.0, 10.0), (30.0, 20.0)]
    assert straighten(line, 1.0) == [(0.0, 0.0), (30.0, 0.0), (30.0, 20.0)]
    assert straighten(line, 0.1) == [
        (0.0, 0.0),
        (10.0, 0.0),
        (20.0, 0.3),
        (30.0, 0.0),
        (30.0, 20.0),
    ]
    assert straighten([(1.0, 1.0)], 1.0) == [(1.0, 1.0)]


def test_text_from_the_run_cannot_break_the_replay_page() -> None:
    world = parse_world('name = "__DATA__ </script> & <b>"\n')
    page = html_text(run('when started\n    say "</script>"\n    say "__TITLE__"\n', world))
    template = resources.files("rootlang.sim.render").joinpath("replay.html").read_text("utf-8")
    assert page.count("</script>") == template.count("</script>")  # the template's own only
    assert "<title>__DATA__ &lt;/script> &amp; &lt;b>: Root RT1</title>" in page
    assert '"__TITLE__"' in page  # what it said, as it said it
