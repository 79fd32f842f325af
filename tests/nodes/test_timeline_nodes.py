"""Kit's main-timeline nodes on a run whose clock is the simulation's."""
import pytest

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.testing import GraphHarness

DT = 0.01
STAGE = """#usda 1.0
(
    metersPerUnit = 1
    upAxis = "Z"
    timeCodesPerSecond = 30
    startTimeCode = 15
    endTimeCode = 300
)
def Xform "World"
{
}
"""


@pytest.fixture()
def world(tmp_path):
    path = tmp_path / "timeline.usda"
    path.write_text(STAGE)
    with create_world(path, time_step=DT) as built:
        yield built


def _graph(*nodes, connections=()):
    return {"nodes": [{"name": "tick", "type": "omni.graph.action.OnPlaybackTick"},
                      {"name": "get", "type": "omni.graph.nodes.GetTimeline"}, *nodes],
            "connections": [{"src": src, "dst": dst} for src, dst in connections]}


def _read(harness):
    harness.instance.compute_node("get")
    return {name: harness.output("get", name) for name in (
        "time", "frame", "startTime", "startFrame", "endTime", "endFrame", "framesPerSecond", "isLooping",
        "isPlaying")}


def test_get_timeline_reads_the_stage_range_and_the_simulated_time(world):
    harness = GraphHarness(_graph(), world=world)
    harness.run(50)
    values = _read(harness)
    assert values["time"] == pytest.approx(0.5, abs=1e-12)
    assert values["frame"] == pytest.approx(15.0, abs=1e-9)            # 0.5 s at 30 frames per second
    assert (values["startTime"], values["startFrame"]) == pytest.approx((0.5, 15.0))
    assert (values["endTime"], values["endFrame"]) == pytest.approx((10.0, 300.0))
    assert values["framesPerSecond"] == 30.0
    assert values["isPlaying"] is True and values["isLooping"] is False


def test_without_a_stage_the_timeline_has_usds_fallbacks():
    harness = GraphHarness(_graph())
    harness.run(3)
    values = _read(harness)
    assert values["framesPerSecond"] == 24.0 and values["endTime"] == 0.0
    assert values["frame"] == pytest.approx(24.0 * values["time"])


def test_loop_and_set_timeline_are_recorded_and_a_reset_restores_the_stage(world):
    graph = _graph(
        {"name": "once", "type": "omni.graph.action.Once"},
        {"name": "loop", "type": "omni.graph.nodes.LoopTimeline", "inputs": {"loop": True}},
        {"name": "end", "type": "omni.graph.nodes.SetTimeline", "inputs": {"propName": "EndTime", "propValue": 4.0}},
        {"name": "fps", "type": "omni.graph.nodes.SetTimeline",
         "inputs": {"propName": "FramesPerSecond", "propValue": 60.0}},
        {"name": "start", "type": "omni.graph.nodes.SetTimeline",
         "inputs": {"propName": "StartFrame", "propValue": 6.0}},
        connections=(("tick.outputs:tick", "once.inputs:execIn"), ("once.outputs:once", "loop.inputs:execIn"),
                     ("loop.outputs:execOut", "end.inputs:execIn"), ("end.outputs:execOut", "fps.inputs:execIn"),
                     ("fps.outputs:execOut", "start.inputs:execIn")))
    harness = GraphHarness(graph, world=world)
    harness.run(2)
    values = _read(harness)
    assert values["isLooping"] is True
    assert (values["endTime"], values["endFrame"]) == pytest.approx((4.0, 240.0))     # seconds kept, 60 fps
    assert (values["startTime"], values["startFrame"]) == pytest.approx((0.1, 6.0))   # frame 6 at 60 fps
    assert values["frame"] == pytest.approx(60.0 * values["time"])
    harness.reset()
    values = _read(harness)
    assert values["isLooping"] is False and values["framesPerSecond"] == 30.0 and values["endTime"] == 10.0


def _stop_after(ticks):
    return _graph(
        {"name": "count", "type": "omni.graph.action.Counter"},
        {"name": "enough", "type": "omni.graph.nodes.Compare", "inputs": {"b": ticks, "operation": ">="}},
        {"name": "branch", "type": "omni.graph.action.Branch"},
        {"name": "stop", "type": "omni.graph.nodes.StopTimeline"},
        {"name": "start", "type": "omni.graph.nodes.StartTimeline"},
        connections=(("tick.outputs:tick", "count.inputs:execIn"), ("count.outputs:execOut", "branch.inputs:execIn"),
                     ("count.outputs:count", "enough.inputs:a"), ("enough.outputs:result", "branch.inputs:condition"),
                     ("branch.outputs:execTrue", "stop.inputs:execIn"), ("tick.outputs:tick", "start.inputs:execIn")))


def test_stop_timeline_ends_the_run_after_its_tick(world):
    harness = GraphHarness(_stop_after(12), world=world)
    result = harness.run(100)
    assert result.stopped_by_graph and result.ticks == 12
    assert world.time == pytest.approx(12 * DT)
    assert _read(harness)["isPlaying"] is False


def test_a_seek_to_now_is_allowed_and_clamped_to_the_range(world):
    """Time 0 lies before the play range (0.5 s): clamped to 0.5 s, asked when the run is at 0.5 s."""
    graph = _graph(
        {"name": "due", "type": "omni.graph.nodes.Compare", "inputs": {"b": 0.5 - DT / 4, "operation": ">="}},
        {"name": "branch", "type": "omni.graph.action.Branch"},
        {"name": "once", "type": "omni.graph.action.Once"},
        {"name": "seek", "type": "omni.graph.nodes.SetTimeline", "inputs": {"propName": "Time", "propValue": 0.0}},
        {"name": "sought", "type": "omni.graph.action.Counter"},
        connections=(("get.outputs:time", "due.inputs:a"), ("due.outputs:result", "branch.inputs:condition"),
                     ("tick.outputs:tick", "branch.inputs:execIn"), ("branch.outputs:execTrue", "once.inputs:execIn"),
                     ("once.outputs:once", "seek.inputs:execIn"), ("seek.outputs:execOut", "sought.inputs:execIn")))
    harness = GraphHarness(graph, world=world)
    harness.run(80)
    assert harness.output("sought", "count") == 1
    assert harness.output("seek", "clamped") is True


def test_seeking_back_fails_the_run_with_one_line(world):
    graph = _graph(
        {"name": "wait", "type": "omni.graph.action.Delay", "inputs": {"duration": 0.6}},
        {"name": "once", "type": "omni.graph.action.Once"},
        {"name": "seek", "type": "omni.graph.nodes.SetTimeline", "inputs": {"propName": "Frame", "propValue": 15.0}},
        connections=(("tick.outputs:tick", "once.inputs:execIn"), ("once.outputs:once", "wait.inputs:execIn"),
                     ("wait.outputs:finished", "seek.inputs:execIn")))
    harness = GraphHarness(graph, world=world)
    with pytest.raises(GraphRuntimeError) as raised:
        harness.run(100)
    message = str(raised.value)
    assert message.startswith("node 'seek': cannot seek the timeline to 0.5 s") and "\n" not in message
    assert world.time == pytest.approx(0.61, abs=DT)
