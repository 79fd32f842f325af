"""omni.graph.core.ReadVariable: read a graph variable."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.core.ReadVariable",
    version=2,
    compatible_versions=(1,),
    description="Outputs the current value of the graph variable named by variableName (a data node).",
    categories=("graph:action", "variables"),
    ui_name="Read Variable",
    inputs=(
        Attribute("variableName", "token", default="", description="Name of the graph variable"),
        Attribute("graph", "target", optional=True,
                  description="Ignored, as in Kit since version 2: the variable is this graph's"),
        Attribute("targetPath", "token", default="", description="Ignored, as in Kit since version 2"),
    ),
    outputs=(
        Attribute("value", "any", description="The variable's value"),
    ),
)


def compute(db):
    name = db.inputs.variableName
    if not name:
        db.error("inputs:variableName is empty; name the graph variable to read")
        return
    db.outputs.value = db.get_variable(name)
