"""omni.graph.nodes.CompareTargets: whether two target arrays are (or are not) the same."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.CompareTargets",
    version=1,
    description=(
        "outputs:result = (a == b) or (a != b) by operation: the whole arrays, or with compareEach one bool per "
        "element (arrays of different lengths compare unequal beyond the shorter one)."),
    categories=("math:condition",),
    ui_name="Compare Targets",
    inputs=(
        Attribute("a", "target", description="Input A"),
        Attribute("b", "target", description="Input B"),
        Attribute("compareEach", "bool", default=False, description="Compare element by element"),
        Attribute("operation", "token", default="==", allowed_tokens=("==", "!="), description="== or !="),
    ),
    outputs=(
        Attribute("result", "any", description="bool, or bool[] with compareEach"),
    ),
)


def compute(db):
    a, b, equal = tuple(db.inputs.a or ()), tuple(db.inputs.b or ()), db.inputs.operation == "=="
    if not db.inputs.compareEach:
        db.outputs.result = (a == b) is equal
        return
    length = max(len(a), len(b))
    db.outputs.result = tuple(
        ((a[i] if i < len(a) else None) == (b[i] if i < len(b) else None)) is equal for i in range(length))
