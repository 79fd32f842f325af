"""A floating four-wheel robot built from text layers (issue 21 item 5): a scene layer, a chassis layer,
a wheels layer that references one wheel asset four times, all sublayered by a root. It simulates; the
authored values that made such a robot's links non-finite at step 1 are refused on one line naming the
prim, the attribute and the value; a layer in other units is named."""
import math
import warnings

import pytest

from graphflow.physics import StageError, UnsupportedPrimWarning, create_world

WHEELS = (("FL", 0.25, 0.25), ("FR", 0.25, -0.25), ("RL", -0.25, 0.25), ("RR", -0.25, -0.25))
RADIUS, AXLE_DROP, CHASSIS_Z = 0.1, 0.2, 0.3


def write_rover(folder, wheel_units=1.0, joint_frame="(0, 0, 0)"):
    """The rover's layers in *folder*; returns the root layer's path. The wheel asset is authored in
    *wheel_units* metres per unit (its sizes scaled to stay 0.1 m); *joint_frame*: the first wheel joint's
    localPos1."""
    header = '#usda 1.0\n(\n    metersPerUnit = {units}\n    upAxis = "Z"\n{extra})\n'
    (folder / "root.usda").write_text(header.format(
        units=1, extra='    defaultPrim = "World"\n    subLayers = [@./wheels.usda@, @./chassis.usda@, @./scene.usda@]\n'))
    (folder / "scene.usda").write_text(header.format(units=1, extra="") + '''
def Xform "World"
{
    def PhysicsScene "physicsScene" {}
    def Cube "Ground" (prepend apiSchemas = ["PhysicsCollisionAPI"])
    {
        double size = 1
        double3 xformOp:translate = (0, 0, -0.5)
        float3 xformOp:scale = (20, 20, 1)
        uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:scale"]
    }
}
''')
    (folder / "chassis.usda").write_text(header.format(units=1, extra="") + f'''
over "World"
{{
    def Xform "Rover" (prepend apiSchemas = ["PhysicsArticulationRootAPI"])
    {{
        def Xform "Chassis" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"])
        {{
            double3 xformOp:translate = (0, 0, {CHASSIS_Z})
            uniform token[] xformOpOrder = ["xformOp:translate"]
            float physics:mass = 10
            def Cube "Box" (prepend apiSchemas = ["PhysicsCollisionAPI"])
            {{
                double size = 1
                float3 xformOp:scale = (0.6, 0.4, 0.1)
                uniform token[] xformOpOrder = ["xformOp:scale"]
            }}
        }}
    }}
}}
''')
    (folder / "wheel.usda").write_text(header.format(units=wheel_units, extra='    defaultPrim = "Wheel"\n') + f'''
def Cylinder "Wheel" (prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsCollisionAPI", "PhysicsMassAPI"])
{{
    uniform token axis = "Y"
    double height = {0.05 / wheel_units:g}
    double radius = {RADIUS / wheel_units:g}
    float physics:mass = 1
}}
''')
    lines = [header.format(units=1, extra=""), 'over "World"\n{\n    over "Rover"\n    {']
    for index, (name, x, y) in enumerate(WHEELS):
        local = joint_frame if index == 0 else "(0, 0, 0)"
        lines.append(f'''        def "Wheel_{name}" (prepend references = @./wheel.usda@)
        {{
            double3 xformOp:translate = ({x}, {y}, {CHASSIS_Z - AXLE_DROP})
            uniform token[] xformOpOrder = ["xformOp:translate"]
        }}
        def PhysicsRevoluteJoint "Joint_{name}"
        {{
            rel physics:body0 = </World/Rover/Chassis>
            rel physics:body1 = </World/Rover/Wheel_{name}>
            point3f physics:localPos0 = ({x}, {y}, {-AXLE_DROP})
            point3f physics:localPos1 = {local}
            uniform token physics:axis = "Y"
        }}''')
    lines.append("    }\n}\n")
    (folder / "wheels.usda").write_text("\n".join(lines))
    return str(folder / "root.usda")


def test_the_layered_rover_rests_on_its_wheels_and_nothing_drives_it(tmp_path):
    """14 kg on four free wheels of radius 0.1 m on flat ground: no horizontal force acts, so after 4 s the
    chassis is still 0.3 m up (to 2 mm) and rolls no faster than landing left it (Bullet's cylinder contact:
    1.0 cm/s; with sphere wheels 0). The friction anchors of the wheels drove it: 0.28 m/s and 0.41 m
    after 4 s, accelerating at 0.17 m/s^2."""
    with create_world(write_rover(tmp_path)) as world:
        for _ in range(240):
            world.step()
        position = world.prim_pose("/World/Rover/Chassis")[0]
        wheel_speed = max(abs(v) for v in world.joint_velocities("/World/Rover"))
    assert all(math.isfinite(c) for c in position)
    assert position[2] == pytest.approx(CHASSIS_Z, abs=2e-3)
    assert wheel_speed * RADIUS < 0.02 and math.hypot(position[0], position[1]) < 0.06


def test_a_joint_frame_with_nan_in_a_layer_is_refused_naming_the_joint_and_the_value(tmp_path):
    """It diverged at physics step 1 ("/World/Rover/Chassis: pose or velocity is not finite")."""
    with pytest.raises(StageError, match=r"joint /World/Rover/Joint_FL: physics:localPos1 is \(nan, 0, 0\); "
                                         r"a joint frame must be finite") as caught:
        create_world(write_rover(tmp_path, joint_frame="(nan, 0, 0)"))
    assert "\n" not in str(caught.value)


def test_a_wheel_layer_in_centimetres_is_named(tmp_path):
    """USD composes a layer's values unscaled: wheels authored in cm become 100x larger in a metre stage
    (the robot was flung 95 m). The layer and its units are named."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", UnsupportedPrimWarning)
        create_world(write_rover(tmp_path, wheel_units=0.01)).close()
    assert any("wheel.usda" in str(w.message) and "metersPerUnit 0.01" in str(w.message) for w in caught)
