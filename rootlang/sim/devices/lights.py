"""Device 3, lights: Root's LEDs, a Create 3's light ring."""

from __future__ import annotations

from collections.abc import Mapping

from rootlang.protocol import LedState, Packet
from rootlang.sim.devices.base import Context, Handler, SimDevice
from rootlang.sim.recording import LedMode, LightChange

DARK = (0, 0, 0)
LED_MODES: dict[LedState, LedMode] = {
    LedState.OFF: "off",
    LedState.ON: "on",
    LedState.BLINK: "blink",
    LedState.SPIN: "spin",
}


class Lights(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.mode: LedMode = "off"
        self.rgb = DARK

    def commands(self) -> Mapping[str, Handler]:
        return {"set_led_animation": self._set_led_animation}

    def _set_led_animation(self, packet: Packet) -> None:
        mode = LED_MODES[LedState(packet["state"])]
        rgb = (int(packet["red"]), int(packet["green"]), int(packet["blue"]))
        self.mode, self.rgb = mode, DARK if mode == "off" else rgb
        self.robot.recording.lights.append(LightChange(self.robot.now_ms, self.mode, self.rgb))
        self.robot.record_frame(force=True)
