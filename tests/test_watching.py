"""What a watch sees: the files a run reads (stage layers composed, scripted inputs), and one change per edit."""
import json
import os

import pytest
from polls import Script

from graphflow.watching import Watcher, graph_files, paths_files


def write_stage(folder):
    """scene.usda sublayers base.usda and references props/box.usda (which payloads props/detail.usda); a URL is skipped."""
    (folder / "props").mkdir()
    (folder / "props" / "detail.usda").write_text('#usda 1.0\n\ndef Xform "Detail"\n{\n}\n')
    (folder / "props" / "box.usda").write_text('#usda 1.0\n\ndef Xform "Box" (\n    payload = @./detail.usda@\n)\n{\n}\n')
    (folder / "base.usda").write_text('#usda 1.0\n\ndef Xform "World"\n{\n}\n')
    (folder / "scene.usda").write_text('#usda 1.0\n(\n    subLayers = [@./base.usda@, @https://example.com/far.usd@]\n)\n\n'
                                       'def Xform "Box" (\n    references = @props/box.usda@\n)\n{\n}\n')


def test_a_graph_reads_its_stage_every_local_layer_the_stage_composes_and_its_scripted_inputs(tmp_path):
    write_stage(tmp_path)
    graph = tmp_path / "g.json"
    graph.write_text(json.dumps({"settings": {"stage": "scene.usda"}, "scenario": {"keys": "g.keys.json", "seed": 3}}))
    found = {path.resolve().relative_to(tmp_path.resolve()).as_posix() for path in graph_files(graph)}
    assert found == {"g.json", "scene.usda", "base.usda", "props/box.usda", "props/detail.usda", "g.keys.json"}


def test_a_table_reads_its_graph_and_its_cases_input_files_and_a_half_edited_file_is_watched_alone(tmp_path):
    (tmp_path / "g.json").write_text(json.dumps({"settings": {"stage": "asset:ur10.usda"}}))   # packaged: not watched
    table = tmp_path / "t.json"
    table.write_text(json.dumps({"format": "graphflow-cases", "graph": "g.json", "cases": [{"name": "a", "gamepad": "a.pad.json"}]}))
    assert [path.name for path in graph_files(table)] == ["t.json", "a.pad.json", "g.json"]
    table.write_text('{"format": "graphflow-cases", "graph": ')
    assert graph_files(table) == [table]
    (tmp_path / "trace.jsonl").write_text("{}\n")   # what runs write is not watched in a folder
    assert paths_files([tmp_path]) == [tmp_path, tmp_path / "g.json", tmp_path / "t.json"]   # the folder: files added


def test_one_edit_is_one_change_once_the_file_settles_and_a_new_sublayer_is_watched_from_then_on(tmp_path):
    write_stage(tmp_path)
    graph = tmp_path / "g.json"
    graph.write_text(json.dumps({"settings": {"stage": "scene.usda"}}))
    extra = tmp_path / "extra.usda"
    extra.write_text('#usda 1.0\n')
    scene = tmp_path / "scene.usda"
    steps = Script(None, lambda: graph.write_text(json.dumps({"settings": {"stage": "scene.usda"}, "x": 1})),
                   lambda: graph.write_text(json.dumps({"settings": {"stage": "scene.usda"}, "x": 12})),   # still saving
                   None,
                   lambda: scene.write_text(scene.read_text().replace("@./base.usda@", "@./base.usda@, @./extra.usda@")),
                   None,
                   lambda: extra.write_text('#usda 1.0\n\ndef Xform "More"\n{\n}\n'),
                   None)
    watcher = Watcher(lambda: graph_files(graph), sleep=steps)
    assert watcher.wait() == [str(graph)]
    assert steps.polls == 4   # quiet, edited, edited again, settled
    assert watcher.wait() == [str(scene.resolve())]
    assert watcher.wait() == [str(extra.resolve())]
    with pytest.raises(KeyboardInterrupt):
        watcher.wait()   # nothing else changed: no spurious change before Ctrl-C


def test_a_file_that_goes_away_is_a_change(tmp_path):
    graph = tmp_path / "g.json"
    graph.write_text(json.dumps({"scenario": {"topics": "g.topics.json"}}))
    topics = tmp_path / "g.topics.json"
    topics.write_text('{"topics": []}')
    watcher = Watcher(lambda: graph_files(graph), sleep=Script(lambda: os.remove(topics), None))
    assert watcher.wait() == [str(topics)]
