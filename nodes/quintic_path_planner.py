"""isaacsim.robot.wheeled_robots.QuinticPathPlanner: a smooth planar path from the robot to a target.

Isaac's planner (PythonRobotics' quintic polynomials planner): x(t) and y(t)
are quintic polynomials meeting position, speed and acceleration at both ends
(speeds and accelerations along the start and goal headings); the duration T
is the first of 5, 10, ... 95 s whose sampled path keeps |acceleration| <=
maxAccel and |jerk| <= maxJerk. The path is sampled every `step` seconds and
kept until the target moves by more than 0.1 m or turns by more than 0.05 rad.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState
from graphflow.world import WorldError
from graphflow_nodes._wheeled import yaw_of

SHORTEST_T, LONGEST_T = 5.0, 100.0      # s: durations tried, 5 s apart, below 100 s
MOVED, TURNED = 0.1, 0.05               # m, rad: a target closer than this to the planned one keeps the path

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.QuinticPathPlanner",
    version=1,
    aliases=("omni.isaac.wheeled_robots.QuinticPathPlanner",),
    description=(
        "On execIn, plans quintic polynomial x(t), y(t) from the robot's pose to the target (targetPrim's world "
        "pose, else targetPosition/targetOrientation) with the given end speeds and accelerations, within "
        "maxAccel and maxJerk, sampled every step seconds. pathArrays is the speeds, then x, then y, then "
        "yaw of the samples, concatenated; the path is re-planned only when the target moves."),
    categories=("isaacWheeledRobots",),
    ui_name="Quintic Path Planner",
    inputs=(
        Attribute("execIn", "execution", description="Plan (or keep the plan)"),
        Attribute("currentPosition", "vectord[3]", default=(0.0, 0.0, 0.0), description="Robot position, m"),
        Attribute("currentOrientation", "quatd[4]", default=(0.0, 0.0, 0.0, 0.0),
                  description="Robot orientation (x, y, z, w; all 0: yaw 0)"),
        Attribute("targetPrim", "target", optional=True, description="The goal prim (overrides targetPosition)"),
        Attribute("targetPosition", "vectord[3]", default=(0.0, 0.0, 0.0), description="Goal position, m"),
        Attribute("targetOrientation", "quatd[4]", default=(0.0, 0.0, 0.0, 0.0),
                  description="Goal orientation (x, y, z, w; all 0: yaw 0)"),
        Attribute("initialVelocity", "double", default=0.5, description="Speed at the start, m/s"),
        Attribute("initialAccel", "double", default=0.02, description="Acceleration at the start, m/s^2"),
        Attribute("goalVelocity", "double", default=0.5, description="Speed at the goal, m/s"),
        Attribute("goalAccel", "double", default=0.02, description="Acceleration at the goal, m/s^2"),
        Attribute("maxAccel", "double", default=1.5, description="Largest acceleration allowed, m/s^2"),
        Attribute("maxJerk", "double", default=0.3, description="Largest jerk allowed, m/s^3"),
        Attribute("step", "double", default=0.16666666667, description="Time between path samples, s"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after planning"),
        Attribute("pathArrays", "double[]", description="Speeds, x, y and yaw of the samples, concatenated"),
        Attribute("target", "double[3]", description="The planned-for target: x, y (m) and yaw (rad)"),
        Attribute("targetChanged", "bool", description="This compute planned a new path"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs, plan = db.inputs, db.internal
    goal = _goal(db)
    old = plan.get("target")
    changed = old is None or not (abs(goal[0] - old[0]) < MOVED and abs(goal[1] - old[1]) < MOVED
                                  and abs(goal[2] - old[2]) < TURNED)
    if changed:
        start = (inputs.currentPosition[0], inputs.currentPosition[1], yaw_of(inputs.currentOrientation))
        try:
            plan["path"] = plan_path(start, inputs.initialVelocity, inputs.initialAccel, goal, inputs.goalVelocity,
                                     inputs.goalAccel, inputs.maxAccel, inputs.maxJerk, inputs.step)
        except ValueError as error:
            db.error(str(error))
        plan["target"] = goal
    speeds, xs, ys, yaws = plan["path"]
    db.outputs.pathArrays = tuple(speeds + xs + ys + yaws)
    db.outputs.target = tuple(plan["target"])
    db.outputs.targetChanged = changed
    db.outputs.execOut = ExecState.ENABLED


def _goal(db) -> tuple[float, float, float]:
    """(x, y, yaw) of the target prim, else of the target inputs.

    Isaac takes a target prim's rotation angle about its own axis, which is the yaw for a prim turned
    counter-clockwise about +z; graphflow takes the yaw, the same there and right for clockwise turns too.
    """
    if db.inputs.targetPrim:
        try:
            position, orientation = db.world.prim_pose(db.inputs.targetPrim[0])
        except WorldError as error:
            db.error(f"inputs:targetPrim: {error}")
        return position[0], position[1], yaw_of(orientation)
    position = db.inputs.targetPosition
    return position[0], position[1], yaw_of(db.inputs.targetOrientation)


def _coefficients(start, start_speed, start_accel, end, end_speed, end_accel, duration):
    """a0..a5 of the quintic meeting position, speed and acceleration at t = 0 and t = duration."""
    import numpy as np
    a0, a1, a2 = start, start_speed, start_accel / 2.0
    t = duration
    matrix = np.array([[t ** 3, t ** 4, t ** 5], [3 * t ** 2, 4 * t ** 3, 5 * t ** 4], [6 * t, 12 * t ** 2, 20 * t ** 3]])
    rhs = np.array([end - a0 - a1 * t - a2 * t ** 2, end_speed - a1 - 2 * a2 * t, end_accel - 2 * a2])
    a3, a4, a5 = np.linalg.solve(matrix, rhs)
    return a0, a1, a2, a3, a4, a5


def _derivatives(a, t):
    """(value, first, second, third derivative) of the quintic with coefficients *a* at time *t*."""
    a0, a1, a2, a3, a4, a5 = a
    return (a0 + a1 * t + a2 * t ** 2 + a3 * t ** 3 + a4 * t ** 4 + a5 * t ** 5,
            a1 + 2 * a2 * t + 3 * a3 * t ** 2 + 4 * a4 * t ** 3 + 5 * a5 * t ** 4,
            2 * a2 + 6 * a3 * t + 12 * a4 * t ** 2 + 20 * a5 * t ** 3,
            6 * a3 + 24 * a4 * t + 60 * a5 * t ** 2)


def plan_path(start, start_speed, start_accel, goal, goal_speed, goal_accel, max_accel, max_jerk, step):
    """(speeds, xs, ys, yaws) sampled every *step* s on the shortest admissible duration; ValueError if none."""
    import numpy as np  # here, not at the top: loading the node library imports no numpy
    if not step > 0.0:
        raise ValueError(f"inputs:step must be positive, got {step}")
    (sx, sy, syaw), (gx, gy, gyaw) = start, goal
    for duration in np.arange(SHORTEST_T, LONGEST_T, SHORTEST_T):
        x = _coefficients(sx, start_speed * math.cos(syaw), start_accel * math.cos(syaw),
                          gx, goal_speed * math.cos(gyaw), goal_accel * math.cos(gyaw), float(duration))
        y = _coefficients(sy, start_speed * math.sin(syaw), start_accel * math.sin(syaw),
                          gy, goal_speed * math.sin(gyaw), goal_accel * math.sin(gyaw), float(duration))
        speeds, xs, ys, yaws, accels, jerks = [], [], [], [], [], []
        for t in np.arange(0.0, duration + step, step):
            px, vx, ax, jx = _derivatives(x, t)
            py, vy, ay, jy = _derivatives(y, t)
            speeds.append(float(math.hypot(vx, vy)))
            xs.append(float(px))
            ys.append(float(py))
            yaws.append(math.atan2(vy, vx))
            accels.append(math.hypot(ax, ay))
            jerks.append(math.hypot(jx, jy))
        if max(accels) <= max_accel and max(jerks) <= max_jerk:
            return speeds, xs, ys, yaws
    raise ValueError(f"no path to ({gx:g}, {gy:g}) keeps acceleration <= {max_accel:g} m/s^2 and jerk <= "
                     f"{max_jerk:g} m/s^3 within {LONGEST_T - SHORTEST_T:g} s")
