"""`rootlang test --junit/--report/--shard`: reports that CI systems and autograders read, and a
deterministic split of many programs over many machines."""

from __future__ import annotations

import csv
import json
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import pytest

from rootlang.cli import main
from rootlang.testing.reports import shard

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="needs fork and resource")

GOOD = "when started\n    move 5 cm\n"


@pytest.fixture
def submissions(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> Path:
    """Three programs: one passes, one's output differs from its golden file, one has none."""
    for name in ("pass", "differs", "new"):
        (tmp_path / f"{name}.root").write_text(GOOD, encoding="utf-8")
    assert (
        main(["test", "--update", str(tmp_path / "pass.root"), str(tmp_path / "differs.root")]) == 0
    )
    differs = tmp_path / "differs.golden"
    text = differs.read_text(encoding="utf-8")
    differs.write_text(text.replace("move 50 mm", "move 60 mm <&\x01>"), encoding="utf-8")
    capsys.readouterr()
    return tmp_path


def test_junit_xml_has_a_case_per_program_and_the_failures_with_their_diff(
    submissions: Path,
) -> None:
    junit = submissions / "out" / "results.xml"
    junit.parent.mkdir()
    assert main(["test", str(submissions), "--junit", str(junit)]) == 1
    root = ElementTree.parse(junit).getroot()
    (suite,) = root.iter("testsuite")
    assert (suite.get("tests"), suite.get("failures"), suite.get("errors")) == ("3", "2", "0")
    cases = {str(case.get("name")): case for case in suite.iter("testcase")}
    assert sorted(cases) == ["differs.root", "new.root", "pass.root"]
    assert list(cases["pass.root"]) == []
    (failure,) = cases["differs.root"]
    assert failure.tag == "failure" and failure.get("type") == "failed"
    assert "expected" in (failure.get("message") or "") and "move 60 mm" in (failure.text or "")
    assert cases["new.root"][0].get("type") == "missing"
    assert float(cases["pass.root"].get("time") or 0) > 0


@pytest.mark.parametrize("kind", ["json", "csv"])
def test_the_report_has_a_row_per_program_with_outcome_time_and_first_difference(
    submissions: Path, kind: str
) -> None:
    report = submissions / f"report.{kind}"
    assert main(["test", str(submissions), "--report", str(report)]) == 1
    text = report.read_text(encoding="utf-8")
    if kind == "json":
        rows = json.loads(text)["programs"]
    else:
        rows = list(csv.DictReader(text.splitlines()))
    by_name = {Path(str(row["program"])).name: row for row in rows}
    assert [str(by_name[n]["outcome"]) for n in ("differs.root", "new.root", "pass.root")] == [
        "failed",
        "missing",
        "passed",
    ]
    assert float(by_name["pass.root"]["seconds"]) > 0
    difference = str(by_name["differs.root"]["first_difference"])
    assert (
        difference.startswith("line ") and "expected" in difference and "move 50 mm" in difference
    )
    assert by_name["pass.root"]["first_difference"] in (None, "")


def test_a_report_of_another_kind_is_refused_before_anything_runs(
    submissions: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["test", str(submissions), "--report", str(submissions / "r.txt")]) == 1
    captured = capsys.readouterr()
    assert "must end in .json or .csv, not .txt" in captured.err
    assert "programs in" not in captured.out  # nothing was tested
    assert not (submissions / "r.txt").exists()


def test_shards_split_every_program_once_the_same_way_everywhere() -> None:
    programs = [Path(f"class/{name}.root") for name in "qwertyuiopasdfghjklzxcvbnm"]
    shares = [shard(programs, k, 4) for k in range(1, 5)]
    assert sorted(p for share in shares for p in share) == sorted(programs)
    assert {len(share) for share in shares} == {6, 7}
    assert shard(list(reversed(programs)), 2, 4) == shares[1]  # the listing order doesn't matter


def test_the_shard_option_runs_only_its_share(
    submissions: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    report = submissions / "r.json"
    tested: list[str] = []
    for k in (1, 2):
        main(["test", str(submissions), "--shard", f"{k}/2", "--report", str(report)])
        tested += [row["program"] for row in json.loads(report.read_text("utf-8"))["programs"]]
    assert sorted(Path(p).name for p in tested) == ["differs.root", "new.root", "pass.root"]
    with pytest.raises(SystemExit):
        main(["test", str(submissions), "--shard", "3/2"])
    assert "like 2/8" in capsys.readouterr().err
