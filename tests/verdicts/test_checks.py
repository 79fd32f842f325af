"""The checks section: each kind of check measured on a scripted world, one line per failed check."""
import math

import pytest

from graphflow.document import GraphError, parse_document
from graphflow.gripper.manager import SurfaceGripperManager
from graphflow.runtime import Simulation
from graphflow.verdicts.checks import CheckEvaluator
from graphflow.world import ClockWorld

STEP = 0.1


class ScriptedWorld(ClockWorld):
    """A clock whose prims move as scripted: ``motion[path](t) -> ((x, y, z), (qx, qy, qz, qw))``."""

    def __init__(self, motion):
        super().__init__(STEP)
        self.motion = motion

    def prim_pose(self, path):
        return self.motion[path](self.time)


class ScriptedGripper:
    """What the checks read of a surface gripper: status, gripped objects and the component's reason."""

    def __init__(self, timeline):
        self.timeline = timeline            # [(from time, status, gripped, reason)]
        self.components = {"/G": self}

    def _now(self, time):
        return [entry for entry in self.timeline if entry[0] <= time + 1e-9][-1]

    def get_gripper_status(self, path):
        return self._now(self.world.time)[1]

    def get_gripped_objects(self, path):
        return list(self._now(self.world.time)[2])

    @property
    def reason(self):
        return self._now(self.world.time)[3]

    def after_step(self, dt):
        """Scripted: nothing to step."""

    def reset(self):
        """Scripted: nothing to reset."""


def _document(checks, stop_at_tick=None, duration=2.0):
    nodes = [{"name": "tick", "type": "omni.graph.action.OnTick"},
             {"name": "counter", "type": "omni.graph.action.Counter"}]
    connections = [{"src": "tick.outputs:tick", "dst": "counter.inputs:execIn"}]
    if stop_at_tick is not None:
        nodes += [{"name": "enough", "type": "omni.graph.nodes.Compare", "inputs": {"b": stop_at_tick, "operation": ">="}},
                  {"name": "branch", "type": "omni.graph.action.Branch"},
                  {"name": "stop", "type": "graphflow.StopRun"}]
        connections += [{"src": "counter.outputs:count", "dst": "enough.inputs:a"},
                        {"src": "counter.outputs:execOut", "dst": "branch.inputs:execIn"},
                        {"src": "enough.outputs:result", "dst": "branch.inputs:condition"},
                        {"src": "branch.outputs:execTrue", "dst": "stop.inputs:execIn"}]
    return parse_document({"format": "graphflow", "formatVersion": [1, 0], "settings": {"duration": duration},
                           "nodes": nodes, "connections": connections, "checks": checks}, "scenario.json")


def _run(checks, motion=None, gripper=None, **options):
    document = _document(checks, **options)
    world = ScriptedWorld(motion or {})
    if gripper is not None:
        gripper.world = world
        world.services.add(gripper, SurfaceGripperManager)
    evaluator = CheckEvaluator(document)
    simulation = Simulation(document, world=world, listeners=[evaluator])
    result = simulation.run(seconds=document.settings["duration"])
    return [str(failure) for failure in evaluator.finish(simulation, result)]


def _sliding(t):
    """A cube sliding along +X at 0.1 m/s from the origin, upright."""
    return (0.1 * t, 0.0, 0.025), (0.0, 0.0, 0.0, 1.0)


def test_position_at_the_end_within_tolerance_passes_and_a_miss_prints_measured_and_expected():
    assert _run([{"check": "position", "prim": "/Cube", "position": [0.2, 0.0, 0.025], "tolerance": 0.001}],
                {"/Cube": _sliding}) == []
    assert _run([{"check": "position", "prim": "/Cube", "position": [0.25, 0.0, 0.025], "tolerance": 0.01}],
                {"/Cube": _sliding}) == [
        "scenario.json: check 1 'position of /Cube at the end': measured (0.2000, 0.0000, 0.0250), 50.0 mm from "
        "(0.2500, 0.0000, 0.0250); expected within 10.0 mm of (0.2500, 0.0000, 0.0250) at the end"]


def test_position_at_a_time_is_measured_once_on_the_first_tick_at_that_time():
    check = {"check": "position", "prim": "/Cube", "position": [0.05, 0.0, 0.025], "tolerance": 0.001, "at": 0.5}
    assert _run([check], {"/Cube": _sliding}) == []     # at the end it is 150 mm away: not measured then
    later = dict(check, at=5.0, name="slid half a metre")   # the graph stops itself before 5 s
    assert _run([later], {"/Cube": _sliding}, stop_at_tick=20, duration=10.0) == [
        "scenario.json: check 1 'slid half a metre': measured the run ended at t = 2.000 s; "
        "expected within 1.0 mm of (0.0500, 0.0000, 0.0250) at t = 5 s"]


def test_axes_compare_only_the_named_coordinates():
    dropped = {"/Cube": lambda t: ((0.2, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))}
    check = {"check": "position", "prim": "/Cube", "position": [0.2, 0.0, 0.05], "tolerance": 0.01}
    assert len(_run([check], dropped)) == 1
    assert _run([dict(check, axes="xy")], dropped) == []


def test_upright_measures_the_tilt_of_the_prims_axis_from_vertical():
    tilt = math.radians(10.0)
    tipped = {"/Cube": lambda t: ((0.0, 0.0, 0.0), (math.sin(tilt / 2), 0.0, 0.0, math.cos(tilt / 2)))}
    assert _run([{"check": "upright", "prim": "/Cube", "within": 11.0}], tipped) == []
    (line,) = _run([{"check": "upright", "prim": "/Cube", "within": 5.0}], tipped)
    assert line.endswith("measured its Z axis 10.0 deg from vertical; expected its Z axis within 5 deg of vertical at the end")


def test_gripper_status_at_a_time_and_held_interval_report_the_grippers_reason():
    gripper = ScriptedGripper([(0.0, "Open", (), ""), (0.5, "Closed", ("/Cube",), ""),
                               (1.2, "Open", (), "grip on /Cube broken by shear force 30.0 N > limit 20 N at /j0")])
    lines = _run([{"check": "gripperStatus", "gripper": "/G", "status": "Closed", "at": 0.6},
                  {"check": "held", "gripper": "/G", "object": "/Cube", "from": 0.5, "to": 1.5},
                  {"check": "gripperStatus", "gripper": "/G", "status": "Closed"}], gripper=gripper)
    assert lines == [
        "scenario.json: check 2 '/G holds /Cube from 0.5 s to 1.5 s': measured holding nothing at t = 1.200 s "
        "(gripper Open: grip on /Cube broken by shear force 30.0 N > limit 20 N at /j0); expected /Cube held throughout",
        "scenario.json: check 3 'gripper /G Closed at the end': measured status Open (grip on /Cube broken by shear "
        "force 30.0 N > limit 20 N at /j0); expected status Closed at the end"]


def test_stops_by_needs_the_graph_to_stop_itself_in_time():
    assert _run([{"check": "stopsBy", "time": 1.0}], stop_at_tick=5) == []
    assert _run([{"check": "stopsBy", "time": 1.0}], stop_at_tick=15) == [
        "scenario.json: check 1 'graph stops by itself by 1 s': measured stopped at t = 1.500 s; "
        "expected the graph stops by itself (StopRun) by t = 1 s"]
    assert _run([{"check": "stopsBy", "time": 1.0}])[0].endswith(
        "measured still running when the run ended at t = 2.000 s; expected the graph stops by itself (StopRun) by t = 1 s")


def test_finite_catches_the_first_non_finite_pose_of_a_prim_other_checks_name():
    blown_up = {"/Cube": lambda t: ((math.nan if t > 0.95 else 0.0, 0.0, 0.0), (0.0, 0.0, 0.0, 1.0))}
    lines = _run([{"check": "finite"}, {"check": "upright", "prim": "/Cube", "within": 90.0}], blown_up)
    assert lines[0].startswith("scenario.json: check 1 'nothing non-finite': measured pose of /Cube = ((nan, 0.0, 0.0)")
    assert "at t = 1.000 s; expected every output and pose finite" in lines[0]


def test_the_schema_names_what_is_missing_or_misspelled_in_a_check():
    with pytest.raises(GraphError) as error:
        _document([{"check": "position", "prim": "/Cube", "position": [0, 0, 0]},
                   {"check": "postion", "prim": "/Cube"},
                   {"check": "held", "gripper": "/G", "from": 1.0, "until": 2.0}])
    lines = [str(problem) for problem in error.value.problems]
    assert "scenario.json: checks/0: 'tolerance' is a required property" in lines
    assert any(line.startswith("scenario.json: checks/1/check: 'postion' is not one of") for line in lines)
    assert "scenario.json: checks/2: Additional properties are not allowed ('until' was unexpected)" in lines


def test_checks_survive_save_and_load():
    from graphflow.document import dumps

    document = _document([{"check": "stopsBy", "time": 1.0}])
    again = parse_document(__import__("json").loads(dumps(document)), "scenario.json")
    assert [dict(check) for check in again.checks] == [{"check": "stopsBy", "time": 1.0}]
