"""omni.graph.nodes.ReadPrims: several prims, one child bundle each (Kit's legacy form of ReadPrimsV2)."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP, TIME_HELP, read_all, search, usd_time

NO_SKELETONS = "inputs:applySkelBinding: graphflow's world has no skeletal animation to apply (set it false)"

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrims",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "outputs:primsBundle = one child bundle per prim (its attributes as ReadPrim reads them, with "
        "sourcePrimPath and sourcePrimType): the prims of 'prims', or with useFindPrims every prim of the "
        "stage whose path matches pathPattern and whose type matches typePattern, in stage order."),
    categories=("sceneGraph", "bundle"),
    ui_name="Read Prims (Legacy)",
    inputs=(
        Attribute("applySkelBinding", "bool", default=False,
                  description="Deform skinned prims by their skeleton (not available: must stay false)"),
        Attribute("attrNamesToImport", "string", default="*", description=f"Attribute names to read: {PATTERN_HELP}"),
        Attribute("computeBoundingBox", "bool", default=False,
                  description="Add each prim's local bounding box (bboxMinCorner, bboxMaxCorner, bboxTransform)"),
        Attribute("pathPattern", "string", default="", description=f"Prim paths to find: {PATTERN_HELP}"),
        Attribute("prims", "target", optional=True, description="The prims to read when useFindPrims is false"),
        Attribute("typePattern", "string", default="*", description=f"Prim types to find: {PATTERN_HELP}"),
        Attribute("usdTimecode", "timecode", default="nan", description=TIME_HELP),
        Attribute("useFindPrims", "bool", default=False,
                  description="Read the prims pathPattern and typePattern find instead of 'prims'"),
    ),
    outputs=(
        Attribute("primsBundle", "bundle", description="One child bundle per prim read"),
    ),
)


def validate(node_name, values):
    return [NO_SKELETONS] if values.get("applySkelBinding") else []


def compute(db):
    inputs = db.inputs
    paths = search(db, (), inputs.pathPattern, inputs.typePattern) if inputs.useFindPrims else inputs.prims
    db.outputs.primsBundle = read_all(db, paths, inputs.attrNamesToImport, inputs.computeBoundingBox,
                                      usd_time(inputs.usdTimecode))
