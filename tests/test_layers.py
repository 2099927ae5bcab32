"""The layers of docs/architecture.md hold: the language, the runtime, the simulator and Bluetooth
never import the application layer (``rootlang.app``) or what stands on it (the command line,
the studio, the golden tests), counting imports inside functions; and the application layer
imports none of those three."""

from __future__ import annotations

import ast
from pathlib import Path

import rootlang

PACKAGE = Path(rootlang.__file__).parent
ABOVE_APP = ("rootlang.cli", "rootlang.studio", "rootlang.testing")
APP = "rootlang.app"


def module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def imported(path: Path) -> set[str]:
    """Every rootlang module ``path`` imports, anywhere in it (at the top or in a function)."""
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found.add(node.module)
            found.update(f"{node.module}.{alias.name}" for alias in node.names)
        elif isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
    return {name for name in found if name.startswith("rootlang.")}


def within(name: str, packages: tuple[str, ...]) -> bool:
    return any(name == package or name.startswith(package + ".") for package in packages)


def test_no_lower_layer_imports_the_application_layer_or_above() -> None:
    upward = []
    for path in sorted(PACKAGE.rglob("*.py")):
        name = module_name(path)
        if name in ("rootlang", "rootlang.__main__") or within(name, ABOVE_APP):
            continue  # the public API (names loaded on first use) and the command's start
        above = ABOVE_APP if within(name, (APP,)) else (*ABOVE_APP, APP)
        upward += [f"{name} -> {target}" for target in imported(path) if within(target, above)]
    assert upward == []


def test_the_check_finds_an_upward_import(tmp_path: Path) -> None:
    # the check itself can fail: a lower module reaching up is seen, even inside a function
    lower = tmp_path / "lower.py"
    lower.write_text("def f():\n    from rootlang.app.session import load\n", encoding="utf-8")
    assert any(within(target, (APP,)) for target in imported(lower))
