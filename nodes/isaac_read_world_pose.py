"""isaacsim.core.nodes.IsaacReadWorldPose: a prim's world translation, orientation and scale."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.world import WorldError

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacReadWorldPose",
    version=2,
    compatible_versions=(1,),
    aliases=("omni.isaac.core_nodes.IsaacReadWorldPose",),
    description=(
        "World translation (m) and orientation (x, y, z, w) of prim, live from the world, and its world scale "
        "as composed on the stage (the world moves bodies rigidly; 1, 1, 1 without a stage)."),
    categories=("isaacCore",),
    ui_name="Isaac Read World Pose",
    inputs=(
        Attribute("prim", "target", description="The prim whose pose to read"),
    ),
    outputs=(
        Attribute("translation", "vectord[3]", description="World translation, m"),
        Attribute("orientation", "quatd[4]", default=(0.0, 0.0, 0.0, 1.0), description="World orientation (x, y, z, w)"),
        Attribute("scale", "vectord[3]", default=(1.0, 1.0, 1.0), description="World scale"),
    ),
)


def compute(db):
    if not db.inputs.prim:
        db.error("inputs:prim is not set: no prim to read")
    try:
        position, orientation = db.world.prim_pose(db.inputs.prim[0])
    except WorldError as error:
        db.error(f"inputs:prim: {error}")
    db.outputs.translation = tuple(float(c) for c in position)
    db.outputs.orientation = tuple(float(c) for c in orientation)
    db.outputs.scale = _world_scale(db.world, db.inputs.prim[0])


def _world_scale(world, path):
    """The scale of the prim's local-to-world matrix on the stage, as Isaac decomposes it (physics never scales)."""
    stage = getattr(world, "stage", None)
    prim = stage.GetPrimAtPath(path) if stage is not None else None
    from pxr import Gf, Usd, UsdGeom

    if not prim or not prim.IsA(UsdGeom.Xformable):
        return (1.0, 1.0, 1.0)
    matrix = UsdGeom.Xformable(prim).ComputeLocalToWorldTransform(Usd.TimeCode.Default())
    return tuple(float(c) for c in Gf.Transform(matrix).GetScale())
