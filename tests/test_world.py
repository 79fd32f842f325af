"""The declared backend interface: every backend implements all of it; one factory picks the backend."""
import inspect

import pytest

from graphflow.runtime import DEFAULT_TIME_STEP, create_world
from graphflow.testing.fake_world import FakeWorld
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


BOX, GRIPPER = "/World/Box", "/World/Gripper"
BOXES = {BOX: ((0.0, 0.0, 0.5), 0.1), GRIPPER: ((0.0, 0.0, 1.0), 0.05)}     # centre, half size


def _pybullet_scene():
    pytest.importorskip("pybullet")
    from pxr import Gf, Usd, UsdGeom, UsdPhysics

    from graphflow.physics import create_world as create_pybullet_world

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    for path, (center, half) in BOXES.items():
        cube = UsdGeom.Cube.Define(stage, path)
        cube.CreateSizeAttr(2 * half)
        cube.AddTranslateOp().Set(Gf.Vec3d(*center))
        UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
        UsdPhysics.RigidBodyAPI.Apply(cube.GetPrim()).CreateKinematicEnabledAttr(True)
    return create_pybullet_world(stage)


def _fake_scene():
    world = FakeWorld()
    for path, (center, half) in BOXES.items():
        world.add_box(path, center, (half, half, half))
    return world


@pytest.fixture(params=[_fake_scene, _pybullet_scene], ids=["fake", "pybullet"])
def two_boxes(request):
    """The gripper box 0.4 m above the other box, on each backend."""
    world = request.param()
    yield world
    getattr(world, "close", lambda: None)()


def test_the_fake_and_pybullet_agree_on_rays_bodies_and_attachments(two_boxes):
    world = two_boxes
    hit = world.raycast((0.0, 0.0, 0.9), (0.0, 0.0, -2.0), 1.0)     # from under the gripper, straight down
    assert hit.prim_path == BOX and hit.distance == pytest.approx(0.3, abs=1e-4)
    assert hit.position == pytest.approx((0.0, 0.0, 0.6), abs=1e-4)
    assert hit.normal == pytest.approx((0.0, 0.0, 1.0), abs=1e-6)
    assert world.raycast((1.0, 0.0, 0.9), (0.0, 0.0, -1.0), 1.0) is None
    assert [h is None for h in world.raycast_batch([(0, 0, 0.9), (0, 0, 0.9)], [(0, 0, -1), (0, 0, 1)], 0.05)] == [
        True, False]                                                  # down: 0.3 m away; up: the gripper, 0.05 m
    assert world.body_of(BOX) == BOX and world.body_of("/World/Nothing") is None
    assert world.same_body(BOX, BOX) and not world.same_body(BOX, GRIPPER)
    under = ((0.0, 0.0, -0.05), (0.0, 0.0, 0.0, 1.0))                  # a frame on the gripper's bottom face
    frame = world.attachments.frame(GRIPPER, under)
    assert frame[0] == pytest.approx((0.0, 0.0, 0.95), abs=1e-6)
    assert world.attachments.frame("/World/Nothing", under) is None
    assert world.attachments.attach(GRIPPER, under, "/World/Nothing") is None
    handle = world.attachments.attach(GRIPPER, under, BOX)
    assert world.attachments.target_of(handle) == BOX
    world.step()
    assert len(world.attachments.force_on_gripper(handle)) == 3
    world.attachments.detach(handle)
    world.attachments.detach(handle)                                  # twice is harmless
    world.reset()
    assert world.step_index == 0
