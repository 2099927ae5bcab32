"""rootlang studio: write, see and run programs as blocks or text, in the browser, offline.

- :mod:`rootlang.studio.folder` — the class folder: its ``.root`` files and their layout sidecars,
  and nothing outside it;
- :mod:`rootlang.studio.clock` — a wall clock scaled for 2×, 5×, 10× runs;
- :mod:`rootlang.studio.worker` — one simulated run in a worker process under the limits of
  ``rootlang test``, streaming what the robot does;
- :mod:`rootlang.studio.server` — the aiohttp web server: the page, the files, the block/text
  conversions and the WebSocket that runs programs;
- ``static/`` — the page (our own HTML, CSS and JS) and the vendored Blockly and CodeMirror
  (``scripts/vendor_web.py`` refreshes them).
"""
