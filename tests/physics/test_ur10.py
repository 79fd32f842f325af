"""The UR10 asset against the UR10's Denavit-Hartenberg kinematics, and its drives."""
import math

import numpy as np
import pytest

from graphflow.physics import create_world

# UR10 DH (ros-industrial/universal_robot ur10 physical_parameters.yaml): a, d, alpha
DH_A = (0.0, -0.612, -0.5723, 0.0, 0.0, 0.0)
DH_D = (0.1273, 0.0, 0.0, 0.163941, 0.1157, 0.0922)
DH_ALPHA = (math.pi / 2, 0.0, 0.0, math.pi / 2, -math.pi / 2, 0.0)
TOOL_TIP = 0.1611          # m along the flange axis (DH z6 = ee_link +X)


def dh_tool_tip(q):
    """Tool tip in base_link: URDF base_link is the DH base turned by pi about z."""
    transform = np.diag([-1.0, -1.0, 1.0, 1.0])
    for theta, a, d, alpha in zip(q, DH_A, DH_D, DH_ALPHA):
        ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
        transform = transform @ np.array([[ct, -st * ca, st * sa, a * ct],
                                          [st, ct * ca, -ct * sa, a * st],
                                          [0.0, sa, ca, d],
                                          [0.0, 0.0, 0.0, 1.0]])
    return (transform @ np.array([0.0, 0.0, TOOL_TIP, 1.0]))[:3]


@pytest.mark.parametrize("target", [
    (0.0, 0.0, 0.0, 0.0, 0.0, 0.0),
    (-math.pi / 2, -math.pi / 2, -math.pi / 2, -math.pi / 2, math.pi / 2, 0.0),
    (0.4, -1.1, 1.3, -0.9, 0.7, 2.0),
])
def test_tool_tip_matches_dh_forward_kinematics(target):
    with create_world("asset:ur10.usda") as world:
        world.set_joint_targets("/ur10", range(6), positions=target)
        for _ in range(120):
            world.step()
        q = world.joint_positions("/ur10")
        assert q == pytest.approx(target, abs=1e-4)                 # the drives reached their targets
        tip = world.prim_pose("/ur10/ee_link/attachment_joint")[0]
        assert np.linalg.norm(np.array(tip) - dh_tool_tip(q)) < 1e-3


def test_default_state_and_names_from_the_stage():
    with create_world("asset:ur10.usda") as world:
        assert world.joint_names("/ur10/ee_link") == ("shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                                      "wrist_1_joint", "wrist_2_joint", "wrist_3_joint")
        assert world.joint_positions("/ur10") == pytest.approx((-math.pi / 2, -math.pi / 2, -math.pi / 2,
                                                                 -math.pi / 2, math.pi / 2, 0.0))
        assert world.description.surface_grippers[0].attachment_points == ("/ur10/ee_link/attachment_joint",)


def test_joint_speed_is_limited_to_the_ur10_velocity_limit():
    with create_world("asset:ur10.usda") as world:
        world.set_joint_targets("/ur10", [0], positions=[1.5])
        peak = 0.0
        for _ in range(60):
            world.step()
            peak = max(peak, abs(world.joint_velocities("/ur10")[0]))
        assert peak == pytest.approx(2.16, abs=0.05)                 # shoulder pan: 2.16 rad/s
