"""omni.graph.nodes.SelectTargetIf: one of two target arrays (or element by element) by a condition."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import plain

SPEC = NodeSpec(
    id="omni.graph.nodes.SelectTargetIf",
    version=1,
    description=(
        "outputs:result = ifTrue when condition is true, else ifFalse; a bool array condition picks element by "
        "element from ifTrue and ifFalse, which must then be as long as it."),
    categories=("flowControl",),
    ui_name="Select Target If",
    inputs=(
        Attribute("condition", "any", default=False, description="bool or bool[]"),
        Attribute("ifFalse", "target", description="The targets when the condition is false"),
        Attribute("ifTrue", "target", description="The targets when the condition is true"),
    ),
    outputs=(
        Attribute("result", "target", description="The selected targets"),
    ),
)


def compute(db):
    condition = plain(db.inputs.condition)
    when_true, when_false = tuple(db.inputs.ifTrue or ()), tuple(db.inputs.ifFalse or ())
    if isinstance(condition, bool):
        db.outputs.result = when_true if condition else when_false
    elif isinstance(condition, tuple) and all(isinstance(c, bool) for c in condition):
        if not len(condition) == len(when_true) == len(when_false):
            db.error(f"inputs:condition has {len(condition)} bools, ifTrue {len(when_true)} and ifFalse "
                     f"{len(when_false)} targets: element-wise needs the same number")
        db.outputs.result = tuple(t if c else f for c, t, f in zip(condition, when_true, when_false))
    else:
        db.error(f"inputs:condition must be a bool or bool array, got {condition!r}")
