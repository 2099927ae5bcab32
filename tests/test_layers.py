"""The layers of docs/architecture.md hold: the language, the runtime, the simulator and Bluetooth
never import the application layer (``rootlang.app``) or what stands on it (the command line,
the studio, the golden tests, the adventures), counting imports inside functions; and the
application layer imports none of those."""

from __future__ import annotations

import ast
from pathlib import Path

import rootlang

PACKAGE = Path(rootlang.__file__).parent
ABOVE_APP = ("rootlang.cli", "rootlang.studio", "rootlang.testing", "rootlang.adventures")
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


def module_imports() -> dict[str, set[str]]:
    """Each rootlang module -> the rootlang modules it imports, anywhere in it. ``from package
    import module`` imports that module (the package's ``__init__`` only when a name is no
    module of its own)."""
    paths = {module_name(path): path for path in PACKAGE.rglob("*.py")}
    graph: dict[str, set[str]] = {}
    for name, path in paths.items():
        found: set[str] = set()
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            targets: list[str] = []
            if isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
                modules = [f"{node.module}.{alias.name}" for alias in node.names]
                targets = [target for target in modules if target in paths] or [node.module]
            elif isinstance(node, ast.Import):
                targets = [alias.name for alias in node.names]
            found.update(target for target in targets if target in paths and target != name)
        graph[name] = found
    return graph


def circles(graph: dict[str, set[str]]) -> list[frozenset[str]]:
    """The groups of modules that import each other, round a circle (Tarjan's algorithm)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[frozenset[str]] = []

    def visit(module: str) -> None:
        index[module] = low[module] = len(index)
        stack.append(module)
        for target in sorted(graph[module]):
            if target not in index:
                visit(target)
                low[module] = min(low[module], low[target])
            elif target in stack:
                low[module] = min(low[module], index[target])
        if low[module] == index[module]:
            group = {stack.pop()}
            while module not in group:
                group.add(stack.pop())
            if len(group) > 1:
                found.append(frozenset(group))

    for module in sorted(graph):
        if module not in index:
            visit(module)
    return found


def test_no_import_circle() -> None:
    # no two modules import each other, round any circle, even inside a function: the
    # suggestions are tried by rootlang.checks.parse, above the grammar and the checks
    assert circles(module_imports()) == []


def test_the_circle_check_finds_a_circle() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert circles(graph) == [frozenset({"a", "b", "c"})]


def folder_imports(graph: dict[str, set[str]]) -> dict[str, set[str]]:
    """The import graph with each folder of ``rootlang/`` one node (``rootlang.locale``, its
    modules together), each module at the top its own."""

    def folder(module: str) -> str:
        return ".".join(module.split(".")[:2])

    folders: dict[str, set[str]] = {}
    for module, targets in graph.items():
        found = folders.setdefault(folder(module), set())
        found.update(folder(target) for target in targets if folder(target) != folder(module))
    for targets in list(folders.values()):
        for target in targets:
            folders.setdefault(target, set())
    return folders


def test_no_folder_imports_one_that_imports_it_back() -> None:
    # the floors of docs/architecture.md at the level of folders: the message plumbing
    # (rootlang/wording) below units.py and diagnostics.py, the program's own words in other
    # languages (rootlang/locale) above the forms, and no arrow from one folder back up into
    # another that reaches it
    assert circles(folder_imports(module_imports())) == []


def test_the_folder_check_finds_an_arrow_back_up() -> None:
    graph = {
        "rootlang.units": {"rootlang.locale.shown"},  # the plumbing in the translation's folder
        "rootlang.locale.shown": set(),
        "rootlang.locale.lines": {"rootlang.forms"},
        "rootlang.forms": {"rootlang.units"},
    }
    assert circles(folder_imports(graph)) == [
        frozenset({"rootlang.units", "rootlang.locale", "rootlang.forms"})
    ]
