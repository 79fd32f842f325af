"""omni.graph.nodes MakeArray, GetGraphTargetId and IsPrimSelected."""
import hashlib

import pytest

from graphflow.build import og
from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness, NodeHarness
from graphflow.testing.fake_world import FakeWorld
from graphflow.usd.omnigraph import import_graph


def outputs(type_id, **inputs):
    return NodeHarness(f"omni.graph.nodes.{type_id}", inputs).compute().outputs


def test_make_array_takes_the_first_elements_and_repeats_e():
    # an Isaac differential-drive graph's joint names: four tokens into arraySize 4
    names = outputs("MakeArray", arraySize=4, a="front_left_wheel", b="front_right_wheel", c="rear_left_wheel",
                    d="rear_right_wheel")
    assert names["array"] == ("front_left_wheel", "front_right_wheel", "rear_left_wheel", "rear_right_wheel")
    assert outputs("MakeArray", arraySize=2, a=0.5, b=-0.5, c=9.0)["array"] == (0.5, -0.5)
    assert outputs("MakeArray", arraySize=7, a=1.0, b=2.0, c=3.0, d=4.0, e=5.0)["array"] == \
        (1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0)
    assert outputs("MakeArray")["array"] == ()          # arraySize defaults to 0


def test_make_array_typed_elements_default_to_zero_and_auto_needs_every_element():
    assert outputs("MakeArray", arraySize=3, arrayType="double[]", a=2)["array"] == (2.0, 0.0, 0.0)
    with pytest.raises(GraphRuntimeError, match="inputs:b has no value"):
        outputs("MakeArray", arraySize=2, a=1.0)
    with pytest.raises(GraphRuntimeError, match="inputs:a does not fit arrayType int"):
        outputs("MakeArray", arraySize=1, arrayType="int[]", a="wheel")


def test_graph_target_id_is_the_same_for_the_same_path_in_every_run():
    first = outputs("GetGraphTargetId", targetPath="/World/ActionGraph")["targetId"]
    assert first == int.from_bytes(hashlib.sha256(b"/World/ActionGraph").digest()[:8], "big")
    assert outputs("GetGraphTargetId", targetPath="/World/ActionGraph")["targetId"] == first
    assert outputs("GetGraphTargetId", targetPath="/World/Other")["targetId"] != first
    assert 0 <= first < 2 ** 64
    with pytest.raises(GraphRuntimeError, match="targetPath is empty"):
        outputs("GetGraphTargetId")


def test_import_tells_graph_target_id_its_graph_prim(tmp_path):
    stage = tmp_path / "target.usda"
    stage.write_text('''#usda 1.0
def Xform "World"
{
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        def OmniGraphNode "id"
        {
            token node:type = "omni.graph.nodes.GetGraphTargetId"
            int node:typeVersion = 1
        }
    }
}
''')
    document = import_graph(str(stage)).document
    assert document.node("id").inputs == {"targetPath": "/World/ActionGraph"}


def test_no_prim_is_selected_headless_and_a_missing_prim_fails():
    world = FakeWorld()
    world.add_box("/World/Robot", (0.0, 0.0, 0.5), (0.1, 0.1, 0.1))
    for inputs in ({"primPath": "/World/Robot"}, {"prim": ["/World/Robot"]}):
        assert NodeHarness("omni.graph.nodes.IsPrimSelected", inputs, world=world).compute().outputs["isSelected"] is False
    with pytest.raises(GraphRuntimeError, match="/World/Robt"):
        NodeHarness("omni.graph.nodes.IsPrimSelected", {"primPath": "/World/Robt"}, world=world).compute()


def test_each_instance_of_an_instanced_graph_gets_its_own_target_id(tmp_path):
    stage = tmp_path / "instances.usda"
    stage.write_text('''#usda 1.0
def Xform "World"
{
    def Cube "A" (prepend apiSchemas = ["OmniGraphAPI"])
    {
        rel omniGraphs = </Graph>
    }
    def Cube "B" (prepend apiSchemas = ["OmniGraphAPI"])
    {
        rel omniGraphs = </Graph>
    }
}
def OmniGraph "Graph"
{
    def OmniGraphNode "id"
    {
        token node:type = "omni.graph.nodes.GetGraphTargetId"
        int node:typeVersion = 1
    }
}
''')
    document = import_graph(str(stage), output_path=str(tmp_path / "graph.json")).document
    harness = GraphHarness(document)
    for name in ("A_id", "B_id"):
        harness.instance.compute_node(name)
    expected = [int.from_bytes(hashlib.sha256(path).digest()[:8], "big") for path in (b"/World/A", b"/World/B")]
    assert [harness.output(name, "targetId") for name in ("A_id", "B_id")] == expected


def test_a_husky_script_builds_its_joint_name_array_with_make_array():
    """As a published Isaac 2022 script does: four ConstantTokens read from their inputs into MakeArray's a..d."""
    keys = og.Controller.Keys
    graph, *_ = og.Controller.edit("/MakeArrayHusky", {
        keys.CREATE_NODES: [("tick", "omni.graph.action.OnTick"), ("names", "omni.graph.nodes.MakeArray"),
                            ("text", "graphflow.FormatText"), ("show", "omni.graph.ui_nodes.PrintText")]
        + [(f"token{i}", "omni.graph.nodes.ConstantToken") for i in range(1, 5)],
        keys.SET_VALUES: [("token1.inputs:value", "front_left_wheel"), ("token2.inputs:value", "front_right_wheel"),
                          ("token3.inputs:value", "rear_left_wheel"), ("token4.inputs:value", "rear_right_wheel"),
                          ("names.inputs:arraySize", 4)],
        keys.CONNECT: [("token1.inputs:value", "names.inputs:b"), ("token2.inputs:value", "names.inputs:a"),
                       ("token3.inputs:value", "names.inputs:d"), ("token4.inputs:value", "names.inputs:c"),
                       ("tick.outputs:tick", "show.inputs:execIn"), ("names.outputs:array", "text.inputs:value"),
                       ("text.outputs:text", "show.inputs:text")]})
    harness = GraphHarness(graph.document)
    harness.run(1)
    assert harness.output("names", "array") == ("front_right_wheel", "front_left_wheel", "rear_right_wheel",
                                                "rear_left_wheel")
