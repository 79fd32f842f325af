"""The prim-reading and prim-writing bundle nodes of omni.graph.nodes on a small PyBullet stage.

The stage: a 0.2 m cube (scaled 1 x 2 x 1, 1 kg rigid body) 1 m above a ground box, and a static sphere.
References are USD's own composition (authored values), free fall (z = z0 - g t^2 / 2 within the
integrator's g dt t / 2, v = -g t) and the world's own pose of the body.
"""
import math

import pytest

from graphflow.bundles import Bundle, BundleAttribute
from graphflow.document import GraphError
from graphflow.executor import GraphRuntimeError
from graphflow.observe.trace import to_json_value
from graphflow.poses import quat_rotate
from graphflow.runtime import create_world
from graphflow.testing import GraphHarness, NodeHarness
from graphflow.world import WorldError

G = 9.81
STAGE = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def PhysicsScene "physicsScene"
    {
        vector3f physics:gravityDirection = (0, 0, -1)
        float physics:gravityMagnitude = 9.81
    }
    def Cube "Ground" (prepend apiSchemas = ["PhysicsCollisionAPI"])
    {
        double size = 1
        double3 xformOp:translate = (0, 0, -0.5)
        float3 xformOp:scale = (10, 10, 1)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    }
    def Cube "Cube" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
    {
        double size = 0.2
        float physics:mass = 1
        double3 xformOp:translate = (0, 0, 1)
        quatf xformOp:orient = (1, 0, 0, 0)
        float3 xformOp:scale = (1, 2, 1)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:orient", "xformOp:scale"]
        color3f[] primvars:displayColor = [(1, 0, 0)]
    }
    def Sphere "Ball"
    {
        double radius = 0.3
        double3 xformOp:translate = (2, 0, 0.3)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
'''


@pytest.fixture
def world(tmp_path):
    path = tmp_path / "cube.usda"
    path.write_text(STAGE)
    return create_world(str(path))


def _read_and_extract(names, prim="/World/Cube", **read_inputs):
    nodes = [{"name": "read", "type": "omni.graph.nodes.ReadPrim", "inputs": {"prim": [prim], **read_inputs}}]
    connections = []
    for name in names:
        node = "x_" + name.replace(":", "_")
        nodes.append({"name": node, "type": "omni.graph.nodes.ExtractAttribute", "inputs": {"attrName": name}})
        connections.append({"src": "read.outputs:primBundle", "dst": f"{node}.inputs:data"})
    return {"nodes": nodes, "connections": connections}


def pulled(graph, node, port):
    """Compute *node* (its upstream pure nodes first, as a consumer's pull does) and read *port*."""
    graph.instance.compute_node(node)
    return graph.output(node, port)


def _x(name):
    return "x_" + name.replace(":", "_")


def test_read_prim_then_extract_attribute_reads_the_composed_values(world):
    names = ["size", "xformOp:translate", "xformOp:orient", "primvars:displayColor", "sourcePrimPath", "sourcePrimType"]
    graph = GraphHarness(_read_and_extract(names), world=world)
    values = {name: pulled(graph, _x(name), "output") for name in names}
    assert values["size"] == pytest.approx(0.2)
    assert values["xformOp:translate"] == (0.0, 0.0, 1.0)
    assert values["xformOp:orient"] == (0.0, 0.0, 0.0, 1.0)            # USD's (1, 0, 0, 0) is w first
    assert values["primvars:displayColor"] == ((1.0, 0.0, 0.0),)
    assert (values["sourcePrimPath"], values["sourcePrimType"]) == ("/World/Cube", "Cube")


def test_the_falling_cube_reads_its_physics_pose_and_world_matrix(world):
    graph = GraphHarness(_read_and_extract(["worldMatrix", "xformOp:translate", "physics:velocity"]), world=world)
    graph.run(ticks=10)                                                 # 1/6 s of free fall from 1 m
    t = world.time
    matrix = pulled(graph, _x("worldMatrix"), "output")
    position, orientation = world.prim_pose("/World/Cube")
    for row, scale in zip(range(3), (1.0, 2.0, 1.0)):                  # row i: the body's axis i times its scale
        axis = quat_rotate(orientation, tuple(float(i == row) for i in range(3)))
        assert matrix[4 * row:4 * row + 3] == pytest.approx(tuple(scale * c for c in axis), abs=1e-12)
    assert matrix[12:15] == pytest.approx(position, abs=1e-12) and matrix[15] == 1.0
    assert abs(matrix[14] - (1.0 - G * t * t / 2)) <= G * world.time_step * t / 2    # free fall, integrator's error
    assert pulled(graph, _x("xformOp:translate"), "output") == pytest.approx(position, abs=1e-12)
    assert pulled(graph, _x("physics:velocity"), "output")[2] == pytest.approx(-G * t, rel=1e-6)


def test_bounding_box_attributes_are_the_prims_own_extent(world):
    graph = GraphHarness(_read_and_extract(["bboxMinCorner", "bboxMaxCorner"], prim="/World/Ball",
                                           computeBoundingBox=True), world=world)
    assert pulled(graph, _x("bboxMinCorner"), "output") == pytest.approx((-0.3, -0.3, -0.3))
    assert pulled(graph, _x("bboxMaxCorner"), "output") == pytest.approx((0.3, 0.3, 0.3))
    plain = GraphHarness(_read_and_extract(["bboxMinCorner"], prim="/World/Ball"), world=world)
    with pytest.raises(GraphRuntimeError, match="no attribute 'bboxMinCorner' in the bundle"):
        pulled(plain, _x("bboxMinCorner"), "output")


def test_has_attribute_and_the_name_list(world):
    bundle = world.read_prim("/World/Ball")
    assert NodeHarness("omni.graph.nodes.HasAttribute", {"attrName": "radius"}).compute(data=bundle).outputs["output"]
    assert not NodeHarness("omni.graph.nodes.HasAttribute", {"attrName": "size"}).compute(data=bundle).outputs["output"]
    names = NodeHarness("omni.graph.nodes.GetAttributeNames").compute(data=bundle).outputs["output"]
    assert {"radius", "xformOp:translate", "sourcePrimPath", "sourcePrimType", "worldMatrix"} <= set(names)
    assert list(names) == sorted(names)


def test_attribute_patterns_choose_what_is_read(world):
    read = NodeHarness("omni.graph.nodes.ReadPrimAttributes", {"prim": ["/World/Cube"], "attrNamesToImport":
                                                              "xformOp:* ^xformOpOrder"}, world=world)
    names = read.compute().outputs["primBundle"].names
    assert set(names) == {"sourcePrimPath", "sourcePrimType", "xformOp:translate", "xformOp:orient",
                          "xformOp:scale", "worldMatrix"}


def test_read_prims_v2_finds_prims_by_pattern_and_extract_prim_and_get_prims_pick_them(world):
    read = NodeHarness("omni.graph.nodes.ReadPrimsV2", {"pathPattern": "/World/*", "typePattern": "Cube Sphere"},
                       world=world)
    bundle = read.compute().outputs["primsBundle"]
    assert [child.source_prim_path for child in bundle.children] == ["/World/Ground", "/World/Cube", "/World/Ball"]
    spheres = NodeHarness("omni.graph.nodes.GetPrims", {"typePattern": "Sphere"}).compute(bundle=bundle)
    assert [child.source_prim_path for child in spheres.outputs["bundle"].children] == ["/World/Ball"]
    others = NodeHarness("omni.graph.nodes.GetPrims", {"typePattern": "Sphere", "inverse": True}).compute(bundle=bundle)
    assert [child.source_prim_path for child in others.outputs["bundle"].children] == ["/World/Ground", "/World/Cube"]
    ball = NodeHarness("omni.graph.nodes.ExtractPrim", {"primPath": "/World/Ball"}).compute(prims=bundle)
    assert ball.outputs["primBundle"].get("radius").value == pytest.approx(0.3)
    with pytest.raises(GraphRuntimeError, match="no prim /World/Nothing in the bundle"):
        NodeHarness("omni.graph.nodes.ExtractPrim", {"primPath": "/World/Nothing"}).compute(prims=bundle)
    connected = NodeHarness("omni.graph.nodes.ReadPrimsV2", {"prims": ["/World/Ball", "/World/Cube"]}, world=world)
    assert [c.source_prim_path for c in connected.compute().outputs["primsBundle"].children] == ["/World/Ball",
                                                                                                "/World/Cube"]


def _writer_graph(name, value):
    """ReadPrim of the cube, and on the first tick a WritePrim of one attribute (through InsertAttribute)."""
    return {"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick", "inputs": {"onlyPlayback": False}},
        {"name": "insert", "type": "omni.graph.nodes.InsertAttribute", "inputs": {"outputAttrName": name,
                                                                                   "attrToInsert": value}},
        {"name": "write", "type": "omni.graph.nodes.WritePrim", "inputs": {"prim": ["/World/Cube"]}},
        {"name": "read", "type": "omni.graph.nodes.ReadPrim", "inputs": {"prim": ["/World/Cube"]}},
        {"name": "x", "type": "omni.graph.nodes.ExtractAttribute", "inputs": {"attrName": name}}],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
            {"src": "insert.outputs:data", "dst": "write.inputs:attributes"},
            {"src": "read.outputs:primBundle", "dst": "x.inputs:data"}]}


def test_write_prim_changes_what_a_later_read_prim_reads(world):
    graph = GraphHarness(_writer_graph("xformOp:translate", [0.5, 0.0, 2.0]), world=world)
    graph.run(ticks=1)
    assert pulled(graph, "x", "output") == pytest.approx((0.5, 0.0, 2.0), abs=1e-9)   # teleported this tick
    assert world.prim_pose("/World/Cube")[0] == pytest.approx((0.5, 0.0, 2.0), abs=1e-9)


def test_a_write_the_world_cannot_honour_fails_naming_node_and_attribute(world):
    graph = GraphHarness(_writer_graph("size", 0.5), world=world)
    with pytest.raises(GraphRuntimeError, match="attribute 'size'.*would change what is simulated .*CubeShape /World/Cube halfExtents") as failure:
        graph.run(ticks=1)
    assert failure.value.node == "write" and len(str(failure.value).splitlines()) == 1


def test_a_bundle_read_back_unchanged_writes_as_a_no_op_and_a_changed_one_moves_the_body(world):
    bundle = world.read_prim("/World/Cube")                    # size, extent, purpose...: none writable
    writer = NodeHarness("omni.graph.nodes.WritePrims", world=world)
    assert "execOut" in writer.compute("execIn", primsBundle=Bundle((), (bundle,))).fired
    moved = bundle.with_attribute(BundleAttribute("xformOp:translate", "double[3]", (1.0, 1.0, 1.0)))
    NodeHarness("omni.graph.nodes.WritePrimsV2", world=world).compute("execIn", primsBundle=moved)
    assert world.prim_pose("/World/Cube")[0] == pytest.approx((1.0, 1.0, 1.0), abs=1e-9)


def test_write_prims_v2_maps_prim_bundles_to_targets_one_to_one(world):
    bundle = world.read_prim("/World/Cube").with_attribute(BundleAttribute("physics:mass", "float", 3.0))
    writer = NodeHarness("omni.graph.nodes.WritePrimsV2", {"prims": ["/World/Cube", "/World/Ball"]}, world=world)
    with pytest.raises(GraphRuntimeError, match="names 2 targets for 1 prim bundles"):
        writer.compute("execIn", primsBundle=bundle)
    NodeHarness("omni.graph.nodes.WritePrimsV2", {"prims": ["/World/Cube"]}, world=world).compute(
        "execIn", primsBundle=bundle)
    assert world.get_attribute("/World/Cube", "physics:mass") == 3.0


def test_skeletons_and_scattering_are_refused_at_load():
    with pytest.raises(GraphError, match="inputs:applySkelBinding: graphflow's world has no skeletal"):
        NodeHarness("omni.graph.nodes.ReadPrimsV2", {"applySkelBinding": True})
    with pytest.raises(GraphError, match="inputs:scatterUnderTargets"):
        NodeHarness("omni.graph.nodes.WritePrimsV2", {"scatterUnderTargets": True})


def test_a_bundle_connects_only_to_a_bundle():
    with pytest.raises(GraphError) as problems:
        GraphHarness({"nodes": [
            {"name": "read", "type": "omni.graph.nodes.ReadPrim"},
            {"name": "x", "type": "omni.graph.nodes.ExtractAttribute"},
            {"name": "has", "type": "omni.graph.nodes.HasAttribute"}],
            "connections": [{"src": "read.outputs:primBundle", "dst": "x.inputs:attrName"},
                            {"src": "x.outputs:output", "dst": "has.inputs:data"}]})
    lines = str(problems.value).splitlines()
    assert any("node 'x' connection 'inputs:attrName': type mismatch in read.outputs:primBundle -> x.inputs:attrName: "
               "bundle cannot feed token" in line for line in lines)
    assert any("node 'has' connection 'inputs:data': type mismatch in x.outputs:output -> has.inputs:data: "
               "any cannot feed bundle" in line for line in lines)


def test_a_bundle_in_a_trace_is_its_attributes_by_name(world):
    ball = world.read_prim("/World/Ball")
    shown = to_json_value(Bundle((), (ball,)))
    assert shown["attributes"] == {}
    (child,) = shown["children"]
    assert child["attributes"]["radius"] == pytest.approx(0.3)
    assert child["attributes"]["xformOp:translate"] == [2.0, 0.0, 0.3]
    assert list(child["attributes"])[:2] == ["sourcePrimPath", "sourcePrimType"]
    assert math.isclose(child["attributes"]["worldMatrix"][14], 0.3)


def test_the_fake_world_reads_prims_with_its_own_values_live():
    from pxr import Usd, UsdGeom

    from graphflow.testing.fake_world import FakeWorld

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.Cube.Define(stage, "/World/Box").CreateSizeAttr(0.5)
    world = FakeWorld(stage=stage)
    half = math.sqrt(0.5)
    world.add_box("/World/Box", (1.0, 2.0, 3.0), (0.25, 0.25, 0.25), orientation=(0.0, 0.0, half, half))
    world.set_attribute("/World/Box", "size", 0.75)                       # the world's value wins over USD's
    bundle = world.read_prim("/World/Box")
    assert bundle.get("size").value == 0.75 and bundle.source_prim_type == "Cube"
    matrix = bundle.get("worldMatrix").value                               # +90 deg about Z: x axis -> +y
    assert matrix[0:3] == pytest.approx((0.0, 1.0, 0.0)) and matrix[12:15] == pytest.approx((1.0, 2.0, 3.0))
    bare = FakeWorld()
    bare.add_box("/Box", (0.0, 0.0, 1.0), (0.1, 0.1, 0.1))
    bare.set_attribute("/Box", "label", "crate")
    assert bare.read_prim("/Box").get("label") == BundleAttribute("label", "token", "crate")
    with pytest.raises(WorldError, match="no prim /Nothing"):
        bare.read_prim("/Nothing")


def test_usd_timecode_reads_authored_time_samples():
    from pxr import Usd, UsdGeom

    from graphflow.testing.fake_world import FakeWorld

    stage = Usd.Stage.CreateInMemory()
    size = UsdGeom.Cube.Define(stage, "/World/Box").CreateSizeAttr(1.0)
    size.Set(1.0, 1.0)
    size.Set(3.0, 3.0)                                                     # USD interpolates linearly between
    world = FakeWorld(stage=stage)
    at = {time: NodeHarness("omni.graph.nodes.ReadPrim", {"prim": ["/World/Box"], "usdTimecode": time},
                            world=world).compute().outputs["primBundle"].get("size").value for time in (1.0, 2.0, 5.0)}
    assert at == {1.0: 1.0, 2.0: 2.0, 5.0: 3.0}
    default = NodeHarness("omni.graph.nodes.ReadPrim", {"prim": ["/World/Box"]}, world=world).compute()
    assert default.outputs["primBundle"].get("size").value == 1.0           # NaN: USD's default time


def test_a_value_read_back_unchanged_is_no_write_even_when_it_is_nan():
    from graphflow.testing.fake_world import FakeWorld

    class ReadOnlyWorld(FakeWorld):
        def set_attribute(self, prim_path, name, value):
            raise WorldError(f"{prim_path}: attribute {name} is read-only")

    world = ReadOnlyWorld()
    world.attributes[("/Box", "gap")] = float("nan")
    world.attributes[("/Box", "limits")] = (float("nan"), 1.0)
    writer = NodeHarness("omni.graph.nodes.WritePrims", world=world)
    assert "execOut" in writer.compute("execIn", primsBundle=world.read_prim("/Box")).fired
    changed = world.read_prim("/Box").with_attribute(BundleAttribute("gap", "double", 0.5))
    with pytest.raises(GraphRuntimeError, match="attribute 'gap': /Box: attribute gap is read-only"):
        writer.compute("execIn", primsBundle=changed)
