"""omni.graph.nodes.WritePrims: write a bundle of prims back to the prims they were read from."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._bundles import PATTERN_HELP, write
from .find_prims import wildcard

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrims",
    version=1,
    description=(
        "When execIn fires, writes each prim bundle of primsBundle (ReadPrims' output, or one prim's bundle) "
        "to the prim its sourcePrimPath names, as WritePrimAttribute does: the prims whose path matches "
        "pathPattern and type typePattern, the attributes attrNamesToExport matches. Values equal to the "
        "world's are left alone; one the world cannot honour fails the node naming prim and attribute. "
        "graphflow writes to the running world only, so usdWriteBack changes nothing."),
    categories=("sceneGraph", "bundle"),
    ui_name="Write Prims (Legacy)",
    inputs=(
        Attribute("attrNamesToExport", "string", default="*", description=f"Attributes to write: {PATTERN_HELP}"),
        Attribute("execIn", "execution", description="Write now"),
        Attribute("pathPattern", "string", default="*", description=f"Prims to write: {PATTERN_HELP}"),
        Attribute("primsBundle", "bundle", description="The prims to write back"),
        Attribute("typePattern", "string", default="*", description=f"Prim types to write: {PATTERN_HELP}"),
        Attribute("usdWriteBack", "bool", default=False, description="Kit's persist-to-USD switch (no effect)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the prims were written"),
    ),
)


def prim_bundles(bundle):
    """The prim bundles of a bundle: its children, or the bundle itself when it is one prim's bundle."""
    return bundle.children if bundle.children or not bundle.source_prim_path else (bundle,)


def write_matching(db, pairs, attribute_patterns: str) -> None:
    """Write each (prim path, prim bundle) pair whose source prim matches pathPattern and typePattern."""
    inputs = db.inputs
    for path, prim in pairs:
        if wildcard(inputs.pathPattern, prim.source_prim_path) and wildcard(inputs.typePattern, prim.source_prim_type):
            write(db, path, prim, attribute_patterns)


def compute(db):
    prims = prim_bundles(db.inputs.primsBundle)
    write_matching(db, [(prim.source_prim_path, prim) for prim in prims], db.inputs.attrNamesToExport)
    db.outputs.execOut = ExecState.ENABLED
