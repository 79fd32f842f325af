"""A sweep's episodes never see the stage edits an earlier episode made (one worker, the stage reused).

The graph reads the box's variant selection every tick: while it is the file's 'plain' it selects another
look, once it is not it stops the run. A fresh run therefore stops on its second tick (t = 2 x 0.5 s); an
episode that inherited an edit would stop on its first.
"""
import json

from graphflow.sweep.definition import load_sweep
from graphflow.sweep.episode import EpisodeRunner

STAGE = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def Cube "Box" (
        variants = {
            string look = "plain"
        }
        prepend variantSets = "look"
    )
    {
        variantSet "look" = {
            "plain" {
                float custom:glow = 0
            }
            "shiny" {
                float custom:glow = 4
            }
            "glossy" {
                float custom:glow = 2
            }
        }
    }
}
'''
GRAPH = {
    "format": "graphflow", "formatVersion": [1, 0],
    "settings": {"stage": "box.usda", "timeStep": 0.5, "duration": 5.0},
    "nodes": [
        {"name": "on_tick", "type": "omni.graph.action.OnTick"},
        {"name": "read", "type": "omni.graph.nodes.GetVariantSelection",
         "inputs": {"prim": ["/World/Box"], "variantSetName": "look"}},
        {"name": "is_plain", "type": "omni.graph.nodes.Compare", "inputs": {"b": "plain", "operation": "=="}},
        {"name": "branch", "type": "omni.graph.action.Branch"},
        {"name": "switch", "type": "omni.graph.nodes.SetVariantSelection",
         "inputs": {"prim": ["/World/Box"], "variantSetName": "look", "variantName": "shiny", "setVariant": True}},
        {"name": "stop", "type": "graphflow.StopRun"},
    ],
    "connections": [
        {"src": "on_tick.outputs:tick", "dst": "branch.inputs:execIn"},
        {"src": "read.outputs:variantName", "dst": "is_plain.inputs:a"},
        {"src": "is_plain.outputs:result", "dst": "branch.inputs:condition"},
        {"src": "branch.outputs:execTrue", "dst": "switch.inputs:execIn"},
        {"src": "branch.outputs:execFalse", "dst": "stop.inputs:execIn"},
    ],
}


def test_every_episode_starts_from_the_files_variant_selection(tmp_path):
    (tmp_path / "box.usda").write_text(STAGE)
    (tmp_path / "graph.json").write_text(json.dumps(GRAPH))
    (tmp_path / "sweep.json").write_text(json.dumps({
        "format": "graphflow-sweep", "formatVersion": [1, 0], "graph": "graph.json",
        "grid": {"switch.variantName": ["shiny", "glossy"]}, "seeds": 2,
        "metrics": [{"name": "time_to_finish", "timeToFinish": {}}]}))
    sweep = load_sweep(str(tmp_path / "sweep.json"))
    runner = EpisodeRunner(sweep)
    try:
        rows = [runner.run(episode) for episode in sweep.episodes()]     # same world reset, then a new one
    finally:
        runner.close()
    assert [row["metrics"]["time_to_finish"] for row in rows] == [1.0, 1.0, 1.0, 1.0]
    assert (tmp_path / "box.usda").read_text() == STAGE
