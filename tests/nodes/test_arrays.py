"""omni.graph.nodes.ConstructArray and ArrayIndex."""
import pytest

from graphflow.document import GraphError
from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness, NodeHarness


def _construct(**inputs):
    return NodeHarness("omni.graph.nodes.ConstructArray", inputs=inputs).compute().outputs["array"]


def test_krabby_style_double_array_converts_ints_and_fills_unset_with_zero():
    # as in krabby crab_simple.usda: arraySize 18, arrayType "double[]", input0 unset
    inputs = {"arraySize": 18, "arrayType": "double[]"}
    inputs.update({f"input{i}": i for i in range(1, 18)})
    array = _construct(**inputs)
    assert array == tuple(float(i) for i in range(18))
    assert all(type(v) is float for v in array)


def test_token_array_of_joint_names():
    names = ["FL_Body_Hip", "FL_Hip_Femur", "FL_Femur_Tibia"]
    array = _construct(arraySize=3, arrayType="token[]", **{f"input{i}": n for i, n in enumerate(names)})
    assert array == tuple(names)


def test_auto_type_keeps_elements_and_only_uses_array_size_inputs():
    assert _construct(arraySize=2, input0=[1.0, 0.0, 0.0], input1=[0.0, 1.0, 0.0], input2=5) == (
        (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))
    assert _construct(arraySize=0) == ()


def test_all_32_inputs_are_available():
    assert _construct(arraySize=32, arrayType="int[]", input31=31)[31] == 31


def test_auto_type_with_an_unset_input_is_an_error_naming_it():
    with pytest.raises(GraphRuntimeError, match="inputs:input1 has no value"):
        _construct(arraySize=2, input0=1.0)


def test_element_that_does_not_fit_the_array_type_is_an_error():
    with pytest.raises(GraphRuntimeError, match="inputs:input0 does not fit arrayType double\\[3\\]\\[\\]"):
        _construct(arraySize=1, arrayType="double[3][]", input0=[1.0, 2.0])


def test_array_size_out_of_range_is_rejected_at_load():
    with pytest.raises(GraphError, match="inputs:arraySize"):
        NodeHarness("omni.graph.nodes.ConstructArray", inputs={"arraySize": 33})


def test_array_index_reads_elements_including_negative_indices():
    h = NodeHarness("omni.graph.nodes.ArrayIndex", inputs={"array": [10, 20, 30]})
    assert h.compute(index=0).outputs["value"] == 10
    assert h.compute(index=2).outputs["value"] == 30
    assert h.compute(index=-1).outputs["value"] == 30


@pytest.mark.parametrize("index", [3, -4])
def test_array_index_out_of_range_is_an_error(index):
    with pytest.raises(GraphRuntimeError, match=f"inputs:index {index} is out of range for an array of 3"):
        NodeHarness("omni.graph.nodes.ArrayIndex", inputs={"array": [1, 2, 3], "index": index}).compute()


def test_construct_then_index_in_a_graph():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "arr", "type": "omni.graph.nodes.ConstructArray",
             "inputs": {"arraySize": 3, "arrayType": "token[]", "input0": "a", "input1": "b", "input2": "c"}},
            {"name": "at", "type": "omni.graph.nodes.ArrayIndex", "inputs": {"index": 1}},
            {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "print.inputs:execIn"},
            {"src": "arr.outputs:array", "dst": "at.inputs:array"},
            {"src": "at.outputs:value", "dst": "print.inputs:text"},
        ],
    })
    g.run(ticks=1)
    assert g.logs == ["b"]


def test_array_remove_index_fill_and_resize():
    from graphflow.testing import NodeHarness

    def out(type_name, **inputs):
        return NodeHarness(f"omni.graph.nodes.{type_name}", inputs).compute().outputs["array"]

    assert out("ArrayRemoveIndex", array=[1, 2, 3], index=-1) == (1, 2)
    assert out("ArrayRemoveIndex", array=[1, 2, 3], index=0) == (2, 3)
    assert out("ArrayFill", array=[1.0, 2.0, 3.0], fillValue=7.5) == (7.5, 7.5, 7.5)
    assert out("ArrayResize", array=[1, 2, 3], newSize=2) == (1, 2)
    assert out("ArrayResize", array=[[1.0, 2.0]], newSize=3) == ((1.0, 2.0), (0.0, 0.0), (0.0, 0.0))
    assert out("ArrayResize", array=[1, 2], newSize=-4) == ()


def test_array_set_index_and_to_target():
    from graphflow.testing import NodeHarness

    def out(type_name, output, **inputs):
        return NodeHarness(f"omni.graph.nodes.{type_name}", inputs).compute().outputs[output]

    assert out("ArraySetIndex", "array", array=[1, 2, 3], index=-1, value=9) == (1, 2, 9)
    assert out("ArraySetIndex", "array", array=[1.0], index=2, value=5.0, resizeToFit=True) == (1.0, 0.0, 5.0)
    assert out("ToTarget", "converted", value="/World/Cube") == ("/World/Cube",)
    assert out("ToTarget", "converted", value=["/World/a", "/World/b"]) == ("/World/a", "/World/b")
    assert out("ToTarget", "converted", value="") == ()


def test_array_reverse_rotate_remove_and_insert_values():
    from graphflow.testing import NodeHarness

    def out(type_name, output="array", **inputs):
        return NodeHarness(f"omni.graph.nodes.{type_name}", inputs).compute().outputs[output]

    assert out("ArrayReverse", array=[1, 2, 3]) == (3, 2, 1)
    assert out("ArrayRotate", array=[1, 2, 3, 4], steps=1) == (4, 1, 2, 3)
    assert out("ArrayRotate", array=[1, 2, 3, 4], steps=-1) == (2, 3, 4, 1)
    assert out("ArrayRemoveValue", array=[1, 2, 1, 3], value=1) == (2, 1, 3)
    assert out("ArrayRemoveValue", array=[1, 2, 1, 3], value=1, removeAll=True) == (2, 3)
    assert out("ArrayRemoveValue", "found", array=[1, 2], value=5) is False
    assert out("ArrayInsertValue", array=[1, 2, 3], index=1, value=9) == (1, 9, 2, 3)
    assert out("ArrayInsertValue", array=[1, 2], index=-1, value=0) == (0, 1, 2)
    assert out("ArrayInsertValue", array=[1, 2], index=7, value=3) == (1, 2, 3)


def test_array_find_value_gives_the_first_index_or_minus_one():
    from graphflow.testing import NodeHarness

    def find(array, value):
        return NodeHarness("omni.graph.nodes.ArrayFindValue", {"array": array, "value": value}).compute().outputs["index"]

    assert find([4, 7, 7], 7) == 1
    assert find([[0.0, 1.0], [1.0, 0.0]], [1.0, 0.0]) == 1
    assert find([1, 2], 3) == -1


def test_construct_array_reads_elements_kit_saved_as_text_while_unresolved():
    """Kit saves an unresolved 'any' input as token text (Isaac's Basic Robot tutorial: input0 = "-0.9")."""
    from graphflow.testing import NodeHarness

    made = NodeHarness("omni.graph.nodes.ConstructArray", {"arraySize": 3, "arrayType": "double[]", "input0": "-0.9",
                                                           "input1": 1.8}).compute().outputs["array"]
    assert made == (-0.9, 1.8, 0.0)
    rows = NodeHarness("omni.graph.nodes.ConstructArray", {"arraySize": 1, "arrayType": "double[3][]",
                                                           "input0": "(1, 2, 3)"}).compute().outputs["array"]
    assert rows == ((1.0, 2.0, 3.0),)
    tokens = NodeHarness("omni.graph.nodes.ConstructArray", {"arraySize": 1, "arrayType": "token[]",
                                                             "input0": "1.5"}).compute().outputs["array"]
    assert tokens == ("1.5",)
