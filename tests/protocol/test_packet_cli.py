"""`rootlang packet`: encode, decode and list, for people and scripts."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from rootlang.cli import main
from rootlang.protocol import PACKETS

FORWARD = "01040000000064000000640000000000000000d1"


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(["packet", *argv])
    out, err = capsys.readouterr()
    return code, out, err


def test_encode(capsys: pytest.CaptureFixture[str]) -> None:
    assert run(capsys, "encode", "set_wheel_speeds", "left=100", "right=100") == (
        0,
        FORWARD + "\n",
        "",
    )


def test_encode_with_id_names_and_lists(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "encode", "enable_events", "devices=bumpers,0x4,0", "--id", "9")
    assert code == 0
    assert out[:38] == "000709" + "00" * 14 + "1011"  # devices 12 and 4, then 0
    code, out, _ = run(capsys, "decode", out.strip(), "--from", "host", "--json")
    assert json.loads(out)["fields"] == {"devices": [0, 4, 12]}
    assert json.loads(out)["id"] == 9


def test_encode_text_and_enum_by_name(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "encode", "say_phrase", "phrase=hi there")
    assert code == 0
    _, decoded, _ = run(capsys, "decode", out.strip(), "--from", "host")
    assert decoded.strip() == "say_phrase #0 phrase='hi there'"
    code, out, _ = run(capsys, "encode", "set_marker_position", "position=marker_down")
    assert code == 0 and out.startswith("020000" + "01")


@pytest.mark.parametrize(
    ("argv", "code_in_message"),
    [
        (["encode", "set_wheel_speeds", "left=101", "right=0"], "left must be -100 to 100"),
        (["encode", "set_wheel_speed", "left=1"], 'Did you mean "set_wheel_speeds"'),
        (["encode", "drive_distance", "distance=far"], "expected a whole number"),
        (["encode", "drive_distance", "distance"], 'has no "="'),
        (["encode", "drive_distance", "distanc=4"], 'Did you mean "distance"'),
        (["encode", "drive_distance", "distance=4", "--id", "256"], "0 to 255"),
        (["encode", "drive_distance", "distance=4", "--id", "x"], "0 to 255"),
        (["encode", "drive_distance", "distance=4", "--robot", "Roomba"], "RT0, RT1"),
        (["decode", "zz"], "not a hex digit"),
        (["decode", "010"], "odd number"),
        (["decode", "0104"], "exactly 20 bytes"),
        (["decode", FORWARD[:-2] + "00"], "damaged"),
        (["decode", "2a0100" + "00" * 16 + "3f"], "damaged"),
    ],
)
def test_bad_input_is_an_e5xx_message_and_exit_1(
    capsys: pytest.CaptureFixture[str], argv: list[str], code_in_message: str
) -> None:
    code, out, err = run(capsys, *argv)
    assert code == 1
    assert out == ""
    assert code_in_message in err
    assert "Traceback" not in err


def test_unknown_device_is_reported(capsys: pytest.CaptureFixture[str]) -> None:
    from rootlang.protocol import crc8

    body = bytes([42, 1, 0]) + bytes(16)
    hex_text = (body + bytes([crc8(body)])).hex()
    code, _, err = run(capsys, "decode", hex_text, "--from", "robot")
    assert code == 1 and "Device 42 has no response or event numbered 1" in err
    code, _, err = run(capsys, "decode", hex_text)
    assert code == 1 and "Device 42" in err


def test_decode_text_and_json(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "decode", FORWARD)
    assert code == 0
    assert out == "from host: set_wheel_speeds #0 left=100 mm/s right=100 mm/s\n"
    code, out, _ = run(capsys, "decode", FORWARD, "--from", "host", "--json")
    assert json.loads(out) == {
        "name": "set_wheel_speeds",
        "device": 1,
        "command": 4,
        "id": 0,
        "kind": "command",
        "fields": {"left": 100, "right": 100},
        "from": "host",
    }


def test_decode_spaced_hex(capsys: pytest.CaptureFixture[str]) -> None:
    spaced = " ".join(FORWARD[i : i + 2] for i in range(0, 40, 2))
    code, out, _ = run(capsys, "decode", *spaced.split(), "--json")
    assert code == 0 and json.loads(out)["name"] == "set_wheel_speeds"


def test_decode_without_sender_shows_every_reading(capsys: pytest.CaptureFixture[str]) -> None:
    _, hex_text, _ = run(capsys, "encode", "get_name", "--id", "3")
    code, out, _ = run(capsys, "decode", hex_text.strip(), "--json")
    readings = json.loads(out)
    assert code == 0
    assert [(r["name"], r["kind"], r["from"]) for r in readings] == [
        ("get_name", "command", "host"),
        ("get_name_response", "response", "robot"),
    ]
    _, text_out, _ = run(capsys, "decode", hex_text.strip())
    assert text_out.splitlines() == [
        "from host: get_name #3",
        "from robot: get_name_response #3 name=''",
    ]


def test_decode_event_json_is_plain_data(capsys: pytest.CaptureFixture[str]) -> None:
    _, hex_text, _ = run(
        capsys,
        "encode",
        "touch_sensor_event",
        "timestamp=1500",
        "state=FRONT_LEFT|REAR_RIGHT",
        "--id",
        "40",
    )
    code, out, _ = run(capsys, "decode", hex_text.strip(), "--from", "robot", "--json")
    assert code == 0
    assert json.loads(out) == {
        "name": "touch_sensor_event",
        "device": 17,
        "command": 0,
        "id": 40,
        "kind": "event",
        "fields": {"timestamp": 1500, "state": ["REAR_RIGHT", "FRONT_LEFT"]},
        "from": "robot",
    }


def test_list(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "list")
    assert code == 0
    assert len(out.splitlines()) == len(PACKETS)
    assert out.splitlines()[0].startswith("get_versions ")
    code, out, _ = run(capsys, "list", "--json")
    rows = json.loads(out)
    assert [r["name"] for r in rows] == [p.name for p in PACKETS]
    undock = next(r for r in rows if r["name"] == "undock_response")
    assert (undock["device"], undock["command"], undock["kind"]) == (1, 20, "response")
    assert undock["robots"] == ["Ci3"] and undock["min_protocol"] == "1.5" and undock["errata"]
    left = next(r for r in rows if r["name"] == "set_wheel_speeds")["fields"][0]
    assert (left["minimum"], left["maximum"], left["unit"]) == (-100, 100, "mm/s")


def test_the_installed_command_shows_no_traceback() -> None:
    done = subprocess.run(
        [sys.executable, "-m", "rootlang", "packet", "decode", "01"],
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert done.returncode == 1
    assert "E501" in done.stderr or "exactly 20 bytes" in done.stderr
    assert "Traceback" not in done.stderr
