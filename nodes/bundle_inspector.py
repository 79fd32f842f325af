"""omni.graph.nodes.BundleInspector: what a bundle holds, as parallel lists (for checking a graph's data)."""
import json

from graphflow.spec import Attribute, NodeSpec

from ._bundles import ROLES, base_type_name, fabric_type

SPEC = NodeSpec(
    id="omni.graph.nodes.BundleInspector",
    version=4,
    compatible_versions=(1, 2, 3),
    description=(
        "When execIn fires: the attributes of 'bundle' and of its child bundles down to inspectDepth (0: the "
        "bundle's own, 1: also its children's, -1: all) as parallel lists (names, Fabric base type names, role "
        "names, tuple counts, array depths, values as text), their count, the bundle's number of children, "
        "and the bundle passed through; print logs one line per attribute."),
    categories=("bundle",),
    ui_name="Bundle Inspector",
    inputs=(
        Attribute("bundle", "bundle", description="The bundle to inspect"),
        Attribute("execIn", "execution", description="Inspect now"),
        Attribute("inspectDepth", "int", default=1, minimum=-1,
                  description="Levels of child bundles to include (-1: all)"),
        Attribute("print", "bool", default=False, description="Log the contents"),
    ),
    outputs=(
        Attribute("arrayDepths", "int[]", description="Array depth of each attribute"),
        Attribute("attributeCount", "uint64", description="Number of attributes listed"),
        Attribute("bundle", "bundle", description="The input bundle, unchanged"),
        Attribute("childCount", "uint64", description="Number of child bundles of the bundle"),
        Attribute("count", "uint64", description="Kit's deprecated name of attributeCount"),
        Attribute("names", "token[]", description="Attribute names"),
        Attribute("roles", "token[]", description="Role name of each attribute (none, position, color, ...)"),
        Attribute("tupleCounts", "int[]", description="Components of each attribute"),
        Attribute("types", "token[]", description="Base type name of each attribute (double, token, ...)"),
        Attribute("values", "token[]", description="Each attribute's value as text"),
    ),
)


def _listed(bundle, depth: int):
    yield from bundle.attributes
    if depth != 0:
        for child in bundle.children:
            yield from _listed(child, depth - 1)


def _text(value) -> str:
    return value if isinstance(value, str) else json.dumps(value)


def compute(db):
    bundle = db.inputs.bundle
    listed = list(_listed(bundle, db.inputs.inspectDepth))
    codes = [fabric_type(attribute.type) for attribute in listed]
    outputs = db.outputs
    outputs.names = tuple(attribute.name for attribute in listed)
    outputs.types = tuple(base_type_name(attribute.type) for attribute in listed)
    outputs.roles = tuple(ROLES[code[3]] for code in codes)
    outputs.tupleCounts = tuple(code[1] for code in codes)
    outputs.arrayDepths = tuple(code[2] for code in codes)
    outputs.values = tuple(_text(attribute.value) for attribute in listed)
    outputs.attributeCount = outputs.count = len(listed)
    outputs.childCount = len(bundle.children)
    outputs.bundle = bundle
    if db.inputs.print:
        for attribute in listed:
            db.log(f"{attribute.name} ({attribute.type}) = {_text(attribute.value)}")
