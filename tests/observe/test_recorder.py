"""A run report's recording keeps each tick's output values as they were on that tick, and its records are a
streamed trace's, whatever the nodes do with their objects afterwards."""
import io
import json

import numpy
from pxr import Gf, Sdf

from graphflow.observe.recorder import TraceRecorder
from graphflow.testing import GraphHarness

GRAPH = {"nodes": [{"name": "tick", "type": "omni.graph.action.OnTick", "inputs": {"onlyPlayback": False}},
                   {"name": "held", "type": "omni.graph.nodes.ConstantDouble"}]}   # never computes: the test sets it


def _record(deferred: bool) -> list[dict]:
    """Ticks 1-6 with ``held.value`` set as a node might: a list, the same list grown in place, numpy scalars
    inside a tuple, a tuple holding a list that is then emptied in place, a list holding a function, USD
    values pickle cannot copy."""
    graph = GraphHarness(GRAPH)
    records: list = []
    stream = None if deferred else io.StringIO()
    recorder = TraceRecorder(graph.simulation, stream, records=records, deferred=deferred)
    outputs = graph.instance.database("held").outputs.__dict__
    grown = [1.0, 2.0]
    outputs["value"] = grown
    graph.run(ticks=1)
    grown.append(3.0)
    graph.run(ticks=1)
    inner = [4.0]
    outputs["value"] = (numpy.float64(0.5), numpy.int64(7))
    graph.run(ticks=1)
    outputs["value"] = ("path", inner)
    graph.run(ticks=1)
    inner.clear()
    outputs["value"] = [1.0, lambda: None]   # pickle cannot copy a lambda: the value is its JSON form, read now
    graph.run(ticks=1)
    outputs["value"] = (Sdf.Path("/World/Cube"), Gf.Quatd(1, 0, 0, 0))   # USD's types raise RuntimeError in pickle
    graph.run(ticks=1)
    recorder.flush()
    if stream is not None:
        assert [json.loads(line) for line in stream.getvalue().splitlines()] == records
    return records


def test_each_tick_keeps_the_value_it_had_then():
    ticks = _record(deferred=True)[1:]
    assert [record["outputs"]["held.value"] for record in ticks] == [
        [1.0, 2.0], [1.0, 2.0, 3.0], [0.5, 7], ["path", [4.0]], [1.0, "<function>"], ["<Path>", "<Quatd>"]]


def test_a_report_recording_gives_a_streamed_traces_records():
    assert _record(deferred=True) == _record(deferred=False)
