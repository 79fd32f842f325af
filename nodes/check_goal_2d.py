"""isaacsim.robot.wheeled_robots.CheckGoal2D: has a wheeled robot reached its planar goal?

As Isaac's node: the target (x, y, yaw) is taken when targetChanged is set and
kept; reachedGoal[0] is whether the robot is within thresholds[0] metres of the
target's x, y, and reachedGoal[1] whether its current yaw (rad, in [-pi, pi])
is at most thresholds[1] (Isaac compares the yaw itself with the threshold,
not its difference from the target's).
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.CheckGoal2D",
    version=1,
    aliases=("omni.isaac.wheeled_robots.CheckGoal2D",),
    description=(
        "On execIn, reachedGoal = [distance to the target's x, y <= thresholds[0], current yaw <= "
        "thresholds[1]] (Isaac's test); the target is taken when targetChanged is true."),
    categories=("isaacWheeledRobots",),
    ui_name="Check Goal 2D",
    inputs=(
        Attribute("execIn", "execution", description="Check the goal"),
        Attribute("currentPosition", "vectord[3]", default=(0.0, 0.0, 0.0), description="Robot position, m"),
        Attribute("currentOrientation", "quatd[4]", default=(0.0, 0.0, 0.0, 0.0),
                  description="Robot orientation (x, y, z, w; all 0: yaw 0)"),
        Attribute("target", "double[3]", default=(0.0, 0.0, 0.0), description="Target x, y (m) and yaw (rad)"),
        Attribute("targetChanged", "bool", default=False, description="Take inputs:target as the new target"),
        Attribute("thresholds", "double[2]", default=(0.1, 0.1), description="Position (m) and yaw (rad) thresholds"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the check"),
        Attribute("reachedGoal", "bool[]", description="[position reached, orientation reached]"),
    ),
    state=(
        Attribute("goal", "double[3]", default=(0.0, 0.0, 0.0), description="The target being checked"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    if inputs.targetChanged:
        db.state.goal = inputs.target
    goal = db.state.goal
    x, y = inputs.currentPosition[0], inputs.currentPosition[1]
    db.outputs.reachedGoal = (math.hypot(x - goal[0], y - goal[1]) <= inputs.thresholds[0],
                              _yaw(inputs.currentOrientation) <= inputs.thresholds[1])
    db.outputs.execOut = ExecState.ENABLED


def _yaw(q) -> float:
    x, y, z, w = q
    return math.atan2(2.0 * (w * z + x * y), 1.0 - 2.0 * (y * y + z * z))
