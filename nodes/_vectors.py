"""Vector and 4x4 matrix helpers of the omni.graph.nodes vector and transform nodes.

Not a node type. Matrices are USD's: 16 doubles row by row, points as row
vectors (p' = p M), so the upper 3x3 is the rotation transposed and the last
row holds the translation.
"""
import math

from graphflow.poses import quat_matrix, quat_normalize

IDENTITY = (1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 1.0)


def is_vector(value) -> bool:
    return isinstance(value, tuple) and bool(value) and all(
        isinstance(c, (int, float)) and not isinstance(c, bool) for c in value)


def pose_matrix(position, orientation) -> tuple[float, ...]:
    """The USD matrix of a pose (position, (x, y, z, w) orientation)."""
    r = quat_matrix(orientation)        # row-major, column vectors
    return (r[0], r[3], r[6], 0.0, r[1], r[4], r[7], 0.0, r[2], r[5], r[8], 0.0,
            float(position[0]), float(position[1]), float(position[2]), 1.0)


def matrix_translation(matrix) -> tuple[float, float, float]:
    return float(matrix[12]), float(matrix[13]), float(matrix[14])


def matrix_quaternion(matrix) -> tuple[float, float, float, float]:
    """The (x, y, z, w) rotation of a USD matrix, scale divided out of each row."""
    rows = [matrix[4 * i:4 * i + 3] for i in range(3)]
    rows = [[c / (math.sqrt(sum(x * x for x in row)) or 1.0) for c in row] for row in rows]
    # r[i][j] (column-vector rotation) = rows[j][i]
    m00, m01, m02 = rows[0][0], rows[1][0], rows[2][0]
    m10, m11, m12 = rows[0][1], rows[1][1], rows[2][1]
    m20, m21, m22 = rows[0][2], rows[1][2], rows[2][2]
    trace = m00 + m11 + m22
    if trace > 0.0:
        s = 2.0 * math.sqrt(trace + 1.0)
        q = ((m21 - m12) / s, (m02 - m20) / s, (m10 - m01) / s, 0.25 * s)
    elif m00 > m11 and m00 > m22:
        s = 2.0 * math.sqrt(1.0 + m00 - m11 - m22)
        q = (0.25 * s, (m01 + m10) / s, (m02 + m20) / s, (m21 - m12) / s)
    elif m11 > m22:
        s = 2.0 * math.sqrt(1.0 + m11 - m00 - m22)
        q = ((m01 + m10) / s, 0.25 * s, (m12 + m21) / s, (m02 - m20) / s)
    else:
        s = 2.0 * math.sqrt(1.0 + m22 - m00 - m11)
        q = ((m02 + m20) / s, (m12 + m21) / s, 0.25 * s, (m10 - m01) / s)
    return quat_normalize(q)


def matrix_multiply(a, b) -> tuple[float, ...]:
    return tuple(sum(a[4 * i + k] * b[4 * k + j] for k in range(4)) for i in range(4) for j in range(4))


def rigid_inverse(matrix) -> tuple[float, ...]:
    """The inverse of a rotation-and-translation matrix."""
    r = [[matrix[4 * i + j] for j in range(3)] for i in range(3)]
    t = matrix[12:15]
    rt = [[r[j][i] for j in range(3)] for i in range(3)]
    inverse_t = [-sum(t[k] * rt[k][j] for k in range(3)) for j in range(3)]
    return (rt[0][0], rt[0][1], rt[0][2], 0.0, rt[1][0], rt[1][1], rt[1][2], 0.0,
            rt[2][0], rt[2][1], rt[2][2], 0.0, inverse_t[0], inverse_t[1], inverse_t[2], 1.0)
