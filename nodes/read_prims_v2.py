"""omni.graph.nodes.ReadPrimsV2: prims (connected, or found under them by pattern) as one child bundle each."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP, TIME_HELP, read_all, search, usd_time
from .read_prims import NO_SKELETONS

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimsV2",
    version=1,
    description=(
        "outputs:primsBundle = one child bundle per prim (its attributes as ReadPrim reads them, with "
        "sourcePrimPath and sourcePrimType). With pathPattern empty the prims of 'prims' are read; otherwise "
        "every prim at or under them (under the stage's root when none is given) whose path matches "
        "pathPattern and whose type matches typePattern, in stage order. graphflow reads on every compute, so "
        "the change-tracking switches change nothing."),
    categories=("sceneGraph", "bundle"),
    ui_name="Read Prims",
    inputs=(
        Attribute("applySkelBinding", "bool", default=False,
                  description="Deform skinned prims by their skeleton (not available: must stay false)"),
        Attribute("attrNamesToImport", "string", default="*", description=f"Attribute names to read: {PATTERN_HELP}"),
        Attribute("computeBoundingBox", "bool", default=False,
                  description="Add each prim's local bounding box (bboxMinCorner, bboxMaxCorner, bboxTransform)"),
        Attribute("enableBundleChangeTracking", "bool", default=False,
                  description="Kit's change tracking of the output bundle (no effect on values)"),
        Attribute("enableChangeTracking", "bool", default=True,
                  description="Kit's USD change tracking (no effect on values: graphflow reads every compute)"),
        Attribute("pathPattern", "string", default="", description=f"Prim paths to find: {PATTERN_HELP}"),
        Attribute("prims", "target", optional=True, description="The prims to read, or the roots to search under"),
        Attribute("typePattern", "string", default="*", description=f"Prim types to find: {PATTERN_HELP}"),
        Attribute("usdTimecode", "timecode", default="nan", description=TIME_HELP),
    ),
    outputs=(
        Attribute("primsBundle", "bundle", description="One child bundle per prim read"),
    ),
)


def validate(node_name, values):
    return [NO_SKELETONS] if values.get("applySkelBinding") else []


def compute(db):
    inputs = db.inputs
    paths = search(db, inputs.prims, inputs.pathPattern, inputs.typePattern) if inputs.pathPattern else inputs.prims
    db.outputs.primsBundle = read_all(db, paths, inputs.attrNamesToImport, inputs.computeBoundingBox,
                                      usd_time(inputs.usdTimecode))
