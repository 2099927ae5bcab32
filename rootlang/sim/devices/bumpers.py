"""Device 12, bumpers: left and right halves of the front bumper, pressed by what the body
touches in the physics world, or by a person's hand (a world's or the studio's "bump")."""

from __future__ import annotations

from rootlang.protocol import BumperState
from rootlang.sim.devices.base import Context, SimDevice

MIDDLE_DEG = 15.0  # chosen: a touch this near straight ahead presses both halves


class Bumpers(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.state = BumperState.NONE
        self._felt: dict[int, tuple[float, float]] = {}  # touches: lowest, highest angle felt
        self._by_hand = 0  # BumperState bits of the halves a person holds pressed now
        self._by_touch = 0  # ... and of those pressed by what the body touches

    def pressed_by_hand(self, sides: tuple[str, ...], hold_ms: int) -> None:
        """A person presses these halves (``left``, ``right``) now, for ``hold_ms``."""
        bits = 0
        for side in sides:
            bits |= BumperState.LEFT if side == "left" else BumperState.RIGHT
        self._by_hand |= bits
        self._show()

        def release() -> None:
            self._by_hand &= ~bits
            self._show()

        self.robot.at(self.robot.now_ms + hold_ms, release)

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
        self._by_touch = (BumperState.LEFT if left else 0) | (BumperState.RIGHT if right else 0)
        self._show()

    def _show(self) -> None:
        state = BumperState(self._by_touch | self._by_hand)
        if state != self.state:
            self.state = state
            self.robot.happened(f"bumper {str(state.name).lower()}")
            self.robot.event("bumper_event", timestamp=self.robot.now_ms, state=state)
