"""Run-time defects found by trying rootlang as an attacker would: each a small program."""

from __future__ import annotations

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


def test_calls_too_deep_for_python_are_a_clear_error_not_an_internal_one() -> None:
    ran = run_root(_deep_procedure(nested=200, calls=99))
    assert ran.result.error is not None
    assert ran.result.error.code == "E215"
