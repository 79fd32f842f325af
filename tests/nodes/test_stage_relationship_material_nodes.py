"""WritePrimRelationship, AddPrimRelationship, ReadPrimMaterial and WritePrimMaterial on a stage written here.

Run on the PyBullet world built from it: what the nodes write, the reading nodes (ReadPrimRelationship,
GetPrimRelationship, ReadPrimAttribute, ReadPrim) see at once; physics relationships and physics materials
are refused with the node's one line; a reset brings back the file's targets and bindings.
"""
import pytest
from pxr import Usd

from graphflow.executor import GraphRuntimeError
from graphflow.physics import create_world
from graphflow.testing import NodeHarness

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
    }
    def Scope "Looks"
    {
        def Material "Red"
        {
        }
        def Material "Blue"
        {
        }
        def Material "Rubber" (
            prepend apiSchemas = ["PhysicsMaterialAPI"]
        )
        {
            float physics:dynamicFriction = 1.2
        }
    }
    def Cube "Box" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "MaterialBindingAPI"]
        variants = {
            string look = "plain"
        }
        prepend variantSets = "look"
    )
    {
        double size = 0.2
        double3 xformOp:translate = (0, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
        rel material:binding = </World/Looks/Red>
        rel custom:targets = [</World/Looks/Red>, </World/Looks/Blue>]
        variantSet "look" = {
            "plain" {
                float custom:glow = 0
            }
            "shiny" {
                float custom:glow = 4
            }
        }
        def Cube "Decal" (
            prepend apiSchemas = ["MaterialBindingAPI"]
        )
        {
            double size = 0.05
            rel material:binding:preview = </World/Looks/Blue>
        }
    }
    def Cube "Anchor" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
    )
    {
        double size = 0.2
        double3 xformOp:translate = (1, 0, 1)
        uniform token[] xformOpOrder = ["xformOp:translate"]
    }
    def PhysicsFixedJoint "Weld"
    {
        rel physics:body0 = </World/Anchor>
    }
}
'''
BOX = "/World/Box"


@pytest.fixture
def world():
    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString(STAGE)
    with create_world(stage) as built:
        yield built


def run(type_id, world, pulse=None, **inputs):
    harness = NodeHarness(type_id, inputs, world=world)
    return (harness.compute(pulse) if pulse else harness.compute()).outputs


def targets(world, prim, name):
    return run("omni.graph.nodes.ReadPrimRelationship", world, prim=[prim], name=name)["value"]


def test_write_prim_relationship_replaces_the_targets_and_every_reader_sees_them(world):
    assert targets(world, BOX, "custom:targets") == ("/World/Looks/Red", "/World/Looks/Blue")
    run("omni.graph.nodes.WritePrimRelationship", world, "execIn", prim=[BOX], name="custom:targets",
        value=["/World/Anchor"])
    assert targets(world, BOX, "custom:targets") == ("/World/Anchor",)
    assert run("omni.graph.nodes.GetPrimRelationship", world, path=BOX, name="custom:targets")["paths"] == \
        ("/World/Anchor",)
    run("omni.graph.nodes.WritePrimRelationship", world, "execIn", prim=[BOX], name="custom:new", value=[BOX])
    assert targets(world, BOX, "custom:new") == (BOX,)                  # created where missing
    world.reset()
    assert targets(world, BOX, "custom:targets") == ("/World/Looks/Red", "/World/Looks/Blue")
    with pytest.raises(GraphRuntimeError, match="has no relationship 'custom:new'"):
        targets(world, BOX, "custom:new")


def test_add_prim_relationship_appends_once_and_creates_the_relationship(world):
    add = dict(path=BOX, name="custom:targets", target="/World/Anchor")
    assert run("omni.graph.action.AddPrimRelationship", world, "execIn", **add)["isSuccessful"] is True
    assert run("omni.graph.action.AddPrimRelationship", world, "execIn", **add)["isSuccessful"] is True
    assert targets(world, BOX, "custom:targets") == ("/World/Looks/Red", "/World/Looks/Blue", "/World/Anchor")
    run("omni.graph.action.AddPrimRelationship", world, "execIn", path=BOX, name="custom:fresh", target=BOX)
    assert targets(world, BOX, "custom:fresh") == (BOX,)
    harness = NodeHarness("omni.graph.action.AddPrimRelationship", {"path": BOX, "name": ""}, world=world)
    assert harness.compute("execIn").outputs["isSuccessful"] is False
    assert any("inputs:name is empty" in line for line in harness.logs)


@pytest.mark.parametrize("type_id, inputs, why", [
    ("omni.graph.nodes.WritePrimRelationship", {"prim": ["/World/Weld"], "name": "physics:body1", "value": [BOX]},
     "/World/Weld.physics:body1 would appear"),
    ("omni.graph.action.AddPrimRelationship", {"path": BOX, "name": "physics:filteredPairs", "target": "/World/Anchor"},
     "filteredPairs"),
    ("omni.graph.nodes.WritePrimMaterial", {"prim": [BOX], "material": ["/World/Looks/Rubber"]}, "materials"),
])
def test_edits_of_what_is_simulated_fail_the_run_naming_the_node_and_prim(world, type_id, inputs, why):
    with pytest.raises(GraphRuntimeError, match=rf"^node 'node': /World/\w+: .* would change what is simulated "
                                                rf"\(.*{why}"):
        run(type_id, world, "execIn", **inputs)
    assert targets(world, "/World/Weld", "physics:body0") == ("/World/Anchor",)
    assert run("omni.graph.nodes.ReadPrimMaterial", world, prim=[BOX])["material"] == "/World/Looks/Red"


def test_read_prim_material_is_the_direct_binding_and_write_prim_material_binds_a_visual_one(world):
    read = run("omni.graph.nodes.ReadPrimMaterial", world, prim=[BOX])
    assert read == {"material": "/World/Looks/Red", "materialPrim": ("/World/Looks/Red",)}
    assert run("omni.graph.nodes.ReadPrimMaterial", world, primPath=BOX)["material"] == "/World/Looks/Red"
    # the decal has only a preview-purpose binding (and inherits none directly): no direct binding
    assert run("omni.graph.nodes.ReadPrimMaterial", world, prim=[f"{BOX}/Decal"]) == {"material": "",
                                                                                     "materialPrim": ()}
    run("omni.graph.nodes.WritePrimMaterial", world, "execIn", prim=[f"{BOX}/Decal"], materialPath="/World/Looks/Red")
    run("omni.graph.nodes.WritePrimMaterial", world, "execIn", primPath=BOX, material=["/World/Looks/Blue"])
    assert run("omni.graph.nodes.ReadPrimMaterial", world, prim=[f"{BOX}/Decal"])["material"] == "/World/Looks/Red"
    assert run("omni.graph.nodes.ReadPrimMaterial", world, prim=[BOX])["material"] == "/World/Looks/Blue"
    with pytest.raises(GraphRuntimeError, match="/World/Anchor is not a Material prim"):
        run("omni.graph.nodes.WritePrimMaterial", world, "execIn", prim=[BOX], material=["/World/Anchor"])
    world.reset()
    assert run("omni.graph.nodes.ReadPrimMaterial", world, prim=[BOX])["material"] == "/World/Looks/Red"


def test_attribute_and_bundle_readers_see_a_variant_switch(world):
    def glow():
        return run("omni.graph.nodes.ReadPrimAttribute", world, prim=[BOX], name="custom:glow")["value"]

    def bundled_glow():
        bundle = run("omni.graph.nodes.ReadPrim", world, prim=[BOX], attrNamesToImport="custom:glow")["primBundle"]
        return bundle.get("custom:glow").value

    assert glow() == 0.0 and bundled_glow() == 0.0
    run("omni.graph.nodes.SetVariantSelection", world, "execIn", prim=[BOX], variantSetName="look",
        variantName="shiny", setVariant=True)
    assert glow() == 4.0 and bundled_glow() == 4.0
    world.reset()
    assert glow() == 0.0 and bundled_glow() == 0.0
