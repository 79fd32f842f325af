"""``graphflow test PATH...``: every test item under the paths, in parallel, with a verdict each.

An item is a scenario (graph with checks), one case of a scenario table (``graphflow.verdicts.cases``)
or a rate scenario run over seeds (``graphflow.verdicts.rates``). One line per item (PASS / XFAIL /
FAIL with its failure lines), then exactly ``N passed, M failed``. A failing run keeps its trace and
timeline picture and prints the command that re-runs it. ``--junit FILE`` writes JUnit XML (one
testsuite, one testcase per item, a rate's counts as properties, kept files in ``<system-out>``)
through a temporary file and a rename.
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
from typing import Any, Literal

from graphflow.errors import BadInput
from graphflow.files import FileProblem, read_json, refuse_existing, write_bytes
from graphflow.verdicts.cases import Case, is_table, load_table, run_case
from graphflow.verdicts.checked_run import rerun_command, run_checked
from graphflow.verdicts.rates import RatePlan, rate_plan


class NoScenarios(BadInput):
    """The paths name no scenario (or do not exist): bad input."""


def scenario_problem(path: Path) -> str | None | Literal[False]:
    """What a ``*.json`` found under a test path is: False when it is no scenario (not a graph, or a graph
    without checks that loads), None for a scenario, or the one-line problem of a file that does not parse
    or looks like a graph and does not load. Nothing under the paths is skipped silently."""
    from graphflow.document import load_document

    try:
        data = read_json(path)
    except FileProblem as error:
        return str(error)
    if is_table(data):
        try:
            load_table(path)
        except BadInput as error:
            return error.lines()[0]
        return None
    looks_like_graph = isinstance(data, dict) and (data.get("format") == "graphflow" or "nodes" in data)
    if not looks_like_graph:
        return False
    try:
        load_document(path)
    except BadInput as error:
        return error.lines()[0]
    return None if data.get("checks") else False


@dataclass(frozen=True)
class TestItem:
    """One verdict of ``graphflow test``: a scenario file, a case of a table, or a rate over seeds."""

    path: Path
    problem: str | None = None
    case: Case | None = None
    rate: RatePlan | None = None

    @property
    def name(self) -> str:
        return self.case.item_name if self.case is not None else str(self.path)


def expand(path: Path, problem: str | None, seeds: int | None = None, gate: float | None = None) -> list[TestItem]:
    """The items of one collected file: a table's cases, a rate (declared ``seeds`` or ``--seeds``), or itself."""
    if problem is not None:
        return [TestItem(path, problem)]
    try:
        data = read_json(path)
        if is_table(data):
            return [TestItem(path, case=case) for case in load_table(path)]
    except BadInput as error:
        return [TestItem(path, error.lines()[0])]
    plan = rate_plan(str(path), data, seeds, gate) if isinstance(data, dict) else None
    return [TestItem(path, rate=plan)]


def collect_items(paths, seeds: int | None = None, gate: float | None = None) -> list[TestItem]:
    return [item for path, problem in collect(paths) for item in expand(path, problem, seeds, gate)]


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
    result: Any   # a Verdict, or a RateVerdict; None for bad input
    error: str | None = None        # bad input: the graph, stage or scripted inputs did not load
    wall: float = 0.0
    trace: str | None = None
    output: list[str] = field(default_factory=list)
    rerun: str = ""
    artifacts: list[str] = field(default_factory=list)   # lines on what a failing run left: trace, timeline
    files: list[str] = field(default_factory=list)       # the files those lines name
    case: str | None = None                               # the table case's name
    properties: dict = field(default_factory=dict)       # JUnit properties (a rate's counts and interval)
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
            lines += [f"    {artifact}" for artifact in self.artifacts]
            if self.report:
                lines.append(f"    report: {self.report}")
            if self.rerun:
                lines.append(f"    re-run: {self.rerun}")
        return lines


def run_one(item: TestItem, trace: str, update_golden: bool = False, quiet: bool = True,
            report: str | None = None) -> Outcome:
    """Worker: run one scenario or case with a trace (deleted when it passes, else drawn) and, if asked, a
    scenario's report (kept)."""
    if quiet:
        logging.getLogger("graphflow").setLevel(logging.ERROR)   # the graph's lines go to the report, not stderr
    started = time.perf_counter()
    name = item.name
    try:
        if item.case is not None:
            result, rerun, report = run_case(item.case, trace=trace), item.case.rerun_command(), None
        else:
            result = run_checked(item.path, trace=trace, report=report, update_golden=update_golden)
            rerun = rerun_command(name)
    except BadInput as error:
        return Outcome(name, None, error=error.lines()[0], wall=time.perf_counter() - started)
    outcome = Outcome(name, result, wall=time.perf_counter() - started, trace=trace, output=result.output,
                      rerun=rerun, case=item.case.name if item.case is not None else None, report=report)
    if result.passed:
        os.unlink(trace)
        outcome.trace = None
    else:
        outcome.artifacts, outcome.files = failure_artifacts(trace)
    return outcome


def failure_artifacts(trace: str) -> tuple[list[str], list[str]]:
    """The kept trace and its timeline picture (``graphflow plot``): lines for the report, and the files."""
    lines, files = [f"trace: {trace}"], [trace]
    picture = str(Path(trace).with_suffix(".png"))
    try:
        from graphflow.observe.timeline import write_timeline
        from graphflow.observe.trace import read_trace

        write_timeline(read_trace(trace), picture)
    except ImportError as error:
        lines.append(f"timeline: not drawn ({error.name} is not installed: pip install 'graphflow[viz]')")
    else:
        lines.append(f"timeline: {picture}")
        files.append(picture)
    return lines, files


def run_rate_item(item: TestItem, jobs: int | None, ray: bool, rate_runner) -> Outcome:
    """A rate item, in this process: *rate_runner* (``graphflow.sweep.scenario_rates.run_rate``, given by the
    command line, which sits above both packages) runs its episodes on the sweep launcher's own workers."""
    started = time.perf_counter()
    try:
        result = rate_runner(item.rate, jobs=jobs, ray=ray)
    except BadInput as error:
        return Outcome(item.name, None, error=error.lines()[0], wall=time.perf_counter() - started)
    return Outcome(item.name, result, wall=time.perf_counter() - started, properties=result.properties(),
                   output=[result.rate_line(), *result.failures[0 if result.gate_passed else 1:]])


def run_all(items: list[TestItem], jobs: int, trace_dir: Path, report=print, *, update_golden: bool = False,
            ray: bool = False, rate_runner=None, report_dir: Path | None = None) -> list[Outcome]:
    """Run every item, single runs on *jobs* processes and rates on the sweep launcher in turn; report each
    item's lines in the given order as it is known. A file whose problem is already known (it does not
    parse or load) is an ERROR outcome without a run.
    """
    traces = [str(trace_dir / f"{index:03d}-{item.path.stem}.jsonl") for index, item in enumerate(items)]
    reports = [str(report_dir / f"{index:03d}-{item.path.stem}.html") if report_dir is not None else None
               for index, item in enumerate(items)]
    outcomes: list[Outcome | None] = [None if item.problem is None else Outcome(item.name, None, error=item.problem)
                                      for item in items]
    runnable = [index for index, item in enumerate(items) if item.problem is None and item.rate is None]
    futures: dict = {index: _Later(run_rate_item, item, jobs, ray, rate_runner) for index, item in enumerate(items)
                     if item.problem is None and item.rate is not None}
    if jobs <= 1 or len(runnable) <= 1:
        futures.update({index: _Later(run_one, items[index], traces[index], update_golden, True, reports[index])
                        for index in runnable})
        return _report_in_order(outcomes, futures, report)
    with ProcessPoolExecutor(max_workers=min(jobs, len(runnable))) as pool:
        futures.update({index: pool.submit(run_one, items[index], traces[index], update_golden, True, reports[index])
                        for index in runnable})
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
        path = Path(outcome.path.split("::")[0])
        classname = path.parent.as_posix().replace("/", ".").strip(".") or "graphs"
        if outcome.case is not None:   # a table's case: the table is the class, the case the test
            classname = f"{classname}.{path.stem}"
        case = ET.SubElement(suite, "testcase", name=outcome.case or path.name, classname=classname,
                             file=str(path), time=f"{outcome.wall:.3f}")
        # a rate's counts and interval, the run report beside the verdict (CI servers show testcase properties)
        shown = {**outcome.properties, **({"report": outcome.report} if outcome.report else {})}
        if shown:
            properties = ET.SubElement(case, "properties")
            for key, value in shown.items():
                ET.SubElement(properties, "property", name=key, value=value)
        if outcome.error is not None:
            ET.SubElement(case, "error", message=outcome.error, type="BadInput").text = outcome.error
        elif not outcome.passed:
            element = ET.SubElement(case, "failure", message=outcome.lines()[0], type="CheckFailed")
            element.text = "\n".join(outcome.lines()[1:])
        if outcome.output or outcome.files:   # [[ATTACHMENT|path]]: how Jenkins and GitLab pick up a test's files
            ET.SubElement(case, "system-out").text = "\n".join(
                [*outcome.output, *outcome.artifacts, *(f"[[ATTACHMENT|{Path(file).resolve()}]]" for file in outcome.files)])
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


def command_test(args, report=print, rate_runner=None) -> int:
    """Exit 0 when every scenario passes, 1 when one fails, 2 when a scenario or path is bad input."""
    items = collect_items(args.paths, args.seeds, args.min_pass_rate)
    junit = Path(args.junit) if args.junit else None
    if junit is not None:
        refuse_existing(junit, args.force)
    if args.traces:
        trace_dir = Path(args.traces)
        trace_dir.mkdir(parents=True, exist_ok=True)
    else:
        trace_dir = Path(tempfile.mkdtemp(prefix="graphflow-test-"))
    report_dir = _report_folder(getattr(args, "reports", None), args.force)
    outcomes = run_all(items, args.jobs or os.cpu_count() or 1, trace_dir, report, update_golden=args.update_golden,
                       ray=args.ray, rate_runner=rate_runner, report_dir=report_dir)
    if not args.traces and not any(o.trace for o in outcomes):
        shutil.rmtree(trace_dir, ignore_errors=True)
    if junit is not None:
        write_bytes(junit, junit_xml(outcomes), force=args.force)
    passed = sum(1 for o in outcomes if o.passed)
    report(f"{passed} passed, {len(outcomes) - passed} failed")
    if any(o.error is not None for o in outcomes):
        return 2
    return 0 if passed == len(outcomes) else 1
