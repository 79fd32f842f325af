"""The declared backend interface: every backend implements all of it; one factory picks the backend."""
import inspect

import pytest

from graphflow.runtime import DEFAULT_TIME_STEP, create_world
from graphflow.testing_backend import FakeWorld
from graphflow.world import Attachments, ClockWorld, World, WorldError


def _members(protocol) -> set[str]:
    return {name for name in dir(protocol) if not name.startswith("_")} | set(protocol.__annotations__)


def _backends():
    yield ClockWorld()
    yield FakeWorld()
    physics = pytest.importorskip("graphflow.physics")
    with physics.create_world() as world:
        yield world


def test_every_backend_has_every_member_of_the_interface():
    for world in _backends():
        missing = {name for name in _members(World) if not hasattr(world, name)}
        assert missing == set(), f"{type(world).__name__} lacks {sorted(missing)}"
        if world.attachments is not None:
            missing = {name for name in _members(Attachments) if not hasattr(world.attachments, name)}
            assert missing == set(), f"{type(world).__name__}.attachments lacks {sorted(missing)}"


def test_the_interface_methods_take_the_same_parameters_everywhere():
    for world in _backends():
        if isinstance(world, ClockWorld):
            continue          # every physics query is one "no stage" error there
        for protocol, implementation in ((World, world), (Attachments, world.attachments)):
            for name, declared in inspect.getmembers(protocol, inspect.isfunction):
                if name.startswith("_"):
                    continue
                expected = list(inspect.signature(declared).parameters)[1:]
                actual = list(inspect.signature(getattr(implementation, name)).parameters)
                assert actual == expected, (type(implementation).__name__, name)


def test_a_world_without_a_stage_is_a_clock_and_says_so_when_asked_for_prims():
    world = create_world()
    assert isinstance(world, ClockWorld) and world.time_step == DEFAULT_TIME_STEP
    with pytest.raises(WorldError, match="names no stage"):
        world.raycast((0, 0, 0), (0, 0, -1), 1.0)


def test_a_stage_picks_the_pybullet_backend_at_the_stage_rate():
    pytest.importorskip("pybullet")
    world = create_world("asset:ur10_pick_place.usda", time_step=0.01)
    try:
        assert type(world).__name__ == "PyBulletWorld" and world.time_step == 0.01
        assert world.body_of("/World/ur10/ee_link") == "/World/ur10/ee_link"
    finally:
        world.close()
