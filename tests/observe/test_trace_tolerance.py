"""Golden traces with tolerances: trace diff --tolerance, the matchesTrace check and test --update-golden.

The synthetic traces differ by known amounts, so each bound is checked against the difference put in; the
physics cases check the documented claims: a one-ulp change of every IK solution stays within the default
tolerances and a 1 % heavier cube does not."""
import dataclasses
import json
import math
import re

import pytest
from conftest import ROOT

from graphflow import cli
from graphflow.observe.trace import parse_trace
from graphflow.observe.trace_tolerance import Bound, ToleranceError, Tolerances, tolerances_from, tolerant_difference

GOLDEN_SCENARIO = ROOT / "graphs" / "scenarios" / "tuned_pick_place_golden.json"


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def trace_text(z_values, *, pulses=("on_tick.tick",), status="Open", force=None) -> str:
    """A pose reader's z per tick (a value equal to the previous one is not written, as the recorder does)."""
    header = {"format": "graphflow-trace", "version": 1, "graph": "g.json", "timeStep": 0.5,
              "nodes": {"on_tick": "omni.graph.action.OnTick", "pose": "graphflow.ReadPrimPose",
                        "pick": "graphflow.PickPlaceController"},
              "outputs": {"pose.position": [0.0, 0.0, 0.0], "pick.eventName": ""}, "phases": ["pick.eventName"],
              "grippers": ["/G"], "versions": {"python": "3.11"}}
    lines, previous = [json.dumps(header)], None
    for tick, z in enumerate(z_values, start=1):
        record = {"tick": tick, "t": tick * 0.5, "pulses": list(pulses)}
        if z != previous:
            record["outputs"] = {"pose.position": [0.4, 0.4, z], **({"pick.eventName": "lift"} if tick == 1 else {})}
        if tick == 1:
            record["grippers"] = {"/G": {"status": status, "gripped": [], "force": force, "heldZ": None, "reason": ""}}
        previous = z
        lines.append(json.dumps(record))
    return "\n".join(lines) + "\n"


def diff(left, right, tolerances=Tolerances()):
    return tolerant_difference(parse_trace(left), parse_trace(right), tolerances)


def test_a_change_within_the_position_bound_matches_even_where_only_one_trace_wrote_it():
    # B's tick 2 moved by 5e-8 m: B writes a record, A (unchanged) does not; carried state compares them
    assert diff(trace_text([0.1, 0.1, 0.1]), trace_text([0.1, 0.1 + 5e-8, 0.1])) is None


def test_beyond_the_position_bound_names_field_tick_phase_and_gripper():
    found = diff(trace_text([0.1, 0.1, 0.1]), trace_text([0.1, 0.1, 0.1 + 3e-7]))
    assert (found.tick, found.field, found.phase) == (3, "outputs.pose.position[2]", "lift")
    assert found.grippers == ("/G Open",) and found.bound == "positions tolerance 1e-07 m"
    assert math.isclose(abs(found.right - found.left), 3e-7, rel_tol=1e-6)


def test_exact_fields_stay_exact_whatever_the_tolerance():
    loose = tolerances_from(1.0, "test")
    assert diff(trace_text([0.1]), trace_text([0.1], pulses=("on_tick.tick", "x.execOut")), loose).field == "pulses"
    found = diff(trace_text([0.1]), trace_text([0.1], status="Closed"), loose)
    assert (found.field, found.bound) == ("grippers./G.status", "")


def test_per_field_bounds_and_relative_force_bounds():
    tolerances = tolerances_from({"fields": {"pose.position": 1e-3}, "forces": {"absolute": 0, "relative": 0.01}}, "t")
    assert diff(trace_text([0.1]), trace_text([0.1 + 5e-4]), tolerances) is None
    assert diff(trace_text([0.1], force=100.0), trace_text([0.1], force=100.9), tolerances) is None   # 0.9 % of 100 N
    assert diff(trace_text([0.1], force=100.0), trace_text([0.1], force=101.1), tolerances).field == "grippers./G.force"
    assert Bound(0.0, 0.01).allows(100.0, 100.9) and not Bound(0.0, 0.01).allows(100.0, 101.1)


@pytest.mark.parametrize("spec, message", [
    (-1.0, "t: expected a non-negative number"),
    ({"lengths": 1}, "t: unknown key 'lengths'"),
    ({"fields": {"pose.position": "big"}}, "t: fields.pose.position: expected a non-negative number")])
def test_bad_tolerances_say_which(spec, message):
    with pytest.raises(ToleranceError) as caught:
        tolerances_from(spec, "t")
    assert str(caught.value).startswith(message)


def test_trace_diff_tolerance_exit_codes(tmp_path, capsys):
    a, b, c = tmp_path / "a.jsonl", tmp_path / "b.jsonl", tmp_path / "c.jsonl"
    a.write_text(trace_text([0.1, 0.1]))
    b.write_text(trace_text([0.1, 0.1 + 1e-12]))
    c.write_text(trace_text([0.1, 0.2]))
    assert run_cli(capsys, "trace", "diff", a, b)[0] == 1                       # exact: the last bits differ
    assert run_cli(capsys, "trace", "diff", a, b, "--tolerance") == (0, "traces match within tolerance (2 ticks)\n", "")
    code, out, _ = run_cli(capsys, "trace", "diff", a, c, "--tolerance")
    assert code == 1 and out.splitlines()[0] == ("traces differ at tick 2 (t = 1.0 s), field outputs.pose.position[2] "
                                                 "(beyond positions tolerance 1e-07 m):")
    assert run_cli(capsys, "trace", "diff", a, c, "--tolerance", "0.2")[0] == 0
    (tmp_path / "tol.json").write_text('{"positions": "wide"}')
    code, _, err = run_cli(capsys, "trace", "diff", a, c, "--tolerance", tmp_path / "tol.json")
    assert code == 2 and err.startswith(f"graphflow: error: {tmp_path / 'tol.json'}: positions: expected")


def _golden_counter(tmp_path):
    """Counts 0.5 s ticks and stops at 3, its trace compared with golden/count.jsonl."""
    path = tmp_path / "count.json"
    path.write_text(json.dumps({
        "format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.5, "duration": 10.0},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "counter", "type": "omni.graph.action.Counter"},
                  {"name": "enough", "type": "omni.graph.nodes.Compare", "inputs": {"b": 3, "operation": ">="}},
                  {"name": "branch", "type": "omni.graph.action.Branch"},
                  {"name": "stop", "type": "graphflow.StopRun"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                        {"src": "counter.outputs:count", "dst": "enough.inputs:a"},
                        {"src": "counter.outputs:execOut", "dst": "branch.inputs:execIn"},
                        {"src": "enough.outputs:result", "dst": "branch.inputs:condition"},
                        {"src": "branch.outputs:execTrue", "dst": "stop.inputs:execIn"}],
        "checks": [{"check": "stopsBy", "time": 2.0}, {"check": "matchesTrace", "trace": "golden/count.jsonl"}]}))
    return path


def test_update_golden_writes_the_trace_and_the_check_then_holds(tmp_path, capsys):
    path = _golden_counter(tmp_path)
    code, out, _ = run_cli(capsys, "test", path)
    assert code == 1 and "no golden trace" in out and "--update-golden writes it" in out
    assert run_cli(capsys, "test", path, "--update-golden")[0] == 0
    golden = tmp_path / "golden" / "count.jsonl"
    assert run_cli(capsys, "test", path)[0] == 0
    lines = golden.read_text().splitlines()
    lines[3] = lines[3].replace('"counter.count":3', '"counter.count":4')   # the golden run counted differently
    golden.write_text("\n".join(lines) + "\n")
    code, out, _ = run_cli(capsys, "test", path)
    assert code == 1 and "outputs.counter.count at tick 3 (t = 1.500 s): 3 vs golden 4" in out


@pytest.mark.slow
def test_golden_pick_place_survives_one_ulp_and_catches_a_one_percent_heavier_cube(monkeypatch):
    from graphflow import kinematics
    from graphflow.document import load_document
    from graphflow.variants.overrides import make_variant, parse_set
    from graphflow.verdicts.checked_run import CheckedRun, run_checked

    assert run_checked(GOLDEN_SCENARIO).failures == []
    document = load_document(GOLDEN_SCENARIO)
    heavier = CheckedRun(document, variant=make_variant(document, [parse_set("/World/Cube.physics:mass=0.101")])).run()
    assert len(heavier.failures) == 1
    # the first field beyond tolerance, named with its tick and phase: the hold's force or the cube's pose
    found = re.search(r"trace matches golden/tuned_pick_place.jsonl': measured (\S+) at tick (\d+) .* phase (\w+)",
                      heavier.failures[0])
    assert found, heavier.failures[0]
    assert found[1] in ("grippers./World/ur10/ee_link/SurfaceGripper_01.force", "outputs.cube_pose.orientation[0]",
                        "outputs.cube_pose.position[2]") and found[3] in ("lift", "move_to_place")
    solve = kinematics.SerialChain.inverse

    def one_ulp_off(self, *args, **kwargs):   # what another libm or BLAS might give: the last bit of every joint
        solution = solve(self, *args, **kwargs)
        return dataclasses.replace(solution, positions=tuple(math.nextafter(q, math.inf) for q in solution.positions))

    monkeypatch.setattr(kinematics.SerialChain, "inverse", one_ulp_off)
    assert run_checked(GOLDEN_SCENARIO).failures == []
