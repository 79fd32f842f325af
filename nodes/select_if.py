"""omni.graph.nodes.SelectIf: ifTrue or ifFalse by a condition, elementwise over arrays."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.SelectIf",
    version=1,
    description=(
        "outputs:result = ifTrue when condition is true, else ifFalse. With a bool[] condition, ifTrue and "
        "ifFalse arrays of its length are picked from element by element; a single value on either side is "
        "used for every element."),
    categories=("flowControl",),
    ui_name="Select If",
    inputs=(
        Attribute("condition", "any", default=False, description="bool or bool[]"),
        Attribute("ifTrue", "any", description="Value if condition is true"),
        Attribute("ifFalse", "any", description="Value if condition is false"),
    ),
    outputs=(
        Attribute("result", "any", description="The selected value(s)"),
    ),
)


def compute(db):
    condition, if_true, if_false = plain(db.inputs.condition), plain(db.inputs.ifTrue), plain(db.inputs.ifFalse)
    if if_true is None or if_false is None:
        db.error("inputs:ifTrue and inputs:ifFalse need values; connect them or set them")
    if isinstance(condition, bool):
        db.outputs.result = if_true if condition else if_false
        return
    if not isinstance(condition, tuple) or not all(isinstance(c, bool) for c in condition):
        db.error(f"inputs:condition must be a bool or a bool array, got {condition!r}")
    picks = []
    for name, side in (("ifTrue", if_true), ("ifFalse", if_false)):
        is_array = isinstance(side, tuple) and len(side) == len(condition) and not isinstance(side, str)
        picks.append(side if is_array else (side,) * len(condition))
    db.outputs.result = tuple(t if c else f for c, t, f in zip(condition, *picks))
