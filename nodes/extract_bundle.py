"""omni.graph.nodes.ExtractBundle: a bundle passed through; its attributes are Kit's dynamic outputs.

On import each connection from one of Kit's per-attribute outputs of this
node reads the bundle through an ExtractAttribute node the importer adds
(graphflow.usd.bundle_ports).
"""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.ExtractBundle",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "outputs:passThrough = the bundle 'bundle' as it is. Kit's per-attribute outputs come over as "
        "ExtractAttribute nodes on import."),
    categories=("bundle",),
    ui_name="Extract Bundle",
    inputs=(
        Attribute("bundle", "bundle", description="The bundle to read"),
    ),
    outputs=(
        Attribute("passThrough", "bundle", description="The same bundle"),
    ),
)


def compute(db):
    db.outputs.passThrough = db.inputs.bundle
