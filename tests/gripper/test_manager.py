"""Manager behaviour beyond Isaac's tests: USD write-back, authority of the in-memory status, lookups."""
import pytest

from graphflow.gripper import manager_for
from graphflow.physics import create_world

GRIPPER = "/World/SurfaceGripper"


@pytest.fixture
def world():
    world = create_world("asset:gantry.usda")
    yield world
    world.close()


def test_one_manager_per_world_reachable_from_the_world(world):
    manager = manager_for(world)
    assert manager_for(world) is manager and world.services.get(type(manager)) is manager
    assert list(world.services) == [manager]


def test_write_to_usd_is_off_by_default(world):
    manager = manager_for(world)
    manager.close_gripper(GRIPPER)
    world.step()
    assert manager.get_gripper_status(GRIPPER).token == "Closing"
    assert world.stage.GetPrimAtPath(GRIPPER).GetAttribute("isaac:status").Get() == "Open"
    assert list(world.stage.GetSessionLayer().subLayerPaths) == []


def test_status_authored_in_usd_never_overwrites_the_runtime(world):
    manager = manager_for(world)
    world.stage.GetPrimAtPath(GRIPPER).GetAttribute("isaac:status").Set("Closed")
    world.stage.GetPrimAtPath(GRIPPER).GetAttribute("isaac:shearForceLimit").Set(7.0)   # a property edit
    world.step()
    assert manager.get_gripper_status(GRIPPER).token == "Open"
    assert manager.get_gripper_properties(GRIPPER)[2] == pytest.approx(7.0)


def test_unknown_grippers(world):
    manager = manager_for(world)
    assert manager.close_gripper("/World/Nothing") is False
    assert manager.get_gripper_status("/World/Nothing").token == "Open"
    assert manager.get_gripped_objects("/World/Nothing") == []
    with pytest.raises(KeyError, match="no IsaacSurfaceGripper prim at /World/Nothing"):
        manager.set_gripper_properties("/World/Nothing", max_grip_distance=0.1)


def test_a_gripper_created_after_the_world_is_found(world):
    from graphflow.gripper import create_surface_gripper

    manager = manager_for(world)
    prim = create_surface_gripper(world.stage, "/World")
    prim.GetRelationship("isaac:attachmentPoints").SetTargets(
        [world.stage.GetPrimAtPath("/World/Surface_Gripper_Joints/D6Joint").GetPath()])
    assert manager.get_gripper_status(prim.GetPath().pathString).token == "Open"
    assert len(manager.component(prim.GetPath().pathString).points) == 1


def test_reset_releases_everything_and_returns_to_open(world):
    manager = manager_for(world)
    world.set_attribute("/World/Joints/z_joint", "drive:linear:physics:targetPosition", 0.14)
    for _ in range(240):
        world.step()
    manager.close_gripper(GRIPPER)
    world.step()
    assert manager.get_gripped_objects(GRIPPER) == ["/World/Boxes/Cube_28"]
    world.reset()
    assert manager.get_gripper_status(GRIPPER).token == "Open" and manager.get_gripped_objects(GRIPPER) == []
    world.step()
    assert manager.get_gripper_status(GRIPPER).token == "Open"
