"""Instanced graphs (omni.usd.schema.omnigraph): a graph that prims name in their omniGraphs relationship runs
once per such prim, its graph-target nodes and _OMNI_GRAPH_TARGET paths bound to that prim."""
from graphflow.testing import GraphHarness
from graphflow.usd.omnigraph import import_graph

STAGE = '''#usda 1.0
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
    token evaluationMode = "%s"
    def OmniGraphNode "target"
    {
        token node:type = "omni.graph.nodes.GraphTarget"
        int node:typeVersion = 1
    }
    def OmniGraphNode "prim"
    {
        token node:type = "omni.graph.nodes.GetGraphTargetPrim"
        int node:typeVersion = 1
    }
    def OmniGraphNode "paths"
    {
        token node:type = "omni.graph.nodes.ConstantPath"
        int node:typeVersion = 1
        custom string inputs:value = "/_OMNI_GRAPH_TARGET/child"
    }
}
'''


def _import(tmp_path, mode):
    stage = tmp_path / "instances.usda"
    stage.write_text(STAGE % mode)
    return import_graph(str(stage), output_path=str(tmp_path / "graph.json"))


def _computed(document):
    """A harness over *document* whose (pure) nodes have each computed once."""
    harness = GraphHarness(document)
    for node in document.nodes:
        harness.instance.compute_node(node.name)
    return harness


def test_an_automatic_graph_named_by_two_prims_runs_once_for_each(tmp_path):
    result = _import(tmp_path, "Automatic")
    names = sorted(node.name for node in result.document.nodes)
    assert names == ["A_paths", "A_prim", "A_target", "B_paths", "B_prim", "B_target"]
    assert any("imported once per target prim: /World/A, /World/B" in line for line in result.warnings)
    harness = _computed(result.document)
    assert [harness.output(f"{n}_target", "primPath") for n in "AB"] == ["/World/A", "/World/B"]
    assert [harness.output(f"{n}_prim", "prim") for n in "AB"] == [("/World/A",), ("/World/B",)]
    assert [harness.output(f"{n}_paths", "value") for n in "AB"] == ["/World/A/child", "/World/B/child"]


def test_a_standalone_graph_runs_once_for_itself_and_names_the_prims_it_ignores(tmp_path):
    result = _import(tmp_path, "Standalone")
    assert sorted(node.name for node in result.document.nodes) == ["paths", "prim", "target"]
    assert any("Standalone: the prims naming it (/World/A, /World/B) are ignored" in line for line in result.warnings)
    harness = _computed(result.document)
    assert harness.output("target", "primPath") == "/Graph"
