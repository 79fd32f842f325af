"""Importing Isaac Sim action graphs from USD: composed connections, relative paths, legacy and unknown types."""
import json
import subprocess
import sys

import pytest
from conftest import USDA_SAMPLES as SAMPLES

from graphflow.testing import GraphHarness
from graphflow.usd.omnigraph import ImportProblem, import_graph

TINY_GRAPH = '''#usda 1.0
def Xform "World"
{
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        token flatCacheBacking = "Shared"
        int2 fileFormatVersion = (1, 3)

        def OmniGraphNode "on_tick"
        {
            token node:type = "omni.graph.action.OnTick"
            int node:typeVersion = 1
            custom uint outputs:tick (customData = {bool isExecution = 1})
        }
        def OmniGraphNode "constant"
        {
            token node:type = "omni.graph.nodes.ConstantDouble"
            int node:typeVersion = 1
            custom double inputs:value = 2.5
        }
        def OmniGraphNode "add"
        {
            token node:type = "omni.graph.nodes.Add"
            int node:typeVersion = 2
            custom token inputs:a
            delete token inputs:a.connect = </World/ActionGraph/stale.outputs:value>
            prepend token inputs:a.connect = <../constant.inputs:value>
            custom double inputs:b = 0.5
            custom token inputs:unusedByGraphflow = "x"
            uniform float2 ui:nodegraph:node:pos = (120, 40)
        }
        def OmniGraphNode "counter"
        {
            token node:type = "omni.graph.action.Counter"
            int node:typeVersion = 1
            prepend uint inputs:execIn.connect = <../on_tick.outputs:tick>
        }
        def OmniGraphNode "vendor_node"
        {
            token node:type = "com.example.vendor.Teleporter"
            int node:typeVersion = 1
            prepend uint inputs:execIn.connect = <../on_tick.outputs:tick>
        }
    }
}
'''


@pytest.fixture
def tiny_stage(tmp_path):
    path = tmp_path / "scene.usda"
    path.write_text(TINY_GRAPH)
    return path


def test_unknown_types_are_reported_with_their_prim_paths(tiny_stage):
    with pytest.raises(ImportProblem) as caught:
        import_graph(str(tiny_stage))
    assert caught.value.problems == [
        f"{tiny_stage}: node 'vendor_node' (/World/ActionGraph/vendor_node): unknown node type 'com.example.vendor.Teleporter'"]


def test_composed_relative_connections_and_values_import_and_run(tiny_stage, tmp_path):
    output = tmp_path / "graphs" / "imported.json"
    output.parent.mkdir()
    result = import_graph(str(tiny_stage), output_path=str(output), skip_unknown=True)
    document = result.document
    assert [n.name for n in document.nodes] == ["on_tick", "constant", "add", "counter"]
    assert {(c.src, c.dst) for c in document.connections} == {
        ("constant.outputs:value", "add.inputs:a"), ("on_tick.outputs:tick", "counter.inputs:execIn")}
    assert document.node("add").inputs == {"b": 0.5}
    assert document.settings["stage"] == "../scene.usda"
    assert document.ui["nodes"]["add"] == {"pos": [120.0, 40.0]}
    assert any("vendor_node" in w and "skipped" in w for w in result.warnings)
    assert any("inputs:unusedByGraphflow" in w and "dropped" in w for w in result.warnings)
    core_only = {"format": "graphflow", "formatVersion": [1, 0], "nodes": [dict(name=n.name, type=n.type, inputs=dict(n.inputs)) for n in document.nodes],
                 "connections": [{"src": c.src, "dst": c.dst} for c in document.connections]}
    harness = GraphHarness(core_only)
    harness.run(3)
    assert harness.output("counter", "count") == 3


def test_cli_import_writes_once_and_refuses_to_overwrite(tiny_stage, tmp_path):
    output = tmp_path / "out.json"

    def run(*args):
        return subprocess.run([sys.executable, "-m", "graphflow", "import", str(tiny_stage), *args],
                              capture_output=True, text=True)

    failed = run("-o", str(output))
    assert failed.returncode == 2 and not output.exists()
    done = run("-o", str(output), "--skip-unknown")
    assert done.returncode == 0, done.stderr
    assert json.loads(output.read_text())["settings"]["stage"] == "scene.usda"
    output.write_text("keep me\n")
    again = run("-o", str(output), "--skip-unknown")
    assert again.returncode == 2 and "already exists" in again.stderr
    assert output.read_text() == "keep me\n"


def test_not_usd_is_a_one_line_error(tmp_path):
    junk = tmp_path / "junk.usda"
    junk.write_text("this is not usd\n")
    with pytest.raises(ImportProblem) as caught:
        import_graph(str(junk))
    assert len(caught.value.problems) == 1 and "not a USD stage" in caught.value.problems[0]


def _sample(name):
    path = SAMPLES / name
    if not path.is_file():
        pytest.skip(f"{path} not present")
    return str(path)


def test_isaac_legacy_sensor_node_types_load_as_the_current_ones():
    document = import_graph(_sample("isaacsim_test_rename_node_type.usda")).document
    assert {node.name: node.type for node in document.nodes} == {
        "isaac_read_imu_node": "omni.isaac.isaac_sensor.IsaacReadIMU",
        "isaac_read_contact_sensor": "omni.isaac.isaac_sensor.IsaacReadContactSensor"}


def test_isaac_surface_gripper_template_with_old_header_keys():
    result = import_graph(_sample("isaacsim_OgnSurfaceGripperTemplate.usda"))
    node = result.document.nodes[0]
    # written at graphflow's version (3): the import mapped the authored v2's ports, so loading it warns of no migration
    assert node.type == "isaacsim.robot.surface_gripper.SurfaceGripper" and node.type_version == 3
    assert node.inputs == {"enabled": True}
    assert any("evaluator 'push'" in w for w in result.warnings)


def test_krabby_relative_connections_and_targets():
    result = import_graph(_sample("krabby_crab_simple.usda"))
    document = result.document
    controller = document.node("ArticulationController")
    assert controller.inputs["targetPrim"] == ["/krabby"]
    assert {(c.src, c.dst) for c in document.connections} >= {
        ("OnPlaybackTick.outputs:tick", "ArticulationController.inputs:execIn"),
        ("JointNameArray.outputs:array", "ArticulationController.inputs:jointNames"),
        ("JointCommandArray.outputs:array", "ArticulationController.inputs:positionCommand")}
    names = document.node("JointNameArray").inputs
    commands = document.node("JointCommandArray").inputs
    assert names["arraySize"] == 18 and names["input0"] == "FL_Body_Hip_RevoluteJoint"
    assert commands["input0"] == 0.0, "an extended input's value comes from customData omni:graph:attrValue"
    assert all(f"input{i}" in commands for i in range(18))


def test_isaac_gantry_graph_resolves_list_op_residue():
    result = import_graph(_sample("isaacsim_SurfaceGripper_gantry.usda"))      # every node type is known
    pairs = {(c.src, c.dst) for c in result.document.connections}
    # Kit left `delete ... = add.outputs:sum` and `prepend ... = maximum.outputs:maximum`
    assert ("maximum.outputs:maximum", "write_prim_attribute.inputs:value") in pairs
    assert ("add.outputs:sum", "write_prim_attribute.inputs:value") not in pairs
    assert ("on_tick.outputs:tick", "write_prim_attribute.inputs:execIn") in pairs
    assert ("constant_float_01.outputs:value", "multiply_01.inputs:b") in pairs
    assert len(result.document.nodes) == 36 and not any("skipped" in w for w in result.warnings)


def test_isaac_gantry_gamepad_nodes_import_with_their_inputs():
    document = import_graph(_sample("isaacsim_SurfaceGripper_gantry.usda")).document
    pairs = {(c.src, c.dst) for c in document.connections}
    assert ("on_gamepad_input.outputs:pressed", "surface_gripper.inputs:Toggle") in pairs
    assert ("read_gamepad_state_02.outputs:value", "multiply_01.inputs:a") in pairs
    assert ("read_gamepad_state.outputs:value", "multiply_03.inputs:a") in pairs
    assert ("read_gamepad_state_03.outputs:value", "multiply_04.inputs:b") in pairs
    elements = {node.name: node.inputs.get("gamepadElement") for node in document.nodes
                if node.type == "omni.graph.nodes.ReadGamepadState"}
    assert elements == {"read_gamepad_state": "Right Stick Y Axis", "read_gamepad_state_01": "Left Stick X Axis",
                        "read_gamepad_state_02": "Left Stick Y Axis", "read_gamepad_state_03": "Right Shoulder"}
    gamepad_button = document.node("on_gamepad_input")
    assert gamepad_button.type_version == 2 and gamepad_button.inputs == {}     # Kit's default: Face Button Bottom
    text = document.node("draw_screen_space_text_beta_").inputs
    assert text["position"] == pytest.approx([51.1, 92.2])
    assert text["text"].startswith("Use Gamepad to control Gantry")
