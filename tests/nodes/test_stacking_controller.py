"""graphflow.StackingController on a fake UR10 world: cube order, stack heights, one routine per cube."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.kinematics import ur10_chain
from graphflow.testing import ExecState, NodeHarness

from .fakes import FakeUR10World

ROBOT, GRIPPER = "/World/ur10", "/World/ur10/ee_link/SurfaceGripper"
CUBES = {"/World/Cube_0": (0.25, 0.25, 0.025), "/World/Cube_1": (0.2, -0.2, 0.025), "/World/Cube_2": (0.5, 0.0, 0.025)}
FAST = [0.125, 0.125, 0.5, 1.0, 0.125, 0.125, 0.125, 1.0, 0.125, 0.5]   # 8+8+2+1+8+8+8+1+8+2 = 54 ticks per cube
PER_CUBE = 54
CHAIN = ur10_chain()


def _stacking(cubes=tuple(CUBES), **inputs):
    world = FakeUR10World(poses={path: (position, (0.0, 0.0, 0.0, 1.0)) for path, position in CUBES.items()})
    values = {"robotPrim": ROBOT, "gripperPrim": GRIPPER, "cubePrims": list(cubes),
              "stackPosition": (0.4, 0.4, 0.025), "cubeHeight": 0.05, "endEffectorOffset": (0.0, 0.0, 0.03),
              "eventsDT": FAST, **inputs}
    node = NodeHarness("graphflow.StackingController", inputs=values, world=world)
    results = [node.tick("execIn")] + [node.tick() for _ in range(3 * PER_CUBE + 2)]
    return node, world, results


def _tip(result):
    return CHAIN.forward(result.outputs["jointTargets"])[:3, 3]


def test_cubes_are_handled_in_order_without_idle_ticks():
    _, _, results = _stacking()
    assert [r.outputs["cubeIndex"] for r in results[:162]] == [0] * PER_CUBE + [1] * PER_CUBE + [2] * PER_CUBE
    assert [r.outputs["event"] for r in results[52:56]] == [9, 9, 0, 0]
    assert results[162].outputs["cubeIndex"] == 3 and results[162].outputs["isDone"]
    assert results[162].exec_states["finished"] == ExecState.LATENT_FINISH
    assert sum("phaseStarted" in r.fired for r in results) == 3 * 10 + 1


def test_each_cube_is_picked_where_it_is_and_placed_one_height_higher():
    _, world, results = _stacking()
    for index, (x, y, z) in enumerate(CUBES.values()):
        start = PER_CUBE * index
        assert _tip(results[start + 19]) == pytest.approx((x, y, z + 0.03), abs=1e-4)          # lift, t = 0
        assert _tip(results[start + 44]) == pytest.approx((0.4, 0.4, 0.025 + 0.05 * index + 0.03), abs=1e-4)
    closes = [step for step, kind, _ in world.surface_grippers.commands if kind == "close"]
    opens = [step for step, kind, _ in world.surface_grippers.commands if kind == "open"]
    assert closes == [19, 73, 127] and opens == [44, 98, 152]     # world steps: tick 18 and 43 of each cube


def test_no_cubes_is_an_error():
    node = NodeHarness("graphflow.StackingController", inputs={"robotPrim": ROBOT, "gripperPrim": GRIPPER},
                       world=FakeUR10World())
    with pytest.raises(GraphRuntimeError, match="inputs:cubePrims: no cubes"):
        node.tick("execIn")
