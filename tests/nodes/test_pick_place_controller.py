"""graphflow.PickPlaceController without physics: a fake UR10 world whose joints reach their targets."""
import math

import numpy as np
import pytest

from graphflow.document import GraphError
from graphflow.executor import GraphRuntimeError
from graphflow.kinematics import ur10_chain
from graphflow.testing import ExecState, GraphHarness, NodeHarness

from .fakes import FakeUR10World

ROBOT, GRIPPER = "/World/ur10", "/World/ur10/ee_link/SurfaceGripper"
PICK, PLACE, OFFSET, H1 = (0.3, 0.3, 0.02575), (0.7, 0.7, 0.02575), (0.0, 0.0, 0.02), 0.3
UR10_PHASE_TICKS = [100, 286, 100, 1, 125, 200, 200, 1, 100, 13]   # reference §5.2, 1126 ticks
CHAIN = ur10_chain()


def test_the_default_orientation_is_the_solvers_suction_down():
    from graphflow.kinematics import SUCTION_DOWN
    from graphflow_nodes._pick_place import SUCTION_DOWN as written_out

    assert written_out == SUCTION_DOWN


def _controller(world=None, **inputs):
    world = world or FakeUR10World()
    values = {"robotPrim": ROBOT, "gripperPrim": GRIPPER, "pickingPosition": PICK, "placingPosition": PLACE,
              **inputs}
    return NodeHarness("graphflow.PickPlaceController", inputs=values, world=world), world


def _run(node, ticks):
    """Start on the first tick, then let it advance on its own (as the executor's latent re-compute)."""
    results = [node.tick("execIn")]
    results += [node.tick() for _ in range(ticks - 1)]
    return results


def _tip(result, base=(0.0, 0.0, 0.0)):
    return CHAIN.forward(result.outputs["jointTargets"])[:3, 3] + np.array(base)


def _mix(t):
    return 0.5 * (1 - math.cos(math.pi * t))


def test_ur10_phase_durations_and_names():
    node, _ = _controller()
    results = _run(node, 1128)
    events = [r.outputs["event"] for r in results]
    durations = [events.count(event) for event in range(10)]
    assert durations == UR10_PHASE_TICKS
    assert events[1126] == 10 and results[1126].outputs["eventName"] == "done"
    assert [results[sum(UR10_PHASE_TICKS[:i])].outputs["eventName"] for i in range(10)] == [
        "move_above_pick", "descend", "settle", "gripper_close", "lift", "move_to_place", "descend_to_place",
        "gripper_open", "lift_after_place", "hold_above_place"]


def test_latent_start_phase_pulses_and_a_single_finish():
    node, _ = _controller()
    results = _run(node, 1130)
    assert results[0].exec_states["finished"] == ExecState.LATENT_PUSH
    finishes = [i for i, r in enumerate(results) if r.exec_states["finished"] == ExecState.LATENT_FINISH]
    assert finishes == [1126]
    assert not node.is_latent and results[-1].outputs["isDone"]
    started = [i for i, r in enumerate(results) if "phaseStarted" in r.fired]
    assert started == [0, 100, 386, 486, 487, 612, 812, 1012, 1013, 1113, 1126]
    assert all("execOut" in r.fired for r in results[:1127]) and not results[1127].fired


def test_gripper_closes_in_phase_3_and_opens_in_phase_7():
    node, world = _controller()
    _run(node, 1127)
    assert world.surface_grippers.commands == [(487, "close", GRIPPER), (1013, "open", GRIPPER)]


def test_tip_targets_follow_isaacs_heights_and_xy_blend():
    node, _ = _controller(endEffectorOffset=OFFSET)
    results = _run(node, 1126)
    h0, place_z = PICK[2], PLACE[2]
    expected = {
        0: (PICK[0], PICK[1], H1),                                   # phase 0
        100: (PICK[0], PICK[1], H1),                                 # phase 1, t = 0
        100 + 143: (PICK[0], PICK[1], (1 - _mix(143 * 0.0035)) * H1 + _mix(143 * 0.0035) * h0),
        385: (PICK[0], PICK[1], (1 - _mix(285 * 0.0035)) * H1 + _mix(285 * 0.0035) * h0),
        487 + 62: (PICK[0], PICK[1], (1 - _mix(62 * 0.008)) * h0 + _mix(62 * 0.008) * H1),   # lift
        612 + 100: (PICK[0] + _mix(0.5) * 0.4, PICK[1] + _mix(0.5) * 0.4, H1),               # xy blend
        812 + 199: (PLACE[0], PLACE[1], (1 - _mix(199 * 0.005)) * H1 + _mix(199 * 0.005) * place_z),
        1013 + 50: (PLACE[0], PLACE[1], (1 - _mix(0.5)) * place_z + _mix(0.5) * H1),
        1125: (PLACE[0], PLACE[1], H1),                              # phase 9 holds above the place
    }
    for tick, (x, y, z) in expected.items():
        assert _tip(results[tick]) == pytest.approx((x, y, z + OFFSET[2]), abs=1e-4), tick


def test_settle_and_gripper_phases_send_no_arm_command():
    node, world = _controller()
    results = _run(node, 500)
    held = results[385].outputs["jointTargets"]
    assert all(r.outputs["jointTargets"] == held for r in results[386:487])
    assert len(world.calls) == 500 - 100 - 1


def test_pick_position_is_latched_after_phase_1():
    node, _ = _controller()
    _run(node, 400)
    node.set_inputs(pickingPosition=(0.5, -0.3, 0.1))
    results = [node.tick() for _ in range(150)]
    assert _tip(results[-1])[:2] == pytest.approx(PICK[:2], abs=1e-4)


def test_picking_position_changes_are_followed_during_phases_0_and_1():
    node, _ = _controller()
    _run(node, 50)
    node.set_inputs(pickingPosition=(0.35, 0.25, 0.02575))
    assert _tip(node.tick())[:2] == pytest.approx((0.35, 0.25), abs=1e-4)


def test_pause_holds_and_resume_continues():
    node, world = _controller()
    _run(node, 50)
    node.tick("pause")
    paused = [node.tick() for _ in range(30)]
    assert {r.outputs["event"] for r in paused} == {0} and not any(r.fired for r in paused)
    calls = len(world.calls)
    node.tick("resume")
    assert len(world.calls) == calls + 1
    results = [node.tick() for _ in range(50)]    # advancing ticks 52..101; phase 0 takes 100
    assert [r.outputs["event"] for r in results[-2:]] == [0, 1]


def test_reset_restarts_and_a_finished_controller_waits_for_exec_in():
    node, world = _controller(eventsDT=[0.5] * 10)
    _run(node, 21)
    assert node.outputs.isDone
    assert node.tick().outputs["isDone"]
    result = node.tick("reset")
    assert result.outputs["event"] == 0 and not result.outputs["isDone"] and not result.fired
    assert node.tick("execIn").exec_states["finished"] == ExecState.LATENT_PUSH


def test_robot_base_offset_is_respected():
    world = FakeUR10World(base_position=(1.0, -0.5, 0.2))
    node, _ = _controller(world, pickingPosition=(1.3, -0.2, 0.3), placingPosition=(1.7, 0.2, 0.3))
    result = _run(node, 1)[0]
    assert _tip(result, base=(1.0, -0.5, 0.2)) == pytest.approx((1.3, -0.2, 0.32 + H1 - 0.3 + 0.0), abs=1e-4)


def test_exec_in_every_tick_does_not_double_the_speed():
    world = FakeUR10World()
    graph = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "pick_place", "type": "graphflow.PickPlaceController",
             "inputs": {"robotPrim": ROBOT, "gripperPrim": GRIPPER, "pickingPosition": list(PICK),
                        "placingPosition": list(PLACE)}},
        ],
        "connections": [{"src": "tick.outputs:tick", "dst": "pick_place.inputs:execIn"}],
    }, world=world)
    graph.run(ticks=100)
    assert graph.output("pick_place", "event") == 0
    graph.run(ticks=1)
    assert graph.output("pick_place", "event") == 1


def test_unreachable_target_is_a_run_time_error():
    node, _ = _controller(pickingPosition=(3.0, 0.0, 0.1))
    with pytest.raises(GraphRuntimeError, match="cannot reach tool target"):
        node.tick("execIn")


def test_missing_gripper_is_a_run_time_error():
    node, _ = _controller(gripperPrim="/World/nothing", eventsDT=[1.0] * 10)
    with pytest.raises(GraphRuntimeError, match="no surface gripper at /World/nothing"):
        _run(node, 4)


@pytest.mark.parametrize("values, fragment", [
    ([0.01] * 9, "exactly 10 phase increments, got 9"),
    ([0.01] * 9 + [0.0], "must be positive"),
])
def test_events_dt_is_checked_at_load_time(values, fragment):
    with pytest.raises(GraphError, match=fragment) as error:
        NodeHarness("graphflow.PickPlaceController", inputs={"eventsDT": values})
    assert "inputs:eventsDT" in str(error.value)


def test_legacy_id_loads():
    assert NodeHarness("omni.isaac.examples_nodes.IsaacPickPlaceController").database.spec.id == \
        "graphflow.PickPlaceController"


def test_a_controller_computes_once_a_tick_and_a_finished_one_pulls_nothing():
    """The latent continuation after the tick's advance and the pulses after the routine is done change no
    output, so the executor skips them (the controllers' ``idle``): no compute, no pull of its inputs."""
    world = FakeUR10World()
    graph = GraphHarness({
        "nodes": [
            {"name": "tick", "type": "omni.graph.action.OnTick"},
            {"name": "pick_at", "type": "omni.graph.nodes.MakeVector3",
             "inputs": {"x": PICK[0], "y": PICK[1], "z": PICK[2]}},
            {"name": "pick_place", "type": "graphflow.PickPlaceController",
             "inputs": {"robotPrim": ROBOT, "gripperPrim": GRIPPER, "placingPosition": list(PLACE),
                        "eventsDT": [0.5] * 10}},
        ],
        "connections": [{"src": "tick.outputs:tick", "dst": "pick_place.inputs:execIn"},
                        {"src": "pick_at.outputs:tuple", "dst": "pick_place.inputs:pickingPosition"}],
    }, world=world)
    graph.run(ticks=5)
    assert graph.compute_counts["pick_place"] == 5 and graph.output("pick_place", "event") == 2
    graph.run(ticks=30)
    assert graph.output("pick_place", "isDone") and graph.output("pick_place", "eventName") == "done"
    finished = graph.compute_counts
    graph.run(ticks=100)
    assert graph.compute_counts == {**finished, "tick": finished["tick"] + 100}
    assert graph.output("pick_place", "event") == 10
