"""How long the pictures of a run take, and how big they are: SVG, PNG and the HTML replay.

Run: ``.venv/bin/python benchmarks/render.py``. Simulates a long drawing (a marker-down walk of
about 10 simulated minutes, many corners) and the gallery's flower, then renders each picture
(best of three) and prints milliseconds and kilobytes. The simulation itself is not timed.
"""

from __future__ import annotations

import time
from collections.abc import Callable
from pathlib import Path

from rootlang.app.session import simulate
from rootlang.checks import load_checked
from rootlang.sim.recording import Recording
from rootlang.sim.render import html_text, png_bytes, svg_text
from rootlang.sim.world import parse_world

PROGRAMS = Path(__file__).resolve().parents[1] / "programs"
LONG_WALK = """when started
    marker down
    repeat 150
        move 15 cm
        turn left 97 degrees
        arc left 30 degrees radius 4 cm
"""
BIG_FLOOR = parse_world(
    "time_limit = 700\n[floor]\nwidth = 3000\nheight = 3000\n[robot]\nx = 1500\ny = 1500\n"
)


def record(source: str, world_text: str | None = None) -> Recording:
    world = BIG_FLOOR if world_text is None else parse_world(world_text)
    checked = load_checked(source, "bench.root", world.robot.model)
    return simulate(checked.program, world, source=source)[1]


def best_ms(make: Callable[[Recording], str | bytes], recording: Recording) -> tuple[float, int]:
    """The best of three times (ms) for ``make(recording)``, and its size in bytes."""
    times, size = [], 0
    for _ in range(3):
        started = time.perf_counter()
        out = make(recording)
        times.append((time.perf_counter() - started) * 1000)
        size = len(out.encode("utf-8") if isinstance(out, str) else out)
    return min(times), size


def main() -> None:
    runs = {
        "long walk": record(LONG_WALK),
        "flower": record((PROGRAMS / "flower.root").read_text(encoding="utf-8"), ""),
    }
    for name, recording in runs.items():
        points = sum(len(s.points) for s in recording.strokes)
        print(
            f"{name}: {recording.duration_ms / 1000:.0f} s simulated, "
            f"{len(recording.frames)} frames, {points} stroke points"
        )
        makers: dict[str, Callable[[Recording], str | bytes]] = {
            "svg": svg_text, "png": png_bytes, "html": html_text,
        }  # fmt: skip
        for kind, make in makers.items():
            ms, size = best_ms(make, recording)
            print(f"  {kind:4}  {ms:7.1f} ms  {size / 1024:7.1f} kB")


if __name__ == "__main__":
    main()
