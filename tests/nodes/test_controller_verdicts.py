"""success / failed / reason of the pick-and-place and stacking controllers, on the fake UR10 world."""
from graphflow.testing import ExecState, NodeHarness

from .fakes import FakeUR10World

ROBOT, GRIPPER, CUBE = "/World/ur10", "/World/ur10/ee_link/SurfaceGripper", "/World/Cube"
PICK, PLACE = (0.3, 0.3, 0.02575), (0.7, 0.7, 0.02575)
UPRIGHT = (0.0, 0.0, 0.0, 1.0)
CARRY_STARTS, DONE_TICK = 612, 1125          # 0-based: first tick of move_to_place; the 1126th tick, when phase 9 ends


def _run(cube_at, holds=True, drop_at=None, **inputs):
    world = FakeUR10World(poses={CUBE: (cube_at, UPRIGHT)})
    manager = world.surface_grippers
    if holds:
        manager.holds[GRIPPER] = CUBE
    node = NodeHarness("graphflow.PickPlaceController", world=world, inputs={
        "robotPrim": ROBOT, "gripperPrim": GRIPPER, "pickingPosition": PICK, "placingPosition": PLACE, **inputs})
    results = [node.tick("execIn")]
    for tick in range(1, DONE_TICK + 2):
        if tick == drop_at:
            manager.gripped[GRIPPER] = []
            manager.reason = "grip on /World/Cube broken by shear force 40.0 N > limit 30 N at /j0"
        results.append(node.tick())
    fired = [(i, name) for i, r in enumerate(results) for name in ("success", "failed")
             if r.exec_states.get(name) == ExecState.ENABLED]
    return fired, results[-1].outputs["reason"]


def test_placed_within_tolerance_fires_success_once_with_the_distance():
    fired, reason = _run((0.7, 0.703, 0.02575))
    assert fired == [(DONE_TICK, "success")]
    assert reason == "placed /World/Cube 3.0 mm from the target"


def test_placed_too_far_fails_with_the_distance_and_tolerance():
    fired, reason = _run((0.7, 0.73, 0.02575), placeTolerance=0.01)
    assert fired == [(DONE_TICK, "failed")]
    assert reason == "placed /World/Cube 30.0 mm from the target (tolerance 10.0 mm)"


def test_a_gripper_that_never_closed_fails_when_the_carry_starts():
    fired, reason = _run(PLACE, holds=False)
    assert fired == [(CARRY_STARTS, "failed")]
    assert reason == "the gripper never closed on an object: status Closed"


def test_an_object_dropped_while_carried_fails_with_the_grippers_reason():
    fired, reason = _run(PLACE, drop_at=700)
    assert fired == [(700, "failed")]
    assert reason.startswith("/World/Cube dropped during move_to_place at t = ")
    assert reason.endswith(": grip on /World/Cube broken by shear force 40.0 N > limit 30 N at /j0")
