"""How a run ended and what stopped it, kept as data until it is shown.

The scheduler records a :class:`StoppedBy` (a :class:`StopReason` and its values) and the run's
last trace entry carries it as a :class:`RunEnded`; each edge puts it into words: the trace and
golden files in the catalogue's English (:meth:`StoppedBy.english`, the same on every computer),
the child's view and the studio in the languages they are handed (:meth:`StoppedBy.shown`),
JSON as its reason's name and values (:meth:`StoppedBy.to_json`). A run's error is kept the same
way, as its diagnostic (:class:`Failed`).
"""

from __future__ import annotations

from dataclasses import dataclass
from enum import Enum
from typing import Literal

from rootlang.diagnostics import Diagnostic
from rootlang.messages import MESSAGES
from rootlang.wording.catalogue import message
from rootlang.wording.language import Languages

End = Literal["finished", "stopped", "time_limit", "error", "disconnected"]


class StopReason(Enum):
    """What stopped a run (its value names it in JSON)."""

    FINISHED = "finished"  # every script finished
    STOP_ALL = "stop_all"  # the program's `stop all`
    ROBOT_STOP_BUTTON = "robot_stop_button"
    CTRL_C = "ctrl_c"
    CANCELLED = "cancelled"  # the run's caller gave up on it
    TIME_LIMIT = "time_limit"
    RUN_ERROR = "run_error"
    STOP_BUTTON = "stop_button"  # the studio's
    STUDIO = "studio"
    PAGE_CLOSED = "page_closed"
    PAGE_LINK_DROPPED = "page_link_dropped"  # the page's Bluetooth link to its robot
    PAGE_LOST_STUDIO = "page_lost_studio"
    # the page stopped its robot itself (its own safety rules, docs/studio.md), and said so
    PAGE_STOPPED_QUIET = "page_stopped_quiet"  # the studio said nothing for `seconds`
    PAGE_STOPPED_HIDDEN = "page_stopped_hidden"  # the tab was hidden for `seconds`
    PAGE_STOPPED_LATE = "page_stopped_late"  # the run had not stopped `seconds` after Stop
    TEACHER = "teacher"  # the teacher's "stop every run"
    REPLACED = "replaced"  # the same pupil started a new run (the studio's places for runs)
    LINK = "link"  # the robot's link dropped, in the link's own words

    @property
    def code(self) -> str:
        """The catalogue's message that says it ("" for the link's own words)."""
        return _CODES[self]


_CODES = {
    StopReason.FINISHED: "V020", StopReason.STOP_ALL: "V021",
    StopReason.ROBOT_STOP_BUTTON: "V022", StopReason.CTRL_C: "V023",
    StopReason.CANCELLED: "V024", StopReason.TIME_LIMIT: "V025", StopReason.RUN_ERROR: "V026",
    StopReason.STOP_BUTTON: "V027", StopReason.STUDIO: "V028", StopReason.PAGE_CLOSED: "V029",
    StopReason.PAGE_LINK_DROPPED: "V031", StopReason.PAGE_LOST_STUDIO: "V032",
    StopReason.PAGE_STOPPED_QUIET: "V033", StopReason.PAGE_STOPPED_HIDDEN: "V034",
    StopReason.PAGE_STOPPED_LATE: "V035",
    StopReason.TEACHER: "V058", StopReason.REPLACED: "V075", StopReason.LINK: "",
}  # fmt: skip


@dataclass(frozen=True)
class StoppedBy:
    """What stopped a run: the reason, the time limit's ``seconds``, or the link's ``words``."""

    reason: StopReason
    seconds: float | None = None  # TIME_LIMIT, PAGE_STOPPED_*
    words: str = ""  # LINK

    @classmethod
    def link(cls, why: str | StoppedBy) -> StoppedBy:
        """A dropped link: rootlang's own reason as it is (the studio ended a page's link: it
        hands it on as data, so the child reads it in their language), else the transport's
        words."""
        return why if isinstance(why, StoppedBy) else cls(StopReason.LINK, words=why)

    def _values(self) -> dict[str, object]:
        return {} if self.seconds is None else {"seconds": f"{self.seconds:g}"}

    def english(self) -> str:
        """In the catalogue's English, as the trace records it."""
        if self.reason is StopReason.LINK:
            return self.words
        return MESSAGES[self.reason.code].format(**self._values())

    def shown(self, languages: Languages) -> str:
        """As ``languages`` show messages."""
        if self.reason is StopReason.LINK:
            return self.words
        return message(self.reason.code, self._values(), languages)

    def to_json(self) -> dict[str, object]:
        data: dict[str, object] = {"reason": self.reason.value}
        if self.seconds is not None:
            data["seconds"] = self.seconds
        if self.words:
            data["words"] = self.words
        return data

    @classmethod
    def from_json(cls, data: object) -> StoppedBy | None:
        """Back from :meth:`to_json` (None: not one)."""
        if not isinstance(data, dict):
            return None
        try:
            reason = StopReason(data.get("reason"))
        except ValueError:
            return None
        seconds, words = data.get("seconds"), data.get("words", "")
        if not (seconds is None or isinstance(seconds, int | float)) or not isinstance(words, str):
            return None
        return cls(reason, None if seconds is None else float(seconds), words)

    def outcome(self) -> dict[str, object]:
        """The outcome's keys that tell it: ``stopped_by`` in English, ``stop`` as data."""
        return {"stopped_by": self.english(), "stop": self.to_json()}


@dataclass(frozen=True)
class RunEnded:
    """The run's last trace entry: how it ended and what stopped it."""

    end: End
    by: StoppedBy

    def english(self) -> str:
        return f"ended: {self.end} ({self.by.english()})"

    def shown(self, languages: Languages) -> str:
        """In a child's words: "the end: every script finished"."""
        if self.end == "error":
            return message("V002", {}, languages)
        code = {"finished": "V001", "disconnected": "V003"}.get(self.end, "V004")
        return message(code, {"by": self.by.shown(languages)}, languages)

    def to_json(self) -> dict[str, object]:
        return {"end": self.end, "by": self.by.to_json()}


@dataclass(frozen=True)
class Connected:
    """The run's first trace entry: which robot, speaking which protocol version."""

    robot: str
    version: str

    def english(self) -> str:
        return MESSAGES["V030"].format(robot=self.robot, version=self.version)

    def shown(self, languages: Languages) -> str:
        return message("V030", {"robot": self.robot, "version": self.version}, languages)

    def to_json(self) -> dict[str, object]:
        return {"robot": self.robot, "version": self.version}


@dataclass(frozen=True)
class Failed:
    """A run's error entry: the mistake that stopped it (or a `when stopped` script's), its
    message put into words only where it is shown."""

    error: Diagnostic

    def english(self) -> str:
        return self.error.english

    def shown(self, languages: Languages) -> str:
        return self.error.shown(languages)

    def to_json(self) -> dict[str, object]:
        return {"code": self.error.code}


Record = RunEnded | Connected | Failed  # what a run's own entries carry
