"""omni.graph.nodes matrix nodes, checked against USD's own matrix math (pxr Gf and UsdGeom xform ops).

graphflow takes Kit's Euler angles as USD's xformOp:rotate<ORDER> (degrees, the
first letter's axis first): UsdGeom is the independent reference for every order.
"""
import math

import pytest
from pxr import Gf, Usd, UsdGeom

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness

ORDERS = ("XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX")


def out(type_id, output, **inputs):
    return NodeHarness(f"omni.graph.nodes.{type_id}", inputs=inputs).compute().outputs[output]


def flat(matrix):
    return tuple(matrix[i][j] for i in range(len(matrix)) for j in range(len(matrix)))


def usd_xform(order="XYZ", translate=(0, 0, 0), rotate=(0, 0, 0), scale=(1, 1, 1)):
    """The local matrix USD composes for translate, rotate<ORDER>, scale ops (Kit's TRS)."""
    stage = Usd.Stage.CreateInMemory()
    xform = UsdGeom.Xform.Define(stage, "/X")
    xform.AddTranslateOp().Set(Gf.Vec3d(*translate))
    getattr(xform, f"AddRotate{order}Op")().Set(Gf.Vec3f(*rotate))
    xform.AddScaleOp().Set(Gf.Vec3f(*scale))
    return xform.GetLocalTransformation()


A = Gf.Matrix4d(1, 2, 0, 0, 0, 1, 3, 0, 4, 0, 1, 0, 5, 6, 7, 1)
B = Gf.Matrix4d(0, 1, 0, 0, -1, 0, 0, 0, 0, 0, 2, 0, 1, 1, 1, 1)


def test_matrix_multiply_matches_gf_for_matrices_row_vectors_and_dot_products():
    assert out("MatrixMultiply", "output", a=flat(A), b=flat(B)) == pytest.approx(flat(A * B))
    row = Gf.Vec4d(1, 2, 3, 1)
    assert out("MatrixMultiply", "output", a=tuple(row), b=flat(A)) == pytest.approx(tuple(row * A))
    assert out("MatrixMultiply", "output", a=flat(A), b=tuple(row)) == pytest.approx(tuple(A * row))
    assert out("MatrixMultiply", "output", a=(1, 2, 3), b=(4, 5, 6)) == 32.0
    arrays = out("MatrixMultiply", "output", a=(flat(A), flat(B)), b=flat(B))
    assert arrays[0] == pytest.approx(flat(A * B)) and arrays[1] == pytest.approx(flat(B * B))
    with pytest.raises(GraphRuntimeError, match="cannot multiply 3 values"):
        out("MatrixMultiply", "output", a=(1, 2, 3), b=flat(A))


def test_transpose_and_rows_round_trip():
    assert out("Transpose", "result", matrix=flat(A)) == flat(A.GetTranspose())
    assert out("Transpose", "result", matrix=(0, 1, 2, 3)) == (0.0, 2.0, 1.0, 3.0)
    rows = [tuple(A.GetRow(i)) for i in range(4)]
    assert out("MakeMatrix4", "matrix", x=rows[0], y=rows[1], z=rows[2], w=rows[3]) == flat(A)
    broken = NodeHarness("omni.graph.nodes.BreakMatrix4", inputs={"matrix": flat(A)}).compute().outputs
    assert [broken[k] for k in "xyzw"] == rows
    short = NodeHarness("omni.graph.nodes.BreakMatrix4", inputs={"matrix": flat(A), "outputType": "double[3]"})
    assert short.compute().outputs["w"] == (5.0, 6.0, 7.0)
    assert out("MakeMatrix4", "matrix", x=(1, 0, 0), y=(0, 1, 0), z=(0, 0, 1), w=(5, 6, 7)) == \
        flat(Gf.Matrix4d(1).SetTranslate(Gf.Vec3d(5, 6, 7)))
    assert out("MakeMatrix3", "matrix", x=(1, 2, 3), y=(4, 5, 6), z=(7, 8, 9)) == tuple(float(i) for i in range(1, 10))
    two = NodeHarness("omni.graph.nodes.BreakMatrix2", inputs={"matrix": (1, 2, 3, 4)}).compute().outputs
    assert (two["x"], two["y"]) == ((1.0, 2.0), (3.0, 4.0))
    assert out("MakeMatrix2", "matrix", x=(1, 2), y=(3, 4)) == (1.0, 2.0, 3.0, 4.0)


@pytest.mark.parametrize("order", ORDERS)
def test_make_transform_is_usds_translate_rotate_scale(order):
    expected = usd_xform(order, (1, -2, 3), (10, 20, 30), (2, 3, 0.5))
    made = out("MakeTransform", "transform", translation=(1, -2, 3), rotationXYZ=(10, 20, 30), scale=(2, 3, 0.5),
               rotationOrder=order)
    assert made == pytest.approx(flat(expected), abs=1e-12)


@pytest.mark.parametrize("order", ORDERS)
def test_get_rotation_gives_back_the_authored_euler_angles(order):
    matrix = flat(usd_xform(order, (4, 5, 6), (-35, 50, 70), (2, 2, 3)))
    assert out("GetMatrix4Rotation", "rotation", matrix=matrix, rotationOrder=order) == \
        pytest.approx((-35.0, 50.0, 70.0))
    rotation = out("GetMatrix4RotationMatrix", "rotation", matrix=(-35, 50, 70), rotationOrder=order)
    expected = usd_xform(order, rotate=(-35, 50, 70)).ExtractRotationMatrix()
    assert rotation == pytest.approx(flat(expected), abs=1e-12)


def test_quaternion_rotations():
    half = math.sqrt(0.5)
    assert out("GetMatrix4Rotation", "rotation", matrix=(0.0, 0.0, half, half)) == pytest.approx((0.0, 0.0, 90.0))
    expected = Gf.Matrix3d(Gf.Rotation(Gf.Vec3d(0, 0, 1), 90))
    assert out("GetMatrix4RotationMatrix", "rotation", matrix=(0.0, 0.0, half, half)) == \
        pytest.approx(flat(expected), abs=1e-12)


def test_transform_vector_applies_a_4x4_to_a_point_and_a_3x3_to_a_vector():
    matrix = usd_xform("XYZ", (1, 2, 3), (0, 0, 90), (2, 2, 2))
    assert out("TransformVector", "result", matrix=flat(matrix), vector=(1, 0, 0)) == \
        pytest.approx(tuple(matrix.Transform(Gf.Vec3d(1, 0, 0))))
    m3 = flat(matrix.ExtractRotationMatrix())
    turned = out("TransformVector", "result", matrix=m3, vector=((1, 0, 0), (0, 1, 0)))
    assert turned[0] == pytest.approx((0.0, 2.0, 0.0), abs=1e-12)
    assert turned[1] == pytest.approx((-2.0, 0.0, 0.0), abs=1e-12)


def test_scale_and_translation_get_and_set():
    matrix = flat(usd_xform("ZYX", (1, 2, 3), (30, 40, 50), (2, 3, 4)))
    assert out("GetMatrix4Scale", "scale", matrix=matrix) == pytest.approx((2.0, 3.0, 4.0))
    rescaled = out("SetMatrix4Scale", "matrix", matrix=matrix, scale=(1, 1, 1))
    assert rescaled == pytest.approx(flat(usd_xform("ZYX", (1, 2, 3), (30, 40, 50))))
    moved = out("SetMatrix4Translation", "matrix", matrix=matrix, translation=(-1, 0, 9))
    assert moved == pytest.approx(flat(usd_xform("ZYX", (-1, 0, 9), (30, 40, 50), (2, 3, 4))))


@pytest.mark.parametrize("inputs, order, angles", [
    ({"rotationAngle": 90.0, "fixedRotationAxis": "X"}, "XYZ", (90, 0, 0)),
    ({"rotationAngle": -45.0}, "XYZ", (0, -45, 0)),
    ({"rotationAngle": 60.0, "fixedRotationAxis": "Custom", "rotationAxis": (0, 0, 5)}, "XYZ", (0, 0, 60)),
    ({"rotationAngle": (10.0, 20.0, 30.0), "rotationOrder": "YZX"}, "YZX", (10, 20, 30)),
])
def test_set_rotation_keeps_translation_and_scale(inputs, order, angles):
    start = flat(usd_xform("XYZ", (1, 2, 3), (5, 6, 7), (2, 2, 2)))
    result = out("SetMatrix4Rotation", "matrix", matrix=start, **inputs)
    assert result == pytest.approx(flat(usd_xform(order, (1, 2, 3), angles, (2, 2, 2))), abs=1e-12)
