"""Run-time defects found by trying rootlang as an attacker would: each a small program."""

from __future__ import annotations

import os
import resource
import subprocess
import sys
from pathlib import Path

import pytest
from runtime_helpers import run_root


def test_a_number_grown_too_big_is_an_error_at_the_line_that_made_it() -> None:
    ran = run_root(
        """
        when started
            set x to 10
            repeat 400
                set x to x * x
            move x mm
        """
    )
    assert ran.result.error is not None
    assert ran.result.error.code == "E214"
    assert ran.result.error.span.line == 4


def test_a_failing_when_condition_stops_the_run_with_an_error() -> None:

    ran = run_root(
        """
        when started
            set x to 10
            forever
                set x to x * x
        when sin (x * 1 degrees) > 2
            print "never"
        """
    )
    assert ran.result.end == "error"
    assert ran.result.error is not None and ran.result.error.code == "E214"


def test_stop_other_scripts_before_the_others_ran_lets_the_program_end() -> None:

    ran = run_root(
        """
        when started
            stop other scripts
        when started
            print "second"
        """,
        time_limit=None,
    )
    assert ran.result.end == "finished"


def _deep_procedure(nested: int, calls: int) -> str:
    lines = ["to down n"]
    for level in range(nested):
        lines.append("    " * (level + 1) + ("if n > 0" if level == 0 else "if true"))
    brackets = nested + 2
    lines.append("    " * (nested + 1) + "down " + "(" * brackets + "n - 1" + ")" * brackets)
    lines += ["when started", f"    down {calls}", '    print "ok"']
    return "\n".join(lines)


def test_99_calls_with_blocks_and_brackets_inside_stay_within_the_documented_limit() -> None:
    ran = run_root(_deep_procedure(nested=4, calls=99))
    assert ran.result.error is None
    assert ran.printed == ["ok"]
    too_many = run_root(_deep_procedure(nested=4, calls=100))
    assert too_many.result.error is not None and too_many.result.error.code == "E206"


def test_blocks_inside_99_calls_nest_on_the_interpreters_own_stack() -> None:
    ran = run_root(_deep_procedure(nested=90, calls=99))
    assert ran.result.error is None
    assert ran.printed == ["ok"]


def _deep_value(inside: int) -> str:
    """``down`` gives its value from inside ``inside`` calculations around its own call."""
    value = "1 + (" * inside + "down (n - 1)" + ")" * inside
    return f"to down n\n    if n > 0\n        return {value}\n    return 0\n" + (
        "when started\n    print down 99\n"
    )


def test_values_called_from_deep_calculations_stop_with_e215_at_the_interpreters_count() -> None:
    ran = run_root(_deep_value(inside=40))
    assert ran.result.error is not None
    assert ran.result.error.code == "E215"
    assert ran.result.error.span.line == 3
    # the first call (from `print`) counts 6 of the 800 coroutines, each one from inside 40
    # calculations 46 more: the 19th would pass the limit
    assert "called itself 19 times" in ran.result.error.english
    assert run_root(_deep_value(inside=2)).printed == ["198"]


def test_memory_run_out_in_the_simulator_is_the_programs_doing_not_ours(tmp_path: Path) -> None:
    program = tmp_path / "grow.root"
    program.write_text(
        'when started\n    set s to "ab"\n    forever\n        set s to join(s, s)\n',
        encoding="utf-8",
    )

    def small_memory() -> None:
        cap = 600 * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (cap, cap))

    done = subprocess.run(
        [sys.executable, "-m", "rootlang", "sim", str(program)],
        capture_output=True, text=True, preexec_fn=small_memory, timeout=120,
        env={**os.environ, "XDG_CACHE_HOME": str(tmp_path)},
    )  # fmt: skip
    assert "line 4:" in done.stderr + done.stdout
    assert "more memory than this computer could give it" in done.stderr + done.stdout
    assert "inside rootlang itself" not in done.stderr + done.stdout


def test_ctrl_c_while_rootlang_is_still_starting_up_is_a_clean_stop() -> None:
    # Ctrl-C lands while the command line is being imported (the first ~45 ms): made certain
    # here by an import that raises KeyboardInterrupt, as the signal would.
    script = (
        "import builtins, sys\n"
        "real = builtins.__import__\n"
        "def interrupted(name, *args, **kwargs):\n"
        "    if name == 'rootlang.cli':\n"
        "        raise KeyboardInterrupt\n"
        "    return real(name, *args, **kwargs)\n"
        "builtins.__import__ = interrupted\n"
        "from rootlang.__main__ import entry\n"
        "sys.exit(entry())\n"
    )
    done = subprocess.run(
        [sys.executable, "-c", script], capture_output=True, text=True, timeout=60
    )
    assert done.returncode == 130
    assert done.stderr.strip() == "Stopped (Ctrl-C)."


@pytest.mark.parametrize(
    "line",
    [
        "move (x * x) mm",
        "repeat x * x\n        wait 1 ms",
        "print round (x * x)",
        "print sin (x * x * 1 degrees)",
        "print (x * x) mod 3",
        "print random 1 to x * x",
        "light on rgb (x * x) 0 0",
        "play (x * x) Hz for 1 second",
        "wait (x * x - x * x) seconds",
    ],
)
def test_a_number_too_big_is_caught_where_it_is_made_in_every_command(line: str) -> None:
    grown = "    set x to 10\n    repeat 8\n        set x to x * x\n"  # 10 ** 256: still a number
    ran = run_root(f"when started\n{grown}    {line}\n")
    assert ran.result.error is not None
    assert (ran.result.error.code, ran.result.error.span.line) == ("E214", 5)


def test_memory_run_out_outside_a_statement_is_the_programs_not_a_bug_of_ours() -> None:
    from rootlang.runtime.scheduler import _unexpected

    assert _unexpected(MemoryError()).diagnostics[0].code == "E216"  # (as inside a statement)
    assert _unexpected(ValueError("x")).diagnostics[0].code == "E699"
