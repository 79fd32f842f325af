"""Issue 26: a node whose required ``target`` input is unset is warned about by ``validate`` and ``import``.

Without the warning such a graph validated and then failed at its first tick.
"""
import json

from conftest import GRAPHS

from graphflow import cli

TUNED = GRAPHS / "ur10_pick_place_tuned.json"
WARNING = ("required target is unset (neither authored nor connected): the node has no prim to work on and "
           "fails at its first compute")

POSE_READER_STAGE = '''#usda 1.0
def Xform "World"
{
    def Cube "Box" {}
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        def OmniGraphNode "on_tick"
        {
            token node:type = "omni.graph.action.OnTick"
            int node:typeVersion = 1
            custom uint outputs:tick (customData = {bool isExecution = 1})
        }
        def OmniGraphNode "pose"
        {
            token node:type = "isaacsim.core.nodes.IsaacReadWorldPose"
            int node:typeVersion = 1
        }
        def OmniGraphNode "boxed"
        {
            token node:type = "isaacsim.core.nodes.IsaacReadWorldPose"
            int node:typeVersion = 1
            custom rel inputs:prim = </World/Box>
        }
    }
}
'''


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    assert "unexpected error" not in err and "Traceback" not in err
    return code, out, err


def test_validate_warns_about_the_unset_end_effector_that_run_then_fails_on(tmp_path, capsys):
    from graphflow.usd.resolver import resolve_stage

    data = json.loads(TUNED.read_text(encoding="utf-8"))
    data["settings"]["stage"] = str(resolve_stage(data["settings"]["stage"], TUNED.parent))
    del next(n for n in data["nodes"] if n["name"] == "gripper")["inputs"]["endEffectorPrim"]
    path = tmp_path / "no_end_effector.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    code, out, err = run_cli(capsys, "validate", path)
    assert code == 0 and out == f"{path}: ok\n"
    assert err.splitlines() == [f"warning: {path}: node 'gripper' input 'inputs:endEffectorPrim': {WARNING}"]
    code, _out, err = run_cli(capsys, "run", path)
    assert code == 1 and "node 'gripper': inputs:endEffectorPrim: no end effector given" in err


def test_the_shipped_graphs_have_no_unset_target(capsys):
    paths = [p for p in sorted(GRAPHS.glob("*.json")) + sorted(GRAPHS.glob("scenarios/*.json"))
             if not p.name.endswith((".keys.json", ".topics.json"))]
    code, _out, err = run_cli(capsys, "validate", *paths)
    assert code == 0 and "required target is unset" not in err


def test_import_warns_about_the_unset_target_and_not_the_set_one(tmp_path, capsys):
    stage = tmp_path / "scene.usda"
    stage.write_text(POSE_READER_STAGE, encoding="utf-8")
    code, _out, err = run_cli(capsys, "import", stage, "-o", tmp_path / "graph.json")
    assert code == 0
    assert [line for line in err.splitlines() if "required target" in line] == [
        f"warning: {stage}: /World/ActionGraph: node 'pose' input 'inputs:prim': {WARNING}"]


def test_an_alternative_path_input_counts_as_the_target(tmp_path, capsys):
    data = {"format": "graphflow", "formatVersion": [1, 0],
            "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                      {"name": "state", "type": "isaacsim.core.nodes.IsaacArticulationState",
                       "inputs": {"robotPath": "/ur10"}}],
            "connections": [{"src": "tick.outputs:tick", "dst": "state.inputs:execIn"}]}
    path = tmp_path / "g.json"
    path.write_text(json.dumps(data), encoding="utf-8")
    code, _out, err = run_cli(capsys, "validate", path)
    assert code == 0 and "required target" not in err
