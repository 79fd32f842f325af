"""``graphflow test PATH...``: every scenario (graph with checks) under the paths, in parallel, with a verdict each.

One line per scenario (PASS / FAIL with its failure lines), then exactly
``N passed, M failed``. A failing scenario keeps its trace and prints the
command that re-runs it. ``--junit FILE`` writes JUnit XML (one testsuite,
one testcase per scenario) through a temporary file and a rename.
"""
from __future__ import annotations

import logging
import os
import shutil
import tempfile
import time
import xml.etree.ElementTree as ET
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from graphflow.errors import BadInput
from graphflow.files import FileProblem, read_json, refuse_existing, write_bytes
from graphflow.verdicts.checked_run import Verdict, rerun_command, run_checked


class NoScenarios(BadInput):
    """The paths name no scenario (or do not exist): bad input."""


def scenario_problem(path: Path) -> str | None | bool:
    """What a ``*.json`` found under a test path is: False when it is no scenario (not a graph, or a graph
    without checks that loads), None for a scenario, or the one-line problem of a file that does not parse
    or looks like a graph and does not load. Nothing under the paths is skipped silently."""
    from graphflow.document import load_document

    try:
        data = read_json(path)
    except FileProblem as error:
        return str(error)
    looks_like_graph = isinstance(data, dict) and (data.get("format") == "graphflow" or "nodes" in data)
    if not looks_like_graph:
        return False
    try:
        load_document(path)
    except BadInput as error:
        return error.lines()[0]
    return None if data.get("checks") else False


def collect(paths) -> list[tuple[Path, str | None]]:
    """Scenario files named or found (recursively, sorted) under the given paths, each with its problem.

    A file named directly is taken even when it has no checks, so what is wrong with it is reported.
    """
    found: list[tuple[Path, str | None]] = []
    for given in map(Path, paths):
        if given.is_dir():
            for candidate in sorted(given.rglob("*.json")):
                problem = scenario_problem(candidate)
                if problem is not False:
                    found.append((candidate, problem))
        elif given.is_file():
            found.append((given, None))
        else:
            raise NoScenarios(f"{given}: no such file or folder")
    unique = list(dict(found).items())
    if not unique:
        raise NoScenarios(f"no graph with checks under {', '.join(map(str, paths))}")
    return unique


@dataclass
class Outcome:
    """A scenario's result as sent back from a worker process (plain data), plus wall time."""

    path: str
    result: Verdict | None
    error: str | None = None        # bad input: the graph, stage or scripted inputs did not load
    wall: float = 0.0
    trace: str | None = None
    output: list[str] = field(default_factory=list)
    report: str | None = None       # the scenario's HTML run report (graphflow test --reports)

    @property
    def passed(self) -> bool:
        return self.error is None and self.result is not None and self.result.passed

    def lines(self) -> list[str]:
        """The scenario's line and, when it failed, its failure lines, trace and re-run command."""
        if self.error is not None:
            return [f"ERROR {self.path}: {self.error}"]
        lines = [self.result.verdict_line()]
        lines += [f"    {failure}" for failure in self.result.failures]
        if not self.passed:
            if self.trace:
                lines.append(f"    trace: {self.trace}")
            if self.report:
                lines.append(f"    report: {self.report}")
            lines.append(f"    re-run: {rerun_command(self.path)}")
        return lines


def run_one(path: str, trace: str, report: str | None = None) -> Outcome:
    """Worker: run one scenario with a trace (deleted when the scenario passes) and, if asked, a report (kept)."""
    logging.getLogger("graphflow").setLevel(logging.ERROR)   # the graph's lines go to the report, not stderr
    started = time.perf_counter()
    try:
        result = run_checked(path, trace=trace, report=report)
    except BadInput as error:
        return Outcome(path, None, error=error.lines()[0], wall=time.perf_counter() - started)
    outcome = Outcome(path, result, wall=time.perf_counter() - started, trace=trace, output=result.output,
                      report=report)
    if result.passed:
        os.unlink(trace)
        outcome.trace = None
    return outcome


def run_all(scenarios: list[tuple[Path, str | None]], jobs: int, trace_dir: Path, report=print,
            report_dir: Path | None = None) -> list[Outcome]:
    """Run every scenario on *jobs* processes; report each one's lines in the given order as it is known.

    A file whose problem is already known (it does not parse or load) is an ERROR outcome without a run.
    """
    traces = [str(trace_dir / f"{index:03d}-{path.stem}.jsonl") for index, (path, _) in enumerate(scenarios)]
    reports = [str(report_dir / f"{index:03d}-{path.stem}.html") if report_dir is not None else None
               for index, (path, _) in enumerate(scenarios)]
    runnable = [index for index, (_, problem) in enumerate(scenarios) if problem is None]
    outcomes: list[Outcome | None] = [None if problem is None else Outcome(str(path), None, error=problem)
                                      for path, problem in scenarios]
    if jobs <= 1 or len(runnable) <= 1:
        futures = {index: _Later(run_one, str(scenarios[index][0]), traces[index], reports[index]) for index in runnable}
        return _report_in_order(outcomes, futures, report)
    with ProcessPoolExecutor(max_workers=min(jobs, len(runnable))) as pool:
        futures = {index: pool.submit(run_one, str(scenarios[index][0]), traces[index], reports[index])
                   for index in runnable}
        return _report_in_order(outcomes, futures, report)


class _Later:
    """A scenario run in this process when its outcome is asked for, shaped like a future."""

    def __init__(self, function, *arguments):
        self.function, self.arguments = function, arguments

    def result(self) -> Outcome:
        return self.function(*self.arguments)


def _report_in_order(outcomes: list, futures: dict, report) -> list[Outcome]:
    for index in range(len(outcomes)):
        if outcomes[index] is None:
            outcomes[index] = futures[index].result()
        for line in outcomes[index].lines():
            report(line)
    return outcomes


def junit_xml(outcomes: list[Outcome]) -> bytes:
    """JUnit XML: one testsuite 'graphflow', one testcase per scenario (failure = checks, error = bad input)."""
    failures = sum(1 for o in outcomes if o.error is None and not o.passed)
    errors = sum(1 for o in outcomes if o.error is not None)
    total_time = sum(o.wall for o in outcomes)
    suites = ET.Element("testsuites", tests=str(len(outcomes)), failures=str(failures), errors=str(errors),
                        time=f"{total_time:.3f}")
    suite = ET.SubElement(suites, "testsuite", name="graphflow", tests=str(len(outcomes)), failures=str(failures),
                          errors=str(errors), skipped="0", time=f"{total_time:.3f}")
    for outcome in outcomes:
        path = Path(outcome.path)
        case = ET.SubElement(suite, "testcase", name=path.name, classname=path.parent.as_posix().replace("/", ".").strip(".") or "graphs",
                             file=outcome.path, time=f"{outcome.wall:.3f}")
        if outcome.report:   # the run report beside the verdict (CI servers show testcase properties)
            properties = ET.SubElement(case, "properties")
            ET.SubElement(properties, "property", name="report", value=outcome.report)
        if outcome.error is not None:
            ET.SubElement(case, "error", message=outcome.error, type="BadInput").text = outcome.error
        elif not outcome.passed:
            element = ET.SubElement(case, "failure", message=outcome.lines()[0], type="CheckFailed")
            element.text = "\n".join(outcome.lines()[1:])
        if outcome.output:
            ET.SubElement(case, "system-out").text = "\n".join(outcome.output)
    ET.indent(suites)
    return ET.tostring(suites, encoding="utf-8", xml_declaration=True) + b"\n"


def _report_folder(folder: str | None, force: bool) -> Path | None:
    """The --reports folder, made if missing; one already holding reports only with --force."""
    if folder is None:
        return None
    path = Path(folder)
    path.mkdir(parents=True, exist_ok=True)
    existing = sorted(p.name for p in path.glob("*.html"))
    if existing and not force:
        raise BadInput(f"{path}: already holds reports ({existing[0]}, ...); not overwriting them (use --force)")
    return path


def command_test(args, report=print) -> int:
    """Exit 0 when every scenario passes, 1 when one fails, 2 when a scenario or path is bad input."""
    scenarios = collect(args.paths)
    junit = Path(args.junit) if args.junit else None
    if junit is not None:
        refuse_existing(junit, args.force)
    if args.traces:
        trace_dir = Path(args.traces)
        trace_dir.mkdir(parents=True, exist_ok=True)
    else:
        trace_dir = Path(tempfile.mkdtemp(prefix="graphflow-test-"))
    report_dir = _report_folder(getattr(args, "reports", None), args.force)
    outcomes = run_all(scenarios, args.jobs or os.cpu_count() or 1, trace_dir, report, report_dir)
    if not args.traces and not any(o.trace for o in outcomes):
        shutil.rmtree(trace_dir, ignore_errors=True)
    if junit is not None:
        write_bytes(junit, junit_xml(outcomes), force=args.force)
    passed = sum(1 for o in outcomes if o.passed)
    report(f"{passed} passed, {len(outcomes) - passed} failed")
    if any(o.error is not None for o in outcomes):
        return 2
    return 0 if passed == len(outcomes) else 1
