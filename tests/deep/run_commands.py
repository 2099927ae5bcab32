"""Run rootlang commands one after another in this process, each twice: on the main thread and
on a thread with a 1 MB stack (what Windows gives a program's main thread). Each command's
result is one JSON line on stdout, so a crash (exit -11) shows after which command it came.

Usage: ``python run_commands.py '["check", "a.root"]' '["sim", "a.root"]' ...``; a command as
``{"args": [...], "out": "file"}`` writes its whole output to ``file`` too (for the next one)."""

from __future__ import annotations

import contextlib
import io
import json
import sys
import threading

from rootlang.cli import main

THREAD_STACK_BYTES = 1024 * 1024


def _run(arguments: list[str], where: str) -> str:
    print(json.dumps({"start": arguments, "where": where}), flush=True)
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(arguments)
    result = {"command": arguments, "where": where, "exit": code}
    print(json.dumps({**result, "stdout": _clip(out.getvalue()), "stderr": _clip(err.getvalue())}))
    sys.stdout.flush()
    return out.getvalue()


def _clip(text: str) -> str:
    return text if len(text) < 6000 else f"{text[:3000]} … {text[-3000:]}"


def _on_small_thread(arguments: list[str]) -> None:
    threading.stack_size(THREAD_STACK_BYTES)
    thread = threading.Thread(target=_run, args=(arguments, "thread"))
    thread.start()
    thread.join()


if __name__ == "__main__":
    for argument in sys.argv[1:]:
        command = json.loads(argument)
        arguments = command["args"] if isinstance(command, dict) else command
        said = _run(arguments, "main")
        if isinstance(command, dict):
            with open(command["out"], "w", encoding="utf-8") as out:
                out.write(said)
        _on_small_thread(arguments)
