"""Isaac's ``test_surface_gripper_view.py`` scenarios (reference §7.2)."""
import pytest

from graphflow.gripper import manager_for
from graphflow.gripper.view import GripperView
from graphflow.physics import create_world

from .view_scenes import view_stage


@pytest.fixture
def two_envs():
    stage, paths = view_stage([1, 1])
    world = create_world(stage)
    yield world, GripperView(manager_for(world), paths)
    world.close()


def _flat(columns):
    return [value for column in columns for value in column]


def _frames(world, count):
    for _ in range(count):
        world.step()


def test_initialize_and_play_eight_frames(two_envs):
    world, view = two_envs
    _frames(world, 8)
    assert view.get_surface_gripper_status() == ["Open", "Open"]


def test_status_changes_at_once_and_by_index(two_envs):
    world, view = two_envs
    _frames(world, 8)
    view.apply_gripper_action([-0.5, -0.5])
    _frames(world, 8)
    assert view.get_surface_gripper_status() == ["Open", "Open"]
    view.apply_gripper_action([0.5, 0.5])
    assert view.get_surface_gripper_status() == ["Closed", "Closed"]      # no physics step needed
    assert view.get_gripped_objects() == [[], []]                          # attaches run at the next step
    view.apply_gripper_action([0.0, -0.5], indices=[1])
    assert view.get_surface_gripper_status() == ["Closed", "Open"]
    _frames(world, 1)
    assert view.get_gripped_objects() == [["/env0/box0"], []]


def test_action_thresholds_are_strict(two_envs):
    world, view = two_envs
    manager = view.manager
    assert manager.set_gripper_action("/env0/SurfaceGripper", 0.3) is False
    assert view.get_surface_gripper_status()[0] == "Open"
    assert manager.set_gripper_action("/env0/SurfaceGripper", 0.30001) is True
    assert view.get_surface_gripper_status()[0] == "Closed"
    assert manager.set_gripper_action("/env0/SurfaceGripper", -0.3) is False
    assert view.get_surface_gripper_status()[0] == "Closed"
    assert manager.set_gripper_action_batch(["/env0/SurfaceGripper"], [0.5, 0.5]) == []


def test_properties_round_trip_partially_and_by_index(two_envs):
    _, view = two_envs
    assert _flat(view.get_surface_gripper_properties()) == pytest.approx([0.01] * 2 + [500000.0] * 4 + [0.0] * 2)
    view.set_surface_gripper_properties(max_grip_distance=[1.0, 1.0], coaxial_force_limit=[2.0, 2.0],
                                        shear_force_limit=[0.3, 0.5], retry_interval=[0.1, 0.2])
    assert _flat(view.get_surface_gripper_properties()) == pytest.approx([1.0, 1.0, 2.0, 2.0, 0.3, 0.5, 0.1, 0.2])
    view.set_surface_gripper_properties(max_grip_distance=[0.05, 0.06], shear_force_limit=[7.0, 8.0])
    assert _flat(view.get_surface_gripper_properties()) == pytest.approx([0.05, 0.06, 2.0, 2.0, 7.0, 8.0, 0.1, 0.2])
    view.set_surface_gripper_properties(coaxial_force_limit=[9.0, 10.0], indices=[1])
    assert view.get_surface_gripper_properties()[1] == pytest.approx([2.0, 10.0])
    with pytest.raises(ValueError, match="max_grip_distance needs 2 values"):
        view.set_surface_gripper_properties(max_grip_distance=[1.0])
    with pytest.raises(ValueError, match="values needs 2 values"):
        view.apply_gripper_action([0.5])


def test_properties_authored_on_the_stage_are_picked_up(two_envs):
    world, view = two_envs
    world.stage.GetPrimAtPath("/env1/SurfaceGripper").GetAttribute("isaac:maxGripDistance").Set(0.5)
    assert view.get_surface_gripper_properties()[0] == pytest.approx([0.01, 0.5])


@pytest.mark.slow
def test_900_single_point_and_100_nine_point_grippers_all_close_within_two_steps():
    stage, paths = view_stage([1] * 900 + [9] * 100)
    world = create_world(stage)
    try:
        view = GripperView(manager_for(world), paths)
        _frames(world, 8)
        view.apply_gripper_action([0.5] * view.count)
        _frames(world, 2)
        assert view.get_surface_gripper_status() == ["Closed"] * 1000
        gripped = view.get_gripped_objects()
        assert gripped == [[f"/env{i}/box0"] for i in range(1000)]
        assert all(len(view.manager.component(p).active) == 9 for p in paths[900:])
    finally:
        world.close()
