"""The studio's and the replay page's JavaScript: ES modules, type-checked against the message
contract (``tsc --checkJs``, strict) and linted (eslint), with the tools ``tools/js`` pins
(``npm ci --prefix tools/js`` installs them; ``.ci/run`` does). The contract's ``.d.ts`` files
are what ``python -m rootlang.studio.messages`` writes from the Python types."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest

from rootlang.studio import messages

REPO = Path(__file__).resolve().parents[2]
TOOLS = REPO / "tools" / "js"
STATIC = REPO / "rootlang" / "studio" / "static"
MODULES = [
    *sorted(STATIC.glob("*.js")),
    *sorted((REPO / "rootlang" / "sim" / "render").glob("*.js")),
    REPO / "rootlang" / "blocks" / "root_blocks.js",
]
NODE = shutil.which("node")
# Modules linted but not yet annotated for tsc: this list may only shrink.
NOT_YET_TYPED: set[str] = set()
TYPED = [module for module in MODULES if module.name not in NOT_YET_TYPED]


def _tool(name: str) -> Path:
    if NODE is None:
        pytest.skip("node is not installed (apt-get install nodejs npm)")
    path = TOOLS / "node_modules" / ".bin" / name
    if not path.exists():
        pytest.skip(f"{name} is not installed: run `npm ci --prefix tools/js` (as .ci/run does)")
    return path


def test_the_contracts_declarations_are_written_from_the_python_types() -> None:
    for path, text in messages.written().items():
        assert path.read_text(encoding="utf-8") == text, (
            f"{path.name} is out of date: run `python -m rootlang.studio.messages`"
        )


def test_every_module_is_type_checked_by_tsc() -> None:
    tsc = _tool("tsc")
    found = subprocess.run([str(tsc), "-p", str(TOOLS / "tsconfig.json")], cwd=TOOLS,
                           capture_output=True, text=True, timeout=300)  # fmt: skip
    assert found.returncode == 0, found.stdout + found.stderr
    listed = subprocess.run([str(tsc), "-p", str(TOOLS / "tsconfig.json"), "--listFilesOnly"],
                            cwd=TOOLS, capture_output=True, text=True, timeout=300)  # fmt: skip
    checked = {Path(line).resolve() for line in listed.stdout.splitlines()}
    assert set(TYPED) <= checked
    assert {module.name for module in MODULES} >= NOT_YET_TYPED  # (gone ones leave the list)


def test_every_module_is_linted_by_eslint() -> None:
    eslint = _tool("eslint")
    found = subprocess.run(
        [str(eslint), "--config", str(TOOLS / "eslint.config.js"), "--max-warnings", "0",
         *map(str, MODULES)],
        cwd=REPO, capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert found.returncode == 0, found.stdout + found.stderr


def test_a_type_mistake_against_the_contract_is_caught(tmp_path: Path) -> None:
    """The check can fail: a module that reads a field the contract does not have."""
    tsc = _tool("tsc")
    wrong = tmp_path / "wrong.js"
    wrong.write_text(
        "// @ts-check\n"
        f'/** @param {{import("{STATIC / "messages"}").FrameMessage}} f */\n'
        "export const lag = f => f.sent_by;\n",
        encoding="utf-8",
    )
    found = subprocess.run(
        [str(tsc), "--noEmit", "--allowJs", "--checkJs", "--strict", "--target", "es2022",
         "--module", "es2022", "--moduleResolution", "bundler", "--skipLibCheck", str(wrong)],
        cwd=TOOLS, capture_output=True, text=True, timeout=300,
    )  # fmt: skip
    assert found.returncode != 0 and "sent_by" in found.stdout


def test_every_module_says_ts_check_and_the_pages_load_modules_only() -> None:
    """No globals of our own: a page's classic scripts are the vendored libraries alone."""
    for module in TYPED:
        assert module.read_text(encoding="utf-8").startswith("// @ts-check\n"), module.name
    for page in STATIC.glob("*.html"):
        html = page.read_text(encoding="utf-8")
        classic = re.findall(r'<script src="([^"]+)"', html)
        assert all(src.startswith("/static/vendor/") for src in classic), (page.name, classic)
        assert re.findall(r'<script type="module" src="([^"]+)"', html), page.name
    studio = (STATIC / "index.html").read_text(encoding="utf-8")
    assert "/static/studio.js" in re.findall(r'<script type="module" src="([^"]+)"', studio)
