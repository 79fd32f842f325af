"""omni.graph.nodes.AttributeType: Fabric's type of one attribute of a bundle, as Kit's integer codes."""
from graphflow.spec import Attribute, NodeSpec

from ._bundles import fabric_type, full_type

SPEC = NodeSpec(
    id="omni.graph.nodes.AttributeType",
    version=1,
    description=(
        "The type of the attribute attrName of the bundle 'data' as Fabric numbers it (omni.fabric Type): "
        "baseType (1 bool, 3 int, 5 int64, 8 float, 9 double, 10 token, 2 uchar for text), componentCount "
        "(3 for a double[3], 16 for a 4x4 matrix), arrayDepth (0 value, 1 array; text counts as an array), "
        "role (0 none, 1 vector, 2 normal, 3 position, 4 color, 5 texCoord, 6 quaternion, 9 timecode, 10 "
        "text, 14 matrix, 17 path) and fullType = baseType | componentCount << 8 | arrayDepth << 16 | "
        "role << 24. All are -1 when the bundle has no such attribute."),
    categories=("bundle",),
    ui_name="Extract Attribute Type Information",
    inputs=(
        Attribute("attrName", "token", default="input", description="The attribute to look at"),
        Attribute("data", "bundle", description="The bundle holding it"),
    ),
    outputs=(
        Attribute("arrayDepth", "int", description="0 a value, 1 an array; -1 no such attribute"),
        Attribute("baseType", "int", description="Fabric's base type number; -1 no such attribute"),
        Attribute("componentCount", "int", description="Components per element; -1 no such attribute"),
        Attribute("fullType", "int", description="The four numbers packed into one; -1 no such attribute"),
        Attribute("role", "int", description="Fabric's role number; -1 no such attribute"),
    ),
)


def compute(db):
    found = db.inputs.data.get(db.inputs.attrName)
    outputs = db.outputs
    if found is None:
        outputs.baseType = outputs.componentCount = outputs.arrayDepth = outputs.role = outputs.fullType = -1
        return
    outputs.baseType, outputs.componentCount, outputs.arrayDepth, outputs.role = fabric_type(found.type)
    outputs.fullType = full_type(found.type)
