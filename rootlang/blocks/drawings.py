"""The pictures on Level 1's blocks: small SVG drawings, made here (no borrowed art).

Each function returns an SVG document as text; :func:`data_uri` makes it an image Blockly can
show. The drawings are 40 x 40 units; strokes are dark on light shapes, so each reads on any
block colour.
"""

from __future__ import annotations

from urllib.parse import quote

__all__ = [
    "arrow",
    "bell",
    "bumper",
    "clock",
    "color_seen",
    "data_uri",
    "flag",
    "forever",
    "light",
    "number",
    "pen",
    "repeat",
    "swatch",
    "touch",
    "turn",
]

INK = "#1f2937"
PAPER = "#ffffff"
_INK = INK
_BODY = "#f3f4f6"
_LIT = "#facc15"


def _svg(inner: str) -> str:
    return (
        '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40" width="40" height="40">'
        f"{inner}</svg>"
    )


def data_uri(svg: str) -> str:
    """The drawing as a ``data:`` URI for a Blockly image field."""
    return "data:image/svg+xml;charset=utf-8," + quote(svg, safe="")


def number(count: int) -> str:
    """A number as a big button: dark digits on a white key (14:1), read by sight."""
    return _svg(
        f'<rect x="2" y="2" width="36" height="36" rx="8" fill="{PAPER}" stroke="{INK}"'
        ' stroke-width="2.5"/>'
        f'<text x="20" y="29" font-size="{24 if count < 10 else 20}" font-weight="bold"'
        f' font-family="sans-serif" text-anchor="middle" fill="{INK}">{count}</text>'
    )


def arrow(forward: bool) -> str:
    """A thick arrow up the block (forward) or down it (backward)."""
    points = "20,3 35,19 26,19 26,37 14,37 14,19 5,19"
    turn = "" if forward else ' transform="rotate(180 20 20)"'
    return _svg(f'<polygon points="{points}" fill="#ffffff" stroke="{_INK}" stroke-width="2.5"'
                f' stroke-linejoin="round"{turn}/>')  # fmt: skip


def turn(right: bool) -> str:
    """A quarter-circle arrow bending right (clockwise) or left, round a dot (the robot)."""
    path = (
        f'<circle cx="20" cy="28" r="4" fill="{_INK}"/>'
        '<path d="M8 30 A 13 13 0 0 1 24 10" fill="none" stroke="#ffffff" stroke-width="6"/>'
        f'<path d="M8 30 A 13 13 0 0 1 24 10" fill="none" stroke="{_INK}" stroke-width="2"/>'
        f'<polygon points="22,3 34,11 21,17" fill="#ffffff" stroke="{_INK}" stroke-width="2"'
        ' stroke-linejoin="round"/>'
    )
    flip = "" if right else ' transform="translate(40 0) scale(-1 1)"'
    return _svg(f"<g{flip}>{path}</g>")


def pen(down: bool) -> str:
    """A marker over a line: touching it and drawing (down), or lifted above it (up)."""
    lift = 0 if down else -9
    drawn = f'<path d="M3 36 H 20" stroke="{_INK}" stroke-width="3" stroke-linecap="round"/>'
    dashed = f'<path d="M3 36 H 37" stroke="{_INK}" stroke-width="2" stroke-dasharray="3 3"/>'
    line = drawn if down else dashed
    marker = (
        f'<g transform="translate(0 {lift})">'
        f'<polygon points="15,9 27,9 27,27 21,35 15,27" fill="#ffffff" stroke="{_INK}"'
        ' stroke-width="2.5" stroke-linejoin="round"/>'
        f'<rect x="15" y="3" width="12" height="7" fill="#2563eb" stroke="{_INK}"'
        ' stroke-width="2"/>'
        "</g>"
    )
    up = (
        ""
        if down
        else f'<path d="M33 22 V 8 M28 13 L33 8 L38 13" fill="none" stroke="{_INK}"'
        ' stroke-width="2.5" stroke-linecap="round"/>'
    )
    return _svg(line + marker + up)


def swatch(colour: str | None) -> str:
    """A round colour patch (None: the light off, a grey patch crossed out)."""
    if colour is None:
        return _svg(
            f'<circle cx="20" cy="20" r="15" fill="#9ca3af" stroke="{_INK}" stroke-width="2.5"/>'
            f'<path d="M9 9 L31 31" stroke="{_INK}" stroke-width="3"/>'
        )
    return _svg(f'<circle cx="20" cy="20" r="15" fill="{colour}" stroke="{_INK}"'
                ' stroke-width="2.5"/>')  # fmt: skip


def _robot(extra: str = "", ring: str = "#d1d5db") -> str:
    """The Root from above: a rounded body, its light ring, its nose to the top."""
    return (
        f'<rect x="7" y="6" width="26" height="29" rx="8" fill="{_BODY}" stroke="{_INK}"'
        ' stroke-width="2"/>'
        f'<circle cx="20" cy="21" r="7" fill="none" stroke="{ring}" stroke-width="4"/>'
        f"{extra}"
    )


def light() -> str:
    """The robot with its lights glowing."""
    rays = "".join(
        f'<path d="{d}" stroke="{_INK}" stroke-width="2" stroke-linecap="round"/>'
        for d in ("M20 1 V 4", "M2 21 H 5", "M35 21 H 38", "M5 6 L7 8", "M35 6 L33 8")
    )
    return _svg(_robot(rays, ring=_LIT))


def bell(colour: str, height: int) -> str:
    """A hand bell of one colour (each note its own); ``height`` 0-7 lifts a dot with the note."""
    return _svg(
        f'<path d="M10 30 Q 10 10 20 8 Q 30 10 30 30 Z" fill="{colour}" stroke="{_INK}"'
        ' stroke-width="2" stroke-linejoin="round"/>'
        f'<rect x="7" y="29" width="26" height="4" rx="2" fill="{colour}" stroke="{_INK}"'
        ' stroke-width="2"/>'
        f'<circle cx="20" cy="36" r="2.5" fill="{_INK}"/>'
        f'<rect x="18" y="3" width="4" height="5" fill="{_INK}"/>'
        f'<circle cx="36" cy="{33 - 4 * height}" r="2.5" fill="{_INK}"/>'
    )


def clock() -> str:
    """A clock face (waiting)."""
    return _svg(
        f'<circle cx="20" cy="20" r="16" fill="#ffffff" stroke="{_INK}" stroke-width="2.5"/>'
        f'<path d="M20 20 V 9 M20 20 L28 24" stroke="{_INK}" stroke-width="3"'
        ' stroke-linecap="round"/>'
    )


def _loop(mark: str) -> str:
    return _svg(
        '<path d="M30 12 A 13 13 0 1 0 33 24" fill="none" stroke="#ffffff" stroke-width="7"/>'
        f'<path d="M30 12 A 13 13 0 1 0 33 24" fill="none" stroke="{_INK}" stroke-width="2.5"/>'
        f'<polygon points="24,5 37,7 31,18" fill="#ffffff" stroke="{_INK}" stroke-width="2"'
        ' stroke-linejoin="round"/>' + mark
    )


def repeat() -> str:
    """A loop arrow (do again, a number of times)."""
    return _loop("")


def forever() -> str:
    """A loop arrow round an endless loop (∞)."""
    return _loop(
        f'<path d="M20 20 C 16 14 10 14 10 20 C 10 26 16 26 20 20 C 24 14 30 14 30 20'
        f' C 30 26 24 26 20 20 Z" fill="none" stroke="{_INK}" stroke-width="2"/>'
    )


def flag() -> str:
    """A green flag on its pole (start)."""
    return _svg(
        f'<path d="M9 37 V 4" stroke="{_INK}" stroke-width="3" stroke-linecap="round"/>'
        f'<path d="M10 5 Q 18 1 24 6 Q 30 10 35 6 V 22 Q 30 26 24 22 Q 18 17 10 21 Z"'
        f' fill="#22c55e" stroke="{_INK}" stroke-width="2" stroke-linejoin="round"/>'
    )


def bumper(sides: str) -> str:
    """The robot with its front bumper pressed on the ``left``, ``right`` or ``both`` sides
    (``any``: both halves, with a question mark for 'either')."""
    left = sides in ("left", "both", "any")
    right = sides in ("right", "both", "any")
    parts = [
        f'<path d="M6 14 Q 6 4 19 4" fill="none" stroke="{_LIT if left else "#9ca3af"}"'
        ' stroke-width="5" stroke-linecap="round"/>',
        f'<path d="M21 4 Q 34 4 34 14" fill="none" stroke="{_LIT if right else "#9ca3af"}"'
        ' stroke-width="5" stroke-linecap="round"/>',
    ]
    if sides == "any":
        parts.append(
            f'<text x="20" y="26" font-size="11" text-anchor="middle" fill="{_INK}">?</text>'
        )
    return _svg(_robot("".join(parts)))


_ZONES = {  # touch zone -> the corner of the robot's top it lights
    "front left": (8, 7),
    "front right": (21, 7),
    "back left": (8, 22),
    "back right": (21, 22),
}


def touch(zone: str) -> str:
    """The robot's top with one touch zone (or every one, ``any``) lit, under a finger dot."""
    zones = _ZONES if zone == "any" else {zone: _ZONES[zone]}
    lit = "".join(
        f'<rect x="{x}" y="{y}" width="11" height="12" rx="3" fill="{_LIT}"/>'
        for x, y in zones.values()
    )
    fingers = "".join(
        f'<circle cx="{x + 5.5}" cy="{y + 6}" r="3" fill="{_INK}"/>' for x, y in zones.values()
    )
    return _svg(
        f'<rect x="7" y="6" width="26" height="29" rx="8" fill="{_BODY}" stroke="{_INK}"'
        f' stroke-width="2"/>{lit}{fingers}'
    )


def nose() -> str:
    """The robot's top with its nose button (at the front) lit, under a finger dot."""
    return _svg(
        f'<rect x="7" y="6" width="26" height="29" rx="8" fill="{_BODY}" stroke="{_INK}"'
        f' stroke-width="2"/><circle cx="20" cy="13" r="5" fill="{_LIT}" stroke="{_INK}"'
        f' stroke-width="1.5"/><circle cx="20" cy="13" r="2.5" fill="{_INK}"/>'
    )


def color_seen(colour: str) -> str:
    """The robot seen from the side over a patch of ``colour``, its eye looking down at it."""
    return _svg(
        f'<rect x="2" y="29" width="36" height="9" rx="2" fill="{colour}" stroke="{_INK}"'
        ' stroke-width="2"/>'
        f'<rect x="8" y="8" width="24" height="14" rx="5" fill="{_BODY}" stroke="{_INK}"'
        ' stroke-width="2"/>'
        f'<circle cx="20" cy="22" r="3" fill="{_INK}"/>'
        f'<path d="M20 24 L14 29 M20 24 L26 29" stroke="{_INK}" stroke-width="1.5"/>'
    )
