"""Noise: the properties Kit's reference states of its Perlin field (static per seed, smooth, zero at integers)."""
import math
import random

import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness

NOISE = "omni.graph.nodes.Noise"


def _noise(position, seed=0):
    return NodeHarness(NOISE, {"position": position, "seed": seed}).compute().outputs["result"]


@pytest.mark.parametrize("seed", [0, 1, 12345, 2**32 - 1])
def test_integral_positions_give_zero_as_kits_reference_says(seed):
    """Its examples: 5.0 in one dimension and (3.0, -1.0) in two; every lattice point in three and four too."""
    assert _noise(5.0, seed) == 0.0
    assert _noise([3.0, -1.0], seed) == 0.0
    assert _noise([[2.0, 0.0, -7.0], [1.0, 1.0, 1.0, -4.0]], seed) == (0.0, 0.0)


def test_a_float_array_samples_one_dimension_per_value():
    values = [0.25, 1.5, -2.75, 3.125, 7.5]
    assert _noise(values, seed=2) == tuple(_noise(value, seed=2) for value in values)
    assert _noise([[0.25], [1.5]], seed=2) == tuple(_noise(value, seed=2) for value in values[:2])


def test_the_field_is_static_for_a_seed_and_another_seed_is_another_field():
    points = [[x + 0.37, 0.5 * x - 0.21] for x in range(20)]
    first, again = _noise(points, seed=3), _noise(points, seed=3)
    assert first == again and first == tuple(_noise(point, seed=3) for point in points)
    other = _noise(points, seed=4)
    assert sum(a != b for a, b in zip(first, other)) >= 18


@pytest.mark.parametrize("dimensions", [1, 2, 3, 4])
def test_values_lie_in_minus_one_to_one_and_vary(dimensions):
    rng = random.Random(dimensions)
    points = [[rng.uniform(-40.0, 40.0) for _ in range(dimensions)] for _ in range(400)]
    values = _noise(points if dimensions > 1 else [p[0] for p in points], seed=9)
    assert all(-1.0 <= v <= 1.0 for v in values)
    assert sum(abs(v) for v in values) / len(values) > 0.05      # not a flat field


@pytest.mark.parametrize("dimensions", [1, 2, 3, 4])
def test_small_moves_give_small_changes(dimensions):
    """Locally smooth: a Lipschitz bound from the construction. Each of the 2^d corner terms w * (g . o) has
    partial derivatives at most |fade'| max (1.875) * |g . o| (<= sqrt(d)) + w * |g_i| (<= 1); scaled by
    2 / sqrt(d), the gradient's norm is at most 2^d (1.875 sqrt(d) + 1) * 2."""
    bound = 2 ** dimensions * (1.875 * math.sqrt(dimensions) + 1.0) * 2.0
    rng = random.Random(100 + dimensions)
    for _ in range(200):
        point = [rng.uniform(-10.0, 10.0) for _ in range(dimensions)]
        moved = [c + rng.uniform(-1e-6, 1e-6) for c in point]
        here = _noise(point if dimensions > 1 else point[0])
        there = _noise(moved if dimensions > 1 else moved[0])
        assert abs(here - there) <= bound * math.dist(point, moved)


def test_a_position_that_is_not_one_to_four_numbers_fails_the_run_naming_the_input():
    with pytest.raises(GraphRuntimeError, match="inputs:position must be a float or a 2-, 3- or 4-vector"):
        _noise([[1.0, 2.0, 3.0, 4.0, 5.0]])
