"""``python -m rootlang.locale``: rewrites the keyword table of docs/languages.md from the forms
(a test fails while it is out of date). A module of its own: run as ``-m
rootlang.locale.keywords``, Python would load that module twice (the package loads it first)."""

from pathlib import Path

from rootlang.locale.keywords import with_table

docs = Path(__file__).resolve().parents[2] / "docs" / "languages.md"
docs.write_text(with_table(docs.read_text(encoding="utf-8")), encoding="utf-8")
