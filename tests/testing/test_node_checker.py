"""The generic node checker over every registered node type, and the checker's own findings on broken types.

How a node type is checked: every type computes on its defaults on a ClockWorld
(a graph without a stage). A type that declares a prim input (``target`` or
``path``) reads or drives the scene, so it is checked twice more with the inputs
in ``STAGE_INPUTS`` (prims of the packaged ``asset:ur10_pick_place.usda``): on a
ClockWorld it must refuse them clearly, on a fresh world of that stage it must
compute them. A new node type with a prim input needs an entry there.
"""
import pytest

from graphflow.physics import create_world
from graphflow.registry import default_registry
from graphflow.spec import Attribute, NodeSpec, NodeType
from graphflow.testing.node_checker import (
    NodeCheckError,
    check_node_type,
    spec_problems,
)
from graphflow.types import ExecState

STAGE = "asset:ur10_pick_place.usda"
UR10, EE, GRIPPER, CUBE = "/World/ur10", "/World/ur10/ee_link", "/World/ur10/ee_link/SurfaceGripper", "/World/Cube"
STAGE_INPUTS = {
    "graphflow.LegacySurfaceGripper": {"endEffectorPrim": EE},
    "graphflow.PickPlaceController": {"robotPrim": UR10, "gripperPrim": GRIPPER,
                                      "pickingPosition": [0.6, 0.0, 0.03], "placingPosition": [0.6, 0.3, 0.03]},
    "graphflow.PickPlaceSequence": {"robotPrim": UR10, "gripperPrim": GRIPPER, "objectPrims": [CUBE],
                                    "placePositions": [[0.6, 0.3, 0.03]]},
    "graphflow.StackingController": {"robotPrim": UR10, "gripperPrim": GRIPPER, "cubePrims": [CUBE],
                                     "stackPosition": [0.6, 0.3, 0.0]},
    "graphflow.ReadJointState": {"prim": UR10},
    "graphflow.ReadPrimPose": {"prim": CUBE},
    "isaacsim.core.nodes.IsaacArticulationController": {"robotPath": UR10, "positionCommand": [0.1] * 6},
    "isaacsim.robot.surface_gripper.SurfaceGripper": {"SurfaceGripper": GRIPPER},
    "omni.graph.nodes.ReadPrimAttribute": {"prim": CUBE, "name": "physics:mass"},
    "omni.graph.nodes.WritePrimAttribute": {"prim": CUBE, "name": "physics:mass", "value": 0.5},
    "isaacsim.asset.gen.conveyor.IsaacConveyor": {"conveyorPrim": CUBE},
    "isaacsim.robot.manipulators.IsaacGripperController": {"articulationRootPrim": UR10, "jointNames": ["wrist_3_joint"],
                                                           "openPosition": [0.0], "closePosition": [0.5]},
    "isaacsim.ros2.bridge.ROS2PublishJointState": {"targetPrim": UR10},
    "isaacsim.sensors.physics.IsaacReadContactSensor": {"csPrim": CUBE},
    "isaacsim.sensors.physics.IsaacReadIMU": {"imuPrim": CUBE},
    "isaacsim.core.nodes.IsaacComputeOdometry": {"chassisPrim": CUBE},
    "isaacsim.core.nodes.IsaacReadWorldPose": {"prim": CUBE},
    "isaacsim.ros2.bridge.ROS2PublishTransformTree": {"targetPrims": [UR10, CUBE]},
    "omni.graph.nodes.FindPrims": {"rootPrim": "/World", "type": "Cube"},
    "isaacsim.core.nodes.IsaacComputeTransformTree": {"targetPrims": [UR10, CUBE]},
    "isaacsim.core.nodes.IsaacArticulationState": {"targetPrim": UR10, "jointNames": ["elbow_joint"]},
    "isaacsim.sensors.physics.IsaacReadEffortSensor": {"prim": UR10 + "/wrist_2_link/wrist_3_joint"},
    "isaacsim.sensors.physics.IsaacReadJointState": {"prim": UR10},
    "isaacsim.robot.wheeled_robots.QuinticPathPlanner": {"targetPrim": CUBE},
    "omni.graph.nodes.GetPrimLocalToWorldTransform": {"prim": CUBE, "usePath": False},
    "omni.graph.nodes.ReadPrimLocalTransform": {"prim": CUBE},
    "omni.graph.nodes.WritePrimLocalTransform": {"prim": CUBE},
    "omni.graph.nodes.IsPrimActive": {"primTarget": CUBE},
    "omni.graph.nodes.IsPrimSelected": {"prim": CUBE},
    "omni.graph.action.SetPrimActive": {"primTarget": CUBE},
    "omni.graph.action.OnObjectChange": {"prim": CUBE, "name": "physics:mass"},
    "isaacsim.core.nodes.IsaacJointNameResolver": {"robotPath": UR10, "jointNames": ["elbow_joint"]},
    "omni.graph.nodes.GetPrimDirectionVector": {"prim": CUBE, "usePath": False},
    "omni.graph.nodes.ReadPrimRelationship": {"prim": UR10 + "/root_joint", "name": "physics:body1"},
    "omni.graph.nodes.ReadPrim": {"prim": CUBE, "computeBoundingBox": True},
    "omni.graph.nodes.ReadPrims": {"prims": [CUBE, UR10]},
    "omni.graph.nodes.ReadPrimsV2": {"prims": [UR10], "pathPattern": "*joint*", "typePattern": "Physics*"},
    "omni.graph.nodes.ReadPrimBundle": {"prim": [CUBE]},
    "omni.graph.nodes.ReadPrimsBundle": {"prims": [CUBE]},
    "omni.graph.nodes.ReadPrimAttributes": {"prim": CUBE},
    # stage edits (stage-21)
    "omni.graph.action.AddPrimRelationship": {"path": CUBE, "name": "custom:tags", "target": UR10},
    "omni.graph.nodes.WritePrimRelationship": {"prim": CUBE, "name": "custom:tags", "value": [UR10]},
    "omni.graph.nodes.ReadPrimMaterial": {"prim": CUBE},
    "omni.graph.nodes.GetVariantSetNames": {"prim": CUBE},
    "omni.graph.nodes.HasVariantSet": {"prim": CUBE, "variantSetName": "look"},
    "omni.graph.nodes.TranslateToLocation": {"prim": CUBE, "target": [0.6, 0.0, 0.3]},
    "omni.graph.nodes.RotateToOrientation": {"prim": CUBE, "target": [0.0, 0.0, 90.0]},
    "omni.graph.nodes.ScaleToSize": {"prim": CUBE, "target": [1.0, 1.0, 1.0]},
    "omni.graph.nodes.MoveToTransform": {"prim": CUBE},
    "omni.graph.nodes.TranslateToTarget": {"sourcePrim": CUBE, "targetPrim": EE},
    "omni.graph.nodes.RotateToTarget": {"sourcePrim": CUBE, "targetPrim": EE},
    "omni.graph.nodes.MoveToTarget": {"sourcePrim": CUBE, "targetPrim": EE},
}

# types whose prim the packaged stage lacks: on it they must refuse clearly, naming the prim
OWN_PRIM = {"isaacsim.sensors.physics.IsaacReadRaycastSensor": ({"raycastSensorPrim": CUBE}, "rayOrigins"),
            "isaacsim.robot.wheeled_robots.HolonomicRobotUsdSetup": ({"robotPrim": UR10}, "isaacmecanumwheel:angle"),
            # stage edits (stage-21): the packaged stage has no variant sets and no materials
            "omni.graph.nodes.WritePrimMaterial": ({"prim": CUBE, "materialPath": "/World/Looks/Red"}, "/World/Looks/Red"),
            **{f"omni.graph.nodes.{name}": ({"prim": CUBE, "variantSetName": "look"}, "no variant set 'look'")
               for name in ("GetVariantNames", "GetVariantSelection", "SetVariantSelection", "ClearVariantSelection",
                            "BlendVariants")}}

TYPES = default_registry().types()
# constants holding paths and path conversions pass them on without reading the scene
PATHS_ONLY = ("omni.graph.nodes.GetPrimPaths", "omni.graph.action.ForEachTarget", "omni.graph.nodes.GetTargetsSize",
              "omni.graph.nodes.GetParentPrims", "omni.graph.nodes.GetPrimPath", "omni.graph.nodes.AppendTargetPaths",
              "omni.graph.nodes.AppendTargets", "omni.graph.nodes.CompareTargets", "omni.graph.nodes.GetTargets",
              "omni.graph.nodes.InsertTargets", "omni.graph.nodes.ReplaceTargetName", "omni.graph.nodes.ReplaceTargets",
              "omni.graph.nodes.SelectTargetIf", "omni.graph.nodes.SetTarget",
              # bundle nodes whose prims pick within a bundle or name where its attributes go: no bundle, no scene
              "omni.graph.nodes.GetPrims", "omni.graph.nodes.ExtractPrim", "omni.graph.nodes.WritePrim",
              "omni.graph.nodes.WritePrimsV2")
# Kit's variable nodes declare an ignored inputs:graph target (validate.stage_names.IGNORED_TARGETS)
IGNORED_TARGETS_ONLY = ("omni.graph.core.ReadVariable", "omni.graph.core.WriteVariable")
STAGE_TYPES = [t for t in TYPES if any(a.type in ("target", "path") for a in t.spec.inputs)
               and "constants" not in t.spec.categories and t.spec.id not in PATHS_ONLY + IGNORED_TARGETS_ONLY]


@pytest.mark.parametrize("node_type", TYPES, ids=lambda t: t.spec.id)
def test_every_node_type_passes_the_checker_on_its_defaults(node_type):
    report = check_node_type(node_type)
    assert report.world == "ClockWorld"
    assert report.computed == (tuple(a.name for a in node_type.spec.exec_inputs) or ("",))


@pytest.mark.parametrize("node_type", STAGE_TYPES, ids=lambda t: t.spec.id)
def test_scene_nodes_refuse_prims_without_a_stage_and_compute_them_on_one(node_type):
    if node_type.spec.id in OWN_PRIM:
        inputs, named = OWN_PRIM[node_type.spec.id]
        with create_world(STAGE) as world:
            on_stage = check_node_type(node_type, world, inputs)
        assert on_stage.refused and all(named in message for message in on_stage.refusals.values())
        return
    inputs = STAGE_INPUTS.get(node_type.spec.id)
    assert inputs is not None, (f"{node_type.spec.id} declares a prim input: add the inputs it needs on "
                                f"{STAGE} to STAGE_INPUTS in {__file__}")
    without_stage = check_node_type(node_type, inputs=inputs)
    assert without_stage.refused and all("stage" in message for message in without_stage.refusals.values())
    with create_world(STAGE) as world:
        on_stage = check_node_type(node_type, world, inputs)
    assert on_stage.world == "PyBulletWorld" and not on_stage.refused


# -- the checker finds what is wrong -------------------------------------------------------------


def _node_type(compute=lambda db: None, initialize=None, **spec_fields) -> NodeType:
    fields = {"id": "test.Broken", "version": 1, "description": "A node type made to fail a check."}
    fields.update(spec_fields)
    return NodeType(spec=NodeSpec(**fields), compute=compute, initialize=initialize, module="tests.broken")


def _problems(node_type) -> str:
    with pytest.raises(NodeCheckError) as caught:
        check_node_type(node_type)
    return "\n".join(caught.value.problems)


def test_the_checker_rejects_malformed_specs():
    spec = NodeSpec(
        id="test.Malformed", version=0, description=" ",
        inputs=(Attribute("gain", "double", default=5.0, minimum=0.0, maximum=1.0, description="Gain"),
                Attribute("gain", "double", description="Gain again"),
                Attribute("mode", "token", default="fast", allowed_tokens=("slow", "medium"), description="Mode"),
                Attribute("count", "int", default=2, maximum=1, minimum=3, description="Count"),
                Attribute("name", "string", minimum=0.0, description="Name"),
                Attribute("class", "bool", description="")),
        state=(Attribute("pulse", "execution", description="Not a state"),))
    found = "\n".join(spec_problems(spec))
    for expected in ("version 0 is not a positive integer", "no description",
                     "inputs:gain is declared twice", "inputs:gain: the default 5.0 is out of bounds",
                     "inputs:mode: the default 'fast' is out of bounds",
                     "inputs:count: minimum 3 is above maximum 1", "inputs:name: a range on the non-numeric type",
                     "inputs:class: the name is not usable", "inputs:class: no description",
                     "state:pulse: state cannot be an execution attribute"):
        assert expected in found


def test_the_checker_rejects_a_raw_exception_but_accepts_a_clear_refusal():
    def divides(db):
        db.outputs.ratio = 1.0 / db.inputs.divisor

    def refuses(db):
        if db.inputs.divisor == 0:
            db.error("inputs:divisor is 0")
        db.outputs.ratio = 1.0 / db.inputs.divisor

    ports = {"inputs": (Attribute("divisor", "double", description="Divisor"),),
             "outputs": (Attribute("ratio", "double", description="1 / divisor"),)}
    assert "a raw ZeroDivisionError escaped compute" in _problems(_node_type(divides, **ports))
    report = check_node_type(_node_type(refuses, **ports))
    assert report.refusals == {"": "node 'node': inputs:divisor is 0"}


def test_the_checker_rejects_outputs_that_do_not_fit_and_undeclared_writes():
    def sloppy(db):
        db.outputs.position = [1.0, 2.0, 3.0]   # a list: mutable
        db.outputs.mode = "sideways"
        db.outputs.typo = 1
        db.outputs.execOut = True

    found = _problems(_node_type(
        sloppy, inputs=(Attribute("execIn", "execution", description="Go"),),
        outputs=(Attribute("position", "double[3]", description="Where"),
                 Attribute("mode", "token", allowed_tokens=("up", "down"), description="Mode"),
                 Attribute("execOut", "execution", description="Done"))))
    assert "outputs:position = [1.0, 2.0, 3.0]: values flow along connections uncopied" in found
    assert "outputs:mode = 'sideways': not one of its allowed tokens" in found
    assert "compute set undeclared outputs typo" in found
    assert "outputs:execOut = True: an exec output must hold an ExecState" in found


def test_the_checker_rejects_a_node_that_a_reset_does_not_restore():
    made = []

    def remembers_across_resets(db):   # module-level memory instead of declared state
        made.append(db.node_name)
        db.outputs.count = len(made)
        db.outputs.execOut = ExecState.ENABLED

    found = _problems(_node_type(
        remembers_across_resets, inputs=(Attribute("execIn", "execution", description="Count"),),
        outputs=(Attribute("count", "int", description="Computes so far"),
                 Attribute("execOut", "execution", description="Counted"))))
    assert "after a reset, computing (inputs:execIn pulsed) gives something else: outputs:count is 2, expected 1" in found


def test_the_checker_rejects_a_compute_that_changes_its_inputs():
    def overwrites(db):
        db.inputs.limit = 0.0

    found = _problems(_node_type(overwrites, inputs=(Attribute("limit", "double", default=1.0, description="Limit"),)))
    assert "compute changed its own inputs limit" in found
