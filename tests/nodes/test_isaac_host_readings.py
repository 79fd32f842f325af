"""IsaacReadEnvVar and IsaacReadFilePath: host readings taken once per run, so a run repeats exactly; IsaacTestNode."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness, NodeHarness

ENV = "isaacsim.core.nodes.IsaacReadEnvVar"
FILE = "isaacsim.core.nodes.IsaacReadFilePath"


def test_env_var_is_read_when_the_run_starts_and_kept_for_the_run(monkeypatch):
    monkeypatch.setenv("ROS_DOMAIN_ID", "7")
    node = NodeHarness(ENV, {"envVar": "ROS_DOMAIN_ID"})
    assert node.compute().outputs["value"] == "7"
    monkeypatch.setenv("ROS_DOMAIN_ID", "12")           # changed while the run goes: the run keeps 7
    assert node.compute().outputs["value"] == "7"
    node.reset()                                         # a new run reads it again
    assert node.compute().outputs["value"] == "12"


def test_env_var_not_set_or_not_named_gives_the_empty_string_as_isaac(monkeypatch):
    monkeypatch.delenv("GRAPHFLOW_TEST_UNSET", raising=False)
    assert NodeHarness(ENV, {"envVar": "GRAPHFLOW_TEST_UNSET"}).compute().outputs["value"] == ""
    assert NodeHarness(ENV).compute().outputs["value"] == ""


def _file_graph(tmp_path, path):
    """A graph file in tmp_path whose printer pulls the file's contents every tick."""
    return GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "read", "type": FILE, "inputs": {"path": path}},
                  {"name": "print", "type": "omni.graph.ui_nodes.PrintText"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "print.inputs:execIn"},
                        {"src": "read.outputs:fileContents", "dst": "print.inputs:text"}],
    }, source=str(tmp_path / "graph.json"))


def test_file_path_is_read_relative_to_the_graph_files_folder(tmp_path):
    (tmp_path / "config").mkdir()
    (tmp_path / "config" / "domain.txt").write_text("ROS_DOMAIN_ID=7\n", encoding="utf-8")
    graph = _file_graph(tmp_path, "config/domain.txt")
    graph.run(1)
    assert graph.output("read", "fileContents") == "ROS_DOMAIN_ID=7\n"
    (tmp_path / "config" / "domain.txt").write_text("changed", encoding="utf-8")
    graph.run(1)                                         # read once per run
    assert graph.output("read", "fileContents") == "ROS_DOMAIN_ID=7\n"
    absolute = _file_graph(tmp_path / "elsewhere", str(tmp_path / "config" / "domain.txt"))
    absolute.run(1)
    assert absolute.output("read", "fileContents") == "changed"


def test_a_missing_file_fails_the_run_naming_the_node_and_path(tmp_path):
    graph = _file_graph(tmp_path, "missing.txt")
    with pytest.raises(GraphRuntimeError) as failure:
        graph.run(1)
    assert failure.value.node == "read" and f"no file {tmp_path / 'missing.txt'}" in str(failure.value)


def test_an_empty_path_gives_the_empty_string_with_a_warning():
    node = NodeHarness(FILE)
    assert node.compute().outputs["fileContents"] == ""
    assert any("inputs:path is empty" in line for line in node.logs)


def test_isaac_test_node_echoes_its_input_only_when_pulsed():
    """Isaac's test probe: the output is the input as of the last execIn, not a live copy."""
    graph = GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "probe", "type": "omni.isaac.core_nodes.IsaacTestNode", "inputs": {"input": "ready"}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "probe.inputs:execIn"}],
    })
    assert graph.output("probe", "output") == ""
    graph.run(1)
    assert graph.output("probe", "output") == "ready"
    graph.instance.set_input("probe", "input", "changed")
    assert graph.output("probe", "output") == "ready"
    graph.run(1)
    assert graph.output("probe", "output") == "changed"
