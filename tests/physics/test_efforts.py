"""Efforts add to the drives and no joint passes its limits (issue 12 item 3)."""
import math

import pytest

from graphflow.physics import create_world
from graphflow.testing import NodeHarness

from .test_drives import LOAD_FORCE, slide_stage


def settle(world, seconds=2.0):
    for _ in range(round(seconds * 60)):
        world.step()
    return world.joint_positions("/World/Robot")[0]


@pytest.mark.parametrize("stiffness", [1e3, 1e4, 1e6])
def test_an_effort_deflects_a_drive_by_effort_over_stiffness(stiffness):
    """50 N up on the 2 kg load: the drive settles at (50 - m g) / k above its target (soft drives use
    the torque law, the 1e6 one a motor). Measured: (tau - L) / k to 1e-7."""
    effort = 50.0
    expected = (effort - LOAD_FORCE) / stiffness
    with create_world(slide_stage(stiffness, 2.0 * math.sqrt(stiffness * 2.0), start=-LOAD_FORCE / stiffness)) as world:
        world.set_joint_targets("/World/Robot", [0], efforts=[effort])
        assert settle(world) == pytest.approx(expected, rel=0.01)


def test_an_effort_beyond_the_drive_force_stops_at_the_limit():
    """200 N down on a 60 N drive: the load goes to its lower limit (-0.1 m) and no further."""
    with create_world(slide_stage(1e4, 2e2, max_force=60.0, limits=(-0.1, 0.1))) as world:
        world.set_joint_targets("/World/Robot", [0], efforts=[-200.0])
        lowest = 0.0
        for _ in range(120):
            world.step()
            lowest = min(lowest, world.joint_positions("/World/Robot")[0])
        assert lowest >= -0.1 - 1e-6
        assert world.joint_positions("/World/Robot")[0] == pytest.approx(-0.1, abs=1e-6)


def test_an_undriven_joint_pushed_hard_stops_at_its_limits():
    """No drive, 2 kN up then 2 kN down on the slide: it hits +0.1 m, then -0.1 m, never beyond (PyBullet's
    own limit let a joint through by v dt and never pushed it back: 0.35 rad on the UR10 wrist)."""
    with create_world(slide_stage(None, None, limits=(-0.1, 0.1))) as world:
        for effort in (2000.0, -2000.0):
            world.set_joint_targets("/World/Robot", [0], efforts=[effort])
            for _ in range(30):
                world.step()
                assert -0.1 - 1e-6 <= world.joint_positions("/World/Robot")[0] <= 0.1 + 1e-6
            assert world.joint_positions("/World/Robot")[0] == pytest.approx(math.copysign(0.1, effort), abs=1e-6)


def test_effort_command_on_the_ur10_wrist_through_the_articulation_controller():
    """The issue's case: 5 N m of effortCommand on wrist_3 (drive k = 1e4 N m/deg, force limit 54 N m)
    deflects it by ~tau / k = 9e-6 rad (measured 4e-6: the motor's solver residual) instead of spinning
    it at 100 rad/s past its +-2 pi limit."""
    with create_world("asset:ur10.usda") as world:
        node = NodeHarness("isaacsim.core.nodes.IsaacArticulationController",
                           inputs={"robotPath": "/ur10", "effortCommand": [0.0, 0.0, 0.0, 0.0, 0.0, 5.0]}, world=world)
        node.compute("execIn")
        start = world.joint_positions("/ur10")
        for _ in range(120):
            world.step()
            assert abs(world.joint_velocities("/ur10")[5]) < 0.01
        wrist = world.joint_positions("/ur10")[5] - start[5]
        assert 0.0 < wrist < 2.0 * 5.0 / (1e4 * 180 / math.pi)


@pytest.mark.parametrize("stiffness", [1e3, 1e6])
@pytest.mark.parametrize("extra", [0.0, 50.0])
def test_joint_efforts_at_rest_hold_the_load_up(stiffness, extra):
    """Statics: at rest the slide's actuation carries the 2 kg load's weight, m g = 19.6 N up, whether the
    drive alone holds it or an added 50 N effort shares the work (soft drive: torque law; stiff: motor)."""
    with create_world(slide_stage(stiffness, 2.0 * math.sqrt(stiffness * 2.0), start=-LOAD_FORCE / stiffness)) as world:
        world.set_joint_targets("/World/Robot", [0], efforts=[extra])
        settle(world)
        assert world.joint_efforts("/World/Robot") == pytest.approx((LOAD_FORCE,), rel=0.01)
        assert world.joint_dof_types("/World/Robot") == (1,)
