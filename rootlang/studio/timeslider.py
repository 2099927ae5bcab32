"""The time slider's data: a simulated run's moments, for the page to go back to any of them.

The worker records every run's :class:`~rootlang.runtime.timeline.Timeline` as it goes (a
few tuples a statement). A paused run sends it when the page asks (``("debug", {"action":
"timeline"})``: the page's slider, once it is moved), with the stage so far; an ended run sends
it in its outcome (its stage is there already). The page then moves through the run by itself,
without asking again: the robot and the drawing from the stage's frames and ink (each point
has its time), the scripts' lines and the values from the timeline, the events from the
child's view of the trace. See docs/studio.md, "Going back in time".
"""

from __future__ import annotations

from rootlang.app.session import Simulation
from rootlang.protocol.behaviour import Actuator
from rootlang.runtime.timeline import Timeline
from rootlang.runtime.trace import TraceEntry, ViewLine
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages

POSE_HOLES = {"x": "{x}", "y": "{y}", "heading": "{heading}"}  # filled in by the page


class GoingBack:
    """One simulated run's timeline, and what the page needs besides to show its moments."""

    def __init__(
        self,
        simulation: Simulation,
        trace: list[TraceEntry],
        languages: Languages,
    ) -> None:
        self.timeline = Timeline()
        self._simulation = simulation
        self._trace = trace  # the run's, as it grows
        self._languages = languages

    def to_json(self, story: list[ViewLine]) -> dict[str, object]:
        """The moments so far, in the page's words, with the times and lines of the child's
        view of the run (``story``: its lines as :func:`~rootlang.studio.worker.child_story`
        makes them)."""
        languages = self._languages
        robot_time = self._simulation.sim_transport.robot_time()
        return {
            **self.timeline.to_json(languages),
            # the robot's recording counts from its switching on; the run, from its start
            "recording_offset_ms": round((robot_time - self.timeline.now()) * 1000),
            "pose_words": message("V205", POSE_HOLES, languages),
            "motions": [
                [entry.time_ms, entry.end_ms, entry.line]
                for entry in list(self._trace)  # (the sampling thread reads it too)
                if entry.kind == "command" and entry.group == Actuator.MOTION.value and entry.line
            ],
            "story": [[line.time_ms, line.line] for line in story],
        }
