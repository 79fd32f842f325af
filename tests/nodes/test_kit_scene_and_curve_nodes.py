"""omni.graph.nodes ReadPrimRelationship, GetPrimDirectionVector, Ease, Interpolator and the Random* nodes."""
import math

import pytest
from pxr import Usd

from graphflow.executor import GraphRuntimeError
from graphflow.testing import GraphHarness, NodeHarness
from graphflow.testing.fake_world import FakeWorld


def out(type_id, output, world=None, **inputs):
    return NodeHarness(f"omni.graph.nodes.{type_id}", inputs, world=world).compute().outputs[output]


def test_read_prim_relationship_reads_the_authored_targets():
    stage = Usd.Stage.CreateInMemory()
    stage.DefinePrim("/World/Gripper").CreateRelationship("grips").SetTargets(["/World/A", "/World/B"])
    world = FakeWorld(stage=stage)
    assert out("ReadPrimRelationship", "value", world, prim=["/World/Gripper"], name="grips") == \
        ("/World/A", "/World/B")
    with pytest.raises(GraphRuntimeError, match="has no relationship 'holds'"):
        out("ReadPrimRelationship", "value", world, prim=["/World/Gripper"], name="holds")


def test_direction_vectors_turn_with_the_prim():
    world = FakeWorld()
    half = math.sqrt(0.5)
    world.add_box("/World/robot", (1.0, 2.0, 0.0), (0.1, 0.1, 0.1), orientation=(0.0, 0.0, half, half))  # +90 deg about Z
    vectors = NodeHarness("omni.graph.nodes.GetPrimDirectionVector", {"primPath": "/World/robot"},
                          world=world).compute().outputs
    assert vectors["rightVector"] == pytest.approx((0.0, 1.0, 0.0))      # local +X now points along world +Y
    assert vectors["leftVector"] == pytest.approx((0.0, -1.0, 0.0))
    assert vectors["upVector"] == pytest.approx((-1.0, 0.0, 0.0))
    assert vectors["forwardVector"] == pytest.approx((0.0, 0.0, -1.0))
    assert vectors["backwardVector"] == pytest.approx((0.0, 0.0, 1.0))
    assert vectors["downVector"] == pytest.approx((1.0, 0.0, 0.0))


@pytest.mark.parametrize("func, alpha, expected", [
    ("Linear", 0.25, 2.5), ("EaseIn", 0.5, 0.25 * 10), ("EaseOut", 0.5, 0.75 * 10), ("EaseInOut", 0.25, 1.25),
    ("EaseInOut", 0.75, 8.75), ("SinIn", 1 / 3, (1 - math.cos(math.pi / 6)) * 10), ("SinOut", 1 / 3, 5.0),
    ("SinInOut", 0.5, 5.0), ("Linear", 7.0, 10.0), ("EaseIn", -1.0, 0.0),
])
def test_ease_curves_with_the_default_quadratic_exponent(func, alpha, expected):
    assert out("Ease", "result", start=0.0, end=10.0, alpha=alpha, easeFunc=func) == pytest.approx(expected)


def test_ease_vectors_componentwise_and_alpha_arrays():
    assert out("Ease", "result", start=(0.0, 10.0), end=(4.0, 20.0), alpha=0.5, easeFunc="Linear") == (2.0, 15.0)
    assert out("Ease", "result", start=0.0, end=1.0, alpha=(0.0, 0.5, 1.0), easeFunc="EaseIn",
               blendExponent=3) == pytest.approx((0.0, 0.125, 1.0))


def test_interpolator_is_piecewise_linear_and_held_outside():
    knots, values = (0.0, 1.0, 3.0), (0.0, 10.0, 30.0)
    for param, expected in [(-1.0, 0.0), (0.5, 5.0), (2.0, 20.0), (3.0, 30.0), (9.0, 30.0)]:
        assert out("Interpolator", "value", knots=knots, values=values, param=param) == pytest.approx(expected)
    with pytest.raises(GraphRuntimeError, match="must be as long"):
        out("Interpolator", "value", knots=(0.0, 1.0), values=(1.0,))


def _draws(type_id, ticks, **inputs):
    g = GraphHarness({"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "rand", "type": f"omni.graph.nodes.{type_id}", "inputs": inputs}],
        "connections": [{"src": "tick.outputs:tick", "dst": "rand.inputs:execIn"}]})
    values = []
    for _ in range(ticks):
        g.run(ticks=1)
        values.append(g.output("rand", "random"))
    return values


def test_random_draws_follow_the_seed_and_noise_repeats():
    first = _draws("RandomUnitVector", 200, useSeed=True, seed=7)
    assert first == _draws("RandomUnitVector", 200, useSeed=True, seed=7)
    assert first != _draws("RandomUnitVector", 200, useSeed=True, seed=8)
    assert all(math.isclose(sum(c * c for c in v), 1.0) for v in first)
    assert abs(sum(v[2] for v in first) / len(first)) < 0.15           # uniform on the sphere: mean z near 0
    noise = _draws("RandomBoolean", 20, isNoise=True, seed=3)
    assert len(set(noise)) == 1
    coins = _draws("RandomBoolean", 400, useSeed=True, seed=1)
    assert 160 < sum(coins) < 240
    quaternions = _draws("RandomUnitQuaternion", 50, useSeed=True, seed=2)
    assert all(math.isclose(sum(c * c for c in q), 1.0) for q in quaternions)


def test_random_without_a_seed_follows_the_runs_seed():
    from graphflow.seeding import seed_everything

    try:
        seed_everything(11)
        run_a = _draws("RandomUnitVector", 30)
        seed_everything(11)
        assert _draws("RandomUnitVector", 30) == run_a
        seed_everything(12)
        assert _draws("RandomUnitVector", 30) != run_a
    finally:
        seed_everything(0)


def test_any_zero_and_each_zero_follow_the_references_examples():
    assert out("AnyZero", "result", value=(3, 0, 1)) is True
    assert out("AnyZero", "result", value=((3, 0, 1), (-5, 4, 17))) is False
    assert out("AnyZero", "result", value=((3, 0, 1), (0, 0, 0))) is True
    assert out("AnyZero", "result", value=0.05, tolerance=0.1) is True
    assert out("EachZero", "result", value=(3, 0, 1)) == (False, True, False)
    assert out("EachZero", "result", value=((3, 0, 1), (-5, 4, 17))) == (False, False)
    assert out("EachZero", "result", value=-0.0) is True
