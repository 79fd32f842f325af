"""Why a close failed or a grip ended: the reasons the status machine records where its status changes."""
from graphflow.gripper.component import GripperStatus

from .test_status_machine import _gripper, _place


def _place_box(world, gap):
    _place(world, "/box", [0.0], gap=gap)
    return world.boxes["/box"]


def test_failed_close_names_each_empty_ray_its_reach_and_the_nearest_surface_beyond():
    component, world, step = _gripper(count=2)
    _place(world, "/box", [0.0], gap=0.035)               # 35 mm below point 0; nothing under point 1
    component.set_status(GripperStatus.CLOSED)
    assert component.reason == ""                          # still Closing: nothing to explain yet
    step()
    assert component.status == GripperStatus.OPEN
    assert component.reason.startswith("close failed; ")
    assert "/j0: no surface within 0.0200 m (nearest hit /box at 0.035" in component.reason   # to 0.1 mm
    assert "/j1: no surface within 0.0200 m (nothing within 1 m)" in component.reason


def test_retry_window_elapsed_is_part_of_the_reason_and_a_new_close_clears_it():
    component, world, step = _gripper(count=1, retry_interval=0.1)
    component.set_status(GripperStatus.CLOSED)
    for _ in range(8):                                      # 0.1 s at 60 Hz, then one more step gives up
        step()
    assert component.status == GripperStatus.OPEN
    assert component.reason.startswith("close failed: retry interval 0.1 s elapsed; /j0: no surface within")
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    assert component.status == GripperStatus.CLOSED and component.reason == ""


def test_the_nearest_hit_is_measured_where_the_close_was_commanded_not_where_the_retry_gave_up():
    component, world, step = _gripper(count=1, retry_interval=0.05)
    box = _place_box(world, gap=0.03)
    component.set_status(GripperStatus.CLOSED)
    box.center = (box.center[0], box.center[1], box.center[2] - 0.27)   # the object moves away while the close retries
    for _ in range(5):
        step()
    assert component.status == GripperStatus.OPEN
    assert "nearest hit /box at 0.030" in component.reason


def test_a_force_break_says_which_limit_with_the_measured_force():
    component, world, step = _gripper(count=1, coaxial_force_limit=1.0, shear_force_limit=2.0)
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    for _ in range(12):                                     # past the settling delay
        step()
    world.attachments.forces["/box"] = (3.0, 0.0, 0.0)                # across the forward axis: shear
    step()
    step()
    assert component.status == GripperStatus.OPEN
    assert component.reason == "grip on /box broken by shear force 3.0 N > limit 2 N at /j0"


def test_open_releases_with_the_objects_named_and_keeps_a_break_reason():
    component, world, step = _gripper(count=1, coaxial_force_limit=1.0)
    _place(world, "/box", [0.0])
    component.set_status(GripperStatus.CLOSED)
    step()
    component.set_status(GripperStatus.OPEN)
    assert component.reason == "released /box by Open"
    component.set_status(GripperStatus.CLOSED)            # too soon: the point settles after its last grip
    step()
    assert component.reason == "close failed; /j0: still settling after its last grip (10 physics steps)"
    for _ in range(10):
        step()
    component.set_status(GripperStatus.CLOSED)
    for _ in range(12):
        step()
    world.attachments.forces["/box"] = (0.0, 0.0, -5.0)               # pulls along the forward axis: coaxial
    step()
    component.set_status(GripperStatus.OPEN)                # the legacy update opens after a break
    assert component.reason == "grip on /box broken by coaxial force 5.0 N > limit 1 N at /j0"


def test_stop_forgets_the_reason():
    component, world, step = _gripper(count=1)
    component.set_status(GripperStatus.CLOSED)
    step()
    assert component.reason
    component.stop()
    assert component.reason == ""
