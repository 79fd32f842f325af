"""Issue 26: names and summaries that match the run.

Check names in graphs/*.json quote no measured figure (a figure in a name drifts from the run the
first time the physics changes); the README's quoted figures are the ones the runs give now; and a
node summary in ``graphflow nodes`` is never a bare label such as "Event source".
"""
import json
import math
import re

import pytest
from conftest import GRAPHS, ROOT

from graphflow import cli
from graphflow.document import load_document
from graphflow.verdicts.checked_run import CheckedRun, ScriptedInputs

README = (ROOT / "README.md").read_text(encoding="utf-8")


def shipped_graphs():
    return [p for p in sorted(GRAPHS.glob("*.json")) + sorted(GRAPHS.glob("scenarios/*.json"))
            if not p.name.endswith((".keys.json", ".topics.json"))]


@pytest.mark.parametrize("path", shipped_graphs(), ids=lambda p: p.name)
def test_check_names_quote_no_measured_figure(path):
    names = [check.get("name", "") for check in json.loads(path.read_text(encoding="utf-8")).get("checks", [])]
    assert [name for name in names if re.search(r"measured|\d+(\.\d+)? mm off", name)] == []


def distance_mm(graph: str, check_index: int) -> float:
    """How far the position check's prim ends from its target, measured on a run of the graph as shipped."""
    document = load_document(GRAPHS / graph)
    run = CheckedRun(document, inputs=ScriptedInputs.of_document(document))
    try:
        run.start()
        assert run.run().failures == []
        check = document.checks[check_index]
        position = run.simulation.world.prim_pose(check["prim"])[0]
        return 1000 * math.dist(position, check["position"])
    finally:
        run.close()


@pytest.mark.parametrize("graph, check_index, quoted", [
    ("ur10_pick_place.json", 0, r"cube ends ([\d.]+) mm from the target"),
    ("ur10_pick_place_tuned.json", 0, r"cube ends ([\d.]+) mm from \(-0\.4, 0\.5\)"),
    ("ur10_stacking.json", 1, r"top cube centred within ([\d.]+) mm"),
    ("gantry_keyboard.json", 0, r"box set down ([\d.]+) mm from where the keys put it"),
])
def test_readme_figures_are_what_the_runs_give(graph, check_index, quoted):
    figure = re.search(quoted, README)
    assert figure is not None, quoted
    stated = float(figure.group(1))
    decimals = len(figure.group(1).split(".")[1])
    measured = distance_mm(graph, check_index)
    # "0.02 mm" is read as the measured distance rounded to that many decimals; "within" as an upper bound
    if "within" in quoted:
        assert measured <= stated and round(measured, decimals) >= stated - 10 ** -decimals
    else:
        assert round(measured, decimals) == stated, (graph, measured)


def test_node_summaries_are_more_than_a_label(capsys):
    assert cli.main(["nodes"]) == 0
    summaries = {line.split()[0]: re.split(r"\s+v\d+\s+", line, maxsplit=1)[1]
                 for line in capsys.readouterr().out.splitlines()}
    assert summaries["omni.graph.action.OnLoaded"] == (
        "Event source. execOut fires once, on the first tick after the graph is loaded or reset")
    assert [node for node, summary in summaries.items() if len(summary.split()) < 3] == []
