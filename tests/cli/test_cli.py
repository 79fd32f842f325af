"""The graphflow command: outputs and exit codes (0 ok, 1 run-time failure, 2 bad input)."""
import json
import subprocess
import sys

import pytest
from conftest import ROOT


def graphflow(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def test_core_demo_prints_its_lines_and_stops_on_its_own():
    result = graphflow("run", str(ROOT / "graphs" / "counter_branch_print.json"))
    assert result.returncode == 0, result.stderr
    assert result.stdout.splitlines() == ["count = 1", "count = 2", "count reached 3: done"]
    assert "Traceback" not in result.stderr


def test_tick_limit_stops_the_run_early():
    result = graphflow("run", str(ROOT / "graphs" / "counter_branch_print.json"), "--ticks", "2")
    assert result.returncode == 0
    assert result.stdout.splitlines() == ["count = 1", "count = 2"]


def test_validate_prints_every_mistake_one_line_each(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0], "nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "gripper", "type": "omni.graph.action.Branch", "inputs": {"condition": "yes"}},
        {"name": "mystery", "type": "acme.Teleport"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "nowhere.inputs:execIn"}]}))
    good = ROOT / "graphs" / "counter_branch_print.json"
    result = graphflow("validate", str(good), str(bad))
    assert result.returncode == 2
    assert result.stdout.splitlines() == [f"{good}: ok"]
    lines = result.stderr.splitlines()
    assert lines == [
        f"{bad}: node 'gripper' input 'inputs:condition': expected bool, got \"yes\"",
        f"{bad}: node 'mystery': unknown node type 'acme.Teleport'",
        f"{bad}: node 'nowhere' connection 'inputs:execIn': dangling connection tick.outputs:tick -> nowhere.inputs:execIn: no node named 'nowhere'",
    ]


def test_bad_graph_on_run_exits_2_without_traceback(tmp_path):
    broken = tmp_path / "broken.json"
    broken.write_text("{ not json")
    result = graphflow("run", str(broken))
    assert result.returncode == 2
    assert result.stderr.startswith(f"graphflow: error: {broken}: malformed JSON at line 1 column 3")
    assert "Traceback" not in result.stderr


def test_runtime_failure_exits_1_naming_the_node(tmp_path):
    looping = tmp_path / "loop.json"
    looping.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0], "settings": {"stepBudget": 100},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "ping", "type": "omni.graph.action.Counter"},
                  {"name": "pong", "type": "omni.graph.action.Counter"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "ping.inputs:execIn"},
                        {"src": "ping.outputs:execOut", "dst": "pong.inputs:execIn"},
                        {"src": "pong.outputs:execOut", "dst": "ping.inputs:execIn"}]}))
    result = graphflow("run", str(looping), "--ticks", "3")
    assert result.returncode == 1
    error, summary = result.stderr.strip().splitlines()
    assert "runaway execution loop through" in error and "ping" in error
    assert summary == f"graphflow: FAIL {looping}: 1 failure (1 tick, 0.017 s simulated)"


def test_usage_errors_exit_2():
    assert graphflow("run").returncode == 2
    assert graphflow("run", "x.json", "--ticks", "-3").returncode == 2
    assert graphflow("frobnicate").returncode == 2


def test_nodes_json_lists_every_spec():
    result = graphflow("nodes", "--json")
    assert result.returncode == 0
    specs = {spec["id"]: spec for spec in json.loads(result.stdout)}
    branch = specs["omni.graph.action.Branch"]
    assert branch["version"] == 1
    assert {"name": "condition", "type": "bool", "default": False} == {k: branch["inputs"][1][k] for k in ("name", "type", "default")}
    assert [o["name"] for o in branch["outputs"]] == ["execTrue", "execFalse"]
    plain = graphflow("nodes").stdout.splitlines()
    assert len(plain) == len(specs)


def test_new_writes_a_runnable_starter_and_never_overwrites(tmp_path):
    result = graphflow("new", "starter", cwd=tmp_path)
    assert result.returncode == 0
    starter = tmp_path / "starter.json"
    run = graphflow("run", str(starter))
    assert run.returncode == 0
    assert run.stdout.splitlines() == [f"tick {count}" for count in range(1, 11)]   # its description: every count
    starter.write_text("my edits\n")
    again = graphflow("new", "starter", cwd=tmp_path)
    assert again.returncode == 2
    assert "already exists" in again.stderr
    assert starter.read_text() == "my edits\n"


def test_stage_graph_stdout_holds_only_the_graph_lines(tmp_path):
    graph = tmp_path / "hello.json"
    graph.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0],
        "settings": {"stage": "asset:ur10.usda"},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "hello", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "hello"}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "hello.inputs:execIn"}]}))
    result = graphflow("run", str(graph), "--ticks", "2")
    assert result.returncode == 0, result.stderr
    assert result.stdout == "hello\nhello\n"
    assert "pybullet build time" not in result.stderr


def test_missing_stage_is_one_line_on_stderr(tmp_path):
    graph = tmp_path / "lost.json"
    graph.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0], "settings": {"stage": "nope.usda"},
                                 "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}]}))
    result = graphflow("run", str(graph))
    assert result.returncode == 2
    assert result.stderr.splitlines() == [
        f"graphflow: error: {graph}: settings/stage: {tmp_path / 'nope.usda'}: no such stage file"]


def test_gui_pacer_waits_for_simulated_time_only_when_ahead(monkeypatch):
    from types import SimpleNamespace

    from graphflow.observe import terminal

    clock = [100.0]
    slept = []
    monkeypatch.setattr(terminal.time, "perf_counter", lambda: clock[0])
    monkeypatch.setattr(terminal.time, "sleep", slept.append)
    world = SimpleNamespace(time=0.0)
    simulation = SimpleNamespace(world=world)
    pacer = terminal.RealTimePacer(speed=2.0)
    world.time, clock[0] = 1.0, 100.1        # 1 s simulated at 2x = 0.5 s of wall time; 0.1 s went by
    pacer.on_tick(simulation, 1)
    world.time, clock[0] = 1.5, 101.0        # behind: no wait
    pacer.on_tick(simulation, 2)
    assert slept == [pytest.approx(0.4)]


@pytest.mark.skipif(__import__("shutil").which("xvfb-run") is None, reason="needs xvfb-run for a virtual display")
def test_gui_run_opens_the_window_and_keeps_stdout_for_the_graph():
    result = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 800x600x24", sys.executable, "-m", "graphflow",
                             "run", str(ROOT / "graphs" / "ur10_pick_place.json"), "--gui", "--speed", "0", "--seconds", "2"],
                            capture_output=True, text=True, timeout=120)
    assert result.returncode == 0, result.stderr[-2000:]
    assert result.stdout.splitlines() == ["phase 0 move_above_pick: gripper Open", "phase 1 descend: gripper Open"]
    assert "GL_VERSION" in result.stderr, "the PyBullet window really opened (its diagnostics go to stderr)"


def test_stage_and_import_take_packaged_asset_names(capsys):
    """``asset:NAME`` means the same packaged stage to stage and import as to a graph's settings.stage."""
    from graphflow.cli import main

    assert main(["stage", "asset:ur10.usda", "--json"]) == 0
    report = json.loads(capsys.readouterr().out)
    assert [a["path"] for a in report["articulations"]] == ["/ur10"]
    assert len(report["articulations"][0]["movable_joints"]) == 6          # the UR10's six revolute joints
    assert main(["import", "asset:nope.usda"]) == 2
    assert "asset:nope.usda: no such packaged asset" in capsys.readouterr().err
