"""Light on the school's Wi-Fi: the studio's answers are compressed, the vendored Blockly and
CodeMirror are kept by the browser for good (under a URL named for their contents), the page's
own files are asked again and answered "not modified", and the API is never kept."""

from __future__ import annotations

import asyncio
import re
from pathlib import Path

import aiohttp
import pytest

from rootlang.studio import pages
from rootlang.studio.pages import KEPT_FOR_GOOD, NEVER_KEPT, vendor_url

from .conftest import RunningStudio

GZIP = {"Accept-Encoding": "gzip, deflate, br"}
PLAIN = {"Accept-Encoding": "identity"}


def test_the_page_names_its_vendored_files_by_version_and_they_are_kept_for_good(
    studio: RunningStudio,
) -> None:
    async def check() -> None:
        async with aiohttp.ClientSession(studio.address, auto_decompress=False) as session:
            async with session.get("/", headers=GZIP) as answer:
                assert answer.headers["Cache-Control"] == NEVER_KEPT
                assert answer.headers["Content-Encoding"] == "gzip"
            async with session.get("/", headers=PLAIN) as answer:
                html = await answer.text()
            scripts = re.findall(r'src="(/vendor/[^"]+)"', html)
            assert scripts, "the page loads no vendored script from a versioned URL"
            assert '"/static/vendor/' not in html
            for script in scripts:
                async with session.get(script, headers=GZIP) as answer:
                    assert answer.status == 200, script
                    assert answer.headers["Cache-Control"] == KEPT_FOR_GOOD
                    assert answer.headers["Content-Encoding"] == "gzip"
                    compressed = len(await answer.read())
                plain = (pages.VENDOR / script.removeprefix(vendor_url())).stat().st_size
                assert compressed < plain / 2, script
            async with session.get("/api/setup", headers=GZIP) as answer:
                assert answer.headers["Cache-Control"] == NEVER_KEPT
                assert answer.headers["Content-Encoding"] == "gzip"
            async with session.get("/api/setup", headers=PLAIN) as answer:
                words = (await answer.json())["blockly_messages"]
            assert words.startswith(vendor_url())
            async with session.get(words) as answer:
                assert answer.status == 200

    asyncio.run(check())


def test_the_pages_own_files_are_asked_again_and_answered_not_modified(
    studio: RunningStudio,
) -> None:
    async def check() -> None:
        async with aiohttp.ClientSession(studio.address) as session:
            for path in ("/static/studio.js", "/static/studio.css", "/blocks/root_blocks.js"):
                async with session.get(path) as answer:
                    assert answer.headers["Cache-Control"] == "no-cache", path
                    tag = answer.headers["ETag"]
                async with session.get(path, headers={"If-None-Match": tag}) as answer:
                    assert answer.status == 304, path

    asyncio.run(check())


def test_the_vendored_files_url_changes_with_their_contents(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "blockly").mkdir()
    (tmp_path / "blockly" / "blockly.js").write_text("one", "utf-8")
    monkeypatch.setattr(pages, "VENDOR", tmp_path)
    vendor_url.cache_clear()
    try:
        before = vendor_url()
        vendor_url.cache_clear()
        (tmp_path / "blockly" / "blockly.js").write_text("two", "utf-8")
        assert vendor_url() != before
    finally:
        monkeypatch.undo()
        vendor_url.cache_clear()
