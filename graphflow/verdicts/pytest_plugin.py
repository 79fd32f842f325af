"""pytest plugin: scenario graphs (graph files with checks) as test items, so one pytest run covers both.

Opt-in, so installing graphflow never changes another project's test run:
collection starts when the ini option ``graphflow_scenarios = true`` is set
(pyproject's ``[tool.pytest.ini_options]``) or ``--graphflow-scenarios`` is
given. Then every ``*.json`` graph with a ``checks`` section that pytest visits
(for example a folder listed in ``testpaths``) becomes one item; a scenario table
(``graphflow-cases``) one item per case, named by the case; a rate scenario one
item for all its seeds. A failure shows the failed checks, the kept trace and
the command that re-runs it.
Items carry the marker ``graphflow_scenario`` (``-m 'not graphflow_scenario'`` skips them).
Registered through the ``pytest11`` entry point ``graphflow``.
"""
from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

import pytest


def pytest_addoption(parser):
    parser.addini("graphflow_scenarios", "collect graph files with checks as test items", type="bool", default=False)
    parser.addoption("--graphflow-scenarios", action="store_true", default=False,
                     help="collect graph files with checks (graphflow scenarios) as test items")


def pytest_configure(config):
    config.addinivalue_line("markers", "graphflow_scenario: a graph with checks run as a test item "
                                       "(deselect with -m 'not graphflow_scenario')")


def _enabled(config) -> bool:
    return config.getoption("--graphflow-scenarios") or config.getini("graphflow_scenarios")


def pytest_collect_file(parent, file_path: Path):
    if file_path.suffix != ".json" or not _enabled(parent.config):
        return None
    from graphflow.verdicts.suite import scenario_problem

    problem = scenario_problem(file_path)
    if problem is False:
        return None
    return ScenarioFile.from_parent(parent, path=file_path, problem=problem)


class ScenarioFile(pytest.File):
    """A scenario file; one that does not parse, or looks like a graph and does not load, is a collection error."""

    def __init__(self, *, problem: str | None = None, **kwargs):
        super().__init__(**kwargs)
        self.problem = problem

    def collect(self):
        from graphflow.verdicts.suite import expand

        if self.problem is not None:
            raise self.CollectError(self.problem)
        for item in expand(self.path, None):
            if item.problem is not None:
                raise self.CollectError(item.problem)
            name = item.case.name if item.case is not None else self.path.name
            yield ScenarioItem.from_parent(self, name=name, test_item=item)


class ScenarioFailed(Exception):
    """A scenario's verdict was a failure; the args are the lines to show."""


class ScenarioItem(pytest.Item):
    def __init__(self, *, test_item, **kwargs):
        super().__init__(**kwargs)
        self.test_item = test_item   # graphflow.verdicts.suite.TestItem: a scenario, a table's case or a rate
        self.add_marker("graphflow_scenario")

    def runtest(self):
        from graphflow.verdicts.suite import run_one

        if self.test_item.rate is not None:
            self.run_rate()
            return
        folder = Path(tempfile.mkdtemp(prefix="graphflow-scenario-"))
        outcome = run_one(self.test_item, str(folder / f"{self.path.stem}.jsonl"), quiet=False)
        if outcome.passed or outcome.error is not None:
            folder.rmdir()
        if outcome.error is not None:   # the graph, its stage, a check target or a key file
            raise ScenarioFailed(outcome.error)
        if not outcome.passed:
            raise ScenarioFailed(*(line.strip() for line in outcome.lines()))

    def run_rate(self):
        """A rate runs its episodes on sweep workers: through ``graphflow test`` in a process of its own."""
        result = subprocess.run([sys.executable, "-m", "graphflow", "test", str(self.path)],
                                capture_output=True, text=True)
        if result.returncode != 0:
            raise ScenarioFailed(*(line.strip() for line in (result.stdout + result.stderr).splitlines()[:-1] or ["failed"]))

    def repr_failure(self, excinfo, style=None):
        if isinstance(excinfo.value, ScenarioFailed):
            return "\n".join(excinfo.value.args)
        return super().repr_failure(excinfo, style)

    def reportinfo(self):
        return self.path, None, f"scenario {self.test_item.name}"
