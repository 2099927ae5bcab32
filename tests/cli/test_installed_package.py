"""`pip install .` (not editable) gives a package that works from an empty folder: the worlds,
the grammar and the replay page travel inside the wheel."""

from __future__ import annotations

import os
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

REPO = Path(__file__).parents[2]


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The wheel `pip install .` would build, unpacked as pip installs it (the dependencies
    come from this environment: what is under test is what the wheel carries)."""
    target = tmp_path_factory.mktemp("site")
    wheels = tmp_path_factory.mktemp("wheels")
    build = [sys.executable, "-m", "pip", "wheel", "-q", "--no-deps", "-w", str(wheels), str(REPO)]
    if subprocess.run(build, capture_output=True, text=True, timeout=300).returncode != 0:
        pytest.skip("pip could not build the wheel here (no build backend to fetch?)")
    (wheel,) = wheels.glob("rootlang-*.whl")
    with zipfile.ZipFile(wheel) as archive:
        archive.extractall(target)
    return target


@pytest.mark.slow
def test_the_installed_package_runs_the_gallery_worlds_by_name_from_an_empty_folder(
    installed: Path, tmp_path: Path
) -> None:
    folder = tmp_path / "class"
    folder.mkdir()
    (folder / "hello.root").write_text(
        "# world: line_mat\nwhen started\n    move 5 cm\n", encoding="utf-8"
    )
    env = {**os.environ, "PYTHONPATH": str(installed), "XDG_CACHE_HOME": str(tmp_path / "c")}

    def rootlang(*args: str) -> subprocess.CompletedProcess[str]:
        command = [sys.executable, "-m", "rootlang", *args]
        return subprocess.run(command, cwd=folder, env=env, capture_output=True, text=True)

    where = subprocess.run(
        [sys.executable, "-c", "import rootlang; print(rootlang.__file__)"],
        cwd=folder, env=env, capture_output=True, text=True, check=True,
    )  # fmt: skip
    assert where.stdout.startswith(str(installed)), "the wheel's copy is the one under test"
    for world in ("color_mat", "arena", "line_mat"):
        ran = rootlang("sim", "hello.root", "--world", world)
        assert ran.returncode == 0, ran.stderr
        assert "the end: every script finished" in ran.stdout
    ran = rootlang("sim", "hello.root", "--html", "hello.html")  # the `# world:` line's name
    assert ran.returncode == 0, ran.stderr
    assert (folder / "hello.html").read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
