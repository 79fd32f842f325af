"""Importing Isaac graphs that use bundles: Kit's bundle relationships and its dynamic bundle ports.

The graph, in the .usda form Kit saves: ReadPrimAttributes of a falling cube exposes `size` as a dynamic
output feeding an Add; a BundleConstructor holds an authored `speed` and a connected `total` (the sum);
ReadPrimsV2's output bundle reaches ExtractPrim through a relationship to its `outputs_primsBundle` prim,
and ExtractPrim's reaches GetAttributeNames through one to `.outputs:primBundle` (newer files); a WritePrim
writes its connected dynamic `xformOp:translate` (and drops the authored, unconnected `size`, as Kit does).
"""
import math

import pytest

from graphflow.document import load_document, save_document
from graphflow.runtime import create_world
from graphflow.testing import GraphHarness
from graphflow.usd.omnigraph import import_graph

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
    def Cube "Cube" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
    {
        double size = 0.2
        float physics:mass = 1
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        int2 fileFormatVersion = (1, 9)
        def OmniGraphNode "tick"
        {
            token node:type = "omni.graph.action.OnTick"
            int node:typeVersion = 2
            custom bool inputs:onlyPlayback = 0
            custom uint outputs:tick (customData = {bool isExecution = 1})
        }
        def OmniGraphNode "attrs"
        {
            token node:type = "omni.graph.nodes.ReadPrimAttributes"
            int node:typeVersion = 3
            custom string inputs:attrNamesToImport = "*"
            custom timecode inputs:usdTimecode = nan
            rel inputs:prim = </World/Cube>
            custom double outputs:size
            custom double3 outputs:xformOp:translate
        }
        def OmniGraphNode "add"
        {
            token node:type = "omni.graph.nodes.Add"
            int node:typeVersion = 2
            custom token inputs:a
            prepend token inputs:a.connect = </World/ActionGraph/attrs.outputs:size>
            custom double inputs:b = 1
        }
        def OmniGraphNode "ctor"
        {
            token node:type = "omni.graph.nodes.BundleConstructor"
            int node:typeVersion = 1
            custom double inputs:speed = 2.5
            custom double inputs:total
            prepend double inputs:total.connect = </World/ActionGraph/add.outputs:sum>
            def Output "outputs_bundle"
            {
            }
        }
        def OmniGraphNode "total"
        {
            token node:type = "omni.graph.nodes.ExtractAttribute"
            int node:typeVersion = 1
            custom token inputs:attrName = "total"
            rel inputs:data = </World/ActionGraph/ctor/outputs_bundle>
        }
        def OmniGraphNode "read"
        {
            token node:type = "omni.graph.nodes.ReadPrimsV2"
            int node:typeVersion = 1
            rel inputs:prims = </World/Cube>
            def Output "outputs_primsBundle"
            {
            }
        }
        def OmniGraphNode "pick"
        {
            token node:type = "omni.graph.nodes.ExtractPrim"
            int node:typeVersion = 1
            custom string inputs:primPath = "/World/Cube"
            rel inputs:prims = </World/ActionGraph/read/outputs_primsBundle>
        }
        def OmniGraphNode "names"
        {
            token node:type = "omni.graph.nodes.GetAttributeNames"
            int node:typeVersion = 1
            rel inputs:data = </World/ActionGraph/pick.outputs:primBundle>
        }
        def OmniGraphNode "place"
        {
            token node:type = "omni.graph.nodes.ConstantDouble3"
            int node:typeVersion = 1
            custom double3 inputs:value = (0.5, 0, 2)
        }
        def OmniGraphNode "write"
        {
            token node:type = "omni.graph.nodes.WritePrim"
            int node:typeVersion = 4
            custom uint inputs:execIn (customData = {bool isExecution = 1})
            prepend uint inputs:execIn.connect = </World/ActionGraph/tick.outputs:tick>
            rel inputs:prim = </World/Cube>
            custom double3 inputs:xformOp:translate
            prepend double3 inputs:xformOp:translate.connect = </World/ActionGraph/place.inputs:value>
            custom double inputs:size = 3
        }
    }
}
'''


@pytest.fixture
def imported(tmp_path):
    path = tmp_path / "bundles.usda"
    path.write_text(STAGE)
    return import_graph(str(path)), str(path)


def test_dynamic_bundle_ports_become_extract_and_insert_nodes_each_named_once(imported):
    result, _ = imported
    types = {node.name: node.type for node in result.document.nodes}
    assert types["attrs_size"] == "omni.graph.nodes.ExtractAttribute"
    assert (types["ctor_speed"], types["ctor_total"]) == ("omni.graph.nodes.InsertAttribute",) * 2
    assert types["write_xformOp_translate"] == "omni.graph.nodes.InsertAttribute"
    connections = {(c.src, c.dst) for c in result.document.connections}
    assert {("attrs.outputs:primBundle", "attrs_size.inputs:data"), ("attrs_size.outputs:output", "add.inputs:a"),
            ("ctor.outputs:bundle", "ctor_speed.inputs:data"), ("ctor_speed.outputs:data", "ctor_total.inputs:data"),
            ("add.outputs:sum", "ctor_total.inputs:attrToInsert"), ("ctor_total.outputs:data", "total.inputs:data"),
            ("read.outputs:primsBundle", "pick.inputs:prims"), ("pick.outputs:primBundle", "names.inputs:data"),
            ("place.outputs:value", "write_xformOp_translate.inputs:attrToInsert"),
            ("write_xformOp_translate.outputs:data", "write.inputs:attributes")} <= connections
    lines = result.warnings
    for added in ("attrs_size", "ctor_speed", "ctor_total", "write_xformOp_translate"):
        assert sum(f"'{added}'" in line for line in lines) == 1
    assert any("node 'write' input 'inputs:size' = 3.0 is not connected" in line for line in lines)
    assert not any("dropped" in line and "size" not in line for line in lines), lines


def test_kits_nan_time_code_is_saved_as_strict_json_and_loads_back(imported, tmp_path):
    result, stage = imported
    saved = tmp_path / "bundles.json"
    save_document(result.document, saved)
    assert '"usdTimecode": "nan"' in saved.read_text()                 # graph files hold no NaN literal
    graph = GraphHarness(load_document(saved), world=create_world(stage))
    assert math.isnan(graph.instance.database("attrs").inputs.usdTimecode)


def test_the_imported_bundle_graph_runs_and_writes_the_cube(imported):
    result, stage = imported
    graph = GraphHarness(result.document, world=create_world(stage))
    graph.run(ticks=1)
    world = graph.world
    assert world.prim_pose("/World/Cube")[0] == pytest.approx((0.5, 0.0, 2.0), abs=1e-9)
    graph.instance.compute_node("total")
    assert graph.output("total", "output") == pytest.approx(1.2)       # the cube's size + 1, through the bundle
    graph.instance.compute_node("names")
    assert {"size", "xformOp:translate", "worldMatrix", "sourcePrimPath"} <= set(graph.output("names", "output"))
