"""Level 1: picture blocks a child who can't read yet can use, each exactly one rootlang line.

A picture block is a line of the language with a picture: ``move forward {n} cm`` is an up
arrow and a number of robot lengths; ``light red`` a bulb and a red swatch. Nothing here says
what a line means: each is read with the language's own parser into the word block
(:mod:`rootlang.blocks.text_to_blocks`, from :mod:`rootlang.forms`) it stands for, so a
Level 1 workspace is a Level 2 one with some blocks drawn differently:

- :func:`to_words` — Level 1 -> Level 2: each picture block becomes its word block (the text
  follows as for any workspace, :func:`rootlang.blocks.to_text`);
- :func:`to_pictures` — Level 2 -> Level 1: each word block that is a picture block's line
  becomes that picture block (same id, comments and blank lines kept); the others stay, and
  are listed: they are what keeps a program above Level 1;
- :func:`picture_definitions`, :func:`picture_toolbox`, :func:`picture_meanings` — the blocks,
  the toolbox and what each block says aloud, for the studio.

The mapping, for teachers: docs/levels.md.
"""

from __future__ import annotations

import copy
import functools
import json
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from importlib import resources
from typing import Any

from rootlang.blocks import drawings
from rootlang.blocks.names import FORMS_BY_BLOCK, JSON
from rootlang.colors import NAMED_COLORS, SENSOR_COLORS
from rootlang.forms import Category

__all__ = [
    "LEVELS",
    "PICTURES",
    "ROBOT_LENGTH_CM",
    "Picture",
    "block_colour",
    "contrast",
    "picture_definitions",
    "picture_meanings",
    "picture_toolbox",
    "to_pictures",
    "to_words",
]

LEVELS = (1, 2, 3)
"""Level 1 picture blocks, Level 2 word blocks, Level 3 text: three views of one program."""

ROBOT_LENGTH_CM = 15
"""A forward or backward step of Level 1: one robot length (a Root is 149 mm long)."""

AMOUNT = "N"  # the field of a picture block's number (its buttons: 1 to MOST)
PICK = "PICK"  # the field of a picture block's picture menu (which colour, note, side ...)
MOST = 10


@dataclass(frozen=True)
class Variant:
    """One line a picture block stands for: its ``value`` in the block's picture menu, the
    line (``{n}`` the number shown, ``{amount}`` that times the step) and its picture."""

    value: str
    line: str
    picture: str


@dataclass(frozen=True)
class Picture:
    """A Level 1 block: its type, its picture, the lines it can be (one per picture in its
    menu), whether it has a number (1 to 10; ``step``: what one counts in the line), and the
    line for 1 when it differs (``wait 1 second``)."""

    block: str
    picture: str
    variants: tuple[Variant, ...]
    step: float = 0
    one: str = ""

    @property
    def counted(self) -> bool:
        return self.step > 0

    def line(self, value: str, count: int) -> str:
        """The rootlang line for a choice in the menu and a number."""
        variant = next(v for v in self.variants if v.value == value)
        if count == 1 and self.one:
            return self.one
        amount = count * self.step
        return variant.line.format(n=count, amount=int(amount) if amount == int(amount) else amount)

    def choices(self) -> Iterator[tuple[str, int]]:
        for variant in self.variants:
            for count in range(1, MOST + 1) if self.counted else (0,):
                yield variant.value, count


def _one(block: str, picture: str, line: str, step: float = 0, one: str = "") -> Picture:
    return Picture(block, picture, (Variant("", line, ""),), step, one)


_NOTES = (  # a bell colour for each note, as in classroom hand bells (C red ... B pink)
    ("C4", "#ef4444"), ("D4", "#f97316"), ("E4", "#facc15"), ("F4", "#22c55e"),
    ("G4", "#14b8a6"), ("A4", "#6366f1"), ("B4", "#d946ef"), ("C5", "#ef4444"),
)  # fmt: skip
_LIGHT_COLOURS = tuple(name for name in NAMED_COLORS if name != "black")  # black: off
_SEEN_COLOURS = tuple(name for name in SENSOR_COLORS if name != "white")


PICTURES: tuple[Picture, ...] = (
    Picture("pic_when_started", drawings.flag(), (Variant("", "when started", ""),)),
    Picture("pic_when_bumper", "", tuple(
        Variant(side, line, drawings.bumper(side))
        for side, line in (("any", "when bumped"), ("left", "when bumper left pressed"),
                           ("right", "when bumper right pressed"),
                           ("both", "when bumper both pressed"))
    )),
    Picture("pic_when_touch", "", tuple(
        Variant(zone, "when touched" if zone == "any" else f"when touch {zone} pressed",
                drawings.touch(zone))
        for zone in ("any", "front left", "front right", "back left", "back right")
    )),
    Picture("pic_when_color", "", tuple(
        Variant(name, f"when color {name} seen", drawings.color_seen(NAMED_COLORS[name].hex))
        for name in _SEEN_COLOURS
    )),
    _one("pic_forward", drawings.arrow(forward=True), "move forward {amount} cm", ROBOT_LENGTH_CM),
    _one("pic_backward", drawings.arrow(forward=False), "move backward {amount} cm",
         ROBOT_LENGTH_CM),
    _one("pic_turn_right", drawings.turn(right=True), "turn right 90 degrees"),
    _one("pic_turn_left", drawings.turn(right=False), "turn left 90 degrees"),
    _one("pic_pen_down", drawings.pen(down=True), "marker down"),
    _one("pic_pen_up", drawings.pen(down=False), "marker up"),
    Picture("pic_light", drawings.light(), (
        *(Variant(name, f"light {name}", drawings.swatch(NAMED_COLORS[name].hex))
          for name in _LIGHT_COLOURS),
        Variant("off", "light off", drawings.swatch(None)),
    )),
    Picture("pic_note", "", tuple(
        Variant(note, f"play note {note} for 0.5 seconds", drawings.bell(colour, height))
        for height, (note, colour) in enumerate(_NOTES)
    )),
    _one("pic_wait", drawings.clock(), "wait {n} seconds", 1, one="wait 1 second"),
    _one("pic_repeat", drawings.repeat(), "repeat {n}", 1),
    _one("pic_forever", drawings.forever(), "repeat forever"),
)  # fmt: skip
"""Every Level 1 block, in the toolbox's order."""

_BY_BLOCK = {picture.block: picture for picture in PICTURES}


# ---- each picture block's word block (from the language's own parser) ----------------------


def _word_block(line: str) -> JSON:
    """The word block of ``line``, as the language's parser reads it: in a script (an event
    line heads one), with a body under it when it takes one."""
    from rootlang.blocks.text_to_blocks import to_workspace
    from rootlang.diagnostics import RootlangError

    body = "    wait 1 second\n"
    if line.startswith("when "):
        return dict(to_workspace(f"{line}\n{body}")["blocks"]["blocks"][0])
    try:
        script = to_workspace(f"when started\n    {line}\n")
    except RootlangError:  # a loop: its body under it
        script = to_workspace(f"when started\n    {line}\n    {body}")
    return dict(script["blocks"]["blocks"][0]["inputs"]["BODY"]["block"])


def _strip(block: JSON, bodies: tuple[str, ...]) -> JSON:
    """The block as its line writes it: no ids, place, next block or blocks in its body."""
    kept = {key: value for key, value in block.items() if key in ("type", "fields", "inputs")}
    if "inputs" in kept:
        inputs = {name: value for name, value in kept["inputs"].items() if name not in bodies}
        kept["inputs"] = inputs
        if not inputs:
            del kept["inputs"]
    stripped: JSON = json.loads(json.dumps(kept, sort_keys=True), object_hook=_no_ids)
    return stripped


def _no_ids(item: dict[str, Any]) -> dict[str, Any]:
    return {key: value for key, value in item.items() if key != "id"}


def _bodies(block_type: str) -> tuple[str, ...]:
    from rootlang.blocks.names import field_name
    from rootlang.forms import EVENT_FORMS, Body

    form = FORMS_BY_BLOCK[block_type]
    own = tuple(field_name(part.field) for part in form.parts if isinstance(part, Body))
    return (*own, "BODY") if form in EVENT_FORMS else own


@dataclass(frozen=True)
class _Table:
    word_blocks: dict[tuple[str, str, int], JSON]  # (picture block, menu value, count) -> block
    pictures: dict[str, tuple[str, str, int]]  # a word block's key -> its picture block
    bodies: dict[str, tuple[str, ...]]  # word block type -> its body inputs


@functools.cache
def _table() -> _Table:
    word_blocks: dict[tuple[str, str, int], JSON] = {}
    pictures: dict[str, tuple[str, str, int]] = {}
    bodies: dict[str, tuple[str, ...]] = {}
    for picture in PICTURES:
        for value, count in picture.choices():
            block = _word_block(picture.line(value, count))
            bodies[block["type"]] = _bodies(block["type"])
            stripped = _strip(block, bodies[block["type"]])
            word_blocks[picture.block, value, count] = stripped
            pictures.setdefault(json.dumps(stripped, sort_keys=True), (picture.block, value, count))
    return _Table(word_blocks, pictures, bodies)


# ---- Level 1 <-> Level 2 ---------------------------------------------------------------------


def _each_block(workspace: JSON, change: Callable[[JSON, bool], JSON]) -> JSON:
    """The workspace with ``change`` made to each of its blocks, from the inside out
    (``change`` gets a block whose body, next and values are already changed, and whether the
    block is a line of its own: a statement or an event, not a value). Without recursion: a
    script of 2,000 statements is 2,000 levels of ``next`` (docs/runtime.md, "Depth")."""
    made = copy.copy(workspace)
    if not (
        isinstance(workspace.get("blocks"), dict)
        and isinstance(workspace["blocks"].get("blocks", []), list)
    ):
        return made
    made["blocks"] = dict(workspace["blocks"])
    tops: list[Any] = list(workspace["blocks"].get("blocks", []))
    made["blocks"]["blocks"] = tops
    # each block copied on the way in (its connections copied too, to hold the changed
    # children), then changed on the way out, children before their parents
    waiting: list[tuple[Any, bool, Any, Any]] = [(b, True, tops, i) for i, b in enumerate(tops)]
    seen: list[tuple[JSON, bool, Any, Any]] = []
    while waiting:
        block, line, holder, key = waiting.pop()
        if not isinstance(block, dict):  # (not a block: the text direction says so)
            continue
        block = holder[key] = dict(block)
        seen.append((block, line, holder, key))
        inputs = block.get("inputs")
        if isinstance(inputs, dict) and all(isinstance(c, dict) for c in inputs.values()):
            bodies = _table().bodies.get(_type(block), ())
            block["inputs"] = {name: dict(connection) for name, connection in inputs.items()}
            for name, connection in block["inputs"].items():
                body = name in bodies or bool(_BODY_INPUT.match(name))
                for kind in ("block", "shadow"):
                    if kind in connection:
                        waiting.append((connection[kind], body, connection, kind))
        if isinstance(block.get("next"), dict):
            block["next"] = dict(block["next"])
            for kind in block["next"]:
                waiting.append((block["next"][kind], True, block["next"], kind))
    for block, line, holder, key in reversed(seen):
        holder[key] = change(block, line)
    return made


_BODY_INPUT = re.compile(r"^(BODY|DO\d+|ELSE)$")  # statement inputs of blocks not drawn here


def _type(block: JSON) -> str:
    kind = block.get("type")
    return kind if isinstance(kind, str) else ""


_OWN_KEYS = ("type", "fields", "inputs")  # what a block's picture or words change; the rest stays


def to_words(workspace: JSON) -> JSON:
    """Level 1 -> Level 2: every picture block as its word block (the rest as it is). A
    picture block whose menu or number is not one of its own is left, for the text direction
    to name (E70x)."""
    table = _table()

    def change(block: JSON, line: bool) -> JSON:
        picture = _BY_BLOCK.get(_type(block))
        if picture is None:
            return block
        fields = block.get("fields")
        fields = fields if isinstance(fields, dict) else {}
        value = str(fields.get(PICK, ""))
        count = str(fields.get(AMOUNT, "")) if picture.counted else "0"
        words = table.word_blocks.get((picture.block, value, int(count) if count.isdigit() else -1))
        if words is None:
            return block
        made = copy.deepcopy(words)
        made.update((key, value) for key, value in block.items() if key not in _OWN_KEYS)
        inputs = block.get("inputs")
        own = table.bodies[words["type"]]
        bodies = {name: connection for name, connection in inputs.items()
                  if name in own} if isinstance(inputs, dict) else {}  # fmt: skip
        if bodies:
            made["inputs"] = {**made.get("inputs", {}), **bodies}
        return made

    return _each_block(workspace, change)


def to_pictures(workspace: JSON) -> tuple[JSON, list[str]]:
    """Level 2 -> Level 1: each word block that is a picture block's line as that picture
    block; and the ids of the statement blocks that are not (what keeps the program above
    Level 1; a picture block's values are part of it, not listed)."""
    table = _table()
    above: list[str] = []

    def change(block: JSON, line: bool) -> JSON:
        bodies = table.bodies.get(_type(block))
        found = None
        if bodies is not None:
            found = table.pictures.get(json.dumps(_strip(block, bodies), sort_keys=True))
        if found is None:
            if line:
                above.append(str(block.get("id", "")))
            return block
        block_type, value, count = found
        picture = _BY_BLOCK[block_type]
        made: JSON = {"type": block_type}
        made.update((key, value) for key, value in block.items() if key not in _OWN_KEYS)
        fields: JSON = {}
        if len(picture.variants) > 1:
            fields[PICK] = value
        if picture.counted:
            fields[AMOUNT] = str(count)
        if fields:
            made["fields"] = fields
        kept = {name: connection for name, connection in block.get("inputs", {}).items()
                if name in (bodies or ())}  # fmt: skip
        if kept:
            made["inputs"] = kept
        return made

    return _each_block(workspace, change), above


# ---- the studio's blocks, toolbox and words -------------------------------------------------


def _luminance(colour: str) -> float:
    def channel(value: int) -> float:
        c = value / 255
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4

    red, green, blue = (int(colour[i : i + 2], 16) for i in (1, 3, 5))
    return 0.2126 * channel(red) + 0.7152 * channel(green) + 0.0722 * channel(blue)


def contrast(one: str, other: str) -> float:
    """The WCAG contrast ratio of two ``#rrggbb`` colours (1 to 21)."""
    light, dark = sorted((_luminance(one), _luminance(other)), reverse=True)
    return (light + 0.05) / (dark + 0.05)


@functools.cache
def block_colour(category: Category) -> str:
    """The category's colour, darkened until white numbers on it reach 4.5:1."""
    red, green, blue = (int(category.colour[i : i + 2], 16) for i in (1, 3, 5))
    shade = 1.0
    while True:
        colour = f"#{int(red * shade):02x}{int(green * shade):02x}{int(blue * shade):02x}"
        if contrast(colour, "#ffffff") >= 4.5:
            return colour
        shade -= 0.02


def _category(picture: Picture) -> Category:
    block_type = _table().word_blocks[next(iter(_keys(picture)))]["type"]
    return FORMS_BY_BLOCK[block_type].category


def _keys(picture: Picture) -> Iterator[tuple[str, str, int]]:
    for value, count in picture.choices():
        yield picture.block, value, count


def _image(svg: str, alt: str, size: int = 36) -> JSON:
    return {"src": drawings.data_uri(svg), "width": size, "height": size, "alt": alt}


def picture_definitions(language: str = "en") -> list[JSON]:
    """The Level 1 blocks, for ``Blockly.common.defineBlocksWithJsonArray``: pictures, a
    picture menu where there is a choice, and number buttons where there is a number (the
    pictures' ``alt`` and the tooltips say what each does in ``language``)."""
    meanings = picture_meanings(language)
    table = _table()
    made: list[JSON] = []
    for picture in PICTURES:
        said = meanings[picture.block]
        args: list[JSON] = []
        if picture.picture:
            args.append({"type": "field_image", **_image(picture.picture, said["words"])})
        if len(picture.variants) > 1:
            options = [[_image(v.picture, said["what"][v.value], 32), v.value]
                       for v in picture.variants]  # fmt: skip
            args.append({"type": "field_dropdown", "name": PICK, "options": options})
        if picture.counted:  # big number keys: a finger's size on the block and in its menu
            options = [[_image(drawings.number(n), str(n), 40), str(n)] for n in range(1, MOST + 1)]
            args.append({"type": "field_dropdown", "name": AMOUNT, "options": options})
        definition: JSON = {
            "type": picture.block,
            "message0": " ".join(f"%{i + 1}" for i in range(len(args))),
            "args0": args,
            "colour": block_colour(_category(picture)),
            "tooltip": said["words"],
            "inputsInline": True,
        }
        words = table.word_blocks[next(iter(_keys(picture)))]
        bodies = table.bodies[words["type"]]
        if bodies:
            definition["message1"] = "%1"
            definition["args1"] = [{"type": "input_statement", "name": bodies[0]}]
        if not picture.variants[0].line.startswith("when "):
            definition["previousStatement"] = None
            definition["nextStatement"] = None
        made.append(definition)
    return made


_SIGNS = {  # a toolbox category's name at Level 1: a sign, not a word to read
    Category.EVENTS: "⚑", Category.MOTION: "⬆", Category.DRAWING: "✎",
    Category.LIGHTS: "☀", Category.SOUND: "♪", Category.CONTROL: "⟳",
}  # fmt: skip


def picture_toolbox() -> JSON:
    """Level 1's toolbox: the picture blocks in the categories of their lines' blocks, each
    named by a sign (the studio swaps it for Level 2's, which has categories too)."""
    contents: dict[Category, list[JSON]] = {}
    for picture in PICTURES:
        contents.setdefault(_category(picture), []).append({"kind": "block", "type": picture.block})
    categories = [{"kind": "category", "name": _SIGNS[category],
                   "colour": block_colour(category), "contents": blocks}
                  for category, blocks in contents.items()]  # fmt: skip
    return {"kind": "categoryToolbox", "contents": categories}


@functools.cache
def _meanings_file() -> dict[str, Any]:
    text = resources.files("rootlang.locale").joinpath("pictures.json").read_text("utf-8")
    loaded: dict[str, Any] = json.loads(text)
    return loaded


def picture_meanings(language: str = "en") -> dict[str, JSON]:
    """What each picture block says aloud, in ``language`` (else English): ``words``, a
    sentence where ``{n}`` is its number and ``{what}`` its picture menu's choice, and
    ``what``: each choice in words."""
    every = _meanings_file()
    shown = every.get(language, every["en"])
    english = every["en"]
    made: dict[str, JSON] = {}
    for picture in PICTURES:
        own = shown.get(picture.block) or english[picture.block]
        what = {variant.value: (own.get("what", {}).get(variant.value)
                                or english[picture.block].get("what", {}).get(variant.value, ""))
                for variant in picture.variants}  # fmt: skip
        made[picture.block] = {"words": own["words"], "one": own.get("one", ""), "what": what}
    return made
