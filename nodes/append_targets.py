"""omni.graph.nodes.AppendTargets: several target arrays joined into one."""
from graphflow.spec import Attribute, NodeSpec

INPUTS = 8      # input0, input1 as Kit publishes them, and the dynamic input2... a Kit user adds

SPEC = NodeSpec(
    id="omni.graph.nodes.AppendTargets",
    version=1,
    description=(
        "outputs:targets = input0, input1, ... joined in order; a path already in the result is skipped unless "
        f"allowDuplicates. Up to {INPUTS} inputs (input0 to input{INPUTS - 1})."),
    categories=("sceneGraph",),
    ui_name="Append Targets",
    inputs=(
        Attribute("allowDuplicates", "bool", default=False, description="Keep every path, repeats included"),
        *(Attribute(f"input{i}", "target", optional=True, description="Input target array") for i in range(INPUTS)),
    ),
    outputs=(
        Attribute("targets", "target", description="The joined target array"),
    ),
)


def compute(db):
    joined = []
    for i in range(INPUTS):
        for path in getattr(db.inputs, f"input{i}") or ():
            if db.inputs.allowDuplicates or path not in joined:
                joined.append(path)
    db.outputs.targets = tuple(joined)
