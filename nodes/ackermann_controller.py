"""isaacsim.robot.wheeled_robots.AckermannController: steering angles and wheel speeds of a car-like robot.

Isaac's bicycle model: the desired steering angle d (the yaw of a virtual
wheel at the middle of the steering axle) gives the turning radius
R = wheelBase / tan d (its sign flipped by invertSteering); the left and right
steering wheels turn atan(L / (R -/+ T/2)) for wheel base L and track T, and
each wheel turns at the body yaw rate v / |R| times its distance from the turn
centre over its radius (front wheels sqrt((|R| -/+ T/2)^2 + L^2), rear wheels
|R| -/+ T/2; the axles swap with invertSteering). Below 0.0157 rad the robot
drives straight: every wheel at v / r. Speed and steering angle ramp at
acceleration and steeringAngleVelocity per second when those are set; limits
at 0 are off.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

STRAIGHT = 0.0157     # rad: below this steering angle Isaac drives straight
SPEED_TOLERANCE, ANGLE_TOLERANCE = 0.0001, 0.00174533   # Isaac's "already there" thresholds

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.AckermannController",
    version=2,
    compatible_versions=(1,),
    aliases=("omni.isaac.wheeled_robots.AckermannController",),
    description=(
        "On execIn, turns a forward speed (m/s) and a steering angle (rad, + left) into the left and right "
        "steering wheel angles (rad) and the four wheel speeds (rad/s: front left, front right, back left, "
        "back right) of an Ackermann robot, ramping speed and angle at the given rates (0: at once)."),
    categories=("isaacWheeledRobots",),
    ui_name="Ackermann Controller",
    inputs=(
        Attribute("execIn", "execution", description="Compute the commands"),
        Attribute("acceleration", "double", default=0.0, description="Speed change per second, m/s^2 (0: at once)"),
        Attribute("maxAcceleration", "double", default=0.0, description="Limit of acceleration, m/s^2 (0: none)"),
        Attribute("speed", "double", default=0.0, description="Desired forward speed, m/s"),
        Attribute("steeringAngle", "double", default=0.0, description="Desired steering angle, rad (+ left)"),
        Attribute("maxWheelRotation", "double", default=6.28, description="Steering wheel angle limit, rad (0: none)"),
        Attribute("steeringAngleVelocity", "double", default=0.0,
                  description="Steering angle change per second, rad/s (0: at once)"),
        Attribute("maxSteeringAngleVelocity", "double", default=0.0,
                  description="Limit of steeringAngleVelocity, rad/s (0: none)"),
        Attribute("wheelBase", "double", default=0.0, description="Distance between the axles, m"),
        Attribute("trackWidth", "double", default=0.0, description="Distance between the left and right wheels, m"),
        Attribute("frontWheelRadius", "double", default=0.0, description="Front wheel radius, m"),
        Attribute("backWheelRadius", "double", default=0.0, description="Back wheel radius, m"),
        Attribute("maxWheelVelocity", "double", default=0.0, description="Wheel speed limit, rad/s (0: none)"),
        Attribute("invertSteering", "bool", default=False,
                  description="The steering joints are on the rear axle (forklifts)"),
        Attribute("dt", "double", default=0.0, description="Seconds since the last compute (0: the time step)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the commands were computed"),
        Attribute("wheelAngles", "double[]", description="[left, right] steering wheel angles, rad"),
        Attribute("wheelRotationVelocity", "double[]",
                  description="[front left, front right, back left, back right] wheel speeds, rad/s"),
    ),
    state=(
        Attribute("speedNow", "double", default=0.0, description="Forward speed commanded last, m/s"),
        Attribute("angleNow", "double", default=0.0, description="Steering angle commanded last, rad"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    front, back = abs(inputs.frontWheelRadius), abs(inputs.backWheelRadius)
    if front == 0.0 and back == 0.0:
        db.error("inputs:frontWheelRadius and inputs:backWheelRadius are both 0")
    front, back = front or back, back or front
    max_wheel = _limit(inputs.maxWheelVelocity)
    max_angle = _limit(inputs.maxWheelRotation)
    top_speed = abs(max_wheel * max(front, back))
    wanted_angle = _clip(inputs.steeringAngle, max_angle)
    wanted_speed = _clip(inputs.speed, top_speed)
    acceleration = min(abs(inputs.acceleration), _limit(inputs.maxAcceleration))
    turn_rate = min(abs(inputs.steeringAngleVelocity), _limit(inputs.maxSteeringAngleVelocity))
    dt = abs(inputs.dt) or db.time_step
    speed = _ramp(db.state.speedNow, wanted_speed, acceleration * dt, SPEED_TOLERANCE)
    angle = _ramp(db.state.angleNow, wanted_angle, turn_rate * dt, ANGLE_TOLERANCE)
    db.state.speedNow, db.state.angleNow = speed, angle
    if abs(angle) >= STRAIGHT and not inputs.wheelBase:
        db.error("inputs:wheelBase is 0: a steered robot needs the distance between its axles")
    angles, wheels = _wheels(speed, angle, abs(inputs.wheelBase), abs(inputs.trackWidth), front, back,
                             inputs.invertSteering)
    db.outputs.wheelAngles = tuple(_clip(a, max_angle) for a in angles)
    db.outputs.wheelRotationVelocity = tuple(_clip(w, max_wheel) for w in wheels)
    db.outputs.execOut = ExecState.ENABLED


def _wheels(speed, angle, base, track, front, back, inverted):
    """((left, right) steering angles, (fl, fr, bl, br) wheel speeds) of Isaac's bicycle model."""
    if abs(angle) < STRAIGHT:
        return (0.0, 0.0), (speed / front, speed / front, speed / back, speed / back)
    radius = (-1.0 if inverted else 1.0) * base / math.tan(angle)
    left, right = math.atan(base / (radius - 0.5 * track)), math.atan(base / (radius + 0.5 * track))
    centre, half = abs(radius), track / 2.0
    sign = 1.0 if angle > 0 else -1.0
    inner, outer = centre - sign * half, centre + sign * half
    steered = (math.hypot(inner, base), math.hypot(outer, base))
    fixed = (inner, outer)
    front_distances, back_distances = (fixed, steered) if inverted else (steered, fixed)
    yaw_rate = speed / centre
    return (left, right), (yaw_rate * front_distances[0] / front, yaw_rate * front_distances[1] / front,
                           yaw_rate * back_distances[0] / back, yaw_rate * back_distances[1] / back)


def _limit(value: float) -> float:
    return abs(value) if value else math.inf


def _clip(value: float, bound: float) -> float:
    return max(-bound, min(bound, value))


def _ramp(previous: float, wanted: float, step: float, tolerance: float) -> float:
    if step == 0.0 or abs(wanted - previous) <= tolerance:
        return wanted if step == 0.0 else previous
    return min(previous + step, wanted) if wanted > previous else max(previous - step, wanted)
