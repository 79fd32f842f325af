"""An import that degrades: missing layers, any node version, graph variables, several graphs in one file.

Each test writes a small stage in Isaac's format and goes through the CLI as a
user would (import -> validate -> run).
"""
import json

import pytest

from graphflow.cli import main

MISSING_ROBOT = '''#usda 1.0
def Xform "Robot" (
    prepend payload = @https://example.invalid/robots/arm.usd@
)
{
}
def OmniGraph "Graph"
{
    def OmniGraphNode "tick"
    {
        token node:type = "omni.graph.action.OnPlaybackTick"
        int node:typeVersion = 2
    }
    def OmniGraphNode "counter"
    {
        token node:type = "omni.graph.action.Counter"
        int node:typeVersion = 1
        prepend uint inputs:execIn.connect = </Graph/tick.outputs:tick>
    }
    def OmniGraphNode "gate"
    {
        token node:type = "omni.graph.nodes.Compare"
        int node:typeVersion = 1
        custom token inputs:operation = ">="
        prepend token inputs:a.connect = </Graph/counter.outputs:count>
        custom int inputs:b = 10
    }
    def OmniGraphNode "branch"
    {
        token node:type = "omni.graph.action.Branch"
        int node:typeVersion = 1
        prepend uint inputs:execIn.connect = </Graph/counter.outputs:execOut>
        prepend bool inputs:condition.connect = </Graph/gate.outputs:result>
    }
    def OmniGraphNode "controller"
    {
        token node:type = "isaacsim.core.nodes.IsaacArticulationController"
        int node:typeVersion = 1
        custom rel inputs:targetPrim = </Robot/base_link>
        prepend uint inputs:execIn.connect = </Graph/branch.outputs:execTrue>
    }
}
'''
LINE = ("node 'controller' input 'inputs:targetPrim': prim /Robot/base_link is not in the stage: it comes from "
        "https://example.invalid/robots/arm.usd (referenced at /Robot), which cannot be opened")


def _import(tmp_path, text, capsys, *extra):
    stage = tmp_path / "scene.usda"
    stage.write_text(text)
    graph = tmp_path / "graph.json"
    code = main(["import", str(stage), "-o", str(graph), *extra])
    return code, graph, capsys.readouterr().err


def test_a_target_in_a_layer_that_cannot_be_opened_is_kept_and_named_once(tmp_path, capsys):
    code, graph, err = _import(tmp_path, MISSING_ROBOT, capsys)
    assert code == 0, err
    assert [line for line in err.splitlines() if "controller" in line] == [f"warning: {tmp_path / 'scene.usda'}: {LINE}"]
    node = next(n for n in json.loads(graph.read_text())["nodes"] if n["name"] == "controller")
    assert node["inputs"]["targetPrim"] == ["/Robot/base_link"]


def test_validate_reports_the_missing_layer_unless_allowed(tmp_path, capsys):
    _import(tmp_path, MISSING_ROBOT, capsys)
    assert main(["validate", str(tmp_path / "graph.json")]) == 2
    assert capsys.readouterr().err.splitlines() == [   # the stage's one line for the layer (graphflow.usd.opening)
        f"{tmp_path / 'graph.json'}: settings/stage: {tmp_path / 'scene.usda'}: cannot open "
        "https://example.invalid/robots/arm.usd, the payload of /Robot in layer scene.usda: prims lost: everything "
        "that payload puts below /Robot (map its URL prefix to a local folder in graphflow.toml [assets.remap] or "
        "GRAPHFLOW_ASSET_REMAP)"]
    assert main(["validate", "--allow-missing-assets", str(tmp_path / "graph.json")]) == 0
    assert f"warning: {tmp_path / 'graph.json'}: {LINE}" in capsys.readouterr().err.splitlines()


def test_run_goes_on_until_the_first_compute_that_needs_the_missing_prim(tmp_path, capsys):
    _import(tmp_path, MISSING_ROBOT, capsys)
    # the branch opens at the 10th tick: ticks 1-9 run the counter, the 10th reaches the controller
    assert main(["run", str(tmp_path / "graph.json"), "--ticks", "9"]) == 0
    capsys.readouterr()
    assert main(["run", str(tmp_path / "graph.json"), "--ticks", "30"]) == 1
    err = capsys.readouterr().err
    assert f"run-time failure: {LINE}" in err
    assert "(10 ticks," in err


def test_a_robot_path_token_under_a_missing_layer_degrades_like_a_target(tmp_path, capsys):
    """Isaac's path inputs (robotPath, primPath with usePath) name prims as targets do (Isaac's Basic Robot tutorial)."""
    text = MISSING_ROBOT.replace("custom rel inputs:targetPrim = </Robot/base_link>",
                                 'custom token inputs:robotPath = "/Robot"')
    code, graph, err = _import(tmp_path, text, capsys)
    assert code == 0, err
    line = ("node 'controller' input 'inputs:robotPath': prim /Robot has no definition: it comes from "
            "https://example.invalid/robots/arm.usd (referenced at /Robot), which cannot be opened")
    assert f"warning: {tmp_path / 'scene.usda'}: {line}" in err.splitlines()
    assert main(["run", str(graph), "--ticks", "9"]) == 0
    capsys.readouterr()
    assert main(["run", str(graph), "--ticks", "30"]) == 1
    assert f"run-time failure: {line}" in capsys.readouterr().err


VERSIONS = '''#usda 1.0
def OmniGraph "Graph"
{
    def OmniGraphNode "tick"
    {
        token node:type = "omni.graph.action.OnPlaybackTick"
        int node:typeVersion = 1
    }
    def OmniGraphNode "key"
    {
        token node:type = "omni.graph.action.OnKeyboardInput"
        int node:typeVersion = 4
        custom token inputs:keyIn = "W"
    }
    def OmniGraphNode "counter"
    {
        token node:type = "omni.graph.action.Counter"
        int node:typeVersion = 7
        custom bool inputs:futureSwitch = true
        prepend uint inputs:execIn.connect = </Graph/tick.outputs:tick>
        prepend uint inputs:futureExec.connect = </Graph/key.outputs:pressed>
    }
}
'''


def test_any_type_version_loads_as_graphflows_with_one_line_each(tmp_path, capsys):
    code, graph, err = _import(tmp_path, VERSIONS, capsys)
    assert code == 0, err
    lines = err.splitlines()
    assert any("node 'tick': typeVersion 1 of omni.graph.action.OnPlaybackTick is older than graphflow's 2: "
               "loaded as version 2" in line for line in lines)
    assert any("node 'key': typeVersion 4 of omni.graph.action.OnKeyboardInput is newer than graphflow's 3: "
               "loaded as version 3 (its ports all exist there)" in line for line in lines)
    assert any("node 'counter': typeVersion 7 of omni.graph.action.Counter is newer than graphflow's 1: loaded as "
               "version 1; ports not in version 1: inputs:futureExec, inputs:futureSwitch (dropped)" in line
               for line in lines)
    assert any("connection from /Graph/key.outputs:pressed dropped: graphflow's omni.graph.action.Counter has no "
               "port 'inputs:futureExec'" in line for line in lines)
    nodes = {n["name"]: n for n in json.loads(graph.read_text())["nodes"]}
    assert (nodes["tick"]["typeVersion"], nodes["key"]["typeVersion"], nodes["counter"]["typeVersion"]) == (2, 3, 1)
    assert main(["run", str(graph), "--ticks", "5"]) == 0


def test_a_removed_port_of_an_old_version_is_named(tmp_path, capsys):
    code, graph, err = _import(tmp_path, '''#usda 1.0
def Xform "Arm"
{
}
def OmniGraph "Graph"
{
    def OmniGraphNode "joints"
    {
        token node:type = "isaacsim.ros2.bridge.ROS2SubscribeJointState"
        int node:typeVersion = 1
        custom rel inputs:targetPrim = </Arm>
    }
}
''', capsys)
    assert code == 0, err
    # Isaac's updateNodeVersion removes targetPrim from a version 1 node: one line says so, the value is not kept
    expected = (f"warning: {tmp_path / 'scene.usda'}: node 'joints': typeVersion 1 of "
                "isaacsim.ros2.bridge.ROS2SubscribeJointState is older than graphflow's 2: loaded as version 2 "
                "(mapped: inputs:targetPrim removed)")
    assert [line for line in err.splitlines() if "joints" in line] == [expected]
    node = json.loads(graph.read_text())["nodes"][0]
    assert node["typeVersion"] == 2 and "inputs" not in node


VARIABLES = '''#usda 1.0
def OmniGraph "Graph"
{
    custom double graph:variable:Speed = 0.75
    custom double3 graph:variable:Offset = (1, 2, 3)
    custom token graph:variable:Mode = "drive"
    def OmniGraphNode "tick"
    {
        token node:type = "omni.graph.action.OnTick"
        int node:typeVersion = 1
    }
    def OmniGraphNode "speed"
    {
        token node:type = "omni.graph.core.ReadVariable"
        int node:typeVersion = 2
        custom token inputs:variableName = "Speed"
    }
    def OmniGraphNode "assert"
    {
        token node:type = "graphflow.Assert"
        int node:typeVersion = 1
        prepend uint inputs:execIn.connect = </Graph/tick.outputs:tick>
        prepend bool inputs:condition.connect = </Graph/positive.outputs:result>
    }
    def OmniGraphNode "positive"
    {
        token node:type = "omni.graph.nodes.Compare"
        int node:typeVersion = 1
        custom token inputs:operation = "=="
        prepend token inputs:a.connect = </Graph/speed.outputs:value>
        custom double inputs:b = 0.75
    }
}
'''


def test_graph_variables_on_the_graph_prim_import_with_types_and_defaults(tmp_path, capsys):
    code, graph, err = _import(tmp_path, VARIABLES, capsys)
    assert code == 0, err
    variables = {v["name"]: v for v in json.loads(graph.read_text())["variables"]}
    assert variables == {"Speed": {"name": "Speed", "type": "double", "default": 0.75},
                         "Offset": {"name": "Offset", "type": "double[3]", "default": [1.0, 2.0, 3.0]},
                         "Mode": {"name": "Mode", "type": "token", "default": "drive"}}
    assert main(["run", str(graph), "--ticks", "3"]) == 0, capsys.readouterr().err


def test_a_file_with_several_graphs_imports_each_with_its_own_names(tmp_path, capsys):
    second = VARIABLES.replace('def OmniGraph "Graph"', 'def OmniGraph "Other"').replace("</Graph/", "</Other/")
    second = second.replace("graph:variable:Speed = 0.75", "graph:variable:Speed = 2.0").replace(
        "inputs:b = 0.75", "inputs:b = 2.0").split("\n", 1)[1]
    code, graph, err = _import(tmp_path, VARIABLES + second, capsys)
    assert code == 0, err
    data = json.loads(graph.read_text())
    names = {n["name"] for n in data["nodes"]}
    assert {"Graph_tick", "Other_tick", "Graph_speed", "Other_speed"} <= names
    speeds = {n["name"]: n["inputs"]["variableName"] for n in data["nodes"] if n["name"].endswith("_speed")}
    assert speeds == {"Graph_speed": "Graph_Speed", "Other_speed": "Other_Speed"}
    defaults = {v["name"]: v["default"] for v in data["variables"] if v["name"].endswith("Speed")}
    assert defaults == {"Graph_Speed": 0.75, "Other_Speed": 2.0}
    # both graphs run: each asserts its own variable's default
    assert main(["run", str(graph), "--ticks", "3"]) == 0, capsys.readouterr().err


ISAAC_4X = '''#usda 1.0
def OmniGraph "Graph"
{
    custom double graph:variable:Speed = 0.5
    def OmniGraphNode "tick"
    {
        token node:type = "omni.graph.action.OnPlaybackTick"
        int node:typeVersion = 1
    }
    def OmniGraphNode "speed"
    {
        token node:type = "omni.graph.core.ReadVariable"
        int node:typeVersion = 1
        custom token inputs:variableName = "Speed"
    }
    def OmniGraphNode "to_meters"
    {
        token node:type = "omni.isaac.core_nodes.OgnIsaacScaleToFromStageUnit"
        int node:typeVersion = 1
        custom token inputs:conversion = "Convert to meters"
        prepend token inputs:value.connect = </Graph/speed.outputs:value>
    }
    def OmniGraphNode "drive"
    {
        token node:type = "omni.isaac.wheeled_robots.DifferentialController"
        int node:typeVersion = 1
        custom double inputs:angularVelocity = 0.2
        custom double inputs:wheelRadius = 0.1
        custom double inputs:wheelDistance = 0.4
        prepend uint inputs:execIn.connect = </Graph/tick.outputs:tick>
        prepend double inputs:linearVelocity.connect = </Graph/to_meters.outputs:result>
    }
}
'''


def test_a_graph_of_isaac_4x_ids_and_old_versions_imports_and_runs(tmp_path, capsys):
    from graphflow.document import load_document
    from graphflow.testing import GraphHarness

    code, graph, err = _import(tmp_path, ISAAC_4X, capsys)
    assert code == 0, err
    assert "typeVersion 1 of omni.graph.action.OnPlaybackTick is older than graphflow's 2" in err
    harness = GraphHarness(load_document(graph))
    harness.run(3)
    # the stage has no metersPerUnit: USD's fallback is centimetres, so 0.5 stage units are 0.005 m;
    # wheels (v -/+ w d / 2) / r
    v = 0.5 * 0.01
    assert harness.output("drive", "velocityCommand") == pytest.approx(((v - 0.04) / 0.1, (v + 0.04) / 0.1))
