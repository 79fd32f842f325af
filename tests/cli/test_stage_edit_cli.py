"""graphflow run with stage-editing nodes on the packaged UR10 cell: a visual edit runs, a physics one exits 1."""
import json

from graphflow import cli

STAGE = "asset:ur10_pick_place.usda"


def run(tmp_path, capsys, node):
    data = {"format": "graphflow", "formatVersion": [1, 0], "settings": {"stage": STAGE},
            "nodes": [{"name": "tick", "type": "omni.graph.action.OnTick"}, node],
            "connections": [{"src": "tick.outputs:tick", "dst": f"{node['name']}.inputs:execIn"}]}
    path = tmp_path / "edit.json"
    path.write_text(json.dumps(data))
    code = cli.main(["run", str(path), "--ticks", "3"])
    out, err = capsys.readouterr()
    return path, code, out, err


def test_a_custom_relationship_edit_runs_and_a_joint_body_edit_fails_on_one_line(tmp_path, capsys):
    tag = {"name": "tag", "type": "omni.graph.action.AddPrimRelationship",
           "inputs": {"path": "/World/Cube", "name": "custom:seenBy", "target": "/World/ur10"}}
    _, code, _, err = run(tmp_path, capsys, tag)
    assert code == 0, err
    rewire = {"name": "rewire", "type": "omni.graph.nodes.WritePrimRelationship",
              "inputs": {"prim": ["/World/ur10/root_joint"], "name": "physics:body1", "value": ["/World/Cube"]}}
    path, code, out, err = run(tmp_path, capsys, rewire)
    lines = err.splitlines()
    assert (code, out, len(lines)) == (1, "", 2) and lines[1].startswith("graphflow: FAIL")
    assert lines[0].startswith(f"{path}: run-time failure: node 'rewire': /World/ur10/root_joint: setting relationship "
                               "physics:body1 to ['/World/Cube'] would change what is simulated (")
    assert "physics:body1 would change from [Sdf.Path('/World/ur10/base_link')] to [Sdf.Path('/World/Cube')]" in lines[0]
