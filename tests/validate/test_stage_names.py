"""graphflow validate against the stage a graph names: prims, kinds, joints, attributes; wiring warnings."""
import json
import subprocess
import sys

from conftest import ROOT

from graphflow.document import load_document
from graphflow.validate.stage_names import deep_validate

PICK_PLACE = ROOT / "graphs" / "ur10_pick_place.json"


def _variant(tmp_path, edit, name="variant.json"):
    graph = json.loads(PICK_PLACE.read_text())
    edit(graph)
    path = tmp_path / name
    path.write_text(json.dumps(graph))
    return path


def _node(graph, name):
    return next(node for node in graph["nodes"] if node["name"] == name)


def _problems(path):
    errors, warnings = deep_validate(load_document(path))
    return [str(p) for p in errors], [str(p) for p in warnings]


def test_every_shipped_graph_is_clean():
    graphs = [path for path in sorted((ROOT / "graphs").rglob("*.json"))   # graph documents, not input timelines
              if json.loads(path.read_text(encoding="utf-8")).get("format") == "graphflow"]
    assert len(graphs) >= 8
    for path in graphs:
        assert _problems(path) == ([], []), path


def test_a_misspelled_gripper_prim_is_caught_with_a_suggestion(tmp_path):
    path = _variant(tmp_path, lambda g: _node(g, "gripper")["inputs"].update(
        SurfaceGripper="/World/ur10/ee_link/SurfaceGriper"))
    errors, _ = _problems(path)
    assert errors == [f"{path}: node 'gripper' input 'inputs:SurfaceGripper': no prim /World/ur10/ee_link/SurfaceGriper "
                      "on the stage (did you mean /World/ur10/ee_link/SurfaceGripper?)"]


def test_prims_of_the_wrong_kind_are_caught(tmp_path):
    def edit(graph):
        _node(graph, "pick_place")["inputs"].update(gripperPrim="/World/Cube", robotPrim="/World/Cube")
    errors, _ = _problems(_variant(tmp_path, edit))
    assert [e.split(": ", 2)[2] for e in errors] == [
        "/World/Cube is a Cube prim, not a surface gripper (surface grippers on the stage: /World/ur10/ee_link/SurfaceGripper)",
        "/World/Cube is not part of an articulation"]


def test_a_missing_joint_of_an_articulation_controller_is_caught(tmp_path):
    def edit(graph):
        graph["nodes"].append({"name": "arm", "type": "isaacsim.core.nodes.IsaacArticulationController",
                               "inputs": {"robotPath": "/World/ur10", "jointNames": ["shoulder_pan_joint", "elbow_jiont"]}})
        graph["connections"].append({"src": "on_tick.outputs:tick", "dst": "arm.inputs:execIn"})
    path = _variant(tmp_path, edit)
    errors, warnings = _problems(path)
    assert errors == [f"{path}: node 'arm' input 'inputs:jointNames': articulation /World/ur10 has no joint "
                      "'elbow_jiont' (did you mean 'elbow_joint'?)"]
    assert warnings == []


def test_attribute_names_and_check_prims_get_did_you_mean(tmp_path):
    def edit(graph):
        graph["nodes"].append({"name": "mass", "type": "omni.graph.nodes.ReadPrimAttribute",
                               "inputs": {"prim": "/World/Cube", "name": "physics:mas"}})
        graph["checks"] = [{"check": "upright", "prim": "/World/Cub", "within": 1.0}]
    path = _variant(tmp_path, edit)
    errors, warnings = _problems(path)
    assert errors == [
        f"{path}: node 'mass' input 'inputs:name': /World/Cube has no attribute 'physics:mas' (did you mean 'physics:mass'?)",
        f"{path}: checks[1] (upright): no prim /World/Cub on the stage (did you mean /World/Cube?)"]
    assert warnings == [f"{path}: node 'mass': computes for nothing: no connection reads its outputs"]


def test_exec_nodes_that_can_never_run_are_warnings(tmp_path):
    def edit(graph):
        graph["nodes"].append({"name": "orphan", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "never"}})
    path = _variant(tmp_path, edit)
    assert _problems(path) == ([], [f"{path}: node 'orphan': never runs: no event source reaches its exec inputs"])


def test_validate_command_missing_stage_and_usd_syntax_error_without_running(tmp_path):
    missing = _variant(tmp_path, lambda g: g["settings"].update(stage="scene.usda"), "missing.json")
    broken_stage = tmp_path / "broken.usda"
    broken_stage.write_text('#usda 1.0\n\ndef Xform "World"\n{\n    double3 xformOp:translate = (0, 0,\n}\n')
    broken = _variant(tmp_path, lambda g: g["settings"].update(stage="broken.usda"), "broken.json")
    result = subprocess.run([sys.executable, "-m", "graphflow", "validate", str(missing), str(broken), str(PICK_PLACE)],
                            capture_output=True, text=True)
    assert result.returncode == 2
    assert result.stdout.splitlines() == [f"{PICK_PLACE}: ok"]
    missing_line, broken_line = result.stderr.splitlines()   # the very lines `run` prints for them
    assert missing_line == f"{missing}: settings/stage: {tmp_path / 'scene.usda'}: no such stage file"
    assert broken_line.startswith(f"{broken}: settings/stage: {broken_stage}: not a USD stage ({broken_stage}:6:1: ")
    assert "at '}' in </World.xformOp:translate>" in broken_line and "pxrInternal" not in broken_line
    loaded = subprocess.run(        # usd-core only: validating never loads the physics engine
        [sys.executable, "-c", "import sys; from graphflow.validate.stage_names import deep_validate; "
                               "from graphflow.document import load_document; "
                               f"deep_validate(load_document({str(PICK_PLACE)!r})); "
                               "print(sorted(m for m in sys.modules if 'bullet' in m))"],
        capture_output=True, text=True)
    assert loaded.stdout == "[]\n", loaded.stderr


def test_an_unknown_input_name_gets_did_you_mean(tmp_path):
    path = _variant(tmp_path, lambda g: _node(g, "pick_place")["inputs"].update(placingPositon=[0, 0, 0]))
    result = subprocess.run([sys.executable, "-m", "graphflow", "validate", str(path)], capture_output=True, text=True)
    assert result.returncode == 2
    assert result.stderr.strip() == (f"{path}: node 'pick_place' input 'inputs:placingPositon': graphflow.PickPlaceController "
                                     "has no such input (did you mean 'placingPosition'?)")


def test_a_robot_from_a_reference_that_does_not_open_is_named_as_the_likely_cause(tmp_path):
    (tmp_path / "scene.usda").write_text('#usda 1.0\n\ndef Xform "robot" (\n    prepend references = @robot_missing.usda@\n)\n{\n}\n')
    graph = {"format": "graphflow", "formatVersion": [1, 0], "settings": {"stage": "scene.usda"},
             "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                       {"name": "arm", "type": "isaacsim.core.nodes.IsaacArticulationController",
                        "inputs": {"targetPrim": "/robot"}}],
             "connections": [{"src": "tick.outputs:tick", "dst": "arm.inputs:execIn"}]}
    path = tmp_path / "graph.json"
    path.write_text(json.dumps(graph))
    assert _problems(path) == ([f"{path}: node 'arm' input 'inputs:targetPrim': /robot is not part of an articulation "
                                "(/robot takes its content from a reference or payload: does that file open?)"], [])


def test_the_attributes_validation_accepts_are_the_worlds():
    from graphflow.physics import ATTRIBUTES
    from graphflow.validate.stage_names import (
        WORLD_BODY_ATTRIBUTES,
        WORLD_JOINT_ATTRIBUTES,
    )

    assert sorted(WORLD_BODY_ATTRIBUTES + WORLD_JOINT_ATTRIBUTES) == sorted(ATTRIBUTES)


def test_kits_ignored_variable_graph_input_is_not_checked_on_the_stage(tmp_path):
    """ReadVariable/WriteVariable v2 inputs:graph is ignored by Kit (the graph's own variable is used): a script
    that names its graph's path there (no prim of the stage) validates; a real prim input still does not."""
    def edit(graph):
        graph.setdefault("variables", []).append({"name": "speed", "type": "float", "default": 1.0})
        graph["nodes"].append({"name": "read_speed", "type": "omni.graph.core.ReadVariable",
                               "inputs": {"variableName": "speed", "graph": ["/World/ConveyorGraph"]}})
    assert _problems(_variant(tmp_path, edit))[0] == []


def test_a_relationship_target_may_be_a_property_but_must_exist(tmp_path):
    """AddPrimRelationship's target may name a prim, an attribute or a relationship (Kit's reference)."""
    def edit(graph, target):
        graph["nodes"].append({"name": "tag", "type": "omni.graph.action.AddPrimRelationship",
                               "inputs": {"path": "/World/Cube", "name": "custom:tags", "target": target}})
        graph["connections"].append({"src": "on_tick.outputs:tick", "dst": "tag.inputs:execIn"})

    for good in ("/World/Cube.physics:mass", "/World/ur10/root_joint.physics:body1", "/World/ur10"):
        errors, _ = _problems(_variant(tmp_path, lambda g: edit(g, good)))
        assert errors == [], good
    errors, _ = _problems(_variant(tmp_path, lambda g: edit(g, "/World/Cube.nothing")))
    assert [e.split(": ", 2)[2] for e in errors] == ["no prim /World/Cube.nothing on the stage (did you mean /World/Cube?)"]
