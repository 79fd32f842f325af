"""Compiling: a document is checked and built in one pass, and only a valid one becomes a compiled graph."""
import pytest

import graphflow_nodes
from graphflow.compiler import compile
from graphflow.document import (
    Connection,
    GraphDocument,
    GraphError,
    NodeDoc,
    parse_document,
)
from graphflow.registry import Registry
from graphflow.runtime import Simulation


class _CountingRegistry(Registry):
    """The built-in node types, counting how often each type name is resolved."""

    def __init__(self):
        super().__init__()
        self.lookups: dict[str, int] = {}

    def get(self, type_id):
        self.lookups[type_id] = self.lookups.get(type_id, 0) + 1
        return super().get(type_id)


COUNTER = {"format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.5},
           "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                     {"name": "counter", "type": "omni.graph.action.Counter"},
                     {"name": "limit", "type": "omni.graph.nodes.Compare", "inputs": {"b": 3, "operation": ">="}}],
           "connections": [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                           {"src": "counter.outputs:count", "dst": "limit.inputs:a"}]}


def test_loading_and_running_resolve_each_node_type_once():
    registry = _CountingRegistry()
    registry.register_package(graphflow_nodes)
    document = parse_document(COUNTER, "counter.json", registry)
    simulations = [Simulation(document, registry=registry) for _ in range(3)]
    simulations[0].run(ticks=4)
    assert registry.lookups == {"omni.graph.action.OnTick": 1, "omni.graph.action.Counter": 1,
                                "omni.graph.nodes.Compare": 1}
    assert simulations[0].instance.output("counter", "count") == 4


def test_simulations_of_one_document_share_its_compiled_graph():
    document = parse_document(COUNTER, "counter.json")
    first, second = Simulation(document), Simulation(document, instances=2)
    assert first.compiled is second.compiled is compile(document)
    second.run(ticks=2)
    assert [instance.output("counter", "count") for instance in second.instances] == [2, 2]
    assert first.instance.output("counter", "count") == 0


def test_a_document_built_in_code_is_checked_before_it_runs():
    document = GraphDocument(nodes=(NodeDoc("tick", "omni.graph.action.OnTick"),
                                    NodeDoc("gate", "omni.graph.action.Branch", inputs={"condition": "yes"})),
                             connections=(Connection("tick", "outputs:tick", "ghost", "inputs:execIn"),),
                             source="built.py")
    with pytest.raises(GraphError) as caught:
        Simulation(document)
    assert [str(problem) for problem in caught.value.problems] == [
        "built.py: node 'gate' input 'inputs:condition': expected bool, got \"yes\"",
        "built.py: node 'ghost' connection 'inputs:execIn': dangling connection "
        "tick.outputs:tick -> ghost.inputs:execIn: no node named 'ghost'"]
