"""Colours: the one small value type shared by the parser, the checks and the runtime."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Color:
    """An RGB colour (each channel 0–255); ``name`` is the word it was written as, if any."""

    red: int
    green: int
    blue: int
    name: str | None = None

    @property
    def rgb(self) -> tuple[int, int, int]:
        return (self.red, self.green, self.blue)

    @property
    def hex(self) -> str:
        return hex_rgb(self.rgb)

    def same_as(self, other: Color) -> bool:
        """Colours are equal by their channels, whatever they were called."""
        return self.rgb == other.rgb

    def __str__(self) -> str:
        if self.name:
            return self.name
        return f"rgb {self.red} {self.green} {self.blue}"

    @classmethod
    def from_hex(cls, text: str) -> Color:
        """``#ff8000`` (with or without the ``#``)."""
        digits = text.lstrip("#")
        return cls(int(digits[0:2], 16), int(digits[2:4], 16), int(digits[4:6], 16))


def hex_rgb(rgb: tuple[int, int, int]) -> str:
    """``#ff8000``, as pictures and recordings write a colour (``Color.from_hex`` reads it)."""
    return "#{:02x}{:02x}{:02x}".format(*rgb)


NAMED_COLORS: dict[str, Color] = {
    name: Color(r, g, b, name)
    for name, (r, g, b) in {
        "red": (255, 0, 0),
        "orange": (255, 128, 0),
        "yellow": (255, 255, 0),
        "green": (0, 255, 0),
        "cyan": (0, 255, 255),
        "blue": (0, 0, 255),
        "purple": (128, 0, 255),
        "pink": (255, 105, 180),
        "white": (255, 255, 255),
        "black": (0, 0, 0),
    }.items()
}


LIGHT_COLORS: tuple[str, ...] = tuple(name for name in NAMED_COLORS if name != "black")
"""The named colours a light shows (black is a light that is off)."""


def color_name(rgb: tuple[int, int, int]) -> str:
    """A colour as people say it: its name when it has one (``green``), else ``#00ff80``."""
    return next((name for name, c in NAMED_COLORS.items() if c.rgb == rgb), hex_rgb(rgb))


# The colours Root's colour sensor can tell apart, in the order of the protocol's nibbles 0–4.
SENSOR_COLORS: tuple[str, ...] = ("white", "black", "red", "green", "blue")


def can_be_seen(color: Color) -> bool:
    """True for a colour the colour sensor can report."""
    return any(color.same_as(NAMED_COLORS[name]) for name in SENSOR_COLORS)
