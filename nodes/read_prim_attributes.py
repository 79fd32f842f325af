"""omni.graph.nodes.ReadPrimAttributes: one prim's attributes as a bundle.

Kit also exposes each attribute read as a dynamic output of the node; an
imported graph's connections from those outputs read this bundle through an
ExtractAttribute node the importer adds (graphflow.usd.bundle_ports).
"""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP, TIME_HELP, read, usd_time
from .read_prim_attribute import prim_path

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimAttributes",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "outputs:primBundle = the attributes of the prim (values as composed on the stage, the ones physics "
        "drives current, plus worldMatrix) whose names match attrNamesToImport, with sourcePrimPath and "
        "sourcePrimType. Kit's per-attribute outputs come over as ExtractAttribute nodes on import."),
    categories=("sceneGraph", "bundle"),
    ui_name="Read Prim Attributes",
    inputs=(
        Attribute("attrNamesToImport", "string", default="*", description=f"Attribute names to read: {PATTERN_HELP}"),
        Attribute("prim", "target", optional=True, description="The prim to read when usePath is false"),
        Attribute("primPath", "path", default="", optional=True, description="The prim read when usePath is true"),
        Attribute("usdTimecode", "timecode", default="nan", description=TIME_HELP),
        Attribute("usePath", "bool", default=False, description="Read primPath instead of 'prim'"),
    ),
    outputs=(
        Attribute("primBundle", "bundle", description="The prim's attributes, with sourcePrimPath and sourcePrimType"),
    ),
)


def compute(db):
    db.outputs.primBundle = read(db, prim_path(db), db.inputs.attrNamesToImport, False,
                                 usd_time(db.inputs.usdTimecode))
