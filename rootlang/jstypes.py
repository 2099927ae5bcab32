"""Python's TypedDicts as TypeScript declarations, and a check that a value has a TypedDict's shape.

The messages between the studio's server and its page (and the replay page's data) are described
once, as TypedDicts next to the Python that makes them. :func:`declarations` writes them as a
``.d.ts`` file that the page's JavaScript names in its JSDoc, so ``tsc --checkJs`` checks the
page against the very types the server is checked against by mypy; :func:`problems` checks a real
message against its type (the tests use it on what the server really sends).

Only what the messages use is understood: ``str``, ``int``, ``float``, ``bool``, ``None``,
``Literal``, unions, ``list``, ``tuple``, ``dict[str, X]``, ``object`` (any JSON) and TypedDicts
(optional keys from ``total=False``).
"""

from __future__ import annotations

import types
from collections.abc import Iterable, Sequence
from typing import Any, Literal, Union, get_args, get_origin, get_type_hints, is_typeddict

_SCALARS: dict[Any, str] = {str: "string", int: "number", float: "number", bool: "boolean",
                            type(None): "null", object: "unknown", Any: "unknown"}  # fmt: skip


def _is_union(hint: Any) -> bool:
    return get_origin(hint) in (Union, types.UnionType)


def typescript(hint: Any) -> str:
    """How TypeScript writes a Python type hint (a TypedDict by its name)."""
    if hint in _SCALARS:
        return _SCALARS[hint]
    if is_typeddict(hint):
        return str(hint.__name__)
    origin, arguments = get_origin(hint), get_args(hint)
    if origin is Literal:
        return " | ".join(_literal(value) for value in arguments)
    if _is_union(hint):
        return " | ".join(typescript(argument) for argument in arguments)
    if origin is list:
        inner = typescript(arguments[0])
        return f"({inner})[]" if "|" in inner else f"{inner}[]"
    if origin is tuple:
        return "[" + ", ".join(typescript(argument) for argument in arguments) + "]"
    if origin is dict:
        return f"Record<string, {typescript(arguments[1])}>"
    raise TypeError(f"no TypeScript for {hint!r}")


def _literal(value: object) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return repr(value)


def _doc(item: Any) -> list[str]:
    text = " ".join((item.__doc__ or "").split())
    return [f"/** {text} */"] if text else []


def declarations(
    items: Sequence[Any], aliases: dict[str, Any], imports: dict[str, Iterable[Any]]
) -> str:
    """A ``.d.ts`` file: one ``interface`` per TypedDict in ``items``, a ``type`` per alias, and
    ``import type`` lines for the TypedDicts another generated file declares (``imports``: that
    file's module specifier → its TypedDicts)."""
    lines = [
        "// Made by `python -m rootlang.studio.messages` from the Python types: do not edit.",
        "",
    ]
    for source, named in imports.items():
        names = ", ".join(sorted(item.__name__ for item in named))
        lines.append(f'import type {{ {names} }} from "{source}";')
    if imports:
        lines.append("")
    for item in items:
        hints = get_type_hints(item)
        lines += _doc(item)
        lines.append(f"export interface {item.__name__} {{")
        for key, hint in hints.items():
            optional = "?" if key in item.__optional_keys__ else ""
            lines.append(f"  {key}{optional}: {typescript(hint)};")
        lines += ["}", ""]
    for name, hint in aliases.items():
        lines.append(f"export type {name} = {typescript(hint)};")
    return "\n".join(lines).rstrip("\n") + "\n"


def problems(value: object, hint: Any, where: str = "message") -> list[str]:
    """What in ``value`` (parsed JSON) does not have the shape ``hint`` describes; [] if it does.
    Keys a TypedDict does not name are problems too: the contract names every key."""
    if hint in (object, Any):
        return []
    if hint is float:
        ok = isinstance(value, (int, float)) and not isinstance(value, bool)
        return [] if ok else [f"{where}: {value!r} is not a number"]
    if hint in (str, int, bool, type(None)):
        ok = isinstance(value, hint) and (hint is bool or not isinstance(value, bool))
        return [] if ok else [f"{where}: {value!r} is not {typescript(hint)}"]
    if is_typeddict(hint):
        return _typeddict_problems(value, hint, where)
    origin, arguments = get_origin(hint), get_args(hint)
    if origin is Literal:
        return [] if value in arguments else [f"{where}: {value!r} is not {typescript(hint)}"]
    if _is_union(hint):
        found = [problems(value, argument, where) for argument in arguments]
        return [] if any(not each for each in found) else min(found, key=len)
    if origin is list:
        if not isinstance(value, list):
            return [f"{where}: {value!r} is not a list"]
        return [p for i, v in enumerate(value) for p in problems(v, arguments[0], f"{where}[{i}]")]
    if origin is tuple:
        if not isinstance(value, list) or len(value) != len(arguments):
            return [f"{where}: {value!r} is not a list of {len(arguments)}"]
        pairs = zip(value, arguments, strict=True)
        return [p for i, (v, a) in enumerate(pairs) for p in problems(v, a, f"{where}[{i}]")]
    if origin is dict:
        if not isinstance(value, dict):
            return [f"{where}: {value!r} is not an object"]
        return [p for k, v in value.items() for p in problems(v, arguments[1], f"{where}.{k}")]
    raise TypeError(f"no check for {hint!r}")


def _typeddict_problems(value: object, hint: Any, where: str) -> list[str]:
    if not isinstance(value, dict):
        return [f"{where}: {value!r} is not an object ({hint.__name__})"]
    hints = get_type_hints(hint)
    found = [f"{where}: no `{key}`" for key in hint.__required_keys__ if key not in value]
    found += [f"{where}: `{key}` is not in {hint.__name__}" for key in value if key not in hints]
    for key, item in value.items():
        if key in hints:
            found += problems(item, hints[key], f"{where}.{key}")
    return found
