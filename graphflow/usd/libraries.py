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

NEEDS_EFFORT = "needs measured joint efforts, which graphflow's world does not report yet"
NOT_YET = "not carried over yet"
HOST = "reads the host machine (environment, files, wall clock): not reproducible, so not carried over"
SERVICES = "ROS 2 services (request/response) are not on graphflow's topic bus yet"
TEST_ONLY = "Isaac's internal test node"
EDITOR = "sets up a robot in the editor, not at run time"
EVENTS = "Kit application and message-bus events do not exist in a headless graphflow run"
PRIM_EDIT = "changes the stage's prims while running, which graphflow's world does not do"
BUNDLES = "works on Kit attribute bundles, which graphflow does not have"

_ISAAC_CORE = "isaacsim.core.nodes"
_ROS2 = "isaacsim.ros2.bridge"
_WHEELED = "isaacsim.robot.wheeled_robots"
_SENSORS = "isaacsim.sensors.physics"


def _ids(prefix: str, names: dict[str, str | None]) -> dict[str, str | None]:
    return {f"{prefix}.{name}": why for name, why in names.items()}


LIBRARIES: dict[str, dict[str, str | None]] = {
    "omni.graph.action": _ids("omni.graph.action", {
        "AddPrimRelationship": PRIM_EDIT, "Branch": None, "Countdown": None, "Counter": None, "Delay": None,
        "ExitApplication": EVENTS, "FlipFlop": None, "ForEach": None, "ForLoop": None, "Gate": None,
        "Multigate": NOT_YET, "Multisequence": None, "OnClosing": EVENTS, "OnCustomEvent": EVENTS,
        "OnGamepadInput": None, "OnImpulseEvent": None, "OnKeyboardInput": None, "OnLoaded": None,
        "OnMessageBusEvent": EVENTS, "OnMouseInput": "needs Kit's viewport mouse (no GUI headless)",
        "OnObjectChange": NOT_YET, "OnPlaybackTick": None, "OnStageEvent": None, "OnTick": None,
        "OnVariableChange": None, "Once": None, "RationalTimeSyncGate": NOT_YET, "SendCustomEvent": EVENTS,
        "SendMessageBusEvent": EVENTS, "Sequence": None, "SetPrimActive": PRIM_EDIT, "SwitchToken": None,
        "SyncGate": NOT_YET}),
    "omni.graph.nodes": _ids("omni.graph.nodes", {
        "Add": None, "ArrayGetSize": None, "ArrayIndex": None, "BooleanAnd": None, "BooleanNot": None,
        "BooleanOr": None, "BreakVector3": None, "BreakVector4": None, "Clamp": None, "Compare": None,
        "ConstantBool": None, "ConstantDouble": None, "ConstantDouble2": None, "ConstantDouble3": None,
        "ConstantFloat": None, "ConstantFloat2": None, "ConstantFloat3": None, "ConstantInt": None,
        "ConstantInt64": None, "ConstantPath": None, "ConstantPoint3d": None, "ConstantPrims": None,
        "ConstantQuatd": None, "ConstantString": None, "ConstantToken": None, "ConstantUInt": None,
        "ConstantUInt64": None, "ConstantVector3d": None, "ConstructArray": None, "Divide": None,
        "FindPrims": None, "GetPrimPaths": None, "GetPrimsAtPath": None, "Increment": None, "MakeVector3": None,
        "MakeVector4": None, "Maximum": None, "Minimum": None, "Modulo": None, "Multiply": None,
        "ReadGamepadState": None, "ReadKeyboardState": None, "ReadPrim": BUNDLES, "ReadPrimAttribute": None,
        "RotateVector": None, "Subtract": None, "ToDouble": None, "ToString": None, "ToToken": None,
        "WritePrimAttribute": None}),
    "isaacsim.core.nodes": _ids(_ISAAC_CORE, {
        "IsaacArticulationController": None, "IsaacArticulationState": None,
        "IsaacAttachHydraTexture": None, "IsaacComputeOdometry": None, "IsaacComputeTransformTree": None,
        "IsaacConvertDepthToPointCloud": None, "IsaacConvertRGBAToRGB": None, "IsaacCreateRenderProduct": None,
        "IsaacCreateViewport": None, "IsaacGenerate32FC1": None, "IsaacGenerateRGBA": None,
        "IsaacGetViewportRenderProduct": None, "IsaacJointNameResolver": NOT_YET,
        "IsaacPassthroughImagePtr": None, "IsaacReadCameraInfo": None, "IsaacReadEnvVar": HOST,
        "IsaacReadFilePath": HOST, "IsaacReadSimulationTime": None, "IsaacReadSimulationTimeAnnotator": None,
        "IsaacReadSystemTime": HOST, "IsaacReadSystemTimeAnnotator": None, "IsaacReadWorldPose": None,
        "IsaacRealTimeFactor": HOST, "IsaacSetCameraOnRenderProduct": None, "IsaacSetViewportResolution": None,
        "IsaacSimulationGate": None, "IsaacTestNode": TEST_ONLY, "IsaacTimeSplitter": None,
        "OgnIsaacRunOneSimulationFrame": None, "OgnIsaacScaleToFromStageUnit": None, "OnPhysicsStep": None}),
    "isaacsim.ros2.bridge / isaacsim.ros2.nodes": _ids(_ROS2, {
        "OgnROS2ServiceClient": SERVICES, "OgnROS2ServiceServerRequest": SERVICES,
        "OgnROS2ServiceServerResponse": SERVICES, "ROS2CameraHelper": None, "ROS2CameraInfoHelper": None,
        "ROS2Context": None, "ROS2PublishAckermannDrive": "ackermann_msgs is not among the standard message types",
        "ROS2PublishBbox2D": None, "ROS2PublishBbox3D": None, "ROS2PublishCameraInfo": None,
        "ROS2PublishClock": None, "ROS2PublishCompressedImage": None, "ROS2PublishImage": None,
        "ROS2PublishImu": None, "ROS2PublishJointState": None, "ROS2PublishLaserScan": None,
        "ROS2PublishObjectIdMap": None, "ROS2PublishOdometry": None, "ROS2PublishPointCloud": None,
        "ROS2PublishRawTransformTree": None, "ROS2PublishSemanticLabels": None, "ROS2PublishTransformTree": None,
        "ROS2Publisher": None, "ROS2QoSProfile": None, "ROS2RtxLidarHelper": None,
        "ROS2RtxLidarPointCloudConfig": None, "ROS2RtxRadarHelper": None, "ROS2ServicePrim": SERVICES,
        "ROS2SubscribeAckermannDrive": "ackermann_msgs is not among the standard message types",
        "ROS2SubscribeClock": None, "ROS2SubscribeJointState": None, "ROS2SubscribeTransformTree": NOT_YET,
        "ROS2SubscribeTwist": None, "ROS2Subscriber": None}),
    "isaacsim.robot.wheeled_robots": _ids(_WHEELED, {
        "AckermannController": None, "CheckGoal2D": None, "DifferentialController": None, "HolonomicController": None,
        "HolonomicRobotUsdSetup": EDITOR, "QuinticPathPlanner": NOT_YET,
        "StanleyControlPID": NOT_YET}),
    "isaacsim.sensors.physics": _ids(_SENSORS, {
        "IsaacReadContactSensor": None, "IsaacReadEffortSensor": NEEDS_EFFORT, "IsaacReadIMU": None,
        "IsaacReadJointState": NOT_YET, "IsaacReadRaycastSensor": NOT_YET}),
    "isaacsim.robot.surface_gripper": {"isaacsim.robot.surface_gripper.SurfaceGripper": None},
    "isaacsim.asset.gen.conveyor": {"isaacsim.asset.gen.conveyor.IsaacConveyor": None},
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
        lines += [f"### {library}", "", ", ".join(f"{count} {state}" for state, count in counts.items()) + ".", "",
                  "| node type | coverage | notes |", "|---|---|---|"]
        for row in rows:
            notes = row.why if row.state != IMPLEMENTED else (
                (f"as `{row.why}`" if row.why else "") + ("; also " + ", ".join(f"`{a}`" for a in row.aliases)
                                                          if row.aliases else ""))
            lines.append(f"| `{row.type_id}` | {row.state} | {notes.lstrip('; ')} |")
        lines.append("")
    return lines
