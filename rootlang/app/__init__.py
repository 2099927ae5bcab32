"""The application layer: what the command line (``rootlang.cli``), the studio
(``rootlang.studio``) and the golden tests (``rootlang.testing``) share, above the language,
the runtime, the simulator and Bluetooth, and below those three.

- :mod:`~rootlang.app.files` — finding and reading programs, the world a program names, the
  starter program;
- :mod:`~rootlang.app.session` — a program loaded (checked once) with its world; simulated (the
  one wiring of a simulated run); run on a robot; the outcome as JSON;
- :mod:`~rootlang.app.sandbox` — untrusted work in child processes under a wall-clock limit
  and a memory cap;
- :mod:`~rootlang.app.bluetooth` — which Bluetooth (the computer's, bumble's, the virtual robot);
- :mod:`~rootlang.app.faulty_link` — gallery programs behind a faulty link, judged.

Nothing below imports from here. Kept light: ``rootlang check`` loads ``files`` alone.
"""
