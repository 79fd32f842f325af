"""SetPrimActive through the world: a free body out of the simulation and back (the packaged UR10 cell)."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.testing import NodeHarness

STAGE = "asset:ur10_pick_place.usda"
CUBE = "/World/Cube"


def _set_active(world, path, active):
    NodeHarness("omni.graph.action.SetPrimActive", {"primTarget": [path], "active": active},
                world=world).compute("execIn")


def _is_active(world, path):
    return NodeHarness("omni.graph.nodes.IsPrimActive", {"primTarget": [path]}, world=world).compute().outputs["active"]


def test_an_inactive_body_neither_moves_nor_collides_and_falls_freely_once_active_again():
    with create_world(STAGE) as world:
        resting_height = world.prim_pose(CUBE)[0][2]                           # on the ground as authored
        world.set_attribute(CUBE, "xformOp:translate", (0.6, 0.3, 0.5))      # half a metre up, at rest
        _set_active(world, CUBE, False)
        assert _is_active(world, CUBE) is False and _is_active(world, "/World/ur10") is True
        for _ in range(30):
            world.step()
        assert world.prim_pose(CUBE)[0] == pytest.approx((0.6, 0.3, 0.5), abs=1e-9)     # half a second, still
        hit = world.raycast((0.6, 0.3, 1.0), (0.0, 0.0, -1.0), 2.0)
        assert hit is not None and hit.prim_path != CUBE and hit.position[2] < 0.01          # the ray meets the ground
        _set_active(world, CUBE, True)
        assert _is_active(world, CUBE) is True
        steps = 6
        for _ in range(steps):
            world.step()
        # from rest: after k substeps of h, semi-implicit Euler has dropped g h^2 k (k + 1) / 2
        g, h = 9.81, world.time_step / world.substeps
        k = steps * world.substeps
        assert world.prim_pose(CUBE)[0][2] == pytest.approx(0.5 - g * h * h * k * (k + 1) / 2, abs=1e-6)
        for _ in range(120):                                                   # it collides again: lands, rests
            world.step()
        assert world.prim_pose(CUBE)[0][2] == pytest.approx(resting_height, abs=2e-3)


def test_a_reset_makes_every_prim_active_again():
    with create_world(STAGE) as world:
        _set_active(world, CUBE, False)
        world.reset()
        assert _is_active(world, CUBE) is True


def test_articulation_links_and_unknown_prims_are_refused_naming_them():
    with create_world(STAGE) as world:
        with pytest.raises(GraphRuntimeError, match="wrist_1_link is part of the articulation /World/ur10"):
            _set_active(world, "/World/ur10/wrist_1_link", False)
        with pytest.raises(GraphRuntimeError, match="no prim /World/Nothing"):
            _set_active(world, "/World/Nothing", False)
    with pytest.raises(GraphRuntimeError, match="names no stage"):
        NodeHarness("omni.graph.action.SetPrimActive", {"prim": CUBE}).compute("execIn")
