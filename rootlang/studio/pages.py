"""What the pupil's page and the teacher's page share: the static files, the page's own
origin, a request's JSON body and languages, and the setup's part that depends on the
language alone.

Beside :mod:`rootlang.studio.server` (the pupil's page) and
:mod:`rootlang.studio.classroom` (the teacher's), below both: neither imports the other's
handlers.
"""

from __future__ import annotations

import functools
from importlib import resources
from pathlib import Path
from typing import Any, cast

from aiohttp import web

from rootlang.locale.blocks import BLOCKLY_MESSAGES, studio_strings, syntax_words
from rootlang.locale.language import Languages
from rootlang.studio import messages as m
from rootlang.studio.conversions import blocks_module, request_object

STATIC = Path(str(resources.files("rootlang.studio").joinpath("static")))
# A request's languages: the page's (``?language=xx``), else the studio's; set by the server's
# middleware before any handler runs.
LANGUAGES = web.RequestKey("languages", Languages)


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
        "blockly_messages": f"/static/{BLOCKLY_MESSAGES[language]}",
        "syntax": syntax_words(language),
        "blocks": None if blocks is None
        else {"definitions": [*blocks.block_definitions(language),
                              *pictures.picture_definitions(language)],
              "toolbox": blocks.toolbox(language),
              "pictures": {"toolbox": pictures.picture_toolbox(),
                           "meanings": cast("dict[str, m.PictureMeaning]",
                                            pictures.picture_meanings(language))}},
    }  # fmt: skip
