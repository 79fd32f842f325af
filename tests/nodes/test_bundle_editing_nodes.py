"""The bundle-editing nodes of omni.graph.nodes on hand-made bundles, against Kit's documented behaviour.

AttributeType's numbers are Fabric's published encoding (omni/fabric Type.h): baseType | componentCount << 8
| arrayDepth << 16 | role << 24, with double 9, float 8, token 10, uchar 2 and roles position 3, text 10.
"""
import pytest
from pxr import Sdf

from graphflow.bundles import Bundle, BundleAttribute
from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness


def node(name, inputs=None, **bundles):
    return NodeHarness(f"omni.graph.nodes.{name}", inputs or {}).compute(**bundles).outputs


CUBE = Bundle.of_prim("/World/Cube", "Cube", (
    BundleAttribute("size", "double", 0.2),
    BundleAttribute("points", "pointf[3][]", ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0))),
    BundleAttribute("xformOp:translate", "double[3]", (0.0, 0.0, 1.0)),
    BundleAttribute("label", "string", "box"),
))


def test_insert_remove_and_rename_give_new_bundles_and_leave_the_input_alone():
    inserted = node("InsertAttribute", {"outputAttrName": "mass", "attrToInsert": 1.5}, data=CUBE)["data"]
    assert inserted.get("mass") == BundleAttribute("mass", "double", 1.5)
    assert CUBE.get("mass") is None                                         # bundles are values
    replaced = node("InsertAttribute", {"outputAttrName": "size", "attrToInsert": [1, 2, 3]}, data=CUBE)["data"]
    assert replaced.get("size") == BundleAttribute("size", "int[3]", (1, 2, 3)) and replaced.names == CUBE.names
    removed = node("RemoveAttribute", {"attrNamesToRemove": "* ^size"}, data=CUBE)["data"]
    assert removed.names == ("sourcePrimPath", "sourcePrimType", "size")    # the prim marks stay
    everything = node("RemoveAttribute", {"attrNamesToRemove": "*", "allowRemovePrimInternal": True}, data=CUBE)
    assert everything["data"].names == ()
    assert node("RemoveAttribute", data=CUBE)["data"] == CUBE              # no pattern: nothing removed
    renamed = node("RenameAttribute", {"inputAttrNames": "size, label", "outputAttrNames": "edge name"},
                   data=CUBE)["data"]
    assert renamed.get("edge").value == 0.2 and renamed.get("name").value == "box"
    assert renamed.get("size") is None and len(renamed) == len(CUBE)


def test_rename_and_copy_name_what_is_wrong():
    with pytest.raises(GraphRuntimeError, match="inputAttrNames lists 2 names but outputAttrNames 1"):
        node("RenameAttribute", {"inputAttrNames": "size label", "outputAttrNames": "edge"}, data=CUBE)
    with pytest.raises(GraphRuntimeError, match="no attribute 'radius' in the bundle"):
        node("RenameAttribute", {"inputAttrNames": "radius", "outputAttrNames": "r"}, data=CUBE)


def test_copy_attribute_takes_all_of_one_bundle_and_named_attributes_of_another():
    other = Bundle((BundleAttribute("size", "double", 5.0), BundleAttribute("color", "colorf[3]", (1.0, 0.0, 0.0))))
    copied = node("CopyAttribute", {"inputAttrNames": "color size", "outputAttrNames": "tint size"},
                  fullData=CUBE, partialData=other)["data"]
    assert copied.get("tint") == BundleAttribute("tint", "colorf[3]", (1.0, 0.0, 0.0))
    assert copied.get("size").value == 5.0 and copied.names[:len(CUBE)] == CUBE.names
    same_names = node("CopyAttribute", {"inputAttrNames": "color"}, fullData=CUBE, partialData=other)["data"]
    assert same_names.get("color") is not None


@pytest.mark.parametrize("name, expected", [
    ("size", (9, 1, 0, 0)),
    ("xformOp:translate", (9, 3, 0, 0)),
    ("points", (8, 3, 1, 3)),
    ("label", (2, 1, 1, 10)),
    ("sourcePrimPath", (10, 1, 0, 0)),
])
def test_attribute_type_gives_fabrics_numbers(name, expected):
    outputs = node("AttributeType", {"attrName": name}, data=CUBE)
    base, count, depth, role = expected
    assert (outputs["baseType"], outputs["componentCount"], outputs["arrayDepth"], outputs["role"]) == expected
    assert outputs["fullType"] == base + 256 * count + 65536 * depth + 16777216 * role


def test_attribute_type_and_array_length_of_a_missing_attribute():
    outputs = node("AttributeType", {"attrName": "nothing"}, data=CUBE)
    assert {outputs[key] for key in ("baseType", "componentCount", "arrayDepth", "role", "fullType")} == {-1}
    assert node("ArrayLength", {"attrName": "points"}, data=CUBE)["length"] == 3
    assert node("ArrayLength", {"attrName": "size"}, data=CUBE)["length"] == 1      # not an array
    with pytest.raises(GraphRuntimeError, match="no attribute 'normals' in the bundle"):
        node("ArrayLength", {"attrName": "normals"}, data=CUBE)


def test_bundle_inspector_lists_attributes_down_to_the_depth_asked():
    prims = Bundle((BundleAttribute("count", "int", 1),), (CUBE,))
    inspector = NodeHarness("omni.graph.nodes.BundleInspector", {"inspectDepth": 0, "print": True})
    outputs = inspector.compute("execIn", bundle=prims).outputs
    assert outputs["names"] == ("count",) and outputs["childCount"] == 1 and outputs["attributeCount"] == 1
    deep = NodeHarness("omni.graph.nodes.BundleInspector").compute("execIn", bundle=prims).outputs   # depth 1
    assert deep["names"] == ("count",) + CUBE.names and deep["attributeCount"] == deep["count"] == 7
    index = deep["names"].index("points")
    assert (deep["types"][index], deep["roles"][index], deep["tupleCounts"][index], deep["arrayDepths"][index]) == \
        ("float", "position", 3, 1)
    assert deep["values"][deep["names"].index("xformOp:translate")] == "[0.0, 0.0, 1.0]"
    assert deep["bundle"] == prims
    assert inspector.logs == ["count (int) = 1"]


def test_bundle_to_usda_writes_text_usd_reads_back():
    text = NodeHarness("omni.graph.BundleToUSDA", {"outputAncestors": True}).compute(bundle=CUBE).outputs["text"]
    layer = Sdf.Layer.CreateAnonymous(".usda")
    assert layer.ImportFromString("#usda 1.0\n" + text)
    prim = layer.GetPrimAtPath("/World/Cube")
    assert prim.typeName == "Cube"
    assert prim.attributes["size"].default == 0.2
    assert prim.attributes["points"].typeName == Sdf.ValueTypeNames.Point3fArray
    assert list(prim.attributes["points"].default)[1] == (1.0, 0.0, 0.0)
    assert prim.attributes["label"].default == "box"
    bare = NodeHarness("omni.graph.BundleToUSDA", {"outputValues": False, "usePrimType": False}).compute(
        bundle=CUBE).outputs["text"]
    assert bare.splitlines()[0] == 'def "Cube"' and "double size\n" in bare


def test_bundle_constructor_starts_empty_and_extract_bundle_passes_through():
    assert node("BundleConstructor")["bundle"] == Bundle()
    assert node("ExtractBundle", bundle=CUBE)["passThrough"] is CUBE
