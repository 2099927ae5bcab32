"""Deep and long programs through every command, each command in a process of its own with a
1 MB stack (the main thread's, as `ulimit -s 1024` sets it, and a 1 MB thread's): a crash of
Python's C stack shows as the process dying (exit -11, 139 in a shell), never passes unseen.
`.ci/run` runs this file again under the machine's own /usr/bin/python3 and `ulimit -s 1024`
(docs/runtime.md, "Depth")."""

from __future__ import annotations

import json
import resource
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from rootlang import jsontree

RUNNER = Path(__file__).with_name("run_commands.py")
STACK_BYTES = 1024 * 1024


def _small_stack() -> None:
    _, hard = resource.getrlimit(resource.RLIMIT_STACK)
    soft = STACK_BYTES if hard == resource.RLIM_INFINITY else min(STACK_BYTES, hard)
    resource.setrlimit(resource.RLIMIT_STACK, (soft, hard))


def run_commands(*commands: list[str] | dict[str, Any]) -> list[dict[str, Any]]:
    """Each command's result (exit code and output), on the main thread and on a 1 MB thread;
    fails the test if the process crashed or a command failed inside rootlang (E699)."""
    arguments = [json.dumps(command) for command in commands]
    done = subprocess.run(
        [sys.executable, str(RUNNER), *arguments],
        capture_output=True, text=True, timeout=300, preexec_fn=_small_stack,
    )  # fmt: skip
    lines = [json.loads(line) for line in done.stdout.splitlines() if line.startswith("{")]
    last = lines[-1] if lines else {}
    assert done.returncode == 0, f"the process died ({done.returncode}) in {last}: {done.stderr}"
    results = [line for line in lines if "exit" in line]
    assert len(results) == 2 * len(commands)
    for result in results:
        output = result["stdout"] + result["stderr"]
        assert result["exit"] in (0, 1), result
        assert "E699" not in output and "Traceback" not in output, result
    return results


def _write(folder: Path, name: str, text: str) -> str:
    path = folder / name
    path.write_text(text, encoding="utf-8")
    return str(path)


def deep_procedure(nested: int, calls: int) -> str:
    """``down`` calls itself ``calls`` times from inside ``nested`` blocks."""
    lines = ["to down n"]
    for level in range(nested):
        lines.append("    " * (level + 1) + ("if n > 0" if level == 0 else "if true"))
    lines.append("    " * (nested + 1) + "down (n - 1)")
    lines += ["when started", f"    down {calls}", '    print "ok"']
    return "\n".join(lines) + "\n"


def test_100_nested_blocks_inside_99_calls_check_and_run(tmp_path: Path) -> None:
    program = _write(tmp_path, "deep.root", deep_procedure(nested=100, calls=99))
    checked, _, ran, _ = run_commands(["check", program], ["sim", program])
    assert checked["exit"] == 0
    assert ran["exit"] == 0 and 'print "ok"' in ran["stdout"], ran


def test_values_from_deep_calculations_stop_with_e215_not_a_crash(tmp_path: Path) -> None:
    value = "1 + (" * 60 + "down (n - 1)" + ")" * 60
    text = f"to down n\n    if n > 0\n        return {value}\n    return 0\n"
    program = _write(tmp_path, "value.root", text + "when started\n    print down 99\n")
    for ran in run_commands(["sim", program]):
        assert ran["exit"] == 1 and "ran out of room" in ran["stderr"], ran  # E215


def nested_ifs(count: int) -> str:
    lines = [" " * 4 * (level + 1) + "if true" for level in range(count)]
    return "\n".join(["when started", *lines, " " * 4 * (count + 1) + 'print "deep"']) + "\n"


TOO_DEEP = "inside too many things"  # E018


def test_300_nested_ifs_are_e018_at_the_101st_in_every_command(tmp_path: Path) -> None:
    program = _write(tmp_path, "ifs.root", nested_ifs(300))
    commands = [["check", program], ["sim", program], ["blocks", program]]
    for result in run_commands(*commands, ["format", "--check", program]):
        assert result["exit"] == 1, result
        said = result["stdout"] + result["stderr"]  # (`blocks` says it as JSON)
        if result["command"][0] != "format":
            assert ("line 102:" in said or '"line": 102' in said) and TOO_DEEP in said, result


def test_100_nested_ifs_and_100_calculations_go_through_every_command(tmp_path: Path) -> None:
    calculation = "(1 cm + " * 100 + "1 cm" + ")" * 100
    text = nested_ifs(100).replace('print "deep"', f"move {calculation}")
    program = _write(tmp_path, "deep.root", text)
    translated = str(tmp_path / "diep.root")
    commands = [["check", program], ["sim", program], ["blocks", program], ["format", program]]
    for result in run_commands(*commands, ["translate", program, "--to", "nl", "-o", translated]):
        assert result["exit"] == 0, result


def test_a_245_deep_calculation_is_e018_at_its_line(tmp_path: Path) -> None:
    calculation = "(1 cm + " * 245 + "1 cm" + ")" * 245
    program = _write(tmp_path, "calc.root", f"when started\n    print 1\n    move {calculation}\n")
    for result in run_commands(["check", program], ["sim", program], ["blocks", program]):
        said = result["stdout"] + result["stderr"]
        assert result["exit"] == 1 and ("line 3:" in said or '"line": 3' in said), result
        assert TOO_DEEP in said, result


def test_long_else_if_chains_have_no_limit(tmp_path: Path) -> None:
    chain = "".join(f"    else if x = {n}\n        print {n}\n" for n in range(1, 2000))
    text = f"when started\n    set x to 1999\n    if x = 0\n        print 0\n{chain}"
    program = _write(tmp_path, "chain.root", text)
    checked, _, ran, _, blocks, _, formatted, _ = run_commands(
        ["check", program], ["sim", program], ["blocks", program], ["format", "--check", program]
    )
    assert checked["exit"] == ran["exit"] == blocks["exit"] == formatted["exit"] == 0
    assert 'print "1999"' in ran["stdout"] or "print 1999" in ran["stdout"], ran


def test_4000_and_40000_unclosed_brackets_are_checked_in_linear_time(tmp_path: Path) -> None:
    short = _write(tmp_path, "short.root", "when started\n    move " + "(" * 4000 + "1 cm\n")
    long = _write(tmp_path, "long.root", "when started\n    move " + "(" * 40000 + "1 cm\n")
    for result in run_commands(["check", short], ["check", long]):
        assert result["exit"] == 1 and "stops too early" in result["stderr"], result
    # the CPU time the commands' process took, not the wall clock's: a busy machine stretches
    # one run and not the other
    ten_times = _cpu_seconds_of(lambda: run_commands(["check", long]))
    once = _cpu_seconds_of(lambda: run_commands(["check", short]))
    assert ten_times < 4 * once + 2.0, (once, ten_times)  # quadratic would be 100 times


def _cpu_seconds_of(work: Callable[[], object]) -> float:
    """The CPU time (user and system) of the child processes ``work`` ran and waited for."""

    def children() -> float:
        used = resource.getrusage(resource.RUSAGE_CHILDREN)
        return used.ru_utime + used.ru_stime

    before = children()
    work()
    return children() - before


def test_flat_scripts_of_500_and_2000_lines_go_through_every_command(tmp_path: Path) -> None:
    for lines in (500, 2000):
        body = "".join(
            f"    move {n % 7 + 1} cm\n    turn left {n % 90} degrees\n" for n in range(lines // 2)
        )
        program = _write(tmp_path, f"flat{lines}.root", f"when started\n{body}")
        workspace, back = str(tmp_path / f"flat{lines}.json"), str(tmp_path / f"back{lines}.root")
        results = run_commands(
            ["check", program], ["format", "--check", program],
            ["translate", program, "--to", "fr", "-o", str(tmp_path / "fr.root")],
            {"args": ["blocks", program], "out": workspace},
            {"args": ["blocks", "--to-text", workspace], "out": back},
            ["sim", program],
        )  # fmt: skip
        assert all(result["exit"] == 0 for result in results[:10]), results
        assert Path(back).read_text(encoding="utf-8") == Path(program).read_text(encoding="utf-8")
        assert results[10]["exit"] in (0, 1) and "line 2" in results[10]["stdout"]  # sim ran


def test_a_1000_deep_workspace_and_a_huge_number_are_clear_errors(tmp_path: Path) -> None:
    block: dict[str, Any] = {"type": "root_stop_moving", "id": "end"}
    for n in range(1000):
        condition = {"block": {"type": "root_boolean", "id": f"v{n}", "fields": {"BOOL": "true"}}}
        block = {"type": "controls_if", "id": f"if{n}", "inputs": {"IF0": condition,
                 "DO0": {"block": block}}}  # fmt: skip
    length = {"type": "root_length", "id": "n", "fields": {"UNIT": "cm", "NUM": 10**400}}
    move = {"type": "root_move", "id": "m", "inputs": {"DISTANCE": {"block": length}}}
    files = []
    for name, body in (("deep", block), ("huge", move)):
        script = {"type": "root_when_started", "id": "top", "inputs": {"BODY": {"block": body}}}
        text = jsontree.dumps({"blocks": {"languageVersion": 0, "blocks": [script]}})
        files.append(_write(tmp_path, f"{name}.json", text))
    brackets = _write(tmp_path, "brackets.json", "[" * 100_000 + "]" * 100_000)
    commands = [["blocks", "--to-text", file] for file in (*files, brackets)]
    for result in run_commands(*commands):
        assert result["exit"] == 1 and result["stderr"].startswith(("E705", "E701")), result
