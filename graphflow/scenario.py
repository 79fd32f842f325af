"""Scenarios: one checked, headless run of a graph with a verdict (``graphflow test``, the pytest plugin).

A scenario is a graph document with a ``checks`` section; its ``scenario``
section may script the keyboard and gamepad. ``run_scenario`` runs it the way
``graphflow run GRAPH`` does (same seed, same inputs, same limit), so a
scenario's verdict and its re-run command always agree.
"""
from __future__ import annotations


import shlex
from dataclasses import dataclass, field
from pathlib import Path

from .checks import CheckEvaluator
from .document import GraphDocument, load_document
from .executor import GraphRuntimeError
from .seeding import seed_everything


@dataclass
class ScenarioResult:
    """The verdict of one run: passed, the failure lines, how long it ran, what it printed."""

    path: str
    checks: int
    failures: list[str] = field(default_factory=list)
    ticks: int = 0
    time: float = 0.0
    output: list[str] = field(default_factory=list)
    trace: str | None = None
    expect_failure: tuple[str, ...] = ()   # the scenario section's expectFailure texts

    @property
    def run_passed(self) -> bool:
        """Every check held and nothing failed: ``graphflow run`` exits 0."""
        return not self.failures

    @property
    def passed(self) -> bool:
        """The scenario's verdict: the run passed, or it failed as its expectFailure says."""
        if not self.expect_failure:
            return self.run_passed
        return not self.run_passed and not self.missing_failures()

    def missing_failures(self) -> list[str]:
        text = "\n".join(self.failures)
        return [expected for expected in self.expect_failure if expected not in text]

    def verdict_line(self) -> str:
        """``graphflow test``'s line: PASS, XFAIL (failed as expected) or FAIL."""
        if not self.expect_failure:
            return self.summary()
        ran = self.summary().rsplit(" (", 1)[1]
        if self.passed:
            return f"XFAIL {self.path}: failed as expected ({ran}"
        if self.run_passed:
            return f"FAIL {self.path}: expected to fail ({', '.join(map(repr, self.expect_failure))}) but passed ({ran}"
        return f"FAIL {self.path}: failed, but not with {', '.join(map(repr, self.missing_failures()))} ({ran}"

    def summary(self) -> str:
        """One line: PASS or FAIL, the file, what held or failed, ticks and simulated time."""
        ran = f"({self.ticks} tick{'s' if self.ticks != 1 else ''}, {self.time:.3f} s simulated)"
        if self.run_passed and not self.checks:
            return f"done {self.path}: no checks {ran}"
        if self.run_passed:
            return f"PASS {self.path}: {f'{self.checks} checks hold' if self.checks > 1 else '1 check holds'} {ran}"
        return f"FAIL {self.path}: {len(self.failures)} failure{'s' if len(self.failures) != 1 else ''} {ran}"


def scripted_inputs(document: GraphDocument):
    """The keyboard and gamepad sources the document's ``scenario`` section scripts (None where it names none).

    Raises ``KeySpecError`` / ``PadSpecError`` for timelines that cannot be read.
    """
    from .gamepad import scripted_pad
    from .keyboard import scripted_keys

    scenario = document.scenario
    sources = []
    for name, make in (("keys", scripted_keys), ("gamepad", scripted_pad)):
        value = scenario.get(name)
        if value is None:
            sources.append(None)
        elif isinstance(value, str):
            sources.append(make(str(document.base_dir / value)))
        else:
            sources.append(make(None, list(value)))
    return tuple(sources)


def run_seconds(document: GraphDocument, evaluator: CheckEvaluator, ticks: int | None, seconds: float | None):
    """The run's time limit: the one given, else the graph's duration, capped by a stopsBy check."""
    if ticks is not None or seconds is not None:
        return seconds
    seconds = document.settings.get("duration")
    stop_by = evaluator.time_limit()
    if stop_by is not None and (seconds is None or seconds > stop_by):
        seconds = stop_by
    return seconds


def rerun_command(path: str) -> str:
    """The shell command that repeats a scenario's run (add --trace FILE to record it again)."""
    return " ".join(shlex.quote(word) for word in ("graphflow", "run", path))


class _CollectedLog:
    """Run listener keeping the graph's log lines, warnings and errors marked, for a scenario's report."""

    def __init__(self, lines: list[str]):
        self.lines = lines

    def on_log(self, event) -> None:
        if event.level in ("warning", "warn", "error"):
            self.lines.append(f"{event.level.upper()}: {event.node}: {event.message}")
        else:
            self.lines.append(event.message)


def run_scenario(path: str | Path, *, trace: str | Path | None = None, report: str | Path | None = None) -> ScenarioResult:
    """Run the graph at *path* headless with its scenario inputs and evaluate its checks.

    Bad input (a graph that does not load, a missing stage or key file) raises
    ``GraphError`` / ``ValueError`` / ``OSError``; a run-time failure (an Assert,
    a failing node) is a failed result naming the node, tick and time. *report*: an HTML run report
    (graphflow.report) is written there, passed or failed.
    """
    from .keyboard import attach_keyboard
    from .gamepad import attach_gamepad
    from .runtime import Simulation

    path = str(path)
    document = load_document(path)
    seed_everything(int(document.scenario.get("seed", 0)))
    keys, pad = scripted_inputs(document)
    evaluator = CheckEvaluator(document)
    result = ScenarioResult(path, len(evaluator), expect_failure=tuple(document.scenario.get("expectFailure", ())))
    simulation = Simulation(document, listeners=[_CollectedLog(result.output), evaluator])
    closers = []
    try:
        if keys is not None:
            attach_keyboard(simulation.world, keys)
        if pad is not None:
            attach_gamepad(simulation.world, pad)
        stream = None
        if trace is not None:
            stream = open(trace, "w", encoding="utf-8", newline="\n")
            closers.append(stream.close)
            result.trace = str(trace)
        recording = None
        if report is not None:
            from .report.recording import ReportRecording

            recording = ReportRecording(simulation, path, also_to=stream)
        elif stream is not None:
            from .trace import TraceRecorder

            TraceRecorder(simulation, stream, graph=path)

        seconds = run_seconds(document, evaluator, None, None)
        if seconds is None:   # a scenario must end by itself: nothing hangs
            raise ValueError("no run limit: give settings.duration or a stopsBy check")
        try:
            run = simulation.run(seconds=seconds)
        except GraphRuntimeError as error:
            result.failures.append(f"{path}: run-time failure: {error}")
            result.ticks, result.time = simulation.instance.tick_count, simulation.world.time
            if recording is not None:
                recording.write(report, document, evaluator=evaluator, runtime_failure=str(error),
                                seed=int(document.scenario.get("seed", 0)), force=True)
            return result
        result.ticks, result.time = run.ticks, run.time
        result.failures.extend(str(failure) for failure in evaluator.finish(simulation, run))
        if recording is not None:
            recording.write(report, document, evaluator=evaluator, seed=int(document.scenario.get("seed", 0)), force=True)
        return result
    finally:
        for close in closers:
            close()
        simulation.close()

