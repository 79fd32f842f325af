"""omni.graph.nodes.WritePrimsV2: write a bundle of prims back, to their source prims or to given targets."""
from graphflow.spec import Attribute, NodeSpec
from graphflow.types import ExecState

from ._bundles import PATTERN_HELP
from .write_prims import prim_bundles, write_matching

NO_SCATTER = ("inputs:scatterUnderTargets: graphflow's world cannot create prims while running, so the prims "
              "cannot be exported under the targets (set it false)")

SPEC = NodeSpec(
    id="omni.graph.nodes.WritePrimsV2",
    version=1,
    description=(
        "When execIn fires, writes each prim bundle of primsBundle as WritePrims does: to the prim its "
        "sourcePrimPath names, or, when 'prims' names targets, to the target at the same place (one target "
        "per prim bundle). Values equal to the world's are left alone; one the world cannot honour fails the "
        "node naming prim and attribute. graphflow writes to the running world only, so usdWriteBack and "
        "layerIdentifier change nothing; scatterUnderTargets (which creates prims) must stay false."),
    categories=("sceneGraph", "bundle"),
    ui_name="Write Prims",
    inputs=(
        Attribute("attrNamesToExport", "string", default="*", description=f"Attributes to write: {PATTERN_HELP}"),
        Attribute("execIn", "execution", description="Write now"),
        Attribute("layerIdentifier", "token", default="", description="Kit's USD layer to persist to (no effect)"),
        Attribute("pathPattern", "string", default="*", description=f"Prims to write: {PATTERN_HELP}"),
        Attribute("prims", "target", optional=True, description="Target prims, one per prim bundle (none: the source prims)"),
        Attribute("primsBundle", "bundle", description="The prims to write"),
        Attribute("scatterUnderTargets", "bool", default=False,
                  description="Create the prims under the targets (not available: must stay false)"),
        Attribute("typePattern", "string", default="*", description=f"Prim types to write: {PATTERN_HELP}"),
        Attribute("usdWriteBack", "bool", default=True, description="Kit's persist-to-USD switch (no effect)"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after the prims were written"),
    ),
)


def validate(node_name, values):
    return [NO_SCATTER] if values.get("scatterUnderTargets") else []


def compute(db):
    prims, targets = prim_bundles(db.inputs.primsBundle), db.inputs.prims
    if targets and len(targets) != len(prims):
        db.error(f"'prims' names {len(targets)} targets for {len(prims)} prim bundles (one each)")
    paths = targets or tuple(prim.source_prim_path for prim in prims)
    write_matching(db, list(zip(paths, prims)), db.inputs.attrNamesToExport)
    db.outputs.execOut = ExecState.ENABLED
