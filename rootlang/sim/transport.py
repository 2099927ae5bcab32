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

On a virtual clock, when nothing else on the loop would run before the robot's next wake-up, a
timer's turn goes on to that wake-up at once, moving the clock as the loop would
(:meth:`Clock.run_ahead`), and so on until something else is due or ready (a packet handed over
may start a script) or a simulated second has passed (so Ctrl-C is heard at once): the same
steps, the same packets at the same moments, in the same order, without a turn of the loop (or
a timer) for each 40 ms reading.
"""

from __future__ import annotations

import asyncio
from collections.abc import Callable

from rootlang.runtime.clock import Clock
from rootlang.runtime.transport import DisconnectHandler, PacketHandler, RobotInfo, Transport
from rootlang.sim.robot import VirtualRobot
from rootlang.sim.world import Stimulus

LOOK_AHEAD_S = 1.0  # chosen: a turn runs ahead at most this far, so Ctrl-C is heard at once


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
        self.on_closing: Callable[[], None] | None = None
        """Called as the host closes the link, the world caught up to then (and the robot not
        yet stopped by the link going): the faulty-link tools look at the robot there."""

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
        if self.on_closing is not None:
            self.on_closing()
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

    def robot_time(self) -> float:
        """The robot's time now (seconds since it was switched on: its recording's)."""
        return self._robot_time()

    def _catch_up(self) -> None:
        self.robot.advance_to(self._robot_time())

    def _tick(self) -> None:
        """A wake-up: the world caught up to now, its packets handed over, the next wake-up's
        timer set; or, when the clock can run ahead to it (see the module's docstring), that
        wake-up at once, and so on."""
        self._timer = self._timer_due = None
        clock = self.clock
        start = now = clock.now()
        alone = False  # whether nothing else is ready or due now: run_ahead says so
        while self._loop is not None:
            robot_time = now - self._origin
            self._held = []
            try:
                self.robot.advance_to(robot_time)
            finally:
                held, self._held = self._held, None
            due = self._next_due()
            if held:
                # a timer set after the hand-over goes where one set before it would: among
                # timers due at the same moment, before any the hand-over sets
                place = clock.take_place()
                if alone or clock.nothing_else_now():
                    for data in held:
                        self._hand_over(data)
                else:
                    self._post(held)
            else:
                place = None
            if due is None or self._loop is None:
                return
            delay = max(0.0, due - robot_time)
            if now + delay - start > LOOK_AHEAD_S or not clock.run_ahead(delay):
                self._set_timer(delay, due, place)
                return
            now = clock.now()
            alone = True

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
        self._set_timer(max(0.0, due - self._robot_time()), due)

    def _set_timer(self, delay: float, due: float, place: int | None = None) -> None:
        self._timer = self.clock.call_later(delay, self._tick, place=place)
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
