"""The codeless IsaacSurfaceGripper / IsaacAttachmentPointAPI schema plugin."""
import json
from pathlib import Path

import pytest
from conftest import ISAAC_GANTRY

from graphflow.gripper import usd_schema
from graphflow.gripper.usd_schema import (
    apply_attachment_point_api,
    create_surface_gripper,
    define_surface_gripper,
    read_forward_axis,
    register_schema,
)


@pytest.fixture
def stage():
    register_schema()
    from pxr import Usd

    return Usd.Stage.CreateInMemory()


def test_plugin_files_ship_inside_the_package():
    directory = Path(usd_schema.SCHEMA_DIRECTORY)
    info = json.loads((directory / "plugInfo.json").read_text())
    types = info["Plugins"][0]["Info"]["Types"]
    assert {t["alias"]["UsdSchemaBase"] for t in types.values()} == {"IsaacSurfaceGripper", "IsaacAttachmentPointAPI"}
    assert (directory / "generatedSchema.usda").is_file()


def test_surface_gripper_is_a_typed_schema_with_isaacs_names_and_fallbacks(stage):
    from pxr import Usd

    prim = define_surface_gripper(stage, "/World/SurfaceGripper")
    assert prim.IsA(Usd.SchemaRegistry.GetTypeFromName("IsaacSurfaceGripper"))
    assert prim.GetTypeName() == "IsaacSurfaceGripper"
    values = {name: prim.GetAttribute(name).Get() for name in (
        "isaac:maxGripDistance", "isaac:retryInterval", "isaac:shearForceLimit", "isaac:coaxialForceLimit",
        "isaac:status")}
    assert values == {"isaac:maxGripDistance": pytest.approx(0.01), "isaac:retryInterval": 0.0,
                      "isaac:shearForceLimit": -1.0, "isaac:coaxialForceLimit": -1.0, "isaac:status": "Open"}
    for name in values:
        attribute = prim.GetAttribute(name)
        assert not attribute.IsCustom() and not attribute.HasAuthoredValue()   # created, never set, as Isaac
    from pxr import Sdf

    assert prim.GetAttribute("isaac:status").GetVariability() == Sdf.VariabilityUniform
    assert prim.GetRelationship("isaac:attachmentPoints") and prim.GetRelationship("isaac:grippedObjects")


def test_attachment_point_api_applies_with_fallbacks(stage):
    joint = stage.DefinePrim("/World/Joint", "PhysicsJoint")
    apply_attachment_point_api(joint)
    assert joint.HasAPI("IsaacAttachmentPointAPI")
    assert joint.GetAttribute("isaac:forwardAxis").Get() == "X"
    assert joint.GetAttribute("isaac:clearanceOffset").Get() == 0.0
    apply_attachment_point_api(joint, forward_axis="Z", clearance_offset=0.008)
    assert joint.GetAttribute("isaac:forwardAxis").Get() == "Z"
    assert joint.GetAttribute("isaac:clearanceOffset").Get() == pytest.approx(0.008)
    assert list(joint.GetAppliedSchemas()).count("IsaacAttachmentPointAPI") == 1


@pytest.mark.parametrize("token, axis", [("X", "X"), ("y", "Y"), ("Zed", "Z"), ("", "X"), ("Q", "X")])
def test_forward_axis_reads_the_first_character(stage, token, axis):
    from pxr import Sdf

    joint = stage.DefinePrim("/World/Joint", "PhysicsJoint")
    joint.CreateAttribute("isaac:forwardAxis", Sdf.ValueTypeNames.Token).Set(token)
    assert read_forward_axis(joint) == axis


def test_create_surface_gripper_picks_the_next_free_name(stage):
    stage.DefinePrim("/World", "Xform")
    names = [create_surface_gripper(stage, "/World").GetPath().pathString for _ in range(3)]
    assert names == ["/World/SurfaceGripper", "/World/SurfaceGripper_01", "/World/SurfaceGripper_02"]


def test_isaac_files_load_with_the_schema():
    from pxr import Usd

    gantry = ISAAC_GANTRY
    if not gantry.is_file():
        pytest.skip(f"{gantry} is not available")
    register_schema()
    stage = Usd.Stage.Open(str(gantry))
    joint = stage.GetPrimAtPath("/World/Surface_Gripper_Joints/D6Joint")
    assert joint.HasAPI("IsaacAttachmentPointAPI")
    assert read_forward_axis(joint) == "Z"
    assert joint.GetAttribute("isaac:clearanceOffset").Get() == pytest.approx(0.008)
