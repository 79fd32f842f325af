"""QuinticPathPlanner and StanleyControlPID against closed-form references."""
import math

import numpy as np
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.poses import quat_from_axis_angle
from graphflow.testing import NodeHarness

PLANNER = "isaacsim.robot.wheeled_robots.QuinticPathPlanner"
STANLEY = "isaacsim.robot.wheeled_robots.StanleyControlPID"
STEP = 1.0 / 6.0


def _split(path_arrays):
    count = len(path_arrays) // 4
    return [path_arrays[count * k:count * (k + 1)] for k in range(4)]


def test_a_10_m_straight_rest_to_rest_plan_is_the_minimum_jerk_profile_of_the_first_admissible_duration():
    """From rest to rest over d = 10 m the quintic is d (10 s^3 - 15 s^4 + 6 s^5), s = t / T: peak jerk
    60 d / T^3 and peak acceleration 10 d / (sqrt(3) T^2). T = 5 s breaks maxAccel (2.31 > 1.5), 10 s
    breaks maxJerk (0.6 > 0.3), so T = 15 s: peak speed 15 d / (8 T) = 1.25 m/s at the midpoint."""
    node = NodeHarness(PLANNER, {"targetPosition": [10.0, 0.0, 0.0], "initialVelocity": 0.0, "initialAccel": 0.0,
                                 "goalVelocity": 0.0, "goalAccel": 0.0, "step": 0.5})
    result = node.compute("execIn")
    assert result.fired == {"execOut"} and result.outputs["targetChanged"] is True
    speeds, xs, ys, yaws = _split(result.outputs["pathArrays"])
    times = np.arange(0.0, 15.0 + 0.5, 0.5)
    assert len(xs) == len(times) == 31
    s = times / 15.0
    assert xs == pytest.approx(10.0 * (10 * s ** 3 - 15 * s ** 4 + 6 * s ** 5), abs=1e-9)
    assert max(speeds) == pytest.approx(1.25) and speeds[15] == pytest.approx(1.25)
    assert ys == pytest.approx([0.0] * 31, abs=1e-12)
    assert result.outputs["target"] == (10.0, 0.0, 0.0)


def test_the_plan_meets_the_boundary_speeds_along_the_headings_and_is_kept_until_the_target_moves():
    goal_yaw = math.pi / 2
    inputs = {"currentPosition": [1.0, 2.0, 0.0], "targetPosition": [4.0, 6.0, 0.0],
              "targetOrientation": list(quat_from_axis_angle((0.0, 0.0, 1.0), goal_yaw)),
              "initialVelocity": 0.5, "goalVelocity": 0.3}
    node = NodeHarness(PLANNER, inputs)
    speeds, xs, ys, yaws = _split(node.compute("execIn").outputs["pathArrays"])
    assert (xs[0], ys[0], speeds[0], yaws[0]) == pytest.approx((1.0, 2.0, 0.5, 0.0))
    assert (xs[-1], ys[-1], speeds[-1], yaws[-1]) == pytest.approx((4.0, 6.0, 0.3, goal_yaw))
    node.set_inputs(targetPosition=[4.05, 6.0, 0.0])            # within 0.1 m: the plan stays
    assert node.compute("execIn").outputs["targetChanged"] is False
    node.set_inputs(targetPosition=[4.5, 6.0, 0.0])
    assert node.compute("execIn").outputs["targetChanged"] is True


def test_no_admissible_duration_is_a_one_line_error():
    node = NodeHarness(PLANNER, {"targetPosition": [1.0, 0.0, 0.0], "maxAccel": 0.0, "maxJerk": 0.0})
    with pytest.raises(GraphRuntimeError, match="no path to"):
        node.compute("execIn")


STRAIGHT = {"pathArrays": [1.0] * 11 + [0.1 * i for i in range(11)] + [0.0] * 11 + [0.0] * 11,
            "target": [1.0, 0.0, 0.0], "targetChanged": True, "maxVelocity": 1.0}


def test_stanley_on_the_path_at_rest_accelerates_straight():
    """On the path, facing along it, at rest: no steering, and v = gains[1] * profile[0] = 0.1 * 1 m/s."""
    out = NodeHarness(STANLEY, STRAIGHT).compute("execIn").outputs
    assert out["linearVelocity"] == pytest.approx(0.1)
    assert out["angularVelocity"] == pytest.approx(0.0, abs=1e-12)


def test_stanley_beside_the_path_steers_back_at_the_steering_limit():
    """0.2 m right of the path at 1 m/s: atan(0.5 * 0.2 / 1) = 0.0997 rad > the 0.0873 rad limit, so the
    bicycle (base 0.4132 * 0.1 m) turns left at 1 / 0.04132 * tan(0.0873) rad/s; speed stays 1 m/s (profile
    1 m/s) and the differential widening is 1 + |0.4132 w / 1| * 0.1 / step."""
    out = NodeHarness(STANLEY, {**STRAIGHT, "currentPosition": [0.3, -0.2, 0.0],
                                "currentSpeed": [1.0, 0.0, 0.0]}).compute("execIn").outputs
    bicycle_turn = 1.0 / (0.4132 * 0.1) * math.tan(0.0872665)
    assert out["linearVelocity"] == pytest.approx(1.0)
    assert out["angularVelocity"] == pytest.approx(bicycle_turn * (1.0 + 0.4132 * bicycle_turn * 0.1 / STEP))


def test_stanley_at_the_target_turns_in_place_towards_its_yaw_and_stops_when_reached():
    at_target = {**STRAIGHT, "currentPosition": [1.0, 0.0, 0.0], "target": [1.0, 0.0, 0.5]}
    out = NodeHarness(STANLEY, at_target).compute("execIn").outputs
    assert out["linearVelocity"] == 0.0
    assert out["angularVelocity"] == pytest.approx(0.5 * 0.1 / STEP)      # 0.3 rad/s, under the 1 rad/s cap
    done = NodeHarness(STANLEY, {**at_target, "reachedGoal": [True, True]}).compute("execIn")
    assert done.fired == {"execOut"}
    assert (done.outputs["linearVelocity"], done.outputs["angularVelocity"]) == (0.0, 0.0)
