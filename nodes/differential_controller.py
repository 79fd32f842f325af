"""isaacsim.robot.wheeled_robots.DifferentialController: wheel speeds of a two-wheel drive.

left = (2 v - w d) / (2 r), right = (2 v + w d) / (2 r) (rad/s) for forward
speed v (m/s), yaw rate w (rad/s), wheel distance d and radius r (m). Limits
that are 0 are off: speeds are clamped to maxLinearSpeed / maxAngularSpeed;
changes of v and w per compute to the acceleration limits times dt (dt 0:
the tick's time step); wheel speeds to maxWheelSpeed.
"""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

SPEC = NodeSpec(
    id="isaacsim.robot.wheeled_robots.DifferentialController",
    version=1,
    aliases=("omni.isaac.wheeled_robots.DifferentialController",),
    description=(
        "On execIn, turns linearVelocity (m/s) and angularVelocity (rad/s) into [left, right] wheel velocity "
        "commands (rad/s), with optional speed, acceleration and wheel-speed limits (0 = no limit)."),
    categories=("isaacWheeledRobots",),
    ui_name="Differential Controller",
    inputs=(
        Attribute("execIn", "execution", description="Compute the wheel commands"),
        Attribute("linearVelocity", "double", default=0.0, description="Desired forward speed, m/s"),
        Attribute("angularVelocity", "double", default=0.0, description="Desired yaw rate, rad/s"),
        Attribute("wheelRadius", "double", default=0.0, minimum=0.0, description="Wheel radius, m"),
        Attribute("wheelDistance", "double", default=0.0, minimum=0.0, description="Distance between the wheels, m"),
        Attribute("maxLinearSpeed", "double", default=0.0, minimum=0.0, description="Forward speed limit, m/s"),
        Attribute("maxAngularSpeed", "double", default=0.0, minimum=0.0, description="Yaw rate limit, rad/s"),
        Attribute("maxWheelSpeed", "double", default=0.0, minimum=0.0, description="Wheel speed limit, rad/s"),
        Attribute("maxAcceleration", "double", default=0.0, minimum=0.0, description="Forward acceleration limit, m/s^2"),
        Attribute("maxDeceleration", "double", default=0.0, minimum=0.0, description="Forward deceleration limit, m/s^2"),
        Attribute("maxAngularAcceleration", "double", default=0.0, minimum=0.0, description="Yaw acceleration limit, rad/s^2"),
        Attribute("dt", "double", default=0.0, minimum=0.0, description="Seconds since the last compute (0: the time step)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the commands were computed"),
        Attribute("velocityCommand", "double[]", default=(0.0, 0.0), description="[left, right] wheel velocities, rad/s"),
        Attribute("positionCommand", "double[]", description="Empty: this controller commands velocities"),
        Attribute("effortCommand", "double[]", description="Empty: this controller commands velocities"),
    ),
    state=(
        Attribute("linear", "double", default=0.0, description="Forward speed commanded last, m/s"),
        Attribute("angular", "double", default=0.0, description="Yaw rate commanded last, rad/s"),
    ),
)


def compute(db):
    if db.inputs.execIn != ExecState.ENABLED:
        return
    inputs = db.inputs
    if not inputs.wheelRadius > 0 or not inputs.wheelDistance > 0:
        db.error("inputs:wheelRadius and inputs:wheelDistance must be positive")
    dt = inputs.dt or db.time_step
    linear = _limit(inputs.linearVelocity, inputs.maxLinearSpeed)
    angular = _limit(inputs.angularVelocity, inputs.maxAngularSpeed)
    speeding_up = abs(linear) > abs(db.state.linear) and linear * db.state.linear >= 0
    linear = _ramp(db.state.linear, linear, (inputs.maxAcceleration if speeding_up else inputs.maxDeceleration) * dt)
    angular = _ramp(db.state.angular, angular, inputs.maxAngularAcceleration * dt)
    db.state.linear, db.state.angular = linear, angular
    half_track = angular * inputs.wheelDistance / 2.0
    wheels = ((linear - half_track) / inputs.wheelRadius, (linear + half_track) / inputs.wheelRadius)
    db.outputs.velocityCommand = tuple(_limit(w, inputs.maxWheelSpeed) for w in wheels)
    db.outputs.execOut = ExecState.ENABLED


def _limit(value: float, bound: float) -> float:
    return max(-bound, min(bound, value)) if bound > 0 else value


def _ramp(previous: float, wanted: float, step: float) -> float:
    if step <= 0 or math.isclose(previous, wanted):
        return wanted
    return previous + max(-step, min(step, wanted - previous))
