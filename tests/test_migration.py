"""Node type versions: an older typeVersion a node type still reads is migrated on load with one line per
node, and graphflow migrate rewrites the file."""
import json
import warnings

from graphflow.cli import main
from graphflow.document import load_document
from graphflow.migration import MigrationWarning


def graph(*nodes):
    return {"format": "graphflow", "formatVersion": [1, 0], "nodes": list(nodes)}


OLD_READ = {"name": "read", "type": "omni.graph.nodes.ReadPrimAttribute", "typeVersion": 1,
            "inputs": {"name": "physics:mass", "prim": "/World/Cube"}}


def test_an_older_type_version_is_migrated_on_load_with_one_line(tmp_path):
    path = tmp_path / "old.json"
    path.write_text(json.dumps(graph(OLD_READ)))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        document = load_document(path)
    lines = [str(w.message) for w in caught if issubclass(w.category, MigrationWarning)]
    assert lines == [f"{path}: node 'read': omni.graph.nodes.ReadPrimAttribute typeVersion 1 -> 3 (version 3 "
                     "reads the inputs version 1 authored; only the typeVersion changes)"]
    assert document.node("read").type_version == 3
    assert document.node("read").inputs == OLD_READ["inputs"]


def test_graphflow_migrate_rewrites_the_file_once(tmp_path, capsys):
    path = tmp_path / "old.json"
    path.write_text(json.dumps(graph(OLD_READ)))
    assert main(["migrate", str(path)]) == 0
    assert "typeVersion 1 -> 3" in capsys.readouterr().out
    assert json.loads(path.read_text())["nodes"][0]["typeVersion"] == 3
    assert main(["migrate", str(path)]) == 0
    assert "nothing to migrate" in capsys.readouterr().out
    path.write_text(json.dumps(graph({**OLD_READ, "typeVersion": 9})))
    assert main(["migrate", str(path)]) == 2
    assert "node 'read': typeVersion 9 of omni.graph.nodes.ReadPrimAttribute is not supported" in capsys.readouterr().err
