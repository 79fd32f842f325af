"""Every stage error a line (issue 26 item 3, issue 21 item 5): nothing from PyBullet or the file system
reaches the user, and the stage report names what it leaves out."""
import warnings

import pytest
from pxr import Gf, UsdGeom, UsdPhysics

from graphflow.physics import StageError, UnsupportedPrimWarning, create_world

from .test_import import add_body, make_stage

LONG = "/World/" + "/".join(f"converted_robot_link_with_a_long_name_{i:02d}" for i in range(8))


def hull_body(stage, path):
    """A 0.1 m convex-hull cube body at *path*, 1 m up."""
    for index, prefix in enumerate(path.strip("/").split("/")[:-1]):
        UsdGeom.Xform.Define(stage, "/" + "/".join(path.strip("/").split("/")[:index + 1]))
    mesh = UsdGeom.Mesh.Define(stage, path)
    mesh.CreatePointsAttr([(x, y, z) for x in (-0.05, 0.05) for y in (-0.05, 0.05) for z in (-0.05, 0.05)])
    mesh.CreateFaceVertexCountsAttr([4] * 6)
    mesh.CreateFaceVertexIndicesAttr([0, 1, 3, 2, 4, 6, 7, 5, 0, 4, 5, 1, 2, 3, 7, 6, 0, 2, 6, 4, 1, 5, 7, 3])
    mesh.AddTranslateOp().Set(Gf.Vec3d(0, 0, 1))
    UsdPhysics.RigidBodyAPI.Apply(mesh.GetPrim())
    UsdPhysics.CollisionAPI.Apply(mesh.GetPrim())
    UsdPhysics.MeshCollisionAPI.Apply(mesh.GetPrim()).CreateApproximationAttr("convexHull")
    UsdPhysics.MassAPI.Apply(mesh.GetPrim()).CreateMassAttr(1.0)


def test_a_hull_deep_in_a_long_prim_path_builds_and_falls_freely():
    """A 400-character prim path (the hull's file was named after it: "File name too long"): the cube falls
    g t^2 / 2 = 1.226 m in 0.5 s, as a free body should (within the integrator's 1 %)."""
    assert len(LONG) > 300
    stage = make_stage()
    hull_body(stage, LONG)
    with create_world(stage) as world:
        for _ in range(30):
            world.step()
        assert 1.0 - world.prim_pose(LONG)[0][2] == pytest.approx(9.81 * 0.5 ** 2 / 2, rel=0.015)


@pytest.mark.parametrize("inertia, message", [
    ((-0.01, 0.02, 0.02), r"/World/Link: physics:diagonalInertia is \(-0.01, 0.02, 0.02\); an inertia is"),
    ((0.0, 0.02, 0.02), r"/World/Link: physics:diagonalInertia is \(0, 0.02, 0.02\); an inertia is"),
    ((float("nan"), 0.02, 0.02), r"/World/Link: physics:diagonalInertia is \(nan, 0.02, 0.02\); an inertia is"),
    ((0.01, 0.01, 0.03), r"body /World/Link: principal moments of inertia \(0.01, 0.01, 0.03\) kg m\^2 break the triangle inequality"),
])
def test_an_impossible_inertia_is_refused_naming_the_body_and_the_value(inertia, message):
    stage = make_stage()
    box = add_body(stage, "/World/Link", size=0.1, mass=1.0)
    UsdPhysics.MassAPI(box).CreateDiagonalInertiaAttr(Gf.Vec3f(*inertia))
    with pytest.raises(StageError, match=message) as caught:
        create_world(stage)
    assert "\n" not in str(caught.value)


def test_a_disc_rounded_past_the_triangle_inequality_is_lowered_onto_it_and_named():
    """Izz = Ixx + Iyy + 0.4 %: a thin disc's moments rounded in a converted URDF; simulated with Izz = Ixx + Iyy
    (PyBullet's inverse dynamics refused it with a SystemError), and named once."""
    stage = make_stage()
    box = add_body(stage, "/World/Disc", size=0.1, mass=1.0)
    UsdPhysics.MassAPI(box).CreateDiagonalInertiaAttr(Gf.Vec3f(0.001, 0.001, 0.002008))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", UnsupportedPrimWarning)
        with create_world(stage) as world:
            inertia = world.client.getDynamicsInfo(world.scene.bodies["/World/Disc"].body_id, -1)[2]
    assert inertia == pytest.approx((0.001, 0.001, 0.002), rel=1e-6)
    assert any("rounded onto the triangle inequality" in str(w.message) for w in caught)


def ur5e_without_drives(tmp_path, joints) -> str:
    """The UR5e's .usda with the drives of *joints* (1-6) removed."""
    from pxr import Usd

    from .arms import UR5E, write_usda

    path = write_usda(UR5E, tmp_path / "ur5e_bare.usda")
    stage = Usd.Stage.Open(path)
    for joint in joints:
        prim = stage.GetPrimAtPath(f"/World/Arm/joint{joint}")
        prim.RemoveAPI(UsdPhysics.DriveAPI, "angular")
        for name in list(prim.GetPropertyNames()):
            if name.startswith("drive:"):
                prim.RemoveProperty(name)
    stage.GetRootLayer().Save()
    return path


def stage_command(path, *options) -> str:
    import subprocess
    import sys

    result = subprocess.run([sys.executable, "-m", "graphflow", "stage", path, *options],
                            capture_output=True, text=True, check=False)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_graphflow_stage_names_undriven_joints_and_other_simulators_authoring(tmp_path):
    """A converted UR5e without drives, carrying MuJoCo, Newton and URDF authoring: `graphflow stage` names all
    six free joints and every prim whose authoring it ignores, and never says the drives hold (the arm falls)."""
    from pxr import Sdf, Usd

    path = ur5e_without_drives(tmp_path, range(1, 7))
    stage = Usd.Stage.Open(path)
    shoulder = stage.GetPrimAtPath("/World/Arm/joint2")
    shoulder.CreateAttribute("mjc:armature", Sdf.ValueTypeNames.Float).Set(0.1)
    shoulder.CreateAttribute("newton:damping", Sdf.ValueTypeNames.Float).Set(2.0)
    shoulder.CreateAttribute("urdf:limit:effort", Sdf.ValueTypeNames.Float).Set(150.0)
    shoulder.CreateAttribute("physxJointAxis:angular:armature", Sdf.ValueTypeNames.Float).Set(0.01)
    shoulder.CreateAttribute("physxJoint:maxJointVelocity", Sdf.ValueTypeNames.Float).Set(180.0)   # read: not listed
    stage.DefinePrim("/World/Arm/shoulder_motor", "MjcActuator")
    stage.GetRootLayer().Save()
    out = stage_command(path, "--simulate", "0.5")
    assert "without a drive (free): " + ", ".join(f"/World/Arm/joint{j}" for j in range(1, 7)) in out
    assert "/World/Arm/joint2: MuJoCo and Newton and PhysX and URDF attributes mjc:armature, newton:damping, " \
           "physxJointAxis:angular:armature, urdf:limit:effort not simulated" in out
    assert "/World/Arm/shoulder_motor: MuJoCo prim MjcActuator not simulated" in out
    assert "drives at their targets" not in out
    assert "limp: 6 articulated joints and no drive, every joint falls free" in out


def test_graphflow_stage_counts_the_free_joints_of_a_partly_driven_arm(tmp_path):
    out = stage_command(ur5e_without_drives(tmp_path, (4, 6)), "--simulate", "0.2")
    assert "without a drive (free): /World/Arm/joint4, /World/Arm/joint6" in out
    assert "; 2 joints without a drive free" in out


@pytest.mark.parametrize("geometry, size, message", [
    (UsdGeom.Cylinder, {"radius": 0.0, "height": 0.1}, r"a collider cylinder of invalid size \(radius 0.0, height 0.1\)"),
    (UsdGeom.Capsule, {"radius": 0.0, "height": 0.1}, r"a collider capsule of invalid size \(radius 0.0, height 0.1\)"),
    (UsdGeom.Cylinder, {"radius": float("nan"), "height": 0.1}, r"a collider cylinder of invalid size \(radius nan"),
])
def test_a_round_collider_of_no_size_is_refused(geometry, size, message):
    """PyBullet's createCollisionShapeArray failed on these with a bare "error" (an unexpected error)."""
    stage = make_stage()
    add_body(stage, "/World/Wheel", geometry=geometry, mass=1.0, **size)
    with pytest.raises(StageError, match="/World/Wheel: " + message):
        create_world(stage)


def test_a_nan_density_is_refused():
    """It diverged at physics step 1."""
    stage = make_stage()
    box = add_body(stage, "/World/Box", size=0.1)
    UsdPhysics.MassAPI.Apply(box).CreateDensityAttr(float("nan"))
    with pytest.raises(StageError, match=r"/World/Box: physics:density is nan; a density must be a finite number"):
        create_world(stage)


def test_a_hull_pybullet_cannot_make_is_a_stage_error_naming_the_collider():
    """Two points: PyBullet raised pybullet.error("createCollisionShapeArray failed.")."""
    stage = make_stage()
    mesh = UsdGeom.Mesh.Define(stage, "/World/Sliver")
    mesh.CreatePointsAttr([(0, 0, 0), (0.1, 0, 0)])
    mesh.CreateFaceVertexCountsAttr([2])
    mesh.CreateFaceVertexIndicesAttr([0, 1])
    UsdPhysics.RigidBodyAPI.Apply(mesh.GetPrim())
    UsdPhysics.CollisionAPI.Apply(mesh.GetPrim())
    UsdPhysics.MeshCollisionAPI.Apply(mesh.GetPrim()).CreateApproximationAttr("convexHull")
    UsdPhysics.MassAPI.Apply(mesh.GetPrim()).CreateMassAttr(1.0)
    with pytest.raises(StageError, match=r"collider /World/Sliver: PyBullet cannot make a collision shape of it"):
        create_world(stage)
