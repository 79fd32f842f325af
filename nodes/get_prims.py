"""omni.graph.nodes.GetPrims: the prims of a bundle of prims that match paths and types."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP
from .find_prims import wildcard

SPEC = NodeSpec(
    id="omni.graph.nodes.GetPrims",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:bundle = the bundle 'bundle' keeping only the child bundles (prims) whose sourcePrimPath "
        "matches pathPattern, whose sourcePrimType matches typePattern and, when 'prims' names any, that are "
        "among them; with inverse, only the others."),
    categories=("bundle",),
    ui_name="Get Prims",
    inputs=(
        Attribute("bundle", "bundle", description="A bundle of prims (ReadPrims' output)"),
        Attribute("inverse", "bool", default=False, description="Keep the prims that do not match instead"),
        Attribute("pathPattern", "string", default="*", description=f"Prim paths to keep: {PATTERN_HELP}"),
        Attribute("prims", "target", optional=True, description="Prims to keep (none: no restriction)"),
        Attribute("typePattern", "string", default="*", description=f"Prim types to keep: {PATTERN_HELP}"),
    ),
    outputs=(
        Attribute("bundle", "bundle", description="The bundle with the kept prims"),
    ),
)


def compute(db):
    inputs = db.inputs
    chosen = set(inputs.prims)

    def matches(child) -> bool:
        path = child.source_prim_path
        return ((not chosen or path in chosen) and wildcard(inputs.pathPattern, path)
                and wildcard(inputs.typePattern, child.source_prim_type))

    db.outputs.bundle = inputs.bundle.with_children(
        tuple(child for child in inputs.bundle.children if matches(child) != inputs.inverse))
