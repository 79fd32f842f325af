"""isaacsim.ros2.bridge.ROS2Context: the ROS 2 context the bridge nodes share.

Headless there is no rcl context: the handle names the domain (domain id + 1,
so 0 stays "no context") and every bridge node uses the world's topic bus
whatever handle it gets. ``useDomainIDEnvVar`` reads ROS_DOMAIN_ID as Isaac does.
"""
import os

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2Context",
    version=2,
    compatible_versions=(1,),
    aliases=("omni.isaac.ros2_bridge.ROS2Context",),
    description=(
        "The ROS 2 context for the bridge nodes: a handle for domain_id (or ROS_DOMAIN_ID when "
        "useDomainIDEnvVar). Headless runs share one topic bus per world whatever the domain."),
    categories=("isaacRos2",),
    ui_name="ROS2 Context",
    inputs=(
        Attribute("domain_id", "uint", default=0, maximum=232, description="ROS 2 domain id"),
        Attribute("useDomainIDEnvVar", "bool", default=True, description="Use ROS_DOMAIN_ID when it is set"),
    ),
    outputs=(
        Attribute("context", "uint64", description="Context handle (domain id + 1)"),
    ),
)


def compute(db):
    domain = db.inputs.domain_id
    if db.inputs.useDomainIDEnvVar and os.environ.get("ROS_DOMAIN_ID", "").strip().isdigit():
        domain = int(os.environ["ROS_DOMAIN_ID"])
    db.outputs.context = domain + 1
