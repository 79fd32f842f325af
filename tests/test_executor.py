"""Executor semantics: exec push order, data pull memoisation, latent nodes, budget, reset, instancing."""
import sys
import types

import pytest

import graphflow_nodes
from graphflow.compiler import compile
from graphflow.document import parse_document
from graphflow.executor import GraphInstance, GraphRuntimeError, StepBudgetExceeded
from graphflow.registry import Registry, default_registry
from graphflow.spec import Attribute, NodeSpec
from graphflow.testing import GraphHarness
from graphflow.types import ExecState


def _module(name, spec, compute):
    module = types.ModuleType(f"test_nodes.{name}")
    module.SPEC, module.compute = spec, compute
    return module


def _recording_registry(record):
    """Built-ins plus 'test.Record' (logs its label on every pulse) and 'test.Source' (a pure node counting computes)."""
    registry = Registry()
    registry.register_package(graphflow_nodes)

    def record_compute(db):
        record.append(db.inputs.label)
        db.outputs.execOut = ExecState.ENABLED

    registry.register_module(_module("record", NodeSpec(
        id="test.Record", version=1, description="Appends its label to a list.",
        inputs=(Attribute("execIn", "execution"), Attribute("label", "string"), Attribute("value", "any")),
        outputs=(Attribute("execOut", "execution"),)), record_compute))

    def source_compute(db):
        record.append("source computed")
        db.outputs.value = db.inputs.value + 1.0

    registry.register_module(_module("source", NodeSpec(
        id="test.Source", version=1, description="Pure: value + 1, recording each compute.",
        inputs=(Attribute("value", "double"),), outputs=(Attribute("value", "double"),)), source_compute))
    return registry


def _graph(nodes, connections, registry, **extra):
    data = {"format": "graphflow", "formatVersion": [1, 0], "nodes": nodes, "connections": connections, **extra}
    return parse_document(data, "<test>", registry)


def _conn(src, dst):
    return {"src": src, "dst": dst}


def test_sequence_runs_a_downstream_completely_before_b():
    record = []
    registry = _recording_registry(record)
    document = _graph(
        [{"name": "tick", "type": "omni.graph.action.OnTick"},
         {"name": "seq", "type": "omni.graph.action.Sequence"},
         {"name": "a1", "type": "test.Record", "inputs": {"label": "a1"}},
         {"name": "a2", "type": "test.Record", "inputs": {"label": "a2"}},
         {"name": "b1", "type": "test.Record", "inputs": {"label": "b1"}}],
        [_conn("tick.outputs:tick", "seq.inputs:execIn"), _conn("seq.outputs:a", "a1.inputs:execIn"),
         _conn("a1.outputs:execOut", "a2.inputs:execIn"), _conn("seq.outputs:b", "b1.inputs:execIn")], registry)
    instance = GraphInstance(compile(document, registry))
    instance.tick()
    assert record == ["a1", "a2", "b1"]


def test_fan_out_runs_in_connection_order_and_fan_in_fires_once_per_pulse():
    record = []
    registry = _recording_registry(record)
    document = _graph(
        [{"name": "tick", "type": "omni.graph.action.OnTick"},
         {"name": "first", "type": "test.Record", "inputs": {"label": "first"}},
         {"name": "second", "type": "test.Record", "inputs": {"label": "second"}},
         {"name": "join", "type": "test.Record", "inputs": {"label": "join"}}],
        [_conn("tick.outputs:tick", "first.inputs:execIn"), _conn("tick.outputs:tick", "second.inputs:execIn"),
         _conn("first.outputs:execOut", "join.inputs:execIn"), _conn("second.outputs:execOut", "join.inputs:execIn")],
        registry)
    instance = GraphInstance(compile(document, registry))
    instance.tick()
    assert record == ["first", "join", "second", "join"]


def test_pulse_log_lists_each_computes_fired_outputs_in_declared_order_and_empties_each_tick():
    """What a trace reads instead of a call per compute: the same pulses on_compute reports, in the same order."""
    record = []
    registry = _recording_registry(record)

    def fork_compute(db):   # fires both outputs in one compute: the push loop visits them last to first
        db.outputs.left = ExecState.ENABLED
        db.outputs.right = ExecState.ENABLED_AND_PUSH if db.state.first else ExecState.ENABLED
        db.state.first = False

    registry.register_module(_module("fork", NodeSpec(
        id="test.Fork", version=1, description="Fires both outputs.",
        inputs=(Attribute("execIn", "execution"),),
        outputs=(Attribute("left", "execution"), Attribute("right", "execution")),
        state=(Attribute("first", "bool", default=True),)), fork_compute))
    document = _graph(
        [{"name": "tick", "type": "omni.graph.action.OnTick"},
         {"name": "fork", "type": "test.Fork"},
         {"name": "a", "type": "test.Record", "inputs": {"label": "a"}},
         {"name": "b", "type": "test.Record", "inputs": {"label": "b"}}],
        [_conn("tick.outputs:tick", "fork.inputs:execIn"),
         _conn("fork.outputs:left", "a.inputs:execIn"), _conn("fork.outputs:right", "b.inputs:execIn")],
        registry)
    reported = []

    class Listener:
        reads_pulses = True

        def on_compute(self, instance, node_name, fired, db):
            reported.extend((node_name, name, getattr(db.outputs, name)) for name in fired)

    instance = GraphInstance(compile(document, registry), listeners=[Listener()])
    names = [node.name for node in instance.compiled.nodes]
    ticks = []
    for _tick in range(2):
        reported.clear()
        instance.tick()
        assert [(names[index], name, state) for index, name, state in instance.pulse_log] == reported
        ticks.append([f"{node}.{name}" for node, name, _state in reported])
    # tick 1: right re-enters fork (ENABLED_AND_PUSH) after b, and fork fires both again; tick 2 starts empty
    assert ticks[0] == ["tick.tick", "fork.left", "fork.right", "a.execOut", "b.execOut",
                        "fork.left", "fork.right", "a.execOut", "b.execOut"]
    assert ticks[1] == ["tick.tick", "fork.left", "fork.right", "a.execOut", "b.execOut"]


def test_diamond_pulls_its_top_once_per_tick():
    record = []
    registry = _recording_registry(record)
    document = _graph(
        [{"name": "tick", "type": "omni.graph.action.OnTick"},
         {"name": "top", "type": "test.Source", "inputs": {"value": 1.0}},
         {"name": "left", "type": "omni.graph.nodes.Add", "inputs": {"b": 10.0}},
         {"name": "right", "type": "omni.graph.nodes.Add", "inputs": {"b": 100.0}},
         {"name": "join", "type": "omni.graph.nodes.Add"},
         {"name": "out", "type": "test.Record", "inputs": {"label": "out"}}],
        [_conn("tick.outputs:tick", "out.inputs:execIn"),
         _conn("top.outputs:value", "left.inputs:a"), _conn("top.outputs:value", "right.inputs:a"),
         _conn("left.outputs:sum", "join.inputs:a"), _conn("right.outputs:sum", "join.inputs:b"),
         _conn("join.outputs:sum", "out.inputs:value")], registry)
    instance = GraphInstance(compile(document, registry))
    instance.tick()
    instance.tick()
    assert record == ["source computed", "out", "source computed", "out"]
    assert instance.database("out").inputs.value == pytest.approx((1.0 + 1.0 + 10.0) + (1.0 + 1.0 + 100.0))


def test_pure_node_recomputes_when_an_exec_source_changes_within_a_tick():
    """A ForEach body pulls element-dependent math: each iteration sees its own element."""
    record = []
    registry = _recording_registry(record)
    document = _graph(
        [{"name": "tick", "type": "omni.graph.action.OnTick"},
         {"name": "array", "type": "omni.graph.nodes.ConstructArray",
          "inputs": {"arraySize": 3, "arrayType": "double[]", "input0": 1.0, "input1": 2.0, "input2": 3.0}},
         {"name": "loop", "type": "omni.graph.action.ForEach"},
         {"name": "double", "type": "omni.graph.nodes.Multiply", "inputs": {"b": 2.0}},
         {"name": "body", "type": "test.Record", "inputs": {"label": "body"}}],
        [_conn("tick.outputs:tick", "loop.inputs:execIn"), _conn("array.outputs:array", "loop.inputs:arrayIn"),
         _conn("loop.outputs:loopBody", "body.inputs:execIn"), _conn("loop.outputs:element", "double.inputs:a"),
         _conn("double.outputs:product", "body.inputs:value")], registry)
    seen = []
    instance = GraphInstance(compile(document, registry), listeners=[types.SimpleNamespace(
        on_compute=lambda instance, name, fired, db: seen.append(db.inputs.value) if name == "body" else None)])
    instance.tick()
    assert seen == [2.0, 4.0, 6.0]
    assert record == ["body"] * 3


def test_delay_is_latent_and_locks_further_pulses():
    harness = GraphHarness({
        "settings": {"timeStep": 0.1},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "delay", "type": "omni.graph.action.Delay", "inputs": {"duration": 0.5}},
                  {"name": "done", "type": "omni.graph.action.Counter"}],
        "connections": [_conn("tick.outputs:tick", "delay.inputs:execIn"),
                        _conn("delay.outputs:finished", "done.inputs:execIn")]})
    finished_at = []
    for _ in range(12):
        harness.run(1)
        if harness.output("done", "count") > len(finished_at):
            finished_at.append(harness.instance.tick_count)
    # started on tick 1, finishes 0.5 s (5 ticks) later; the pulses of ticks 2..6 are ignored,
    # then tick 7's pulse starts the next delay, which finishes on tick 12
    assert finished_at == [6, 12]


def test_step_budget_names_the_runaway_loop():
    document = {
        "settings": {"stepBudget": 50},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "ping", "type": "omni.graph.action.Counter"},
                  {"name": "pong", "type": "omni.graph.action.Counter"}],
        "connections": [_conn("tick.outputs:tick", "ping.inputs:execIn"),
                        _conn("ping.outputs:execOut", "pong.inputs:execIn"),
                        _conn("pong.outputs:execOut", "ping.inputs:execIn")]}
    harness = GraphHarness(document)
    with pytest.raises(StepBudgetExceeded) as caught:
        harness.run(1)
    assert "ping" in str(caught.value) and "pong" in str(caught.value) and "50" in str(caught.value)


def test_node_failure_is_a_runtime_error_naming_the_node():
    harness = GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "zero", "type": "omni.graph.nodes.ConstantDouble", "inputs": {"value": 0.0}},
                  {"name": "ratio", "type": "omni.graph.nodes.Divide", "inputs": {"a": 1.0}},
                  {"name": "print", "type": "graphflow.FormatText"},
                  {"name": "show", "type": "omni.graph.ui_nodes.PrintText"}],
        "connections": [_conn("tick.outputs:tick", "show.inputs:execIn"),
                        _conn("zero.outputs:value", "ratio.inputs:b"),
                        _conn("ratio.outputs:result", "print.inputs:value"),
                        _conn("print.outputs:text", "show.inputs:text")]})
    with pytest.raises(GraphRuntimeError) as caught:
        harness.run(1)
    assert caught.value.node == "ratio"


def _counting_graph():
    return {"variables": [{"name": "total", "type": "int", "default": 5}],
            "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                      {"name": "counter", "type": "omni.graph.action.Counter"},
                      {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "total"}}],
            "connections": [_conn("tick.outputs:tick", "counter.inputs:execIn"),
                            _conn("counter.outputs:execOut", "write.inputs:execIn"),
                            _conn("counter.outputs:count", "write.inputs:value")]}


def test_reset_returns_to_the_initial_state():
    harness = GraphHarness(_counting_graph())
    harness.run(4)
    assert harness.output("counter", "count") == 4 and harness.instance.variables["total"] == 4
    harness.reset()
    assert harness.output("counter", "count") == 0 and harness.instance.variables["total"] == 5
    assert harness.world.time == 0.0
    harness.run(2)
    assert harness.output("counter", "count") == 2


def test_one_document_instanced_side_by_side_keeps_separate_state():
    document = parse_document({"format": "graphflow", "formatVersion": [1, 0], **_counting_graph()})
    compiled = compile(document, default_registry())
    first, second = GraphInstance(compiled), GraphInstance(compiled)
    for _ in range(3):
        first.tick()
    second.tick()
    assert first.output("counter", "count") == 3
    assert second.output("counter", "count") == 1
    assert compiled.document is document


def test_event_sources_fire_in_document_order():
    record = []
    registry = _recording_registry(record)
    document = _graph(
        [{"name": "late", "type": "omni.graph.action.OnTick"},
         {"name": "early", "type": "omni.graph.action.OnPlaybackTick"},
         {"name": "x", "type": "test.Record", "inputs": {"label": "from late"}},
         {"name": "y", "type": "test.Record", "inputs": {"label": "from early"}}],
        [_conn("early.outputs:tick", "y.inputs:execIn"), _conn("late.outputs:tick", "x.inputs:execIn")], registry)
    GraphInstance(compile(document, registry)).tick()
    assert record == ["from late", "from early"]


def test_core_engine_imports_neither_pybullet_nor_pxr():
    import subprocess

    code = ("import sys, graphflow.cli, graphflow.executor, graphflow.runtime, graphflow.testing.harness;"
            "from graphflow.registry import default_registry; default_registry();"
            "from graphflow.testing import GraphHarness;"
            "GraphHarness({'nodes':[{'name':'t','type':'omni.graph.action.OnTick'}]}).run(3);"
            "print(sorted(m for m in ('pybullet','pxr') if m in sys.modules))")
    output = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert output.strip() == "[]"
