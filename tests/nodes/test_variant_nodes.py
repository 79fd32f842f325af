"""The variant nodes of omni.graph.nodes on a stage written here: read, select, write values, clear, blend.

Kit's semantics (its node library reference and sources): SetVariantSelection with setVariant selects the
variant; without it (the default) it writes the values the variant authors onto the prim and leaves the
selection; ClearVariantSelection blocks the selection or removes those written values; BlendVariants writes
(1 - blend) a + blend b for what both variants author, switching bool/int/token values at 0.5.
"""
import pytest
from pxr import Gf, Usd

from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness
from graphflow.testing.fake_world import FakeWorld

STAGE = '''#usda 1.0
(
    defaultPrim = "World"
    metersPerUnit = 1
    upAxis = "Z"
)
def Xform "World"
{
    def Material "Red"
    {
    }
    def Material "Chrome"
    {
    }
    def Cube "Box" (
        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI"]
        variants = {
            string look = "plain"
            string size = "small"
        }
        prepend variantSets = ["look", "size"]
    )
    {
        float custom:glow = 0.5
        variantSet "look" = {
            "plain" {
                rel material:binding = </World/Red>
                float custom:glow = 0
                token custom:finish = "matte"
                int custom:coats = 1
                color3f primvars:tint = (0.5, 0.5, 0.5)
                quatf custom:spin = (1, 0, 0, 0)
            }
            "shiny" {
                rel material:binding = </World/Chrome>
                float custom:glow = 4
                token custom:finish = "gloss"
                int custom:coats = 3
                color3f primvars:tint = (1, 0, 0)
                quatf custom:spin = (0, 0, 0, 1)
                string custom:label = "new"
            }
            "striped" {
                color3f[] primvars:displayColor = [(1, 1, 1), (0, 0, 0)]
            }
            "banded" {
                color3f[] primvars:displayColor = [(0, 0, 0), (1, 1, 1)]
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
    }
}
'''
BOX = ["/World/Box"]


@pytest.fixture
def world():
    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString(STAGE)
    return FakeWorld(stage=stage)


def outputs(type_id, world, pulse=None, **inputs):
    harness = NodeHarness(f"omni.graph.nodes.{type_id}", inputs, world=world)
    return (harness.compute(pulse) if pulse else harness.compute()).outputs


def value(world, name):
    """The composed value on the stage (None where nothing authors one)."""
    attribute = world.stage.GetAttributeAtPath(f"/World/Box.{name}")
    return attribute.Get() if attribute else None


def glow(world):
    return value(world, "custom:glow")


def test_the_readers_list_sets_variants_and_the_selection(world):
    assert outputs("GetVariantSetNames", world, prim=BOX)["variantSetNames"] == ("look", "size")
    assert outputs("GetVariantNames", world, prim=BOX, variantSetName="look")["variantNames"] == \
        ("banded", "plain", "shiny", "striped")         # USD lists them sorted
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="size")["variantName"] == "small"
    assert outputs("GetVariantSelection", world, usePath=True, primPath="/World/Box",
                   variantSetName="look")["variantName"] == "plain"
    assert outputs("HasVariantSet", world, prim=BOX, variantSetName="look")["exists"] is True
    assert outputs("HasVariantSet", world, prim=BOX, variantSetName="colour")["exists"] is False
    with pytest.raises(GraphRuntimeError, match="node 'node': /World/Box has no variant set 'colour'"):
        outputs("GetVariantNames", world, prim=BOX, variantSetName="colour")


def test_set_variant_selects_it_and_the_default_writes_its_values_instead(world):
    # the file's local opinion (0.5) is stronger than any variant's, so selecting 'shiny' leaves glow at 0.5 ...
    outputs("SetVariantSelection", world, "execIn", prim=BOX, variantSetName="look", variantName="shiny",
            setVariant=True)
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="look")["variantName"] == "shiny"
    assert glow(world) == 0.5
    assert value(world, "custom:finish") == "gloss"
    world.reset()
    # ... while writing the variant's values (Kit's default) puts 4 on the prim and keeps the selection 'plain'
    outputs("SetVariantSelection", world, "execIn", prim=BOX, variantSetName="look", variantName="shiny")
    assert glow(world) == 4.0 and value(world, "custom:label") == "new"
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="look")["variantName"] == "plain"
    assert outputs("ReadPrimMaterial", world, prim=BOX)["material"] == "/World/Chrome"    # its binding too
    # ClearVariantSelection without setVariant removes the written values: the file's show again
    outputs("ClearVariantSelection", world, "execIn", prim=BOX, variantSetName="look")
    assert glow(world) == 0.5 and value(world, "custom:finish") == "matte"


def test_written_values_keep_their_usd_types_arrays_and_quaternions_included(world):
    outputs("SetVariantSelection", world, "execIn", prim=BOX, variantSetName="look", variantName="striped")
    assert list(value(world, "primvars:displayColor")) == [Gf.Vec3f(1, 1, 1), Gf.Vec3f(0, 0, 0)]
    outputs("SetVariantSelection", world, "execIn", prim=BOX, variantSetName="look", variantName="shiny")
    assert value(world, "custom:spin") == Gf.Quatf(0, 0, 0, 1)             # (w, x, y, z) as the file writes it
    assert world.stage.GetAttributeAtPath("/World/Box.custom:label").GetTypeName() == "string"


def test_clear_with_set_variant_blocks_the_selection(world):
    outputs("ClearVariantSelection", world, "execIn", prim=BOX, variantSetName="look", setVariant=True)
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="look")["variantName"] == ""
    assert value(world, "custom:finish") is None           # only the variants author it
    world.reset()
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="look")["variantName"] == "plain"


def test_blend_writes_the_weighted_values_and_switches_discrete_ones_at_one_half(world):
    def blend(t, **more):
        return outputs("BlendVariants", world, "execIn", prim=BOX, variantSetName="look", variantNameA="plain",
                       variantNameB="shiny", blend=t, **more)["bundle"]

    bundle = blend(0.25)
    # 0.75 a + 0.25 b, by hand: tint (0.75 * 0.5 + 0.25 * 1, 0.75 * 0.5, 0.75 * 0.5), glow 0.25 * 4
    assert world.stage.GetAttributeAtPath("/World/Box.primvars:tint").Get() == (0.625, 0.375, 0.375)
    assert glow(world) == 1.0
    assert bundle.get("custom:glow").value == 1.0 and bundle.get("primvars:tint").value == (0.625, 0.375, 0.375)
    assert value(world, "custom:finish") == "matte"     # a token: a below 0.5
    assert value(world, "custom:coats") == 1
    # quaternions componentwise, as Kit's GfLerp: (w, x, y, z) = 0.75 (1, 0, 0, 0) + 0.25 (0, 0, 0, 1)
    assert value(world, "custom:spin") == Gf.Quatf(0.75, 0.0, 0.0, 0.25)
    blend(0.5)
    assert value(world, "custom:finish") == "gloss" and glow(world) == 2.0
    assert outputs("ReadPrimMaterial", world, prim=BOX)["material"] == "/World/Chrome"    # b's binding from 0.5
    assert value(world, "custom:coats") == 3
    assert value(world, "custom:label") is None            # only b authors it: not blended
    blend(1.0, setVariant=True)          # finished: b is selected and the written values are removed
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="look")["variantName"] == "shiny"
    assert glow(world) == 0.5 and world.stage.GetAttributeAtPath("/World/Box.primvars:tint").Get() == (1, 0, 0)


def test_blend_refuses_arrays_and_physics_as_kit_and_the_world_do(world):
    with pytest.raises(GraphRuntimeError, match="primvars:displayColor: a color3f\\[\\] value cannot be blended"):
        outputs("BlendVariants", world, "execIn", prim=BOX, variantSetName="look", variantNameA="striped",
                variantNameB="banded", blend=0.5)
    with pytest.raises(GraphRuntimeError, match="node 'node': /World/Box: blending 'small' and 'big' at 0.5 would "
                                                "change what is simulated .*halfExtents"):
        outputs("BlendVariants", world, "execIn", prim=BOX, variantSetName="size", variantNameA="small",
                variantNameB="big", blend=0.5)
    assert world.stage.GetAttributeAtPath("/World/Box.size").Get() == 0.5


def test_a_physics_variant_switch_fails_the_run_naming_the_node_the_prim_and_why(world):
    with pytest.raises(GraphRuntimeError, match=r"^node 'node': /World/Box: selecting variant 'big' of 'size' would "
                                                r"change what is simulated \(CubeShape /World/Box halfExtents"):
        outputs("SetVariantSelection", world, "execIn", prim=BOX, variantSetName="size", variantName="big",
                setVariant=True)
    assert outputs("GetVariantSelection", world, prim=BOX, variantSetName="size")["variantName"] == "small"
    with pytest.raises(GraphRuntimeError, match="variant set 'size' has no variant 'huge' \\(it has big, small\\)"):
        outputs("SetVariantSelection", world, "execIn", prim=BOX, variantSetName="size", variantName="huge",
                setVariant=True)


def test_kits_tutorial_blend_turns_the_torus_halfway_and_its_pose_follows():
    """Kit's "Using Variant Nodes" tutorial: a torus with variant set Blend, rotateXYZ (90, 0, 0) in A and
    (0, 0, 90) in B. Blending at 0.5 gives (45, 0, 45): X first, then Z, so the world orientation is
    qz(45) qx(45) = (c s, s^2, s c, c^2) with s = sin 22.5 deg, c = cos 22.5 deg (x, y, z, w)."""
    import math

    from graphflow.physics import create_world

    stage = Usd.Stage.CreateInMemory()
    stage.GetRootLayer().ImportFromString('''#usda 1.0
(
    upAxis = "Z"
    metersPerUnit = 1
)
def Xform "World"
{
    def Xform "Torus" (
        variants = {
            string Blend = "A"
        }
        prepend variantSets = "Blend"
    )
    {
        uniform token[] xformOpOrder = ["xformOp:rotateXYZ"]
        variantSet "Blend" = {
            "A" {
                float3 xformOp:rotateXYZ = (90, 0, 0)
            }
            "B" {
                float3 xformOp:rotateXYZ = (0, 0, 90)
            }
        }
    }
}
''')
    with create_world(stage) as world:
        assert world.prim_pose("/World/Torus")[1] == pytest.approx((math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)))
        outputs("BlendVariants", world, "execIn", prim=["/World/Torus"], variantSetName="Blend", variantNameA="A",
                variantNameB="B", blend=0.5)
        assert value_at(world, "/World/Torus.xformOp:rotateXYZ") == (45.0, 0.0, 45.0)
        s, c = math.sin(math.radians(22.5)), math.cos(math.radians(22.5))
        assert world.prim_pose("/World/Torus")[1] == pytest.approx((c * s, s * s, s * c, c * c), abs=1e-6)
        world.reset()
        assert world.prim_pose("/World/Torus")[1] == pytest.approx((math.sqrt(0.5), 0.0, 0.0, math.sqrt(0.5)))


def value_at(world, path):
    return tuple(world.stage.GetAttributeAtPath(path).Get())
