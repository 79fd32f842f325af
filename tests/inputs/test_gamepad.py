"""Gamepad nodes on scripted pads (graphflow.inputs.gamepad): OnGamepadInput, ReadGamepadState, DrawScreenSpaceText."""
import json

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.inputs.gamepad import (
    ELEMENTS,
    NeutralPad,
    PadChange,
    PadSpecError,
    ScriptedPad,
    attach_gamepad,
    gamepad_for,
    load_pad_timeline,
    parse_pad_spec,
    scripted_pad,
)
from graphflow.testing import GraphHarness, NodeHarness

DT = 0.1


def _node(type_id, changes, **inputs):
    harness = NodeHarness(type_id, inputs=inputs, time_step=DT)
    attach_gamepad(harness.world, ScriptedPad(changes))
    return harness


def test_button_presses_once_and_releases_once():
    node = _node("omni.graph.action.OnGamepadInput",
                 [PadChange("Face Button Bottom", 1.0, 0.2), PadChange("Face Button Bottom", 0.0, 0.5)])
    results = [node.tick() for _ in range(7)]
    assert [sorted(r.fired) for r in results] == [[], ["pressed"], [], [], ["released"], [], []]
    assert [r.outputs["isPressed"] for r in results] == [False, True, True, True, False, False, False]


def test_analog_button_presses_at_one_half_and_other_buttons_do_nothing():
    node = _node("omni.graph.action.OnGamepadInput",
                 [PadChange("Right Shoulder", 0.3, 0.1), PadChange("Right Shoulder", 0.5, 0.2),
                  PadChange("Right Shoulder", 0.7, 0.3), PadChange("Face Button Top", 1.0, 0.3),
                  PadChange("Right Shoulder", 0.49, 0.4)],
                 gamepadElementIn="Right Shoulder")
    assert [sorted(node.tick().fired) for _ in range(5)] == [[], ["pressed"], [], ["released"], []]


def test_press_and_release_within_one_step_fire_both():
    node = _node("omni.graph.action.OnGamepadInput",
                 [PadChange("D-Pad Up", 1.0, 0.15), PadChange("D-Pad Up", 0.0, 0.18)], gamepadElementIn="D-Pad Up")
    result = [node.tick() for _ in range(2)][1]
    assert result.fired == {"pressed", "released"} and result.outputs["isPressed"] is False


def test_second_pad_by_gamepad_id():
    changes = [PadChange("Face Button Bottom", 1.0, 0.1, pad=1), PadChange("Face Button Bottom", 1.0, 0.3)]
    pad_one = _node("omni.graph.action.OnGamepadInput", changes, gamepadId=1)
    assert [sorted(pad_one.tick().fired) for _ in range(3)] == [["pressed"], [], []]
    reader = _node("omni.graph.nodes.ReadGamepadState", changes, gamepadElement="Face Button Bottom", gamepadId=1)
    assert [reader.tick().outputs["value"] for _ in range(3)] == [1.0, 1.0, 1.0]


def test_a_pad_that_is_not_connected_is_a_run_time_error():
    node = NodeHarness("omni.graph.nodes.ReadGamepadState", inputs={"gamepadId": 2})
    with pytest.raises(GraphRuntimeError, match=r"inputs:gamepadId: no gamepad 2 \(connected: 0\)"):
        node.tick()


def test_axis_values_hold_and_the_deadzone_reads_zero():
    node = _node("omni.graph.nodes.ReadGamepadState",
                 [PadChange("Right Stick Y Axis", -0.75, 0.1), PadChange("Right Stick Y Axis", 0.1, 0.3),
                  PadChange("Right Stick Y Axis", 0.25, 0.4)],
                 gamepadElement="Right Stick Y Axis")
    results = [node.tick().outputs for _ in range(5)]
    assert [r["value"] for r in results] == [-0.75, -0.75, 0.0, 0.25, 0.25]
    assert [r["isPressed"] for r in results] == [True, True, False, True, True]


def test_trigger_and_button_values():
    changes = [PadChange("Left Trigger", 0.4, 0.1), PadChange("Face Button Left", 0.4, 0.1)]
    trigger = _node("omni.graph.nodes.ReadGamepadState", changes, gamepadElement="Left Trigger", deadzone=0.0)
    assert trigger.tick().outputs == {"value": 0.4, "isPressed": True}
    button = _node("omni.graph.nodes.ReadGamepadState", changes, gamepadElement="Face Button Left")
    assert button.tick().outputs == {"value": 0.4, "isPressed": False}      # a button is pressed from 0.5


def test_without_a_source_the_pad_is_neutral():
    node = NodeHarness("omni.graph.nodes.ReadGamepadState", inputs={"gamepadElement": "Left Stick X Axis"})
    assert isinstance(gamepad_for(node.world).source, NeutralPad)
    assert node.tick().outputs == {"value": 0.0, "isPressed": False}


def test_readers_share_one_snapshot_and_reset_replays_the_timeline():
    graph = GraphHarness({
        "settings": {"timeStep": DT},
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "stick", "type": "omni.graph.nodes.ReadGamepadState", "inputs": {"gamepadElement": "Left Stick X Axis"}},
            {"name": "text", "type": "graphflow.FormatText", "inputs": {"format": "x {value}"}},
            {"name": "draw", "type": "omni.graph.visualization.nodes.DrawScreenSpaceText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "draw.inputs:execIn"},
            {"src": "stick.outputs:value", "dst": "text.inputs:value"},
            {"src": "text.outputs:text", "dst": "draw.inputs:text"},
        ],
    })
    attach_gamepad(graph.world, scripted_pad(None, ["Left Stick X Axis=0.5@0.2", "Left Stick X Axis=-1@0.4"]))
    graph.run(ticks=6)
    assert graph.logs == ["x 0.0", "x 0.5", "x -1.0"]                  # logged when the text changes only
    graph.reset()
    graph.run(ticks=6)
    assert graph.logs == ["x 0.0", "x 0.5", "x -1.0"]


@pytest.mark.parametrize("spec, expected", [
    ("Left Stick X Axis=0.5@1.0", PadChange("Left Stick X Axis", 0.5, 1.0)),
    ("Right Stick Y Axis=-1@0.25", PadChange("Right Stick Y Axis", -1.0, 0.25)),
    ("1:D-Pad Left=1@2", PadChange("D-Pad Left", 1.0, 2.0, pad=1)),
])
def test_parse_pad_spec(spec, expected):
    assert parse_pad_spec(spec) == expected


@pytest.mark.parametrize("spec, fragment", [
    ("Left Stick X Axis@1", "expected ELEMENT=VALUE@TIME"),
    ("Left Stick Z Axis=1@1", "unknown gamepad element 'Left Stick Z Axis'"),
    ("Left Trigger=-0.5@1", r"Left Trigger takes values in \[0, 1\]"),
    ("Left Stick X Axis=1.5@1", r"takes values in \[-1, 1\]"),
])
def test_bad_pad_specs_say_why(spec, fragment):
    with pytest.raises(PadSpecError, match=fragment):
        parse_pad_spec(spec)


def test_pad_file(tmp_path):
    path = tmp_path / "pad.json"
    path.write_text(json.dumps({"gamepad": [{"element": "Face Button Bottom", "time": 3.0, "value": 1},
                                            {"element": "Right Stick Y Axis", "time": 1.0, "value": -1.0, "pad": 1}]}))
    assert load_pad_timeline(path) == [PadChange("Face Button Bottom", 1.0, 3.0),
                                       PadChange("Right Stick Y Axis", -1.0, 1.0, pad=1)]
    assert scripted_pad(path, ["Left Trigger=1@0.5"]).connected == {0, 1}
    path.write_text(json.dumps({"gamepad": [{"element": "Face Button Bottom", "value": 1}]}))
    with pytest.raises(PadSpecError, match=r"gamepad\[0\]: missing time"):
        load_pad_timeline(path)


def test_kit_element_tokens_are_the_allowed_tokens():
    assert len(ELEMENTS) == 20
    with pytest.raises(Exception, match="inputs:gamepadElementIn"):
        NodeHarness("omni.graph.action.OnGamepadInput", inputs={"gamepadElementIn": "Left Stick X Axis"})


STICK_LABEL_GRAPH = {
    "format": "graphflow", "formatVersion": [1, 0],
    "settings": {"timeStep": 0.25, "duration": 1.5},
    "nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "button", "type": "omni.graph.action.OnGamepadInput"},
        {"name": "stick", "type": "omni.graph.nodes.ReadGamepadState", "inputs": {"gamepadElement": "Right Stick Y Axis"}},
        {"name": "text", "type": "graphflow.FormatText", "inputs": {"format": "stick {value}"}},
        {"name": "draw", "type": "omni.graph.visualization.nodes.DrawScreenSpaceText"},
        {"name": "print", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "button"}},
    ],
    "connections": [
        {"src": "tick.outputs:tick", "dst": "draw.inputs:execIn"},
        {"src": "stick.outputs:value", "dst": "text.inputs:value"},
        {"src": "text.outputs:text", "dst": "draw.inputs:text"},
        {"src": "button.outputs:pressed", "dst": "print.inputs:execIn"},
    ],
}


def test_cli_gamepad_file_and_pad_flags(tmp_path, capsys):
    from graphflow.cli import main

    graph = tmp_path / "stick.json"
    graph.write_text(json.dumps(STICK_LABEL_GRAPH))
    pad_file = tmp_path / "pad.json"
    pad_file.write_text(json.dumps({"gamepad": [{"element": "Right Stick Y Axis", "time": 0.5, "value": -1.0}]}))
    assert main(["run", str(graph), "--gamepad", str(pad_file), "--pad", "Face Button Bottom=1@0.75",
                 "--pad", "Right Stick Y Axis=0.5@1.0"]) == 0
    assert capsys.readouterr().out.splitlines() == ["stick 0.0", "stick -1.0", "button", "stick 0.5"]
    assert main(["run", str(graph), "--pad", "Face Button Bottom@1"]) == 2
    assert "expected ELEMENT=VALUE@TIME" in capsys.readouterr().err
