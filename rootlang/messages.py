"""The one catalogue of messages people see, keyed by code.

Messages are written for a 10-year-old: say what happened and what to do, in plain words,
never a token name. Values in braces are filled in by the code that reports the problem.
Codes are grouped by the part of rootlang that reports them; keep each section sorted.

| range | reported by |
|---|---|
| E0xx | reading a program: syntax (rootlang.grammar) |
| E1xx | checking a program: names, units, events (rootlang.checks) |
| E2xx | running a program (rootlang.runtime) |
| E3xx | world files and the simulator (rootlang.sim) |
| E4xx | finding and talking to robots (rootlang.ble, transports) |
| E5xx | packets (rootlang.protocol) |
| E6xx | golden tests and the command line (rootlang.testing, rootlang.cli) |
| W1xx | warnings found while checking |
"""

from __future__ import annotations

MESSAGES: dict[str, str] = {
    # --- E0xx: syntax (rootlang.grammar) ---
    # --- E1xx: checks (rootlang.checks) ---
    # --- E2xx: run time (rootlang.runtime) ---
    # --- E3xx: worlds and the simulator (rootlang.sim) ---
    # --- E4xx: robots and connections (rootlang.ble) ---
    # --- E5xx: packets (rootlang.protocol) ---
    # --- E6xx: tests and the command line (rootlang.testing, rootlang.cli) ---
    "E601": "I can't find the file {path}.",
    "E602": "I can't read {path}: {reason}.",
    "E603": "Stopped (Ctrl-C).",
    "E699": "Something went wrong inside rootlang itself: {error}. "
    "This is our mistake, not yours. Run again with --debug and send the output to your teacher.",
    # --- W1xx: warnings (rootlang.checks) ---
}
