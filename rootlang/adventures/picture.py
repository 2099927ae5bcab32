"""An adventure's goal as a picture a child can read without words: what the goal's robot does.

Drawn from the goal's :class:`~rootlang.adventures.hints.Summary` (so the picture and the
hints can't disagree): the floor as squares of one robot length, the robot where it starts
(grey, its nose up), its way (dashed where it only drives, thick ink where its marker draws),
a green ring where it ends; over it, a row of what else it does: the events it answers (the
Level 1 blocks' own pictures), the colours it lights, a bell for each note, a speech bubble for
each thing it says. Numbers are the only text.
"""

from __future__ import annotations

import re
from html import escape

from rootlang.adventures.hints import Summary
from rootlang.blocks import drawings
from rootlang.colors import NAMED_COLORS

ROBOT_LENGTH_MM = 150  # a square of the floor (docs/levels.md: one robot length)
SCALE = 0.5  # pixels a millimetre
ICON = 40
MOST_ICONS = 8


def goal_svg(goal: Summary, label: str) -> str:
    """The picture, as an SVG document; ``label`` is its text alternative (the goal's words)."""
    points = [(0, 0)] + [(step.x, step.y) for step in goal.track]
    left = min(x for x, _ in points) - ROBOT_LENGTH_MM
    right = max(x for x, _ in points) + ROBOT_LENGTH_MM
    bottom = min(y for _, y in points) - ROBOT_LENGTH_MM
    top = max(y for _, y in points) + ROBOT_LENGTH_MM
    icons = _icons(goal)
    band = ICON + 8 if icons else 0
    width = max((right - left) * SCALE, len(icons) * (ICON + 4) + 4)
    height = (top - bottom) * SCALE + band

    def at(x: float, y: float) -> str:  # the floor's y grows up, the picture's down
        return f"{(x - left) * SCALE:.1f},{(top - y) * SCALE + band:.1f}"

    parts = [f'<rect x="0" y="{band}" width="{width:.0f}" height="{height - band:.0f}"'
             ' fill="#ffffff" stroke="#9ca3af"/>']  # fmt: skip
    start = left + (-left) % ROBOT_LENGTH_MM
    for x in range(int(start), int(right) + 1, ROBOT_LENGTH_MM):
        parts.append(f'<path d="M{at(x, top)} L{at(x, bottom)}" stroke="#e5e7eb"/>')
    start = bottom + (-bottom) % ROBOT_LENGTH_MM
    for y in range(int(start), int(top) + 1, ROBOT_LENGTH_MM):
        parts.append(f'<path d="M{at(left, y)} L{at(right, y)}" stroke="#e5e7eb"/>')
    parts.append(_robot(at(0, 0), 90, "#9ca3af"))
    previous = (0, 0)
    for step in goal.track:
        if (step.x, step.y) != previous:
            look = ('stroke="#1f2937" stroke-width="6"' if step.drawing
                    else 'stroke="#2563eb" stroke-width="3" stroke-dasharray="8 6"')  # fmt: skip
            parts.append(f'<path d="M{at(*previous)} L{at(step.x, step.y)}" {look}'
                         ' stroke-linecap="round" fill="none"/>')  # fmt: skip
        previous = (step.x, step.y)
    if goal.track:
        end = goal.track[-1]
        parts.append(_robot(at(end.x, end.y), end.heading, "#16a34a"))
    for number, icon in enumerate(icons):
        parts.append(f'<g transform="translate({4 + number * (ICON + 4)},4)">{icon}</g>')
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {width:.0f} {height:.0f}"'
        f' width="{width:.0f}" height="{height:.0f}" role="img" aria-label="{escape(label)}">'
        f"<title>{escape(label)}</title>{''.join(parts)}</svg>"
    )


def _robot(where: str, heading: int, ring: str) -> str:
    """The robot from above at ``where``, its nose towards ``heading`` (90: up)."""
    return (
        f'<g transform="translate({where}) rotate({90 - heading})">'
        f'<circle r="16" fill="#f3f4f6" stroke="{ring}" stroke-width="4"/>'
        '<path d="M0 -13 L7 -2 L-7 -2 Z" fill="#1f2937"/></g>'
    )


def _icons(goal: Summary) -> list[str]:
    icons = [_inner(_event(event)) for event in goal.events]
    icons += [_inner(drawings.swatch(_hex(colour))) for colour in goal.lights]
    icons += [_inner(drawings.bell("#facc15", 3))] * min(goal.notes, MOST_ICONS)
    icons += [_bubble()] * min(len(goal.said), MOST_ICONS)
    return icons[: MOST_ICONS * 2]


def _event(event: str) -> str:
    bumped = re.fullmatch(r"when (?:bumped|bumper (left|right|both) pressed)", event)
    if bumped:
        return drawings.bumper(bumped.group(1) or "any")
    touched = re.fullmatch(r"when (?:touched|touch (front left|front right|back left|back right)"
                           r" pressed)", event)  # fmt: skip
    if touched:
        return drawings.touch(touched.group(1) or "any")
    seen = re.fullmatch(r"when colou?r (\w+) seen", event)
    if seen:
        return drawings.color_seen(_hex(seen.group(1)))
    return _envelope() if event.startswith("when message") else drawings.flag()


def _envelope() -> str:
    """A message: a closed envelope."""
    return (
        '<svg viewBox="0 0 40 40"><rect x="4" y="10" width="32" height="22" rx="2" fill="#ffffff"'
        ' stroke="#1f2937" stroke-width="2.5"/><path d="M4 11 L20 24 L36 11" fill="none"'
        ' stroke="#1f2937" stroke-width="2.5"/></svg>'
    )


def _bubble() -> str:
    return (
        '<path d="M4 6 H36 V26 H18 L10 34 V26 H4 Z" fill="#ffffff" stroke="#1f2937"'
        ' stroke-width="2.5" stroke-linejoin="round"/>'
        '<circle cx="13" cy="16" r="2" fill="#1f2937"/><circle cx="20" cy="16" r="2"'
        ' fill="#1f2937"/><circle cx="27" cy="16" r="2" fill="#1f2937"/>'
    )


def _inner(svg: str) -> str:
    """A 40 x 40 drawing's shapes, to place in the picture."""
    return re.sub(r"^<svg[^>]*>|</svg>$", "", svg)


def _hex(colour: str) -> str:
    named = NAMED_COLORS.get(colour)
    return named.hex if named is not None else "#9ca3af"
