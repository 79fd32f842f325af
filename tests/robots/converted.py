"""Small hand-written stages shaped as NVIDIA's converters write them, so the post-processing is tested
without the converters: a URDF-like two-link arm with a mimicked two-finger slide, visual meshes and
render materials, and the MJCF parts (actuators, tendon, equality) as prims of the converters' types.

The numbers are chosen to be checked by hand (tests/robots/reference.py does it with numpy)."""

URDF_ARM = """#usda 1.0
(
    defaultPrim = "arm"
    metersPerUnit = 1
    upAxis = "Z"
)

def Xform "arm"
{
    def Scope "Geometry"
    {
        def Xform "base" (
            prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsArticulationRootAPI", "PhysicsMassAPI"]
        )
        {
            float physics:mass = 3
            def Cube "base_collision" (
                prepend apiSchemas = ["PhysicsCollisionAPI"]
            )
            {
                double size = 0.1
                uniform token purpose = "guide"
            }
            def Mesh "base_visual" (
                prepend apiSchemas = ["MaterialBindingAPI"]
            )
            {
                int[] faceVertexCounts = [3]
                int[] faceVertexIndices = [0, 1, 2]
                point3f[] points = [(0, 0, 0), (0.1, 0, 0), (0, 0.1, 0)]
                normal3f[] normals = [(0, 0, 1), (0, 0, 1), (0, 0, 1)]
                texCoord2f[] primvars:st = [(0, 0), (1, 0), (0, 1)]
                rel material:binding = </arm/Materials/white>
            }

            def Xform "upper" (
                prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
            )
            {
                float physics:mass = 2
                point3f physics:centerOfMass = (0, 0, 0.15)
                float3 physics:diagonalInertia = (0.02, 0.02, 0.001)
                double3 xformOp:translate = (0, 0, 0.1)
                uniform token[] xformOpOrder = ["xformOp:translate"]
                def Capsule "upper_collision" (
                    prepend apiSchemas = ["PhysicsCollisionAPI", "MaterialBindingAPI"]
                )
                {
                    double radius = 0.03
                    double height = 0.24
                    double3 xformOp:translate = (0, 0, 0.15)
                    uniform token[] xformOpOrder = ["xformOp:translate"]
                    rel material:binding = </arm/Materials/white>
                    def Scope "material"
                    {
                        custom string urdf:name = "white"
                    }
                }

                def Xform "lower" (
                    prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
                )
                {
                    float physics:mass = 1
                    point3f physics:centerOfMass = (0, 0, 0.1)
                    float3 physics:diagonalInertia = (0.01, 0.01, 0.001)
                    double3 xformOp:translate = (0, 0, 0.3)
                    quatf xformOp:orient = (1, 0, 0, 0)
                    uniform token[] xformOpOrder = ["xformOp:translate", "xformOp:orient"]
                    def Sphere "lower_collision" (
                        prepend apiSchemas = ["PhysicsCollisionAPI"]
                    )
                    {
                        double radius = 0.03
                        double3 xformOp:translate = (0, 0, 0.1)
                        uniform token[] xformOpOrder = ["xformOp:translate"]
                    }

                    def Xform "finger_a" (
                        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
                    )
                    {
                        float physics:mass = 0.25
                        float3 physics:diagonalInertia = (0.0001, 0.0001, 0.0001)
                        double3 xformOp:translate = (0, 0, 0.2)
                        uniform token[] xformOpOrder = ["xformOp:translate"]
                    }

                    def Xform "finger_b" (
                        prepend apiSchemas = ["PhysicsRigidBodyAPI", "PhysicsMassAPI"]
                    )
                    {
                        float physics:mass = 0.25
                        float3 physics:diagonalInertia = (0.0001, 0.0001, 0.0001)
                        double3 xformOp:translate = (0, 0, 0.2)
                        uniform token[] xformOpOrder = ["xformOp:translate"]
                    }
                }
            }
        }
    }

    def Scope "Physics"
    {
        def PhysicsFixedJoint "root_joint"
        {
            rel physics:body0 = </arm>
            rel physics:body1 = </arm/Geometry/base>
        }

        def PhysicsRevoluteJoint "shoulder"
        {
            uniform token physics:axis = "Y"
            rel physics:body0 = </arm/Geometry/base>
            rel physics:body1 = </arm/Geometry/base/upper>
            point3f physics:localPos0 = (0, 0, 0.1)
            point3f physics:localPos1 = (0, 0, 0)
            quatf physics:localRot0 = (1, 0, 0, 0)
            quatf physics:localRot1 = (1, 0, 0, 0)
            float physics:lowerLimit = -90
            float physics:upperLimit = 90
            custom float urdf:limit:effort = 50
        }

        def PhysicsRevoluteJoint "elbow"
        {
            uniform token physics:axis = "Y"
            rel physics:body0 = </arm/Geometry/base/upper>
            rel physics:body1 = </arm/Geometry/base/upper/lower>
            point3f physics:localPos0 = (0, 0, 0.3)
            point3f physics:localPos1 = (0, 0, 0)
            quatf physics:localRot0 = (1, 0, 0, 0)
            quatf physics:localRot1 = (1, 0, 0, 0)
            float physics:lowerLimit = -120
            float physics:upperLimit = 60
            custom float urdf:limit:effort = 20
        }

        def PhysicsPrismaticJoint "finger_a_joint"
        {
            uniform token physics:axis = "X"
            rel physics:body0 = </arm/Geometry/base/upper/lower>
            rel physics:body1 = </arm/Geometry/base/upper/lower/finger_a>
            point3f physics:localPos0 = (0, 0, 0.2)
            point3f physics:localPos1 = (0, 0, 0)
            float physics:lowerLimit = 0
            float physics:upperLimit = 0.04
            custom float urdf:limit:effort = 10
        }

        def PhysicsPrismaticJoint "finger_b_joint" (
            prepend apiSchemas = ["NewtonMimicAPI"]
        )
        {
            prepend rel newton:mimicJoint = </arm/Physics/finger_a_joint>
            uniform token physics:axis = "X"
            rel physics:body0 = </arm/Geometry/base/upper/lower>
            rel physics:body1 = </arm/Geometry/base/upper/lower/finger_b>
            point3f physics:localPos0 = (0, 0, 0.2)
            point3f physics:localPos1 = (0, 0, 0)
            float physics:lowerLimit = 0
            float physics:upperLimit = 0.04
            custom float urdf:limit:effort = 10
        }
    }

    def Scope "Materials"
    {
        def Material "white"
        {
            token outputs:surface.connect = </arm/Materials/white/shader.outputs:surface>
            def Shader "shader"
            {
                uniform token info:id = "UsdPreviewSurface"
                color3f inputs:diffuseColor = (1, 1, 1)
                token outputs:surface
            }
        }
    }
}

def PhysicsScene "PhysicsScene"
{
    vector3f physics:gravityDirection = (0, 0, -1)
    float physics:gravityMagnitude = 9.81
}
"""

# The MJCF converter's prims, over the same arm: a position servo on the shoulder (kp 400, kv 20, +-50 N m),
# one without kv on the elbow (kp 200), a motor on finger a, an actuator on a tendon, a tendon, an equality.
MJCF_PARTS = """
over "arm"
{
    over "Physics"
    {
        def MjcTendon "coupled"
        {
            prepend rel mjc:path = [</arm/Physics/shoulder>, </arm/Physics/elbow>]
        }

        def MjcActuator "shoulder_act"
        {
            uniform double[] mjc:biasPrm = [0, -400, -20, 0, 0, 0, 0, 0, 0, 0]
            uniform token mjc:biasType = "affine"
            uniform token mjc:forceLimited = "true"
            uniform double mjc:forceRange:max = 50
            uniform double mjc:forceRange:min = -50
            uniform double[] mjc:gainPrm = [400, 0, 0, 0, 0, 0, 0, 0, 0, 0]
            rel mjc:target = </arm/Physics/shoulder>
        }

        def MjcActuator "elbow_act"
        {
            uniform double[] mjc:biasPrm = [0, -200, 0, 0, 0, 0, 0, 0, 0, 0]
            uniform token mjc:biasType = "affine"
            uniform double[] mjc:gainPrm = [200, 0, 0, 0, 0, 0, 0, 0, 0, 0]
            rel mjc:target = </arm/Physics/elbow>
        }

        def MjcActuator "finger_motor"
        {
            rel mjc:target = </arm/Physics/finger_a_joint>
        }

        def MjcActuator "tendon_act"
        {
            uniform double[] mjc:gainPrm = [10, 0, 0, 0, 0, 0, 0, 0, 0, 0]
            rel mjc:target = </arm/Physics/coupled>
        }

        over "elbow" (
            prepend apiSchemas = ["MjcEqualityJointAPI"]
        )
        {
        }
    }
}
"""

MJCF_SOURCE = """<mujoco model="arm">
  <default><joint damping="99"/></default>
  <worldbody>
    <body name="base">
      <body name="upper" pos="0 0 0.1">
        <joint name="shoulder" type="hinge" axis="0 1 0"/>
        <body name="lower" pos="0 0 0.3">
          <joint name="elbow" type="hinge" axis="0 1 0" damping="3"/>
          <body name="finger_a" pos="0 0 0.2"><joint name="finger_a_joint" type="slide" axis="1 0 0"/></body>
          <body name="finger_b" pos="0 0 0.2"><joint name="finger_b_joint" type="slide" axis="1 0 0"/></body>
        </body>
      </body>
    </body>
  </worldbody>
  <sensor><jointpos name="shoulder_pos" joint="shoulder"/></sensor>
  <keyframe>
    <key name="rest" qpos="0 0 0 0"/>
    <key name="home" qpos="0.3 -0.6 0.01 0.02"/>
  </keyframe>
</mujoco>
"""


def write_arm(path, mjcf: bool = False):
    """The URDF-like arm as a .usda at *path*; with *mjcf*, a layer at *path* holding the MJCF parts over the
    arm (its sublayer, beside it). Returns *path*."""
    if not mjcf:
        path.write_text(URDF_ARM)
        return path
    (path.parent / "arm_links.usda").write_text(URDF_ARM)
    header = '#usda 1.0\n(\n    defaultPrim = "arm"\n    metersPerUnit = 1\n    upAxis = "Z"\n'
    path.write_text(header + '    subLayers = [@./arm_links.usda@]\n)\n' + MJCF_PARTS)
    return path
