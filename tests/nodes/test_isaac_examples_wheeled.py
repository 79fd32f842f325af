"""The wheeled-robot nodes on the examples of Isaac Sim's own tests (isaacsim.robot.wheeled_robots.nodes and the
deprecated controllers' tests): Isaac's inputs and expected numbers as facts, each beside an independent reference.

Where Isaac's test needs its Forklift or Jetbot asset and PhysX, only the controller's part (the commands it sends)
is checked here; the physics of a driven robot is covered by the shipped graphs' verdicts.
"""
import math

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness

ACKERMANN = "isaacsim.robot.wheeled_robots.AckermannController"
DIFFERENTIAL = "isaacsim.robot.wheeled_robots.DifferentialController"
HOLONOMIC = "isaacsim.robot.wheeled_robots.HolonomicController"

# Isaac's deprecated Ackermann test: a car of wheel base 1.65 m, track 1.25 m, wheels of 0.25 m
BASE, TRACK, RADIUS = 1.65, 1.25, 0.25
CAR = {"wheelBase": BASE, "trackWidth": TRACK, "frontWheelRadius": RADIUS}


def _ackermann_geometry(speed, turn_radius):
    """(left, right) steering angles and (fl, fr, bl, br) wheel speeds of a rigid body turning about (0, R)."""
    half = TRACK / 2
    angles = (math.atan(BASE / (turn_radius - half)), math.atan(BASE / (turn_radius + half)))
    yaw_rate = speed / turn_radius
    distances = (math.hypot(turn_radius - half, BASE), math.hypot(turn_radius + half, BASE),
                 turn_radius - half, turn_radius + half)
    return angles, tuple(yaw_rate * d / RADIUS for d in distances)


@pytest.mark.parametrize(("speed", "yaw_rate"), [(1.5, 0.4), (10.5, 0.0001)])
def test_ackermann_instant_steering_example(speed, yaw_rate):
    """Isaac's test_ackermann_steering_control: the steering angle atan(L / R) for R = v / w, no ramps; every
    output within Isaac's 0.001. The second case steers 1.6e-5 rad, below the 0.0157 rad under which Isaac's
    node drives straight: the straight speeds v / r differ from the turn's by 2.5e-4 rad/s, inside 0.001."""
    turn_radius = speed / yaw_rate
    outputs = NodeHarness(ACKERMANN, {**CAR, "speed": speed, "steeringAngle": math.atan(BASE / turn_radius)}
                          ).compute("execIn").outputs
    angles, wheels = _ackermann_geometry(speed, turn_radius)
    assert outputs["wheelAngles"] == pytest.approx(angles, abs=1e-3)
    assert outputs["wheelRotationVelocity"] == pytest.approx(wheels, abs=1e-3)
    if yaw_rate == 0.4:   # a real turn: the rigid-body geometry exactly
        assert outputs["wheelAngles"] == pytest.approx(angles, rel=1e-12)
        assert outputs["wheelRotationVelocity"] == pytest.approx(wheels, rel=1e-12)


@pytest.mark.parametrize(("speed", "yaw_rate", "acceleration", "steering_rate", "dt"), [
    (1.1, 0.2, 0.02, 0.05, 0.05), (3.1, 0.15, 0.2, 0.07, 0.015), (3.1, 0.5, 0.13, 0.12, 1 / 60)])
def test_ackermann_ramped_steering_and_speed_example(speed, yaw_rate, acceleration, steering_rate, dt):
    """Isaac's test_ackermann_steering_velocity_drive_acceleration: steering angle and speed ramp at their rates;
    before int(target / (rate dt)) - 1 computes every output is below its final value, after it within 0.01."""
    turn_radius = speed / yaw_rate
    steer = math.atan(BASE / turn_radius)
    node = NodeHarness(ACKERMANN, {**CAR, "speed": speed, "steeringAngle": steer, "acceleration": acceleration,
                                   "steeringAngleVelocity": steering_rate, "dt": dt})
    steering_computes = int(abs(steer / (steering_rate * dt))) - 1
    speed_computes = int(abs(speed / (acceleration * dt))) - 1
    angles, wheels = _ackermann_geometry(speed, turn_radius)
    for i in range(max(steering_computes, speed_computes)):
        outputs = node.compute("execIn").outputs
        if i < steering_computes:
            assert all(a < final for a, final in zip(outputs["wheelAngles"], angles))
        else:
            assert outputs["wheelAngles"] == pytest.approx(angles, abs=0.01)
        if i < speed_computes:
            assert all(w < final for w, final in zip(outputs["wheelRotationVelocity"], wheels))
        else:
            assert outputs["wheelRotationVelocity"] == pytest.approx(wheels, abs=0.01)
    # the ramp itself: after k computes the commanded speed is k a dt
    computes = max(steering_computes, speed_computes)
    assert node.state.speedNow == pytest.approx(min(speed, computes * acceleration * dt), rel=1e-9)


def test_ackermann_forklift_graph_commands_of_isaacs_node_test():
    """Isaac's node test drives its forklift (wheel base 1.65, track 1.05, front wheels 0.325, back 0.255,
    steering on the rear axle) at 1.5 m/s and +-0.3 rad and expects a circle of radius L / tan 0.3 at yaw rate
    v tan(0.3) / L; the commands it sends are those of a rigid body turning about that centre."""
    forklift = {"wheelBase": 1.65, "trackWidth": 1.05, "frontWheelRadius": 0.325, "backWheelRadius": 0.255,
                "invertSteering": True}
    for steer in (0.3, -0.3):
        outputs = NodeHarness(ACKERMANN, {**forklift, "speed": 1.5, "steeringAngle": steer}).compute("execIn").outputs
        centre = 1.65 / math.tan(abs(steer))
        yaw_rate = 1.5 / centre
        inner, outer = centre - 0.525, centre + 0.525
        # steered rear wheels sit on the far axle from the turn centre's line: hypot with the wheel base
        if steer > 0:
            expected = (inner / 0.325, outer / 0.325, math.hypot(inner, 1.65) / 0.255, math.hypot(outer, 1.65) / 0.255)
        else:
            expected = (outer / 0.325, inner / 0.325, math.hypot(outer, 1.65) / 0.255, math.hypot(inner, 1.65) / 0.255)
        assert outputs["wheelRotationVelocity"] == pytest.approx([yaw_rate * d for d in expected], rel=1e-12)
        # rear steering turns the other way: the left wheel's angle has the opposite sign of the command
        left, right = outputs["wheelAngles"]
        assert math.copysign(1.0, left) == -math.copysign(1.0, steer)
        assert abs(1 / math.tan(right) - 1 / math.tan(left)) == pytest.approx(1.05 / 1.65)


JETBOT = {"wheelRadius": 0.03, "wheelDistance": 0.1125, "linearVelocity": 0.3, "angularVelocity": 1.0}


def test_differential_example_of_isaacs_node_and_controller_tests():
    """Isaac's tests (node and controller) expect exactly 8.125 and 11.875 rad/s for the Jetbot's wheels at
    0.3 m/s and 1 rad/s: (v -+ w d / 2) / r; with maxWheelSpeed 9 the right wheel is cut to 9."""
    node = NodeHarness(DIFFERENTIAL, JETBOT)
    for _ in range(4):   # Isaac reads it after one update then three more
        outputs = node.compute("execIn").outputs
    assert outputs["velocityCommand"] == (8.125, 11.875)
    assert (0.3 - 1.0 * 0.1125 / 2) / 0.03 == pytest.approx(8.125) and (0.3 + 1.0 * 0.1125 / 2) / 0.03 == pytest.approx(11.875)
    limited = NodeHarness(DIFFERENTIAL, {**JETBOT, "maxWheelSpeed": 9.0}).compute("execIn").outputs
    assert limited["velocityCommand"] == (8.125, 9.0)


def test_differential_acceleration_limits_example():
    """Isaac's test_differential_controller_node_acceleration_limits: maxAcceleration = maxDeceleration =
    1 m/s^2 at dt 1/60; after four computes both wheels are below the
    unlimited 8.125 and 11.875. The speed is then 4/60 m/s (the yaw rate is not limited), so the wheels turn
    at (4/60 -+ 0.05625) / 0.03."""
    node = NodeHarness(DIFFERENTIAL, {**JETBOT, "maxAcceleration": 1.0, "maxDeceleration": 1.0, "dt": 1 / 60})
    for _ in range(4):
        outputs = node.compute("execIn").outputs
    left, right = outputs["velocityCommand"]
    assert left < 8.125 and right < 11.875
    assert (left, right) == pytest.approx(((4 / 60 - 0.05625) / 0.03, (4 / 60 + 0.05625) / 0.03), rel=1e-12)


def test_differential_reset_zeroes_the_commands():
    """Isaac's reset test: after the timeline stops, nothing is commanded until the node computes again. Isaac
    also writes 0 into the node's velocity inputs on stop; graphflow's reset restores the authored graph (a new
    run), so the next compute commands the authored speeds again."""
    node = NodeHarness(DIFFERENTIAL, {**JETBOT, "maxAcceleration": 1.0, "maxDeceleration": 1.0, "dt": 1 / 60})
    for _ in range(4):
        node.compute("execIn")
    node.reset()
    assert node.outputs.velocityCommand == (0.0, 0.0)
    assert node.state.linear == 0.0   # the ramp starts again from rest
    first = node.compute("execIn").outputs["velocityCommand"]
    assert first == pytest.approx(((1 / 60 - 0.05625) / 0.03, (1 / 60 + 0.05625) / 0.03), rel=1e-12)


THREE_WHEELS = {"wheelRadius": [0.04, 0.04, 0.04], "mecanumAngles": [90, 90, 90],
                "wheelOrientations": [[0, 0, 0, 1], [0.866, 0, 0, -0.5], [0.866, 0, 0, 0.5]],
                "wheelPositions": [[-0.0980432, 0.000636773, -0.050501], [0.0493475, -0.084525, -0.050501],
                                   [0.0495291, 0.0856937, -0.050501]]}


def test_holonomic_node_example_and_its_reset():
    """Isaac's node test: the three-wheel base at (1, 1, 0.1) gives -25.1053, 14.3182, -14.5417 within its
    0.01; after a stop the command is zero. (The unique solution is checked against an independent solve in
    test_isaac_library_nodes.)"""
    node = NodeHarness(HOLONOMIC, {**THREE_WHEELS, "inputVelocity": [1.0, 1.0, 0.1]})
    speeds = node.compute("execIn").outputs["jointVelocityCommand"]
    assert speeds == pytest.approx([-25.1053, 14.3182, -14.5417], abs=0.01)
    node.reset()
    assert not any(node.outputs.jointVelocityCommand)


def test_check_goal_example_with_the_default_zero_quaternion():
    """Isaac's guard test: CheckGoal2D at the target with its orientation left at the .ogn's zero default
    reaches both goals (a zero quaternion is read as yaw 0)."""
    node = NodeHarness("isaacsim.robot.wheeled_robots.CheckGoal2D", {
        "currentPosition": [0.0, 0.0, 0.0], "target": [0.0, 0.0, 0.0], "targetChanged": True,
        "thresholds": [0.1, 0.1]})
    assert tuple(node.database.inputs.currentOrientation) == (0.0, 0.0, 0.0, 0.0)   # the .ogn declares no default
    assert list(node.compute("execIn").outputs["reachedGoal"]) == [True, True]


def test_quintic_planner_example_with_default_zero_quaternions():
    """Isaac's guard test: a 1 m plan along x with both orientations at the zero default and generous limits
    is finite and not empty; its samples start at the robot and end at the target, heading along x."""
    node = NodeHarness("isaacsim.robot.wheeled_robots.QuinticPathPlanner", {
        "currentPosition": [0.0, 0.0, 0.0], "targetPosition": [1.0, 0.0, 0.0], "maxAccel": 1000.0,
        "maxJerk": 1000.0})
    outputs = node.compute("execIn").outputs
    path, target = outputs["pathArrays"], outputs["target"]
    assert path and all(math.isfinite(v) for v in path) and all(math.isfinite(v) for v in target)
    assert tuple(target) == (1.0, 0.0, 0.0)
    count = len(path) // 4
    xs, ys, yaws = path[count:2 * count], path[2 * count:3 * count], path[3 * count:]
    assert xs[0] == pytest.approx(0.0) and xs[-1] == pytest.approx(1.0, abs=1e-6)
    assert max(abs(y) for y in ys) == 0.0 and yaws[0] == yaws[-1] == 0.0
    # the limits admit the shortest duration, in which starting and ending at 0.5 m/s overshoots: the x samples
    # go back between, where the heading (that of the velocity, as Isaac's planner) is pi
    assert any(later < earlier for earlier, later in zip(xs, xs[1:]))
    assert {round(a, 12) for a in yaws} == {0.0, round(math.pi, 12)}


def test_quintic_planner_with_exhausted_constraints_fails():
    """Isaac's planner test: no acceleration or jerk allowed (both 0) admits no plan: an error, not a path."""
    node = NodeHarness("isaacsim.robot.wheeled_robots.QuinticPathPlanner", {
        "targetPosition": [1.0, 0.0, 0.0], "initialVelocity": 0.0, "initialAccel": 0.0, "goalVelocity": 0.0,
        "goalAccel": 0.0, "maxAccel": 0.0, "maxJerk": 0.0, "step": 1.0})
    with pytest.raises(GraphRuntimeError):
        node.compute("execIn")


def test_stanley_example_with_the_default_zero_quaternion():
    """Isaac's guard test: StanleyControlPID at rest, target (0, 0, 0.5), orientation left at the zero default:
    both commands are finite. Without targetChanged Isaac keeps its initial target, the origin, where the robot
    already is, so it stands still (turning only towards that target's yaw 0)."""
    outputs = NodeHarness("isaacsim.robot.wheeled_robots.StanleyControlPID", {
        "currentPosition": [0.0, 0.0, 0.0], "currentSpeed": [0.0, 0.0, 0.0], "reachedGoal": [False, False],
        "target": [0.0, 0.0, 0.5], "thresholds": [0.1, 0.1], "wheelBase": 0.4132, "step": 0.16666666667,
    }).compute("execIn").outputs
    assert (outputs["linearVelocity"], outputs["angularVelocity"]) == (0.0, 0.0)


def test_stanley_angle_wrapping_example():
    """Isaac's Stanley helper test: 5 pi -> pi, -5 pi -> -pi, 1.5 pi -> -0.5 pi; a non-finite angle is refused."""
    from graphflow_nodes._wheeled import normalize_angle

    assert normalize_angle(5 * math.pi) == pytest.approx(math.pi)
    assert normalize_angle(-5 * math.pi) == pytest.approx(-math.pi)
    assert normalize_angle(1.5 * math.pi) == pytest.approx(-0.5 * math.pi)
    for angle in (math.inf, -math.inf, math.nan):
        with pytest.raises(ValueError):
            normalize_angle(angle)


def _three_wheel_rows():
    """The three-wheel base's rows, built independently: each wheel's x axis turned by its (normalised,
    w-first) quaternion, then 90 degrees about z by its roller, times the radius; its yaw moment about the centre."""
    rows = []
    for (w, x, y, z), (px, py, _) in zip(THREE_WHEELS["wheelOrientations"], THREE_WHEELS["wheelPositions"]):
        norm = math.sqrt(w * w + x * x + y * y + z * z)
        w, x, y, z = w / norm, x / norm, y / norm, z / norm
        axis = (1 - 2 * (y * y + z * z), 2 * (x * y + w * z))
        dx, dy = -axis[1] * 0.04, axis[0] * 0.04
        rows.append((dx, dy, dx * py - dy * px))
    return rows


def test_holonomic_forward_command_moves_the_base_forward():
    """Isaac's experimental controller test: a pure forward command (1, 0, 0) gives a positive net x velocity.
    Here the wheels produce exactly (1, 0, 0) through the independently built geometry."""
    speeds = NodeHarness(HOLONOMIC, {**THREE_WHEELS, "inputVelocity": [1.0, 0.0, 0.0]}).compute("execIn").outputs[
        "jointVelocityCommand"]
    produced = [sum(row[k] * s for row, s in zip(_three_wheel_rows(), speeds)) for k in range(3)]
    assert produced[0] > 0
    assert produced == pytest.approx([1.0, 0.0, 0.0], abs=1e-9)


@pytest.mark.parametrize("missing", ["wheelRadius", "wheelPositions", "wheelOrientations", "mecanumAngles"])
def test_holonomic_without_a_wheel_parameter_is_refused(missing):
    """Isaac's experimental controller refuses a missing wheel array (ValueError; its node logs the empty list)."""
    inputs = {**THREE_WHEELS, "inputVelocity": [1.0, 0.0, 0.0], missing: []}
    with pytest.raises(GraphRuntimeError, match="inputs:"):
        NodeHarness(HOLONOMIC, inputs).compute("execIn")
