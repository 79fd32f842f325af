"""Issue 26 item 5, the edges of values and check semantics, reproduced as a user meets them (CLI, exit code, one line).

Non-finite numbers where a spec's range makes them meaningless, check times a run cannot honour.
"""
import json

import pytest
from conftest import GRAPHS

from graphflow import cli

TUNED = GRAPHS / "ur10_pick_place_tuned.json"     # has a graphflow.LegacySurfaceGripper named 'gripper'
PICK_PLACE = GRAPHS / "ur10_pick_place.json"


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def one_line(err: str, *needles: str) -> str:
    lines = err.splitlines()
    assert len(lines) == 1, lines
    assert "unexpected error" not in err and "Traceback" not in err
    for needle in needles:
        assert needle in lines[0], (needle, lines[0])
    return lines[0]


def copy_graph(source, folder, edit) -> str:
    """*source* edited by *edit(data)*, written into *folder* with its stage path made absolute."""
    data = json.loads(source.read_text(encoding="utf-8"))
    stage = data["settings"]["stage"]
    if stage.startswith("asset:"):
        from graphflow.usd.resolver import resolve_stage
        data["settings"]["stage"] = str(resolve_stage(stage, source.parent))
    edit(data)
    path = folder / source.name
    path.write_text(json.dumps(data), encoding="utf-8")
    return str(path)


# ---------------------------------------------------------------- 1. non-finite values

@pytest.mark.parametrize("value", ["nan", "1e400", "inf", "-inf", '"nan"', '"inf"'])
def test_set_a_non_finite_value_on_a_ranged_input_is_refused_at_load(value, capsys):
    code, out, err = run_cli(capsys, "run", TUNED, "--ticks", "3", "--set", f"gripper.kp={value}")
    assert code == 2 and out == ""
    one_line(err, f"--set gripper.kp={value}", "node 'gripper' input 'kp'", "is not a finite number",
             "the range >= 0")


@pytest.mark.parametrize("value", ["nan", "inf", "1e400"])
def test_a_non_finite_string_coerced_to_a_ranged_double_is_refused_by_validate_and_run(value, tmp_path, capsys):
    def kp_as_text(data):
        next(n for n in data["nodes"] if n["name"] == "gripper")["inputs"]["kp"] = value
    path = copy_graph(TUNED, tmp_path, kp_as_text)
    for command in ("validate", "run"):
        code, _out, err = run_cli(capsys, command, path)
        assert code == 2
        if value == "1e400":     # not one of the spellings of a non-finite double: a type error
            one_line(err, path, "node 'gripper'", "inputs:kp", "expected double")
        else:
            one_line(err, path, "node 'gripper'", "inputs:kp", f"value {value} is not a finite number")


def test_unranged_doubles_still_take_nan_as_written():
    """NaN leaves a joint alone where a node reads it so (docs/errors.md): only a declared range refuses it."""
    from graphflow.spec import Attribute
    assert str(Attribute("x", "double").check("nan")) == "nan"
    with pytest.raises(ValueError, match="not a finite number"):
        Attribute("x", "double", minimum=0.0).check(float("nan"))
    with pytest.raises(ValueError, match="range 0 to 1"):
        Attribute("x", "double[]", minimum=0.0, maximum=1.0).check([0.5, float("inf")])


@pytest.mark.parametrize("value", ["nan", "inf", "1e400", "-1"])
def test_set_of_a_stage_attribute_refuses_non_finite_and_negative_mass(value, capsys):
    code, out, err = run_cli(capsys, "run", PICK_PLACE, "--ticks", "3", "--set", f"/World/Cube.physics:mass={value}")
    assert code == 2 and out == ""
    one_line(err, f"--set /World/Cube.physics:mass={value}", "/World/Cube.physics:mass")


# ---------------------------------------------------------------- 2. check semantics

def test_a_held_check_whose_window_ends_before_it_starts_is_refused_naming_the_check(tmp_path, capsys):
    def swap(data):
        held = next(c for c in data["checks"] if c["check"] == "held")
        held["from"], held["to"], held["name"] = 16.8, 8.2, "carried"
    path = copy_graph(PICK_PLACE, tmp_path, swap)
    for command in ("validate", "run"):
        code, _out, err = run_cli(capsys, command, path)
        assert code == 2
        one_line(err, path, "checks[3] (held, 'carried'): from 16.8 s is after to 8.2 s")


@pytest.mark.parametrize("check", [
    {"check": "position", "prim": "/World/Cube", "position": [0.7, 0.7, 0.026], "tolerance": 0.01, "at": 45},
    {"check": "held", "gripper": "/World/ur10/ee_link/SurfaceGripper", "from": 31},
    {"check": "held", "gripper": "/World/ur10/ee_link/SurfaceGripper", "from": 1, "to": 40},
    {"check": "stopsBy", "time": 31.5},
])
def test_a_check_time_after_the_run_ends_is_refused_naming_the_check(check, tmp_path, capsys):
    key = next(k for k in ("at", "to", "time", "from") if isinstance(check.get(k), (int, float)) and check[k] > 30)

    def add(data):
        assert data["settings"]["duration"] == 30.0
        data["checks"].append(check)
    path = copy_graph(PICK_PLACE, tmp_path, add)
    code, _out, err = run_cli(capsys, "validate", path)
    assert code == 2
    one_line(err, path, f"checks[7] ({check['check']}): {key} {check[key]:g} s is after the run ends "
                        "(settings/duration 30 s)")


# ---------------------------------------------------------------- 10. strict JSON: where

GRAPH_WITH_A_FLAW = '''{
  "format": "graphflow",
  "formatVersion": [1, 0],
  "nodes": [
    {"name": "tick", "type": "omni.graph.action.OnTick"},
    {"name": "grip", "type": "graphflow.LegacySurfaceGripper",
     "inputs": {"kp": 100.0, "kd": FLAW}}
  ]
}
'''


@pytest.mark.parametrize("flaw, column, path, reason", [
    ("NaN", 36, "nodes/1/inputs/kd, node 'grip'", "NaN is not a JSON value (RFC 8259 has no NaN or Infinity)"),
    ("-Infinity", 36, "nodes/1/inputs/kd, node 'grip'", "-Infinity is not a JSON value"),
    ("1e999", 36, "nodes/1/inputs/kd, node 'grip'", "number 1e999 is too large"),
    ('1, "kp": 2', 39, "nodes/1/inputs/kp, node 'grip'", 'duplicate key "kp" in one object'),
])
def test_a_strict_json_refusal_names_line_column_key_path_and_node(flaw, column, path, reason, tmp_path, capsys):
    graph = tmp_path / "flawed.json"
    graph.write_text(GRAPH_WITH_A_FLAW.replace("FLAW", flaw), encoding="utf-8")
    for command in ("validate", "run"):
        code, _out, err = run_cli(capsys, command, graph)
        assert code == 2
        one_line(err, f"{graph}: invalid JSON at line 7 column {column} ({path}): {reason}")


def test_a_flaw_outside_the_nodes_names_the_key_path_only(tmp_path, capsys):
    graph = tmp_path / "flawed.json"
    graph.write_text('{"format": "graphflow", "formatVersion": [1, 0], "nodes": [],\n "settings": {"timeStep": NaN}}')
    code, _out, err = run_cli(capsys, "validate", graph)
    assert code == 2
    one_line(err, f"{graph}: invalid JSON at line 2 column 27 (settings/timeStep): NaN is not a JSON value")


# ---------------------------------------------------------------- 9. trace diff on a deeply nested trace

def test_trace_diff_on_a_deeply_nested_trace_is_exit_2_naming_the_line(tmp_path, capsys):
    header = json.dumps({"format": "graphflow-trace", "version": 1, "graph": "g.json", "nodes": {}})
    shallow, deep = tmp_path / "shallow.jsonl", tmp_path / "deep.jsonl"
    shallow.write_text(header + '\n{"tick": 1, "t": 0.5, "outputs": {"x": [[1]]}}\n', encoding="utf-8")
    deep.write_text(header + '\n{"tick": 1, "t": 0.5, "outputs": {"x": ' + "[" * 100_000 + "]" * 100_000 + "}}\n",
                    encoding="utf-8")
    for left, right in ((deep, shallow), (shallow, deep)):
        code, out, err = run_cli(capsys, "trace", "diff", left, right)
        assert code == 2 and out == ""       # 1 would read as "the traces differ"
        one_line(err, f"{deep}: line 2 is not JSON", "nested more than 64 levels deep")
