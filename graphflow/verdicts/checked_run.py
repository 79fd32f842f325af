"""The one checked run: a graph document, its variant, scripted inputs and limits in; a verdict out.

``graphflow run``, ``graphflow test``, the pytest plugin and a sweep episode all run a graph through
``CheckedRun``, so what counts as bad input, what counts as a failure and how checks are judged are
decided here once:

1. ``preflight()`` refuses, before the first tick, everything ``graphflow validate`` can know: the
   stage, prim paths, joints, attributes and check targets the graph names (``BadInput``, exit 2).
2. ``start()`` builds the world through the one factory (``runtime.create_world``, via the variant),
   attaches the scripted keyboard, gamepad and topics, the check evaluator and the caller's listeners.
3. ``run()`` ticks until the limit, the graph's duration, a ``stopsBy`` check or a stop request, and
   returns a ``Verdict``: the failure lines (a failing node, a check that did not hold), ticks, time.
"""
from __future__ import annotations

import contextlib
import re
import shlex
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterable, Sequence

from graphflow.document import GraphDocument, load_document
from graphflow.errors import BadInput, raise_if_interrupted
from graphflow.executor import GraphRuntimeError
from graphflow.seeding import seed_everything
from graphflow.verdicts.checks import CheckEvaluator


@dataclass
class Verdict:
    """The verdict of one run: passed, the failure lines, how long it ran, what it printed."""

    path: str
    checks: int
    failures: list[str] = field(default_factory=list)
    ticks: int = 0
    time: float = 0.0
    output: list[str] = field(default_factory=list)
    trace: str | None = None
    expect_failure: tuple[str, ...] = ()   # the scenario section's expectFailure texts
    expect_pattern: str | None = None      # a table case's expected failure: a regular expression
    stopped_by_graph: bool = False
    run_error: str | None = None   # the failing node's line, when the run stopped on one

    @property
    def run_passed(self) -> bool:
        """Every check held and nothing failed: ``graphflow run`` exits 0."""
        return not self.failures

    @property
    def passed(self) -> bool:
        """The scenario's verdict: the run passed, or it failed as its expectFailure says."""
        if not self.expects_failure:
            return self.run_passed
        return not self.run_passed and not self.missing_failures()

    @property
    def expects_failure(self) -> bool:
        return bool(self.expect_failure) or self.expect_pattern is not None

    def expectations(self) -> list[str]:
        return [*map(repr, self.expect_failure), *([f"/{self.expect_pattern}/"] if self.expect_pattern else [])]

    def missing_failures(self) -> list[str]:
        text = "\n".join(self.failures)
        missing = [repr(expected) for expected in self.expect_failure if expected not in text]
        if self.expect_pattern is not None and re.search(self.expect_pattern, text) is None:
            missing.append(f"/{self.expect_pattern}/")
        return missing

    def verdict_line(self) -> str:
        """``graphflow test``'s line: PASS, XFAIL (failed as expected) or FAIL."""
        if not self.expects_failure:
            return self.summary()
        ran = self.summary().rsplit(" (", 1)[1]
        if self.passed:
            return f"XFAIL {self.path}: failed as expected ({ran}"
        if self.run_passed:
            return f"FAIL {self.path}: expected to fail ({', '.join(self.expectations())}) but passed ({ran}"
        return f"FAIL {self.path}: failed, but not with {', '.join(self.missing_failures())} ({ran}"

    def summary(self) -> str:
        """One line: PASS or FAIL, the file, what held or failed, ticks and simulated time."""
        ran = f"({self.ticks} tick{'s' if self.ticks != 1 else ''}, {self.time:.3f} s simulated)"
        if self.run_passed and not self.checks:
            return f"done {self.path}: no checks {ran}"
        if self.run_passed:
            return f"PASS {self.path}: {f'{self.checks} checks hold' if self.checks > 1 else '1 check holds'} {ran}"
        return f"FAIL {self.path}: {len(self.failures)} failure{'s' if len(self.failures) != 1 else ''} {ran}"


@dataclass(frozen=True)
class ScriptedInputs:
    """The keyboard, gamepad, ROS 2 topic and mouse sources of a run (None: that device is not scripted)."""

    keys: Any = None
    pad: Any = None
    topics: Any = None
    mouse: Any = None

    @classmethod
    def of_document(cls, document: GraphDocument) -> "ScriptedInputs":
        """What the document's ``scenario`` section scripts; ``BadInput`` for a timeline that cannot be read."""
        from graphflow.inputs.gamepad import scripted_pad
        from graphflow.inputs.keyboard import scripted_keys
        from graphflow.inputs.mouse import scripted_mouse

        sources: list[Any] = []
        for name, make in (("keys", scripted_keys), ("gamepad", scripted_pad), ("mouse", scripted_mouse)):
            value = document.scenario.get(name)
            if value is None:
                sources.append(None)
            elif isinstance(value, str):
                sources.append(make(str(document.base_dir / value)))
            else:
                sources.append(make(None, list(value)))
        return cls(keys=sources[0], pad=sources[1], topics=_scenario_topics(document), mouse=sources[2])

    def attach(self, world) -> None:
        """Make the scripted devices services of *world* (they replace a window's or a browser's input)."""
        if self.keys is not None:
            from graphflow.inputs.keyboard import attach_keyboard

            attach_keyboard(world, self.keys)
        if self.pad is not None:
            from graphflow.inputs.gamepad import attach_gamepad

            attach_gamepad(world, self.pad)
        if self.mouse is not None:
            from graphflow.inputs.mouse import attach_mouse

            attach_mouse(world, self.mouse)
        if self.topics is not None:
            from graphflow.ros2.bus import attach_transport

            attach_transport(world, self.topics)


def _scenario_topics(document: GraphDocument):
    """``scenario.topics``: a topics file (relative to the graph) or entries (``TOPIC@TIME=JSON`` or objects)."""
    value = document.scenario.get("topics")
    if value is None:
        return None
    from graphflow.ros2.timeline import ScriptedTopics, TopicSpecError, make_entry, parse_topic_spec, scripted_topics

    if isinstance(value, str):
        return scripted_topics(str(document.base_dir / value))
    entries = []
    for index, entry in enumerate(value):
        where = f"{document.source}: scenario/topics/{index}"
        if isinstance(entry, str):
            entries.append(parse_topic_spec(entry))
            continue
        unknown = sorted(set(entry) - {"topic", "time", "message", "type"})
        missing = sorted({"topic", "time", "message"} - set(entry))
        if unknown or missing:
            raise TopicSpecError(f"{where}: " + (f"missing {', '.join(missing)}" if missing else
                                                 f"unknown {', '.join(unknown)} (an entry has topic, time, message, type)"))
        entries.append(make_entry(entry["topic"], entry["time"], entry["message"], entry.get("type"), where=where))
    return ScriptedTopics(entries)


@dataclass(frozen=True)
class RunLimits:
    """How long a run may go: ticks and/or simulated seconds (None: the graph's duration or stopsBy check)."""

    ticks: int | None = None
    seconds: float | None = None

    @property
    def given(self) -> bool:
        return self.ticks is not None or self.seconds is not None


def run_seconds(document: GraphDocument, evaluator: CheckEvaluator, limits: RunLimits) -> float | None:
    """The run's time limit: the one given, else the graph's duration, capped by a stopsBy check."""
    if limits.given:
        return limits.seconds
    seconds = document.settings.get("duration")
    stop_by = evaluator.time_limit()
    if stop_by is not None and (seconds is None or seconds > stop_by):
        seconds = stop_by
    return seconds


def rerun_command(path: str) -> str:
    """The shell command that repeats a scenario's run (add --trace FILE to record it again)."""
    return shlex.join(("graphflow", "run", path))


class CheckedRun:
    """One run of a graph, checked: preflight, world, inputs, listeners, ticks, verdict.

    *document* is the graph as loaded; *variant* (``graphflow.variants.overrides.Variant``) its node
    overrides and stage edits (None: the document as it is). ``evaluate_checks`` False runs the
    graph without judging its checks (``graphflow run --ticks`` and the like change the run the checks
    were written for). *simulation* reuses a built simulation (a sweep worker's), already reset, whose
    listeners its owner attached once; *evaluator* is then the check evaluator among them.
    """

    def __init__(self, document: GraphDocument, *, source: str | None = None, variant: Any = None,
                 inputs: ScriptedInputs = ScriptedInputs(), limits: RunLimits = RunLimits(),
                 evaluate_checks: bool = True, seed: int | None = None, gui: bool = False,
                 listeners: Iterable[Any] = (), simulation: Any = None, evaluator: CheckEvaluator | None = None,
                 update_golden: bool = False):
        self.source = source or document.source
        self.variant = variant
        self.document = variant.document if variant is not None else document
        self.inputs = inputs
        self.limits = limits
        self.seed = int(document.scenario.get("seed", 0)) if seed is None else seed
        self.gui = gui
        self.evaluator = evaluator or CheckEvaluator(self.document if evaluate_checks else None)
        self.listeners = list(listeners)
        self.simulation = simulation
        self._attached = simulation is not None
        self.update_golden = update_golden   # matchesTrace checks rewrite their golden traces from this run
        self._parsed: Any = None   # the preflight's parsed stage (validate.preflight.ParsedStage)
        self.verdict = Verdict(self.source, len(self.evaluator),
                               expect_failure=tuple(self.document.scenario.get("expectFailure", ())))

    def preflight(self) -> None:
        """Refuse what ``validate`` refuses, before anything is built: ``BadInput`` with every problem.

        The stage it parses is kept for this run's world, so a run reads (and USD warns about) its stage once.
        """
        from graphflow.validate.preflight import document_problems

        problems, self._parsed = document_problems(self.document, quiet=False)
        if problems:
            raise BadInput("\n".join(str(problem) for problem in problems))

    def start(self):
        """Seed, build the world (the one factory), attach inputs and listeners; returns the simulation."""
        from graphflow.runtime import Simulation, create_world_for

        seed_everything(self.seed)
        if self._attached:
            return self.simulation
        if self.variant is not None and self.variant.stage_edits:
            world = self.variant.create_world(gui=self.gui)
        else:
            world = create_world_for(self.document, gui=self.gui, parsed=self._parsed)
        self.simulation = Simulation(self.document, world=world, gui=self.gui)
        raise_if_interrupted()   # a Ctrl-C during the stage load that usd-core's C++ swallowed
        self.inputs.attach(self.simulation.world)
        for listener in (*self.listeners, self.evaluator):
            self.simulation.add_listener(listener)
        self.evaluator.attach(self.simulation, self.source, update_golden=self.update_golden)
        self._attached = True
        return self.simulation

    def time_limit(self) -> float | None:
        return run_seconds(self.document, self.evaluator, self.limits)

    def tick_limit(self) -> int | None:
        return self.simulation.tick_limit(ticks=self.limits.ticks, seconds=self.time_limit())

    def run(self) -> Verdict:
        """Tick to the end and judge; a failing node is a failure line, never an exception."""
        simulation = self.simulation if self._attached else self.start()
        verdict = self.verdict
        try:
            result = simulation.run(ticks=self.limits.ticks, seconds=self.time_limit())
        except GraphRuntimeError as error:
            if isinstance(error.__cause__, BrokenPipeError):
                raise   # the reader of our output has gone: not the graph's failure
            verdict.run_error = str(error)
            verdict.failures.append(f"{self.source}: run-time failure: {error}")
            verdict.ticks, verdict.time = simulation.instance.tick_count, simulation.world.time
            return verdict
        verdict.ticks, verdict.time, verdict.stopped_by_graph = result.ticks, result.time, result.stopped_by_graph
        verdict.failures.extend(str(failure) for failure in self.evaluator.finish(simulation, result))
        return verdict

    def close(self) -> None:
        if self.simulation is not None:
            self.simulation.close()


class CollectedLog:
    """Run listener keeping the graph's log lines, warnings and errors marked, for a scenario's report."""

    def __init__(self, lines: list[str]):
        self.lines = lines

    def on_log(self, event) -> None:
        if event.level in ("warning", "warn", "error"):
            self.lines.append(f"{event.level.upper()}: {event.node}: {event.message}")
        else:
            self.lines.append(event.message)


def run_checked(path: str | Path, *, trace: str | Path | None = None, report: str | Path | None = None,
                listeners: Sequence[Any] = (), update_golden: bool = False) -> Verdict:
    """Run the scenario file at *path* headless with its scripted inputs and judge its checks.

    Bad input (a graph that does not load, a misspelled prim or check target, a missing key file,
    no run limit) raises ``BadInput``; a run-time failure is a failed verdict naming the node.
    *report*: the run's HTML report (graphflow.report) is written there, passed or failed.
    """
    path = str(path)
    document = load_document(path)
    checked = CheckedRun(document, source=path, inputs=ScriptedInputs.of_document(document),
                         listeners=listeners, update_golden=update_golden)
    checked.preflight()
    if checked.time_limit() is None:   # a scenario must end by itself: nothing hangs
        raise BadInput(f"{path}: no run limit: give settings.duration or a stopsBy check")
    checked.listeners.append(CollectedLog(checked.verdict.output))
    with contextlib.ExitStack() as closing:
        closing.callback(checked.close)
        simulation = checked.start()
        stream = None
        if trace is not None:
            stream = closing.enter_context(open(trace, "w", encoding="utf-8", newline="\n"))
            checked.verdict.trace = str(trace)
        if report is None:
            if stream is not None:
                from graphflow.observe.recorder import TraceRecorder

                TraceRecorder(simulation, stream, graph=path)
            return checked.run()
        from graphflow.report.recording import ReportRecording, runtime_failure

        recording = ReportRecording(simulation, path, also_to=stream)
        verdict = checked.run()
        recording.write(report, checked.document, evaluator=checked.evaluator, runtime_failure=runtime_failure(checked),
                        seed=checked.seed, force=True)
        return verdict
