"""The PyBullet attachment mechanism on its own: force calibration and the compliance model."""
import math

import pybullet
import pytest
from pybullet_utils.bullet_client import BulletClient

from graphflow.physics.attachment import PyBulletAttachments
from graphflow.world import RIGID, AxisCompliance

G = 9.81
STEP = 1.0 / 60.0
LOCKED = AxisCompliance(1.0, -1.0)
DOWN = ((0.0, 0.0, -0.02), (1.0, 0.0, 0.0, 0.0))   # joint frame under a 4 cm gripper cube, +Z pointing down


@pytest.fixture
def bullet():
    client = BulletClient(connection_mode=pybullet.DIRECT)
    client.setGravity(0, 0, -G)
    client.setTimeStep(STEP)
    yield client
    client.disconnect()


def _cube(bullet, mass, position, half=0.02):
    shape = bullet.createCollisionShape(pybullet.GEOM_BOX, halfExtents=[half] * 3)
    return bullet.createMultiBody(mass, shape, basePosition=position)


def _hang(bullet, compliance, mass=0.1, steps=300, object_position=(0.0, 0.0, 0.96), joint=DOWN):
    gripper = _cube(bullet, 0.0, (0.0, 0.0, 1.0))
    held = _cube(bullet, mass, object_position)
    attachments = PyBulletAttachments(bullet)
    handle = attachments.attach((gripper, -1), joint, (held, -1), compliance)
    start = bullet.getBasePositionAndOrientation(held)
    heights = []
    for _ in range(steps):
        bullet.stepSimulation()
        attachments.update(STEP)
        heights.append(bullet.getBasePositionAndOrientation(held)[0][2])
    return attachments, handle, held, start, heights


def test_force_on_gripper_is_world_frame_and_pulls_the_gripper_towards_a_hanging_object(bullet):
    attachments, handle, _, _, _ = _hang(bullet, RIGID, mass=0.2, steps=10)
    force = attachments.force_on_gripper(handle)
    # 0.2 kg hanging under the gripper: the gripper is pulled down by m g, exactly, in world axes
    assert force == pytest.approx((0.0, 0.0, -0.2 * G), abs=1e-9)
    forward = (0.0, 0.0, -1.0)   # the joint's +Z, pointing at the object
    coaxial = sum(f * d for f, d in zip(force, forward))
    assert coaxial == pytest.approx(0.2 * G)   # > 0: the object pulls away, as Isaac's getForce on actor0


def test_pushing_the_object_into_the_gripper_reads_a_negative_coaxial_force(bullet):
    gripper = _cube(bullet, 0.0, (0.0, 0.0, 1.0))
    held = _cube(bullet, 0.1, (0.0, 0.0, 0.96))
    attachments = PyBulletAttachments(bullet)
    handle = attachments.attach((gripper, -1), DOWN, (held, -1))
    for _ in range(5):
        bullet.applyExternalForce(held, -1, (0, 0, 10.0), (0, 0, 0.96), pybullet.WORLD_FRAME)
        bullet.stepSimulation()
    coaxial = -attachments.force_on_gripper(handle)[2]
    assert coaxial == pytest.approx(-(10.0 - 0.1 * G), rel=1e-6)


def test_shear_force_is_the_part_across_the_forward_axis(bullet):
    gripper = _cube(bullet, 0.0, (0.0, 0.0, 1.0))
    held = _cube(bullet, 0.1, (0.0, 0.0, 0.96))
    attachments = PyBulletAttachments(bullet)
    handle = attachments.attach((gripper, -1), DOWN, (held, -1))
    for _ in range(5):
        bullet.applyExternalForce(held, -1, (0, -4.0, 0), (0, 0, 0.96), pybullet.WORLD_FRAME)
        bullet.stepSimulation()
    force = attachments.force_on_gripper(handle)
    assert force[1] == pytest.approx(-4.0, rel=1e-4)     # the gripper is dragged along the push
    assert math.hypot(force[0], force[1]) == pytest.approx(4.0, rel=1e-4)


@pytest.mark.parametrize("stiffness", [0.0, 1e2, 1e4, 1e7])
@pytest.mark.parametrize("damping", [0.0, 1e2, 1e7])
def test_axial_sag_is_m_g_over_k_within_the_limit_and_never_blows_up(bullet, stiffness, damping):
    limit = 0.05
    axial = AxisCompliance(0.0, limit, stiffness, damping)
    _, handle, held, start, heights = _hang(bullet, (LOCKED, LOCKED, axial, LOCKED, LOCKED, LOCKED),
                                            steps=600)
    sags = [start[0][2] - z for z in heights]
    assert max(sags) <= limit + 1e-3 and min(sags) >= -1e-3          # bounded: no blow-up
    if damping >= 1e7:
        assert sags[-1] < 1e-5                                          # 10 s of creep at c = 1e7 is nothing
    elif stiffness == 0.0:
        assert sags[-1] == pytest.approx(limit, abs=2e-4)               # no spring: it rests on the limit
    else:
        assert sags[-1] == pytest.approx(min(0.1 * G / stiffness, limit), rel=0.01, abs=2e-5)


def test_bending_follows_the_torque_and_stops_at_the_rotation_limit(bullet):
    side = ((0.02, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))     # joint on the gripper's +X face, object 4 cm beyond
    lever_torque = 0.1 * G * 0.04
    bends = {}
    for stiffness in (1.0, 0.01):
        client = BulletClient(connection_mode=pybullet.DIRECT)
        client.setGravity(0, 0, -G)
        client.setTimeStep(STEP)
        rotation = AxisCompliance(-0.3, 0.3, stiffness, 0.0)
        attachments, handle, _, _, _ = _hang(client, (LOCKED, LOCKED, LOCKED, rotation, rotation, rotation),
                                             object_position=(0.06, 0.0, 1.0), joint=side)
        bends[stiffness] = attachments.offset(handle)
        client.disconnect()
    # gravity bends the object down about the joint's Y axis (world -Y after the 180° flip about X)
    assert bends[1.0][4] == pytest.approx(-lever_torque / 1.0, rel=0.02)
    assert bends[0.01][4] == pytest.approx(-0.3)                        # the limit bounds the bend
    assert bends[1.0][3] == pytest.approx(0.0, abs=1e-6) and bends[1.0][5] == pytest.approx(0.0, abs=1e-6)


def test_detach_restores_collisions_and_lets_the_object_fall(bullet):
    attachments, handle, held, start, _ = _hang(bullet, RIGID, steps=5)
    attachments.detach(handle)
    assert not attachments.is_attached(handle)
    for _ in range(30):
        bullet.stepSimulation()
    assert bullet.getBasePositionAndOrientation(held)[0][2] < start[0][2] - 0.1


def test_a_soft_barely_damped_hold_on_an_object_resting_on_a_table_stays_still(bullet):
    """Contacts are stiff: without extra damping while touching, k = 100, c = 1 oscillated and grew."""
    table = bullet.createCollisionShape(pybullet.GEOM_BOX, halfExtents=[0.2, 0.2, 0.01])
    bullet.createMultiBody(0, table, basePosition=(0.0, 0.0, 0.93))
    soft = AxisCompliance(float("-inf"), float("inf"), 100.0, 1.0)
    attachments, handle, held, start, heights = _hang(bullet, (soft,) * 3 + (LOCKED,) * 3,
                                                      object_position=(0.0, 0.0, 0.96), steps=300)
    assert max(abs(z - start[0][2]) for z in heights) < 2e-3
    assert max(abs(v) for v in attachments.offset(handle)) < 2e-3
