"""How Isaac node types graphflow runs differently are brought over on import.

* Rendering nodes (render products, camera and RTX lidar helpers) need Kit's
  renderer: they are dropped with one line each saying why, and the rest of
  the graph runs.
* Older node versions whose inputs moved: the v1 SurfaceGripper (a gripper
  built by the node from physical parameters) becomes graphflow's
  LegacySurfaceGripper with the same parameters (``onStep`` -> ``execIn``);
  its connected Close/Open pins go to a current SurfaceGripper node
  ``NAME_command`` that commands the gripper the legacy node made; the older
  PickPlaceController's robot inputs become robotPrim. Each mapping is one
  line naming what went where; inputs with no equivalent are named too.
* Isaac's generic ROS2Publisher has one dynamic input per message field;
  they are gathered into graphflow's ``messageFields`` JSON.
* Target prims must exist in the composed stage: when one does not because a
  referenced or payloaded layer could not be opened (an online NVIDIA asset,
  an author's local file), the input is kept with a line naming the prim and
  that layer, and recorded in ``settings.missingAssets`` (validate reports it,
  run fails at the node's first compute); a target no layer defines is a
  warning line.
"""
from __future__ import annotations

import json
import math
from typing import Any, Callable

RENDER_PRODUCT = "needs Kit's RTX renderer (render products do not exist headless)"
RENDERED_IMAGE = "processes rendered images (needs Kit's renderer)"
VIEWPORT = "drives a Kit viewport window (no GUI headless)"
RTX_SENSOR = "reads an RTX sensor (ray-traced by Kit's renderer)"
# the library prefixes each node type was published under: Isaac Sim 5.x and the 4.x omni.isaac ids
_CORE, _ROS2 = ("isaacsim.core.nodes", "omni.isaac.core_nodes"), ("isaacsim.ros2.bridge", "omni.isaac.ros2_bridge")
_RTX = ("isaacsim.sensors.rtx", "omni.isaac.sensor")
_RENDERING = {
    _CORE: {"IsaacCreateRenderProduct": RENDER_PRODUCT, "IsaacGetViewportRenderProduct": RENDER_PRODUCT,
            "IsaacSetCameraOnRenderProduct": RENDER_PRODUCT, "IsaacCreateViewport": VIEWPORT,
            "IsaacSetViewportResolution": VIEWPORT, "IsaacAttachHydraTexture": VIEWPORT,
            "IsaacConvertDepthToPointCloud": RENDERED_IMAGE, "IsaacConvertRGBAToRGB": RENDERED_IMAGE,
            "IsaacGenerate32FC1": RENDERED_IMAGE, "IsaacGenerateRGBA": RENDERED_IMAGE,
            "IsaacPassthroughImagePtr": RENDERED_IMAGE, "IsaacReadCameraInfo": RENDER_PRODUCT,
            "IsaacReadSimulationTimeAnnotator": RENDER_PRODUCT, "IsaacReadSystemTimeAnnotator": RENDER_PRODUCT,
            "IsaacReadTimes": "reads the times of a render result (Kit's post-render graph)"},
    _ROS2: {"ROS2CameraHelper": "publishes rendered camera images (needs Kit's renderer)",
            "ROS2CameraInfoHelper": "publishes a render product's camera info (needs Kit's renderer)",
            "ROS2RtxLidarHelper": "publishes RTX lidar scans (ray-traced by Kit's renderer)",
            "ROS2RtxLidarPointCloudConfig": RTX_SENSOR, "ROS2RtxRadarHelper": RTX_SENSOR,
            "ROS2PublishImage": RENDERED_IMAGE, "ROS2PublishCompressedImage": RENDERED_IMAGE,
            "ROS2PublishCameraInfo": RENDER_PRODUCT, "ROS2PublishBbox2D": RENDERED_IMAGE,
            "ROS2PublishBbox3D": RENDERED_IMAGE, "ROS2PublishSemanticLabels": RENDERED_IMAGE,
            "ROS2PublishObjectIdMap": RENDERED_IMAGE, "ROS2PublishPointCloud": RTX_SENSOR,
            "ROS2PublishLaserScan": RTX_SENSOR},
    ("omni.graph.nodes",): {"GpuInteropRenderProductEntry": RENDER_PRODUCT, "GpuInteropCudaEntry": RENDER_PRODUCT,
                            "RpResourceExampleHydra": "hands render-pipeline resources to Hydra (needs Kit's renderer)"},
    _RTX: {"IsaacExtractRTXSensorPointCloud": RTX_SENSOR, "IsaacComputeRTXLidarFlatScan": RTX_SENSOR,
           "IsaacCreateRTXLidarScanBuffer": RTX_SENSOR, "IsaacReadRTXLidarData": RTX_SENSOR},
}
RENDERING_NODES = {f"{prefix}.{name}": reason for prefixes, names in _RENDERING.items()
                   for prefix in prefixes for name, reason in names.items()}

SURFACE_GRIPPER_IDS = ("isaacsim.robot.surface_gripper.SurfaceGripper", "omni.isaac.surface_gripper.SurfaceGripper")
LEGACY_GRIPPER_ID = "graphflow.LegacySurfaceGripper"
# v1 input -> (LegacySurfaceGripper input, conversion)
LEGACY_GRIPPER_INPUTS: dict[str, tuple[str, Callable[[Any], Any]]] = {
    "GripThreshold": ("gripThreshold", float),
    "ForceLimit": ("forceLimit", float),
    "TorqueLimit": ("torqueLimit", float),
    "BendAngle": ("bendAngle", lambda degrees: math.radians(float(degrees))),
    "Stiffness": ("kp", float),
    "Damping": ("kd", float),
    "DisableGravity": ("disableGravity", bool),
    "ParentRigidBody": ("endEffectorPrim", list),
}
LEGACY_GRIPPER_UNMAPPED = {
    "RetryClose": "graphflow's legacy gripper closes once per command (no retry)",
    "GripPosition": "the suction point is endEffectorPrim's origin (set translate/direction for an offset)",
    "Delta": "the world's time step is used",
    "enabled": "the legacy gripper has no enable switch",
}
LEGACY_GRIPPER_COMMANDS = ("inputs:Close", "inputs:Open")
COMMAND_NODE_SUFFIX = "_command"
PICK_PLACE_ID = "graphflow.PickPlaceController"
PICK_PLACE_OLD_INPUTS = ("robotModel", "robotPrimPath", "usePath", "targetPrim")

# nodes whose per-field dynamic inputs (message fields; a service's Request:* / Response:*) become messageFields
GENERIC_PUBLISHERS = ("isaacsim.ros2.bridge.ROS2Publisher", "omni.isaac.ros2_bridge.ROS2Publisher",
                      "isaacsim.ros2.bridge.OgnROS2ServiceClient", "isaacsim.ros2.bridge.OgnROS2ServiceServerResponse",
                      "omni.graph.action.SendMessageBusEvent")
GENERIC_SUBSCRIBERS = ("isaacsim.ros2.bridge.ROS2Subscriber", "omni.isaac.ros2_bridge.ROS2Subscriber")
MESSAGE_FIELDS = "messageFields"
MESSAGE_FIELD = "graphflow.ROS2MessageField"   # reads one field of a generic subscriber's message


def message_field(subscriber: str, port: str, kept: dict, registry, nodes: list[dict], connections: list[dict],
                  where: str, notes: list[str]) -> str:
    """Kit's per-field output *port* of a generic subscriber, read from its JSON message by a ROS2MessageField node
    (added to *nodes* and *kept* once); the source to connect from."""
    field = port.split(":", 1)[1]
    name = f"{subscriber}_{field.replace(':', '_')}"
    if name not in kept:
        kept[name] = registry.get(MESSAGE_FIELD)
        nodes.append({"name": name, "type": MESSAGE_FIELD, "inputs": {"field": field}})
        connections.append({"src": f"{subscriber}.outputs:message", "dst": f"{name}.inputs:message"})
        notes.append(f"{where} output '{port}': Kit's per-field output read from outputs:message by node '{name}' "
                     f"({MESSAGE_FIELD})")
    return f"{name}.outputs:value"


def is_legacy_surface_gripper(type_id: str, version) -> bool:
    return type_id in SURFACE_GRIPPER_IDS and version is not None and int(version) == 1


def map_legacy_surface_gripper(name: str, authored: dict, where: str, notes: list[str]) -> dict:
    """Inputs of a v1 SurfaceGripper (Isaac 4.x names) as graphflow.LegacySurfaceGripper inputs; one note per input."""
    inputs = {}
    for old, value in sorted(authored.items()):
        if old in LEGACY_GRIPPER_INPUTS:
            new, convert = LEGACY_GRIPPER_INPUTS[old]
            inputs[new] = convert(value)
            shown = f"{value!r} deg -> {inputs[new]!r} rad" if old == "BendAngle" else repr(inputs[new])
            notes.append(f"{where}: v1 SurfaceGripper input '{old}' mapped to {LEGACY_GRIPPER_ID} '{new}' = {shown}")
        elif old in LEGACY_GRIPPER_UNMAPPED:
            notes.append(f"{where}: v1 SurfaceGripper input '{old}' = {value!r} not mapped: {LEGACY_GRIPPER_UNMAPPED[old]}")
        else:
            notes.append(f"{where}: v1 SurfaceGripper input '{old}' = {value!r} has no equivalent; dropped")
    return inputs


def legacy_gripper_renames(name: str) -> dict:
    """Where connections of a v1 SurfaceGripper's pins go: onStep and Closed to the legacy node, Close/Open to its
    command node."""
    command = f"{name}{COMMAND_NODE_SUFFIX}"
    return {(name, "inputs:onStep"): f"{name}.inputs:execIn", (name, "outputs:Closed"): f"{name}.outputs:isClosed",
            (name, "inputs:Close"): f"{command}.inputs:Close", (name, "inputs:Open"): f"{command}.inputs:Open"}


def legacy_gripper_command_node(name: str, where: str, notes: list[str]) -> tuple[dict, dict]:
    """The current SurfaceGripper node that takes a v1 node's Close/Open, and its link to the legacy gripper prim."""
    command = f"{name}{COMMAND_NODE_SUFFIX}"
    notes.append(f"{where}: v1 SurfaceGripper Close/Open connections mapped to a new "
                 f"{SURFACE_GRIPPER_IDS[0]} node '{command}' commanding the gripper '{name}' creates")
    return ({"name": command, "type": SURFACE_GRIPPER_IDS[0]},
            {"src": f"{name}.outputs:gripperPrim", "dst": f"{command}.inputs:SurfaceGripper"})


def map_old_pick_place(authored: dict, where: str, notes: list[str], problems: list[str]) -> dict:
    """The older IsaacPickPlaceController robot inputs (robotModel, robotPrimPath, usePath, targetPrim) as robotPrim."""
    inputs = {key: value for key, value in authored.items() if key not in PICK_PLACE_OLD_INPUTS}
    model = authored.get("robotModel", "")
    if model and model.upper() != "UR10":
        problems.append(f"{where}: input 'inputs:robotModel' = {model!r}: graphflow's PickPlaceController drives the UR10 only")
    elif "robotModel" in authored:
        notes.append(f"{where}: old PickPlaceController input 'robotModel' = {model!r} mapped: the controller drives the UR10")
    use_path = bool(authored.get("usePath", False))
    robot = [authored["robotPrimPath"]] if use_path and authored.get("robotPrimPath") else authored.get("targetPrim")
    source = "robotPrimPath (usePath true)" if use_path and authored.get("robotPrimPath") else "targetPrim"
    if robot:
        inputs["robotPrim"] = list(robot)
        notes.append(f"{where}: old PickPlaceController input '{source}' mapped to 'robotPrim' = {list(robot)!r}")
    for old in ("usePath", "robotPrimPath", "targetPrim"):
        if old in authored and not (robot and old in source):
            notes.append(f"{where}: old PickPlaceController input '{old}' = {authored[old]!r} mapped: "
                         f"{'robot chosen by ' + source if robot else 'no robot given; set robotPrim'}")
    return inputs


def gather_message_fields(fields: dict, where: str, notes: list[str]) -> str:
    """Isaac's per-field publisher inputs as the JSON of graphflow's messageFields input."""
    notes.append(f"{where}: message field inputs {', '.join(sorted(fields))} gathered into 'inputs:{MESSAGE_FIELDS}'")
    return json.dumps(fields, sort_keys=True)


def missing_target(stage, target: str) -> tuple[str, bool] | None:
    """Why *target* cannot be used and whether its layer is missing, or None when it is fine.

    A target under a reference or payload that cannot be opened (an online
    asset, an author's local file) is missing, naming that layer: the robot is
    not there to run against. A prim may exist only as an ``over`` its author
    kept while that layer is absent, which is missing the same way. A target no layer
    defines (a script adds it at run time, as Isaac's gantry sample does) is a
    warning: the user can add it with a stage that sublayers the file.
    """
    from pxr import Sdf

    exists = bool(stage.GetPrimAtPath(target))
    path = Sdf.Path(target)
    while path != Sdf.Path.absoluteRootPath and not path.isEmpty:
        prim = stage.GetPrimAtPath(path)
        layer = _unopened_layer(prim) if prim else None
        if layer:
            state = "has no definition" if exists else "is not in the stage"
            return f"prim {target} {state}: it comes from {layer} (referenced at {path}), which cannot be opened", True
        path = path.GetParentPath()
    if exists:
        return None
    return (f"prim {target} is not in the stage (no layer of this stage defines it); the node fails if it runs "
            "unless the graph gets a stage that adds it"), False


def _unopened_layer(prim) -> str | None:
    """The first reference or payload asset of *prim* that cannot be opened, as authored."""
    from pxr import Sdf

    for spec in prim.GetPrimStack():
        for list_op in (spec.referenceList, spec.payloadList):
            for item in list_op.GetAddedOrExplicitItems():
                asset = item.assetPath
                if not asset:
                    continue
                try:
                    layer = Sdf.Layer.FindOrOpenRelativeToLayer(spec.layer, asset)
                except Exception:   # usd-core raises for unreachable URLs and bad paths
                    layer = None
                if layer is None:
                    return asset
    return None
