"""omni.graph.nodes.ReadPrim: one prim's attributes as a bundle (Kit's deprecated form of ReadPrimAttributes)."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP, TIME_HELP, read, usd_time

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrim",
    version=9,
    compatible_versions=(1, 2, 3, 4, 5, 6, 7, 8),
    description=(
        "outputs:primBundle = the attributes of the prim 'prim' (values as composed on the stage, the ones "
        "physics drives current, plus worldMatrix) whose names match attrNamesToImport, with sourcePrimPath "
        "and sourcePrimType. computeBoundingBox adds bboxMinCorner, bboxMaxCorner and bboxTransform. Kit "
        "types 'prim' as a bundle; Isaac files author it as a relationship to the prim, read here as a target."),
    categories=("sceneGraph", "bundle"),
    ui_name="Read Prim",
    inputs=(
        Attribute("attrNamesToImport", "token", default="*", description=f"Attribute names to read: {PATTERN_HELP}"),
        Attribute("computeBoundingBox", "bool", default=False,
                  description="Add the prim's local bounding box (bboxMinCorner, bboxMaxCorner, bboxTransform)"),
        Attribute("prim", "target", description="The prim to read"),
        Attribute("usdTimecode", "timecode", default="nan", description=TIME_HELP),
    ),
    outputs=(
        Attribute("primBundle", "bundle", description="The prim's attributes, with sourcePrimPath and sourcePrimType"),
    ),
)


def compute(db):
    prims = db.inputs.prim
    if len(prims) != 1:
        db.error(f"reads one prim; 'prim' names {len(prims)}" + (f" ({', '.join(prims)})" if prims else ""))
    db.outputs.primBundle = read(db, prims[0], db.inputs.attrNamesToImport, db.inputs.computeBoundingBox,
                                 usd_time(db.inputs.usdTimecode))
