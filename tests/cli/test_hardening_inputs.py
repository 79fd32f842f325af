"""Issue 15, classes 1-3: strict JSON, typed values, and `validate` refusing exactly what `run` refuses.

Every bad input is one line on stderr naming the file (and node, attribute, key or prim), exit
code 2, never the last-resort "unexpected error" and never a traceback.
"""
import json
import math
import os
from pathlib import Path

import pytest
from conftest import ROOT

from graphflow import cli
from graphflow.document import GraphError, load_document, parse_document
from graphflow.files import FileProblem, loads_strict

ON_TICK = {"name": "tick", "type": "omni.graph.action.OnTick"}


def graph(**fields) -> dict:
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": [ON_TICK], **fields}


def run_cli(capsys, *args):
    code = cli.main(list(args))
    out, err = capsys.readouterr()
    return code, out, err


def assert_one_clear_line(err: str, *needles: str) -> None:
    lines = err.splitlines()
    assert len(lines) == 1, lines
    assert "unexpected error" not in err and "Traceback" not in err
    for needle in needles:
        assert needle in lines[0], (needle, lines[0])


# ---------------------------------------------------------------- 1. strict JSON

VALID_HEAD = '{"format": "graphflow", "formatVersion": [1, 0], "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]'
STRICT_JSON_CASES = {
    "nan_literal": (VALID_HEAD + ', "settings": {"timeStep": NaN}}', "NaN is not a JSON value"),
    "infinity_literal": (VALID_HEAD + ', "settings": {"duration": Infinity}}', "Infinity is not a JSON value"),
    "minus_infinity": (VALID_HEAD + ', "settings": {"duration": -Infinity}}', "-Infinity is not a JSON value"),
    "duplicate_key": (VALID_HEAD + ', "settings": {"timeStep": 0.1, "timeStep": 0.2}}', 'duplicate key "timeStep"'),
    "double_overflow": (VALID_HEAD + ', "settings": {"duration": 1e999}}', "number 1e999 is too large"),
    "huge_integer": (VALID_HEAD + ', "settings": {"substeps": ' + "9" * 500 + '}}', "integer with 500 digits"),
    "deep_nesting": ("[" * 10_000 + "]" * 10_000, "nested more than 64 levels"),
    "lone_surrogate": ('{"format": "graphflow\\ud800", "formatVersion": [1, 0], "nodes": []}', "lone surrogate"),
}


@pytest.mark.parametrize("case", sorted(STRICT_JSON_CASES))
def test_json_outside_rfc_8259_is_one_line_exit_2(case, tmp_path, capsys):
    text, reason = STRICT_JSON_CASES[case]
    path = tmp_path / f"{case}.json"
    path.write_text(text, encoding="utf-8")
    for command in ("validate", "run"):
        code, _out, err = run_cli(capsys, command, str(path))
        assert code == 2
        assert_one_clear_line(err, str(path), reason)


def test_non_utf8_file_names_the_line(tmp_path, capsys):
    path = tmp_path / "latin1.json"
    path.write_bytes(b'{"format": "graphflow",\n "description": "caf\xe9"}')
    code, _out, err = run_cli(capsys, "validate", str(path))
    assert code == 2
    assert_one_clear_line(err, str(path), "not UTF-8 text (byte 0xe9 on line 2)")


def test_folder_is_refused_before_reading(tmp_path, capsys):
    code, _out, err = run_cli(capsys, "run", str(tmp_path))
    assert code == 2
    assert_one_clear_line(err, str(tmp_path), "is a folder, not a file")


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_endless_device_is_refused_without_reading_it(capsys):
    # reading /dev/zero never ends: the type of file is checked first
    code, _out, err = run_cli(capsys, "validate", "/dev/zero")
    assert code == 2
    assert_one_clear_line(err, "/dev/zero", "not a regular file")


def test_strict_reader_accepts_every_shipped_graph():
    for path in sorted((ROOT / "graphs").glob("*.json")):
        data = loads_strict(path.read_text(encoding="utf-8"), str(path))
        assert data == json.loads(path.read_text(encoding="utf-8"))


def test_duplicate_key_error_names_the_key_and_file():
    with pytest.raises(FileProblem) as caught:
        loads_strict('{"a": 1, "b": {"x": 1, "x": 2}}', "twice.json")
    assert str(caught.value) == 'twice.json: invalid JSON at line 1 column 24 (b/x): duplicate key "x" in one object'


# ---------------------------------------------------------------- 2. values

def problems_of(data: dict) -> list[str]:
    with pytest.raises(GraphError) as caught:
        parse_document(data, "g.json")
    return [str(p) for p in caught.value.problems]


@pytest.mark.parametrize("type_name, fits, too_big", [
    ("uint", 2**32 - 1, 2**32),          # OmniGraph's uint is 32-bit
    ("int", 2**31 - 1, 2**31),
    ("int64", 2**63 - 1, 2**63),
    ("uint64", 2**64 - 1, 2**64),
])
def test_integers_must_fit_their_type(type_name, fits, too_big):
    parse_document(graph(variables=[{"name": "v", "type": type_name, "default": fits}]), "g.json")
    assert problems_of(graph(variables=[{"name": "v", "type": type_name, "default": too_big}])) == [
        f"g.json: variable 'v': default: expected {type_name} ({-(2**31) if type_name == 'int' else -(2**63) if type_name == 'int64' else 0}"
        f" to {fits}), got {too_big}"]


def test_float_is_32_bit():
    parse_document(graph(variables=[{"name": "v", "type": "float", "default": 3.0e38}]), "g.json")
    [problem] = problems_of(graph(variables=[{"name": "v", "type": "float", "default": 1e39}]))
    assert "expected float (magnitude up to 3.40282e+38), got 1e+39" in problem


@pytest.mark.parametrize("name, value", [("timeStep", math.nan), ("duration", math.inf), ("duration", math.nan)])
def test_non_finite_settings_are_errors(name, value):
    # JSON files cannot hold these any more; documents built in Python still can
    assert problems_of(graph(settings={name: value})) == [f"g.json: settings/{name}: {value!r} is not a finite number"]


def test_a_duration_that_would_never_end_is_an_error(tmp_path, capsys):
    path = tmp_path / "forever.json"
    path.write_text(json.dumps(graph(settings={"duration": 1e308})))
    code, _out, err = run_cli(capsys, "run", str(path))   # used to overflow computing the tick count
    assert code == 2
    assert_one_clear_line(err, f"{path}: settings/duration: 1e+308 s is more than 1e+07 simulated seconds")


def test_a_variable_of_execution_type_is_an_error():
    assert problems_of(graph(variables=[{"name": "pulse", "type": "execution"}])) == [
        "g.json: variable 'pulse': a variable cannot be of execution type (exec pulses are not values)"]


def test_node_name_with_a_newline_is_reported_on_one_line(tmp_path, capsys):
    path = tmp_path / "newline.json"
    path.write_text(json.dumps(graph(nodes=[{"name": "evil\nname", "type": "omni.graph.action.OnTick"}])))
    code, _out, err = run_cli(capsys, "validate", str(path))
    assert code == 2
    assert_one_clear_line(err, "node 'evil\\nname'", "is not a name")


def test_infinite_authored_joint_target_is_refused_nan_is_not():
    arm = {"name": "arm", "type": "isaacsim.core.nodes.IsaacArticulationController",
           "inputs": {"robotPath": "/World/ur10", "positionCommand": ["inf", 0, 0, 0, 0, 0]}}
    [problem] = problems_of(graph(nodes=[ON_TICK, arm]))
    assert problem.startswith("g.json: node 'arm': inputs:positionCommand: ") and "infinite target" in problem
    # NaN leaves a joint alone (documented): still accepted
    arm["inputs"]["positionCommand"] = ["nan", 0, 0, 0, 0, 0]
    parse_document(graph(nodes=[ON_TICK, arm]), "g.json")


# ---------------------------------------------------------------- 3. validate = run's load

BAD_PHYSICS_STAGE = """#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Xform "World"
{
    def Cube "Heavy" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
    {
        float physics:mass = -2
        double size = 0.1
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Cube "Flat" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"])
    {
        double size = 0
        double3 xformOp:translate = (1, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def Cube "Lost" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"])
    {
        double size = 0.1
        double3 xformOp:translate = (nan, 0, inf)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
}
"""


def write_graph_on_stage(tmp_path, stage_text: str | None, name="scene.usda", **fields) -> Path:
    if stage_text is not None:
        (tmp_path / name).write_text(stage_text)
    path = tmp_path / "graph.json"
    path.write_text(json.dumps(graph(settings={"stage": name}, **fields)))
    return path


def test_stage_with_negative_mass_zero_box_and_nan_transform_lists_all_three(tmp_path, capsys):
    path = write_graph_on_stage(tmp_path, BAD_PHYSICS_STAGE)
    stage = tmp_path / "scene.usda"
    expected = [
        f"{path}: settings/stage: {stage}: /World/Heavy: physics:mass is -2.0; a mass must be a finite number >= 0",
        f"{path}: settings/stage: {stage}: /World/Flat: a collider box of zero or invalid size (size 0.0)",
        f"{path}: settings/stage: {stage}: /World/Lost: its transform is not finite (NaN or infinity in an xformOp)",
    ]
    code, out, err = run_cli(capsys, "validate", str(path))
    assert (code, out, err.splitlines()) == (2, "", expected)
    # run refuses the same stage with the same lines, before the first tick
    code, out, err = run_cli(capsys, "run", str(path))
    assert (code, out, err.splitlines()) == (2, "", [f"graphflow: error: {line}" for line in expected])


@pytest.mark.parametrize("stage_text, reason", [
    (None, "no such stage file"),
    ('#usda 1.0\ndef Xform "World" {\n  def Cube "C" { double size = \n}\n', "scene.usda:3:18: Expected }"),
    ("this is not usd\n", "not a USD stage"),
])
def test_missing_or_unreadable_stage_is_refused_by_validate_and_run_alike(tmp_path, capsys, stage_text, reason):
    path = write_graph_on_stage(tmp_path, stage_text)
    code, _out, validate_err = run_cli(capsys, "validate", str(path))
    assert code == 2
    assert_one_clear_line(validate_err, str(path), "settings/stage", reason)
    assert "pxrInternal" not in validate_err
    code, _out, run_err = run_cli(capsys, "run", str(path))
    assert code == 2
    assert run_err == f"graphflow: error: {validate_err}"


def test_problems_of_every_kind_are_listed_at_once(tmp_path, capsys):
    path = write_graph_on_stage(
        tmp_path, BAD_PHYSICS_STAGE,
        nodes=[{"name": "tick", "type": "omni.graph.action.OnTick", "colour": "red"},   # schema
               {"name": "count", "type": "omni.graph.action.Countr"},                  # semantics
               {"name": "say", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": 5}}])
    code, _out, err = run_cli(capsys, "validate", str(path))
    lines = err.splitlines()
    assert code == 2
    assert lines[0] == f"{path}: node 'tick': nodes/0: Additional properties are not allowed ('colour' was unexpected)"
    assert lines[1] == (f"{path}: node 'count': unknown node type 'omni.graph.action.Countr' "
                        f"(did you mean 'omni.graph.action.Counter'?)")
    assert lines[2] == f"{path}: node 'say' input 'inputs:text': expected string, got 5"
    assert [line.split(": ")[3] for line in lines[3:]] == ["/World/Heavy", "/World/Flat", "/World/Lost"]


def test_shipped_graphs_still_validate(capsys):
    paths = [str(p) for p in sorted((ROOT / "graphs").glob("*.json"))   # graph documents, not input timelines
             if json.loads(p.read_text(encoding="utf-8")).get("format") == "graphflow"]
    code, out, err = run_cli(capsys, "validate", *paths)
    assert (code, err) == (0, "")
    assert out.splitlines() == [f"{p}: ok" for p in paths]


def test_load_document_reports_file_problems_as_graph_errors(tmp_path):
    with pytest.raises(GraphError) as caught:
        load_document(tmp_path / "absent.json")
    assert [str(p) for p in caught.value.problems] == [f"{tmp_path / 'absent.json'}: file not found"]
