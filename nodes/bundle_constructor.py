"""omni.graph.nodes.BundleConstructor: a bundle of the node's dynamic inputs.

Kit adds one dynamic input per attribute to this node. graphflow nodes have
fixed ports, so on import each such input becomes an InsertAttribute node
after this one (graphflow.usd.bundle_ports); the node itself starts the chain
with an empty bundle.
"""
from graphflow.bundles import Bundle
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.BundleConstructor",
    version=1,
    description=(
        "outputs:bundle = an empty bundle: Kit's dynamic inputs of this node come over on import as one "
        "InsertAttribute node each, chained after it, whose last output stands for this node's bundle."),
    categories=("bundle",),
    ui_name="Bundle Constructor",
    outputs=(
        Attribute("bundle", "bundle", description="The constructed bundle"),
    ),
)


def compute(db):
    db.outputs.bundle = Bundle()
