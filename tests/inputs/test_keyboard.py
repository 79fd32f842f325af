"""omni.graph.action.OnKeyboardInput with scripted key timelines (graphflow.inputs.keyboard)."""
import json

import pytest

from graphflow.inputs.keyboard import (
    KeyAction,
    KeySpecError,
    NoKeys,
    ScriptedKeys,
    attach_keyboard,
    keyboard_for,
    load_key_timeline,
    parse_key_spec,
)
from graphflow.testing import GraphHarness, NodeHarness

DT = 0.1


def _node(timeline, **inputs):
    harness = NodeHarness("omni.graph.action.OnKeyboardInput", inputs=inputs, time_step=DT)
    actions = [action for spec in timeline for action in parse_key_spec(spec)]
    attach_keyboard(harness.world, ScriptedKeys(actions))
    return harness


def _fired_per_tick(harness, ticks):
    return [sorted(harness.tick().fired) for _ in range(ticks)]


def test_held_interval_presses_once_and_releases_once():
    node = _node(["A@0.2-0.5"])
    results = [node.tick() for _ in range(7)]
    assert [sorted(r.fired) for r in results] == [[], ["pressed"], [], [], ["released"], [], []]
    assert [r.outputs["isPressed"] for r in results] == [False, True, True, True, False, False, False]
    assert results[1].outputs["keyOut"] == "A"


def test_tap_is_held_for_one_step():
    node = _node(["Space@0.3"], keyIn="Space")
    assert _fired_per_tick(node, 5) == [[], [], ["pressed"], ["released"], []]


def test_other_keys_do_nothing():
    node = _node(["B@0.1-0.3", "Up@0.2"], keyIn="A")
    assert _fired_per_tick(node, 5) == [[]] * 5


def test_explicit_down_and_up():
    node = _node(["Left@0.2:down", "Left@0.4:up"], keyIn="Left")
    assert _fired_per_tick(node, 5) == [[], ["pressed"], [], ["released"], []]


def test_required_modifier_must_be_held_before_the_key():
    node = _node(["LeftShift@0.1-0.6", "A@0.3-0.4", "A@0.8"], keyIn="A", shiftIn=True)
    assert _fired_per_tick(node, 9) == [[], [], ["pressed"], ["released"], [], [], [], [], []]


def test_right_hand_modifier_counts():
    node = _node(["RightControl@0.1-0.5", "A@0.2"], keyIn="A", ctrlIn=True)
    assert _fired_per_tick(node, 4) == [[], ["pressed"], ["released"], []]


def test_releasing_the_required_modifier_releases():
    node = _node(["LeftAlt@0.1-0.3", "F5@0.2-0.6"], keyIn="F5", altIn=True)
    assert _fired_per_tick(node, 7) == [[], ["pressed"], ["released"], [], [], [], []]


def test_unrequested_modifier_blocks_the_press():
    node = _node(["LeftShift@0.1-0.4", "A@0.2", "A@0.6"], keyIn="A")
    assert _fired_per_tick(node, 8) == [[], [], [], [], [], ["pressed"], ["released"], []]


def test_press_and_release_within_one_step_fire_both():
    harness = NodeHarness("omni.graph.action.OnKeyboardInput", inputs={"keyIn": "Key1"}, time_step=DT)
    attach_keyboard(harness.world, ScriptedKeys([KeyAction("Key1", 0.15, "down"), KeyAction("Key1", 0.18, "up")]))
    result = [harness.tick() for _ in range(2)][1]
    assert result.fired == {"pressed", "released"}
    assert result.outputs["isPressed"] is False


def test_pressed_runs_downstream_before_released_in_a_graph():
    graph = GraphHarness({
        "settings": {"timeStep": DT},
        "nodes": [
            {"name": "key", "type": "omni.graph.action.OnKeyboardInput", "inputs": {"keyIn": "Enter"}},
            {"name": "down", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "down"}},
            {"name": "up", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "up"}},
        ],
        "connections": [
            {"src": "key.outputs:pressed", "dst": "down.inputs:execIn"},
            {"src": "key.outputs:released", "dst": "up.inputs:execIn"},
        ],
    })
    attach_keyboard(graph.world, ScriptedKeys([KeyAction("Enter", 0.2, "down"), KeyAction("Enter", 0.2, "up"),
                                               KeyAction("Enter", 0.4, "tap")]))
    graph.run(ticks=5)
    assert graph.logs == ["down", "up", "down", "up"]


def test_two_nodes_see_the_same_events_and_reset_replays_the_timeline():
    graph = GraphHarness({
        "settings": {"timeStep": DT},
        "nodes": [{"name": name, "type": "omni.graph.action.OnKeyboardInput", "inputs": {"keyIn": "PageUp"}}
                  for name in ("first", "second")]
        + [{"name": "print", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "page up"}}],
        "connections": [{"src": f"{name}.outputs:pressed", "dst": "print.inputs:execIn"}
                        for name in ("first", "second")],
    })
    attach_keyboard(graph.world, ScriptedKeys(parse_key_spec("PageUp@0.3")))
    graph.run(ticks=4)
    assert graph.logs == ["page up", "page up"]
    graph.reset()
    graph.run(ticks=4)
    assert graph.logs == ["page up", "page up"]


def test_world_without_keyboard_has_no_keys():
    node = NodeHarness("omni.graph.action.OnKeyboardInput")
    assert isinstance(keyboard_for(node.world).source, NoKeys)
    assert node.tick().fired == set()


@pytest.mark.parametrize("spec, expected", [
    ("A@1.5", [KeyAction("A", 1.5, "tap")]),
    ("A@1.5:up", [KeyAction("A", 1.5, "up")]),
    ("PageDown@1-2.25", [KeyAction("PageDown", 1.0, "down"), KeyAction("PageDown", 2.25, "up")]),
])
def test_parse_key_spec(spec, expected):
    assert parse_key_spec(spec) == expected


@pytest.mark.parametrize("spec, fragment", [
    ("A", "expected KEY@TIME"),
    ("Shift@1", "unknown key 'Shift'"),
    ("A@2-1", "must come after"),
    ("A@1:hold", "expected KEY@TIME"),
])
def test_bad_key_specs_say_why(spec, fragment):
    with pytest.raises(KeySpecError, match=fragment):
        parse_key_spec(spec)


def test_key_file(tmp_path):
    path = tmp_path / "keys.json"
    path.write_text(json.dumps({"keys": ["A@0.5", "Up@1-2"]}))
    assert [a.kind for a in load_key_timeline(path)] == ["tap", "down", "up"]
    path.write_text(json.dumps({"keys": "A@0.5"}))
    with pytest.raises(KeySpecError, match="'keys' list"):
        load_key_timeline(path)


def test_unknown_key_token_is_rejected_at_load_time():
    with pytest.raises(Exception, match="inputs:keyIn"):
        NodeHarness("omni.graph.action.OnKeyboardInput", inputs={"keyIn": "Shift"})


def test_read_keyboard_state_reports_the_key_and_modifiers_held_each_step():
    harness = NodeHarness("omni.graph.nodes.ReadKeyboardState", inputs={"key": "W"}, time_step=DT)
    attach_keyboard(harness.world, ScriptedKeys(
        [a for spec in ("W@0.2-0.4", "RightShift@0.3-0.5") for a in parse_key_spec(spec)]))
    states = [(r.outputs["isPressed"], r.outputs["shiftOut"]) for r in (harness.tick() for _ in range(6))]
    assert states == [(False, False), (True, False), (True, True), (False, True), (False, False), (False, False)]
