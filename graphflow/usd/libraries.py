"""The node libraries Isaac graphs draw on, type by type, and how graphflow covers each.

``LIBRARIES`` lists every node type each library publishes (Isaac Sim's
``.ogn`` files, Kit's node library reference) with, for the types graphflow
does not implement, why not. ``coverage(registry)`` joins it with the registry
and the importer's dropped renderer types (``node_mapping.RENDERING_NODES``):
each type is implemented, dropped on import (a renderer or GUI type, the rest
of the graph runs) or not implemented. docs/nodes.md's coverage tables and the
import test over every library id are generated from this.
"""
from __future__ import annotations

from dataclasses import dataclass

from graphflow.usd.node_mapping import RENDERING_NODES

REAL_TIME_FACTOR = ("its one output is simulated time over wall-clock time, which differs from run to run and "
                    "machine to machine; graphflow traces are bit-identical for the same inputs and seed, so a "
                    "wall-clock reading is not carried into a graph")

_ISAAC_CORE = "isaacsim.core.nodes"
_ROS2 = "isaacsim.ros2.bridge"
_WHEELED = "isaacsim.robot.wheeled_robots"
_SENSORS = "isaacsim.sensors.physics"


def _ids(prefix: str, names: dict[str, str | None]) -> dict[str, str | None]:
    return {f"{prefix}.{name}": why for name, why in names.items()}


LIBRARIES: dict[str, dict[str, str | None]] = {
    "omni.graph.action": _ids("omni.graph.action", {
        "AddPrimRelationship": None, "Branch": None, "Countdown": None, "Counter": None, "Delay": None,
        "ExitApplication": None, "FlipFlop": None, "ForEach": None, "ForEachTarget": None, "ForLoop": None,
        "Gate": None, "Multigate": None, "Multisequence": None, "OnClosing": None, "OnCustomEvent": None,
        "OnGamepadInput": None, "OnImpulseEvent": None, "OnKeyboardInput": None, "OnLoaded": None,
        "OnMessageBusEvent": None, "OnMouseInput": None,
        "OnObjectChange": None, "OnPlaybackTick": None, "OnStageEvent": None, "OnTick": None,
        "OnVariableChange": None, "Once": None, "RationalTimeSyncGate": None, "SendCustomEvent": None,
        "SendMessageBusEvent": None, "Sequence": None, "SetPrimActive": None, "SwitchToken": None,
        "SyncGate": None}),
    "omni.graph.nodes": _ids("omni.graph.nodes", {
        "Absolute": None, "Acos": None, "Add": None, "AnyZero": None, "AppendArray": None, "AppendPath": None,
        "AppendString": None, "AppendTargetPaths": None, "AppendTargets": None, "ArrayAppendValue": None,
        "ArrayFill": None, "ArrayFindValue": None, "ArrayGetSize": None, "ArrayIndex": None, "ArrayInsertValue": None,
        "ArrayLength": None, "ArrayRemoveIndex": None, "ArrayRemoveValue": None, "ArrayReplaceValue": None,
        "ArrayResize": None, "ArrayReverse": None, "ArrayRotate": None, "ArraySetIndex": None, "ArraySlice": None,
        "Asin": None, "Atan": None, "ATan2": None, "AttributeType": None, "BlendVariants": None,
        "BooleanAnd": None, "BooleanExpr": None, "BooleanNand": None, "BooleanNor": None, "BooleanNot": None,
        "BooleanOr": None, "BooleanXor": None, "BreakMatrix2": None, "BreakMatrix3": None, "BreakMatrix4": None,
        "BreakVector2": None, "BreakVector3": None, "BreakVector4": None, "BuildString": None,
        "BundleConstructor": None, "BundleInspector": None, "BundleToUSDA": None, "CapitalizeString": None,
        "Ceil": None, "Clamp": None, "ClearVariantSelection": None, "Compare": None, "CompareTargets": None,
        "ConstantBool": None, "ConstantColor3d": None, "ConstantColor3f": None, "ConstantColor3h": None,
        "ConstantColor4d": None, "ConstantColor4f": None, "ConstantColor4h": None, "ConstantDouble": None,
        "ConstantDouble2": None, "ConstantDouble3": None, "ConstantDouble4": None, "ConstantE": None,
        "ConstantFloat": None, "ConstantFloat2": None, "ConstantFloat3": None, "ConstantFloat4": None,
        "ConstantFrame": None, "ConstantHalf": None, "ConstantHalf2": None, "ConstantHalf3": None,
        "ConstantHalf4": None, "ConstantInt": None, "ConstantInt2": None, "ConstantInt3": None, "ConstantInt4": None,
        "ConstantInt64": None, "ConstantMatrix2d": None, "ConstantMatrix3d": None, "ConstantMatrix4d": None,
        "ConstantNormal3d": None, "ConstantNormal3f": None, "ConstantNormal3h": None, "ConstantPath": None,
        "ConstantPi": None, "ConstantPoint3d": None, "ConstantPoint3f": None, "ConstantPoint3h": None,
        "ConstantPrims": None, "ConstantQuatd": None, "ConstantQuatf": None, "ConstantQuath": None,
        "ConstantString": None, "ConstantTarget": None, "ConstantTexCoord2d": None, "ConstantTexCoord2f": None,
        "ConstantTexCoord2h": None, "ConstantTexCoord3d": None, "ConstantTexCoord3f": None,
        "ConstantTexCoord3h": None, "ConstantTimecode": None, "ConstantToken": None, "ConstantUChar": None,
        "ConstantUInt": None, "ConstantUInt64": None, "ConstantVector3d": None, "ConstantVector3f": None,
        "ConstructArray": None, "CopyAttribute": None, "Cos": None, "CreateTubeTopology": None,
        "CrossProduct": None, "CurveToFrame": None, "CurveTubePositions": None, "CurveTubeST": None,
        "Distance3D": None, "Divide": None, "DotProduct": None, "EachZero": None, "Ease": None, "EndsWith": None,
        "ExtractAttribute": None, "ExtractBundle": None, "ExtractPrim": None, "FindPrims": None,
        "Floor": None, "GetAttributeNames": None, "GetGraphTargetId": None, "GetGraphTargetPrim": None,
        "GetLocationAtDistanceOnCurve": None, "GetLocationAtDistanceOnCurve2": None,
        "GetMatrix4Quaternion": None, "GetMatrix4Rotation": None, "GetMatrix4RotationMatrix": None,
        "GetMatrix4Scale": None, "GetMatrix4Translation": None, "GetParentPath": None, "GetParentPrims": None,
        "GetPrimDirectionVector": None, "GetPrimLocalToWorldTransform": None, "GetPrimPath": None,
        "GetPrimPaths": None, "GetPrimRelationship": None, "GetPrims": None, "GetPrimsAtPath": None,
        "GetString": None, "GetStringLength": None, "GetTargets": None, "GetTargetsSize": None,
        "GetTimeline": None, "GetVariantNames": None, "GetVariantSelection": None,
        "GetVariantSetNames": None, "GpuInteropCudaEntry": None, "GpuInteropRenderProductEntry": None,
        "GraphTarget": None, "HasAttribute": None, "HasVariantSet": None, "Increment": None,
        "InsertAttribute": None, "InsertString": None, "InsertTargets": None, "Interpolator": None,
        "IsPrimActive": None, "IsPrimSelected": None, "IsZero": None, "JoinString": None,
        "LengthAlongCurve": None, "LoopTimeline": None, "Magnitude": None,
        "MakeArray": None,
        "MakeMatrix2": None, "MakeMatrix3": None, "MakeMatrix4": None, "MakeTransform": None,
        "MakeTransformLookAt": None, "MakeVector2": None, "MakeVector3": None, "MakeVector4": None,
        "MatrixMultiply": None, "Maximum": None, "Minimum": None, "Modulo": None, "MoveToTarget": None,
        "MoveToTransform": None, "Multiply": None, "Negate": None, "Noise": None, "Normalize": None,
        "NthRoot": None, "RandomBoolean": None, "RandomGaussian": None, "RandomUnitQuaternion": None,
        "RandomUnitVector": None, "ReadGamepadState": None, "ReadKeyboardState": None, "ReadMouseState": None,
        "ReadOmniGraphValue": None, "ReadPrim": None, "ReadPrimAttribute": None,
        "ReadPrimAttributes": None, "ReadPrimBundle": None, "ReadPrimLocalTransform": None,
        "ReadPrimMaterial": None, "ReadPrimRelationship": None, "ReadPrims": None, "ReadPrimsBundle": None,
        "ReadPrimsV2": None, "ReadSetting": None, "ReadTime": None, "RemoveAttribute": None,
        "RenameAttribute": None, "ReplaceString": None, "ReplaceTargetName": None, "ReplaceTargets": None,
        "RotateToOrientation": None, "RotateToTarget": None, "RotateVector": None, "Round": None,
        "RpResourceExampleHydra": None, "ScaleToSize": None, "SelectIf": None, "SelectTargetIf": None,
        "SetMatrix4Quaternion": None, "SetMatrix4Rotation": None, "SetMatrix4Scale": None,
        "SetMatrix4Translation": None, "SetTarget": None, "SetTimeline": None, "SetVariantSelection": None,
        "Sin": None, "SourceIndices": None, "StartsWith": None, "StartTimeline": None,
        "StopTimeline": None, "Subtract": None, "Tan": None, "Timer": None, "ToBool": None, "ToDeg": None,
        "ToDouble": None, "ToFloat": None, "ToHalf": None, "ToInt": None, "ToInt64": None, "ToRad": None,
        "ToString": None, "ToTarget": None, "ToToken": None, "ToUchar": None, "ToUint": None, "ToUint64": None,
        "TransformVector": None, "TranslateToLocation": None, "TranslateToTarget": None, "Transpose": None,
        "Trig": None, "WritePrim": None, "WritePrimAttribute": None, "WritePrimLocalTransform": None,
        "WritePrimMaterial": None, "WritePrimRelationship": None, "WritePrims": None,
        "WritePrimsV2": None, "WriteSetting": None}),
    "isaacsim.core.nodes": _ids(_ISAAC_CORE, {
        "IsaacArticulationController": None, "IsaacArticulationState": None,
        "IsaacAttachHydraTexture": None, "IsaacComputeOdometry": None, "IsaacComputeTransformTree": None,
        "IsaacConvertDepthToPointCloud": None, "IsaacConvertRGBAToRGB": None, "IsaacCreateRenderProduct": None,
        "IsaacCreateViewport": None, "IsaacGenerate32FC1": None, "IsaacGenerateRGBA": None,
        "IsaacGetViewportRenderProduct": None, "IsaacJointNameResolver": None,
        "IsaacPassthroughImagePtr": None, "IsaacReadCameraInfo": None, "IsaacReadEnvVar": None,
        "IsaacReadFilePath": None, "IsaacReadSimulationTime": None, "IsaacReadSimulationTimeAnnotator": None,
        "IsaacReadSystemTime": None, "IsaacReadSystemTimeAnnotator": None, "IsaacReadTimes": None, "IsaacReadWorldPose": None,
        "IsaacRealTimeFactor": REAL_TIME_FACTOR, "IsaacSetCameraOnRenderProduct": None, "IsaacSetViewportResolution": None,
        "IsaacSimulationGate": None, "IsaacTestNode": None, "IsaacTimeSplitter": None,
        "OgnIsaacRunOneSimulationFrame": None, "OgnIsaacScaleToFromStageUnit": None, "OnPhysicsStep": None}),
    "isaacsim.ros2.bridge / isaacsim.ros2.nodes": _ids(_ROS2, {
        "OgnROS2ServiceClient": None, "OgnROS2ServiceServerRequest": None,
        "OgnROS2ServiceServerResponse": None, "ROS2CameraHelper": None, "ROS2CameraInfoHelper": None,
        "ROS2Context": None, "ROS2PublishAckermannDrive": None,
        "ROS2PublishBbox2D": None, "ROS2PublishBbox3D": None, "ROS2PublishCameraInfo": None,
        "ROS2PublishClock": None, "ROS2PublishCompressedImage": None, "ROS2PublishImage": None,
        "ROS2PublishImu": None, "ROS2PublishJointState": None, "ROS2PublishLaserScan": None,
        "ROS2PublishObjectIdMap": None, "ROS2PublishOdometry": None, "ROS2PublishPointCloud": None,
        "ROS2PublishRawTransformTree": None, "ROS2PublishSemanticLabels": None, "ROS2PublishTransformTree": None,
        "ROS2Publisher": None, "ROS2QoSProfile": None, "ROS2RtxLidarHelper": None,
        "ROS2RtxLidarPointCloudConfig": None, "ROS2RtxRadarHelper": None, "ROS2ServicePrim": None,
        "ROS2SubscribeAckermannDrive": None,
        "ROS2SubscribeClock": None, "ROS2SubscribeJointState": None, "ROS2SubscribeTransformTree": None,
        "ROS2SubscribeTwist": None, "ROS2Subscriber": None}),
    "isaacsim.robot.wheeled_robots": _ids(_WHEELED, {
        "AckermannController": None, "CheckGoal2D": None, "DifferentialController": None, "HolonomicController": None,
        "HolonomicRobotUsdSetup": None, "QuinticPathPlanner": None,
        "StanleyControlPID": None}),
    "isaacsim.sensors.physics": _ids(_SENSORS, {
        "IsaacReadContactSensor": None, "IsaacReadEffortSensor": None, "IsaacReadIMU": None,
        "IsaacReadJointState": None, "IsaacReadRaycastSensor": None}),
    "isaacsim.robot.surface_gripper": {"isaacsim.robot.surface_gripper.SurfaceGripper": None},
    "isaacsim.asset.gen.conveyor": {"isaacsim.asset.gen.conveyor.IsaacConveyor": None},
}
# what a table does not show
LIBRARY_NOTES = {
    "omni.graph.nodes": (
        "Every type of Kit's omni.graph.nodes extension (and its omni.graph.nodes_core split) that Kit's node "
        "library reference lists; a graph using a type not listed here is refused on import with a line naming "
        "it (--skip-unknown drops the node)."),
}
IMPLEMENTED, DROPPED, MISSING = "implemented", "dropped on import", "not implemented"


@dataclass(frozen=True)
class Coverage:
    type_id: str
    state: str      # IMPLEMENTED, DROPPED or MISSING
    why: str        # for DROPPED and MISSING; the graphflow id when implemented under another id
    aliases: tuple[str, ...] = ()


def coverage(registry) -> dict[str, list[Coverage]]:
    """Per library, every published node type and how graphflow covers it."""
    tables = {}
    for library, types in LIBRARIES.items():
        rows = []
        for type_id, why in sorted(types.items()):
            node_type = registry.get(type_id)
            if node_type is not None:
                spec = node_type.spec
                rows.append(Coverage(type_id, IMPLEMENTED, "" if spec.id == type_id else spec.id,
                                     tuple(a for a in spec.aliases if a != type_id)))
            elif type_id in RENDERING_NODES:
                rows.append(Coverage(type_id, DROPPED, RENDERING_NODES[type_id]))
            else:
                rows.append(Coverage(type_id, MISSING, why or "not carried over yet"))
        tables[library] = rows
    return tables


def render_coverage(registry) -> list[str]:
    """docs/nodes.md's coverage section: one table per library."""
    tables = coverage(registry)
    lines = ["## Coverage of the node libraries", "",
             "Every node type the libraries Isaac graphs use publish, and what graphflow does with it "
             "(generated from `graphflow/usd/libraries.py` and the registry). Dropped types are removed "
             "on import with one line naming them; the rest of the graph runs.", ""]
    for library, rows in tables.items():
        counts = {state: sum(row.state == state for row in rows) for state in (IMPLEMENTED, DROPPED, MISSING)}
        lines += [f"### {library}", "", ", ".join(f"{count} {state}" for state, count in counts.items()) + ".", ""]
        if library in LIBRARY_NOTES:
            lines += [LIBRARY_NOTES[library], ""]
        lines += ["| node type | coverage | notes |", "|---|---|---|"]
        for row in rows:
            notes = row.why if row.state != IMPLEMENTED else (
                (f"as `{row.why}`" if row.why else "") + ("; also " + ", ".join(f"`{a}`" for a in row.aliases)
                                                          if row.aliases else ""))
            lines.append(f"| `{row.type_id}` | {row.state} | {notes.lstrip('; ')} |")
        lines.append("")
    return lines
