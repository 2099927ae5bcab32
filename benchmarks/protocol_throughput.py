"""Packets encoded and decoded per second on one core (target: 200,000 encodes+decodes/s).

    .venv/bin/python benchmarks/protocol_throughput.py [--rounds N]

A realistic mix: what the runtime sends most (wheel speeds, drive, LEDs, notes) and what the
robot sends most (movement responses, bumper, colour and touch events). Prints packets per
second for encode, decode, and an encode followed by a decode, best of three rounds.
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable

from rootlang.protocol import (
    BumperState,
    LedState,
    SensorColor,
    TouchSensors,
    decode,
    encode,
)
from rootlang.protocol.codec import CRC_C_EXTENSION
from rootlang.protocol.specs import Sender

MIX: list[tuple[str, dict[str, object]]] = [
    ("set_wheel_speeds", {"left": 100, "right": -100}),
    ("drive_distance", {"distance": 250}),
    ("set_led_animation", {"state": LedState.SPIN, "red": 255, "green": 0, "blue": 128}),
    ("play_note", {"frequency": 440, "duration": 500}),
    ("drive_distance_response", {"timestamp": 123456, "x": 10, "y": 250, "heading": 900}),
    ("bumper_event", {"timestamp": 123999, "state": BumperState.LEFT}),
    ("color_sensor_event", {"colors": (SensorColor.BLACK,) * 16 + (SensorColor.WHITE,) * 16}),
    ("touch_sensor_event", {"timestamp": 5, "state": TouchSensors.FRONT_LEFT}),
]


def best_rate(work: Callable[[], int], rounds: int) -> float:
    """Packets per second of the fastest of ``rounds`` runs of ``work``."""
    best = 0.0
    for _ in range(rounds):
        start = time.perf_counter()
        done = work()
        best = max(best, done / (time.perf_counter() - start))
    return best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=20_000, help="passes over the mix per round")
    parser.add_argument("--rounds", type=int, default=3)
    args = parser.parse_args()
    encoded: list[tuple[bytes, Sender]] = []
    for name, fields in MIX:
        data = encode(name, fields, 7)
        sender: Sender = "host" if decode(data, "host").name == name else "robot"
        encoded.append((data, sender))
    repeat: int = args.repeat

    def encode_all() -> int:
        for _ in range(repeat):
            for name, fields in MIX:
                encode(name, fields, 7)
        return repeat * len(MIX)

    def decode_all() -> int:
        for _ in range(repeat):
            for data, sender in encoded:
                decode(data, sender)
        return repeat * len(MIX)

    def both() -> int:
        for _ in range(repeat):
            for (name, fields), (_, sender) in zip(MIX, encoded, strict=True):
                decode(encode(name, fields, 7), sender)
        return 2 * repeat * len(MIX)  # an encode and a decode each

    extension = "yes" if CRC_C_EXTENSION else "no"
    print(f"crcmod C extension: {extension}; {len(MIX)} packet kinds")
    print(f"encode:          {best_rate(encode_all, args.rounds):>12,.0f} packets/s")
    print(f"decode:          {best_rate(decode_all, args.rounds):>12,.0f} packets/s")
    print(f"encode+decode:   {best_rate(both, args.rounds):>12,.0f} operations/s (target 200,000)")


if __name__ == "__main__":
    main()
