"""Device 20, cliff sensor: the floor under the robot's front, gone at a table's edge or when a
person picks the robot up."""

from __future__ import annotations

from rootlang.sim.devices.base import Context, Pose, SimDevice
from rootlang.sim.sensors import body_point

# chosen (the spec gives the fields, not typical values): millivolts the sensor reads over the
# floor and over a drop, and the threshold between them that it reports
FLOOR_MV, DROP_MV, THRESHOLD_MV = 2000, 100, 1000


class Cliff(SimDevice):
    def __init__(self, robot: Context) -> None:
        super().__init__(robot)
        self.over_edge = False
        # walls round the floor and no table tops: no drop the sensor could reach but the air
        world = robot.world
        self._edges = bool(world.table) or not world.border_walls

    def sense(self, pose: Pose) -> None:
        robot = self.robot
        cliff = robot.picked_up or (self._edges and not self._on_table(pose))
        if cliff == self.over_edge:
            return
        self.over_edge = cliff
        robot.happened("cliff" if cliff else "cliff cleared")
        robot.event(
            "cliff_event", timestamp=robot.now_ms, cliff=int(cliff),
            sensor=DROP_MV if cliff else FLOOR_MV, threshold=THRESHOLD_MV,
        )  # fmt: skip

    def _on_table(self, pose: Pose) -> bool:
        x, y = body_point(pose, self.robot.spec.cliff_ahead, 0)
        return self.robot.world.on_table(x, y)
