"""isaacsim.ros2.bridge.ROS2QoSProfile on the examples of Isaac Sim's own test (isaacsim.ros2.nodes test_qos_profile):
the JSON profile for the defaults, custom policies, single policies and each preset, as Isaac's test expects them."""
import json

import pytest

from graphflow.testing import NodeHarness

QOS = "isaacsim.ros2.bridge.ROS2QoSProfile"
PUB_SUB = {"history": "keepLast", "depth": 10, "reliability": "reliable", "durability": "volatile", "deadline": 0.0,
           "lifespan": 0.0, "liveliness": "systemDefault", "leaseDuration": 0.0}


def _profile(**inputs):
    text = NodeHarness(QOS, inputs).compute().outputs["qosProfile"]
    assert text == json.dumps(json.loads(text), sort_keys=True, separators=(",", ":"))   # compact, sorted keys
    return json.loads(text)


def test_default_profile_has_every_policy():
    profile = _profile()
    assert profile == PUB_SUB
    assert isinstance(profile["depth"], int)


def test_custom_profile_keeps_the_policy_inputs():
    custom = {"history": "keepAll", "depth": 20, "reliability": "bestEffort", "durability": "transientLocal",
              "deadline": 1.5, "lifespan": 2.0, "liveliness": "automatic", "leaseDuration": 3.0}
    assert _profile(**custom, createProfile="Custom") == custom


@pytest.mark.parametrize(("policy", "value"), [("reliability", "bestEffort"), ("history", "keepAll"),
                                               ("durability", "transientLocal")])
def test_one_policy_changed(policy, value):
    """Isaac's single-policy tests set one policy (its editor then flips createProfile to Custom)."""
    assert _profile(**{policy: value}, createProfile="Custom") == {**PUB_SUB, policy: value}


def test_nonzero_time_policies():
    profile = _profile(deadline=0.5, lifespan=1.0, leaseDuration=2.5, createProfile="Custom")
    assert (profile["deadline"], profile["lifespan"], profile["leaseDuration"]) == (0.5, 1.0, 2.5)


@pytest.mark.parametrize(("preset", "expected"), [
    ("Sensor Data", {**PUB_SUB, "depth": 5, "reliability": "bestEffort"}),
    ("System Default", {**PUB_SUB, "history": "systemDefault", "depth": 0, "reliability": "systemDefault",
                        "durability": "systemDefault"}),
    ("Services", PUB_SUB), ("Default for publishers/subscribers", PUB_SUB)])
def test_presets_replace_the_policies(preset, expected):
    """A preset's policies win over the policy inputs, as Isaac's node applies a preset to them."""
    assert _profile(createProfile=preset, history="keepAll", depth=99) == expected
