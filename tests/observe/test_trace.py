"""Run traces record what the run did, tick by tick, byte-identically from run to run."""
import io
import json
import subprocess
import sys

from conftest import ROOT

from graphflow.document import load_document
from graphflow.observe.recorder import TraceRecorder
from graphflow.observe.trace import read_trace
from graphflow.runtime import Simulation
from graphflow.testing import GraphHarness

COUNTER_GRAPH = ROOT / "graphs" / "counter_branch_print.json"


def graphflow(*args, cwd=None):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True, cwd=cwd)


def traced_run(tmp_path, name="run.jsonl", *extra):
    path = tmp_path / name
    result = graphflow("run", str(COUNTER_GRAPH), "--trace", str(path), *extra)
    assert result.returncode == 0, result.stderr
    return path


def test_counter_trace_holds_the_counts_and_the_print_pulses_tick_by_tick(tmp_path):
    trace = read_trace(traced_run(tmp_path))
    assert [r["tick"] for r in trace.ticks] == [1, 2, 3]
    assert list(trace.series("counter.count")) == [(0.5, 1), (1.0, 2), (1.5, 3)]
    pulses = {r["tick"]: r["pulses"] for r in trace.ticks}
    assert pulses[1] == ["on_tick.tick", "counter.execOut", "branch.execFalse", "print_count.execOut"]
    assert pulses[2] == pulses[1]
    assert pulses[3] == ["on_tick.tick", "counter.execOut", "branch.execTrue", "print_done.execOut", "stop.execOut"]
    assert [line["message"] for r in trace.ticks for line in r.get("log", [])] == [
        "count = 1", "count = 2", "count reached 3: done"]


def test_tick_records_hold_only_changes(tmp_path):
    trace = read_trace(traced_run(tmp_path))
    second, third = trace.ticks[1]["outputs"], trace.ticks[2]["outputs"]
    assert "at_least_three.result" not in second           # still false: not repeated
    assert third["at_least_three.result"] is True
    assert "format_count.text" not in third                  # the pure node was not pulled on tick 3
    assert trace.header["outputs"]["counter.count"] == 0     # values before the first tick


def test_header_names_graph_stage_time_step_nodes_and_versions(tmp_path):
    header = read_trace(traced_run(tmp_path)).header
    assert header["format"] == "graphflow-trace" and header["version"] == 2
    assert header["graph"] == str(COUNTER_GRAPH)
    assert header["stage"] is None and header["timeStep"] == 0.5
    assert header["nodes"]["counter"] == "omni.graph.action.Counter"
    assert set(header["versions"]) == {"graphflow", "python"}   # no physics loaded for a core graph
    assert header["phases"] == [] and header["grippers"] == []


def test_the_same_run_gives_a_byte_identical_trace(tmp_path):
    first = traced_run(tmp_path, "a.jsonl")
    second = traced_run(tmp_path, "b.jsonl")
    assert first.read_bytes() == second.read_bytes()


def test_every_line_is_compact_json(tmp_path):
    for line in traced_run(tmp_path).read_text().splitlines():
        assert json.dumps(json.loads(line), separators=(",", ":"), ensure_ascii=False) == line


def test_latent_pulses_carry_their_state(tmp_path):
    harness = GraphHarness({"settings": {"timeStep": 0.1}, "nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick", "inputs": {"onlyPlayback": False}},
        {"name": "once", "type": "omni.graph.action.Once"},
        {"name": "wait", "type": "omni.graph.action.Delay", "inputs": {"duration": 0.2}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "once.inputs:execIn"},
                        {"src": "once.outputs:once", "dst": "wait.inputs:execIn"}]})
    stream = io.StringIO()
    TraceRecorder(harness.simulation, stream)
    harness.simulation.run(ticks=4)
    records = [json.loads(line) for line in stream.getvalue().splitlines()[1:]]
    wait_pulses = [[p for p in r.get("pulses", []) if p.startswith("wait.")] for r in records]
    assert wait_pulses[0] == ["wait.finished:latentPush"]
    assert ["wait.finished:latentFinish"] in wait_pulses[1:]


def test_a_failing_run_keeps_the_ticks_before_the_failure(tmp_path):
    graph = tmp_path / "loop.json"
    graph.write_text(json.dumps({"format": "graphflow", "formatVersion": [1, 0], "settings": {"stepBudget": 50},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "counter", "type": "omni.graph.action.Counter"},
                  {"name": "at_two", "type": "omni.graph.nodes.Compare", "inputs": {"b": 2, "operation": ">="}},
                  {"name": "gate", "type": "omni.graph.action.Branch"},
                  {"name": "again", "type": "omni.graph.action.Counter"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"},
                        {"src": "counter.outputs:count", "dst": "at_two.inputs:a"},
                        {"src": "at_two.outputs:result", "dst": "gate.inputs:condition"},
                        {"src": "counter.outputs:execOut", "dst": "gate.inputs:execIn"},
                        {"src": "gate.outputs:execTrue", "dst": "again.inputs:execIn"},
                        {"src": "again.outputs:execOut", "dst": "gate.inputs:execIn"}]}))
    trace_path = tmp_path / "loop.jsonl"
    result = graphflow("run", str(graph), "--ticks", "5", "--trace", str(trace_path))
    assert result.returncode == 1
    assert [r["tick"] for r in read_trace(trace_path).ticks] == [1]


def test_unwritable_trace_path_is_bad_input(tmp_path):
    result = graphflow("run", str(COUNTER_GRAPH), "--trace", str(tmp_path / "missing" / "run.jsonl"))
    assert result.returncode == 2
    assert result.stderr.splitlines() == [
        f"graphflow: error: {tmp_path / 'missing' / 'run.jsonl'}: folder {tmp_path / 'missing'} does not exist"]


def test_recorder_attaches_as_a_listener_of_the_simulation():
    simulation = Simulation(load_document(COUNTER_GRAPH))
    stream = io.StringIO()
    recorder = TraceRecorder(simulation, stream)
    assert simulation.listeners == [recorder]
    simulation.step()
    simulation.step()
    assert [json.loads(line)["tick"] for line in stream.getvalue().splitlines()[1:]] == [1, 2]


def test_non_finite_outputs_and_bundles_are_written_and_read_back():
    """A trace writes NaN and infinities as Python's json does (docs/trace.md) and reads them back; a bundle
    is its attributes by name."""
    from graphflow.bundles import Bundle, BundleAttribute
    from graphflow.observe.trace import parse_trace

    bundle = Bundle.of_prim("/World/Cube", "Cube", (BundleAttribute("physics:centerOfMass", "pointf[3]",
                                                                    (float("-inf"),) * 3),))
    graph = GraphHarness({"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick", "inputs": {"onlyPlayback": False}},
        {"name": "insert", "type": "omni.graph.nodes.InsertAttribute", "inputs": {"outputAttrName": "gap"}},
        {"name": "inspect", "type": "omni.graph.nodes.BundleInspector"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "inspect.inputs:execIn"},
                        {"src": "insert.outputs:data", "dst": "inspect.inputs:bundle"}]})
    graph.instance.set_input("insert", "attrToInsert", float("nan"))
    graph.instance.set_input("insert", "data", bundle)
    stream = io.StringIO()
    TraceRecorder(graph.simulation, stream)
    graph.run(ticks=1)
    assert "-Infinity" in stream.getvalue() and "NaN" in stream.getvalue()
    trace = parse_trace(stream.getvalue())
    (record,) = trace.ticks
    shown = record["outputs"]["inspect.bundle"]["attributes"]
    assert shown["physics:centerOfMass"] == [float("-inf")] * 3 and shown["gap"] != shown["gap"]   # NaN
    assert shown["sourcePrimPath"] == "/World/Cube"
