"""Typed handles (graphflow schema --python): a type checker completes a node's ports and flags a
misspelled one before anything runs; at run time they are the builder's handles."""
import os
import subprocess
import sys

import pytest
from conftest import ROOT

from graphflow.build import Graph
from graphflow.cli import main
from graphflow.registry import default_registry

SCRIPT = '''from graphflow.build import Graph
from typed_nodes import Counter, OnTick

graph = Graph()
tick = graph.node("tick", OnTick)
count = graph.node("count", Counter)
graph.connect(tick.outputs.tick, count.inputs.execIn)
graph.connect(tick.outputs.tick, count.inputs.{port})
'''


@pytest.fixture
def typed_nodes(tmp_path, monkeypatch, capsys):
    assert main(["schema", "--python", "-o", str(tmp_path / "typed_nodes.py")]) == 0
    monkeypatch.syspath_prepend(str(tmp_path))
    yield tmp_path
    sys.modules.pop("typed_nodes", None)


def test_every_node_type_gets_a_handle_class(typed_nodes):
    import typed_nodes as typed

    classes = [value for value in vars(typed).values() if isinstance(value, type) and getattr(value, "TYPE_ID", "")]
    assert sorted(c.TYPE_ID for c in classes) == sorted(t.spec.id for t in default_registry().types())
    graph = Graph()
    count = graph.node("count", typed.Counter)
    assert isinstance(count, typed.Counter) and str(count.outputs.count) == "count.outputs:count"
    assert graph.document.node("count").type == "omni.graph.action.Counter"


@pytest.mark.parametrize("port, errors", [("execIn", []), ("execInn", ['"Inputs" has no attribute "execInn"'])])
def test_a_type_checker_flags_a_misspelled_port(typed_nodes, port, errors):
    (typed_nodes / "cell.py").write_text(SCRIPT.format(port=port))
    result = subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--follow-imports=silent", "--ignore-missing-imports",
         "cell.py"], cwd=typed_nodes, capture_output=True, text=True,
        env={**os.environ, "MYPYPATH": f"{ROOT}{os.pathsep}{typed_nodes}"})
    found = [line for line in result.stdout.splitlines() if "error:" in line]
    assert len(found) == len(errors) and all(e in line for e, line in zip(errors, found)), result.stdout
