"""`rootlang test`: golden files written, passed, failed with a diff and the program line,
updated, missing; and a program's simulated time limit, wall-clock limit and memory cap."""

from __future__ import annotations

import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from rootlang.app.sandbox import Limits
from rootlang.cli import main
from rootlang.testing.produce import produce
from rootlang.testing.runner import Settings, Verdict, run_golden_tests

pytestmark = pytest.mark.skipif(sys.platform == "win32", reason="needs fork and resource")

SHORT = """\
# short.root: a little program for the runner's tests
when started
    move 5 cm
    print "done"
"""
LONG = "# world: long.toml\nwhen started\n    forever\n        turn left 10 degrees\n"


def _program(folder: Path, text: str = SHORT, name: str = "short.root") -> Path:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return path


def _rootlang(capsys: pytest.CaptureFixture[str], *args: str) -> tuple[int, str]:
    status = main(["test", *args])
    captured = capsys.readouterr()
    return status, captured.out + captured.err


def test_update_writes_the_golden_file_then_the_program_passes(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = _program(tmp_path)
    status, output = _rootlang(capsys, "--update", str(tmp_path))
    assert status == 0, output
    golden = program.with_suffix(".golden").read_text(encoding="utf-8")
    assert golden.startswith("end: finished at ")
    assert "done" in golden and "robot at the end, in the world: x 1000 mm, y 1050 mm" in golden
    status, output = _rootlang(capsys, str(program))
    assert status == 0, output
    assert "1 program in" in output and "1 passed" in output


def test_a_mismatch_shows_a_diff_and_the_program_line_behind_it(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = _program(tmp_path)
    assert _rootlang(capsys, "--update", str(program))[0] == 0
    _program(tmp_path, SHORT.replace('print "done"', 'print "all done"'))
    status, output = _rootlang(capsys, str(program))
    assert status == 1
    assert f"FAILED {program}: its output differs from {tmp_path / 'short.golden'}" in output
    assert "The first difference comes from line 4 of short.root:" in output
    assert '       4 |     print "all done"' in output
    assert "+++ this run" in output
    assert any(line.startswith("+") and "all done" in line for line in output.splitlines())
    assert any(line.startswith("-") and '"done"' in line for line in output.splitlines())
    # --update accepts the new output; then it passes again.
    assert _rootlang(capsys, "--update", str(program))[0] == 0
    assert "all done" in program.with_suffix(".golden").read_text(encoding="utf-8")
    assert _rootlang(capsys, str(program))[0] == 0


def test_a_program_without_a_golden_file_fails_and_says_how_to_make_one(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    _program(tmp_path)
    status, output = _rootlang(capsys, str(tmp_path))
    assert status == 1
    assert "There is no golden file" in output and "--update" in output
    assert not (tmp_path / "short.golden").exists()


def test_a_program_with_mistakes_is_compared_with_what_check_says(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = _program(tmp_path, "when started\n    mve 10 cm\n", "typo.root")
    produced = produce(program)
    assert produced.end == "check"
    assert main(["check", str(program)]) == 1
    checked = capsys.readouterr()
    assert produced.text == checked.err.replace(str(program), program.name)
    assert produced.source_lines[0] == 2


def test_the_simulated_time_limit_ends_a_program_that_never_stops(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    program = _program(tmp_path, "when started\n    forever\n        turn left 10 degrees\n")
    produced = produce(program, time_limit=1.5)
    assert produced.end == "time_limit"
    assert produced.text.startswith("end: reached the time limit at 1.500 s")
    status, output = _rootlang(capsys, "--update", "--time-limit", "1.5", str(program))
    assert status == 0
    assert "(1 ran until their simulated time limit)" in output


def test_the_cpu_time_limit_stops_a_program_that_computes_too_long(tmp_path: Path) -> None:
    (tmp_path / "long.toml").write_text("time_limit = 100000\n", encoding="utf-8")
    program = _program(tmp_path, LONG, "long.root")
    settings = Settings(limits=Limits(cpu_seconds=1))
    (result,) = run_golden_tests([program], settings)
    assert result.verdict is Verdict.CPU_LIMIT
    assert "still computing after 1 s of the computer's time" in result.report
    assert "loop forever" in result.report
    assert result.headline == f"FAILED {program}: over the CPU-time limit"


def test_the_wall_clock_backstop_never_blames_the_program(tmp_path: Path) -> None:
    (tmp_path / "long.toml").write_text("time_limit = 100000\n", encoding="utf-8")
    program = _program(tmp_path, LONG, "long.root")
    settings = Settings(limits=Limits(cpu_seconds=60, wall_seconds=0.5))
    (result,) = run_golden_tests([program], settings)
    assert result.verdict is Verdict.WALL_LIMIT
    assert "too busy to finish testing this program within 0.5 s" in result.report
    assert "not the program's fault" in result.report
    assert result.headline.startswith(f"NOT FINISHED {program}: the computer was too busy")


def test_the_memory_cap_stops_a_program_that_eats_memory(tmp_path: Path) -> None:
    program = _program(
        tmp_path,
        'when started\n    set s to "0123456789"\n    forever\n        set s to join(s, s)\n',
        "greedy.root",
    )
    settings = Settings(limits=Limits(wall_seconds=30, memory_mb=150))
    (result,) = run_golden_tests([program], settings)
    assert result.verdict is Verdict.MEMORY_LIMIT
    assert "more memory than its cap of 150 MB" in result.report


def test_a_missing_path_is_a_clear_error(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, output = _rootlang(capsys, str(tmp_path / "nothing-here"))
    assert status == 1
    assert "I can't find the file" in output and "Traceback" not in output


def test_ctrl_c_stops_the_run_and_its_workers(tmp_path: Path) -> None:
    (tmp_path / "long.toml").write_text("time_limit = 100000\n", encoding="utf-8")
    _program(tmp_path, LONG, "long.root")
    command = [sys.executable, "-m", "rootlang", "test", str(tmp_path)]
    pipe = subprocess.PIPE
    with subprocess.Popen(command, stdout=pipe, stderr=pipe, text=True) as run:
        _wait_for_a_worker(run.pid)  # (a Ctrl-C before rootlang has begun is Python's own)
        run.send_signal(signal.SIGINT)
        _out, err = run.communicate(timeout=60)  # (a hang's bound, never a speed)
    assert run.returncode == 130
    assert "Stopped (Ctrl-C)." in err and "Traceback" not in err


def _wait_for_a_worker(pid: int, seconds: float = 60) -> None:
    """Until the process ``pid`` has started a worker of its own (Linux: its children in /proc)."""
    children = Path(f"/proc/{pid}/task/{pid}/children")
    deadline = time.monotonic() + seconds
    while not children.read_text(encoding="ascii").split():
        assert time.monotonic() < deadline, "no worker started"
        time.sleep(0.05)


def test_a_folder_without_programs_is_an_error_not_a_pass(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    status, output = _rootlang(capsys, str(tmp_path))
    assert status == 1
    assert "I found no .root programs in" in output


def test_a_program_that_is_not_text_is_reported_not_crashed(tmp_path: Path) -> None:
    program = tmp_path / "binary.root"
    program.write_bytes(b'when started\n    say "\xff\xfe"\n')
    produced = produce(program)
    assert produced.end == "check"
    assert produced.text.startswith("binary.root isn't plain text, so it can't be a program.")


@pytest.mark.parametrize("language", ["nl", "es", "fr", "de"])
def test_the_report_speaks_the_commands_language(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], language: str
) -> None:
    """Headlines, the line behind a difference, the diff's labels, `updated` and the summary
    come from the catalogue: a Dutch class's report was Dutch only where a message was."""
    from rootlang.wording.catalogue import message
    from rootlang.wording.language import Languages

    languages = Languages(chosen=language)
    program = _program(tmp_path)
    missing = _program(tmp_path, SHORT, "new.root")
    status, output = _rootlang(capsys, "--language", language, "--update", str(program))
    golden = program.with_suffix(".golden")
    assert message("V114", {"golden": str(golden)}, languages) in output
    _program(tmp_path, SHORT.replace('print "done"', 'print "all done"'))
    status, output = _rootlang(capsys, "--language", language, str(program), str(missing))
    assert status == 1
    for english in ("FAILED", "differs", "first difference", "this run", "programs in", "failed",
                    "no golden file", "If the new output"):  # fmt: skip
        assert english not in output, english
    said = {"program": str(program), "golden": str(golden)}
    assert message("V111", said, languages) in output
    assert message("V110", {"program": str(missing), "reason": message("V103", {}, languages)},
                   languages) in output  # fmt: skip
    assert message("V115", {"line": 4, "program": "short.root"}, languages) in output
