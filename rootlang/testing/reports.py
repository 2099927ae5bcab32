"""Reports of a golden test run for machines: JUnit XML (CI systems, GitHub Classroom's
autograding) and a JSON or CSV table (one row per program: its outcome, its time, where its
output first differed). And sharding: a deterministic share of the programs for one of N
machines, so a CI matrix or any job system can spread thousands of submissions."""

from __future__ import annotations

import csv
import io
import json
import re
import xml.etree.ElementTree as ElementTree
from collections.abc import Sequence
from pathlib import Path

from rootlang.diagnostics import RootlangError, file_problem
from rootlang.testing.runner import ProgramResult, Verdict

REPORT_COLUMNS = ("program", "outcome", "passed", "seconds", "end", "first_difference")
_NOT_XML = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")  # XML 1.0 can't hold these
_BROKEN = frozenset({Verdict.CPU_LIMIT, Verdict.WALL_LIMIT, Verdict.MEMORY_LIMIT, Verdict.CRASHED})


def shard(programs: Sequence[Path], index: int, count: int) -> list[Path]:
    """Share ``index`` (1-based) of ``count``: every count-th program of the sorted list, so the
    shares are about equal, together hold every program once, and are the same on every
    machine that lists the same programs."""
    ordered = sorted(programs, key=lambda path: path.as_posix())
    return ordered[index - 1 :: count]


def report_rows(results: Sequence[ProgramResult]) -> list[dict[str, object]]:
    return [
        {
            "program": result.program.as_posix(),
            "outcome": result.verdict.name.lower(),
            "passed": result.verdict.ok,
            "seconds": round(result.seconds, 3),
            "end": None if result.produced is None else result.produced.end,
            "first_difference": result.first_difference or None,
        }
        for result in results
    ]


def report_text(results: Sequence[ProgramResult], suffix: str) -> str:
    """The JSON (``.json``) or CSV (``.csv``) report; E618 for any other kind of file."""
    rows = report_rows(results)
    if suffix == ".json":
        return json.dumps({"programs": rows}, indent=2, ensure_ascii=False) + "\n"
    if suffix == ".csv":
        out = io.StringIO()
        writer = csv.DictWriter(out, REPORT_COLUMNS, lineterminator="\n")
        writer.writeheader()
        writer.writerows(rows)
        return out.getvalue()
    raise RootlangError.of("E618", suffix=suffix or "a name without one")


def junit_xml(results: Sequence[ProgramResult], name: str = "rootlang") -> str:
    """JUnit XML: one test case per program; a wrong output or a missing golden file is a
    failure, a limit hit or a crash an error; the report (the diff) is its text."""
    failures = sum(r.verdict in (Verdict.FAILED, Verdict.MISSING) for r in results)
    errors = sum(r.verdict in _BROKEN for r in results)
    total = sum(r.seconds for r in results)
    suite = ElementTree.Element(
        "testsuite",
        name=name,
        tests=str(len(results)),
        failures=str(failures),
        errors=str(errors),
        skipped="0",
        time=f"{total:.3f}",
    )
    for result in results:
        program = result.program
        case = ElementTree.SubElement(
            suite,
            "testcase",
            classname=_xml_text(program.parent.as_posix()),
            name=_xml_text(program.name),
            file=_xml_text(program.as_posix()),
            time=f"{result.seconds:.3f}",
        )
        if not result.verdict.ok:
            tag = "error" if result.verdict in _BROKEN else "failure"
            problem = ElementTree.SubElement(
                case,
                tag,
                message=_xml_text(result.first_difference or result.headline),
                type=result.verdict.name.lower(),
            )
            problem.text = _xml_text(result.report)
    root = ElementTree.Element("testsuites")
    root.append(suite)
    ElementTree.indent(root)
    body = ElementTree.tostring(root, encoding="unicode")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + body + "\n"


def _xml_text(text: str) -> str:
    return _NOT_XML.sub("\ufffd", text)


def write_report(path: str, text: str) -> None:
    try:
        Path(path).write_text(text, encoding="utf-8")
    except OSError as error:
        raise RootlangError.of("E619", path=path, reason=file_problem(error)) from None
