"""DifferentialController, IsaacGripperController, IsaacReadSimulationTime and OgnIsaacRunOneSimulationFrame."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import ClockWorld, GraphHarness, NodeHarness

from .fakes import FakeArticulationWorld

DIFF = "isaacsim.robot.wheeled_robots.DifferentialController"
WHEELS = {"wheelRadius": 0.1, "wheelDistance": 0.4}


def test_differential_drive_wheel_speeds():
    node = NodeHarness(DIFF, {**WHEELS, "linearVelocity": 1.0, "angularVelocity": 0.5})
    result = node.compute("execIn")
    # left = (v - w d / 2) / r = (1 - 0.1) / 0.1, right = (1 + 0.1) / 0.1
    assert result.outputs["velocityCommand"] == pytest.approx((9.0, 11.0))
    assert result.fired == {"execOut"}


def test_old_id_loads_and_limits_clamp_speeds_and_ramps():
    node = NodeHarness("omni.isaac.wheeled_robots.DifferentialController",
                       {**WHEELS, "linearVelocity": 3.0, "maxLinearSpeed": 2.0, "maxWheelSpeed": 15.0})
    assert node.compute("execIn").outputs["velocityCommand"] == pytest.approx((15.0, 15.0))   # 2 m/s -> 20 rad/s -> 15
    ramped = NodeHarness(DIFF, {**WHEELS, "linearVelocity": 1.0, "maxAcceleration": 0.6, "dt": 0.5})
    speeds = [ramped.compute("execIn").outputs["velocityCommand"][0] for _ in range(3)]
    assert speeds == pytest.approx([3.0, 6.0, 9.0])   # +0.3 m/s per compute


def test_differential_controller_needs_its_wheel_geometry():
    with pytest.raises(GraphRuntimeError, match="wheelRadius and inputs:wheelDistance must be positive"):
        NodeHarness(DIFF, {"linearVelocity": 1.0}).compute("execIn")


def test_gripper_controller_closes_at_its_speed_then_opens():
    world = FakeArticulationWorld({"/World/hand": ("finger_a", "finger_b", "wrist")}, time_step=0.1)
    node = NodeHarness("isaacsim.robot.manipulators.IsaacGripperController",
                       {"articulationRootPrim": ["/World/hand"], "jointNames": ["finger_a", "finger_b"],
                        "openPosition": [0.04, 0.04], "closePosition": [0.0, 0.0], "gripperSpeed": [0.1]},
                       world=world)
    world.positions["/World/hand"] = [0.04, 0.04, 0.0]
    first = node.compute("close")
    assert first.outputs["jointNames"] == ("finger_a", "finger_b")
    assert first.outputs["positionCommands"] == pytest.approx((0.03, 0.03))   # 0.1 m/s x 0.1 s
    assert node.compute("execIn").outputs["positionCommands"] == pytest.approx((0.02, 0.02))
    node.set_inputs(gripperSpeed=[])
    assert node.compute("open").outputs["positionCommands"] == pytest.approx((0.04, 0.04))


def test_read_simulation_time_follows_the_world_clock():
    world = ClockWorld(0.25)
    node = NodeHarness("isaacsim.core.nodes.IsaacReadSimulationTime", world=world)
    for _ in range(3):
        node.tick()
    assert node.compute().outputs["simulationTime"] == 0.75
    node.set_inputs(referenceTimeNumerator=3, referenceTimeDenominator=2)
    assert node.compute().outputs["simulationTime"] == 1.5


def test_run_one_simulation_frame_passes_one_pulse_per_reset():
    node = NodeHarness("isaacsim.core.nodes.OgnIsaacRunOneSimulationFrame")
    assert [node.compute("execIn").fired for _ in range(3)] == [{"step"}, set(), set()]
    node.reset()
    assert node.compute("execIn").fired == {"step"}


def test_differential_controller_commands_zero_wheel_speeds_until_it_first_computes():
    """The .ogn default of outputs:velocityCommand is [0.0, 0.0]: a graph indexing it (ArrayIndex 0 and 1 into
    two conveyors or joints) before the first twist arrives reads stopped wheels, not an empty array."""
    graph = GraphHarness({
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "twist", "type": "isaacsim.ros2.bridge.ROS2SubscribeTwist", "inputs": {"topicName": "cmd"}},
                  {"name": "drive", "type": "isaacsim.robot.wheeled_robots.DifferentialController",
                   "inputs": {"wheelRadius": 0.1, "wheelDistance": 0.5}},
                  {"name": "right", "type": "omni.graph.nodes.ArrayIndex", "inputs": {"index": 1}},
                  {"name": "text", "type": "graphflow.FormatText"},
                  {"name": "show", "type": "omni.graph.ui_nodes.PrintText"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "twist.inputs:execIn"},
                        {"src": "twist.outputs:execOut", "dst": "drive.inputs:execIn"},
                        {"src": "tick.outputs:tick", "dst": "show.inputs:execIn"},
                        {"src": "drive.outputs:velocityCommand", "dst": "right.inputs:array"},
                        {"src": "right.outputs:value", "dst": "text.inputs:value"},
                        {"src": "text.outputs:text", "dst": "show.inputs:text"}]})
    graph.run(2)
    assert graph.output("right", "value") == 0.0
    assert graph.compute_counts["drive"] == 0
