"""``graphflow test PATH...``: every scenario (graph with checks) under the paths, in parallel, with a verdict each.

One line per scenario (PASS / FAIL with its failure lines), then exactly
``N passed, M failed``. A failing scenario keeps its trace and prints the
command that re-runs it. ``--junit FILE`` writes JUnit XML (one testsuite,
one testcase per scenario) through a temporary file and a rename.
"""
from __future__ import annotations

import json
import logging
import os
import shutil
import tempfile
import time
import xml.etree.ElementTree as ET
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path

from .scenario import ScenarioResult, rerun_command, run_scenario


class NoScenarios(ValueError):
    """The paths name no scenario (or do not exist): bad input."""


def is_scenario(path: Path) -> bool:
    """A graph document (format graphflow) with a non-empty checks section."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError):
        return False
    return isinstance(data, dict) and data.get("format") == "graphflow" and bool(data.get("checks"))


def collect(paths) -> list[Path]:
    """Scenario files named or found (recursively, sorted) under the given paths.

    A file named directly is taken even when it does not load, so its problem is reported.
    """
    found: list[Path] = []
    for given in map(Path, paths):
        if given.is_dir():
            found.extend(p for p in sorted(given.rglob("*.json")) if is_scenario(p))
        elif given.is_file():
            found.append(given)
        else:
            raise NoScenarios(f"{given}: no such file or folder")
    unique = list(dict.fromkeys(found))
    if not unique:
        raise NoScenarios(f"no graph with checks under {', '.join(map(str, paths))}")
    return unique


@dataclass
class Outcome:
    """A scenario's result as sent back from a worker process (plain data), plus wall time."""

    path: str
    result: ScenarioResult | None
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
    from .document import GraphError

    logging.getLogger("graphflow").setLevel(logging.ERROR)   # the graph's lines go to the report, not stderr
    started = time.perf_counter()
    try:
        result = run_scenario(path, trace=trace, report=report)
    except GraphError as error:
        return Outcome(path, None, error=str(error).splitlines()[0], wall=time.perf_counter() - started)
    except (ValueError, OSError) as error:
        return Outcome(path, None, error=str(error), wall=time.perf_counter() - started)
    outcome = Outcome(path, result, wall=time.perf_counter() - started, trace=trace, output=result.output, report=report)
    if result.passed:
        os.unlink(trace)
        outcome.trace = None
    return outcome


def run_all(paths: list[Path], jobs: int, trace_dir: Path, report=print, report_dir: Path | None = None) -> list[Outcome]:
    """Run every scenario on *jobs* processes; report each one's lines in the given order as it is known."""
    traces = [str(trace_dir / f"{index:03d}-{path.stem}.jsonl") for index, path in enumerate(paths)]
    reports = [str(report_dir / f"{index:03d}-{path.stem}.html") if report_dir is not None else None
               for index, path in enumerate(paths)]
    outcomes = []
    if jobs <= 1 or len(paths) == 1:
        for path, trace, html in zip(paths, traces, reports):
            outcomes.append(run_one(str(path), trace, html))
            for line in outcomes[-1].lines():
                report(line)
        return outcomes
    with ProcessPoolExecutor(max_workers=min(jobs, len(paths))) as pool:
        futures = [pool.submit(run_one, str(path), trace, html) for path, trace, html in zip(paths, traces, reports)]
        for future in futures:
            outcomes.append(future.result())
            for line in outcomes[-1].lines():
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


def write_new_file(path: Path, data: bytes, *, force: bool) -> None:
    """Write *data* to *path* through a temporary file and a rename; an existing file only with *force*."""
    if path.exists() and not force:
        raise FileExistsError(f"{path}: already exists; not overwriting it (use --force)")
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        if force:
            os.replace(temporary, path)
        else:
            os.link(temporary, path)   # fails if the file appeared meanwhile: never overwrites
            os.unlink(temporary)
    except BaseException:
        if os.path.exists(temporary):
            os.unlink(temporary)
        raise


def command_test(args, report=print) -> int:
    """Exit 0 when every scenario passes, 1 when one fails, 2 when a scenario or path is bad input."""
    paths = collect(args.paths)
    junit = Path(args.junit) if args.junit else None
    if junit is not None and junit.exists() and not args.force:
        raise FileExistsError(f"{junit}: already exists; not overwriting it (use --force)")
    if args.traces:
        trace_dir = Path(args.traces)
        trace_dir.mkdir(parents=True, exist_ok=True)
    else:
        trace_dir = Path(tempfile.mkdtemp(prefix="graphflow-test-"))
    report_dir = None
    if getattr(args, "reports", None):
        report_dir = Path(args.reports)
        report_dir.mkdir(parents=True, exist_ok=True)
        existing = [p.name for p in report_dir.glob("*.html")] if not args.force else []
        if existing:
            raise FileExistsError(f"{report_dir}: already holds reports ({existing[0]}, ...); not overwriting them (use --force)")
    outcomes = run_all(paths, args.jobs or os.cpu_count() or 1, trace_dir, report, report_dir)
    if not args.traces and not any(o.trace for o in outcomes):
        shutil.rmtree(trace_dir, ignore_errors=True)
    if junit is not None:
        write_new_file(junit, junit_xml(outcomes), force=args.force)
    passed = sum(1 for o in outcomes if o.passed)
    report(f"{passed} passed, {len(outcomes) - passed} failed")
    if any(o.error is not None for o in outcomes):
        return 2
    return 0 if passed == len(outcomes) else 1
