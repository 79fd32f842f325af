"""UR10 kinematics (graphflow.kinematics): IK accuracy, and agreement with the simulated arm."""
import math

import numpy as np
import pytest

from graphflow.kinematics import (
    SUCTION_DOWN,
    UR10_DEFAULT_JOINTS,
    matrix_to_quaternion,
    quaternion_to_matrix,
    rotation_error,
    ur10_chain,
)

ARM = "/ur10"
TIP = "/ur10/ee_link/attachment_joint"
# the demos' pick, place and stack targets for the suction tip (cube centre + 0.02 m offset, or above it)
TARGETS = [(0.3, 0.3, 0.04575), (0.7, 0.7, 0.04575), (0.7, 0.7, 0.3), (0.4, 0.4, 0.045),
           (-0.4, 0.5, 0.07), (0.25, 0.25, 0.07), (0.2, -0.2, 0.07), (0.4, 0.4, 0.14)]


@pytest.mark.parametrize("target", TARGETS)
def test_ik_reaches_the_tip_target_within_a_tenth_of_a_millimetre(target):
    chain = ur10_chain()
    solution = chain.inverse(target, SUCTION_DOWN, UR10_DEFAULT_JOINTS)
    tool = chain.forward(solution.positions)
    assert solution.converged
    assert np.linalg.norm(tool[:3, 3] - target) < 1e-4
    assert tool[:3, :3] @ np.array([1.0, 0.0, 0.0]) == pytest.approx([0.0, 0.0, -1.0], abs=1e-4)


def test_ik_warm_started_from_the_previous_solution_takes_few_iterations():
    chain = ur10_chain()
    previous = chain.inverse((0.3, 0.3, 0.3), SUCTION_DOWN, UR10_DEFAULT_JOINTS)
    step = chain.inverse((0.3, 0.3, 0.299), SUCTION_DOWN, previous.positions)
    assert step.converged and step.iterations <= 3


def test_unreachable_target_reports_no_convergence():
    solution = ur10_chain().inverse((3.0, 0.0, 0.5), SUCTION_DOWN, UR10_DEFAULT_JOINTS, max_iterations=50)
    assert not solution.converged
    assert solution.position_error > 1.0


def test_jacobian_matches_finite_differences():
    chain = ur10_chain()
    q = np.array([-1.9, -1.2, -2.0, -1.5, 1.4, 0.6])
    jacobian = chain.jacobian(q)
    h = 1e-6
    for i in range(6):
        dq = np.zeros(6)
        dq[i] = h
        plus, minus = chain.forward(q + dq), chain.forward(q - dq)
        assert (plus[:3, 3] - minus[:3, 3]) / (2 * h) == pytest.approx(jacobian[:3, i], abs=1e-6)
        assert rotation_error(plus[:3, :3], minus[:3, :3]) / (2 * h) == pytest.approx(jacobian[3:, i], abs=1e-6)


def test_quaternion_round_trip():
    for quaternion in [(0.0, 0.0, 0.0, 1.0), SUCTION_DOWN, (0.2548, -0.6180, -0.1888, -0.7193)]:
        q = np.array(quaternion) / np.linalg.norm(quaternion)
        back = np.array(matrix_to_quaternion(quaternion_to_matrix(q)))
        assert min(np.linalg.norm(back - q), np.linalg.norm(back + q)) < 1e-9


@pytest.fixture(scope="module")
def ur10_world():
    from graphflow.physics import create_world

    with create_world("asset:ur10.usda") as world:
        yield world


def test_forward_kinematics_matches_the_simulated_arm(ur10_world):
    chain = ur10_chain()
    for q in [UR10_DEFAULT_JOINTS, (-1.9, -1.2, -2.0, -1.5, 1.4, 0.6), (0.3, -2.2, 1.1, -0.4, -1.0, 2.0)]:
        ur10_world.reset()
        ur10_world.set_joint_targets(ARM, range(6), positions=q)
        for _ in range(240):
            ur10_world.step()
        reached = ur10_world.joint_positions(ARM)
        position, orientation = ur10_world.prim_pose(TIP)
        tool = chain.forward(reached)
        assert np.linalg.norm(np.array(position) - tool[:3, 3]) < 1e-6
        assert np.linalg.norm(rotation_error(quaternion_to_matrix(orientation), tool[:3, :3])) < 1e-6


def test_ik_solution_puts_the_simulated_tip_within_a_millimetre(ur10_world):
    chain = ur10_chain()
    for target in TARGETS[:4]:
        ur10_world.reset()
        solution = chain.inverse(target, SUCTION_DOWN, ur10_world.joint_positions(ARM))
        ur10_world.set_joint_targets(ARM, range(6), positions=solution.positions)
        for _ in range(300):
            ur10_world.step()
        position, _ = ur10_world.prim_pose(TIP)
        assert math.dist(position, target) < 1e-3
