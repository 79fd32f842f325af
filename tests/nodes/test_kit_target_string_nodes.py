"""omni.graph.nodes target-array, string and array nodes, on the examples and rules of Kit's reference."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


def out(type_id, output, **inputs):
    return NodeHarness(f"omni.graph.nodes.{type_id}", inputs=inputs).compute().outputs[output]


ROBOTS = ("/World/ur10", "/World/franka", "/World/jetbot")


def test_append_targets_skips_repeats_unless_allowed():
    assert out("AppendTargets", "targets", input0=["/A", "/B"], input1=["/B", "/C"]) == ("/A", "/B", "/C")
    assert out("AppendTargets", "targets", input0=["/A", "/B"], input1=["/B"], input2=["/A"],
               allowDuplicates=True) == ("/A", "/B", "/B", "/A")


def test_append_target_paths_follows_the_references_example():
    assert out("AppendTargetPaths", "targets", rootTargets=["/World"], input0="Cube") == ("/World/Cube",)
    assert out("AppendTargetPaths", "targets", input0="Xform/Cube") == ("/Xform/Cube",)
    assert out("AppendTargetPaths", "targets", rootTargets=["/A", "/B"], input0=["x", "y"]) == ("/A/x", "/B/y")
    with pytest.raises(GraphRuntimeError, match="relative path"):
        out("AppendTargetPaths", "targets", rootTargets=["/World"], input0="/Cube")


def test_compare_targets_whole_and_each():
    assert out("CompareTargets", "result", a=list(ROBOTS), b=list(ROBOTS)) is True
    assert out("CompareTargets", "result", a=list(ROBOTS), b=list(ROBOTS[:2]), operation="!=") is True
    assert out("CompareTargets", "result", a=["/A", "/B"], b=["/A", "/C", "/D"], compareEach=True) == \
        (True, False, False)


def test_get_set_insert_replace_and_select():
    assert out("GetTargets", "targets", targets=list(ROBOTS), index=-2) == ("/World/franka",)
    assert out("GetTargets", "targets", targets=list(ROBOTS), index=1, count=-1) == ROBOTS[1:]
    assert out("GetTargets", "targets", targets=list(ROBOTS), index=2, count=5) == ROBOTS[2:]
    with pytest.raises(GraphRuntimeError, match="out of range"):
        out("GetTargets", "targets", targets=list(ROBOTS), index=3)
    assert out("SetTarget", "targets", targets=list(ROBOTS), index=-1, setTarget=["/World/carter"]) == \
        ("/World/ur10", "/World/franka", "/World/carter")
    assert out("InsertTargets", "targets", targets=list(ROBOTS), index=99, insertTargets=["/X"]) == ROBOTS + ("/X",)
    assert out("InsertTargets", "targets", targets=list(ROBOTS), index=-5, insertTargets=["/X"]) == ("/X",) + ROBOTS
    assert out("ReplaceTargets", "targets", targets=["/A", "/B", "/A"], replaceTargets=["/A"],
               setTargets=["/Z"]) == ("/Z", "/B", "/Z")
    assert out("ReplaceTargets", "targets", targets=["/A", "/B", "/A"], replaceTargets=["/A"]) == ("/B",)
    assert out("ReplaceTargetName", "targets", targets=["/World/Cube"], newName="Sphere") == ("/World/Sphere",)
    assert out("SelectTargetIf", "result", condition=True, ifTrue=["/T"], ifFalse=["/F"]) == ("/T",)
    assert out("SelectTargetIf", "result", condition=[True, False], ifTrue=["/T1", "/T2"],
               ifFalse=["/F1", "/F2"]) == ("/T1", "/F2")


def test_string_nodes():
    assert out("GetString", "string", string="base_link", index=-4) == "link"
    assert out("GetString", "string", string="base_link", index=0, count=4) == "base"
    with pytest.raises(GraphRuntimeError, match="out of range"):
        out("GetString", "string", string="abc", index=3)
    assert out("InsertString", "string", string="/World/robot", index=99, value="_1") == "/World/robot_1"
    assert out("InsertString", "string", string="link", index=-3, value="base_") == "base_link"
    assert out("ReplaceString", "string", string="a-b-c", replace="-", value="/") == "a/b-c"
    assert out("ReplaceString", "string", string="a-b-c", replace="-", value="", replaceAll=True) == "abc"


def test_array_slice_append_and_replace():
    values = (0, 1, 2, 3, 4)
    assert out("ArraySlice", "array", array=values, start=1, end=3, useLength=False) == (1, 2)
    assert out("ArraySlice", "array", array=values, start=-2) == (3, 4)
    assert out("ArraySlice", "array", array=values, start=-99, end=99, useLength=False) == values
    assert out("ArraySlice", "array", array=values, start=3, end=1, useLength=False) == ()
    assert out("ArrayAppendValue", "array", array=[[1.0, 2.0]], value=[3.0, 4.0]) == ((1.0, 2.0), (3.0, 4.0))
    assert out("ArrayReplaceValue", "array", array=[1, 2, 1], value=1, newValue=7) == (7, 2, 1)
    assert out("ArrayReplaceValue", "array", array=[1, 2, 1], value=1, newValue=7, replaceAll=True) == (7, 2, 7)
