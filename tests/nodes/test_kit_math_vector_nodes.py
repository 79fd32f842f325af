"""omni.graph.nodes trigonometry, rounding, vector and 4x4 transform nodes against math and USD's Gf."""
import math
import struct

import pytest
from pxr import Gf

from graphflow.executor import GraphRuntimeError
from graphflow.poses import quat_from_axis_angle
from graphflow.testing import NodeHarness
from graphflow.testing.fake_world import FakeWorld


def _out(type_name, output, **inputs):
    return NodeHarness(f"omni.graph.nodes.{type_name}", inputs).compute().outputs[output]


@pytest.mark.parametrize("degrees", [-270.0, -30.0, 0.0, 45.0, 123.4])
def test_trigonometry_takes_degrees_as_kit(degrees):
    assert _out("Sin", "value", value=degrees) == pytest.approx(math.sin(math.radians(degrees)))
    assert _out("Cos", "value", value=degrees) == pytest.approx(math.cos(math.radians(degrees)))
    assert _out("Tan", "value", value=degrees) == pytest.approx(math.tan(math.radians(degrees)))
    assert _out("Atan", "value", value=math.tan(math.radians(30.0))) == pytest.approx(30.0)


def test_inverse_trigonometry_and_atan2_answer_in_degrees():
    assert _out("Asin", "value", value=0.5) == pytest.approx(30.0)
    assert _out("Acos", "value", value=[0.5, -1.0]) == pytest.approx((60.0, 180.0))
    assert _out("ATan2", "result", a=1.0, b=-1.0) == pytest.approx(135.0)
    with pytest.raises(GraphRuntimeError, match="inputs:value: math domain error"):
        NodeHarness("omni.graph.nodes.Asin", {"value": 2.0}).compute()


def test_floor_ceil_and_negate_elementwise():
    assert _out("Floor", "result", a=[-1.5, 2.5]) == (-2, 2)
    assert _out("Ceil", "result", a=[-1.5, 2.5]) == (-1, 3)
    assert _out("Negate", "output", input=[1.0, -2.0, 0.5]) == (-1.0, 2.0, -0.5)


def test_vector_nodes():
    assert _out("Normalize", "result", vector=[3.0, 4.0, 0.0]) == pytest.approx((0.6, 0.8, 0.0))
    assert _out("Normalize", "result", vector=[0.0, 0.0, 0.0]) == (0.0, 0.0, 0.0)
    assert _out("CrossProduct", "product", a=[1.0, 0.0, 0.0], b=[0.0, 1.0, 0.0]) == (0.0, 0.0, 1.0)
    assert _out("CrossProduct", "product", a=[[0.0, 1.0, 0.0]], b=[[0.0, 0.0, 1.0]]) == ((1.0, 0.0, 0.0),)
    assert _out("Distance3D", "distance", a=[1.0, 2.0, 2.0], b=[0.0, 0.0, 0.0]) == pytest.approx(3.0)
    assert _out("Distance3D", "distance", a=[[3.0, 4.0, 0.0], [0.0, 0.0, 2.0]], b=[0.0, 0.0, 0.0]) == (5.0, 2.0)


def _gf_matrix(axis, degrees, translation):
    return Gf.Matrix4d(Gf.Rotation(Gf.Vec3d(*axis), degrees), Gf.Vec3d(*translation))


def _flat(matrix):
    return tuple(matrix[i][j] for i in range(4) for j in range(4))


def _same_rotation(q, gf_quat):
    expected = (*gf_quat.GetImaginary(), gf_quat.GetReal())
    sign = 1.0 if sum(a * b for a, b in zip(q, expected)) >= 0 else -1.0
    return tuple(sign * c for c in q) == pytest.approx(expected, abs=1e-12)


@pytest.mark.parametrize("axis, degrees", [((0, 0, 1), 30.0), ((1, 2, 3), 140.0), ((1, 0, 0), 179.0)])
def test_matrix_rotation_and_translation_match_usd_gf(axis, degrees):
    matrix = _gf_matrix(axis, degrees, (0.5, -1.0, 2.0))
    assert _same_rotation(_out("GetMatrix4Quaternion", "quaternion", matrix=_flat(matrix)),
                          matrix.ExtractRotationQuat())
    assert _out("GetMatrix4Translation", "translation", matrix=_flat(matrix)) == (0.5, -1.0, 2.0)


def test_prim_world_and_local_transforms_match_usd_gf():
    """A box turned 30 deg about z at (1, 2, 3) carries a frame 0.5 m along its x: world and local matrices
    are what Gf composes (local * parent = world)."""
    world = FakeWorld()
    turn = quat_from_axis_angle((0.0, 0.0, 1.0), math.radians(30.0))
    world.add_box("/World/Box", (1.0, 2.0, 3.0), (0.1, 0.1, 0.1), orientation=turn)
    world.add_frame("/World/Box/Tip", "/World/Box", ((0.5, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0)))
    box = _gf_matrix((0, 0, 1), 30.0, (1.0, 2.0, 3.0))
    local = Gf.Matrix4d(Gf.Rotation(Gf.Vec3d(0, 0, 1), 0.0), Gf.Vec3d(0.5, 0.0, 0.0))
    read_world = NodeHarness("omni.graph.nodes.GetPrimLocalToWorldTransform", {"primPath": "/World/Box/Tip"},
                             world=world).compute().outputs["localToWorldTransform"]
    assert read_world == pytest.approx(_flat(local * box), abs=1e-12)
    read_local = NodeHarness("omni.graph.nodes.ReadPrimLocalTransform", {"prim": "/World/Box/Tip"},
                             world=world).compute().outputs["value"]
    assert read_local == pytest.approx(_flat(local), abs=1e-12)


def test_the_older_trig_node_and_set_rotation_quaternion():
    assert _out("Trig", "result", a=30.0, operation="SIN") == pytest.approx(0.5)
    assert _out("Trig", "result", a=0.5, operation="ARCCOS") == pytest.approx(60.0)
    assert _out("Trig", "result", a=math.pi, operation="DEGREES") == pytest.approx(180.0)
    start = _gf_matrix((1, 0, 0), 10.0, (0.5, -1.0, 2.0))
    turn = Gf.Rotation(Gf.Vec3d(0, 1, 2), 70.0).GetQuat()
    quaternion = (*turn.GetImaginary(), turn.GetReal())
    expected = Gf.Matrix4d(Gf.Rotation(Gf.Vec3d(0, 1, 2), 70.0), Gf.Vec3d(0.5, -1.0, 2.0))
    assert _out("SetMatrix4Quaternion", "matrix", matrix=_flat(start), quaternion=quaternion) == pytest.approx(
        _flat(expected), abs=1e-12)


def test_write_prim_local_transform_places_a_free_body_where_read_prim_local_transform_reads_it():
    """On a real world: a free cube written to a Gf transform reads back that transform."""
    from graphflow.physics import create_world

    matrix = _gf_matrix((0, 0, 1), 25.0, (0.3, -0.2, 0.5))
    with create_world("asset:ur10_pick_place.usda") as world:
        NodeHarness("omni.graph.nodes.WritePrimLocalTransform",
                    {"prim": "/World/Cube", "value": _flat(matrix)}, world=world).compute("execIn")
        read = NodeHarness("omni.graph.nodes.ReadPrimLocalTransform", {"prim": "/World/Cube"},
                           world=world).compute().outputs["value"]
    assert read == pytest.approx(_flat(matrix), abs=1e-6)
    with pytest.raises(GraphRuntimeError, match="scale or shear"):
        NodeHarness("omni.graph.nodes.WritePrimLocalTransform",
                    {"prim": "/World/Cube", "value": _flat(Gf.Matrix4d(2.0))}).compute("execIn")


def test_magnitude_absolute_dot_product_and_conversions():
    assert _out("Magnitude", "magnitude", input=[3.0, 4.0]) == pytest.approx(5.0)
    assert _out("Magnitude", "magnitude", input=-2.5) == 2.5
    assert _out("Magnitude", "magnitude", input=[[1.0, 2.0, 2.0], [0.0, 0.0, -3.0]]) == pytest.approx((3.0, 3.0))
    assert _out("Absolute", "absolute", input=[-1.5, 2.0, -0.0]) == (1.5, 2.0, 0.0)
    assert _out("DotProduct", "product", a=[1.0, 2.0, 3.0], b=[4.0, -5.0, 6.0]) == pytest.approx(12.0)
    assert _out("DotProduct", "product", a=[[1.0, 0.0]], b=[[0.5, 9.0]]) == (0.5,)
    assert _out("ToFloat", "converted", value=0.1) == struct.unpack("f", struct.pack("f", 0.1))[0]
    assert _out("ToHalf", "converted", value=[1.0 / 3.0, True]) == (0.333251953125, 1.0)
    assert _out("ConstantPi", "value", factor=0.5) == pytest.approx(math.pi / 2)


def test_round_is_zero_and_read_time():
    assert _out("Round", "output", input=[1.2345, -2.5, 1234.5], decimals=2) == (1.23, -2.5, 1234.5)
    assert _out("Round", "output", input=1234.5, decimals=-2) == 1200.0
    assert _out("IsZero", "result", value=[0.001, -0.002], tolerance=0.01) is True
    assert _out("IsZero", "result", value=[[0.0, 0.0], [0.0, 0.5]], tolerance=0.1) is False
    clock = NodeHarness("omni.graph.nodes.ReadTime", time_step=0.25)
    for _ in range(3):
        clock.world.step()
    out = clock.compute().outputs
    assert (out["time"], out["deltaSeconds"], out["isPlaying"]) == (0.75, 0.25, True)
