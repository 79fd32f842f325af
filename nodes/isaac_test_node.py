"""isaacsim.core.nodes.IsaacTestNode: echoes a string, on each execIn.

Isaac ships it for its own OmniGraph tests; graphs copied from those tests use it
as a probe, so it imports and runs rather than being refused. It has no
execution output: it computes when pulsed and its output is pulled downstream.
"""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacTestNode",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacTestNode",),
    description="outputs:output = inputs:input, copied each time execIn fires.",
    categories=("isaacCore",),
    ui_name="Isaac Test Node",
    inputs=(
        Attribute("execIn", "execution", description="Copies the input when it fires"),
        Attribute("input", "string", default="", description="The string to echo"),
    ),
    outputs=(
        Attribute("output", "string", default="", description="The input as of the last execIn"),
    ),
)


def compute(db):
    db.outputs.output = db.inputs.input
