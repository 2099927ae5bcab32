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
from pathlib import Path
from typing import Any

RUNNER = Path(__file__).with_name("run_commands.py")
STACK_BYTES = 1024 * 1024


def _small_stack() -> None:
    _, hard = resource.getrlimit(resource.RLIMIT_STACK)
    soft = STACK_BYTES if hard == resource.RLIM_INFINITY else min(STACK_BYTES, hard)
    resource.setrlimit(resource.RLIMIT_STACK, (soft, hard))


def run_commands(*commands: list[str]) -> list[dict[str, Any]]:
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
