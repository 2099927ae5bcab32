"""`rootlang studio` on the command line, and the page's files shipping in the package."""

from __future__ import annotations

import asyncio
import fnmatch
import os
import re
import signal
import socket
import subprocess
import sys
from pathlib import Path

import aiohttp
import pytest

import rootlang.studio
from rootlang.cli import main

from .conftest import RunningStudio

if sys.version_info >= (3, 11):
    import tomllib
else:  # Python 3.10
    import tomli as tomllib

ROOT = Path(__file__).resolve().parents[2]
STATIC = Path(rootlang.studio.__file__).parent / "static"


def test_help_names_the_options(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["studio", "--help"])
    shown = capsys.readouterr().out
    for option in ("FOLDER", "--port", "--host", "--no-browser", "--transport"):
        assert option in shown


def test_a_missing_folder_is_a_clear_error(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["studio", "no/such/folder", "--no-browser"]) == 1
    err = capsys.readouterr().err
    assert "no/such/folder" in err and "Traceback" not in err


def test_a_port_in_use_is_a_clear_error(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    with socket.socket() as taken:
        taken.bind(("127.0.0.1", 0))
        taken.listen()
        port = taken.getsockname()[1]
        assert main(["studio", str(tmp_path), "--port", str(port), "--no-browser"]) == 1
    err = capsys.readouterr().err
    assert f"port {port}" in err and "--port" in err and "Traceback" not in err


def test_the_server_starts_in_its_language_prints_its_address_and_stops_on_ctrl_c(
    tmp_path: Path,
) -> None:
    server = subprocess.Popen(
        [sys.executable, "-m", "rootlang", "studio", str(tmp_path), "--port", "0",
         "--no-browser", "--language", "nl", "--level", "1"],
        stdout=subprocess.PIPE, text=True, env={**os.environ, "LC_ALL": "en_GB.UTF-8"},
    )  # fmt: skip
    try:
        assert server.stdout is not None
        line = server.stdout.readline()
        found = re.search(r"http://127\.0\.0\.1:\d+/", line)
        assert found, line
        assert line.rstrip().endswith("/?level=1")  # (the page opens at Level 1)

        async def fetch() -> tuple[int, str]:
            async with aiohttp.ClientSession() as session:
                page = await session.get(found.group(0))
                setup = await session.get(found.group(0) + "api/setup")
                return page.status, (await setup.json())["language"]

        # --language reaches the page, over the computer's own (English) settings
        assert asyncio.run(fetch()) == (200, "nl")
        server.send_signal(signal.SIGINT)
        assert server.wait(20) == 0
    finally:
        server.kill()


def test_another_host_name_for_the_loopback_address_is_refused(studio: RunningStudio) -> None:
    async def fetch() -> int:
        async with aiohttp.ClientSession() as session:
            reply = await session.get(studio.address + "/", headers={"Host": "evil.example"})
            return reply.status

    assert asyncio.run(fetch()) == 403


def test_every_file_of_the_page_is_package_data() -> None:
    """`pip install .` (not editable) ships what the page loads: each file under static/
    matches a package-data pattern, and the vendored parts are all there."""
    config = tomllib.loads((ROOT / "pyproject.toml").read_text(encoding="utf-8"))
    patterns = config["tool"]["setuptools"]["package-data"]["rootlang"]
    package = STATIC.parents[1]
    files = [p.relative_to(package).as_posix() for p in STATIC.rglob("*") if p.is_file()]
    unshipped = [
        name for name in files
        if not any(fnmatch.fnmatch(name, pattern.replace("**/", "*")) for pattern in patterns)
    ]  # fmt: skip
    assert unshipped == []
    for needed in ("vendor/blockly/blockly_compressed.js", "vendor/blockly/media/sprites.svg",
                   "vendor/blockly/msg/nl.js", "vendor/blockly/LICENSE",
                   "vendor/codemirror/lib/codemirror.js", "vendor/codemirror/LICENSE",
                   "vendor/VERSIONS.md"):  # fmt: skip
        assert (STATIC / needed).is_file(), needed


def test_the_page_loads_only_files_the_package_has() -> None:
    page = (STATIC / "index.html").read_text(encoding="utf-8")
    for source in re.findall(r'(?:src|href)="(/static/[^"]+)"', page):
        assert (STATIC / source.removeprefix("/static/")).is_file(), source
    assert "http" not in re.sub(r"<!--.*?-->", "", page)
