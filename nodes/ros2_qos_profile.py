"""isaacsim.ros2.bridge.ROS2QoSProfile: a QoS profile as the JSON the bridge nodes' qosProfile takes.

Isaac writes the eight policies as one compact JSON object with sorted keys;
createProfile is the editor's preset picker (it rewrites the policy inputs in
Kit's UI), so here the policy inputs are what counts. The headless bus keeps
the latest message whatever the profile.
"""
import json

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2QoSProfile",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2QoSProfile",),
    description=(
        "outputs:qosProfile = the policies (history, depth, reliability, durability, deadline, lifespan, "
        "liveliness, leaseDuration) as a compact JSON object with sorted keys."),
    categories=("isaacRos2",),
    ui_name="ROS2 QoS Profile",
    inputs=(
        Attribute("history", "token", default="keepLast",
                  allowed_tokens=("systemDefault", "keepLast", "keepAll", "unknown"), description="History policy"),
        Attribute("depth", "uint64", default=10, description="Queue size (with keepLast)"),
        Attribute("reliability", "token", default="reliable",
                  allowed_tokens=("systemDefault", "reliable", "bestEffort", "unknown"),
                  description="Reliability policy"),
        Attribute("durability", "token", default="volatile",
                  allowed_tokens=("systemDefault", "transientLocal", "volatile", "unknown"),
                  description="Durability policy"),
        Attribute("deadline", "double", default=0.0, description="Deadline, s"),
        Attribute("lifespan", "double", default=0.0, description="Lifespan, s"),
        Attribute("liveliness", "token", default="systemDefault",
                  allowed_tokens=("systemDefault", "automatic", "manualByTopic", "unknown"),
                  description="Liveliness policy"),
        Attribute("leaseDuration", "double", default=0.0, description="Lease duration, s"),
        Attribute("createProfile", "token", default="Default for publishers/subscribers",
                  description="The editor's preset (Kit's UI rewrites the policies from it)"),
    ),
    outputs=(
        Attribute("qosProfile", "string", description="The profile as JSON"),
    ),
)

POLICIES = ("history", "depth", "reliability", "durability", "deadline", "lifespan", "liveliness", "leaseDuration")


def compute(db):
    profile = {name: getattr(db.inputs, name) for name in POLICIES}
    db.outputs.qosProfile = json.dumps(profile, sort_keys=True, separators=(",", ":"))
