"""Issue 15: the trace header lists the surface grippers that exist when the run starts (docs/trace.md)."""
import io
import json

from conftest import ROOT

from graphflow.observe.recorder import TraceRecorder
from graphflow.runtime import Simulation


def test_header_lists_the_stage_gripper_before_any_node_touched_it():
    with Simulation.load(ROOT / "graphs" / "ur10_pick_place.json") as simulation:
        stream = io.StringIO()
        TraceRecorder(simulation, stream, graph="graphs/ur10_pick_place.json")
        header = json.loads(stream.getvalue().splitlines()[0])
    # the pick-and-place controller only closes this gripper in phase 4; it is on the stage from tick 0
    assert header["grippers"] == ["/World/ur10/ee_link/SurfaceGripper"]


def test_header_of_a_graph_without_a_stage_lists_no_gripper():
    with Simulation.load(ROOT / "graphs" / "counter_branch_print.json") as simulation:
        stream = io.StringIO()
        TraceRecorder(simulation, stream)
        assert json.loads(stream.getvalue().splitlines()[0])["grippers"] == []
