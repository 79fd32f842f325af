"""Import mapping of Isaac node versions graphflow runs differently (graphflow/usd/node_mapping.py)."""
import json

import pytest

from graphflow.usd.omnigraph import ImportProblem, import_graph

HEADER = '''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Xform "World"
{
    def Cube "Tool"
    {
    }
    def OmniGraph "ActionGraph"
    {
        token evaluator:type = "execution"
        def OmniGraphNode "on_tick"
        {
            token node:type = "omni.graph.action.OnTick"
            int node:typeVersion = 1
            custom uint outputs:tick
        }
'''
FOOTER = '''    }
}
'''


def _import(tmp_path, nodes):
    stage = tmp_path / "scene.usda"
    stage.write_text(HEADER + nodes + FOOTER)
    return import_graph(str(stage), output_path=str(tmp_path / "graph.json"))


def test_v1_surface_gripper_becomes_the_legacy_gripper_and_a_command_node(tmp_path):
    result = _import(tmp_path, '''
        def OmniGraphNode "gripper"
        {
            token node:type = "omni.isaac.surface_gripper.SurfaceGripper"
            int node:typeVersion = 1
            custom float inputs:GripThreshold = 0.02
            custom float inputs:BendAngle = 15
            custom float inputs:Stiffness = 5000
            custom bool inputs:RetryClose = 1
            custom rel inputs:ParentRigidBody = </World/Tool>
            custom uint inputs:onStep
            prepend uint inputs:onStep.connect = </World/ActionGraph/on_tick.outputs:tick>
            custom uint inputs:Close
            prepend uint inputs:Close.connect = </World/ActionGraph/on_tick.outputs:tick>
        }
''')
    document = result.document
    gripper = document.node("gripper")
    assert gripper.type == "graphflow.LegacySurfaceGripper"
    assert gripper.inputs == {"gripThreshold": pytest.approx(0.02), "bendAngle": pytest.approx(0.2617993877991494),
                              "kp": 5000.0, "endEffectorPrim": ["/World/Tool"]}
    assert document.node("gripper_command").type == "isaacsim.robot.surface_gripper.SurfaceGripper"
    assert {(c.src, c.dst) for c in document.connections} == {
        ("on_tick.outputs:tick", "gripper.inputs:execIn"),
        ("on_tick.outputs:tick", "gripper_command.inputs:Close"),
        ("gripper.outputs:gripperPrim", "gripper_command.inputs:SurfaceGripper")}
    lines = "\n".join(result.warnings)
    assert "input 'BendAngle' mapped to graphflow.LegacySurfaceGripper 'bendAngle' = 15.0 deg -> 0.2617993877991494 rad" in lines
    assert "input 'Stiffness' mapped to graphflow.LegacySurfaceGripper 'kp' = 5000.0" in lines
    assert "input 'RetryClose' = True not mapped: graphflow's legacy gripper closes once per command" in lines
    assert "Close/Open connections mapped to a new isaacsim.robot.surface_gripper.SurfaceGripper node 'gripper_command'" in lines


def test_old_pick_place_robot_inputs_become_robot_prim(tmp_path):
    result = _import(tmp_path, '''
        def OmniGraphNode "controller"
        {
            token node:type = "omni.isaac.examples_nodes.IsaacPickPlaceController"
            int node:typeVersion = 1
            custom string inputs:robotModel = "UR10"
            custom bool inputs:usePath = 1
            custom string inputs:robotPrimPath = "/World/Tool"
        }
''')
    assert result.document.node("controller").inputs["robotPrim"] == ["/World/Tool"]
    assert any("input 'robotPrimPath (usePath true)' mapped to 'robotPrim' = ['/World/Tool']" in w for w in result.warnings)
    with pytest.raises(ImportProblem, match="robotModel' = 'Franka': graphflow's PickPlaceController drives the UR10 only"):
        _import(tmp_path, '''
        def OmniGraphNode "controller"
        {
            token node:type = "omni.isaac.examples_nodes.IsaacPickPlaceController"
            custom string inputs:robotModel = "Franka"
        }
''')


def test_rendering_nodes_drop_with_a_reason_and_generic_publisher_fields_gather(tmp_path):
    result = _import(tmp_path, '''
        def OmniGraphNode "render_product"
        {
            token node:type = "isaacsim.core.nodes.IsaacCreateRenderProduct"
            int node:typeVersion = 2
        }
        def OmniGraphNode "status"
        {
            token node:type = "isaacsim.ros2.bridge.ROS2Publisher"
            int node:typeVersion = 1
            custom string inputs:messagePackage = "std_msgs"
            custom string inputs:messageName = "String"
            custom string inputs:data = "ready"
            custom uint inputs:execIn
            prepend uint inputs:execIn.connect = </World/ActionGraph/on_tick.outputs:tick>
        }
''')
    document = result.document
    assert [node.name for node in document.nodes] == ["on_tick", "status"]
    assert json.loads(document.node("status").inputs["messageFields"]) == {"data": "ready"}
    assert any("node 'render_product' (isaacsim.core.nodes.IsaacCreateRenderProduct): dropped: needs Kit's RTX "
               "renderer" in w for w in result.warnings)


def test_a_generic_subscribers_field_output_is_read_from_its_message_by_a_message_field_node(tmp_path):
    """Kit's ROS2Subscriber of std_msgs/Float32 has outputs:data; graphflow's has outputs:message (JSON)."""
    result = _import(tmp_path, '''
        def OmniGraphNode "speed_sub"
        {
            token node:type = "isaacsim.ros2.bridge.ROS2Subscriber"
            int node:typeVersion = 1
            custom string inputs:messageName = "Float32"
            custom string inputs:topicName = "speed"
            custom uint inputs:execIn
            prepend uint inputs:execIn.connect = </World/ActionGraph/on_tick.outputs:tick>
            custom float outputs:data
        }
        def OmniGraphNode "show"
        {
            token node:type = "omni.graph.nodes.ToString"
            int node:typeVersion = 1
            custom token inputs:value
            prepend token inputs:value.connect = </World/ActionGraph/speed_sub.outputs:data>
        }
''')
    document = result.document
    assert document.node("speed_sub_data").inputs == {"field": "data"}
    assert {(c.src, c.dst) for c in document.connections} >= {
        ("speed_sub.outputs:message", "speed_sub_data.inputs:message"),
        ("speed_sub_data.outputs:value", "show.inputs:value")}
    assert any("output 'outputs:data': Kit's per-field output read from outputs:message by node 'speed_sub_data'"
               in line for line in result.warnings)


def test_v1_surface_gripper_closed_output_is_the_legacy_grippers_is_closed(tmp_path):
    """v1's outputs:Closed ("Surface gripper is closed or not", the 4.x .ogn) reads LegacySurfaceGripper.isClosed."""
    result = _import(tmp_path, '''
        def OmniGraphNode "gripper"
        {
            token node:type = "omni.isaac.surface_gripper.SurfaceGripper"
            int node:typeVersion = 1
            custom rel inputs:ParentRigidBody = </World/Tool>
            custom uint inputs:onStep
            prepend uint inputs:onStep.connect = </World/ActionGraph/on_tick.outputs:tick>
            custom bool outputs:Closed
        }
        def OmniGraphNode "show"
        {
            token node:type = "omni.graph.nodes.ToString"
            int node:typeVersion = 1
            custom token inputs:value
            prepend token inputs:value.connect = </World/ActionGraph/gripper.outputs:Closed>
        }
''')
    assert ("gripper.outputs:isClosed", "show.inputs:value") in {(c.src, c.dst) for c in result.document.connections}
