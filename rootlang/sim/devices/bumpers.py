"""Device 12, bumpers: left and right halves of the front bumper, pressed by what the body
touches in the physics world."""

from __future__ import annotations

from rootlang.protocol import BumperState
from rootlang.sim.devices.base import Context, SimDevice

MIDDLE_DEG = 15.0  # chosen: a touch this near straight ahead presses both halves


class Bumpers(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.state = BumperState.NONE
        self._felt: dict[int, tuple[float, float]] = {}  # touches: lowest, highest angle felt

    def sense(self) -> None:
        """Read the contacts (debounced: only at the sensing period)."""
        physics = self.robot.physics
        if not physics.touching and not self._felt:
            return
        # each touch keeps the range of angles it has been felt at: a bumper stays pressed for
        # the whole touch, as a real one does while the robot pushes
        felt = {
            key: (min(angle, self._felt[key][0]), max(angle, self._felt[key][1]))
            if key in self._felt
            else (angle, angle)
            for key, angle in physics.contact_angles().items()
        }
        self._felt = felt
        left = right = False
        reach = self.robot.spec.bumper_half_angle
        for lowest, highest in felt.values():
            low, high = max(lowest, -reach), min(highest, reach)
            if low > high:
                continue  # felt only behind the bumper
            left |= high > -MIDDLE_DEG
            right |= low < MIDDLE_DEG
        state = BumperState((BumperState.LEFT if left else 0) | (BumperState.RIGHT if right else 0))
        if state != self.state:
            self.state = state
            self.robot.happened(f"bumper {str(state.name).lower()}")
            self.robot.event("bumper_event", timestamp=self.robot.now_ms, state=state)
