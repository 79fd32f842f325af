"""The status machine of reference §2.4-2.7 and 2.11 on a scripted fake backend (no physics)."""
import pytest

from graphflow.gripper.runtime import (SETTLING_DELAY, AttachmentPoint, GripperProperties, GripperStatus,
                                       SurfaceGripperComponent)

STEP = 1.0 / 60.0
DOWN = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))    # forward +Z turned to point down


class FakeBackend:
    """Rays hit whatever ``targets`` maps a point's x position to; forces are scripted per object."""

    def __init__(self):
        self.targets = {}          # joint x position -> (object path, distance) the ray finds
        self.forces = {}           # object path -> force on the gripper
        self.attached = {}
        self.rays = []
        self._next = 0

    def same_body(self, a, b):
        return a == b

    def attachment_frame(self, point):
        return point.local_pose0[0], DOWN[1]

    def raycast(self, origin, direction, length):
        self.rays.append((origin, length))
        hit = self.targets.get(origin[0])
        if hit is None:
            return None
        path, distance = hit
        return path if distance <= length else None

    def attach(self, point, target):
        self._next += 1
        self.attached[self._next] = target
        return self._next

    def detach(self, handle):
        self.attached.pop(handle, None)

    def force_on_gripper(self, handle, rigid_rows_only=True):
        return self.forces.get(self.attached[handle], (0.0, 0.0, 0.0))

    def torque_on_gripper(self, handle):
        return 0.0, 0.0, 0.0


def _gripper(count=2, **properties):
    backend = FakeBackend()
    actions = []
    points = [AttachmentPoint(f"/j{i}", "/body", ((float(i), 0.0, 0.0), DOWN[1]), forward_axis="Z")
              for i in range(count)]
    component = SurfaceGripperComponent("/G", points, backend, actions.append,
                                        GripperProperties(max_grip_distance=0.02, **properties))

    def step():
        component.on_physics_step(STEP)
        for action in actions:          # the manager's queue, run at the end of the update
            if action[0] == "attach":
                component.handles[action[2]] = backend.attach(points[action[2]], action[3])
            else:
                handle = component.handles.pop(action[2], None)
                if handle is not None:
                    backend.detach(handle)
        actions.clear()

    return component, backend, step


def test_close_with_every_point_hitting_is_closed_at_once():
    component, backend, step = _gripper()
    backend.targets = {0.0: ("/box", 0.01), 1.0: ("/box", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    assert component.status == GripperStatus.CLOSED
    assert component.gripped_objects() == []          # attaches are queued until the next update
    step()
    assert component.gripped_objects() == ["/box"]    # two points, one object, listed once


def test_failed_close_without_retry_shows_closing_until_the_next_step():
    component, _, step = _gripper(retry_interval=0.0)
    component.set_status(GripperStatus.CLOSED)
    assert component.status == GripperStatus.CLOSING
    step()
    assert component.status == GripperStatus.OPEN


def test_retry_window_counts_physics_time_then_gives_up():
    component, backend, step = _gripper(retry_interval=0.1)
    component.set_status(GripperStatus.CLOSED)
    for _ in range(6):
        step()
    assert component.status == GripperStatus.CLOSING
    step()                                             # 7 * 1/60 > 0.1 s
    assert component.status == GripperStatus.OPEN


def test_object_arriving_inside_the_retry_window_closes():
    component, backend, step = _gripper(retry_interval=1.0)
    component.set_status(GripperStatus.CLOSED)
    step()
    backend.targets = {0.0: ("/box", 0.01), 1.0: ("/box", 0.01)}
    step()
    assert component.status == GripperStatus.CLOSED and component.retry_elapsed == 0.0


def test_partial_grip_stays_closing_and_keeps_casting_after_the_window():
    component, backend, step = _gripper(retry_interval=0.05)
    backend.targets = {0.0: ("/box", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    for _ in range(30):
        step()
    assert component.status == GripperStatus.CLOSING and not component.retry_active
    rays = len(backend.rays)
    step()
    assert len(backend.rays) == rays + 1               # the free point still raycasts
    backend.targets[1.0] = ("/other", 0.01)
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
    component, backend, step = _gripper()
    backend.targets = {0.0: ("/a", 0.01), 1.0: ("/b", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    step()
    component.set_status(GripperStatus.OPEN)
    assert component.status == GripperStatus.OPEN and component.gripped_objects() == []
    step()
    assert backend.attached == {} and component.events.releases == 1


def test_reach_is_max_grip_distance_from_the_joint_origin_and_self_hits_step_1mm():
    component, backend, step = _gripper(count=1)
    point = component.points[0]
    point.clearance_offset = 0.004
    calls = []

    def raycast(origin, direction, length):
        calls.append((round(origin[2], 6), round(length, 6)))
        return "/body" if len(calls) < 3 else "/box"

    backend.raycast = raycast
    component.set_status(GripperStatus.CLOSED)
    # rays start 4, 5 and 6 mm down the forward axis (-Z); each ends 20 mm from the joint origin
    assert calls == [(-0.004, 0.016), (-0.005, 0.015), (-0.006, 0.014)]
    assert point.clearance_offset == pytest.approx(0.006)
    assert component.status == GripperStatus.CLOSED


def test_settling_delay_then_signed_coaxial_and_shear_limits():
    component, backend, step = _gripper(count=1, coaxial_force_limit=1.0, shear_force_limit=2.0)
    backend.targets = {0.0: ("/box", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    step()
    backend.forces["/box"] = (0.0, 0.0, -5.0)           # the object pulls the gripper along the forward axis
    for _ in range(4):                                  # settling: 10 checks (synchronous close + steps)
        step()
    assert component.status == GripperStatus.CLOSED
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.OPEN and component.events.force_breaks == 1


def test_pressing_in_never_breaks_coaxially_and_limits_at_or_below_zero_are_off():
    component, backend, step = _gripper(count=1, coaxial_force_limit=1.0, shear_force_limit=0.0)
    backend.targets = {0.0: ("/box", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    backend.forces["/box"] = (50.0, 0.0, 5.0)          # pushed in (negative coaxial), 50 N across: shear is off
    for _ in range(30):
        step()
    assert component.status == GripperStatus.CLOSED


def test_break_with_retry_armed_goes_back_to_closing_and_regrips():
    component, backend, step = _gripper(count=1, shear_force_limit=1.0, retry_interval=1.0)
    backend.targets = {0.0: ("/box", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    step()
    backend.forces["/box"] = (5.0, 0.0, 0.0)
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.CLOSING
    backend.forces.clear()
    for _ in range(SETTLING_DELAY):
        step()
    assert component.status == GripperStatus.CLOSED and component.gripped_objects() == ["/box"]


def test_partial_break_without_retry_stays_closed_and_never_regrips():
    component, backend, step = _gripper(shear_force_limit=1.0)
    backend.targets = {0.0: ("/a", 0.01), 1.0: ("/b", 0.01)}
    component.set_status(GripperStatus.CLOSED)
    step()
    backend.forces["/a"] = (5.0, 0.0, 0.0)
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
