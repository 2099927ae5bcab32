"""Device 5, sound: notes, sweeps and spoken phrases, each answered when it ends."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from rootlang.protocol import Packet
from rootlang.sim.devices.base import Context, Handler, SimDevice
from rootlang.sim.recording import Note, Said

MILLIHERTZ = 1000  # spec: a sweep's frequencies are in mHz
SAY_LETTER_MS = 120  # chosen: saying a letter or digit takes this long ...
SAY_OTHER_MS = 60  # ... any other character this long ...
SAY_SHORTEST_MS = 200  # ... and any phrase at least this long


@dataclass
class _Playing:
    packet: Packet
    note: Note | None
    timer: int  # the number of its end timer


class Sound(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self._playing: _Playing | None = None
        self._pending_sweep: Packet | None = None  # a sweep to play when this sound ends

    def commands(self) -> Mapping[str, Handler]:
        return {
            "play_note": self._play_note,
            "stop_sound": self._stop_sound,
            "say_phrase": self._say_phrase,
            "play_sweep": self._play_sweep,
        }

    def stop(self, *, respond: bool) -> None:
        """Silence now (``respond``: answer the sound playing and the sweep waiting)."""
        playing, self._playing = self._playing, None
        pending, self._pending_sweep = self._pending_sweep, None
        robot = self.robot
        if playing is not None:
            robot.cancel(playing.timer)
            note = playing.note
            if note is not None:  # cut the recorded note short
                played = robot.now_ms - note.t_ms
                notes = robot.recording.notes
                if notes and notes[-1] is note and played < note.duration_ms:
                    notes[-1] = Note(note.t_ms, note.frequency_hz, played, note.end_hz)
            if respond:
                robot.respond(playing.packet)
        if pending is not None and respond:
            robot.respond(pending)

    def _play(self, packet: Packet, duration_ms: int, note: Note | None) -> None:
        self.stop(respond=True)
        if note is not None:
            self.robot.recording.notes.append(note)
        timer = self.robot.at(self.robot.now_ms + duration_ms, self._finished)
        self._playing = _Playing(packet, note, timer)

    def _finished(self) -> None:
        playing, self._playing = self._playing, None
        if playing is not None:
            self.robot.respond(playing.packet)
        pending, self._pending_sweep = self._pending_sweep, None
        if pending is not None:
            self._start_sweep(pending)

    def _start_sweep(self, packet: Packet) -> None:
        start = packet["start_frequency"] / MILLIHERTZ
        end = packet["end_frequency"] / MILLIHERTZ
        duration = int(packet["duration"])
        # volume 0 is silence: nothing to hear, so nothing recorded (the runtime's stop witness)
        heard = Note(self.robot.now_ms, start, duration, end) if packet["volume"] else None
        self._play(packet, duration, heard)

    def _play_note(self, packet: Packet) -> None:
        duration = int(packet["duration"])
        if duration == 0:
            self.stop(respond=True)
            self.robot.respond(packet)
            return
        frequency = float(packet["frequency"])
        self._play(packet, duration, Note(self.robot.now_ms, frequency, duration, frequency))

    def _stop_sound(self, packet: Packet) -> None:
        self.stop(respond=True)

    def _say_phrase(self, packet: Packet) -> None:
        text = str(packet["phrase"])
        duration = say_ms(text)
        self._play(packet, duration, None)
        self.robot.recording.said.append(Said(self.robot.now_ms, text, duration))
        self.robot.happened(f'said "{text}"')

    def _play_sweep(self, packet: Packet) -> None:
        if packet["append"] and self._playing is not None:
            if self._pending_sweep is not None:
                self.robot.respond(self._pending_sweep)  # only one sweep can wait: the older goes
            self._pending_sweep = packet
            return
        self._start_sweep(packet)


def say_ms(text: str) -> int:
    """How long the robot takes to say ``text``."""
    spoken = sum(SAY_LETTER_MS if ch.isalnum() else SAY_OTHER_MS for ch in text)
    return max(SAY_SHORTEST_MS, spoken)
