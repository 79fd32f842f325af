"""graphflow's post-processing of a converted robot, on hand-written stages shaped as the converters write
them (no converter needed): the drive rule against a numpy reference, the home pose, the dropped list."""
import math
import warnings

import numpy as np
import pytest
from pxr import Usd

from graphflow.errors import BadInput
from graphflow.robots.gains import NATURAL_FREQUENCY, SETTLING_FACTOR
from graphflow.robots.post_process import Options, post_process
from graphflow.robots.sources import read_mjcf
from graphflow.usd.physics_import import load_description

from . import reference
from .converted import MJCF_SOURCE, write_arm

OMEGA = 2 * math.pi * NATURAL_FREQUENCY
JOINTS = "/arm/Physics/"


def processed(tmp_path, options=None, mjcf=False):
    path = write_arm(tmp_path / "arm.usda", mjcf=mjcf)
    stage = Usd.Stage.Open(str(path))
    facts = None
    if mjcf:
        (tmp_path / "arm.xml").write_text(MJCF_SOURCE)
        facts = read_mjcf(tmp_path / "arm.xml")
    outcome = post_process(stage, options or Options(), facts)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return outcome, load_description(stage), stage


def test_the_rule_is_critically_damped_at_ten_hertz_and_settles_within_six_ticks():
    """k = I w^2, d = 2 I w: the characteristic roots of I s^2 + d s + k are the double root -w, and a step
    settles to 2 % in 5.83 / w = 0.093 s, under the six 60 Hz ticks (0.1 s) the rule is derived from."""
    inertia = 0.7
    k, d = inertia * OMEGA ** 2, 2 * inertia * OMEGA
    roots = np.roots([inertia, d, k])
    assert np.allclose(roots, [-OMEGA, -OMEGA], rtol=1e-6)
    t = SETTLING_FACTOR / OMEGA
    assert (1 + OMEGA * t) * math.exp(-OMEGA * t) == pytest.approx(0.02, rel=0.01)   # the critically damped step
    assert t < 6 / 60


def test_urdf_joints_get_the_rules_drives_from_the_inertia_they_carry_at_home(tmp_path):
    """Home by the range-middle rule: shoulder 0, elbow -30 degrees, fingers 0.02 m. The shoulder carries
    0.3473 kg m^2 there (numpy reference), the elbow 0.0404, a finger 0.25 kg: k = I w^2, d = 2 I w, the
    effort limit the max force, the target at home."""
    outcome, description, _stage = processed(tmp_path)
    home = (0.0, math.radians(-30.0), 0.02, 0.02)
    i_shoulder, i_elbow, finger = reference.carried(home[0], home[1], home[2:])
    expected = {"shoulder": (i_shoulder, 50.0, home[0]), "elbow": (i_elbow, 20.0, home[1]),
                "finger_a_joint": (finger, 10.0, 0.02), "finger_b_joint": (finger, 10.0, 0.02)}
    for name, (inertia, effort, target) in expected.items():
        drive = description.joints[JOINTS + name].drive
        assert drive.stiffness == pytest.approx(inertia * OMEGA ** 2, rel=1e-5), name
        assert drive.damping == pytest.approx(2 * inertia * OMEGA, rel=1e-5), name
        assert drive.max_force == pytest.approx(effort) and not drive.acceleration
        assert drive.target_position == pytest.approx(target, abs=1e-6), name
    assert i_shoulder == pytest.approx(0.3473, abs=1e-4) and i_elbow == pytest.approx(0.0404, abs=1e-4)
    assert outcome.lines[0].startswith("articulation root: moved from /arm/Geometry/base to /arm")


def test_the_links_are_authored_at_home_with_the_joint_states(tmp_path):
    """Given --home shoulder 0.4, elbow -1.1: every link's world pose is the numpy reference's forward
    kinematics, and each joint's state:*:physics:position says the same value."""
    outcome, description, stage = processed(tmp_path, Options(home={"shoulder": 0.4, "elbow": -1.1}))
    upper, lower, finger_a, _b = reference.frames(0.4, -1.1, 0.02, 0.02)
    for path, (rotation, origin) in [("/arm/Geometry/base/upper", upper), ("/arm/Geometry/base/upper/lower", lower),
                                     ("/arm/Geometry/base/upper/lower/finger_a", finger_a)]:
        position, quaternion = description.bodies[path].pose
        assert np.allclose(position, origin, atol=1e-6), path
        x, y, z, w = quaternion
        angle = 2 * math.atan2(y, w)              # a turn about Y only
        assert abs(x) < 1e-6 and abs(z) < 1e-6 and np.allclose(reference.rot_y(angle), rotation, atol=1e-6)
    assert description.joints[JOINTS + "shoulder"].initial_position == pytest.approx(0.4, abs=1e-6)
    assert description.joints[JOINTS + "elbow"].initial_position == pytest.approx(-1.1, abs=1e-6)
    assert outcome.home[JOINTS + "finger_a_joint"] == pytest.approx(0.02)     # the range middle
    assert any(line.startswith("drive elbow:") and "home -63.03 deg (--home)" in line for line in outcome.lines)


@pytest.mark.parametrize("home, message", [
    ({"wrist": 0.1}, "--home: no movable joint named wrist (joints: elbow, finger_a_joint, finger_b_joint, shoulder)"),
    ({"elbow": 1.5}, "home of elbow: 1.5 is outside its range [-2.0944, 1.0472]"),
])
def test_a_home_naming_no_joint_or_outside_its_range_is_bad_input(tmp_path, home, message):
    with pytest.raises(BadInput) as caught:
        processed(tmp_path, Options(home=home))
    assert str(caught.value) == message


def test_a_mimic_joint_is_listed_as_dropped_never_silently(tmp_path):
    outcome, _description, _stage = processed(tmp_path)
    assert outcome.dropped == [
        "mimic joint /arm/Physics/finger_b_joint (follows finger_a_joint): coupling dropped, driven on its own"]


def test_mjcf_servos_give_their_gains_and_everything_else_is_listed(tmp_path):
    """kp 400 / kv 20 / +-50 N m on the shoulder; kp 200 with kv 0 on the elbow takes the joint's damping (3);
    the keyframe 'home' (not the first, 'rest') sets the pose; a motor, an actuator on a tendon, the tendon,
    the equality, the mimic, the sensor and the unused keyframe are each one line."""
    outcome, description, _stage = processed(tmp_path, mjcf=True)
    shoulder, elbow = description.joints[JOINTS + "shoulder"].drive, description.joints[JOINTS + "elbow"].drive
    assert (shoulder.stiffness, shoulder.damping, shoulder.max_force) == pytest.approx((400.0, 20.0, 50.0))
    assert (elbow.stiffness, elbow.damping, elbow.max_force) == pytest.approx((200.0, 3.0, math.inf))
    assert (shoulder.target_position, elbow.target_position) == pytest.approx((0.3, -0.6), abs=1e-6)
    finger = description.joints[JOINTS + "finger_a_joint"].drive      # the motor maps to nothing: the rule
    assert finger.stiffness == pytest.approx(0.25 * OMEGA ** 2, rel=1e-5)
    assert finger.target_position == pytest.approx(0.01, abs=1e-7)
    assert outcome.dropped == [
        "equality constraint on /arm/Physics/elbow (MjcEqualityJointAPI): dropped, the joint moves on its own",
        "mimic joint /arm/Physics/finger_b_joint (follows finger_a_joint): coupling dropped, driven on its own",
        "tendon /arm/Physics/coupled: dropped (its joints move independently)",
        "MjcActuator /arm/Physics/finger_motor: not mapped (not a position servo (no kp)); "
        "finger_a_joint gets the rule's drive",
        "MjcActuator /arm/Physics/tendon_act: not mapped (on a tendon); nothing drives it",
        "keyframe rest: dropped (only the home pose is kept)",
        "sensor shoulder_pos (jointpos): dropped (graphflow reads joint and body state through its own nodes)",
    ]
    assert any("(MjcActuator shoulder_act)" in line and "home 17.19 deg (keyframe home)" in line
               for line in outcome.lines)
