"""isaacsim.robot.wheeled_robots.StanleyControlPID: follow a planned path with Stanley steering.

Isaac's "Drive to Target Steering" node, with its arithmetic: a bicycle model
of wheel base wheelBase * gains[1] steers by the heading error plus
atan(0.5 * cross-track error / speed) at the front axle (Isaac hands gains[0]
to the Stanley function's unused proportional slot, so the cross-track gain
stays 0.5), clipped to +-gains[2]; speed follows a profile of the path's speeds
scaled to maxVelocity with a proportional gain gains[1]. Within thresholds[0]
of the target it only turns towards the target's yaw. A differential drive
tightens the turn by 1 + |wheelBase w / v| gains[1] / step.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow_nodes._wheeled import normalize_angle, yaw_of

CROSS_TRACK_GAIN = 0.5
PROFILE_MIN_SPEED = 0.05       # m/s: the slowest the speed profile gets near the goal
NO_TARGET = (0.0, 0.0, 0.0)    # Isaac's stored target before a path arrives: turn in place at the origin

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.StanleyControlPID",
    version=1,
    aliases=("omni.isaac.wheeled_robots.StanleyControlPID",),
    description=(
        "On execIn, the linear and angular speed that drive a wheeled robot along pathArrays (from "
        "QuinticPathPlanner) to the target: Stanley steering on a bicycle model, proportional speed control, "
        "a turn in place once within thresholds[0] of the target; zero once reachedGoal is [true, true]."),
    categories=("isaacWheeledRobots",),
    ui_name="Drive to Target Steering",
    inputs=(
        Attribute("execIn", "execution", description="Compute the speeds"),
        Attribute("currentPosition", "vectord[3]", default=(0.0, 0.0, 0.0), description="Robot position, m"),
        Attribute("currentOrientation", "quatd[4]", default=(0.0, 0.0, 0.0, 0.0),
                  description="Robot orientation (x, y, z, w; all 0: yaw 0)"),
        Attribute("currentSpeed", "vectord[3]", default=(0.0, 0.0, 0.0), description="Robot linear velocity, m/s"),
        Attribute("maxVelocity", "double", default=1.5, description="Largest linear speed, m/s"),
        Attribute("reachedGoal", "bool[]", default=(False, False),
                  description="[position reached, orientation reached] (from CheckGoal2D)"),
        Attribute("pathArrays", "double[]", description="Speeds, x, y and yaw of the path samples, concatenated"),
        Attribute("target", "double[3]", default=(0.0, 0.0, 0.0), description="Target x, y (m) and yaw (rad)"),
        Attribute("targetChanged", "bool", default=False, description="Take pathArrays and target as new"),
        Attribute("wheelBase", "double", default=0.4132, description="Front to rear wheel centres, m"),
        Attribute("thresholds", "double[2]", default=(0.1, 0.1), description="Position (m) and yaw (rad) thresholds"),
        Attribute("drawPath", "bool", default=False, description="Draw the path (needs a viewport: ignored)"),
        Attribute("step", "double", default=0.16666666667, description="Control period, s"),
        Attribute("gains", "double[3]", default=(0.5, 0.1, 0.0872665),
                  description="Control, velocity and steering gains (the last is the steering limit, rad)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the speeds are set"),
        Attribute("linearVelocity", "double", description="Forward speed command, m/s"),
        Attribute("angularVelocity", "double", description="Turn rate command, rad/s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs, path = db.inputs, db.internal
    reached = tuple(inputs.reachedGoal) + (False, False)
    if reached[0] and reached[1]:
        _drive(db, 0.0, 0.0)
        return
    if inputs.targetChanged or ("x" not in path and inputs.pathArrays):
        _take_path(db)
    if "base" not in path:            # Isaac reads wheelBase and step once, on the first compute
        path["base"], path["step"] = inputs.wheelBase, inputs.step
    base, step = path["base"], path["step"]
    if base == 0.0 or step == 0.0:
        db.error("inputs:wheelBase is 0" if base == 0.0 else "inputs:step is 0")
    control_gain, speed_gain, steering_limit = inputs.gains
    x, y = inputs.currentPosition[0], inputs.currentPosition[1]
    yaw = yaw_of(inputs.currentOrientation)
    speed = math.hypot(inputs.currentSpeed[0], inputs.currentSpeed[1])
    target = path.get("target", NO_TARGET)
    if math.hypot(x - target[0], y - target[1]) <= inputs.thresholds[0] or reached[0]:
        linear = 0.0
        turn = math.atan2(math.sin(target[2] - yaw), math.cos(target[2] - yaw))
        angular = min(turn * speed_gain / step, 1.0) if turn > 0 else max(turn * speed_gain / step, -1.0)
    else:
        if "x" not in path:
            db.error("inputs:pathArrays is empty: connect a QuinticPathPlanner's pathArrays")
        accel = speed_gain * (path["profile"][path["index"]] - speed) / step
        steer = _stanley_steer(db, x, y, yaw % (2.0 * math.pi), speed, base * speed_gain)
        steer = min(max(steer, -steering_limit), steering_limit)
        angular = speed / (base * speed_gain) * math.tan(steer)
        linear = speed + accel * step
    widen = 1.0
    if not reached[0] and linear > 0:
        widen = 1.0 + abs(base * angular / linear) * speed_gain / step
    _drive(db, linear, widen * angular)


def _drive(db, linear, angular):
    db.outputs.linearVelocity = float(linear)
    db.outputs.angularVelocity = float(angular)
    db.outputs.execOut = ExecState.ENABLED


def _take_path(db):
    """Split pathArrays into speeds, x, y, yaw; build the speed profile; restart at the path's first sample."""
    import numpy as np  # here, not at the top: loading the node library imports no numpy
    arrays, path = db.inputs.pathArrays, db.internal
    count = len(arrays) // 4
    if count == 0:
        db.error("inputs:pathArrays is empty: connect a QuinticPathPlanner's pathArrays")
    speeds = np.array(arrays[:count])
    path["x"], path["y"], path["yaw"] = (np.array(arrays[count * k:count * (k + 1)]) for k in (1, 2, 3))
    path["profile"] = _speed_profile(db, speeds, db.inputs.maxVelocity)
    path["target"] = tuple(db.inputs.target)
    path["index"] = 0


def _speed_profile(db, speeds, max_speed):
    """The path's speeds scaled so the fastest is max_speed, slowed over the last third towards the goal."""
    import numpy as np
    fastest = float(np.max(np.abs(speeds)))
    if fastest == 0.0:
        db.error("inputs:pathArrays: every path speed is 0, so there is no speed profile to follow")
    profile = speeds / fastest * max_speed
    slow_down = min(int(len(speeds) / 3), int(max_speed * 60))
    for i in range(1, slow_down):
        profile[-i] = max(min(profile[-i], profile[-i] / float(slow_down - i) ** 0.5), PROFILE_MIN_SPEED)
    return profile


def _stanley_steer(db, x, y, yaw, speed, wheel_base):
    """Heading error plus cross-track term at the front axle, against the nearest sample not behind the last."""
    import numpy as np
    path = db.internal
    front_x, front_y = x + wheel_base * math.cos(yaw), y + wheel_base * math.sin(yaw)
    dx, dy = front_x - path["x"], front_y - path["y"]
    nearest = int(np.argmin(np.hypot(dx, dy)))
    cross_track = float(dx[nearest] * -math.cos(yaw + math.pi / 2) + dy[nearest] * -math.sin(yaw + math.pi / 2))
    path["index"] = max(nearest, path["index"])
    heading_error = normalize_angle(float(path["yaw"][path["index"]]) - yaw)
    return heading_error + math.atan2(CROSS_TRACK_GAIN * normalize_angle(cross_track), speed)
