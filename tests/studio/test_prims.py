"""The stage's prims for the target pickers, and the forms the variables, checks and settings editors draw from."""
import json

import pytest

from graphflow.document import json_schema
from graphflow.usd.resolver import asset_path

PICK_PLACE_STAGE = "asset:ur10_pick_place.usda"


def applied(stage_file, schema):
    """Prim paths with a UsdPhysics API applied, read by usd-core directly (the reference the listing must match)."""
    from pxr import Usd, UsdPhysics

    stage = Usd.Stage.Open(str(stage_file))
    api = {"rigid body": UsdPhysics.RigidBodyAPI, "articulation": UsdPhysics.ArticulationRootAPI}[schema]
    return {str(prim.GetPath()) for prim in stage.Traverse() if prim.HasAPI(api)}


def test_the_stage_prims_carry_the_kinds_their_physics_schemas_give_them(studio):
    status, listing = studio.request("GET", f"/api/prims?path=counter.json&stage={PICK_PLACE_STAGE}")
    assert status == 200, listing
    kinds = {prim["path"]: set(prim["kinds"]) for prim in listing["prims"]}
    stage_file = asset_path("ur10_pick_place.usda")
    for kind in ("rigid body", "articulation"):
        assert {path for path, found in kinds.items() if kind in found} == applied(stage_file, kind), kind
    assert {path for path, found in kinds.items() if "surface gripper" in found} == {"/World/ur10/ee_link/SurfaceGripper"}
    assert "static collider" in kinds["/World/GroundPlane"]


def test_a_stage_outside_the_served_folder_is_not_listed(studio, studio_folder, tmp_path_factory):
    outside = tmp_path_factory.mktemp("elsewhere") / "secret.usda"
    outside.write_text('#usda 1.0\ndef Xform "Secret" {}\n')
    for reference in (str(outside), "../" + outside.parent.name + "/secret.usda"):
        status, body = studio.request("GET", f"/api/prims?path=counter.json&stage={reference}")
        assert status == 400 and "outside the served folder" in body["error"], body
    inside = studio_folder / "mine.usda"
    inside.write_text('#usda 1.0\ndef Xform "Mine" {}\n')
    status, listing = studio.request("GET", "/api/prims?path=counter.json&stage=mine.usda")
    assert status == 200 and listing["prims"] == [{"path": "/Mine", "type": "Xform", "kinds": ["xform"]}]


def test_the_palette_says_which_kind_of_prim_a_target_input_names(studio):
    _, palette = studio.request("GET", "/api/palette")
    controller = next(t for t in palette["types"] if t["id"] == "graphflow.PickPlaceController")
    ports = {port["name"]: port.get("primKind") for port in controller["inputs"]}
    assert ports["robotPrim"] == "articulation" and ports["gripperPrim"] == "surface gripper"
    assert ports["pickingPosition"] is None


def test_the_editor_forms_are_the_graph_formats_own_schema(studio):
    _, forms = studio.request("GET", "/api/forms")
    schema = json_schema()["properties"]
    assert set(forms["checks"]) == set(schema["checks"]["items"]["properties"]["check"]["enum"])
    assert forms["settings"] == schema["settings"]["properties"]
    assert forms["seed"]["type"] == "integer"


@pytest.mark.parametrize("broken, where", [
    ({"variables": [{"name": "speed", "type": "doubel"}]}, ["variables", 0]),
    ({"settings": {"timeStep": -1}}, ["settings", "timeStep"]),
])
def test_a_problem_of_a_variable_or_setting_names_where_it_is(studio, broken, where):
    _, opened = studio.request("GET", "/api/graph?path=counter.json")
    data = {**opened["data"], **broken, "settings": {**opened["data"].get("settings", {}), **broken.get("settings", {})}}
    _, checked = studio.request("POST", "/api/check", {"path": "counter.json", "data": data})
    problem = checked["problems"][0]
    placed = problem["path"][:2] == where or (problem["kind"] == "variable" and problem["attribute"] == "speed")
    assert placed, json.dumps(checked)


def test_the_stages_offered_are_the_packaged_assets_and_the_folders_own(studio, studio_folder):
    (studio_folder / "scenes").mkdir()
    (studio_folder / "scenes" / "table.usda").write_text('#usda 1.0\ndef Xform "Table" {}\n')
    status, answer = studio.request("GET", "/api/stages?path=counter.json")
    assert status == 200
    assert "asset:ur10_pick_place.usda" in answer["stages"] and "scenes/table.usda" in answer["stages"]
    assert all(stage.startswith("asset:") or not stage.startswith(("/", "..")) for stage in answer["stages"])
