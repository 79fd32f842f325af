"""graphflow draw: every node and edge appears, exec and data edges differ, columns follow execution order."""
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import pytest
from conftest import ROOT

from graphflow.document import load_document
from graphflow.observe import draw
from graphflow.testing import GraphHarness

COUNTER_GRAPH = ROOT / "graphs" / "counter_branch_print.json"
SVG = "{http://www.w3.org/2000/svg}"
EXEC_EDGES = {("on_tick.outputs:tick", "counter.inputs:execIn"), ("counter.outputs:execOut", "branch.inputs:execIn"),
              ("branch.outputs:execFalse", "print_count.inputs:execIn"),
              ("branch.outputs:execTrue", "print_done.inputs:execIn"), ("print_done.outputs:execOut", "stop.inputs:execIn")}
DATA_EDGES = {("counter.outputs:count", "at_least_three.inputs:a"),
              ("at_least_three.outputs:result", "branch.inputs:condition"),
              ("counter.outputs:count", "format_count.inputs:value"), ("format_count.outputs:text", "print_count.inputs:text")}
NODES = ["on_tick", "counter", "at_least_three", "branch", "format_count", "print_count", "print_done", "stop"]


def graphflow(*args):
    return subprocess.run([sys.executable, "-m", "graphflow", *args], capture_output=True, text=True)


def test_columns_follow_execution_with_pure_nodes_between_producer_and_consumer():
    columns = draw.layers(load_document(COUNTER_GRAPH))
    assert columns == {"on_tick": 0, "counter": 1, "at_least_three": 2, "branch": 3, "format_count": 3,
                       "print_count": 4, "print_done": 4, "stop": 5}


def test_svg_lists_every_node_with_its_set_inputs_and_every_edge_by_kind(tmp_path):
    target = tmp_path / "graph.svg"
    result = graphflow("draw", str(COUNTER_GRAPH), "-o", str(target))
    assert result.returncode == 0, result.stderr
    root = ElementTree.parse(target).getroot()
    nodes = {g.get("data-name"): g for g in root.iter(f"{SVG}g") if "node" in g.get("class", "").split()}
    assert list(nodes) == NODES
    assert nodes["counter"].get("data-type") == "omni.graph.action.Counter"
    settings = [t.text for t in nodes["at_least_three"].iter(f"{SVG}text") if t.get("class") == "setting"]
    assert settings == ["b = 3", "operation = >="]
    edges = {kind: {(p.get("data-src"), p.get("data-dst")) for p in root.iter(f"{SVG}path")
                    if p.get("class") == f"edge {kind}"} for kind in ("exec", "data")}
    assert edges == {"exec": EXEC_EDGES, "data": DATA_EDGES}
    exec_style = {p.get("stroke-dasharray") for p in root.iter(f"{SVG}path") if p.get("class") == "edge exec"}
    data_style = {p.get("stroke-dasharray") for p in root.iter(f"{SVG}path") if p.get("class") == "edge data"}
    assert exec_style == {None} and data_style == {"5 3"}


def test_boxes_read_left_to_right_in_execution_order():
    picture = draw.layout(load_document(COUNTER_GRAPH))
    x = {box.name: box.x for box in picture.boxes}
    assert x["on_tick"] < x["counter"] < x["branch"] < x["print_done"] < x["stop"]
    assert x["counter"] < x["at_least_three"] < x["branch"]
    for edge in picture.edges:   # every edge leaves a box's right side and enters another's left side
        source, target = picture.box(edge.src.split(".")[0]), picture.box(edge.dst.split(".")[0])
        assert edge.start[0] == source.x + source.width and edge.end[0] == target.x


def test_mermaid_has_every_node_and_edge(tmp_path):
    target = tmp_path / "graph.mmd"
    assert graphflow("draw", str(COUNTER_GRAPH), "-o", str(target)).returncode == 0
    text = target.read_text()
    assert text.startswith("flowchart LR\n")
    ids = dict(re.findall(r'^  (n\d+)\["<b>([\w-]+)</b>', text, re.M))
    assert sorted(ids.values()) == sorted(NODES)
    exec_edges = {(ids[a], ids[b]) for a, b in re.findall(r"^  (n\d+) ==>\|[^|]*\| (n\d+)$", text, re.M)}
    data_edges = {(ids[a], ids[b]) for a, b in re.findall(r"^  (n\d+) -\.->\|[^|]*\| (n\d+)$", text, re.M)}
    assert exec_edges == {(s.split(".")[0], d.split(".")[0]) for s, d in EXEC_EDGES}
    assert data_edges == {(s.split(".")[0], d.split(".")[0]) for s, d in DATA_EDGES}


def test_dot_has_every_node_and_edge(tmp_path):
    target = tmp_path / "graph.txt"
    assert graphflow("draw", str(COUNTER_GRAPH), "-o", str(target), "--format", "dot").returncode == 0
    text = target.read_text()
    assert text.startswith('digraph "counter_branch_print" {') and "rankdir=LR;" in text
    nodes = re.findall(r'^  "([\w-]+)" \[label=', text, re.M)
    assert nodes == NODES
    edges = re.findall(r'^  "([\w-]+)" -> "([\w-]+)" \[label="(\w+) → (\w+)", style=(\w+)', text, re.M)
    exec_edges = {(f"{a}.outputs:{x}", f"{b}.inputs:{y}") for a, b, x, y, style in edges if style == "bold"}
    data_edges = {(f"{a}.outputs:{x}", f"{b}.inputs:{y}") for a, b, x, y, style in edges if style == "dashed"}
    assert (exec_edges, data_edges) == (EXEC_EDGES, DATA_EDGES)


def test_png_draws_a_box_per_node(tmp_path):
    pytest.importorskip("matplotlib")
    figure = draw.figure(draw.layout(load_document(COUNTER_GRAPH)))
    boxes = [patch.get_gid() for patch in figure.axes[0].patches if patch.get_gid() in NODES]
    assert boxes == NODES
    target = tmp_path / "graph.png"
    assert graphflow("draw", str(COUNTER_GRAPH), "-o", str(target)).returncode == 0
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_exec_loops_and_unreachable_nodes_still_get_columns():
    harness = GraphHarness({"nodes": [
        {"name": "tick", "type": "omni.graph.action.OnTick"},
        {"name": "loop", "type": "omni.graph.action.ForLoop", "inputs": {"stop": 3}},
        {"name": "count", "type": "omni.graph.action.Counter"},
        {"name": "orphan", "type": "omni.graph.action.Counter"}],
        "connections": [{"src": "tick.outputs:tick", "dst": "loop.inputs:execIn"},
                        {"src": "loop.outputs:loopBody", "dst": "count.inputs:execIn"},
                        {"src": "count.outputs:execOut", "dst": "loop.inputs:breakLoop"}]})
    columns = draw.layers(harness.simulation.document)
    assert columns == {"tick": 0, "loop": 1, "count": 2, "orphan": 0}
    assert len(draw.layout(harness.simulation.document).edges) == 3


def test_unknown_suffix_is_bad_input(tmp_path):
    result = graphflow("draw", str(COUNTER_GRAPH), "-o", str(tmp_path / "graph.txt"))
    assert result.returncode == 2
    assert "cannot tell the format" in result.stderr and "Traceback" not in result.stderr
