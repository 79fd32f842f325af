"""AppendArray, NthRoot, RandomGaussian and MakeTransformLookAt on the examples their Kit pages describe."""
import math
import statistics

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness

ROOT = "omni.graph.nodes.NthRoot"


def root(value, n=2):
    return NodeHarness(ROOT, {"value": value, "nthRoot": n}).compute().outputs["result"]


def test_nth_root_matches_powers_elementwise():
    assert root(16.0) == 4.0
    assert root(27, 3) == pytest.approx(3.0, rel=1e-15) and root(-27.0, 3) == pytest.approx(-3.0, rel=1e-15)
    assert root(32.0, 5) == pytest.approx(2.0, rel=1e-15)
    assert root([4.0, 9.0, 2.25]) == (2.0, 3.0, 1.5)                                 # a vector, elementwise
    assert root([[1.0, 16.0], [81.0, 0.0]], 4) == ((1.0, 2.0), (3.0, 0.0))          # an array of vectors
    assert root(0.25, -2) == 2.0                                                    # a negative degree inverts
    assert isinstance(root(4), float)                                               # integers give doubles


def test_nth_root_of_a_negative_value_is_nan_except_the_cube_root_and_zero_degree_is_infinite_power():
    assert math.isnan(root(-4.0)) and math.isnan(root(-32.0, 5))
    assert root(2.0, 0) == math.inf and root(0.5, 0) == 0.0 and root(1.0, 0) == 1.0
    with pytest.raises(GraphRuntimeError, match="inputs:value has no value"):
        NodeHarness(ROOT).compute()


APPEND = "omni.graph.nodes.AppendArray"


def test_append_array_joins_the_inputs_in_order():
    joined = NodeHarness(APPEND, {"input0": [1.0, 2.0], "input1": [3.0], "input2": [4.0, 5.0]}).compute()
    assert joined.outputs["array"] == (1.0, 2.0, 3.0, 4.0, 5.0)
    points = NodeHarness(APPEND, {"input0": [[0, 0, 1]], "input1": [[1, 0, 0], [0, 1, 0]]}).compute()
    assert points.outputs["array"] == ((0, 0, 1), (1, 0, 0), (0, 1, 0))
    assert NodeHarness(APPEND, {"input0": [], "input1": ["a", "b"]}).compute().outputs["array"] == ("a", "b")


def test_append_array_refuses_mixed_element_types_and_a_missing_first_pair():
    with pytest.raises(GraphRuntimeError, match="inputs:input1 holds an array of 3-tuples but inputs:input0 holds"):
        NodeHarness(APPEND, {"input0": [1.0], "input1": [[1.0, 2.0, 3.0]]}).compute()
    with pytest.raises(GraphRuntimeError, match="inputs:input1 has no value"):
        NodeHarness(APPEND, {"input0": [1.0]}).compute()


GAUSSIAN = "omni.graph.nodes.RandomGaussian"


def draws(count, **inputs):
    node = NodeHarness(GAUSSIAN, {"useSeed": True, "seed": 7, **inputs})
    return [node.compute("execIn").outputs["random"] for _ in range(count)]


def test_gaussian_draws_have_the_requested_mean_and_spread():
    count = 4000
    values = draws(count, mean=1.5, stdev=0.2)
    # the sample mean is within 4 standard errors, the sample deviation within 4 of its standard errors
    assert abs(statistics.fmean(values) - 1.5) < 4 * 0.2 / math.sqrt(count)
    assert abs(statistics.stdev(values) - 0.2) < 4 * 0.2 / math.sqrt(2 * count)
    standard = draws(count)                                          # neither set: N(0, 1)
    assert abs(statistics.fmean(standard)) < 4 / math.sqrt(count)
    assert abs(statistics.stdev(standard) - 1.0) < 4 / math.sqrt(2 * count)


def test_gaussian_log_normal_draws_have_the_underlying_normals_moments():
    count = 4000
    logs = [math.log(v) for v in draws(count, mean=0.5, stdev=0.3, useLog=True)]
    assert abs(statistics.fmean(logs) - 0.5) < 4 * 0.3 / math.sqrt(count)
    assert abs(statistics.stdev(logs) - 0.3) < 4 * 0.3 / math.sqrt(2 * count)


def test_gaussian_broadcasts_vectors_repeats_per_seed_and_isnoise_holds_still():
    vector = draws(1, mean=[0.0, 10.0, -10.0], stdev=0.0)[0]
    assert vector == (0.0, 10.0, -10.0)                               # zero spread: exactly the means
    spread = draws(500, mean=[0.0, 100.0], stdev=[1.0, 0.0])
    assert all(v[1] == 100.0 for v in spread) and len({v[0] for v in spread}) == 500
    assert draws(5, mean=2.0, stdev=1.0) == draws(5, mean=2.0, stdev=1.0)
    noise = draws(3, mean=2.0, stdev=1.0, isNoise=True)
    assert noise[0] == noise[1] == noise[2]


LOOK_AT = "omni.graph.nodes.MakeTransformLookAt"


def apply(matrix, point):
    """Row vector times a USD 4x4 matrix (flat, row-major)."""
    return tuple(sum(p * matrix[4 * i + j] for i, p in enumerate((*point, 1.0))) for j in range(3))


@pytest.mark.parametrize("center, eye, up", [((0, 0, 0), (1, 0, 0), (0, 1, 0)),
                                             ((1.0, 2.0, 0.5), (4.0, -2.0, 0.5), (0.0, 0.0, 1.0)),
                                             ((0.3, -0.2, 1.1), (0.0, 0.4, 0.2), (0.2, 0.1, 1.0))])
def test_look_at_is_gfs_view_matrix_with_center_and_eye_swapped_as_kits_compute(center, eye, up):
    from pxr import Gf

    matrix = NodeHarness(LOOK_AT, {"center": center, "eye": eye, "up": up}).compute().outputs["transform"]
    reference = Gf.Matrix4d().SetLookAt(Gf.Vec3d(*center), Gf.Vec3d(*eye), Gf.Vec3d(*up))
    assert matrix == pytest.approx([reference[i][j] for i in range(4) for j in range(4)], abs=1e-12)
    # the camera stands at center: it maps to the origin, and eye lies straight ahead on -Z
    distance = math.dist(center, eye)
    assert apply(matrix, center) == pytest.approx((0.0, 0.0, 0.0), abs=1e-12)
    assert apply(matrix, eye) == pytest.approx((0.0, 0.0, -distance), abs=1e-12)


def test_look_at_refuses_a_degenerate_view():
    with pytest.raises(GraphRuntimeError, match="same point"):
        NodeHarness(LOOK_AT, {"center": [1, 1, 1], "eye": [1, 1, 1]}).compute()
    with pytest.raises(GraphRuntimeError, match="parallel"):
        NodeHarness(LOOK_AT, {"center": [0, 0, 0], "eye": [0, 2, 0]}).compute()
