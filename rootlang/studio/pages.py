"""What the pupil's page and the teacher's page share: the static files, the page's own
origin, a request's JSON body and languages, and the setup's part that depends on the
language alone.

Beside :mod:`rootlang.studio.server` (the pupil's page) and
:mod:`rootlang.studio.classroom` (the teacher's), below both: neither imports the other's
handlers.
"""

from __future__ import annotations

import functools
import hashlib
from importlib import resources
from pathlib import Path
from typing import Any, cast

from aiohttp import web

from rootlang.blocks import drawings
from rootlang.colors import LIGHT_COLORS, NAMED_COLORS, hex_rgb
from rootlang.locale.blocks import BLOCKLY_MESSAGES, studio_strings, syntax_words
from rootlang.sim.world import STIMULI
from rootlang.studio import messages as m
from rootlang.studio.conversions import blocks_module, request_object
from rootlang.wording.language import Languages

STATIC = Path(str(resources.files("rootlang.studio").joinpath("static")))
# A request's languages: the page's (``?language=xx``), else the studio's; set by the server's
# middleware before any handler runs.
LANGUAGES = web.RequestKey("languages", Languages)


# The vendored Blockly and CodeMirror (1.2 MB of the page's 1.4 MB) are served under a URL
# named for their contents, so a browser keeps them for good and never asks again: a class of
# 30 reloading would otherwise pull them 30 times over the school's Wi-Fi. Other files are
# asked again each time (answered "not modified" when unchanged); the API is never kept.
VENDOR = STATIC / "vendor"
KEPT_FOR_GOOD = "public, max-age=31536000, immutable"
ASKED_AGAIN = "no-cache"
NEVER_KEPT = "no-store"


@functools.cache
def vendor_url() -> str:
    """Where the vendored files are served: ``/vendor/<their contents' hash>/``."""
    digest = hashlib.sha256()
    for path in sorted(VENDOR.rglob("*")):
        if path.is_file():
            digest.update(path.relative_to(VENDOR).as_posix().encode() + b"\0")
            digest.update(path.read_bytes())
    return f"/vendor/{digest.hexdigest()[:16]}/"


def cache_control(path: str) -> str:
    """How long a browser may keep the answer to a request for ``path``."""
    if path.startswith("/vendor/"):
        return KEPT_FOR_GOOD
    if path.startswith(("/static/", "/blocks/", "/sim/render/")):
        return ASKED_AGAIN
    return NEVER_KEPT


def compress(request: web.Request, response: web.StreamResponse) -> None:
    """Gzip the answer when the browser takes it (every browser does): about a quarter of the
    bytes for scripts and JSON. Not a socket, nor an answer to a conditional request, which
    may be "not modified": that must have no body, and aiohttp would give it one."""
    conditional = "If-None-Match" in request.headers or "If-Modified-Since" in request.headers
    if (
        not response.prepared
        and not isinstance(response, web.WebSocketResponse)
        and not conditional
        and "gzip" in request.headers.get("Accept-Encoding", "")
    ):
        response.enable_compression(web.ContentCoding.gzip)


BUTTONS_HERE = (
    "    <!-- the stage's buttons: written by the studio from the stimuli the simulator takes "
    "(rootlang/studio/pages.py) -->\n"
)
# The signs beside the stage's buttons, in the order of the parts they press (the touch sensors
# front left, front right, back left, back right; the bumper's left and right halves): where
# each sits on the robot. Their names are the simulator's, rootlang.sim.world.STIMULI.
_TOUCH_SIGNS = ("◤ {}", "{} ◥", "◣ {}", "{} ◢")
_BUMPER_SIGNS = ("⟨ bumper {}", "bumper {} ⟩")


@functools.cache
def _page_text(name: str) -> str:
    text = (STATIC / name).read_text("utf-8").replace('"/static/vendor/', f'"{vendor_url()}')
    return text.replace(BUTTONS_HERE, stage_buttons())


def stage_buttons() -> str:
    """The stage's buttons that touch the robot, press its nose button and its bumpers, each
    sending the stimulus and the parts the simulator names (so the page keeps no copy). Each
    shows its words and, at Level 1, instead a picture of the robot with that part lit (the
    picture blocks' own drawings): a child who can't read knows which button is which."""
    touch, bump = STIMULI["touch"].parts, STIMULI["bump"].parts
    touches = [
        _button(f'data-touch="{part}"', f"Touch {part}", part.replace(" ", "_"),
                sign.format(part), drawings.touch(part))
        for part, sign in zip(touch, _TOUCH_SIGNS, strict=True)
    ]  # fmt: skip
    nose = _button("data-nose", "Press the nose button", "nose", "● nose", drawings.nose())
    bumpers = [
        _button(f'data-bump="{part}"', f"bumper {part}", f"bumper_{part}", sign.format(part),
                drawings.bumper(part))
        for part, sign in zip(bump, _BUMPER_SIGNS, strict=True)
    ]  # fmt: skip
    both = _button('data-bump="{}"'.format(" ".join(bump)), "both bumpers", "both", "both",
                   drawings.bumper("both"))  # fmt: skip
    return (
        '    <div id="robot-buttons" role="group" aria-label="Touch the robot">\n'
        + "".join([*touches[:2], nose, *touches[2:]])
        + "    </div>\n"
        + '    <div id="bumper-buttons" role="group" aria-label="Press the bumpers">\n'
        + "".join([bumpers[0], both, *bumpers[1:]])
        + "    </div>\n"
    )


def _button(data: str, label: str, words: str, shown: str, picture: str) -> str:
    return (
        f'      <button type="button" {data} class="pictured" aria-label="{label}"'
        f' title="{label}"><img class="picture" alt="" src="{drawings.data_uri(picture)}">'
        f'<span class="words" data-i18n="{words}">{shown}</span></button>\n'
    )


def page(name: str) -> web.Response:
    """One of the studio's HTML pages, its vendored files named by their versioned URL."""
    return web.Response(text=_page_text(name), content_type="text/html")


def languages_of(request: web.Request) -> Languages:
    """The languages a request's answer speaks."""
    return request[LANGUAGES]


def own_origin(request: web.Request) -> str:
    return f"{request.scheme}://{request.host}"


async def json_body(request: web.Request) -> dict[str, Any]:
    return request_object(await request.read())


@functools.cache
def setup_in_language(language: str) -> m.SetupInLanguage:
    """The setup's part that depends on the language alone: the page's words (and English's,
    which the page replaces), Blockly's own words file, the blocks and the toolbox. Made once
    per language: the page asks for the setup again at every New and Rename."""
    blocks = blocks_module()
    from rootlang.blocks import pictures  # (with blocks: Level 1's)

    return {
        "strings": studio_strings(language),
        "english": studio_strings("en"),
        "blockly_messages": vendor_url() + BLOCKLY_MESSAGES[language].removeprefix("vendor/"),
        "syntax": syntax_words(language),
        "light_colours": {name: hex_rgb(NAMED_COLORS[name].rgb) for name in LIGHT_COLORS},
        "blocks": None if blocks is None
        else {"definitions": [*blocks.block_definitions(language),
                              *pictures.picture_definitions(language)],
              "toolbox": blocks.toolbox(language),
              "pictures": {"toolbox": pictures.picture_toolbox(),
                           "meanings": cast("dict[str, m.PictureMeaning]",
                                            pictures.picture_meanings(language))}},
    }  # fmt: skip
