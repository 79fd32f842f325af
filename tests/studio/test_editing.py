"""Opening, checking and saving graphs through the studio's HTTP API, judged by graphflow validate on the saved file."""
import json
import subprocess
import sys

from graphflow.document import dumps, load_document


def validate(path):
    return subprocess.run([sys.executable, "-m", "graphflow", "validate", str(path)], capture_output=True, text=True)


def test_the_palette_lists_every_registered_node_type_with_its_ports(studio):
    from graphflow.registry import default_registry

    status, palette = studio.request("GET", "/api/palette")
    assert status == 200
    assert {entry["id"] for entry in palette["types"]} == {t.spec.id for t in default_registry().types()}
    compare = next(entry for entry in palette["types"] if entry["id"] == "omni.graph.nodes.Compare")
    operation = next(port for port in compare["inputs"] if port["name"] == "operation")
    assert operation["tokens"] == [">", "<", ">=", "<=", "==", "!="]
    assert "execution" in palette["connects"]["execution"] and "double" not in palette["connects"]["execution"]
    assert "double" in palette["connects"]["int"] and "bool" not in palette["connects"]["double"]


def test_opening_a_graph_gives_its_text_revision_and_no_problems(studio, studio_folder):
    status, opened = studio.request("GET", "/api/graph?path=counter.json")
    assert status == 200 and opened["problems"] == []
    assert opened["text"] == (studio_folder / "counter.json").read_text()
    assert [node["name"] for node in opened["data"]["nodes"]][:2] == ["on_tick", "counter"]


def test_a_bad_connection_is_a_problem_on_the_node_and_port_it_names(studio):
    _, opened = studio.request("GET", "/api/graph?path=counter.json")
    data = opened["data"]
    data["connections"].append({"src": "on_tick.outputs:tick", "dst": "format_count.inputs:value"})
    status, checked = studio.request("POST", "/api/check", {"path": "counter.json", "data": data})
    assert status == 200 and len(checked["problems"]) == 1
    problem = checked["problems"][0]
    assert problem["node"] == "format_count" and problem["attribute"] == "inputs:value", problem


def test_saving_an_edit_writes_canonical_json_that_validates(studio, studio_folder):
    _, opened = studio.request("GET", "/api/graph?path=counter.json")
    data = opened["data"]
    data["nodes"].append({"name": "twice", "type": "omni.graph.nodes.Multiply"})
    data["connections"].append({"src": "counter.outputs:count", "dst": "twice.inputs:a"})
    data["nodes"][-1]["inputs"] = {"b": 2}
    status, saved = studio.request("POST", "/api/save", {"path": "counter.json", "data": data, "revision": opened["revision"]})
    assert status == 200 and saved["status"] == "saved" and saved["problems"] == [], saved
    path = studio_folder / "counter.json"
    assert validate(path).returncode == 0, validate(path).stdout
    assert path.read_text() == dumps(load_document(path))   # load -> save -> load is byte-identical
    assert [n["name"] for n in json.loads(path.read_text())["nodes"]][-1] == "twice"   # the file's node order kept


def test_a_file_changed_on_disk_since_it_was_opened_is_not_overwritten(studio, studio_folder):
    path = studio_folder / "counter.json"
    _, first = studio.request("GET", "/api/graph?path=counter.json")
    _, second = studio.request("GET", "/api/graph?path=counter.json")
    first["data"]["description"] = "edited in the first tab"
    assert studio.request("POST", "/api/save", {"path": "counter.json", "data": first["data"],
                                                 "revision": first["revision"]})[0] == 200
    second["data"]["description"] = "edited in the second tab"
    status, refused = studio.request("POST", "/api/save", {"path": "counter.json", "data": second["data"],
                                                           "revision": second["revision"]})
    assert status == 409 and refused["status"] == "conflict"
    assert "-  \"description\": \"edited in the first tab\"" in refused["difference"]
    assert "+  \"description\": \"edited in the second tab\"" in refused["difference"]
    assert "first tab" in path.read_text()


def test_an_invalid_graph_never_replaces_a_valid_file_without_an_explicit_choice(studio, studio_folder):
    path = studio_folder / "counter.json"
    before = path.read_text()
    _, opened = studio.request("GET", "/api/graph?path=counter.json")
    opened["data"]["connections"].append({"src": "counter.outputs:count", "dst": "nowhere.inputs:x"})
    request = {"path": "counter.json", "data": opened["data"], "revision": opened["revision"]}
    status, refused = studio.request("POST", "/api/save", request)
    assert status == 409 and refused["status"] == "invalid-over-valid" and refused["problems"]
    assert path.read_text() == before
    status, draft = studio.request("POST", "/api/save", {**request, "path": "counter.draft.json", "revision": None})
    assert status == 200 and validate(studio_folder / "counter.draft.json").returncode == 2
    status, replaced = studio.request("POST", "/api/save", {**request, "replaceValid": True})
    assert status == 200 and replaced["status"] == "saved" and "nowhere" in path.read_text()


def test_the_watched_revision_changes_with_the_graph_and_with_a_layer_its_stage_composes(studio, studio_folder):
    """The page's watch polls this; the files are graphflow.watching's, as for `graphflow run --watch`."""
    (studio_folder / "base.usda").write_text('#usda 1.0\n\ndef Xform "World"\n{\n}\n')
    (studio_folder / "scene.usda").write_text('#usda 1.0\n(\n    subLayers = [@./base.usda@]\n)\n')
    graph = studio_folder / "staged.json"
    data = json.loads((studio_folder / "counter.json").read_text())
    data["settings"]["stage"] = "scene.usda"
    graph.write_text(json.dumps(data))

    def seen():
        status, body = studio.request("GET", "/api/revision?path=staged.json")
        assert status == 200
        return body

    first = seen()
    assert first == seen() and first["stage"] is not None
    (studio_folder / "base.usda").write_text('#usda 1.0\n\ndef Xform "World"\n{\n}\n\ndef Xform "More"\n{\n}\n')
    second = seen()
    assert second["revision"] == first["revision"] and second["stage"] != first["stage"]
    graph.write_text(json.dumps(data, indent=1))
    third = seen()
    assert third["revision"] != second["revision"] and third["stage"] == second["stage"]
