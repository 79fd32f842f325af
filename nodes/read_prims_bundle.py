"""omni.graph.nodes.ReadPrimsBundle: prims by target or by path, one child bundle each."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import PATTERN_HELP, TIME_HELP, read_all, usd_time

SPEC = NodeSpec(
    id="omni.graph.nodes.ReadPrimsBundle",
    version=3,
    compatible_versions=(1, 2),
    description=(
        "outputs:primsBundle = one child bundle per prim read (its attributes as ReadPrim reads them, with "
        "sourcePrimPath and sourcePrimType): the prims of 'prims', or with usePaths those of primPaths (a "
        "path, or a list of paths)."),
    categories=("sceneGraph", "bundle"),
    ui_name="Read Prims into Bundle",
    inputs=(
        Attribute("attrNamesToImport", "string", default="*", description=f"Attribute names to read: {PATTERN_HELP}"),
        Attribute("primPaths", "any", description="The paths read when usePaths is true: a path or a list of them"),
        Attribute("prims", "target", optional=True, description="The prims to read when usePaths is false"),
        Attribute("usdTimecode", "timecode", default="nan", description=TIME_HELP),
        Attribute("usePaths", "bool", default=False, description="Read primPaths instead of 'prims'"),
    ),
    outputs=(
        Attribute("primsBundle", "bundle", description="One child bundle per prim read"),
    ),
)


def validate(node_name, values):
    paths = values.get("primPaths")
    if paths is None or isinstance(paths, str) or (
            isinstance(paths, (list, tuple)) and all(isinstance(path, str) for path in paths)):
        return []
    return [f"inputs:primPaths: expected a path or a list of paths, got {paths!r}"]


def compute(db):
    inputs = db.inputs
    if inputs.usePaths:
        paths = inputs.primPaths
        paths = (paths,) if isinstance(paths, str) else tuple(paths or ())
        if not all(isinstance(path, str) for path in paths):
            db.error(f"primPaths must be a path or a list of paths, got {paths!r}")
    else:
        paths = inputs.prims
    db.outputs.primsBundle = read_all(db, paths, inputs.attrNamesToImport, False, usd_time(inputs.usdTimecode))
