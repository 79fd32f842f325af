"""Simulation listeners: every tick, compute, log line and the end of a run reach them, in order."""
import pytest

from graphflow.document import parse_document
from graphflow.executor import GraphRuntimeError
from graphflow.runtime import Simulation

COUNTING = {"format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.25},
            "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                      {"name": "counter", "type": "omni.graph.action.Counter"},
                      {"name": "say", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "hi"}}],
            "connections": [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                            {"src": "counter.outputs:execOut", "dst": "say.inputs:execIn"}]}


class Recorder:
    def __init__(self, name, heard):
        self.name, self.heard = name, heard

    def on_tick(self, simulation, tick):
        self.heard.append((self.name, "tick", tick, simulation.world.time))

    def on_compute(self, instance, node_name, fired, db):
        self.heard.append((self.name, "compute", node_name, tuple(fired)))

    def on_log(self, event):
        self.heard.append((self.name, "log", event.tick, event.message))

    def on_end(self, simulation, result):
        self.heard.append((self.name, "end", None if result is None else (result.ticks, result.stopped_by_graph)))


def test_listeners_hear_computes_logs_ticks_and_the_end_in_order():
    heard = []
    simulation = Simulation(parse_document(COUNTING), listeners=[Recorder("a", heard)])
    simulation.add_listener(Recorder("b", heard))
    simulation.run(ticks=2)
    first_tick = [
        ("a", "compute", "tick", ("tick",)), ("b", "compute", "tick", ("tick",)),
        ("a", "compute", "counter", ("execOut",)), ("b", "compute", "counter", ("execOut",)),
        ("a", "log", 1, "hi"), ("b", "log", 1, "hi"),
        ("a", "compute", "say", ("execOut",)), ("b", "compute", "say", ("execOut",)),
        ("a", "tick", 1, 0.25), ("b", "tick", 1, 0.25)]
    assert heard[:10] == first_tick
    assert heard[-4:] == [("a", "tick", 2, 0.5), ("b", "tick", 2, 0.5), ("a", "end", (2, False)), ("b", "end", (2, False))]


def test_a_listener_with_only_some_methods_hears_those():
    lines = []
    simulation = Simulation(parse_document(COUNTING), instances=2,
                            listeners=[type("Lines", (), {"on_log": staticmethod(lambda e: lines.append(e.message))})()])
    simulation.run(ticks=3)
    assert lines == ["hi"] * 6        # both instances, three ticks


def test_the_end_is_heard_when_a_node_fails_and_the_failure_propagates():
    heard = []
    failing = dict(COUNTING, nodes=[*COUNTING["nodes"][:2], {"name": "say", "type": "omni.graph.core.WriteVariable",
                                                              "inputs": {"variableName": "missing"}}])
    simulation = Simulation(parse_document(failing), listeners=[Recorder("a", heard)])
    with pytest.raises(GraphRuntimeError, match="node 'say'"):
        simulation.run(ticks=5)
    assert [entry for entry in heard if entry[1] in ("tick", "end")] == [("a", "end", None)]
