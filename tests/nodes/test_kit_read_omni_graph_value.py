"""omni.graph.nodes.ReadOmniGraphValue: another node's attribute, or a prim's, read by name."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness
from graphflow.testing.fake_world import FakeWorld
from graphflow.usd.omnigraph import import_graph


def counting_graph(path, name, world=None):
    """A counter pulsed every tick, and a ReadOmniGraphValue whose value a variable keeps after each count."""
    return GraphHarness({
        "variables": [{"name": "seen", "type": "any"}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "counter", "type": "omni.graph.action.Counter"},
            {"name": "peek", "type": "omni.graph.nodes.ReadOmniGraphValue", "inputs": {"path": path, "name": name}},
            {"name": "keep", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "seen"}},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
            {"src": "counter.outputs:execOut", "dst": "keep.inputs:execIn"},
            {"src": "peek.outputs:value", "dst": "keep.inputs:value"},
        ],
    }, world=world)


def test_reads_another_nodes_output_without_a_connection():
    graph = counting_graph("counter", "outputs:count")
    graph.run(ticks=3)
    assert graph.instance.variables["seen"] == 3      # the counter computed 3 times before each read
    graph = counting_graph("counter", "state:count")
    graph.run(ticks=2)
    assert graph.instance.variables["seen"] == 2


def test_reads_a_prims_attribute_by_its_path():
    world = FakeWorld()
    world.add_box("/World/Cube", (0.0, 0.0, 0.25), (0.1, 0.1, 0.1))
    world.set_attribute("/World/Cube", "mass", 2.5)
    graph = counting_graph("/World/Cube", "mass", world=world)
    graph.run(ticks=1)
    assert graph.instance.variables["seen"] == 2.5


@pytest.mark.parametrize("path, name, reason", [
    ("countr", "outputs:count", "no node named 'countr'"),
    ("counter", "outputs:total", "has no attribute 'outputs:total'"),
    ("", "outputs:count", "inputs:path is empty"),
])
def test_what_is_not_there_fails_the_run_naming_it(path, name, reason):
    with pytest.raises(GraphRuntimeError, match=f"node 'peek'.*{reason}"):
        counting_graph(path, name).run(ticks=1)


def test_import_names_the_node_kit_addresses_by_its_path(tmp_path):
    stage = tmp_path / "peek.usda"
    stage.write_text('''#usda 1.0
def Xform "World"
{
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        def OmniGraphNode "counter"
        {
            token node:type = "omni.graph.action.Counter"
            int node:typeVersion = 1
        }
        def OmniGraphNode "peek"
        {
            token node:type = "omni.graph.nodes.ReadOmniGraphValue"
            int node:typeVersion = 1
            custom token inputs:name = "outputs:count"
            custom string inputs:path = "/World/ActionGraph/counter"
        }
    }
}
''')
    assert import_graph(str(stage)).document.node("peek").inputs == {"name": "outputs:count", "path": "counter"}


def test_in_a_file_of_several_graphs_the_path_names_the_prefixed_node(tmp_path):
    graph = '''
    def OmniGraph "{name}"
    {{
        token evaluator:type = "execution"
        def OmniGraphNode "counter"
        {{
            token node:type = "omni.graph.action.Counter"
            int node:typeVersion = 1
        }}
        def OmniGraphNode "peek"
        {{
            token node:type = "omni.graph.nodes.ReadOmniGraphValue"
            int node:typeVersion = 1
            custom token inputs:name = "outputs:count"
            custom string inputs:path = "/World/{name}/counter"
        }}
    }}'''
    stage = tmp_path / "two.usda"
    stage.write_text('#usda 1.0\ndef Xform "World"\n{' + graph.format(name="Left") + graph.format(name="Right") + "\n}\n")
    nodes = import_graph(str(stage)).document.nodes
    peeks = {node.name: node.inputs["path"] for node in nodes if node.type.endswith("ReadOmniGraphValue")}
    counters = {node.name for node in nodes if node.type.endswith("Counter")}
    assert len(peeks) == 2 and set(peeks.values()) == counters
    assert all(peek.replace("peek", "counter") == path for peek, path in peeks.items())
