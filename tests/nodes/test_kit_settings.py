"""omni.graph.nodes ReadSetting / WriteSetting: a settings store local to the run."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness


def settings_graph(value, path="/app/gain", read_path="/app/gain"):
    return GraphHarness({
        "variables": [{"name": "seen", "type": "any"}],
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "write", "type": "omni.graph.nodes.WriteSetting", "inputs": {"settingPath": path, "value": value}},
            {"name": "read", "type": "omni.graph.nodes.ReadSetting", "inputs": {"settingPath": read_path}},
            {"name": "keep", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "seen"}},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "write.inputs:execIn"},
            {"src": "write.outputs:execOut", "dst": "keep.inputs:execIn"},
            {"src": "read.outputs:value", "dst": "keep.inputs:value"},
        ],
    })


@pytest.mark.parametrize("value", [2.5, 7, True, "fast", (1.0, 2.0, 3.0), ("a", "b")])
def test_a_written_setting_reads_back_in_the_same_run(value):
    graph = settings_graph(value)
    graph.run(ticks=1)
    assert graph.instance.variables["seen"] == value


def test_a_setting_never_written_fails_the_run_naming_node_and_path():
    graph = settings_graph(2.5, read_path="/app/gian")
    with pytest.raises(GraphRuntimeError, match=r"node 'read'.*setting '/app/gian' was never written"):
        graph.run(ticks=1)


def test_a_setting_keeps_its_type_and_the_store_empties_on_reset():
    graph = settings_graph(2.5)
    graph.run(ticks=1)
    graph.instance.set_input("write", "value", "fast")
    with pytest.raises(GraphRuntimeError, match=r"node 'write'.*'/app/gain' holds a float, not a string"):
        graph.run(ticks=1)
    graph.reset()   # a new run: the store starts empty, so the string is the setting's first value
    graph.instance.set_input("write", "value", "fast")
    graph.run(ticks=1)
    assert graph.instance.variables["seen"] == "fast"
