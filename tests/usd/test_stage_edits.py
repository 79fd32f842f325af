"""Run-time stage edits through the world: seen by reads, dropped by reset, never in the file, refused on physics.

The stage below is written here: a falling box with a visual variant set (look), variant sets that would
change its collider (size), its placement (place) or add a body (extras), a lid hinged to it, and two
materials, one visual and one with physics properties. The values checked are the ones written in it.
"""
import pytest
from pxr import Usd

from graphflow.physics import create_world
from graphflow.testing.fake_world import FakeWorld
from graphflow.world import ClockWorld, WorldError

STAGE = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def PhysicsScene "Scene"
    {
        vector3f physics:gravityDirection = (0, 0, -1)
        float physics:gravityMagnitude = 9.81
    }
    def Scope "Looks"
    {
        def Material "Red"
        {
        }
        def Material "Ice" (
            prepend apiSchemas = ["PhysicsMaterialAPI"]
        )
        {
            float physics:dynamicFriction = 0.02
            float physics:staticFriction = 0.02
        }
    }
    def Cube "Box" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
        variants = {
            string extras = "none"
            string look = "plain"
            string place = "home"
            string size = "small"
        }
        prepend variantSets = ["look", "size", "place", "extras"]
    )
    {
        uniform token[] xformOpOrder = ["xformOp:translate"]
        rel custom:owner = </World/Looks>
        variantSet "look" = {
            "plain" {
                float custom:glow = 0
                color3f primvars:tint = (0.5, 0.5, 0.5)
            }
            "shiny" {
                float custom:glow = 4
                color3f primvars:tint = (1, 0, 0)
            }
        }
        variantSet "size" = {
            "small" {
                double size = 0.5
            }
            "big" {
                double size = 2
            }
        }
        variantSet "place" = {
            "home" {
                double3 xformOp:translate = (0, 0, 2)
            }
            "shelf" {
                double3 xformOp:translate = (1, 0, 2)
            }
        }
        variantSet "extras" = {
            "none" {
            }
            "ball" {
                def Sphere "Ball" (
                    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
                )
                {
                    double radius = 0.1
                }
            }
        }
    }
    def Cube "Lid" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "MaterialBindingAPI"]
    )
    {
        double size = 0.2
        double3 xformOp:translate = (0, 0, 2.5)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        rel material:binding = </World/Looks/Red>
    }
    def PhysicsRevoluteJoint "Hinge"
    {
        uniform token physics:axis = "Y"
        rel physics:body0 = </World/Box>
        rel physics:body1 = </World/Lid>
        point3f physics:localPos0 = (0, 0, 0.5)
        point3f physics:localPos1 = (0, 0, 0)
    }
}
'''
BOX = "/World/Box"


@pytest.fixture
def stage_file(tmp_path):
    path = tmp_path / "box.usda"
    path.write_text(STAGE)
    return path


def test_a_visual_variant_switch_is_read_back_dropped_by_reset_and_never_written_to_the_file(stage_file):
    with create_world(str(stage_file)) as world:
        assert world.variant_sets(BOX) == ("look", "size", "place", "extras")      # in authored order
        assert world.variant_names(BOX, "look") == ("plain", "shiny")
        world.set_variant_selection(BOX, "look", "shiny")
        assert world.variant_selection(BOX, "look") == "shiny"
        assert world.get_attribute(BOX, "custom:glow") == 4.0              # the shiny variant's value
        bundle = world.read_prim(BOX)
        assert bundle.get("primvars:tint").value == pytest.approx((1.0, 0.0, 0.0))
        assert not world.stage.GetRootLayer().dirty
        world.reset()
        assert world.variant_selection(BOX, "look") == "plain"
        assert world.get_attribute(BOX, "custom:glow") == 0.0
        assert world.read_prim(BOX).get("primvars:tint").value == pytest.approx((0.5, 0.5, 0.5))
    assert stage_file.read_text() == STAGE


def test_a_visual_edit_leaves_the_simulation_bit_for_bit_as_it_was(stage_file):
    def fall(edit: bool):
        with create_world(str(stage_file)) as world:
            if edit:
                world.set_variant_selection(BOX, "look", "shiny")
                world.set_relationship_targets(BOX, "custom:owner", ["/World/Lid"])
                world.bind_material(BOX, "/World/Looks/Red")
            poses = []
            for _ in range(30):
                world.step()
                poses.append(world.prim_pose(BOX))
            return poses

    edited, plain = fall(True), fall(False)
    assert edited == plain
    assert plain[-1][0][2] < 2.0 - 0.5 * 9.81 * 0.25 ** 2       # it fell: at least most of g t^2 / 2 after 0.5 s


@pytest.mark.parametrize("edit, why", [
    (lambda w: w.set_variant_selection(BOX, "size", "big"), "CubeShape /World/Box halfExtents"),
    (lambda w: w.set_variant_selection(BOX, "place", "shelf"), "RigidBody /World/Box position"),
    (lambda w: w.set_variant_selection(BOX, "extras", "ball"), "/World/Box/Ball .* would appear"),
    (lambda w: w.set_relationship_targets("/World/Hinge", "physics:body1", ["/World/Box"]), "body1"),
    (lambda w: w.set_relationship_targets(BOX, "physics:filteredPairs", ["/World/Lid"]), "filteredPairs"),
    (lambda w: w.bind_material("/World/Lid", "/World/Looks/Ice"), "materials"),
    (lambda w: w.write_stage_values("/World/Hinge", {"/World/Hinge.physics:localPos0": (0.0, 0.0, 0.6)}),
     "physics:localPos0 would change"),
])
def test_an_edit_that_would_change_the_physics_is_refused_naming_the_prim_and_rolled_back(stage_file, edit, why):
    with create_world(str(stage_file)) as world:
        before = world.stage.ExportToString()
        world.set_variant_selection(BOX, "look", "shiny")               # an accepted edit stays through a refusal
        with pytest.raises(WorldError, match=rf"^/World/\w+: .*would change what is simulated \(.*{why}"):
            edit(world)
        assert world.variant_selection(BOX, "size") == "small" and world.variant_selection(BOX, "place") == "home"
        assert world.variant_selection(BOX, "extras") == "none" and world.variant_selection(BOX, "look") == "shiny"
        assert world.relationship_targets("/World/Hinge", "physics:body1") == ("/World/Lid",)
        assert world.bound_material("/World/Lid") == "/World/Looks/Red"
        assert world.stage.GetAttributeAtPath("/World/Hinge.physics:localPos0").Get() == (0.0, 0.0, 0.5)
        world.step()                                                      # the run goes on with the file's physics
        world.reset()
        assert world.stage.ExportToString() == before                 # the composed stage is the file's again


def test_a_new_world_on_a_stage_whose_session_layer_a_sweep_cleared_starts_from_the_file(stage_file):
    stage = Usd.Stage.Open(str(stage_file))
    with create_world(stage) as first:
        first.set_variant_selection(BOX, "look", "shiny")
    stage.GetSessionLayer().Clear()                     # what a sweep does before the next episode's world
    with create_world(stage) as second:
        assert second.variant_selection(BOX, "look") == "plain"
        second.set_variant_selection(BOX, "look", "shiny")
        assert second.get_attribute(BOX, "custom:glow") == 4.0


def test_closing_a_world_drops_its_edits_from_a_stage_that_outlives_it(stage_file):
    stage = Usd.Stage.Open(str(stage_file))
    with create_world(stage) as world:
        world.set_variant_selection(BOX, "look", "shiny")
    assert stage.GetPrimAtPath(BOX).GetVariantSets().GetVariantSelection("look") == "plain"


def test_a_stronger_session_layer_opinion_is_reported_not_silently_kept(stage_file):
    stage = Usd.Stage.Open(str(stage_file))
    with Usd.EditContext(stage, stage.GetSessionLayer()):             # a sweep override of the selection
        stage.GetPrimAtPath(BOX).GetVariantSets().GetVariantSet("look").SetVariantSelection("plain")
    with create_world(stage) as world:
        with pytest.raises(WorldError, match="a stronger opinion on the session layer keeps variant set 'look'"):
            world.set_variant_selection(BOX, "look", "shiny")
        assert world.variant_selection(BOX, "look") == "plain"


def test_the_fake_world_edits_its_stage_and_a_world_without_a_stage_refuses():
    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString(STAGE)
    world = FakeWorld(stage=stage)
    world.set_relationship_targets(BOX, "custom:owner", ["/World/Lid", "/World/Hinge"])
    assert world.relationship_targets(BOX, "custom:owner") == ("/World/Lid", "/World/Hinge")
    world.reset()
    assert world.relationship_targets(BOX, "custom:owner") == ("/World/Looks",)
    with pytest.raises(WorldError, match="names no stage"):
        ClockWorld().set_variant_selection(BOX, "look", "shiny")


def test_an_edit_usd_refuses_is_one_line_naming_the_prim():
    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString('''#usda 1.0
def Xform "Proto"
{
    def Cube "Part"
    {
    }
}
def Xform "Instance" (
    instanceable = true
    references = </Proto>
)
{
}
''')
    world = FakeWorld(stage=stage)
    with pytest.raises(WorldError, match=r"^/Instance/Part: setting relationship custom:r to \['/Proto'\] was refused "
                                         r"by USD: Cannot create property spec at path </Instance/Part>; authoring to "
                                         r"an instance proxy is not allowed.$"):
        world.set_relationship_targets("/Instance/Part", "custom:r", ["/Proto"])


def test_on_the_packaged_ur10_cell_only_the_edit_that_touches_a_drive_is_refused():
    """The parser's joint drives and limits compare by content: a custom edit at the root passes."""
    joint = "/World/ur10/ee_link/attachment_joint"
    with create_world("asset:ur10_pick_place.usda") as world:
        world.set_relationship_targets("/World", "custom:tags", ["/World/ur10"])
        assert world.relationship_targets("/World", "custom:tags") == ("/World/ur10",)
        with pytest.raises(WorldError, match=rf"^{joint}: .*\({joint}.drive:transX:physics:stiffness would change "
                                             "from 1000.0 to 5.0\\)"):
            world.write_stage_values(joint, {f"{joint}.drive:transX:physics:stiffness": 5.0})


def test_a_variant_set_a_reference_brings_is_read_at_the_referencing_path(tmp_path):
    (tmp_path / "lamp.usda").write_text('''#usda 1.0
(
    defaultPrim = "Lamp"
)
def Xform "Lamp" (
    variants = {
        string power = "low"
    }
    prepend variantSets = "power"
)
{
    variantSet "power" = {
        "low" {
            float custom:watts = 5
        }
        "high" {
            def Xform "Bulb"
            {
                float custom:watts = 60
            }
        }
    }
}
''')
    (tmp_path / "room.usda").write_text('''#usda 1.0
def Xform "Room"
{
    def "Lamp" (
        prepend references = @./lamp.usda@
    )
    {
    }
}
''')
    world = FakeWorld(stage=Usd.Stage.Open(str(tmp_path / "room.usda")))
    values = world.variant_values("/Room/Lamp", "power", "high")
    assert values == {"/Room/Lamp/Bulb.custom:watts": ("float", 60.0)}
    with pytest.raises(WorldError, match="/Room/Lamp/Bulb.custom:watts is on a prim this stage does not have now"):
        world.write_stage_values("/Room/Lamp", values)      # the bulb exists only in 'high'
    world.set_variant_selection("/Room/Lamp", "power", "high")
    world.write_stage_values("/Room/Lamp", {"/Room/Lamp/Bulb.custom:watts": 75.0})
    assert world.stage.GetAttributeAtPath("/Room/Lamp/Bulb.custom:watts").Get() == 75.0
    world.reset()
    assert not world.stage.GetPrimAtPath("/Room/Lamp/Bulb")
    assert (tmp_path / "lamp.usda").read_text().count("60") == 1             # the referenced file is untouched
