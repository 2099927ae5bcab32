"""The robot models rootlang knows, and how each one names itself."""

from __future__ import annotations

import enum


class RobotModel(enum.Enum):
    """A robot model, valued by the code it advertises (manufacturer data 0x0600)."""

    RT0 = "RT0"
    RT1 = "RT1"
    CREATE3 = "Ci3"

    @property
    def display_name(self) -> str:
        return {"RT0": "Root RT0", "RT1": "Root RT1", "Ci3": "Create 3"}[self.value]

    @property
    def is_root(self) -> bool:
        return self is not RobotModel.CREATE3

    @classmethod
    def from_name(cls, text: str) -> RobotModel:
        """Accepts `RT0`, `rt1`, `Ci3`, `create3`, `Create 3`."""
        key = text.strip().lower().replace(" ", "").replace("_", "")
        aliases = {"rt0": cls.RT0, "rt1": cls.RT1, "ci3": cls.CREATE3, "create3": cls.CREATE3}
        if key not in aliases:
            raise ValueError(f"unknown robot model {text!r} (known: RT0, RT1, Create3)")
        return aliases[key]

    @classmethod
    def from_details(cls, serial: str, firmware: str) -> RobotModel:
        """A connected robot's model from its Device Information: the serial number's prefix,
        else the firmware's form (``G.x`` is a Create 3, Root firmware is numeric)."""
        for model in cls:
            if serial.upper().startswith(model.value.upper()):
                return model
        return cls.CREATE3 if firmware[:1].isalpha() else cls.RT1
