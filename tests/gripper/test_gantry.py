"""Isaac Sim's surface-gripper tests (reference §7.1) in Isaac's gantry stage and in graphflow's own.

Setup as ``test_surface_gripper.py``: in Isaac's stage the grippers are created
programmatically on the nine cone joints; graphflow's ``asset:gantry.usda``
already has ``/World/SurfaceGripper``. ``GripperView`` values maxGripDistance
0.02, coaxial 0.005 N, shear 5 N, retry 1.0 s; 60 Hz physics; write-to-USD off.
"""
import pytest

from graphflow.gripper import manager_for
from graphflow.physics import create_world

from gantry_scenes import GRIPPER, SECOND_GRIPPER, GantryDriver, isaac_gantry_stage

CUBE_28 = "/World/Boxes/Cube_28"
VIEW_PROPERTIES = dict(max_grip_distance=0.02, coaxial_force_limit=0.005, shear_force_limit=5.0, retry_interval=1.0)


def _gantry(second_gripper_over=None, scene="isaac"):
    world = create_world(isaac_gantry_stage(second_gripper_over) if scene == "isaac" else "asset:gantry.usda")
    manager = manager_for(world)
    paths = [GRIPPER] if second_gripper_over is None else [GRIPPER, SECOND_GRIPPER]
    manager.set_gripper_properties(paths, **VIEW_PROPERTIES)
    return world, manager, GantryDriver(world, manager)


@pytest.fixture(params=["isaac", "graphflow"])
def gantry(request):
    world, manager, driver = _gantry(scene=request.param)
    yield driver
    world.close()


def test_create_and_run_eight_frames(gantry):
    gantry.frames(8)
    assert gantry.status() == "Open" and gantry.gripped() == []


def test_configured_properties_read_back(gantry):
    assert gantry.manager.get_gripper_properties(GRIPPER) == pytest.approx((0.02, 0.005, 5.0, 1.0))


def test_close_open_close_on_one_cube(gantry):
    gantry.move(0, 0, 0.140)
    gantry.action(0.5, 60)
    assert gantry.status() == "Closed"
    assert gantry.gripped() == [CUBE_28]
    gantry.frames(2)
    gantry.action(-0.5, 1)
    assert gantry.status() == "Open" and gantry.gripped() == []
    gantry.frames(2)
    gantry.action(0.5, 120)
    assert gantry.status() == "Closed" and gantry.gripped() == [CUBE_28]


def test_two_cubes_at_once(gantry):
    gantry.move(0.175, 0, 0.140)
    gantry.action(0.5, 60)
    assert gantry.status() == "Closed"
    gantry.frames(1)
    assert gantry.gripped() == ["/World/Boxes/Cube_20", "/World/Boxes/Cube_24"]
    gantry.action(-0.5, 1)
    assert gantry.status() == "Open" and gantry.gripped() == []
    gantry.action(0.5, 60)
    assert gantry.status() == "Closed"
    assert gantry.gripped() == ["/World/Boxes/Cube_20", "/World/Boxes/Cube_24"]


def test_out_of_reach_at_0125_stays_open(gantry):
    gantry.move(0, 0, 0.125, settle=240)      # fully settled: cone centres 24.9 mm above the cube
    cones = gantry.world.prim_pose("/World/Gripper_Cones")[0][2]
    assert cones - 1.2 == pytest.approx(0.0249, abs=0.001)
    gantry.action(0.5, 60)
    assert gantry.status() == "Open" and gantry.gripped() == []
    gantry.action(-0.5, 1)
    assert gantry.status() == "Open"
    gantry.action(0.5, 60)
    assert gantry.status() == "Open" and gantry.gripped() == []


def test_within_reach_at_0140_grips(gantry):
    gantry.move(0, 0, 0.140, settle=240)
    cones = gantry.world.prim_pose("/World/Gripper_Cones")[0][2]
    assert cones - 1.2 == pytest.approx(0.0099, abs=0.001)
    gantry.action(0.5, 1)
    assert gantry.status() == "Closed" and gantry.gripped() == [CUBE_28]


def test_retry_interval_closes_when_the_gantry_comes_down_in_time(gantry):
    gantry.move(0, 0, 0.125)
    gantry.action(0.5, 6)
    assert gantry.status() == "Closing" and gantry.gripped() == []
    gantry.move(0, 0, 0.140)
    gantry.frames(60)
    assert gantry.status() == "Closed" and gantry.gripped() == [CUBE_28]


def test_retry_interval_runs_out_without_an_object(gantry):
    gantry.move(0, 0, 0.125, settle=240)
    gantry.action(0.5, 58)      # 58 steps of 1/60 s: inside the 1.0 s window
    assert gantry.status() == "Closing"
    gantry.frames(4)
    assert gantry.status() == "Open" and gantry.gripped() == []


def _hold_force(gantry, force, frames):
    """A persistent force on Cube_28, as a PhysxForceAPI attribute applies every step."""
    for _ in range(frames):
        gantry.world.apply_force(CUBE_28, force)
        gantry.world.step()


def test_shear_4n_holds_and_500n_breaks(gantry):
    gantry.move(0, 0, 0.140)
    gantry.action(0.5, 60)
    _hold_force(gantry, (0, -4, 0), 1)
    assert gantry.status() == "Closed" and gantry.gripped() == [CUBE_28]
    breaks = gantry.manager.component(GRIPPER).events.force_breaks
    _hold_force(gantry, (0, -500, 0), 61)
    assert gantry.status() == "Open" and gantry.gripped() == []
    assert gantry.manager.component(GRIPPER).events.force_breaks - breaks == 9


def test_small_coaxial_pull_holds_and_1000n_breaks(gantry):
    gantry.move(0, 0, 0.140)
    gantry.action(0.5, 60)
    _hold_force(gantry, (0, 0, -0.003), 1)
    assert gantry.status() == "Closed" and gantry.gripped() == [CUBE_28]
    gantry.move(0, 0, 0.0)                         # lift: the soft Z drives carry the 0.2 kg box
    assert gantry.status() == "Closed" and gantry.gripped() == [CUBE_28]
    assert gantry.world.prim_pose(CUBE_28)[0][2] > 1.24
    component = gantry.manager.component(GRIPPER)
    _hold_force(gantry, (0, 0, -1000), 2)
    # the pull drives the joints to their 10 mm transZ limit: every point breaks, the box is let go
    assert component.events.force_breaks == 9
    assert gantry.status() != "Closed" and CUBE_28 not in gantry.gripped()
    _hold_force(gantry, (0, 0, -1000), 119)
    # the 1000 N pull keeps the box down on the lower layer (its centre 1.1375 m, on the boxes below,
    # not through them). Known difference from Isaac's test, which ends Open: the hold breaks on the
    # second frame here, by when the pull has dragged the gantry (Z drive force limit 30 N) 0.13 m
    # down, within reach of the box, so the retry window (1 s, still armed) grips it again.
    assert 1.13 < gantry.world.prim_pose(CUBE_28)[0][2] < 1.16


def test_two_grippers_with_a_partial_grip():
    world, manager, gantry = _gantry(second_gripper_over="/World/Boxes/Cube_30")
    paths = [GRIPPER, SECOND_GRIPPER]
    try:
        gantry.move(0, 0.05, 0.14)
        gantry.action(0.5, 60, paths)
        assert [s.token for s in manager.get_gripper_status_batch(paths)] == ["Closing", "Closed"]
        assert manager.get_gripped_objects_batch(paths) == [[CUBE_28], ["/World/Boxes/Cube_30"]]
        assert len(manager.component(GRIPPER).active) == 6     # the x = 0.0745 column misses
        gantry.action(-0.5, 60, paths)
        assert [s.token for s in manager.get_gripper_status_batch(paths)] == ["Open", "Open"]
        assert manager.get_gripped_objects_batch(paths) == [[], []]
        gantry.action(0.5, 60, paths)
        assert [s.token for s in manager.get_gripper_status_batch(paths)] == ["Closing", "Closed"]
        assert manager.get_gripped_objects_batch(paths) == [[CUBE_28], ["/World/Boxes/Cube_30"]]
    finally:
        world.close()


def test_create_surface_gripper_direct_picks_free_names():
    from graphflow.gripper import create_surface_gripper

    stage = isaac_gantry_stage()
    assert create_surface_gripper(stage, "/World").GetPath().pathString == "/World/SurfaceGripper_01"
    assert create_surface_gripper(stage, "/World").GetPath().pathString == "/World/SurfaceGripper_02"
    assert create_surface_gripper(stage, "/Other").GetPath().pathString == "/Other/SurfaceGripper"
