"""Issue 25 as a CI user meets it: pass rates over seeds with Wilson gates, scenario tables, shrunk failures,
failure artifacts in JUnit. Interval figures are checked against the closed forms of the Wilson score
interval and the issue's own example; grip physics against the cube's weight and the measured 9.9 N/kg."""
import json
import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET

import pytest
from conftest import ROOT

from graphflow import cli
from graphflow.verdicts.rates import RatePlan, RateVerdict, randomized_edits, z_for

from .counter_graphs import counter_scenario

TABLE = ROOT / "graphs" / "tutorial_experiments.json"
FRAGILE = ROOT / "graphs" / "scenarios" / "fragile_grip_rate.json"
Z95 = 1.959963984540054


def run_cli(capsys, *args):
    code = cli.main([str(a) for a in args])
    out, err = capsys.readouterr()
    return code, out, err


def verdict_of(successes: int, runs: int, gate: float, confidence: float = 0.95) -> RateVerdict:
    records = [{"seed": s, "passed": s < successes, "failures": [] if s < successes else ["x.json: check 1 'c': bad"],
                "replay": f"graphflow run x.json --seed {s}"} for s in range(runs)]
    return RateVerdict("x.json", RatePlan("x.json", list(range(runs)), gate, confidence), records)


# ---------------------------------------------------------------- 1. rates

def test_the_issues_example_line_47_of_50_at_95_percent():
    assert verdict_of(47, 50, 0.80).rate_line() == "47/50 passed, 95 % CI [0.84, 0.98], gate 0.80: PASS"


def test_all_passing_lower_bound_is_n_over_n_plus_z_squared():
    # Wilson with no failures: the lower bound is n / (n + z^2), so 3/3 can never clear a 0.8 gate
    for runs in (3, 20, 50):
        low, high = verdict_of(runs, runs, 0.8).interval()
        assert math.isclose(low, runs / (runs + Z95 ** 2), rel_tol=1e-12) and high == 1.0
    assert not verdict_of(3, 3, 0.8).gate_passed and verdict_of(50, 50, 0.8).gate_passed   # 0.44 and 0.93


def test_confidence_level_sets_the_quantile():
    assert math.isclose(z_for(0.95), Z95, rel_tol=1e-12)
    assert math.isclose(z_for(0.90), 1.6448536269514722, rel_tol=1e-12)
    wide, narrow = verdict_of(40, 50, 0.7, 0.99).interval(), verdict_of(40, 50, 0.7, 0.90).interval()
    assert wide[0] < narrow[0] < 0.8 < narrow[1] < wide[1]


def test_failing_seeds_are_listed_with_reason_and_rerun_command():
    lines = verdict_of(8, 10, 0.9).failures
    assert lines[0] == "x.json: 8/10 passed, 95 % CI [0.49, 0.94], gate 0.90: FAIL"
    assert lines[1:] == ["seed 8: check 1 'c': bad", "  re-run: graphflow run x.json --seed 8",
                         "seed 9: check 1 'c': bad", "  re-run: graphflow run x.json --seed 9"]


def test_seeds_option_makes_any_scenario_a_rate_with_a_gate(tmp_path, capsys):
    path = tmp_path / "count.json"
    path.write_text(json.dumps(counter_scenario()))
    code, out, _ = run_cli(capsys, "test", path, "--seeds", "3", "--junit", tmp_path / "r.xml")
    assert code == 1   # 3/3 passed, but 3 runs cannot show a rate of 0.8 at 95 %
    assert f"FAIL {path}: 3/3 passed, 95 % CI [0.44, 1.00], gate 0.80: FAIL" in out.splitlines()
    code, out, _ = run_cli(capsys, "test", path, "--seeds", "3", "--min-pass-rate", "0.4")
    assert code == 0 and f"PASS {path}: 3/3 passed, 95 % CI [0.44, 1.00], gate 0.40: PASS" in out


def test_rate_junit_has_counts_interval_and_gate_as_properties(tmp_path, capsys):
    path = tmp_path / "count.json"
    path.write_text(json.dumps(counter_scenario(seeds=4, minPassRate=0.3, confidence=0.9)))
    code, _out, _ = run_cli(capsys, "test", path, "--junit", tmp_path / "r.xml")
    assert code == 0
    case = ET.parse(tmp_path / "r.xml").find(".//testcase")
    properties = {p.get("name"): p.get("value") for p in case.iter("property")}
    low = 4 / (4 + 1.6448536269514722 ** 2)
    assert properties == {"runs": "4", "passed": "4", "rate": "1.0000", "confidence": "0.9",
                          "interval_low": f"{low:.4f}", "interval_high": "1.0000", "gate": "0.3", "seeds": "0..3"}


def test_a_bad_randomization_is_an_error_before_any_episode(tmp_path, capsys):
    path = tmp_path / "count.json"
    path.write_text(json.dumps(counter_scenario(seeds=3, randomize=[{"set": "counter.nope", "uniform": [0, 1]}])))
    code, out, _ = run_cli(capsys, "test", path)
    assert code == 2
    assert out.splitlines()[0].startswith(f"ERROR {path}: ") and "no input 'nope'" in out


@pytest.mark.slow
def test_fragile_grip_fails_its_gate_reproducibly_and_the_failing_seeds_are_the_heavy_cubes(tmp_path, capsys):
    code, out, _ = run_cli(capsys, "test", FRAGILE, "--junit", tmp_path / "r.xml")
    assert code == 0   # expectFailure: failing the gate is this example's expected outcome
    assert f"XFAIL {FRAGILE}: 11/20 passed, 95 % CI [0.34, 0.74], gate 0.90: FAIL" in out.splitlines()
    failing = {int(s) for s in re.findall(r"^    seed (\d+): ", out, re.M)}
    assert len(failing) == 9
    # the peak grip force is 9.9 N per kg of cube (README), so a 10 N limit fails from about 1.01 kg
    masses = {seed: next(e.value for e in randomized_edits(str(FRAGILE), seed) if e.target.endswith("physics:mass"))
              for seed in range(20)}
    assert all(masses[seed] > 1.0 for seed in failing)
    assert all(masses[seed] < 1.05 for seed in set(range(20)) - failing)
    forces = [float(f) for f in re.findall(r"broken by force ([\d.]+) N > limit 10 N", out)]
    assert len(forces) == 9 and all(9.5 * masses[s] < f < 10.5 * masses[s] for s, f in zip(sorted(failing), forces))


# ---------------------------------------------------------------- 2. tables

@pytest.mark.slow
def test_tutorial_table_is_four_named_items_each_matching_the_tutorial(tmp_path, capsys):
    code, out, _ = run_cli(capsys, "test", TABLE, "--junit", tmp_path / "t.xml")
    lines = out.splitlines()
    assert code == 0 and lines[-1] == "4 passed, 0 failed"
    verdicts = [line.split(": ", 1)[0] for line in lines if not line.startswith(" ")][:-1]
    assert verdicts == [f"PASS {TABLE}::tuned, as shipped", f"XFAIL {TABLE}::heavy cube against a low force limit",
                        f"PASS {TABLE}::kd = 1", f"XFAIL {TABLE}::grip_threshold 0.001"]
    force = float(re.search(r"broken by force ([\d.]+) N > limit 30 N", out).group(1))
    assert 5.0 * 9.81 < force < 1.1 * 5.0 * 9.81   # the 5 kg cube's weight, plus the lift's acceleration
    cases = ET.parse(tmp_path / "t.xml").findall(".//testcase")
    assert [c.get("name") for c in cases] == ["tuned, as shipped", "heavy cube against a low force limit", "kd = 1",
                                              "grip_threshold 0.001"]
    assert all(c.get("classname").endswith("graphs.tutorial_experiments") for c in cases)   # the table is the class


def test_pytest_collects_one_named_item_per_case():
    result = subprocess.run([sys.executable, "-m", "pytest", "--collect-only", "-q", "-p", "no:cacheprovider", str(TABLE)],
                            cwd=ROOT, capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stdout + result.stderr
    assert [line for line in result.stdout.splitlines() if "::" in line] == [
        "graphs/tutorial_experiments.json::tuned, as shipped", "graphs/tutorial_experiments.json::heavy cube against a low force limit",
        "graphs/tutorial_experiments.json::kd = 1", "graphs/tutorial_experiments.json::grip_threshold 0.001"]


def _table(tmp_path, cases, graph=None):
    (tmp_path / "count.json").write_text(json.dumps(graph or counter_scenario()))
    path = tmp_path / "table.json"
    path.write_text(json.dumps({"format": "graphflow-cases", "formatVersion": [1, 0], "graph": "count.json", "cases": cases}))
    return path


def test_case_expectations_pass_fail_and_wrong_reason(tmp_path, capsys):
    path = _table(tmp_path, [{"name": "stops at 3", "expect": "pass"},
                             {"name": "stops too late", "set": {"enough.b": 9}, "expect": {"fail": r"stops by itself .* by t = 2 s"}},
                             {"name": "expected to fail", "expect": {"fail": "anything"}},
                             {"name": "wrong reason", "set": {"enough.b": 9}, "expect": {"fail": "no such text"}}])
    code, out, _ = run_cli(capsys, "test", path, "-j", "1")
    heads = [line for line in out.splitlines() if not line.startswith(" ")]
    assert code == 1 and heads[-1] == "2 passed, 2 failed"
    assert heads[0].startswith(f"PASS {path}::stops at 3: 1 check holds")
    assert heads[1].startswith(f"XFAIL {path}::stops too late: failed as expected")
    assert heads[2].startswith(f"FAIL {path}::expected to fail: expected to fail (/anything/) but passed")
    assert heads[3].startswith(f"FAIL {path}::wrong reason: failed, but not with /no such text/")
    rerun = next(line for line in out.splitlines() if line.strip().startswith("re-run:") and "enough.b" in line)
    assert rerun.strip() == f"re-run: graphflow run {tmp_path / 'count.json'} --set enough.b=9"


def test_a_bad_case_is_one_error_line_naming_table_and_case(tmp_path, capsys):
    path = _table(tmp_path, [{"name": "typo", "set": {"enoguh.b": 9}}])
    code, out, _ = run_cli(capsys, "test", path)
    assert code == 2 and out.splitlines()[0].startswith(f"ERROR {path}: {path}::typo: set enoguh.b=9: the graph has no node")
    path = _table(tmp_path, [{"name": "twice"}, {"name": "twice"}])
    code, out, _ = run_cli(capsys, "test", path)
    assert code == 2 and out.splitlines()[0] == f"ERROR {path}: {path}: cases/1: the name 'twice' is used twice"


# ---------------------------------------------------------------- 4. shrink

@pytest.mark.slow
def test_shrunk_fragile_case_keeps_only_the_mass_near_the_break_and_fails_alone(capsys):
    code, out, _ = run_cli(capsys, "shrink", FRAGILE, "--seed", "0")
    assert code == 0
    command = next(line.strip() for line in out.splitlines() if line.strip().startswith("graphflow run"))
    mass = float(re.search(r"physics:mass=([\d.]+)", command).group(1))
    assert command.count("--set") == 1                  # the threshold and start pose were not needed
    assert 10.0 / 9.9 <= mass < 1.1                     # 9.9 N/kg puts the break at 1.01 kg (drawn 1.34 kg)
    row = json.loads(out.splitlines()[-1])
    assert row["set"] == {"/World/Cube.physics:mass": mass} and row["seed"] == 0
    result = subprocess.run([sys.executable, "-m", "graphflow", *command.split()[1:]], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 1 and "broken by force" in result.stderr and "> limit 10 N" in result.stderr


# ---------------------------------------------------------------- 5. artifacts

def test_failing_scenario_keeps_trace_and_timeline_and_junit_lists_them(tmp_path, capsys):
    path = tmp_path / "late.json"
    path.write_text(json.dumps(counter_scenario(stop_at=9)))
    code, out, _ = run_cli(capsys, "test", path, "--junit", tmp_path / "r.xml", "--traces", tmp_path / "kept")
    assert code == 1
    trace, picture = tmp_path / "kept" / "000-late.jsonl", tmp_path / "kept" / "000-late.png"
    assert f"    trace: {trace}" in out.splitlines() and f"    timeline: {picture}" in out.splitlines()
    assert picture.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    system_out = ET.parse(tmp_path / "r.xml").find(".//testcase/system-out").text.splitlines()
    assert f"[[ATTACHMENT|{trace.resolve()}]]" in system_out and f"[[ATTACHMENT|{picture.resolve()}]]" in system_out
