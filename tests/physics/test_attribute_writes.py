"""World.set_attribute beyond what physics simulates: other attributes go to the run's stage-edit layer.

The stage is written here: a plain marker Xform (no physics) with a custom attribute, and a falling box with a
collider. Values checked are the ones written in it and the ones the tests write.
"""
import pytest

from graphflow.physics import create_world
from graphflow.testing import GraphHarness
from graphflow.world import WorldError

STAGE = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def PhysicsScene "Scene"
    {
    }
    def Xform "Marker"
    {
        float custom:speed = 1
        double3 xformOp:translate = (1, 2, 3)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Cube "Box" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
    )
    {
        double size = 0.2
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
'''


@pytest.fixture
def stage_file(tmp_path):
    path = tmp_path / "marker.usda"
    path.write_text(STAGE)
    return path


def test_a_custom_attribute_is_written_for_the_run_read_back_and_dropped_by_reset(stage_file):
    with create_world(str(stage_file)) as world:
        world.set_attribute("/World/Marker", "custom:speed", 2.5)
        assert world.get_attribute("/World/Marker", "custom:speed") == 2.5
        assert world.read_prim("/World/Marker").get("custom:speed").value == 2.5
        world.reset()
        assert world.get_attribute("/World/Marker", "custom:speed") == 1.0
    assert stage_file.read_text() == STAGE


def test_a_plain_prims_translate_moves_its_world_pose_and_a_bodys_still_teleports_it(stage_file):
    with create_world(str(stage_file)) as world:
        assert world.prim_pose("/World/Marker")[0] == pytest.approx((1.0, 2.0, 3.0))
        world.set_attribute("/World/Marker", "xformOp:translate", (4.0, 5.0, 6.0))
        assert world.prim_pose("/World/Marker")[0] == pytest.approx((4.0, 5.0, 6.0))
        world.set_attribute("/World/Box", "xformOp:translate", (0.5, 0.0, 2.0))     # simulated: a teleport
        assert world.prim_pose("/World/Box")[0] == pytest.approx((0.5, 0.0, 2.0), abs=1e-9)
        assert world.get_attribute("/World/Box", "xformOp:translate") == pytest.approx((0.5, 0.0, 2.0), abs=1e-9)


def test_a_write_that_would_change_a_collider_or_names_no_attribute_is_refused_with_one_line(stage_file):
    with create_world(str(stage_file)) as world:
        with pytest.raises(WorldError, match="/World/Box: writing size would change what is simulated"):
            world.set_attribute("/World/Box", "size", 0.5)
        assert world.get_attribute("/World/Box", "size") == 0.2             # rolled back
        with pytest.raises(WorldError, match="no attribute /World/Marker.custom:missing"):
            world.set_attribute("/World/Marker", "custom:missing", 1.0)


def test_write_prim_attribute_drives_a_marker_a_later_read_sees(stage_file):
    graph = GraphHarness({
        "settings": {"stage": str(stage_file)},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "write", "type": "omni.graph.nodes.WritePrimAttribute",
                   "inputs": {"prim": "/World/Marker", "name": "custom:speed", "value": 7.0}},
                  {"name": "read", "type": "omni.graph.nodes.ReadPrimAttribute",
                   "inputs": {"prim": "/World/Marker", "name": "custom:speed"}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "write.inputs:execIn"}],
    })
    graph.instance.compute_node("read")             # as a consumer's pull would, before the write
    assert graph.output("read", "value") == 1.0
    graph.run(ticks=1)
    graph.instance.compute_node("read")
    assert graph.output("read", "value") == 7.0
