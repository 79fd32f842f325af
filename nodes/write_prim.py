"""omni.graph.nodes.WritePrim: write attributes to one prim.

Kit gives this node one dynamic input per attribute of the target prim and
writes the connected ones. graphflow nodes have fixed ports: the importer
gathers the connected dynamic inputs into the bundle input 'attributes' (one
InsertAttribute node per input, graphflow.usd.bundle_ports), and this node
writes every attribute of that bundle.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._bundles import write

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrim",
    version=4,
    compatible_versions=(1, 2, 3),
    description=(
        "When execIn fires, writes each attribute of the bundle 'attributes' (graphflow's form of Kit's "
        "per-attribute inputs) to the prim 'prim' as WritePrimAttribute does, then fires execOut. A value "
        "the world cannot honour fails the node naming the attribute; graphflow writes to the running world "
        "only, never to the USD file, so usdWriteBack and layerIdentifier change nothing."),
    categories=("sceneGraph",),
    ui_name="Write Prim Attributes",
    inputs=(
        Attribute("attributes", "bundle",
                  description="graphflow: the attributes to write (Kit's connected dynamic inputs, gathered on import)"),
        Attribute("execIn", "execution", description="Write now"),
        Attribute("layerIdentifier", "token", default="", description="Kit's USD layer to persist to (no effect)"),
        Attribute("prim", "target", description="The prim to write to"),
        Attribute("usdWriteBack", "bool", default=True, description="Kit's persist-to-USD switch (no effect)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the attributes were written"),
    ),
)


def compute(db):
    prims = db.inputs.prim
    if len(prims) != 1:
        db.error(f"writes one prim; 'prim' names {len(prims)}" + (f" ({', '.join(prims)})" if prims else ""))
    write(db, prims[0], db.inputs.attributes)
    db.outputs.execOut = ExecState.ENABLED
