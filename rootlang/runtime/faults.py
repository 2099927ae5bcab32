"""A faulty link: a transport wrapped round another that drops, corrupts, repeats and delays
packets, in each direction, from a seeded random generator (the same seed, the same faults).

Used to test that the runtime keeps its promises on a bad radio (docs/runtime.md, "A lossy
link"): the robot is stopped at the end of every run, and every run either does what the
program says or ends with a clear error. The faults are the ones a Bluetooth link can show
the host; each packet meets at most one:

- **drop**: the packet is lost;
- **corrupt**: one bit of it is flipped (the checksum, CRC-8, catches every one-bit error, so
  the receiver throws it away: what a damaged packet costs is that it is lost);
- **duplicate**: it arrives twice;
- **delay**: it arrives up to ``delay_seconds`` late, and so do the packets behind it — the
  link keeps packets in order (Bluetooth's link layer retransmits in order), it only stalls.
"""

from __future__ import annotations

import asyncio
import enum
import random
from dataclasses import dataclass

from rootlang.runtime.clock import Clock
from rootlang.runtime.transport import DisconnectHandler, PacketHandler, RobotInfo, Transport


class Fault(enum.Enum):
    DROP = "drop"
    CORRUPT = "corrupt"
    DUPLICATE = "duplicate"
    DELAY = "delay"


@dataclass(frozen=True)
class FaultRates:
    """How often a packet meets a fault: ``rate`` of them do, the kind chosen evenly from
    ``faults``."""

    rate: float = 0.1
    faults: tuple[Fault, ...] = tuple(Fault)
    delay_seconds: float = 0.2


@dataclass
class FaultCounts:
    """What the faulty link did, in one direction."""

    packets: int = 0
    dropped: int = 0
    corrupted: int = 0
    duplicated: int = 0
    delayed: int = 0

    def count(self, fault: Fault | None) -> None:
        self.packets += 1
        if fault is Fault.DROP:
            self.dropped += 1
        elif fault is Fault.CORRUPT:
            self.corrupted += 1
        elif fault is Fault.DUPLICATE:
            self.duplicated += 1
        elif fault is Fault.DELAY:
            self.delayed += 1


class _Direction:
    """One direction of the link: decides each packet's fate, and keeps packets in order."""

    def __init__(self, rates: FaultRates, generator: random.Random, clock: Clock) -> None:
        self.rates = rates
        self.random = generator
        self.clock = clock
        self.counts = FaultCounts()
        self._free_at = 0.0  # a delayed packet holds back the ones behind it until then

    def fate(self, data: bytes) -> tuple[list[bytes], float]:
        """The copies of ``data`` that arrive, and how many seconds from now they do."""
        fault: Fault | None = None
        if self.random.random() < self.rates.rate:
            fault = self.random.choice(self.rates.faults)
        self.counts.count(fault)
        now = self.clock.now()
        at = max(now, self._free_at)
        if fault is Fault.DELAY:
            at += self.random.uniform(0.0, self.rates.delay_seconds)
            self._free_at = at
        if fault is Fault.DROP:
            return [], at - now
        if fault is Fault.CORRUPT:
            bit = self.random.randrange(len(data) * 8)
            damaged = bytearray(data)
            damaged[bit // 8] ^= 1 << (bit % 8)
            return [bytes(damaged)], at - now
        copies = 2 if fault is Fault.DUPLICATE else 1
        return [data] * copies, at - now


class FaultyTransport(Transport):
    """``inner`` behind a faulty link. ``to_robot`` and ``to_host`` say how faulty each way is;
    ``seed`` makes the faults repeatable."""

    def __init__(
        self,
        inner: Transport,
        clock: Clock,
        *,
        seed: int = 0,
        to_robot: FaultRates | None = None,
        to_host: FaultRates | None = None,
    ) -> None:
        self.inner = inner
        self.clock = clock
        generator = random.Random(seed)
        self.to_robot = _Direction(to_robot or FaultRates(), generator, clock)
        self.to_host = _Direction(to_host or FaultRates(), generator, clock)
        self._lock = asyncio.Lock()  # packets to the robot go one after another, in order
        self._on_packet: PacketHandler = lambda data: None

    async def connect(
        self, on_packet: PacketHandler, on_disconnect: DisconnectHandler
    ) -> RobotInfo:
        self._on_packet = on_packet
        return await self.inner.connect(self._from_robot, on_disconnect)

    async def send(self, packet: bytes) -> None:
        async with self._lock:
            copies, delay = self.to_robot.fate(packet)
            if delay > 0:
                await self.clock.sleep(delay)  # the link stalls: this sender waits
            for data in copies:
                await self.inner.send(data)

    async def disconnect(self) -> None:
        await self.inner.disconnect()

    def _from_robot(self, data: bytes) -> None:
        copies, delay = self.to_host.fate(data)
        loop = asyncio.get_running_loop()
        for copy in copies:
            if delay > 0:
                loop.call_later(delay, self._on_packet, copy)
            else:
                self._on_packet(copy)
