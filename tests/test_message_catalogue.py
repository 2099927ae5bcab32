"""The one catalogue and the code agree: every message is used, every code used has a message."""

from __future__ import annotations

import re
from pathlib import Path

import rootlang
from rootlang.messages import MESSAGES

PACKAGE = Path(rootlang.__file__).parent
QUOTED_CODE = re.compile(r"""["']([EWV]\d{3})["']""")  # "E101" as the code passes it


def codes_used() -> set[str]:
    return {
        code
        for path in PACKAGE.rglob("*.py")
        if path.name != "messages.py"
        for code in QUOTED_CODE.findall(path.read_text(encoding="utf-8"))
    }


def test_every_message_is_used_somewhere() -> None:
    assert sorted(set(MESSAGES) - codes_used()) == []


def test_every_code_used_has_a_message() -> None:
    assert sorted(codes_used() - set(MESSAGES)) == []


def test_codes_are_well_formed_and_messages_not_empty() -> None:
    assert all(
        re.fullmatch(r"[EWV]\d{3}", code) and text.strip() for code, text in MESSAGES.items()
    )
