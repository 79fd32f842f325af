"""Bundle nodes of files written by older omni.graph.nodes releases, in the .usda form Kit saves them.

From the extension's changelog: ReadPrims of 1.82.6-1.89 searched under ``rootPrims`` (that node is ReadPrimsV2
since 1.90, its roots renamed ``prims``); WritePrims of 1.83.4-1.87 wrote to target prims (``parentPrims``,
renamed ``prims`` in 1.86; WritePrimsV2 since 1.88); ReadPrim before version 6 read every attribute when
``attrNamesToImport`` was empty (its updateNodeVersion rewrites "" to "*").
"""
import pytest

from graphflow.registry import default_registry
from graphflow.runtime import create_world
from graphflow.testing import GraphHarness
from graphflow.usd.node_eras import ERAS
from graphflow.usd.omnigraph import ImportProblem, import_graph

STAGE = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def Cube "Cube"
    {
        double size = 0.2
        double3 xformOp:translate = (1, 2, 3)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def PhysicsScene "physicsScene"
    {
    }
    def Cube "Target" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
    {
        double size = 1
        float physics:mass = 1
        double3 xformOp:translate = (0, 0, 0)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        int2 fileFormatVersion = (1, 5)
        def OmniGraphNode "tick"
        {
            token node:type = "omni.graph.action.OnTick"
            int node:typeVersion = 1
            custom bool inputs:onlyPlayback = 0
        }
        def OmniGraphNode "read"
        {
            token node:type = "omni.graph.nodes.ReadPrims"
            int node:typeVersion = 3
            custom string inputs:pathPattern = "/World/Cube"
            custom bool inputs:useFindPrims = 1
            rel inputs:rootPrims = </World>
            def Output "outputs_primsBundle"
            {
            }
        }
        def OmniGraphNode "write"
        {
            token node:type = "omni.graph.nodes.WritePrims"
            int node:typeVersion = 1
            custom uint inputs:execIn
            prepend uint inputs:execIn.connect = </World/ActionGraph/tick.outputs:tick>
            custom string inputs:attrNamesToExport = "xformOp:translate"
            WRITE_TARGETS
            rel inputs:primsBundle = </World/ActionGraph/read/outputs_primsBundle>
        }
        def OmniGraphNode "one"
        {
            token node:type = "omni.graph.nodes.ReadPrim"
            int node:typeVersion = 5
            custom token inputs:attrNamesToImport = ""
            rel inputs:prim = </World/Cube>
            def Output "outputs_primBundle"
            {
            }
        }
        def OmniGraphNode "names"
        {
            token node:type = "omni.graph.nodes.GetAttributeNames"
            int node:typeVersion = 1
            rel inputs:data = </World/ActionGraph/one/outputs_primBundle>
        }
    }
}
'''
KIT_1_86 = "custom bool inputs:scatterUnderTargets = 0\n            rel inputs:prims = </World/Target>"
KIT_1_83 = "rel inputs:parentPrims = </World/Target>"


def imported(tmp_path, targets):
    path = tmp_path / "old_bundles.usda"
    path.write_text(STAGE.replace("WRITE_TARGETS", targets))
    return import_graph(str(path)), str(path)


def test_the_1_86_era_nodes_load_as_the_v2_nodes_kit_moved_them_to_with_one_line_each(tmp_path):
    result, _ = imported(tmp_path, KIT_1_86)
    nodes = {node.name: node for node in result.document.nodes}
    assert nodes["read"].type == "omni.graph.nodes.ReadPrimsV2" and nodes["write"].type == "omni.graph.nodes.WritePrimsV2"
    assert dict(nodes["read"].inputs) == {"pathPattern": "/World/Cube", "prims": ["/World"]}
    assert nodes["write"].inputs["prims"] == ["/World/Target"]
    assert nodes["one"].inputs["attrNamesToImport"] == "*"
    lines = result.warnings
    assert sum("node 'read'" in line for line in lines) == 1 and sum("node 'one'" in line for line in lines) == 1
    assert any("node 'read': omni.graph.nodes.ReadPrims with inputs:rootPrims is the node of omni.graph.nodes "
               "1.82.6-1.89, which Kit now names omni.graph.nodes.ReadPrimsV2: loaded as omni.graph.nodes.ReadPrimsV2 "
               "(inputs:rootPrims -> inputs:prims, inputs:useFindPrims dropped)" in line for line in lines), lines
    assert any("node 'one': inputs:attrNamesToImport \"\" -> \"*\"" in line for line in lines)


def test_the_mapped_graph_finds_under_the_roots_writes_the_target_and_reads_every_attribute(tmp_path):
    result, stage = imported(tmp_path, KIT_1_86)
    graph = GraphHarness(result.document, world=create_world(stage))
    graph.run(ticks=1)
    assert graph.world.prim_pose("/World/Target")[0] == pytest.approx((1.0, 2.0, 3.0), abs=1e-9)            # the cube found under /World, written there
    graph.instance.compute_node("names")
    assert "size" in graph.output("names", "output")                 # "" read every attribute before version 6


def test_the_1_83_era_parent_prims_map_to_exporting_under_targets_which_is_refused_with_its_one_line(tmp_path):
    with pytest.raises(ImportProblem) as refused:
        imported(tmp_path, KIT_1_83)
    assert "node 'write'" in str(refused.value) and "scatterUnderTargets" in str(refused.value)


@pytest.mark.parametrize("old_id", sorted(ERAS))
def test_every_era_names_a_node_type_graphflow_implements(old_id):
    registry = default_registry()
    assert registry.get(old_id) is not None
    for era in ERAS[old_id]:
        spec = registry.get(era.now).spec
        assert all(new is None or spec.attribute(new) is not None for new in era.renames.values())
