"""The controllers' arm is read off the stage: the chain from the articulation's root body to the gripper's
attachment frame. On the UR10 stage it is the published chain; on a two-link arm, the numpy reference's."""
import math
import warnings

import numpy as np
import pytest
from conftest import ROOT
from pxr import Usd

from graphflow.kinematics import ur10_chain
from graphflow.robots.suction import add_suction_tool
from graphflow.usd.physics_import import load_description
from graphflow_nodes._arm import chain_from_description
from tests.robots import reference
from tests.robots.converted import write_arm


def parse(stage_or_path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return load_description(stage_or_path)


def test_the_ur10_stage_gives_the_published_chain():
    """Forward kinematics of the chain read off graphflow/assets/ur10.usda and of ur10_chain (the published
    URDF numbers) agree to 1e-7 (the stage's float32 frames) over 50 random configurations."""
    description = parse(str(ROOT / "graphflow" / "assets" / "ur10_pick_place.usda"))
    chain, root = chain_from_description(description, "/World/ur10/ee_link/SurfaceGripper")
    published = ur10_chain()
    assert root == "/World/ur10/base_link" and chain.names == published.names
    rng = np.random.default_rng(7)
    worst = max(np.abs(chain.forward(q) - published.forward(q)).max() for q in rng.uniform(-3, 3, (50, 6)))
    assert worst < 1e-7


def test_a_two_link_arm_with_a_suction_tool_gives_the_reference_kinematics(tmp_path):
    """The fixture arm with a tool 0.25 m along the lower link's +Z: the tool point at (0.4, -1.1) is the
    numpy reference's, and the suction axis (tool +X) is the lower link's +Z."""
    stage = Usd.Stage.Open(str(write_arm(tmp_path / "arm.usda")))
    gripper = add_suction_tool(stage, "/arm/Geometry/base/upper/lower", 0.25)
    chain, root = chain_from_description(parse(stage), gripper)
    assert root == "/arm/Geometry/base" and chain.names == ("shoulder", "elbow")
    rotation, origin = reference.frames(0.4, -1.1)[1]
    tool = chain.forward((0.4, -1.1))
    base = np.array([0.0, 0.0, 0.0])          # the base body sits at the origin
    assert np.allclose(base + tool[:3, 3], origin + rotation @ [0.0, 0.0, 0.25], atol=1e-7)
    assert np.allclose(tool[:3, 0], rotation @ [0.0, 0.0, 1.0], atol=1e-7)
    assert chain.lower == pytest.approx((-math.pi / 2, -2 * math.pi / 3)) and chain.upper[1] == pytest.approx(math.pi / 3)


def test_a_slide_between_base_and_gripper_is_refused_naming_it(tmp_path):
    stage = Usd.Stage.Open(str(write_arm(tmp_path / "arm.usda")))
    gripper = add_suction_tool(stage, "/arm/Geometry/base/upper/lower/finger_a", 0.05)
    with pytest.raises(ValueError, match="/arm/Physics/finger_a_joint: a prismatic joint between the arm's base"):
        chain_from_description(parse(stage), gripper)


def test_a_gripper_that_is_not_there_is_named(tmp_path):
    stage = Usd.Stage.Open(str(write_arm(tmp_path / "arm.usda")))
    with pytest.raises(ValueError, match="no surface gripper with an attachment point at /arm/Gripper"):
        chain_from_description(parse(stage), "/arm/Gripper")


@pytest.mark.parametrize("tip", [0.1611, 0.25])
def test_a_ur10_keeps_the_published_chain_only_where_its_tool_is_the_published_one(tip):
    """The UR10 stage with its attachment point at the published 0.1611 m drives ur10_chain (bit-identical
    traces); moved to 0.25 m, the controllers' arm is the stage's and its tool is 0.25 m along ee_link +X."""
    from pxr import Gf

    from graphflow.physics import create_world
    from graphflow.poses import compose
    from graphflow_nodes._arm import Arm

    stage = Usd.Stage.Open(str(ROOT / "graphflow" / "assets" / "ur10_pick_place.usda"))
    stage.SetEditTarget(stage.GetSessionLayer())
    stage.GetPrimAtPath("/World/ur10/ee_link/attachment_joint").GetAttribute("physics:localPos0").Set(
        Gf.Vec3f(tip, 0.0, 0.0))
    with create_world(stage) as world:
        arm = Arm(world, "/World/ur10", "/World/ur10/ee_link/SurfaceGripper")
        home = arm.solution
        tool = arm.chain.forward(home)
        position = compose(arm.base_pose, (tuple(tool[:3, 3]), (0, 0, 0, 1)))[0]
        expected = compose(world.prim_pose("/World/ur10/ee_link"), ((tip, 0.0, 0.0), (0, 0, 0, 1)))[0]
    published = ur10_chain()
    assert np.allclose(position, expected, atol=1e-6)
    assert (np.array_equal(arm.chain.forward(home), published.forward(home))) == (tip == 0.1611)
