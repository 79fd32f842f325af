"""The status machine of reference §2.4-2.7 and 2.11 on the fake backend (kinematic boxes, scripted forces).

The gripper talks to ``FakeWorld`` only through the world interface, as it talks to PyBullet.
Scene: the gripper body is a box above z = 0 (bottom at *body_bottom*); attachment point i
sits at (i, 0, 0) with its forward axis (+Z) turned to point down; objects are boxes whose
tops are 10 mm below the points.
"""
import pytest

from graphflow.gripper.component import (
    SETTLING_DELAY,
    AttachmentPoint,
    GripperProperties,
    GripperStatus,
    SurfaceGripperComponent,
)
from graphflow.testing.fake_world import FakeWorld

STEP = 1.0 / 60.0
DOWN = (1.0, 0.0, 0.0, 0.0)        # forward +Z turned to point down
BODY_TOP = 0.1
BODY_X = 0.5


def _place(world, path, xs, gap=0.01):
    """A 10 cm tall box under the points at *xs*, its top *gap* below them."""
    center = sum(xs) / len(xs)
    half_x = (max(xs) - min(xs)) / 2 + 0.2
    world.add_box(path, (center, 0.0, -gap - 0.05), (half_x, 0.1, 0.05))


def _gripper(count=2, body_bottom=0.001, **properties):
    world = FakeWorld(STEP)
    world.add_box("/body", (BODY_X, 0.0, (BODY_TOP + body_bottom) / 2),
                  (1.0, 0.1, (BODY_TOP - body_bottom) / 2))
    body_z = (BODY_TOP + body_bottom) / 2
    actions = []
    points = [AttachmentPoint(f"/j{i}", "/body", ((float(i) - BODY_X, 0.0, -body_z), DOWN), forward_axis="Z")
              for i in range(count)]
    component = SurfaceGripperComponent("/G", points, world, actions.append,
                                        GripperProperties(max_grip_distance=0.02, **properties))
    attachments = world.attachments

    def step():
        world.step()
        component.on_physics_step(STEP)
        for action in actions:          # the manager's queue, run at the end of the update
            point = points[action[2]]
            if action[0] == "attach":
                component.handles[action[2]] = attachments.attach(point.body0_path, point.local_pose0, action[3])
            else:
                handle = component.handles.pop(action[2], None)
                if handle is not None:
                    attachments.detach(handle)
        actions.clear()

    return component, world, step


def test_close_with_every_point_hitting_is_closed_at_once():
    component, world, step = _gripper()
    _place(world, "/box", [0.0, 1.0])
    component.set_status(GripperStatus.CLOSED)
    assert component.status == GripperStatus.CLOSED
    assert component.gripped_objects() == []          # attaches are queued until the next update
    step()
    assert component.gripped_objects() == ["/box"]    # two points, one object, listed once
    assert world.attachments.held() == ["/box", "/box"]


def test_failed_close_without_retry_shows_closing_until_the_next_step():
    component, _, step = _gripper(retry_interval=0.0)
    component.set_status(GripperStatus.CLOSED)
    assert component.status == GripperStatus.CLOSING
    step()
    assert component.status == GripperStatus.OPEN


def test_retry_window_counts_physics_time_then_gives_up():
    component, world, step = _gripper(retry_interval=0.1)
    component.set_status(GripperStatus.CLOSED)
    for _ in range(6):
        step()
    assert component.status == GripperStatus.CLOSING
    step()                                             # 7 * 1/60 > 0.1 s
    assert component.status == GripperStatus.OPEN


def test_object_arriving_inside_the_retry_window_closes():
    component, world, step = _gripper(retry_interval=1.0)
    component.set_status(GripperStatus.CLOSED)
    step()
    _place(world, "/box", [0.0, 1.0])
    step()
    assert component.status == GripperStatus.CLOSED and component.retry_elapsed == 0.0


def test_partial_grip_stays_closing_and_keeps_casting_after_the_window():
    component, world, step = _gripper(retry_interval=0.05)
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    for _ in range(30):
        step()
    assert component.status == GripperStatus.CLOSING and not component.retry_active
    rays = len(world.rays)
    step()
    assert len(world.rays) == rays + 1                 # the free point still raycasts
    _place(world, "/other", [1.0])
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.CLOSED
    assert component.gripped_objects() == ["/box", "/other"]


def test_close_while_closing_does_not_restart_the_retry_timer():
    component, _, step = _gripper(retry_interval=1.0)
    component.set_status(GripperStatus.CLOSED)
    for _ in range(10):
        step()
    elapsed = component.retry_elapsed
    assert component.set_status(GripperStatus.CLOSED) is True
    assert component.retry_elapsed == elapsed


def test_open_releases_everything():
    component, world, step = _gripper()
    _place(world, "/a", [0.0])
    _place(world, "/b", [1.0])
    component.set_status(GripperStatus.CLOSED)
    step()
    assert world.attachments.held() == ["/a", "/b"]
    component.set_status(GripperStatus.OPEN)
    assert component.status == GripperStatus.OPEN and component.gripped_objects() == []
    step()
    assert world.attachments.holds == {} and component.events.releases == 1


def test_reach_is_max_grip_distance_from_the_joint_origin_and_self_hits_step_1mm():
    component, world, step = _gripper(count=1, body_bottom=-0.0055)     # the body reaches 5.5 mm below the point
    _place(world, "/box", [0.0])
    point = component.points[0]
    point.clearance_offset = 0.004
    component.set_status(GripperStatus.CLOSED)
    # rays start 4, 5 and 6 mm down the forward axis (-Z); each ends 20 mm from the joint origin;
    # the first two start inside the gripper's own body
    assert [(round(origin[2], 6), round(length, 6)) for origin, _, length in world.rays] == [
        (-0.004, 0.016), (-0.005, 0.015), (-0.006, 0.014)]
    assert point.clearance_offset == pytest.approx(0.006)
    assert component.status == GripperStatus.CLOSED


def test_settling_delay_then_signed_coaxial_and_shear_limits():
    component, world, step = _gripper(count=1, coaxial_force_limit=1.0, shear_force_limit=2.0)
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    step()
    world.attachments.forces["/box"] = (0.0, 0.0, -5.0)           # the object pulls the gripper along the forward axis
    for _ in range(4):                                  # settling: 10 checks (synchronous close + steps)
        step()
    assert component.status == GripperStatus.CLOSED
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.OPEN and component.events.force_breaks == 1


def test_pressing_in_never_breaks_coaxially_and_limits_at_or_below_zero_are_off():
    component, world, step = _gripper(count=1, coaxial_force_limit=1.0, shear_force_limit=0.0)
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    world.attachments.forces["/box"] = (50.0, 0.0, 5.0)          # pushed in (negative coaxial), 50 N across: shear is off
    for _ in range(30):
        step()
    assert component.status == GripperStatus.CLOSED


def test_break_with_retry_armed_goes_back_to_closing_and_regrips():
    component, world, step = _gripper(count=1, shear_force_limit=1.0, retry_interval=1.0)
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    step()
    world.attachments.forces["/box"] = (5.0, 0.0, 0.0)
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.CLOSING
    world.attachments.forces.clear()
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.CLOSED and component.gripped_objects() == ["/box"]


def test_partial_break_without_retry_stays_closed_and_never_regrips():
    component, world, step = _gripper(shear_force_limit=1.0)
    _place(world, "/a", [0.0])
    _place(world, "/b", [1.0])
    component.set_status(GripperStatus.CLOSED)
    step()
    world.attachments.forces["/a"] = (5.0, 0.0, 0.0)
    for _ in range(40):
        step()
    assert component.status == GripperStatus.CLOSED and component.gripped_objects() == ["/b"]


def test_no_attachment_points():
    component, _, step = _gripper(count=0, retry_interval=0.0)
    component.set_status(GripperStatus.CLOSED)
    assert component.status == GripperStatus.CLOSING
    step()
    assert component.status == GripperStatus.OPEN
    armed, _, step = _gripper(count=0, retry_interval=0.5)
    armed.set_status(GripperStatus.CLOSED)
    for _ in range(100):
        step()
    assert armed.status == GripperStatus.CLOSING        # the timer only runs while points are free


def test_status_tokens_and_order():
    assert [s.token for s in GripperStatus] == ["Open", "Closing", "Closed"]
    assert [int(s) for s in GripperStatus] == [0, 1, 2]
    assert GripperStatus.from_token("Closed") == GripperStatus.CLOSED
    assert GripperStatus.from_token("bogus") == GripperStatus.OPEN


def test_an_object_beyond_max_grip_distance_is_not_gripped():
    component, world, step = _gripper(count=1)
    _place(world, "/box", [0.0], gap=0.025)             # 25 mm below the point, the reach is 20 mm
    component.set_status(GripperStatus.CLOSED)
    step()
    assert component.status == GripperStatus.OPEN and world.attachments.holds == {}
