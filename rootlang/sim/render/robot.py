"""The robot as drawn from above, in its own frame: forward is +x, left is +y, the marker (the
centre of rotation) at the origin. :func:`~rootlang.sim.render.scene.place` puts it at a pose."""

from __future__ import annotations

from rootlang.robots import RobotModel
from rootlang.sim.models import spec_for
from rootlang.sim.render.scene import Circle, Paint, Polygon, Shape, rounded_rectangle

BODY = Paint(fill="#f5f5f4", stroke="#3f3f46", width_mm=3.0, opacity=0.6)  # ink shows through
ARROW = Paint(fill="#3f3f46")
LED_OFF = "#a1a1aa"


def _arrow(length: float) -> tuple[tuple[float, float], ...]:
    """A heading arrow from the centre to ``length`` ahead."""
    shaft, head = length * 0.08, length * 0.22
    neck = length * 0.6
    return (
        (0.0, -shaft),
        (neck, -shaft),
        (neck, -head),
        (length, 0.0),
        (neck, head),
        (neck, shaft),
        (0.0, shaft),
    )


def robot_shapes(model: RobotModel) -> tuple[tuple[Shape, ...], int]:
    """The robot's outline, its light ring and its heading arrow; also the index of the light ring
    among them (the replay colours it with the LEDs)."""
    spec = spec_for(model)
    size = min(spec.length, spec.width)  # the ring and the arrow scale with the body
    if spec.round_body:
        body: Shape = Circle((0.0, 0.0), spec.length / 2, BODY)
    else:
        body = Polygon(rounded_rectangle(spec.length, spec.width, size * 0.28), BODY)
    ring = Circle((0.0, 0.0), size * 0.18, Paint(stroke=LED_OFF, width_mm=size * 0.05))
    arrow = Polygon(_arrow(spec.length * 0.44), ARROW)
    return (body, ring, arrow), 1
