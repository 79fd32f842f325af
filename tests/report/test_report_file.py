"""graphflow run --report / graphflow report / graphflow test --reports: one self-contained, reproducible HTML file."""
import json
import re

from graphflow.observe.trace import read_trace

from .conftest import PICK_MISSES, PICK_PLACE, graphflow

DATA = re.compile(r'<script id="graphflow-run" type="application/json">(.*?)</script>', re.S)


def embedded(path) -> dict:
    (payload,) = DATA.findall(path.read_text(encoding="utf-8"))
    return json.loads(payload.replace("<\\/", "</"))


def value_at(changes, tick):
    return [value for at, value in changes if at <= tick][-1]


def test_the_same_run_gives_a_byte_identical_report(pick_place_run, tmp_path):
    """Also the recorder's two paths: with --trace every tick is encoded as it ends, without it at the end."""
    again = tmp_path / "again.html"
    assert graphflow("run", str(PICK_PLACE), "--report", str(again)).returncode == 0
    assert again.read_bytes() == pick_place_run["report"].read_bytes()


def test_the_page_loads_nothing_from_the_network(pick_place_run):
    page = pick_place_run["report"].read_text(encoding="utf-8")
    assert not re.search(r"<(script|link|img|iframe)[^>]+(src|href)=", page)
    assert "@import" not in page   # the bundle's one fetch( is the studio's API (studio mode): tests/studio checks the
    # report mode requests nothing at run time (test_the_report_mode_requests_nothing_from_the_network)


def test_wire_values_are_the_trace_values(pick_place_run):
    data = embedded(pick_place_run["report"])
    trace = read_trace(pick_place_run["trace"])
    key = "cube_pose.position"
    assert any(edge["dst"] == "pick_place.inputs:pickingPosition" and edge["src"] == "cube_pose.outputs:position"
               for edge in data["graph"]["edges"])
    expected = trace.header["outputs"][key]
    for record in trace.ticks:
        expected = record.get("outputs", {}).get(key, expected)
        if record["tick"] == 500:
            break
    assert value_at(data["outputs"][key], 500) == expected


def test_nodes_are_laid_out_as_graphflow_draw_lays_them_out(pick_place_run):
    from graphflow.document import load_document
    from graphflow.observe.draw import layout

    picture = layout(load_document(str(PICK_PLACE)))
    nodes = {node["name"]: node for node in embedded(pick_place_run["report"])["graph"]["nodes"]}
    assert set(nodes) == {box.name for box in picture.boxes}
    for box in picture.boxes:
        assert (nodes[box.name]["x"], nodes[box.name]["y"]) == (box.x, box.y)


def test_a_failing_scenario_marks_its_failed_check_where_it_failed(pick_misses_run):
    """pick_misses' held check fails when the hold should start, 9.5 s (tick 570 at 60 Hz), with the gripper's reason."""
    checks = embedded(pick_misses_run["report"])["checks"]
    held, position = checks
    assert held["passed"] is False and held["tick"] == 570 and abs(held["t"] - 9.5) < 1e-9
    assert "nearest hit /World/Cube" in held["measured"]
    assert position["passed"] is False and position["tick"] == embedded(pick_misses_run["report"])["ticks"]


def test_a_report_from_a_trace_shows_the_same_run(pick_place_run, tmp_path):
    target = tmp_path / "from_trace.html"
    result = graphflow("report", str(pick_place_run["trace"]), "-o", str(target))
    assert result.returncode == 0, result.stderr
    from_trace, from_run = embedded(target), embedded(pick_place_run["report"])
    for key in ("outputs", "poses", "pulses", "grippers", "rays", "graph", "times"):
        assert from_trace[key] == from_run[key], key
    assert from_trace["checks"] == [] and from_trace["header"]["judged"] is False


def test_an_existing_report_is_kept_without_force(pick_place_run):
    before = pick_place_run["report"].read_bytes()
    result = graphflow("run", str(PICK_PLACE), "--ticks", "2", "--report", str(pick_place_run["report"]))
    assert result.returncode == 2 and "already exists" in result.stderr and len(result.stderr.splitlines()) == 1
    assert pick_place_run["report"].read_bytes() == before


def test_a_file_that_is_not_a_trace_is_bad_input(tmp_path):
    bad = tmp_path / "bad.jsonl"
    bad.write_text("hello\n")
    result = graphflow("report", str(bad), "-o", str(tmp_path / "r.html"))
    assert result.returncode == 2 and "not a graphflow trace" in result.stderr
    assert "Traceback" not in result.stderr and not (tmp_path / "r.html").exists()


def test_timings_are_wall_clock_per_node_only_when_asked(tmp_path):
    report = tmp_path / "timed.html"
    assert graphflow("run", str(PICK_PLACE), "--ticks", "30", "--report", str(report), "--report-timings").returncode == 0
    data = embedded(report)
    assert data["header"]["timings"] is True
    assert data["timings"]["on_tick"]["computes"] == 30 and data["timings"]["on_tick"]["seconds"] > 0


def test_graphflow_test_leaves_a_report_for_a_failing_scenario_linked_from_junit(tmp_path):
    import xml.etree.ElementTree as ET

    reports, junit = tmp_path / "reports", tmp_path / "junit.xml"
    result = graphflow("test", str(PICK_MISSES.parent), "--reports", str(reports), "--junit", str(junit))
    assert result.returncode == 0, result.stdout + result.stderr   # pick_misses is an expected failure (XFAIL)
    [report] = reports.glob("*-pick_misses.html")   # numbered by its place among the folder's scenarios
    assert embedded(report)["checks"][0]["passed"] is False
    case = ET.parse(junit).getroot().find(".//testcase[@name='pick_misses.json']")
    assert case.find("properties/property[@name='report']").get("value") == str(report)


def test_a_version_1_trace_still_makes_a_report(tmp_path):
    """A trace from before the scene section: the report shows its graph, values and pulses, and no scene."""
    counter = PICK_PLACE.parent / "counter_branch_print.json"
    trace = tmp_path / "new.jsonl"
    assert graphflow("run", str(counter), "--trace", str(trace)).returncode == 0
    lines = [json.loads(line) for line in trace.read_text().splitlines()]
    lines[0]["version"] = 1
    lines[0].pop("scene", None)
    for record in lines[1:]:
        record.pop("computed", None)
    old = tmp_path / "old.jsonl"
    old.write_text("".join(json.dumps(record) + "\n" for record in lines))
    result = graphflow("report", str(old), "-o", str(tmp_path / "old.html"))
    assert result.returncode == 0, result.stderr
    data = embedded(tmp_path / "old.html")
    assert data["header"]["traceVersion"] == 1 and data["scene"]["bodies"] == []
    assert data["outputs"]["counter.count"][-1] == [3, 3]      # three ticks counted


def test_the_header_names_seed_overrides_and_drawn_randomization(tmp_path):
    counter = PICK_PLACE.parent / "counter_branch_print.json"
    randomization = tmp_path / "random.json"
    randomization.write_text(json.dumps({"randomize": [{"set": "at_least_three.b", "choice": [5, 6]}]}))
    report = tmp_path / "r.html"
    result = graphflow("run", str(counter), "--seed", "7", "--set", "format_count.format=n = {value}",
                       "--randomize", str(randomization), "--report", str(report))
    assert result.returncode in (0, 1), result.stderr
    header = embedded(report)["header"]
    assert header["seed"] == 7
    assert header["overrides"] == ["format_count.format=n = {value}"]
    assert header["randomization"] in ({"at_least_three.b": 5}, {"at_least_three.b": 6})


def test_a_run_time_failure_is_in_the_report_and_leaves_other_checks_unjudged(tmp_path):
    graph = tmp_path / "fails.json"
    graph.write_text(json.dumps({
        "format": "graphflow", "formatVersion": [1, 0], "settings": {"timeStep": 0.5, "duration": 3.0},
        "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"},
                  {"name": "never", "type": "graphflow.Assert", "inputs": {"condition": False, "message": "it must hold"}}],
        "connections": [{"src": "tick.outputs:tick", "dst": "never.inputs:execIn"}],
        "checks": [{"check": "stopsBy", "time": 2.0}]}))
    report = tmp_path / "fails.html"
    result = graphflow("run", str(graph), "--report", str(report))
    assert result.returncode == 1
    stops_by, failure = embedded(report)["checks"]
    assert stops_by["passed"] is None                      # the run never reached its end: not judged
    assert failure["passed"] is False and "never" in failure["measured"] and "it must hold" in failure["measured"]
