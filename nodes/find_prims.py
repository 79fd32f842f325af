"""omni.graph.nodes.FindPrims: the prims of the stage that match a set of criteria.

Patterns are Kit's wildcard lists: space-separated, '*' any characters, '?' one
character, a leading '^' excludes what it matches (``"* ^/Box"``: all but
/Box); an empty pattern matches everything. The search covers the children of
the root (rootPrim, else rootPrimPath, else the stage's pseudo-root), or all
its descendants when recursive; results are in stage order.
"""
from __future__ import annotations

from fnmatch import fnmatchcase

from graphflow.spec import Attribute, NodeSpec

SYSTEM_TYPES = ("OmniGraph", "OmniGraphNode", "ComputeGraph", "ComputeNode")

SPEC = NodeSpec(
    id="omni.graph.nodes.FindPrims",
    version=2,
    compatible_versions=(1,),
    description=(
        "outputs:prims / primPaths = the prims under the root (children, or every descendant when recursive) "
        "whose path matches pathPattern, whose type matches type, whose name starts with namePrefix, that "
        "have every attribute of requiredAttributes and, when given, a relationship requiredRelationship "
        "targeting requiredTarget or requiredRelationshipTarget."),
    categories=("sceneGraph",),
    ui_name="Find Prims",
    inputs=(
        Attribute("rootPrim", "target", description="Search under this prim (overrides rootPrimPath)"),
        Attribute("rootPrimPath", "token", default="", description="Search under this path (empty: the stage)"),
        Attribute("recursive", "bool", default=False, description="Search every descendant, not only children"),
        Attribute("namePrefix", "token", default="", description="Prim names must start with this"),
        Attribute("pathPattern", "token", default="", description="Wildcard patterns over prim paths"),
        Attribute("type", "token", default="", description="Wildcard patterns over prim type names"),
        Attribute("requiredAttributes", "string", default="", description="Space-separated attribute names"),
        Attribute("requiredRelationship", "token", default="", description="A relationship the prim must have"),
        Attribute("requiredRelationshipTarget", "path", default="",
                  description="A target requiredRelationship must have"),
        Attribute("requiredTarget", "target", description="A target requiredRelationship must have"),
        Attribute("ignoreSystemPrims", "bool", default=False, description="Leave out OmniGraph prims"),
    ),
    outputs=(
        Attribute("prims", "target", description="The matching prims"),
        Attribute("primPaths", "token[]", description="Their paths"),
    ),
)


def compute(db):
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there are no prims to find")
    inputs = db.inputs
    root_path = inputs.rootPrim[0] if inputs.rootPrim else (inputs.rootPrimPath or "/")
    root = stage.GetPrimAtPath(root_path)
    if not root:
        db.error(f"no prim {root_path} on the stage to search under")
    candidates = _descendants(root) if inputs.recursive else list(root.GetChildren())
    found = tuple(str(prim.GetPath()) for prim in candidates if _matches(prim, inputs))
    db.outputs.prims = found
    db.outputs.primPaths = found


def _descendants(prim):
    for child in prim.GetChildren():
        yield child
        yield from _descendants(child)


def _matches(prim, inputs) -> bool:
    if inputs.ignoreSystemPrims and prim.GetTypeName() in SYSTEM_TYPES:
        return False
    if not prim.GetName().startswith(inputs.namePrefix):
        return False
    if not wildcard(inputs.pathPattern, str(prim.GetPath())) or not wildcard(inputs.type, prim.GetTypeName()):
        return False
    if any(not prim.HasAttribute(name) for name in inputs.requiredAttributes.split()):
        return False
    if inputs.requiredRelationship:
        relationship = prim.GetRelationship(inputs.requiredRelationship)
        if not relationship:
            return False
        wanted = [inputs.requiredRelationshipTarget] if inputs.requiredRelationshipTarget else list(inputs.requiredTarget)
        targets = {str(path) for path in relationship.GetTargets()}
        if wanted and not all(target in targets for target in wanted):
            return False
    return True


def wildcard(patterns: str, text: str) -> bool:
    """Kit's wildcard list: include patterns (any must match; none given: all) minus '^' exclusions."""
    words = patterns.split()
    include = [w for w in words if not w.startswith("^")]
    exclude = [w[1:] for w in words if w.startswith("^")]
    if include and not any(fnmatchcase(text, w) for w in include):
        return False
    return not any(fnmatchcase(text, w) for w in exclude)
