"""omni.graph.nodes types added from Kit's node library reference, on the reference's own examples."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


def test_increment_keeps_the_value_type_and_chops_integers():
    # Kit's example: 4 + 3.2 -> 7; a tuple plus a double stays a tuple; the default increment is 1.0
    assert NodeHarness("omni.graph.nodes.Increment", {"value": 4, "increment": 3.2}).compute().outputs["result"] == 7
    tuple_result = NodeHarness("omni.graph.nodes.Increment", {"value": [1.0, 2.0, 3.0], "increment": 0.5}).compute()
    assert tuple_result.outputs["result"] == (1.5, 2.5, 3.5)
    assert NodeHarness("omni.graph.nodes.Increment", {"value": 2.25}).compute().outputs["result"] == 3.25


def test_modulo_is_the_remainder_and_zero_for_a_zero_divisor():
    assert NodeHarness("omni.graph.nodes.Modulo", {"a": 17, "b": 5}).compute().outputs["result"] == 2
    assert NodeHarness("omni.graph.nodes.Modulo", {"a": 17, "b": 0}).compute().outputs["result"] == 0
    assert NodeHarness("omni.graph.nodes.Modulo", {"a": -7, "b": 3}).compute().outputs["result"] == -1   # C++ %


def test_to_string_writes_numbers_arrays_and_tokens_as_kit_does():
    def text(value):
        return NodeHarness("omni.graph.nodes.ToString", {"value": value}).compute().outputs["converted"]
    assert text(1234567.0) == "1.23457e+06"      # the reference's exponential form
    assert text([1.5, -0.03]) == "[1.5, -0.03]"
    assert text("first") == "first"
    assert text(["first", "second"]) == '["first", "second"]'
    assert text(True) == "true" and text(42) == "42"
    assert NodeHarness("omni.graph.nodes.ToToken", {"value": 0.25}).compute().outputs["converted"] == "0.25"


def test_array_get_size_counts_elements_and_refuses_a_scalar():
    assert NodeHarness("omni.graph.nodes.ArrayGetSize", {"array": [[0, 0, 1], [1, 0, 0]]}).compute().outputs["size"] == 2
    with pytest.raises(GraphRuntimeError, match="inputs:array is not an array"):
        NodeHarness("omni.graph.nodes.ArrayGetSize", {"array": 3.0}).compute()


def test_make_and_break_vector4_round_trip_a_quaternion():
    made = NodeHarness("omni.graph.nodes.MakeVector4", {"x": 0.0, "y": 0.0, "z": 0.7071, "w": 0.7071}).compute()
    assert made.outputs["tuple"] == (0.0, 0.0, 0.7071, 0.7071)
    broken = NodeHarness("omni.graph.nodes.BreakVector4", {"tuple": list(made.outputs["tuple"])}).compute()
    assert (broken.outputs["x"], broken.outputs["z"], broken.outputs["w"]) == (0.0, 0.7071, 0.7071)


@pytest.mark.parametrize(("type_id", "value"), [
    ("omni.graph.nodes.ConstantFloat3", (1.0, 2.0, 3.0)), ("omni.graph.nodes.ConstantVector3d", (0.0, 0.0, 1.0)),
    ("omni.graph.nodes.ConstantPath", "/World/robot"), ("omni.graph.nodes.ConstantQuatd", (0.0, 0.0, 0.0, 1.0)),
    ("omni.graph.nodes.ConstantInt64", 2**40), ("omni.graph.nodes.ConstantUInt", 7),
    ("omni.graph.nodes.ConstantUInt64", 2**63), ("omni.graph.nodes.ConstantFloat2", (0.5, 0.25)),
    ("omni.graph.nodes.ConstantDouble2", (0.5, 0.25)), ("omni.graph.nodes.ConstantPoint3d", (1.0, 0.0, 0.0))])
def test_constants_output_their_value(type_id, value):
    authored = list(value) if isinstance(value, tuple) else value
    assert NodeHarness(type_id, {"value": authored}).compute().outputs["value"] == value


def _scene_world():
    from pxr import Sdf, Usd, UsdGeom

    from graphflow.testing import ClockWorld

    stage = Usd.Stage.CreateInMemory()
    for path in ("/World", "/World/Cube0", "/World/Cube1", "/World/Box", "/World/Box/Cube2"):
        UsdGeom.Xform.Define(stage, path) if "Cube" not in path else UsdGeom.Cube.Define(stage, path)
    stage.DefinePrim("/World/Graph", "OmniGraph")
    stage.GetPrimAtPath("/World/Cube1").CreateRelationship("physics:body0").SetTargets([Sdf.Path("/World/Box")])
    world = ClockWorld(0.1)
    world.stage = stage
    return world


def test_find_prims_filters_as_the_references_wildcard_examples():
    world = _scene_world()

    def found(**inputs):
        return NodeHarness("omni.graph.nodes.FindPrims", {"rootPrimPath": "/World", **inputs},
                           world=world).compute().outputs["primPaths"]
    assert found() == ("/World/Cube0", "/World/Cube1", "/World/Box", "/World/Graph")
    # the reference's examples: '* ^/Box' all but the box, '* ^/Cube*' all but the cubes
    assert found(pathPattern="* ^/World/Box") == ("/World/Cube0", "/World/Cube1", "/World/Graph")
    assert found(pathPattern="* ^/World/Cube*") == ("/World/Box", "/World/Graph")
    assert found(recursive=True, type="Cube") == ("/World/Cube0", "/World/Cube1", "/World/Box/Cube2")
    assert found(namePrefix="Cube", requiredRelationship="physics:body0",
                 requiredRelationshipTarget="/World/Box") == ("/World/Cube1",)
    assert found(ignoreSystemPrims=True, type="* ^Cube") == ("/World/Box",)
    with pytest.raises(GraphRuntimeError, match="names no stage"):
        NodeHarness("omni.graph.nodes.FindPrims").compute()


def test_prim_paths_and_prims_convert_both_ways():
    paths = NodeHarness("omni.graph.nodes.GetPrimPaths", {"prims": ["/World/a", "/World/b"]}).compute()
    assert paths.outputs["primPaths"] == ("/World/a", "/World/b")
    prims = NodeHarness("omni.graph.nodes.GetPrimsAtPath", {"path": "/World/a"}).compute()
    assert prims.outputs["prims"] == ("/World/a",)
    with pytest.raises(GraphRuntimeError, match="absolute prim paths"):
        NodeHarness("omni.graph.nodes.GetPrimsAtPath", {"path": "World"}).compute()
