"""The simulator as a :class:`~rootlang.runtime.transport.Transport`: a virtual robot on a clock.

The robot's time follows the clock (seconds since ``connect``). The world is moved on lazily:
before each packet the host sends, and by a timer on the clock's event loop at the robot's
:meth:`~VirtualRobot.next_wakeup` — while it moves, its next sensor reading (every 40 ms) or about
when its movement ends; else its next timer (a note ending, a scripted touch); else not until a
packet comes. On a :class:`VirtualClock` that costs no real time; on a :class:`WallClock`
(``--realtime``) it paces the world to the wall.

Packets from the robot reach the host with ``loop.call_soon``, never from inside ``send``, at
the simulated moment they were sent (to the physics step). Those a timer's catch-up produced
are handed over at its end, at once when the clock says nothing else is ready or due (the order
is then the same, and a turn of the loop is saved for each of the ~20 colour events a second).

On a virtual clock, when nothing else on the loop will run before the robot's next wake-up, a
timer's turn also runs the wake-ups after it, until the robot has something to say (handed over
by a timer at the moment the wake-up that said it would have come) or something else is due:
the same steps, the same packets at the same moments, without a turn of the loop for each
40 ms reading that says nothing.
"""

from __future__ import annotations

import asyncio

from rootlang.runtime.clock import Clock
from rootlang.runtime.transport import DisconnectHandler, PacketHandler, RobotInfo, Transport
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import Stimulus

QUIET_MARGIN_S = 1e-6  # a look-ahead stops this near anything else due on the loop
LOOK_AHEAD_S = 1.0  # chosen: and after this much simulated time, so Ctrl-C is heard at once


class SimTransport(Transport):
    def __init__(self, robot: VirtualRobot, clock: Clock) -> None:
        self.robot = robot
        self.clock = clock
        self._origin = 0.0  # the clock's time at connect = the robot's time 0 ... plus its age
        self._timer: asyncio.TimerHandle | None = None
        self._timer_due: float | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._on_disconnect: DisconnectHandler | None = None
        self._on_packet: PacketHandler | None = None
        self._held: list[bytes] | None = None  # packets sent during a timer's catch-up
        self._ahead: list[bytes] = []  # packets sent by looking ahead, for the next timer

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        loop = asyncio.get_running_loop()
        self._loop = loop
        self._origin = self.clock.now() - self.robot.time
        self._on_disconnect = on_disconnect
        self._on_packet = on_packet
        self.robot.on_packet = self._robot_sent
        self.robot.on_disconnect = self._robot_disconnected
        self.robot.connect()
        self._schedule()
        return self.robot.info

    async def send(self, packet: bytes) -> None:
        if self._loop is None:
            raise ConnectionError("the simulated robot is not connected")
        self._catch_up()
        self.robot.write(packet)
        self._schedule()

    async def disconnect(self) -> None:
        if self._loop is None:
            return
        self._catch_up()
        self._stop_timer()
        self.robot.on_disconnect = None
        self.robot.disconnect()
        self._loop = None

    def stimulate(self, stimulus: Stimulus) -> None:
        """A person does something to the robot now (the studio's buttons). The world is caught
        up to now first; world files' stimuli come on the world's own timers instead."""
        if self._loop is None:
            return
        self._catch_up()
        self.robot.stimulate(stimulus)
        self._schedule()

    # --- moving the world on -----------------------------------------------------------------

    def _robot_time(self) -> float:
        return self.clock.now() - self._origin

    def _catch_up(self) -> None:
        self.robot.advance_to(self._robot_time())

    def _tick(self) -> None:
        self._timer = self._timer_due = None
        if self._loop is None:
            return
        self._held, self._ahead = self._ahead, []
        ahead_until: float | None = None
        try:
            self._catch_up()
            if not self._held:
                ahead_until = self._look_ahead()
        finally:
            held, self._held = self._held, None
        if ahead_until is None:
            self._schedule()
        else:  # the robot is ahead of the clock: the timer of the wake-up that has news
            self._ahead, held = held, []
            self._stop_timer()
            self._timer = self._loop.call_later(ahead_until - self.clock.now(), self._tick)
        if held and self.clock.nothing_else_now():
            for data in held:
                self._hand_over(data)
        else:
            self._post(held)

    def _look_ahead(self) -> float | None:
        """Run the wake-ups that would come before anything else on the loop could run, until
        one has news: its clock time is returned (the robot is then that far ahead, and its
        packets wait in ``_held``). None if none had news: the next wake-up is scheduled as
        usual (the robot may be ahead of the clock, but nothing can ask it before then)."""
        quiet = self.clock.quiet_until()
        if quiet is None:
            return None
        now = start = self.clock.now()
        while (due := self._next_due()) is not None:
            at = now + max(0.0, due - (now - self._origin))  # when its timer would fire
            if at + QUIET_MARGIN_S >= quiet or at - start > LOOK_AHEAD_S:
                return None
            self.robot.advance_to(at - self._origin)
            if self._held:
                return at
            now = at
        return None

    def _next_due(self) -> float | None:
        """The robot time of its next wake-up (at least a step on), or None."""
        wakeup = self.robot.next_wakeup()
        if wakeup is None:
            return None
        return max(wakeup, self.robot.time + self.robot.step_ms / 1000)

    def _robot_sent(self, data: bytes) -> None:
        if self._held is not None:
            self._held.append(data)
        else:
            self._post([data])

    def _post(self, packets: list[bytes]) -> None:
        if self._loop is not None:
            for data in packets:
                self._loop.call_soon(self._hand_over, data)

    def _hand_over(self, data: bytes) -> None:
        assert self._on_packet is not None
        try:
            self._on_packet(data)
        except Exception as error:  # as the loop treats a failing callback: report, go on
            if self._loop is not None:
                self._loop.call_exception_handler({"message": "packet handler", "exception": error})

    def _schedule(self) -> None:
        if self._loop is None:
            return
        due = self._next_due()
        if due is None:
            self._stop_timer()
            return
        if self._timer is not None and self._timer_due == due:
            return
        self._stop_timer()
        delay = max(0.0, due - self._robot_time())
        self._timer = self._loop.call_later(delay, self._tick)
        self._timer_due = due

    def _stop_timer(self) -> None:
        if self._timer is not None:
            self._timer.cancel()
        self._timer = self._timer_due = None

    def _robot_disconnected(self, reason: str) -> None:
        self._stop_timer()
        if self._held:  # what the robot sent before it went comes first
            self._post(self._held)
            self._held.clear()
        loop, self._loop = self._loop, None
        if loop is not None and self._on_disconnect is not None:
            loop.call_soon(self._on_disconnect, reason)
