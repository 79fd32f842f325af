"""Physics-only flattening keeps what the simulation reads and nothing else: the same bodies, joints, masses,
colliders and drives, in one layer, without visual meshes, render materials, normals or UVs."""
import warnings

import pytest
from pxr import Sdf, Usd

from graphflow.robots.physics_only import flatten_physics_only
from graphflow.robots.post_process import Options, post_process
from graphflow.usd.physics_import import load_description

from .converted import write_arm


def physics(stage_or_path):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        description = load_description(stage_or_path)
    bodies = {path: (body.kind, body.pose, body.mass, [(s.path, s.kind, s.pose, s.radius, s.half_height,
                                                         s.half_extents) for s in body.shapes])
              for path, body in description.bodies.items()}
    joints = {path: (j.kind, j.body0, j.body1, j.pose0, j.pose1, j.axis, j.lower, j.upper, j.drive,
                     j.initial_position) for path, j in description.joints.items()}
    return bodies, joints, [(a.path, a.bodies, a.joints) for a in description.articulations]


def test_flattening_keeps_bodies_joints_masses_and_drives_and_drops_the_visuals(tmp_path):
    """The arm split over two layers (links; graphflow's additions over them) flattens to one: physics equal
    to the last bit; the visual triangle, the material and its shader, the render binding, normals and UVs
    and the URDF note scope are gone; it is smaller."""
    links = write_arm(tmp_path / "links.usda")
    top = Sdf.Layer.CreateNew(str(tmp_path / "arm.usda"))
    top.subLayerPaths.append("./links.usda")
    top.pseudoRoot.SetInfo("defaultPrim", "arm")
    top.pseudoRoot.SetInfo("metersPerUnit", 1.0)
    top.pseudoRoot.SetInfo("upAxis", "Z")
    stage = Usd.Stage.Open(top)
    post_process(stage, Options())
    before = physics(stage)
    flat = flatten_physics_only(stage)
    (tmp_path / "flat.usda").write_text(flat.text)
    assert physics(str(tmp_path / "flat.usda")) == before
    assert (flat.visual_prims, flat.render_prims, flat.note_prims) == (1, 2, 2)     # the note scope, and the Materials scope left empty
    flat_stage = Usd.Stage.Open(str(tmp_path / "flat.usda"))
    assert flat_stage.GetRootLayer().subLayerPaths == []
    assert not flat_stage.GetPrimAtPath("/arm/Geometry/base/base_visual")
    assert not flat_stage.GetPrimAtPath("/arm/Materials/white")
    capsule = flat_stage.GetPrimAtPath("/arm/Geometry/base/upper/upper_collision")
    assert capsule and not capsule.GetRelationship("material:binding") and not capsule.GetChildren()
    assert len(flat.text) < links.stat().st_size + len(top.ExportToString())


@pytest.mark.parametrize("name", ["normals", "primvars:st"])
def test_a_collision_meshs_render_data_is_dropped(tmp_path, name):
    from pxr import UsdPhysics

    stage = Usd.Stage.Open(str(write_arm(tmp_path / "arm.usda")))
    UsdPhysics.CollisionAPI.Apply(stage.GetPrimAtPath("/arm/Geometry/base/base_visual"))   # now a collider
    flat = Usd.Stage.Open(Sdf.Layer.CreateAnonymous(".usda"))
    flat.GetRootLayer().ImportFromString(flatten_physics_only(stage).text)
    mesh = flat.GetPrimAtPath("/arm/Geometry/base/base_visual")
    assert mesh.GetAttribute("points").Get() is not None and not mesh.GetAttribute(name).HasAuthoredValue()


def test_geometry_that_is_a_body_or_holds_physics_is_kept(tmp_path):
    """A Cube that is a rigid body (its collider a child sphere) and a Mesh holding a joint are not visual."""
    from pxr import UsdGeom, UsdPhysics

    stage = Usd.Stage.Open(str(write_arm(tmp_path / "arm.usda")))
    box = UsdGeom.Cube.Define(stage, "/arm/Geometry/box")
    UsdPhysics.RigidBodyAPI.Apply(box.GetPrim())
    UsdPhysics.CollisionAPI.Apply(UsdGeom.Sphere.Define(stage, "/arm/Geometry/box/collider").GetPrim())
    UsdPhysics.FixedJoint.Define(stage, "/arm/Geometry/base/base_visual/weld")
    flat = flatten_physics_only(stage)
    assert flat.visual_prims == 0
    assert 'def Cube "box"' in flat.text and 'def Mesh "base_visual"' in flat.text
