"""Square-matrix and Euler-angle helpers of the omni.graph.nodes matrix nodes.

Not a node type. Matrices are flat, row by row, as graphflow stores USD's
matrixd[2] / [3] / [4] (4, 9 or 16 doubles); vectors are row vectors (v' = v M),
so a 4x4 transform's last row is its translation and its upper 3x3 rows are the
rotated, scaled axes.

Euler angles (the rotationOrder token's nodes): Kit's reference states the
orders (XYZ, XZY, YXZ, YZX, ZXY, ZYX, default XYZ) but not the units; graphflow
takes them as USD's xformOp:rotate<ORDER> does, which is what Kit's transform
nodes write: degrees, the first letter's axis applied first, about fixed axes
(XYZ: the matrix Rx * Ry * Rz for row vectors).

Arrays: an operand that is a tuple of tuples is an array of matrices or
vectors; the helpers' callers map over it with ``each``, broadcasting a single
operand over an array.
"""
from __future__ import annotations

import math

ORDERS = ("XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX")
SIZES = {4: 2, 9: 3, 16: 4}


class MatrixError(ValueError):
    """An operand has no matrix or vector meaning here; the message says what was given."""


def is_array(value) -> bool:
    return isinstance(value, tuple) and bool(value) and isinstance(value[0], tuple)


def each(op, *operands):
    """op over the operands, element by element where any is an array (a single operand is repeated)."""
    lengths = {len(v) for v in operands if is_array(v)}
    if not lengths:
        return op(*operands)
    if len(lengths) > 1:
        raise MatrixError(f"arrays of different lengths {sorted(lengths)}")
    (length,) = lengths
    return tuple(op(*(v[i] if is_array(v) else v for v in operands)) for i in range(length))


def numbers(value, name: str) -> tuple[float, ...]:
    if not isinstance(value, tuple) or not all(isinstance(c, (int, float)) and not isinstance(c, bool)
                                               for c in value):
        raise MatrixError(f"inputs:{name} must be a matrix or vector of numbers, got {value!r}"[:160])
    return tuple(float(c) for c in value)


def side(matrix, name: str, allowed=(2, 3, 4)) -> int:
    """The side of a flat square matrix (4, 9 or 16 values)."""
    n = SIZES.get(len(matrix) if isinstance(matrix, tuple) else 0)
    if n is None or n not in allowed:
        shapes = " or ".join(f"{k}x{k} ({k * k} values)" for k in allowed)
        raise MatrixError(f"inputs:{name} must be a {shapes} matrix, got {len(matrix) if isinstance(matrix, tuple) else matrix!r}"
                          f"{' values' if isinstance(matrix, tuple) else ''}")
    return n


def multiply(a, b, n: int) -> tuple[float, ...]:
    return tuple(sum(a[n * i + k] * b[n * k + j] for k in range(n)) for i in range(n) for j in range(n))


def transpose(m, n: int) -> tuple[float, ...]:
    return tuple(float(m[n * j + i]) for i in range(n) for j in range(n))


def rows(m, n: int) -> list[tuple[float, ...]]:
    return [tuple(float(c) for c in m[n * i:n * i + n]) for i in range(n)]


def upper3(m, n: int) -> tuple[float, ...]:
    """The upper-left 3x3 block of a 3x3 or 4x4 matrix."""
    return tuple(float(m[n * i + j]) for i in range(3) for j in range(3))


def axis_matrix(axis: int, degrees: float) -> tuple[float, ...]:
    """The 3x3 row-vector matrix turning by *degrees* about axis 0 (X), 1 (Y) or 2 (Z)."""
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    j, k = (axis + 1) % 3, (axis + 2) % 3
    m = [[0.0] * 3 for _ in range(3)]
    m[axis][axis] = 1.0
    m[j][j], m[j][k], m[k][j], m[k][k] = c, s, -s, c
    return tuple(c for row in m for c in row)


def check_order(order: str) -> str:
    if order not in ORDERS:
        raise MatrixError(f"inputs:rotationOrder must be one of {', '.join(ORDERS)}, got {order!r}")
    return order


def euler_matrix(angles, order: str) -> tuple[float, ...]:
    """The 3x3 row-vector rotation of Euler *angles* (degrees, about X, Y, Z) applied in *order*."""
    result: tuple[float, ...] = (1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0)
    for letter in check_order(order):
        axis = "XYZ".index(letter)
        result = multiply(result, axis_matrix(axis, angles[axis]), 3)
    return result


def matrix_euler(m3, order: str) -> tuple[float, float, float]:
    """The Euler angles (degrees, about X, Y, Z) that ``euler_matrix`` turns into the rotation *m3*."""
    i, j, k = ("XYZ".index(c) for c in check_order(order))
    r = [[m3[3 * col + row] for col in range(3)] for row in range(3)]    # column-vector form: R = M^T
    sign = 1.0 if (j - i) % 3 == 1 else -1.0                            # XYZ, YZX, ZXY are cyclic
    middle = math.asin(max(-1.0, min(1.0, -sign * r[k][i])))
    if abs(math.cos(middle)) > 1e-9:
        first = math.atan2(sign * r[k][j], r[k][k])
        last = math.atan2(sign * r[j][i], r[i][i])
    else:                                                               # gimbal lock: put it all in the first
        first = math.atan2(-sign * r[j][k], r[j][j])
        last = 0.0
    angles = [0.0, 0.0, 0.0]
    angles[i], angles[j], angles[k] = math.degrees(first), math.degrees(middle), math.degrees(last)
    return angles[0], angles[1], angles[2]


def quaternion_matrix(q) -> tuple[float, ...]:
    """The 3x3 row-vector rotation of a quaternion (x, y, z, w), normalised first."""
    x, y, z, w = q
    norm = math.sqrt(x * x + y * y + z * z + w * w)
    if norm == 0.0:
        raise MatrixError("a zero quaternion has no rotation")
    x, y, z, w = x / norm, y / norm, z / norm, w / norm
    column = (1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
              2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
              2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y))
    return transpose(column, 3)


def row_lengths(m3) -> tuple[float, ...]:
    return tuple(math.sqrt(sum(c * c for c in m3[3 * i:3 * i + 3])) for i in range(3))


def rotation_only(m3) -> tuple[float, ...]:
    """*m3* with each row's scale divided out."""
    lengths = row_lengths(m3)
    return tuple(m3[3 * i + j] / (lengths[i] or 1.0) for i in range(3) for j in range(3))


def with_upper3(m, n: int, m3) -> tuple[float, ...]:
    """*m* (3x3 or 4x4) with its upper 3x3 block replaced by *m3*."""
    out = list(float(c) for c in m)
    for i in range(3):
        for j in range(3):
            out[n * i + j] = m3[3 * i + j]
    return tuple(out)


def rotation_of(value, name="matrix"):
    """The 3x3 row-vector rotation of a 3x3 / 4x4 matrix or a quaternion."""
    values = numbers(value, name)
    if len(values) == 4:
        return quaternion_matrix(values)
    return rotation_only(upper3(values, side(values, name, (3, 4))))
