"""Rotation nodes: Euler <-> quaternion, RotateVector, ComposePoses (radians, quaternions x, y, z, w)."""
import math
import random

import pytest

from graphflow.testing import GraphHarness, NodeHarness

HALF = math.sqrt(0.5)


def euler_to_quaternion(rotation):
    return NodeHarness("graphflow.EulerToQuaternion", inputs={"rotation": list(rotation)}).compute().outputs["quaternion"]


def test_a_yaw_is_a_turn_about_plus_z():
    assert euler_to_quaternion((0, 0, math.pi / 2)) == pytest.approx((0, 0, HALF, HALF))
    assert euler_to_quaternion((math.pi / 2, 0, 0)) == pytest.approx((HALF, 0, 0, HALF))


def test_roll_pitch_yaw_apply_about_fixed_x_then_y_then_z():
    # roll 90 then yaw 90: +Y goes to +Z (roll), which yaw leaves alone; +X goes to +Y (yaw)
    quaternion = euler_to_quaternion((math.pi / 2, 0, math.pi / 2))
    rotate = lambda v: NodeHarness("omni.graph.nodes.RotateVector",
                                   inputs={"rotation": list(quaternion), "vector": list(v)}).compute().outputs["result"]
    assert rotate((0, 1, 0)) == pytest.approx((0, 0, 1), abs=1e-12)
    assert rotate((1, 0, 0)) == pytest.approx((0, 1, 0), abs=1e-12)


def test_quaternion_to_euler_inverts_euler_to_quaternion():
    rng = random.Random(3)
    for _ in range(200):
        angles = (rng.uniform(-3.1, 3.1), rng.uniform(-1.5, 1.5), rng.uniform(-3.1, 3.1))
        back = NodeHarness("graphflow.QuaternionToEuler",
                           inputs={"quaternion": list(euler_to_quaternion(angles))}).compute().outputs
        assert back["rotation"] == pytest.approx(angles, abs=1e-9)
        assert back["yaw"] == pytest.approx(angles[2], abs=1e-9)


def test_rotate_vector_normalises_the_quaternion():
    result = NodeHarness("omni.graph.nodes.RotateVector",
                         inputs={"rotation": [0, 0, 2, 2], "vector": [0.5, 0, 0.1]}).compute().outputs["result"]
    assert result == pytest.approx((0, 0.5, 0.1), abs=1e-12)


def test_compose_poses_places_a_child_in_a_turned_parent_frame():
    outputs = NodeHarness("graphflow.ComposePoses", inputs={
        "parentPosition": [0.4, 0.4, 0.0], "parentOrientation": [0, 0, HALF, HALF],
        "childPosition": [0.1, 0.0, 0.05], "childOrientation": [0, 0, HALF, HALF]}).compute().outputs
    assert outputs["position"] == pytest.approx((0.4, 0.5, 0.05), abs=1e-12)
    assert outputs["orientation"] == pytest.approx((0, 0, 1, 0), abs=1e-12)   # two quarter turns: a half turn


def test_a_graph_turns_a_place_offset_by_a_yaw_read_from_a_quaternion():
    g = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "to_quat", "type": "graphflow.EulerToQuaternion", "inputs": {"rotation": [0.0, 0.0, math.pi]}},
            {"name": "to_euler", "type": "graphflow.QuaternionToEuler"},
            {"name": "turn", "type": "omni.graph.nodes.RotateVector", "inputs": {"vector": [0.2, 0.0, 0.0]}},
            {"name": "show_yaw", "type": "graphflow.FormatText", "inputs": {"format": "{value}"}},
            {"name": "show_turned", "type": "graphflow.FormatText", "inputs": {"format": "{value}"}},
            {"name": "print_yaw", "type": "omni.graph.ui_nodes.PrintText"},
            {"name": "print_turned", "type": "omni.graph.ui_nodes.PrintText"},
        ],
        "connections": [
            {"src": "tick.outputs:tick", "dst": "print_yaw.inputs:execIn"},
            {"src": "print_yaw.outputs:execOut", "dst": "print_turned.inputs:execIn"},
            {"src": "to_quat.outputs:quaternion", "dst": "to_euler.inputs:quaternion"},
            {"src": "to_quat.outputs:quaternion", "dst": "turn.inputs:rotation"},
            {"src": "to_euler.outputs:yaw", "dst": "show_yaw.inputs:value"},
            {"src": "turn.outputs:result", "dst": "show_turned.inputs:value"},
            {"src": "show_yaw.outputs:text", "dst": "print_yaw.inputs:text"},
            {"src": "show_turned.outputs:text", "dst": "print_turned.inputs:text"},
        ],
    })
    g.run(ticks=1)
    assert float(g.logs[0]) == pytest.approx(math.pi)
    assert g.output("turn", "result") == pytest.approx((-0.2, 0.0, 0.0), abs=1e-12)
