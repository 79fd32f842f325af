"""omni.graph.action types added from Kit's node library reference, on its own examples."""
from graphflow.testing import GraphHarness, NodeHarness


def _graph(*nodes, connections=()):
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": list(nodes),
            "connections": [{"src": s, "dst": d} for s, d in connections]}


def test_countdown_ticks_after_3_6_9_and_finishes_after_the_10th():
    # the reference's example: duration 10, period 3
    harness = GraphHarness(_graph(
        {"name": "start", "type": "omni.graph.action.OnLoaded"},
        {"name": "countdown", "type": "omni.graph.action.Countdown", "inputs": {"duration": 10, "period": 3}},
        {"name": "ticks", "type": "omni.graph.action.Counter"},
        {"name": "done", "type": "omni.graph.action.Counter"},
        connections=[("start.outputs:execOut", "countdown.inputs:execIn"),
                     ("countdown.outputs:tick", "ticks.inputs:execIn"),
                     ("countdown.outputs:finished", "done.inputs:execIn")]))
    seen = []
    for _ in range(13):
        harness.run(1)
        seen.append((harness.output("ticks", "count"), harness.output("done", "count")))
    # tick 1 starts it (execution 0); executions 1..10 follow one a tick; the 11th finishes
    assert [t for t, _ in seen] == [0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 3]
    assert [d for _, d in seen] == [0] * 11 + [1, 1]
    assert harness.output("countdown", "alpha") == 1.0


def test_switch_token_fires_the_matching_branch_only():
    node = NodeHarness("omni.graph.action.SwitchToken", {"value": "B", "branch0": "A", "branch1": "B", "branch2": "B"})
    assert node.compute("execIn").fired == {"output1"}
    node.set_inputs(value="C")
    assert node.compute("execIn").fired == set()


def test_start_play_stage_events_fire_once_on_the_first_tick_and_editor_events_never():
    start = NodeHarness("omni.graph.action.OnStageEvent", {"eventName": "Simulation Start Play"})
    assert [start.tick().fired for _ in range(3)] == [{"execOut"}, set(), set()]
    saved = NodeHarness("omni.graph.action.OnStageEvent", {"eventName": "Saved"})
    assert [saved.tick().fired for _ in range(3)] == [set(), set(), set()]
    loaded = NodeHarness("omni.graph.action.OnLoaded")
    assert [loaded.tick().fired for _ in range(2)] == [{"execOut"}, set()]
    loaded.reset()
    assert loaded.tick().fired == {"execOut"}


def test_on_variable_change_fires_the_tick_after_a_write_changes_the_value():
    graph = _graph(
        {"name": "watch", "type": "omni.graph.action.OnVariableChange", "inputs": {"variableName": "mode"}},
        {"name": "changes", "type": "omni.graph.action.Counter"},
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "ticks", "type": "omni.graph.action.Counter"},
        {"name": "every_third", "type": "omni.graph.nodes.Modulo", "inputs": {"b": 3}},
        {"name": "write", "type": "omni.graph.core.WriteVariable", "inputs": {"variableName": "mode"}},
        connections=[("watch.outputs:changed", "changes.inputs:execIn"), ("tick.outputs:tick", "ticks.inputs:execIn"),
                     ("ticks.outputs:count", "every_third.inputs:a"), ("ticks.outputs:execOut", "write.inputs:execIn"),
                     ("every_third.outputs:result", "write.inputs:value")])
    graph["variables"] = [{"name": "mode", "type": "int64", "default": 0}]
    harness = GraphHarness(graph)
    counts = []
    for _ in range(7):
        harness.run(1)
        counts.append(harness.output("changes", "count"))
    # mode after each tick: 1, 2, 0, 1, 2, 0, 1 (count % 3); a change shows on the next tick
    assert counts == [0, 1, 2, 3, 4, 5, 6]


def test_a_custom_event_sent_on_one_tick_fires_its_listeners_on_the_next_with_its_path():
    import json

    harness = GraphHarness(_graph(
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "send", "type": "omni.graph.action.SendCustomEvent",
         "inputs": {"eventName": "go", "path": "/World/Cube"}},
        {"name": "push", "type": "omni.graph.action.SendMessageBusEvent",
         "inputs": {"eventName": "moved", "messageFields": json.dumps({"arg1": 42})}},
        {"name": "listen", "type": "omni.graph.action.OnCustomEvent", "inputs": {"eventName": "go"}},
        {"name": "other", "type": "omni.graph.action.OnCustomEvent", "inputs": {"eventName": "stop"}},
        {"name": "bus", "type": "omni.graph.action.OnMessageBusEvent", "inputs": {"eventName": "moved"}},
        {"name": "heard", "type": "omni.graph.action.Counter"},
        {"name": "unheard", "type": "omni.graph.action.Counter"},
        {"name": "bus_heard", "type": "omni.graph.action.Counter"},
        connections=[("tick.outputs:tick", "send.inputs:execIn"), ("send.outputs:execOut", "push.inputs:execIn"),
                     ("listen.outputs:execOut", "heard.inputs:execIn"),
                     ("other.outputs:execOut", "unheard.inputs:execIn"),
                     ("bus.outputs:execOut", "bus_heard.inputs:execIn")]))
    harness.run(1)
    assert (harness.output("heard", "count"), harness.output("bus_heard", "count")) == (0, 0)   # delivered later
    harness.run(2)
    assert (harness.output("heard", "count"), harness.output("bus_heard", "count")) == (2, 2)
    assert harness.output("unheard", "count") == 0
    assert harness.output("listen", "path") == "/World/Cube"
    assert json.loads(harness.output("bus", "payload")) == {"arg1": 42}


def test_a_custom_events_bundle_payload_reaches_its_listener():
    harness = GraphHarness(_graph(
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "payload", "type": "omni.graph.nodes.InsertAttribute",
         "inputs": {"outputAttrName": "speed", "attrToInsert": 2.5}},
        {"name": "send", "type": "omni.graph.action.SendCustomEvent", "inputs": {"eventName": "go"}},
        {"name": "listen", "type": "omni.graph.action.OnCustomEvent", "inputs": {"eventName": "go"}},
        connections=[("tick.outputs:tick", "send.inputs:execIn"), ("payload.outputs:data", "send.inputs:bundle")]))
    harness.run(1)
    assert harness.output("listen", "bundle").names == ()                 # delivered on the next tick
    harness.run(1)
    assert harness.output("listen", "bundle").get("speed").value == 2.5


def test_exit_application_ends_the_run_after_its_tick():
    harness = GraphHarness(_graph(
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "ticks", "type": "omni.graph.action.Counter"},
        {"name": "third", "type": "omni.graph.nodes.Compare", "inputs": {"b": 3, "operation": "=="}},
        {"name": "branch", "type": "omni.graph.action.Branch"},
        {"name": "exit", "type": "omni.graph.action.ExitApplication"},
        connections=[("tick.outputs:tick", "ticks.inputs:execIn"), ("ticks.outputs:execOut", "branch.inputs:execIn"),
                     ("ticks.outputs:count", "third.inputs:a"), ("third.outputs:result", "branch.inputs:condition"),
                     ("branch.outputs:execTrue", "exit.inputs:execIn")]))
    harness.run(10)
    assert harness.output("ticks", "count") == 3


def test_on_object_change_fires_the_tick_after_a_property_changes():
    from graphflow.testing.fake_world import FakeWorld

    world = FakeWorld()
    world.add_box("/World/Cube", (0.0, 0.0, 0.5), (0.1, 0.1, 0.1))
    world.attributes[("/World/Cube", "physics:mass")] = 1.0
    harness = GraphHarness(_graph(
        {"name": "watch", "type": "omni.graph.action.OnObjectChange",
         "inputs": {"path": "/World/Cube.physics:mass"}},
        {"name": "changes", "type": "omni.graph.action.Counter"},
        connections=[("watch.outputs:changed", "changes.inputs:execIn")]), world=world)
    counts = []
    for mass in (1.0, 1.0, 2.0, 2.0, 3.0):
        world.attributes[("/World/Cube", "physics:mass")] = mass
        harness.run(1)
        counts.append(harness.output("changes", "count"))
    assert counts == [0, 0, 1, 1, 2]
    assert harness.output("watch", "propertyName") == "physics:mass"
