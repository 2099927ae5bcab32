"""`rootlang sim --watch NAME...` tells each change of those values in the run's story;
`rootlang sim --until SECONDS` stops the run there and says where everything is (worksheets:
"where is the robot after 2 s?")."""

from __future__ import annotations

from pathlib import Path

import pytest

from rootlang.cli import main

PROGRAMS = Path(__file__).resolve().parents[2] / "programs"


def _lines(capsys: pytest.CaptureFixture[str]) -> list[str]:
    return [" ".join(line.split()) for line in capsys.readouterr().out.splitlines()]


def test_watch_tells_each_change_on_the_line_that_made_it(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["sim", str(PROGRAMS / "countdown.root"), "--watch", "n"]) == 0
    lines = _lines(capsys)
    assert lines[:5] == [
        "0.0 s line 2 when started",
        "0.0 s line 3 n is now 5",
        '0.0 s line 5 print "5"',
        "0.0 s line 6 play note A4 for 0.2 seconds",
        "0.2 s line 7 n is now 4",
    ]
    assert [line for line in lines if "n is now" in line][-1] == "1.0 s line 7 n is now 0"


def test_until_stops_there_and_says_every_script_the_values_and_the_pose(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["sim", str(PROGRAMS / "square.root"), "--until", "2"]) == 0
    lines = _lines(capsys)
    at = lines.index("After 2.0 s:")
    assert lines[at - 2 : at] == ["2.0 s stopped by the time limit of 2 s", ""]
    assert lines[at + 1 : at + 3] == [
        "`when started`: waiting for `turn right 90 degrees` to end (line 6)",
        "The loop on line 4 is in round 1 of 4.",
    ]
    assert lines[-1] == "The robot is at x 0 cm, y 10 cm, heading 66°."


def test_until_speaks_the_childs_language(capsys: pytest.CaptureFixture[str]) -> None:
    program = PROGRAMS / "messages.root"
    assert main(["--language", "nl", "sim", str(program), "--until", "2.5"]) == 0
    lines = _lines(capsys)
    at = lines.index("Na 2.5 s:")
    assert lines[at + 1] == "`wanneer gestart`: klaar"
    assert (
        '`wanneer bericht "dance" ontvangen`: wacht tot `draai links 360 graden` klaar is'
        in (lines[at + 4])
    )
    assert 'Bericht "go" is verstuurd door `wanneer gestart`.' in lines


@pytest.mark.parametrize("seconds", ["0", "-3", "soon", "nan"])
def test_until_needs_a_time_above_zero(seconds: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["sim", str(PROGRAMS / "square.root"), "--until", seconds])
    assert "is not a number of seconds above 0" in capsys.readouterr().err
