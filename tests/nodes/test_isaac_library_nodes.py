"""Isaac Sim node types added from the published .ogn files, checked against closed-form references."""
import math

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.poses import quat_from_axis_angle
from graphflow.testing import ClockWorld, NodeHarness

ACKERMANN = "isaacsim.robot.wheeled_robots.AckermannController"
CAR = {"wheelBase": 2.5, "trackWidth": 1.5, "frontWheelRadius": 0.3, "backWheelRadius": 0.3}


def test_ackermann_turn_matches_rigid_body_kinematics_about_the_turn_centre():
    speed, steer = 3.0, 0.3
    result = NodeHarness(ACKERMANN, {**CAR, "speed": speed, "steeringAngle": steer}).compute("execIn")
    base, track, radius = 2.5, 1.5, 0.3
    # independent reference: the rear axle centre moves at `speed` about the turn centre (0, R), R = L / tan(steer)
    centre = base / math.tan(steer)
    yaw_rate = speed / centre
    wheels = {"fl": (base, track / 2), "fr": (base, -track / 2), "bl": (0.0, track / 2), "br": (0.0, -track / 2)}
    expected_speeds = [yaw_rate * math.hypot(x, y - centre) / radius for x, y in wheels.values()]
    # a steered wheel rolls perpendicular to the line to the turn centre
    expected_angles = [math.atan2(base, centre - track / 2), math.atan2(base, centre + track / 2)]
    assert result.outputs["wheelRotationVelocity"] == pytest.approx(expected_speeds, rel=1e-12)
    assert result.outputs["wheelAngles"] == pytest.approx(expected_angles, rel=1e-12)
    # Ackermann's condition: cot(right) - cot(left) = track / base
    left, right = result.outputs["wheelAngles"]
    assert 1 / math.tan(right) - 1 / math.tan(left) == pytest.approx(track / base)


def test_ackermann_straight_ramps_speed_at_the_acceleration():
    node = NodeHarness(ACKERMANN, {**CAR, "speed": 2.0, "acceleration": 1.0, "dt": 0.5})
    speeds = [node.compute("execIn").outputs["wheelRotationVelocity"][0] for _ in range(5)]
    assert speeds == pytest.approx([0.5 / 0.3, 1.0 / 0.3, 1.5 / 0.3, 2.0 / 0.3, 2.0 / 0.3])   # v / r, +0.5 m/s a step
    with pytest.raises(GraphRuntimeError, match="wheelBase is 0"):
        NodeHarness(ACKERMANN, {"frontWheelRadius": 0.3, "steeringAngle": 0.4, "speed": 1.0}).compute("execIn")


def _stage_world(meters_per_unit):
    from pxr import Usd, UsdGeom

    world = ClockWorld(0.1)
    world.stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageMetersPerUnit(world.stage, meters_per_unit)
    return world


@pytest.mark.parametrize("type_id", ["isaacsim.core.nodes.OgnIsaacScaleToFromStageUnit",
                                     "omni.isaac.core_nodes.OgnIsaacScaleToFromStageUnit"])
def test_scale_to_and_from_centimetre_stage_units(type_id):
    world = _stage_world(0.01)
    to_stage = NodeHarness(type_id, {"value": [1.5, 0.0, -0.25]}, world=world).compute()
    assert to_stage.outputs["result"] == pytest.approx((150.0, 0.0, -25.0))
    to_meters = NodeHarness(type_id, {"value": 150.0, "conversion": "Convert to meters"}, world=world).compute()
    assert to_meters.outputs["result"] == pytest.approx(1.5)
    assert NodeHarness(type_id, {"value": 2.0}).compute().outputs["result"] == 2.0   # no stage: metres


class DrivingWorld(ClockWorld):
    """A chassis that starts at (1, 2, 0) facing +y (yaw 90 deg) and drives at 2 m/s along world +x while turning."""

    YAW_RATE = 0.5

    def prim_pose(self, path):
        yaw = math.pi / 2 + self.YAW_RATE * self.time
        return (1.0 + 2.0 * self.time, 2.0, 0.0), quat_from_axis_angle((0.0, 0.0, 1.0), yaw)

    def prim_velocity(self, path):
        return (2.0 + self.time, 0.0, 0.0), (0.0, 0.0, self.YAW_RATE)   # speeding up at 1 m/s^2


def test_compute_odometry_is_relative_to_the_start_pose():
    world = DrivingWorld(0.5)
    node = NodeHarness("isaacsim.core.nodes.IsaacComputeOdometry", {"chassisPrim": ["/World/robot"]}, world=world)
    first = node.compute("execIn")
    assert first.outputs["position"] == pytest.approx((0.0, 0.0, 0.0))
    assert first.outputs["linearVelocity"] == pytest.approx((0.0, -2.0, 0.0))   # +x world is the chassis' -y
    node.tick()
    later = node.tick("execIn")
    t = 1.0   # two steps of 0.5 s
    # moved 2 m along world +x: in the start frame (facing +y) that is 2 m to the right, -y
    assert later.outputs["position"] == pytest.approx((0.0, -2.0 * t, 0.0), abs=1e-12)
    yaw = later.outputs["orientation"]
    assert 2 * math.atan2(yaw[2], yaw[3]) == pytest.approx(DrivingWorld.YAW_RATE * t)
    assert later.outputs["globalLinearVelocity"] == pytest.approx((2.0 + t, 0.0, 0.0))
    assert later.outputs["globalLinearAcceleration"] == pytest.approx((1.0, 0.0, 0.0))   # (3 - 2) m/s over 1 s
    assert later.outputs["angularVelocity"] == pytest.approx((0.0, 0.0, 0.5))


@pytest.mark.parametrize(("time", "split"), [
    (1.25, (1, 250, 250_000, 250_000_000)), (-1.25, (-2, 750, 750_000, 750_000_000)), (3.0, (3, 0, 0, 0))])
def test_time_splitter_splits_seconds_like_a_ros_stamp(time, split):
    outputs = NodeHarness("isaacsim.core.nodes.IsaacTimeSplitter", {"time": time}).compute().outputs
    assert (outputs["seconds"], outputs["milliseconds"], outputs["microseconds"], outputs["nanoseconds"]) == split


def test_simulation_gate_passes_every_step_th_pulse():
    node = NodeHarness("isaacsim.core.nodes.IsaacSimulationGate", {"step": 3})
    fired = ["execOut" in node.compute("execIn").fired for _ in range(6)]
    assert fired == [False, False, True, False, False, True]
    node = NodeHarness("isaacsim.core.nodes.IsaacSimulationGate", {"step": 0})
    assert not any("execOut" in node.compute("execIn").fired for _ in range(3))


def test_read_world_pose_reads_the_world():
    world = DrivingWorld(0.5)
    outputs = NodeHarness("isaacsim.core.nodes.IsaacReadWorldPose", {"prim": ["/World/robot"]}, world=world).compute().outputs
    assert outputs["translation"] == (1.0, 2.0, 0.0) and outputs["scale"] == (1.0, 1.0, 1.0)


HOLONOMIC = "isaacsim.robot.wheeled_robots.HolonomicController"
MECANUM = {"wheelRadius": [0.05], "mecanumAngles": [45.0, -45.0, -45.0, 45.0],
           "wheelPositions": [[0.2, 0.15, 0.0], [0.2, -0.15, 0.0], [-0.2, 0.15, 0.0], [-0.2, -0.15, 0.0]],
           "wheelOrientations": [[1.0, 0.0, 0.0, 0.0]] * 4}


def _wheel_rows(radius=0.05):
    """Each wheel's velocity direction (its x axis turned by its roller angle) times r, and its yaw moment."""
    rows = []
    for (x, y, _), angle in zip(MECANUM["wheelPositions"], MECANUM["mecanumAngles"]):
        dx, dy = math.cos(math.radians(angle)) * radius, math.sin(math.radians(angle)) * radius
        rows.append((dx, dy, dx * y - dy * x))
    return rows


def test_holonomic_three_wheel_example_of_isaacs_own_test():
    """Isaac's controller test: a three-wheel omni base (90 degree rollers, wheels turned 0 and +-120 degrees
    about x, orientations w-first) commanded (1, 1, 0.1). Three wheels, three constraints: the speeds are the
    system's unique solution, which Isaac's QP solver (OSQP, tolerance 1e-3) reaches within 0.05 %; its test
    expects -25.105, 14.3182, -14.5417."""
    speeds = NodeHarness(HOLONOMIC, {
        "wheelRadius": [0.04, 0.04, 0.04], "mecanumAngles": [90, 90, 90], "inputVelocity": [1.0, 1.0, 0.1],
        "wheelOrientations": [[0, 0, 0, 1], [0.866, 0, 0, -0.5], [0.866, 0, 0, 0.5]],
        "wheelPositions": [[-0.0980432, 0.000636773, -0.050501], [0.0493475, -0.084525, -0.050501],
                           [0.0495291, 0.0856937, -0.050501]]}).compute("execIn").outputs["jointVelocityCommand"]
    assert speeds == pytest.approx([-25.105, 14.3182, -14.5417], rel=5e-4)
    import numpy as np

    # the same system built independently: a wheel's x axis turned by its quaternion, then 90 degrees about z
    directions = []
    for w, x, y, z in [(0, 0, 0, 1), (0.866, 0, 0, -0.5), (0.866, 0, 0, 0.5)]:
        norm = math.sqrt(w * w + x * x + y * y + z * z)
        w, x, y, z = w / norm, x / norm, y / norm, z / norm
        axis = np.array([1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)])   # R @ (1, 0, 0)
        turned = np.array([-axis[1], axis[0], axis[2]])
        directions.append(turned / np.linalg.norm(turned) * 0.04)
    positions = [(-0.0980432, 0.000636773), (0.0493475, -0.084525), (0.0495291, 0.0856937)]
    a = np.array([[d[0] for d in directions], [d[1] for d in directions],
                  [d[0] * p[1] - d[1] * p[0] for d, p in zip(directions, positions)]])
    assert speeds == pytest.approx(list(np.linalg.solve(a, [1.0, 1.0, 0.1])), rel=1e-9)


@pytest.mark.parametrize("command", [(0.4, 0.0, 0.0), (0.0, 0.3, 0.0), (0.2, -0.1, 0.8)])
def test_holonomic_wheel_speeds_satisfy_the_programs_optimality_conditions(command):
    speeds = NodeHarness(HOLONOMIC, {**MECANUM, "inputVelocity": list(command)}).compute("execIn").outputs[
        "jointVelocityCommand"]
    rows = _wheel_rows()
    # feasibility: the wheels produce the command
    produced = [sum(row[k] * s for row, s in zip(rows, speeds)) for k in range(3)]
    assert produced == pytest.approx(list(command), abs=1e-12)
    # optimality (equal radii: plain least norm): the speeds lie in the span of the three constraint rows
    import numpy as np

    a = np.array(rows).T
    multipliers, *_ = np.linalg.lstsq(a.T, np.array(speeds), rcond=None)
    assert a.T @ multipliers == pytest.approx(np.array(speeds), abs=1e-12)


def test_holonomic_limits_scale_the_wheels_together():
    fast = NodeHarness(HOLONOMIC, {**MECANUM, "inputVelocity": [1.0, 0.0, 0.0], "maxWheelSpeed": 5.0}).compute("execIn")
    speeds = fast.outputs["jointVelocityCommand"]
    assert max(abs(s) for s in speeds) == pytest.approx(5.0)
    still = NodeHarness(HOLONOMIC, {**MECANUM}).compute("execIn").outputs["jointVelocityCommand"]
    assert still == (0.0, 0.0, 0.0, 0.0)
    with pytest.raises(GraphRuntimeError, match="mecanumAngles needs one entry per wheel"):
        NodeHarness(HOLONOMIC, {**MECANUM, "mecanumAngles": [45.0, 45.0]}).compute("execIn")


def test_articulation_state_reads_the_chosen_joints():
    from .fakes import FakeArticulationWorld

    world = FakeArticulationWorld({"/World/arm": ("shoulder", "elbow", "wrist")})
    world.positions["/World/arm"] = [0.1, 0.2, 0.3]
    world.joint_velocities = lambda path: (1.0, 2.0, 3.0)
    world.set_joint_targets("/World/arm", [0, 2], efforts=[4.0, 6.0])
    by_name = NodeHarness("isaacsim.core.nodes.IsaacArticulationState",
                          {"robotPath": "/World/arm", "jointNames": ["wrist", "shoulder"]}, world=world).compute("execIn")
    assert by_name.outputs["jointNames"] == ("wrist", "shoulder")
    assert by_name.outputs["jointPositions"] == (0.3, 0.1) and by_name.outputs["jointVelocities"] == (3.0, 1.0)
    assert by_name.outputs["measuredJointEfforts"] == (6.0, 4.0)
    by_index = NodeHarness("isaacsim.core.nodes.IsaacArticulationState",
                           {"targetPrim": ["/World/arm"], "jointIndices": [1]}, world=world).compute("execIn")
    assert by_index.outputs["jointNames"] == ("elbow",)
    with pytest.raises(GraphRuntimeError, match="has no joint knee"):
        NodeHarness("isaacsim.core.nodes.IsaacArticulationState",
                    {"robotPath": "/World/arm", "jointNames": ["knee"]}, world=world).compute("execIn")


def test_check_goal_2d_tests_distance_and_yaw_as_isaac():
    yaw_30 = quat_from_axis_angle((0.0, 0.0, 1.0), math.radians(30))
    node = NodeHarness("isaacsim.robot.wheeled_robots.CheckGoal2D",
                       {"target": [1.0, 1.0, 0.0], "targetChanged": True, "currentPosition": [1.06, 0.92, 0.0],
                        "currentOrientation": list(yaw_30), "thresholds": [0.1, 0.6]})
    assert node.compute("execIn").outputs["reachedGoal"] == (True, True)    # 0.1 m away, yaw 0.52 <= 0.6
    node.set_inputs(targetChanged=False, target=[5.0, 5.0, 0.0], thresholds=[0.05, 0.5])
    assert node.compute("execIn").outputs["reachedGoal"] == (False, False)  # still the first target; 0.1 > 0.05
