"""Nodes that read joints: IsaacReadEffortSensor, IsaacReadJointState (statics on a real world), IsaacJointNameResolver."""
import math

import pytest

from graphflow.physics import create_world
from graphflow.testing import NodeHarness
from tests.physics.test_drives import LOAD_FORCE, slide_stage

STIFFNESS = 1e4


def _settled_slide():
    world = create_world(slide_stage(STIFFNESS, 2.0 * math.sqrt(STIFFNESS * 2.0), start=-LOAD_FORCE / STIFFNESS))
    for _ in range(120):
        world.step()
    return world


def test_effort_sensor_on_the_slide_reads_the_loads_weight():
    """The joint carries the 2 kg load at rest: its effort is m g = 19.6 N, read at the world's time."""
    with _settled_slide() as world:
        node = NodeHarness("isaacsim.sensors.physics.IsaacReadEffortSensor", {"prim": "/World/Robot/Slide"},
                           world=world)
        result = node.compute("execIn")
        assert result.fired == {"execOut"}
        assert node.outputs.value == pytest.approx(LOAD_FORCE, rel=0.01)
        assert node.outputs.sensorTime == pytest.approx(2.0)


def test_effort_sensor_on_a_prim_that_is_no_joint_names_it():
    with _settled_slide() as world:
        node = NodeHarness("isaacsim.sensors.physics.IsaacReadEffortSensor", {"prim": "/World/Robot/Load"},
                           world=world)
        with pytest.raises(Exception, match="/World/Robot/Load is not a movable joint"):
            node.compute("execIn")


def test_read_joint_state_reports_position_effort_and_a_prismatic_dof():
    """At rest the drive (k = 1e4 N/m, target 0) sags by m g / k under the load and pushes m g up."""
    with _settled_slide() as world:
        node = NodeHarness("isaacsim.sensors.physics.IsaacReadJointState", {"prim": "/World/Robot"}, world=world)
        node.compute("execIn")
        out = node.outputs
        assert out.jointNames == ("Slide",)
        assert out.jointPositions[0] == pytest.approx(-LOAD_FORCE / STIFFNESS, rel=0.02)
        assert out.jointVelocities[0] == pytest.approx(0.0, abs=1e-4)
        assert out.jointEfforts[0] == pytest.approx(LOAD_FORCE, rel=0.01)
        assert out.jointDofTypes == (1,)
        assert out.stageMetersPerUnit == 1.0


def test_joint_name_resolver_maps_an_override_back_to_the_joint_prims_name():
    from pxr import Sdf

    stage = slide_stage(STIFFNESS, 1e2)
    stage.GetPrimAtPath("/World/Robot/Slide").CreateAttribute("isaac:nameOverride", Sdf.ValueTypeNames.String).Set(
        "lift")
    with create_world(stage) as world:
        node = NodeHarness("isaacsim.core.nodes.IsaacJointNameResolver",
                           {"robotPath": "/World/Robot", "jointNames": ["lift", "gripper"]}, world=world)
        out = node.compute("execIn").outputs
        assert out["jointNames"] == ("Slide", "gripper")
        assert out["robotPath"] == "/World/Robot"
        with pytest.raises(Exception, match="no articulation root at or under /World/Ground"):
            NodeHarness("isaacsim.core.nodes.IsaacJointNameResolver", {"robotPath": "/World/Ground"},
                        world=world).compute("execIn")
