"""Programs in other languages: what translating the keywords costs on a 10,000-line program
(aim: reading it in Dutch, Spanish, French or German takes at most 20 % longer than in
English), and translating it to each language and back.

    .venv/bin/python benchmarks/languages.py
"""

from __future__ import annotations

import sys
from pathlib import Path

from rootlang.checks import parse
from rootlang.locale.translate import from_english, to_english

sys.path.insert(0, str(Path(__file__).parent))
from blocks import median_time  # the same timing as the other benchmarks
from parse_check import generated_program


def main() -> None:
    english = generated_program(10_000)
    lines = english.count("\n")
    parse(english)  # builds the parser once
    english_time = median_time(lambda: parse(english, language="en"), rounds=3)
    print(f"parse {lines} lines in English: {english_time:.3f} s")
    for language in ("nl", "es", "fr", "de"):
        measure(english, english_time, language)


def measure(english: str, english_time: float, language: str) -> None:
    local = from_english(english, language)
    assert to_english(local, language).text == english
    local_time = median_time(lambda: parse(local, language=language), rounds=3)
    there = median_time(lambda: from_english(english, language), rounds=3)
    back = median_time(lambda: to_english(local, language), rounds=3)
    extra = (local_time / english_time - 1) * 100
    print(
        f"parse in {language}: {local_time:.3f} s ({extra:+.0f} %, aim ≤ +20 %); "
        f"translate there {there:.3f} s, back {back:.3f} s"
    )


if __name__ == "__main__":
    main()
