"""omni.graph.core.ReadVariable / WriteVariable."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness


def _accumulator_graph():
    # every tick: total = total + 1.5 (ReadVariable -> Add -> WriteVariable)
    return GraphHarness({
        "variables": [{"name": "total", "type": "double", "default": 1.0}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "read", "type": "omni.graph.core.ReadVariable", "inputs": {"variableName": "total"}},
            {"name": "add", "type": "omni.graph.nodes.Add", "inputs": {"b": 1.5}},
            {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "total"}},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
            {"src": "read.outputs:value", "dst": "add.inputs:a"},
            {"src": "add.outputs:sum", "dst": "write.inputs:value"},
        ],
    })


def test_read_modify_write_accumulates_across_ticks():
    g = _accumulator_graph()
    g.run(ticks=3)
    assert g.instance.variables["total"] == pytest.approx(5.5)
    assert g.output("write", "value") == pytest.approx(5.5)  # passed through


def test_graph_reset_restores_variable_default():
    g = _accumulator_graph()
    g.run(ticks=2)
    g.reset()
    assert g.instance.variables["total"] == 1.0
    g.run(ticks=1)
    assert g.instance.variables["total"] == pytest.approx(2.5)


def test_write_variable_fires_exec_out_and_read_sees_new_value_same_tick():
    g = GraphHarness({
        "variables": [{"name": "msg", "type": "string", "default": "old"}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "write", "type": "omni.graph.core.WriteVariable",
             "inputs": {"variableName": "msg", "value": "new"}},
            {"name": "read", "type": "omni.graph.core.ReadVariable", "inputs": {"variableName": "msg"}},
            {"name": "print", "type": "omni.graph.ui_nodes.PrintText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
            {"src": "write.outputs:execOut", "dst": "print.inputs:execIn"},
            {"src": "read.outputs:value", "dst": "print.inputs:text"},
        ],
    })
    g.run(ticks=1)
    assert g.logs == ["new"]


def test_unknown_variable_is_a_runtime_error_naming_it():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "write", "type": "omni.graph.core.WriteVariable",
             "inputs": {"variableName": "nope", "value": 1}},
        ],
        "connections": [{"src": "tick.outputs:tick", "dst": "write.inputs:execIn"}],
    })
    with pytest.raises(GraphRuntimeError, match="nope"):
        g.run(ticks=1)


def _write_graph(value):
    return GraphHarness({
        "variables": [{"name": "speed", "type": "double", "default": 0.0}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "write", "type": "omni.graph.core.WriteVariable",
             "inputs": {"variableName": "speed", **({} if value is None else {"value": value})}},
        ],
        "connections": [{"src": "tick.outputs:tick", "dst": "write.inputs:execIn"}],
    })


def test_written_value_is_converted_to_the_variable_type():
    g = _write_graph(3)
    g.run(ticks=1)
    assert g.instance.variables["speed"] == 3.0 and type(g.instance.variables["speed"]) is float
    assert type(g.output("write", "value")) is float


@pytest.mark.parametrize("value, message", [(None, "inputs:value has no value"),
                                            ("fast", "does not fit graph variable 'speed'")])
def test_unset_or_mistyped_value_is_a_clear_error(value, message):
    with pytest.raises(GraphRuntimeError, match=message):
        _write_graph(value).run(ticks=1)


def test_kits_ignored_graph_and_target_path_inputs_leave_the_graphs_own_variable_in_use():
    """ReadVariable/WriteVariable v2 declare inputs:graph and inputs:targetPath as ignored (Kit's node library)."""
    g = GraphHarness({
        "variables": [{"name": "speed", "type": "float", "default": 0.5}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "read", "type": "omni.graph.core.ReadVariable",
             "inputs": {"variableName": "speed", "graph": ["/World/Other/Graph"], "targetPath": "/World/Other"}},
            {"name": "add", "type": "omni.graph.nodes.Add", "inputs": {"b": 0.25}},
            {"name": "write", "type": "omni.graph.core.WriteVariable",
             "inputs": {"variableName": "speed", "graph": ["/World/Other/Graph"], "targetPath": "/World/Other"}},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
            {"src": "read.outputs:value", "dst": "add.inputs:a"},
            {"src": "add.outputs:sum", "dst": "write.inputs:value"},
        ],
    })
    g.run(ticks=2)
    assert g.instance.variables["speed"] == pytest.approx(1.0)
