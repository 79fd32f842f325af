"""omni.graph.nodes.ReadPrimBundle: a prim (or several) as child bundles (Kit's deprecated form of ReadPrims)."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP, TIME_HELP, read_all, usd_time

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimBundle",
    version=7,
    compatible_versions=(1, 2, 3, 4, 5, 6),
    description=(
        "outputs:primBundle = one child bundle per prim read (its attributes as ReadPrim reads them, with "
        "sourcePrimPath and sourcePrimType): the prims of 'prim', or with usePath the space-separated paths "
        "of primPath."),
    categories=("sceneGraph", "bundle"),
    ui_name="Read Prim into Bundle",
    inputs=(
        Attribute("attrNamesToImport", "token", default="*", description=f"Attribute names to read: {PATTERN_HELP}"),
        Attribute("computeBoundingBox", "bool", default=False,
                  description="Add each prim's local bounding box (bboxMinCorner, bboxMaxCorner, bboxTransform)"),
        Attribute("prim", "target", optional=True, description="The prims to read when usePath is false"),
        Attribute("primPath", "token", default="", description="The paths to read when usePath is true"),
        Attribute("usdTimecode", "timecode", default="nan", description=TIME_HELP),
        Attribute("usePath", "bool", default=False, description="Read primPath instead of 'prim'"),
    ),
    outputs=(
        Attribute("primBundle", "bundle", description="One child bundle per prim read"),
    ),
)


def compute(db):
    inputs = db.inputs
    paths = inputs.primPath.split() if inputs.usePath else inputs.prim
    db.outputs.primBundle = read_all(db, paths, inputs.attrNamesToImport, inputs.computeBoundingBox,
                                     usd_time(inputs.usdTimecode))
