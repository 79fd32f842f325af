"""Mouse nodes on a scripted mouse (graphflow.inputs.mouse): OnMouseInput and ReadMouseState."""
import json

import pytest

from graphflow.inputs.mouse import (
    MouseChange,
    MouseSpecError,
    ScriptedMouse,
    attach_mouse,
    load_mouse_timeline,
    parse_mouse_spec,
)
from graphflow.testing import NodeHarness

DT = 0.1
ON_MOUSE, READ_MOUSE = "omni.graph.action.OnMouseInput", "omni.graph.nodes.ReadMouseState"


def _node(type_id, changes, **inputs):
    harness = NodeHarness(type_id, inputs=inputs, time_step=DT)
    attach_mouse(harness.world, ScriptedMouse(changes))
    return harness


def test_button_press_and_release_fire_once_each():
    node = _node(ON_MOUSE, [MouseChange("Left Button", 1.0, 0.2), MouseChange("Right Button", 1.0, 0.3),
                            MouseChange("Left Button", 0.0, 0.5)])
    results = [node.tick() for _ in range(7)]
    assert [sorted(r.fired) for r in results] == [[], ["pressed"], [], [], ["released"], [], []]
    assert [r.outputs["isPressed"] for r in results] == [False, True, True, True, False, False, False]
    assert all(r.outputs["value"] == (0.0, 0.0) for r in results)


def test_a_click_within_one_step_fires_pressed_and_released():
    node = _node(ON_MOUSE, [MouseChange("Middle Button", 1.0, 0.12), MouseChange("Middle Button", 0.0, 0.15)],
                 mouseElement="Middle Button")
    result = [node.tick() for _ in range(2)][1]
    assert result.fired == {"pressed", "released"} and result.outputs["isPressed"] is False


def test_moves_fire_once_per_step_with_the_last_position_normalized_or_in_pixels():
    moves = [MouseChange("Position", (0.1, 0.2), 0.1), MouseChange("Position", (0.25, 0.5), 0.15),
             MouseChange("Left Button", 1.0, 0.3)]
    normalized = _node(ON_MOUSE, moves, mouseElement="Normalized Move")
    results = [normalized.tick() for _ in range(3)]
    assert [sorted(r.fired) for r in results] == [["valueChanged"], ["valueChanged"], []]
    assert results[1].outputs["value"] == (0.25, 0.5)
    pixels = _node(ON_MOUSE, moves, mouseElement="Pixel Move")
    assert [pixels.tick() for _ in range(2)][1].outputs["value"] == (320.0, 360.0)   # of the nominal 1280x720


def test_scrolls_in_one_step_add_up():
    node = _node(ON_MOUSE, [MouseChange("Scroll", (0.0, 1.0), 0.15), MouseChange("Scroll", (0.0, 2.0), 0.18),
                            MouseChange("Position", (0.5, 0.5), 0.3)], mouseElement="Scroll")
    results = [node.tick() for _ in range(3)]
    assert [sorted(r.fired) for r in results] == [[], ["valueChanged"], []]
    assert results[1].outputs["value"] == (0.0, 3.0)


def test_read_mouse_state_reads_buttons_and_the_pointer():
    changes = [MouseChange("Position", (0.5, 0.25), 0.1), MouseChange("Back Button", 1.0, 0.2)]
    button = _node(READ_MOUSE, changes, mouseElement="Back Button")
    assert [button.tick().outputs["isPressed"] for _ in range(3)] == [False, True, True]
    pointer = _node(READ_MOUSE, changes, mouseElement="Pixel Mouse Coordinates", useRelativeCoords=True)
    outputs = [pointer.tick().outputs for _ in range(2)][1]
    assert outputs["coords"] == (640.0, 180.0) and outputs["isPressed"] is False and outputs["window"] == ""


def test_headless_without_a_mouse_nothing_fires_and_nothing_is_held():
    node = NodeHarness(ON_MOUSE, time_step=DT)
    assert not any(node.tick().fired for _ in range(5))
    state = NodeHarness(READ_MOUSE, {"mouseElement": "Normalized Mouse Coordinates"}, time_step=DT).tick().outputs
    assert state["coords"] == (0.0, 0.0) and state["isPressed"] is False


def test_reset_replays_the_timeline():
    node = _node(ON_MOUSE, [MouseChange("Left Button", 1.0, 0.1)])
    first = [sorted(node.tick().fired) for _ in range(2)]
    node.world.reset()                                  # the world rewinds its mouse, as a new run
    node.reset()
    assert [sorted(node.tick().fired) for _ in range(2)] == first == [["pressed"], []]


@pytest.mark.parametrize("spec, expected", [
    ("Left Button=1@0.5", MouseChange("Left Button", 1.0, 0.5)),
    ("Position=0.25, 0.5@1", MouseChange("Position", (0.25, 0.5), 1.0)),
    ("Scroll=0,-1@2", MouseChange("Scroll", (0.0, -1.0), 2.0)),
])
def test_parse_mouse_spec(spec, expected):
    assert parse_mouse_spec(spec) == expected


@pytest.mark.parametrize("spec, fragment", [
    ("Left Button@1", "expected ELEMENT=VALUE@TIME"),
    ("Wheel=1@1", "unknown mouse element 'Wheel'"),
    ("Left Button=0.5@1", "a button is 1 (down) or 0 (up)"),
    ("Position=1.5,0@1", "each coordinate in [0, 1]"),
    ("Scroll=1@1", "two numbers [x, y]"),
])
def test_bad_mouse_specs_say_why(spec, fragment):
    with pytest.raises(MouseSpecError, match=fragment.replace("[", r"\[").replace("(", r"\(").replace(")", r"\)")):
        parse_mouse_spec(spec)


def test_mouse_file(tmp_path):
    path = tmp_path / "mouse.json"
    path.write_text(json.dumps({"mouse": [{"element": "Position", "time": 0.5, "value": [0.5, 0.5]},
                                          {"element": "Left Button", "time": 1.0, "value": 1}]}))
    assert load_mouse_timeline(path) == [MouseChange("Position", (0.5, 0.5), 0.5),
                                         MouseChange("Left Button", 1.0, 1.0)]
    path.write_text(json.dumps({"mouse": [{"element": "Left Button", "time": 1.0}]}))
    with pytest.raises(MouseSpecError, match=r"mouse\[0\]: missing value"):
        load_mouse_timeline(path)


CLICK_GRAPH = {
    "format": "graphflow", "formatVersion": [1, 0],
    "settings": {"timeStep": 0.25, "duration": 1.5},
    "nodes": [
        {"name": "click", "type": ON_MOUSE},
        {"name": "print", "type": "omni.graph.ui_nodes.PrintText", "inputs": {"text": "clicked"}},
    ],
    "connections": [{"src": "click.outputs:pressed", "dst": "print.inputs:execIn"}],
}


def test_cli_mouse_file_click_flags_and_the_scenario(tmp_path, capsys):
    from graphflow.cli import main

    graph = tmp_path / "click.json"
    graph.write_text(json.dumps(CLICK_GRAPH))
    mouse_file = tmp_path / "mouse.json"
    mouse_file.write_text(json.dumps({"mouse": [{"element": "Left Button", "time": 0.5, "value": 1}]}))
    assert main(["run", str(graph), "--mouse", str(mouse_file), "--click", "Left Button=0@0.75",
                 "--click", "Left Button=1@1.0"]) == 0
    assert capsys.readouterr().out.splitlines() == ["clicked", "clicked"]
    assert main(["run", str(graph)]) == 0                       # headless, no mouse: never fires
    assert capsys.readouterr().out.splitlines() == []
    graph.write_text(json.dumps({**CLICK_GRAPH, "scenario": {"mouse": ["Left Button=1@0.25"]}}))
    assert main(["run", str(graph)]) == 0
    assert capsys.readouterr().out.splitlines() == ["clicked"]
    assert main(["run", str(graph), "--click", "Left Button@1"]) == 2
    assert "expected ELEMENT=VALUE@TIME" in capsys.readouterr().err


def test_a_scenario_table_case_scripts_the_mouse(tmp_path, capsys):
    from graphflow.cli import main

    graph = {"format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.25, "duration": 3.0},
             "nodes": [{"name": "click", "type": ON_MOUSE}, {"name": "stop", "type": "graphflow.StopRun"}],
             "connections": [{"src": "click.outputs:pressed", "dst": "stop.inputs:execIn"}],
             "checks": [{"check": "stopsBy", "time": 1.0}]}
    (tmp_path / "click.json").write_text(json.dumps(graph))
    table = tmp_path / "table.json"
    table.write_text(json.dumps({"format": "graphflow-cases", "formatVersion": [1, 0], "graph": "click.json", "cases": [
        {"name": "clicked", "mouse": ["Left Button=1@0.5"]},
        {"name": "too late", "mouse": ["Left Button=1@2"], "expect": {"fail": "stops by itself"}},
        {"name": "wrongly expected", "mouse": ["Left Button=1@2"]}]}))
    assert main(["test", str(table), "-j", "1"]) == 1
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith(f"PASS {table}::clicked") and lines[1].startswith(f"XFAIL {table}::too late")
    rerun = next(line.strip() for line in lines if line.strip().startswith("re-run:"))
    assert rerun == f"re-run: graphflow run {tmp_path / 'click.json'} --click 'Left Button=1@2'"
