"""Kit's maneuver nodes (TranslateTo*, RotateTo*, MoveTo*, ScaleToSize) on real PyBullet worlds built from small stages.

References are independent of graphflow's code: the ease curve is written out here, rotations come from
USD's own rotateXYZ op and matrices, the free fall from g t^2 / 2.
"""
import pytest
from pxr import Gf, Usd, UsdGeom

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.testing import GraphHarness

DT = 0.01
MARKER = "/World/Marker"

PLAIN = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def Xform "Marker"
    {
        double3 xformOp:translate = (0, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Xform "Frame" (
    )
    {
        double3 xformOp:translate = (0, 2, 0)
        double3 xformOp:rotateXYZ = (0, 0, 90)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ"]
        def Xform "Child"
        {
            double3 xformOp:translate = (1, 0, 0)
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }
    }
    def Xform "Goal"
    {
        double3 xformOp:translate = (3, -1, 0.5)
        double3 xformOp:rotateXYZ = (10, 20, 30)
        double3 xformOp:scale = (2, 2, 0.5)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:rotateXYZ", "xformOp:scale"]
    }
}
"""

CUBE = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
)
def PhysicsScene "physicsScene"
{
    vector3f physics:gravityDirection = (0, 0, -1)
    float physics:gravityMagnitude = 9.81
}
def Xform "World"
{
    def Cube "Cube" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"]
    )
    {
        double size = 0.1
        float physics:mass = 1
        double3 xformOp:translate = (0, 0, 0.05)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""


def _stage(tmp_path, text, name="stage.usda"):
    path = tmp_path / name
    path.write_text(text)
    return path


def _maneuver(node_type, inputs, extra_nodes=(), extra_connections=()):
    """OnPlaybackTick -> Once -> the maneuver, its finished counted."""
    return {
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
            {"name": "once", "type": "omni.graph.action.Once"},
            {"name": "move", "type": node_type, "inputs": inputs},
            {"name": "arrived", "type": "omni.graph.action.Counter"},
            *extra_nodes,
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "once.inputs:execIn"},
            {"src": "once.outputs:once", "dst": "move.inputs:execIn"},
            {"src": "move.outputs:finished", "dst": "arrived.inputs:execIn"},
            *extra_connections,
        ],
    }


def _translate(target, speed=1.0, exponent=1.0, prim=MARKER):
    return _maneuver("omni.graph.nodes.TranslateToLocation",
                     {"usePath": True, "primPath": prim, "target": list(target), "speed": speed,
                      "exponent": exponent})


def _kit_ease(alpha, p):
    """Kit's ease-in-out of degree p, written out."""
    return (2 * alpha) ** p / 2 if alpha < 0.5 else 1 - (2 - 2 * alpha) ** p / 2


def _usd_quaternion(rotate_xyz):
    """The (x, y, z, w) rotation USD gives a prim whose only op is rotateXYZ."""
    stage = Usd.Stage.CreateInMemory()
    xform = UsdGeom.Xform.Define(stage, "/R")
    xform.AddRotateXYZOp().Set(Gf.Vec3d(*rotate_xyz))
    q = Gf.Transform(xform.GetLocalTransformation()).GetRotation().GetQuat()
    return (*q.GetImaginary(), q.GetReal())


def _same_rotation(a, b):
    return abs(abs(sum(x * y for x, y in zip(a, b))) - 1.0) < 1e-9


def test_translate_to_location_linear_reads_x_equal_t_and_fires_finished_once(tmp_path):
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        harness = GraphHarness(_translate((1, 0, 0)), world=world)
        for t in (0.25, 0.5):
            harness.run(round((t - world.time) / DT))
            x = world.prim_pose(MARKER)[0][0]
            assert x == pytest.approx(t, abs=DT + 1e-9)          # within one tick of x = t
            assert world.get_attribute(MARKER, "xformOp:translate")[0] == pytest.approx(x, abs=1e-12)
            matrix = world.read_prim(MARKER).get("worldMatrix").value
            assert matrix[12] == pytest.approx(x, abs=1e-12)
            assert harness.output("arrived", "count") == 0
        harness.run(round((1.0 - world.time) / DT) + 1)
        assert world.prim_pose(MARKER)[0] == pytest.approx((1.0, 0.0, 0.0), abs=1e-12)
        assert harness.output("arrived", "count") == 1
        harness.run(20)
        assert harness.output("arrived", "count") == 1                    # finished fires once, on arrival
        assert world.prim_pose(MARKER)[0] == pytest.approx((1.0, 0.0, 0.0), abs=1e-12)


def test_translate_to_location_eases_with_kits_curve(tmp_path):
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        harness = GraphHarness(_translate((2, 0, 0), speed=0.5, exponent=2.0), world=world)
        harness.run(1)                       # the pulse: the prim starts here
        started = world.time
        for _ in range(10):
            harness.run(17)
            alpha = (world.time - started) * 0.5
            assert world.prim_pose(MARKER)[0][0] == pytest.approx(2.0 * _kit_ease(min(alpha, 1.0), 2), abs=1e-9)


def test_the_animation_stays_off_the_file_and_a_reset_repeats_it(tmp_path):
    path = _stage(tmp_path, PLAIN)
    text = path.read_text()
    with create_world(path, time_step=DT) as world:
        harness = GraphHarness(_translate((1, 0, 0)), world=world)
        harness.run(60)
        first = [world.prim_pose(MARKER)]
        harness.run(10)
        first.append(world.prim_pose(MARKER))
        layer = world.stage.GetRootLayer()
        assert layer.GetAttributeAtPath(MARKER + ".xformOp:translate").default == Gf.Vec3d(0, 0, 0)
        harness.reset()
        assert world.prim_pose(MARKER)[0] == (0.0, 0.0, 0.0)
        assert world.get_attribute(MARKER, "xformOp:translate") == (0.0, 0.0, 0.0)
        harness.run(60)
        again = [world.prim_pose(MARKER)]
        harness.run(10)
        again.append(world.prim_pose(MARKER))
        assert again == first                                       # bit for bit
        stage = world.stage
    assert path.read_text() == text
    assert stage.GetPrimAtPath(MARKER).GetAttribute("xformOp:translate").Get() == Gf.Vec3d(0, 0, 0)


def test_stop_halts_the_prim_where_it_is_and_fires_finished(tmp_path):
    graph = _translate((1, 0, 0))
    graph["nodes"].append({"name": "later", "type": "omni.graph.action.Delay", "inputs": {"duration": 0.3}})
    graph["connections"].append({"src": "once.outputs:once", "dst": "later.inputs:execIn"})
    graph["connections"].append({"src": "later.outputs:finished", "dst": "move.inputs:stop"})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        harness = GraphHarness(graph, world=world)
        harness.run(60)
        x = world.prim_pose(MARKER)[0][0]
        assert x == pytest.approx(0.3, abs=DT + 1e-9)
        assert harness.output("arrived", "count") == 1
        harness.run(60)
        assert world.prim_pose(MARKER)[0][0] == x


def test_a_free_cube_is_held_on_its_path_then_falls_from_the_target_as_g_t2_over_2(tmp_path):
    g, target = 9.81, (0.5, 0.0, 2.0)
    with create_world(_stage(tmp_path, CUBE), time_step=DT) as world:
        harness = GraphHarness(_translate(target, speed=2.0, prim="/World/Cube"), world=world)
        harness.run(26)                         # halfway (the pulse at the first tick)
        z_half = world.prim_pose("/World/Cube")[0][2]
        assert z_half == pytest.approx(0.05 + (2.0 - 0.05) * _kit_ease(0.5, 1), abs=0.05)
        while harness.output("arrived", "count") == 0:
            harness.run(1)
        assert world.prim_pose("/World/Cube")[0] == pytest.approx(target, abs=1e-9)
        arrived = world.time
        harness.run(50)
        fall = world.time - arrived
        z = world.prim_pose("/World/Cube")[0][2]
        assert target[2] - g * (fall + DT) ** 2 / 2 <= z <= target[2] - g * (fall - DT) ** 2 / 2
        assert world.prim_pose("/World/Cube")[0][:2] == pytest.approx(target[:2], abs=1e-9)


def test_rotate_to_orientation_ends_at_usds_rotate_xyz_quaternion(tmp_path):
    angles = (30.0, 45.0, 60.0)
    graph = _maneuver("omni.graph.nodes.RotateToOrientation",
                      {"usePath": True, "primPath": MARKER, "target": list(angles), "speed": 2.0})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        harness = GraphHarness(graph, world=world)
        harness.run(25)
        assert not _same_rotation(world.prim_pose(MARKER)[1], _usd_quaternion(angles))
        harness.run(40)
        assert harness.output("arrived", "count") == 1
        assert _same_rotation(world.prim_pose(MARKER)[1], _usd_quaternion(angles))
        assert world.prim_pose(MARKER)[0] == pytest.approx((0.0, 0.0, 0.0), abs=1e-12)


def test_move_to_target_matches_the_targets_world_matrix(tmp_path):
    graph = _maneuver("omni.graph.nodes.MoveToTarget",
                      {"useSourcePath": True, "sourcePrimPath": "/World/Frame/Child", "useTargetPath": True,
                       "targetPrimPath": "/World/Goal", "speed": 4.0})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        harness = GraphHarness(graph, world=world)
        harness.run(40)
        assert harness.output("arrived", "count") == 1
        stage = Usd.Stage.Open(str(tmp_path / "stage.usda"))
        goal = UsdGeom.Xformable(stage.GetPrimAtPath("/World/Goal")).ComputeLocalToWorldTransform(0)
        moved = world.read_prim("/World/Frame/Child").get("worldMatrix").value
        assert moved == pytest.approx([c for row in goal for c in row], abs=1e-9)


def test_translate_to_target_under_a_turned_parent_ends_at_the_targets_world_position(tmp_path):
    graph = _maneuver("omni.graph.nodes.TranslateToTarget",
                      {"useSourcePath": True, "sourcePrimPath": "/World/Frame/Child", "useTargetPath": True,
                       "targetPrimPath": "/World/Goal", "speed": 4.0})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        before = world.prim_pose("/World/Frame/Child")[1]
        GraphHarness(graph, world=world).run(40)
        position, orientation = world.prim_pose("/World/Frame/Child")
        assert position == pytest.approx((3.0, -1.0, 0.5), abs=1e-9)
        assert _same_rotation(orientation, before)


def test_scale_to_size_scales_a_plain_prim(tmp_path):
    graph = _maneuver("omni.graph.nodes.ScaleToSize",
                      {"usePath": True, "primPath": MARKER, "target": [2.0, 3.0, 0.5], "speed": 4.0,
                       "exponent": 1.0})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        harness = GraphHarness(graph, world=world)
        harness.run(13)                          # alpha 0.48 after the pulse tick
        assert world.get_attribute(MARKER, "xformOp:scale") == pytest.approx((1.48, 1.96, 0.76), abs=1e-9)
        harness.run(20)
        matrix = world.read_prim(MARKER).get("worldMatrix").value
        assert (matrix[0], matrix[5], matrix[10]) == pytest.approx((2.0, 3.0, 0.5), abs=1e-12)


def test_scale_to_size_on_a_body_with_colliders_fails_naming_node_and_prim(tmp_path):
    graph = _maneuver("omni.graph.nodes.ScaleToSize",
                      {"usePath": True, "primPath": "/World/Cube", "target": [2.0, 2.0, 2.0]})
    with create_world(_stage(tmp_path, CUBE), time_step=DT) as world:
        harness = GraphHarness(graph, world=world)
        with pytest.raises(GraphRuntimeError, match=r"node 'move': /World/Cube: .*cannot rescale") as raised:
            harness.run(5)
        assert "\n" not in str(raised.value)


def test_a_prim_with_a_simulated_body_under_it_is_refused(tmp_path):
    with create_world(_stage(tmp_path, CUBE), time_step=DT) as world:
        harness = GraphHarness(_translate((1, 0, 0), prim="/World"), world=world)
        with pytest.raises(GraphRuntimeError, match="node 'move': /World: .*simulated body /World/Cube under it"):
            harness.run(3)


def test_positions_are_in_stage_units(tmp_path):
    text = PLAIN.replace("metersPerUnit = 1", "metersPerUnit = 0.01")
    with create_world(_stage(tmp_path, text), time_step=DT) as world:
        GraphHarness(_translate((100, 0, 0), speed=4.0), world=world).run(30)
        assert world.prim_pose(MARKER)[0] == pytest.approx((1.0, 0.0, 0.0), abs=1e-12)
        assert world.get_attribute(MARKER, "xformOp:translate") == pytest.approx((100.0, 0.0, 0.0), abs=1e-9)


def test_a_speed_of_zero_fails_with_one_line(tmp_path):
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        with pytest.raises(GraphRuntimeError, match=r"node 'move': inputs:speed must be > 0"):
            GraphHarness(_translate((1, 0, 0), speed=0.0), world=world).run(1)



def test_move_to_transform_ends_at_the_usd_matrix_given(tmp_path):
    goal = (Gf.Matrix4d().SetScale(Gf.Vec3d(0.5, 2.0, 1.5))
            * Gf.Matrix4d().SetRotate(Gf.Rotation(Gf.Vec3d(1, 1, 0), 70.0))
            * Gf.Matrix4d().SetTranslate(Gf.Vec3d(0.3, -0.2, 1.1)))
    flat = [c for row in goal for c in row]
    graph = _maneuver("omni.graph.nodes.MoveToTransform",
                      {"usePath": True, "primPath": MARKER, "target": flat, "speed": 4.0})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        GraphHarness(graph, world=world).run(30)
        local = UsdGeom.Xformable(world.stage.GetPrimAtPath(MARKER)).GetLocalTransformation()
        assert [c for row in local for c in row] == pytest.approx(flat, abs=1e-9)


def test_rotate_to_target_takes_the_targets_world_rotation_and_keeps_its_place(tmp_path):
    graph = _maneuver("omni.graph.nodes.RotateToTarget",
                      {"useSourcePath": True, "sourcePrimPath": "/World/Frame/Child", "useTargetPath": True,
                       "targetPrimPath": "/World/Goal", "speed": 4.0})
    with create_world(_stage(tmp_path, PLAIN), time_step=DT) as world:
        place = world.prim_pose("/World/Frame/Child")[0]
        GraphHarness(graph, world=world).run(30)
        position, orientation = world.prim_pose("/World/Frame/Child")
        assert position == pytest.approx(place, abs=1e-9)
        assert _same_rotation(orientation, _usd_quaternion((10.0, 20.0, 30.0)))


def test_the_fake_world_moves_a_box_the_same_way():
    from graphflow.testing.fake_world import FakeWorld

    world = FakeWorld(time_step=DT)
    world.add_box("/Box", (0.0, 0.0, 0.0), (0.1, 0.1, 0.1))
    harness = GraphHarness(_translate((1, 0, 0), speed=2.0, prim="/Box"), world=world)
    harness.run(26)                                  # alpha 0.5 after the pulse tick
    assert world.prim_pose("/Box")[0] == pytest.approx((0.5, 0.0, 0.0), abs=1e-9)
    harness.run(30)
    assert world.prim_pose("/Box")[0] == (1.0, 0.0, 0.0) and harness.output("arrived", "count") == 1
