"""The programmatic scene of Isaac's ``test_surface_gripper_view.py`` (reference §7.2).

Per env *i* (``/env{i}`` at x = 0.2 i): ``box0`` (the target) and ``box1`` (the
gripper body), 1 kg unit cubes scaled to 0.1 m, stacked at z 0.05 and 0.15;
``box1/d6Joint{j}`` attachment joints (body0 only, localPos0 y spread across the
box, z -0.499 in box1's scaled frame, localRot0 (w,x,y,z) = (0.5, -0.5, 0.5, 0.5)
so +X points down, all six axes locked, forward axis "x"); a gripper
``/env{i}/SurfaceGripper`` with coaxial and shear limits 500000 N and
maxGripDistance 0.01. The joints are marked excludeFromArticulation, which
Isaac's runtime writes itself and graphflow's importer needs to leave them to
the gripper.
"""
from graphflow.gripper import create_surface_gripper, register_schema

AXES = ("transX", "transY", "transZ", "rotX", "rotY", "rotZ")


def view_stage(joint_counts):
    """One env per entry of *joint_counts* (the number of attachment joints of that env's gripper)."""
    register_schema()
    from pxr import Gf, Sdf, Usd, UsdGeom, UsdPhysics

    stage = Usd.Stage.CreateInMemory()
    UsdGeom.SetStageUpAxis(stage, UsdGeom.Tokens.z)
    UsdGeom.SetStageMetersPerUnit(stage, 1.0)
    UsdPhysics.Scene.Define(stage, "/physicsScene").CreateGravityDirectionAttr(Gf.Vec3f(0, 0, -1))
    ground = UsdGeom.Plane.Define(stage, "/groundPlane")
    ground.CreateAxisAttr("Z")
    UsdPhysics.CollisionAPI.Apply(ground.GetPrim())
    grippers = []
    for index, count in enumerate(joint_counts):
        env = f"/env{index}"
        UsdGeom.Xform.Define(stage, env).AddTranslateOp().Set(Gf.Vec3d(0.2 * index, 0, 0))
        for name, height in (("box0", 0.05), ("box1", 0.15)):
            cube = UsdGeom.Cube.Define(stage, f"{env}/{name}")
            cube.CreateSizeAttr(1.0)
            cube.AddTranslateOp().Set(Gf.Vec3d(0, 0, height))
            cube.AddScaleOp().Set(Gf.Vec3f(0.1, 0.1, 0.1))
            UsdPhysics.RigidBodyAPI.Apply(cube.GetPrim())
            UsdPhysics.CollisionAPI.Apply(cube.GetPrim())
            UsdPhysics.MassAPI.Apply(cube.GetPrim()).CreateMassAttr(1.0)
        gripper = create_surface_gripper(stage, env)
        gripper.GetAttribute("isaac:coaxialForceLimit").Set(500000.0)
        gripper.GetAttribute("isaac:shearForceLimit").Set(500000.0)
        gripper.GetAttribute("isaac:maxGripDistance").Set(0.01)
        joints = []
        for j in range(count):
            joint = UsdPhysics.Joint.Define(stage, f"{env}/box1/d6Joint{j}")
            joint.CreateBody0Rel().SetTargets([Sdf.Path(f"{env}/box1")])
            joint.CreateLocalPos0Attr(Gf.Vec3f(0, -0.05 + (j + 1) * 0.1 / (count + 1), -0.499))
            joint.CreateLocalRot0Attr(Gf.Quatf(0.5, -0.5, 0.5, 0.5))
            joint.CreateExcludeFromArticulationAttr(True)
            prim = joint.GetPrim()
            for axis in AXES:
                limit = UsdPhysics.LimitAPI.Apply(prim, axis)
                limit.CreateLowAttr(1.0)
                limit.CreateHighAttr(-1.0)
            prim.AddAppliedSchema("IsaacAttachmentPointAPI")
            prim.CreateAttribute("isaac:forwardAxis", Sdf.ValueTypeNames.Token, False).Set(UsdPhysics.Tokens.x)
            joints.append(joint.GetPath())
        gripper.GetRelationship("isaac:attachmentPoints").SetTargets(joints)
        grippers.append(gripper.GetPath().pathString)
    return stage, grippers
