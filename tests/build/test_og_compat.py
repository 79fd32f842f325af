"""Isaac-style scripts (og.Controller.edit) run with only their import changed, build the graphs
graphflow ships, and what they build passes its checks."""
import importlib.util
import itertools
import json
import math
import shutil

import pytest
from conftest import GRAPHS, ROOT

from graphflow.build import og
from graphflow.cli import main
from graphflow.errors import BadInput
from graphflow.model import GraphError
from graphflow.testing.harness import GraphHarness
from graphflow.verdicts.checked_run import run_checked

SCRIPTS = ROOT / "tests" / "build" / "isaac_scripts"
_paths = (f"/World/Graph{n}" for n in itertools.count())   # og keeps graphs by path: one per test


def script(name: str):
    spec = importlib.util.spec_from_file_location(f"isaac_script_{name}", SCRIPTS / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def finished_like(graph, shipped_name: str, folder):
    """Give the built graph the shipped file's stage, checks and scenario, save it in *folder*."""
    shipped = json.loads((GRAPHS / f"{shipped_name}.json").read_text())
    built = graph.document.to_json()
    assert built["nodes"] == shipped["nodes"] and built["connections"] == shipped["connections"]
    for name, value in shipped["settings"].items():
        graph.setting(name, value)
    for check in shipped["checks"]:
        graph.check(check["check"], **{key: value for key, value in check.items() if key != "check"})
    path = folder / f"{shipped_name}.json"
    graph.save(path)
    if "scenario" in shipped:   # the scripted keys: the file and its key presses, as shipped
        shutil.copy(GRAPHS / shipped["scenario"]["keys"], folder)
        data = json.loads(path.read_text())
        data["scenario"] = shipped["scenario"]
        path.write_text(json.dumps(data))
    return path


@pytest.mark.slow
def test_ported_ur10_pick_place_script_builds_the_tuned_graph_and_passes_its_checks(tmp_path):
    graph = script("ur10_pick_place_tuned").create_pick_place_graph(next(_paths))
    path = finished_like(graph, "ur10_pick_place_tuned", tmp_path)
    assert main(["validate", str(path)]) == 0
    verdict = run_checked(path)
    assert verdict.failures == [] and verdict.passed
    assert "Gripper CLOSE command issued. Status: SUCCESS (Object Gripped)" in verdict.output
    assert verdict.stopped_by_graph


@pytest.mark.slow
def test_ported_gantry_script_builds_the_keyboard_graph_and_carries_the_box(tmp_path):
    graph = script("gantry_surface_gripper").create_gantry_graph(next(_paths))
    path = finished_like(graph, "gantry_keyboard", tmp_path)
    assert main(["validate", str(path)]) == 0
    verdict = run_checked(path)
    assert verdict.failures == [] and verdict.passed


def test_edit_again_extends_the_same_graph_and_deletes_in_omnigraph_order():
    keys, path = og.Controller.Keys, next(_paths)
    graph, nodes, _, lookup = og.Controller.edit({"graph_path": path, "evaluator_name": "execution"}, {
        keys.CREATE_NODES: [("tick", "omni.isaac.core_nodes.OnPhysicsStep"), ("count", "omni.graph.action.Counter")],
        keys.CREATE_VARIABLES: [("gain", og.Type(og.BaseDataType.DOUBLE))],
        keys.CONNECT: ("tick.outputs:step", f"{path}/count.inputs:execIn"),
    })
    assert [node.name for node in nodes] == ["tick", "count"] and set(lookup) == {"tick", "count"}
    assert graph.document.variables[0].type == "double"
    again, *_ = og.Controller.edit(path, {keys.DELETE_NODES: ["count"],
                                         keys.CREATE_NODES: [("count", "omni.graph.action.Counter"),
                                                             ("text", "graphflow.FormatText")],
                                         keys.SET_VALUES: [(("inputs:format", "text"), "{value} ticks")]})
    assert again is graph and og.get_graph_by_path(path) is graph
    assert graph.document.connections == ()   # deleting count took its connection with it
    assert graph.document.node("text").inputs == {"format": "{value} ticks"}   # ("inputs:x", node) spelling


def test_edit_refuses_what_it_cannot_build_with_one_line():
    keys = og.Controller.Keys
    with pytest.raises(BadInput, match="expose_prims not supported"):
        og.Controller.edit(next(_paths), {"expose_prims": []})
    path = next(_paths)
    with pytest.raises(GraphError, match="node 'write' input 'inputs:prim'|node 'write'.*no input 'primm'"):
        og.Controller.edit(path, {keys.CREATE_NODES: [("write", "omni.graph.nodes.WritePrimAttribute")],
                                  keys.SET_VALUES: [("write.inputs:primm", "/World/Cube")]})


def test_controller_set_connect_and_attribute_address_ports_by_their_full_path():
    keys, path = og.Controller.Keys, next(_paths)
    _, (tick, text, show), _, _ = og.Controller.edit(path, {keys.CREATE_NODES: [
        ("tick", "omni.graph.action.OnTick"), ("text", "graphflow.FormatText"), ("show", "omni.graph.ui_nodes.PrintText")]})
    og.Controller.set(og.Controller.attribute(f"{path}/text.inputs:format"), "t = {value}")
    og.Controller.set(og.Controller.attribute("inputs:value", text), 2.5)
    og.Controller.connect(f"{path}/tick.outputs:tick", f"{path}/show.inputs:execIn")
    og.Controller.connect(og.Controller.attribute(("outputs:text", text)), f"{path}/show.inputs:text")
    graph = og.get_graph_by_path(path)
    assert graph.document.node("text").inputs == {"format": "t = {value}", "value": 2.5}
    assert [c.src for c in graph.document.connections] == ["tick.outputs:tick", "text.outputs:text"]
    og.Controller.disconnect(f"{path}/tick.outputs:tick", f"{path}/show.inputs:execIn")
    assert len(graph.document.connections) == 1
    with pytest.raises(BadInput, match="/Nowhere/x.inputs:a: no graph made by og.Controller.edit holds it"):
        og.Controller.set("/Nowhere/x.inputs:a", 1)
    with pytest.raises(GraphError, match="node 'text' input 'inputs:formatt'"):
        og.Controller.set(f"{path}/text.inputs:formatt", "x")


def test_a_bundle_output_in_kits_older_underscore_spelling_connects_as_the_importer_reads_it():
    """Kit's bundle outputs were once properties named ``outputs_NAME``; scripts of that time connect them so."""
    keys, path = og.Controller.Keys, next(_paths)
    graph, *_ = og.Controller.edit(path, {
        keys.CREATE_NODES: [("read", "omni.graph.nodes.ReadPrim"), ("names", "omni.graph.nodes.GetAttributeNames")],
        keys.CONNECT: [("read.outputs_primBundle", "names.inputs:data")]})
    assert [(c.src, c.dst) for c in graph.document.connections] == [("read.outputs:primBundle", "names.inputs:data")]
    with pytest.raises(GraphError, match="'read.outputs_nothing' is not an output"):   # a port it does not have
        og.Controller.edit(path, {keys.CONNECT: [("read.outputs_nothing", "names.inputs:data")]})


def test_push_and_on_demand_graphs_build_as_action_graphs_with_one_line_each():
    """Kit's push evaluator and on-demand stage (a script calling evaluate per frame): ticked every step here."""
    keys, path = og.Controller.Keys, next(_paths)
    with pytest.warns(og.OgCompatWarning) as lines:
        graph, *_ = og.Controller.edit(
            {"graph_path": path, "evaluator_name": "push",
             "pipeline_stage": og.GraphPipelineStage.GRAPH_PIPELINE_STAGE_ONDEMAND},
            {keys.CREATE_NODES: [("tick", "omni.graph.action.OnTick"), ("count", "omni.graph.action.Counter")],
             keys.CONNECT: [("tick.outputs:tick", "count.inputs:execIn")]})
    assert [str(line.message) for line in lines] == [
        f"og.Controller.edit: {path}: evaluator 'push' built as an action graph (execution)",
        f"og.Controller.edit: {path}: pipeline stage on-demand built as a graph evaluated every tick "
        "(the script's own evaluate calls are not carried over)"]
    assert len(graph.document.connections) == 1


def test_renderer_nodes_are_dropped_with_their_connections_and_values_as_the_importer_drops_them():
    keys, path = og.Controller.Keys, next(_paths)
    with pytest.warns(og.OgCompatWarning) as lines:
        graph, nodes, _, _ = og.Controller.edit({"graph_path": path, "evaluator_name": "execution"}, {
            keys.CREATE_NODES: [("tick", "omni.graph.action.OnPlaybackTick"),
                                ("render", "omni.isaac.core_nodes.IsaacCreateRenderProduct"),
                                ("camera", "isaacsim.ros2.bridge.ROS2CameraHelper"),
                                ("count", "omni.graph.action.Counter")],
            keys.CONNECT: [("tick.outputs:tick", "render.inputs:execIn"),
                           ("render.outputs:renderProductPath", "camera.inputs:renderProductPath"),
                           ("tick.outputs:tick", "count.inputs:execIn")],
            keys.SET_VALUES: [("render.inputs:cameraPrim", "/World/Camera"), ("camera.inputs:type", "rgb")]})
    assert [str(line.message).split(": dropped")[0] for line in lines] == [
        "og.Controller.edit: node 'render' (omni.isaac.core_nodes.IsaacCreateRenderProduct)",
        "og.Controller.edit: node 'camera' (isaacsim.ros2.bridge.ROS2CameraHelper)"]
    assert all("renderer" in str(line.message) for line in lines)
    assert [node.name for node in nodes] == ["tick", "count"]
    assert [(c.src, c.dst) for c in graph.document.connections] == [("tick.outputs:tick", "count.inputs:execIn")]
    og.Controller.set(f"{path}/camera.inputs:topicName", "rgb")   # later edits of a dropped node go too
    assert [node.name for node in graph.document.nodes] == ["tick", "count"]


def test_a_constant_read_from_its_input_value_feeds_the_connection_as_in_kit():
    """Kit's constants hold their value on ``inputs:value`` and scripts connect from it (ConstantToken -> array)."""
    keys, path = og.Controller.Keys, next(_paths)
    graph, *_ = og.Controller.edit(path, {
        keys.CREATE_NODES: [("left", "omni.graph.nodes.ConstantToken"), ("right", "omni.graph.nodes.ConstantToken"),
                            ("names", "omni.graph.nodes.ConstructArray")],
        keys.CREATE_ATTRIBUTES: [("names.inputs:input1", "token")],
        keys.CONNECT: [("left.inputs:value", "names.inputs:input0"), ("right.inputs:value", "names.inputs:input1")],
        keys.SET_VALUES: [("names.inputs:arraySize", 2), ("names.inputs:arrayType", "token[]"),
                          ("left.inputs:value", "wheel_left_joint"), ("right.inputs:value", "wheel_right_joint")]})
    assert [c.src for c in graph.document.connections] == ["left.outputs:value", "right.outputs:value"]
    og.Controller.edit(path, {   # a consumer pulls the array each tick
        keys.CREATE_NODES: [("tick", "omni.graph.action.OnTick"), ("text", "graphflow.FormatText"),
                            ("show", "omni.graph.ui_nodes.PrintText")],
        keys.CONNECT: [("tick.outputs:tick", "show.inputs:execIn"), ("names.outputs:array", "text.inputs:value"),
                       ("text.outputs:text", "show.inputs:text")]})
    harness = GraphHarness(graph.document)
    harness.run(1)
    assert list(harness.output("names", "array")) == ["wheel_left_joint", "wheel_right_joint"]


def test_create_attributes_names_ports_the_node_type_declares_or_refuses_with_one_line():
    keys, path = og.Controller.Keys, next(_paths)
    og.Controller.edit(path, {keys.CREATE_NODES: [("names", "omni.graph.nodes.ConstructArray")],
                              keys.CREATE_ATTRIBUTES: [("names.inputs:input2", "token")]})
    with pytest.raises(BadInput, match="create_attributes names.inputs:speed: omni.graph.nodes.ConstructArray "
                                       "has no inputs 'speed'"):
        og.Controller.edit(path, {keys.CREATE_ATTRIBUTES: [("names.inputs:speed", "double")]})



def test_variables_of_every_og_base_type_scripts_use_are_created():
    keys, path = og.Controller.Keys, next(_paths)
    graph, *_ = og.Controller.edit(path, {keys.CREATE_VARIABLES: [
        ("domainID", og.Type(og.BaseDataType.UCHAR), 7), ("vehicleID", og.Type(og.BaseDataType.INT), 1),
        ("gains", og.Type(og.BaseDataType.DOUBLE, 3), [1.0, 2.0, 3.0]), ("name", "string", "quad0")]})
    assert [(v.name, v.type, v.default) for v in graph.document.variables] == [
        ("domainID", "uchar", 7), ("vehicleID", "int", 1), ("gains", "double[3]", [1.0, 2.0, 3.0]),
        ("name", "string", "quad0")]


def test_isaac_4_use_path_is_dropped_with_a_line_and_false_keeps_the_target_prim():
    """IsaacArticulationController 4.x: usePath chose robotPath (true) or targetPrim (false); since 4.5 robotPath
    is used when set, else targetPrim (the .ogn), so false means the robotPath given beside it is not used."""
    keys, path = og.Controller.Keys, next(_paths)
    with pytest.warns(og.OgCompatWarning) as lines:
        graph, *_ = og.Controller.edit(path, {
            keys.CREATE_NODES: [("arm", "omni.isaac.core_nodes.IsaacArticulationController"),
                                ("base", "omni.isaac.core_nodes.IsaacArticulationController")],
            keys.SET_VALUES: [("arm.inputs:usePath", True), ("arm.inputs:robotPath", "/World/Arm"),
                              ("base.inputs:usePath", False), ("base.inputs:robotPath", "/World/Old"),
                              ("base.inputs:targetPrim", ["/World/Base"])]})
    assert [str(line.message).split(": dropped")[0] for line in lines] == [
        "og.Controller.edit: node 'arm' input 'inputs:usePath' = True",
        "og.Controller.edit: node 'base' input 'inputs:usePath' = False",
        "og.Controller.edit: node 'base' input 'inputs:robotPath' = '/World/Old'"]
    assert graph.document.node("arm").inputs == {"robotPath": "/World/Arm"}
    assert graph.document.node("base").inputs == {"targetPrim": ["/World/Base"]}


def test_a_generic_subscribers_field_output_is_read_from_its_message_as_kits_field_outputs():
    """Kit's ROS2Subscriber has one output per field (std_msgs/Float32: outputs:data); here a ROS2MessageField
    node reads it from outputs:message, holding the type's default (0.0) until a message arrives, as Kit does."""
    keys, path = og.Controller.Keys, next(_paths)
    with pytest.warns(og.OgCompatWarning, match="output 'outputs:data': .* by node 'pan_data'"):
        graph, *_ = og.Controller.edit(path, {
            keys.CREATE_VARIABLES: [("pan", "float", 0.5)],
            keys.CREATE_NODES: [("tick", "omni.graph.action.OnPlaybackTick"),
                                ("pan", "omni.isaac.ros2_bridge.ROS2Subscriber"),
                                ("write", "omni.graph.core.WriteVariable")],
            keys.CONNECT: [("tick.outputs:tick", "pan.inputs:execIn"), ("tick.outputs:tick", "write.inputs:execIn"),
                           (f"{path}/pan.outputs:data", "write.inputs:value")],
            keys.SET_VALUES: [("pan.inputs:messageName", "Float32"), ("pan.inputs:topicName", "pan"),
                              ("write.inputs:variableName", "pan")]})
    assert graph.document.node("pan_data").inputs == {"field": "data"}
    harness = GraphHarness(graph.document)
    harness.run(1)
    assert harness.instance.variables["pan"] == 0.0


def test_an_isaac_4_surface_gripper_script_maps_as_the_importer_maps_a_v1_node():
    """omni.isaac.surface_gripper.SurfaceGripper only ever named v1: its inputs go to graphflow.LegacySurfaceGripper
    (BendAngle degrees -> radians), Close/Open to a current gripper node commanding it, outputs:Closed is isClosed."""
    keys, path = og.Controller.Keys, next(_paths)
    with pytest.warns(og.OgCompatWarning):
        graph, *_ = og.Controller.edit(path, {
            keys.CREATE_NODES: [("tick", "omni.graph.action.OnPlaybackTick"),
                                ("close", "omni.graph.action.OnImpulseEvent"),
                                ("gripper", "omni.isaac.surface_gripper.SurfaceGripper"),
                                ("closed", "omni.graph.nodes.ToString")],
            keys.CONNECT: [("tick.outputs:tick", "gripper.inputs:onStep"), ("close.outputs:execOut", "gripper.inputs:Close"),
                           ("gripper.outputs:Closed", "closed.inputs:value")],
            keys.SET_VALUES: [("gripper.inputs:ParentRigidBody", "/World/Tool"), ("gripper.inputs:BendAngle", 90.0),
                              ("gripper.inputs:GripThreshold", 0.02)]})
    assert graph.document.node("gripper").type == "graphflow.LegacySurfaceGripper"
    assert graph.document.node("gripper").inputs == {"endEffectorPrim": ["/World/Tool"],
                                                     "bendAngle": pytest.approx(math.pi / 2), "gripThreshold": 0.02}
    assert {(c.src, c.dst) for c in graph.document.connections} == {
        ("tick.outputs:tick", "gripper.inputs:execIn"), ("close.outputs:execOut", "gripper_command.inputs:Close"),
        ("gripper.outputs:gripperPrim", "gripper_command.inputs:SurfaceGripper"),
        ("gripper.outputs:isClosed", "closed.inputs:value")}


def test_a_generic_publishers_field_values_gather_into_message_fields_and_field_wires_drop_with_a_line():
    keys, path = og.Controller.Keys, next(_paths)
    with pytest.warns(og.OgCompatWarning) as lines:
        graph, *_ = og.Controller.edit(path, {
            keys.CREATE_NODES: [("time", "omni.isaac.core_nodes.IsaacReadSimulationTime"),
                                ("pub", "omni.isaac.ros2_bridge.ROS2Publisher")],
            keys.CONNECT: [("time.outputs:simulationTime", "pub.inputs:header:stamp:sec")],
            keys.SET_VALUES: [("pub.inputs:messagePackage", "sensor_msgs"), ("pub.inputs:messageName", "JointState"),
                              ("pub.inputs:name", ["finger"]), ("pub.inputs:position", [0.5])]})
        og.Controller.set(f"{path}/pub.inputs:header:frame_id", "gripper")
    assert json.loads(graph.document.node("pub").inputs["messageFields"]) == {
        "name": ["finger"], "position": [0.5], "header:frame_id": "gripper"}
    assert graph.document.connections == ()
    assert "input 'inputs:header:stamp:sec': connection from time.outputs:simulationTime dropped" in str(lines[0].message)


def test_skip_unknown_leaves_out_types_graphflow_lacks_with_one_line_as_import_does(monkeypatch):
    keys, path = og.Controller.Keys, next(_paths)
    commands = {keys.CREATE_NODES: [("tick", "omni.graph.action.OnPlaybackTick"),
                                    ("px4", "pegasus.simulator.PegasusMultirotorPX4Node"),
                                    ("clock", "isaacsim.ros2.bridge.ROS2PublishClock")],
                keys.CONNECT: [("tick.outputs:tick", "px4.inputs:execIn"), ("tick.outputs:tick", "clock.inputs:execIn")],
                keys.SET_VALUES: [("px4.inputs:numRotors", 4)]}
    with pytest.raises(GraphError, match="node 'px4': unknown node type 'pegasus.simulator.PegasusMultirotorPX4Node'"):
        og.Controller.edit(path, commands)
    monkeypatch.setattr(og, "skip_unknown", True)
    with pytest.warns(og.OgCompatWarning, match="node 'px4' .*unknown node type; skipped"):
        graph, nodes, _, _ = og.Controller.edit(next(_paths), commands)
    assert [node.name for node in nodes] == ["tick", "clock"]
    assert [(c.src, c.dst) for c in graph.document.connections] == [("tick.outputs:tick", "clock.inputs:execIn")]


def test_a_relative_target_path_resolves_against_the_nodes_prim_as_usd_resolves_relationship_targets():
    """Scripts target the prim holding the graph with "../.." from the node (graph /World/quad/Graph, node prim
    /World/quad/Graph/where: ".." is the graph, "../.." the prim holding it)."""
    keys = og.Controller.Keys
    graph, *_ = og.Controller.edit("/World/quad/Graph", {
        keys.CREATE_NODES: [("where", "omni.graph.nodes.GetPrimPath")],
        keys.SET_VALUES: [("where.inputs:prim", "../..")]})
    og.Controller.set("/World/quad/Graph/where.inputs:prim", ["../../Rotor"])
    assert graph.document.node("where").inputs == {"prim": ["/World/quad/Rotor"]}
    og.Controller.edit(graph, {keys.SET_VALUES: [("where.inputs:prim", "../..")]})
    assert graph.document.node("where").inputs == {"prim": ["/World/quad"]}
