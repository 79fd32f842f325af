"""isaacsim.core.nodes.IsaacReadEnvVar: an environment variable of the host, read once per run.

ROS 2 graphs read ROS_DOMAIN_ID this way. A run must be reproducible, so each
variable is read the first time the node asks for it after the run starts (or
is reset) and kept for the rest of the run: a variable changed while a run goes
cannot change its outputs. The value is the node's output, so it is in the
trace and a diff of two runs shows it. A variable that is not set gives the
empty string, as Isaac.
"""
import os

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.core.nodes.IsaacReadEnvVar",
    version=1,
    aliases=("omni.isaac.core_nodes.IsaacReadEnvVar",),
    description=(
        "outputs:value = the environment variable envVar of the process running the graph, read once when "
        "the run starts (recorded in the trace); the empty string when it is not set or envVar is empty."),
    categories=("isaacCore",),
    ui_name="Isaac Read Env Var",
    inputs=(
        Attribute("envVar", "string", default="", description="The environment variable's name"),
    ),
    outputs=(
        Attribute("value", "string", default="", description="Its value, or the empty string when not set"),
    ),
)


def compute(db):
    name = db.inputs.envVar
    if name not in db.internal:
        db.internal[name] = os.environ.get(name, "") if name else ""
    db.outputs.value = db.internal[name]
