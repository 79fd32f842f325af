"""isaacsim.ros2.bridge.ROS2QoSProfile: a QoS profile as the JSON the bridge nodes' qosProfile takes.

Isaac writes the eight policies as one compact JSON object with sorted keys.
createProfile is a preset: as Isaac's node applies it when the node is created
and whenever it changes, a preset's policies replace the policy inputs; at
"Custom" (which Isaac sets as soon as a policy is edited) or at the .ogn's
default "defaultPubSub", which names no preset's value, the policy inputs
count. The headless bus keeps the latest message whatever the profile.
"""
import json

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="isaacsim.ros2.bridge.ROS2QoSProfile",
    version=1,
    aliases=("omni.isaac.ros2_bridge.ROS2QoSProfile",),
    description=(
        "outputs:qosProfile = the policies (history, depth, reliability, durability, deadline, lifespan, "
        "liveliness, leaseDuration) as a compact JSON object with sorted keys: those of the createProfile "
        "preset, else (Custom) the policy inputs."),
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
        Attribute("createProfile", "token", default="defaultPubSub",
                  description="A preset that replaces the policies (Default for publishers/subscribers, Services, "
                              "Sensor Data, System Default), or Custom: the policy inputs"),
    ),
    outputs=(
        Attribute("qosProfile", "string", description="The profile as JSON"),
    ),
)

POLICIES = ("history", "depth", "reliability", "durability", "deadline", "lifespan", "liveliness", "leaseDuration")
_NO_TIMES = {"deadline": 0.0, "lifespan": 0.0, "leaseDuration": 0.0}
_PUB_SUB = {"history": "keepLast", "depth": 10, "reliability": "reliable", "durability": "volatile",
            "liveliness": "systemDefault", **_NO_TIMES}
PRESETS = {   # Isaac's presets, by the createProfile values its editor stores
    "Default for publishers/subscribers": _PUB_SUB,
    "Services": _PUB_SUB,
    "Sensor Data": {"history": "keepLast", "depth": 5, "reliability": "bestEffort", "durability": "volatile",
                    "liveliness": "systemDefault", **_NO_TIMES},
    "System Default": {"history": "systemDefault", "depth": 0, "reliability": "systemDefault",
                       "durability": "systemDefault", "liveliness": "systemDefault", **_NO_TIMES},
}


def compute(db):
    preset = PRESETS.get(db.inputs.createProfile)
    profile = dict(preset) if preset else {name: getattr(db.inputs, name) for name in POLICIES}
    db.outputs.qosProfile = json.dumps(profile, sort_keys=True, separators=(",", ":"))
