"""Recording a run for its report: the trace's records kept in memory (and written to ``--trace``), then the report.

``graphflow run --report`` and ``graphflow test --reports`` use this; ``graphflow
report TRACE`` builds the same data from a trace file instead (``from_trace``).
"""
from __future__ import annotations

from graphflow.observe.recorder import TraceRecorder
from graphflow.observe.trace import Trace, to_json_value
from graphflow.report.build import RunInfo, run_data
from graphflow.report.page import write_report
from graphflow.report.timing import ComputeTimer
from graphflow.report.verdict import check_entries


class ReportRecording:
    """Records a simulation's trace in memory for a report; ``write()`` after the run ends."""

    def __init__(self, simulation, graph: str, *, also_to=None, timings: bool = False, randomized=()):
        self._records: list[dict] = []
        self.simulation = simulation
        self._recorder = TraceRecorder(simulation, also_to, graph=graph, records=self._records, randomized=randomized,
                                      deferred=True)
        self.timer = ComputeTimer(simulation) if timings else None

    @property
    def records(self) -> list[dict]:
        """The trace's header and tick records so far (ticks captured during the run are encoded on reading)."""
        self._recorder.flush()
        return self._records

    def trace(self) -> Trace:
        records = self.records
        return Trace(records[0], records[1:])

    def write(self, path, document, *, evaluator=None, runtime_failure: str | None = None, seed: int | None = None,
              overrides=(), randomization: dict | None = None, force: bool = False) -> None:
        """The report of the run so far; *evaluator* None: checks not judged (they did not apply to this run)."""
        trace = self.trace()
        times = [0.0] + [record["t"] for record in trace.ticks]
        checks = None
        if evaluator is not None and (len(evaluator) or runtime_failure is not None):
            checks = tuple(check_entries(evaluator, times, runtime_failure))
        info = RunInfo(seed=seed, overrides=tuple(overrides), randomization=randomization or {}, checks=checks,
                       timings=self.timer.table() if self.timer is not None else None)
        write_report(run_data(trace, document, info), path, force=force)


def runtime_failure(checked) -> str | None:
    """The failure line of a CheckedRun that a failing node ended before its checks were judged, else None."""
    failures = checked.verdict.failures
    return failures[-1] if failures and checked.evaluator.failures is None else None


def drawn_randomization(edits) -> dict:
    """Each drawn edit (graphflow.variants.randomize): a target's value, or a prim's pose jitter (offset, yaw)."""
    drawn = {}
    for edit in edits:
        if hasattr(edit, "target"):
            drawn[edit.target] = to_json_value(edit.value)
        else:
            drawn[f"pose of {edit.prim}"] = {"offset": to_json_value(edit.offset), "yawDegrees": edit.yaw_degrees}
    return drawn


def from_trace(trace: Trace, document, path, *, force: bool = False) -> None:
    """A report from a trace written earlier: everything but the verdict (a trace holds no verdict)."""
    write_report(run_data(trace, document, RunInfo()), path, force=force)
