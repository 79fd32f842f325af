"""Transform trees for the ROS 2 tf nodes: which frames a target prim stands for, and their parents.

Not a node type. An articulation (a prim with joints under it, as Isaac's
PublishTransformTree expands it) is every rigid-body link below it, each the
child of the link its joint's body0 names; the link no joint moves hangs off
the parent frame ("world" unless a parentPrim is set). Any other prim is one
frame. Frame names are prim names, or their isaac:nameOverride when authored;
names two prims would share are made unique as each of Isaac's nodes does it
(pose_tree_namer, compute_tree_names). A camera's frame is turned to ROS's
optical convention, as Isaac's nodes turn it.
The structure is read from the world's USD stage; poses come from the world.
"""
from __future__ import annotations

from graphflow.poses import compose, relative

NAME_OVERRIDE = "isaac:nameOverride"   # a prim attribute that renames its frame
# USD cameras look down their -z with +y up, ROS optical frames down +z with +y down: Isaac turns a camera's
# frame 180 degrees about its own x axis before publishing it
OPTICAL_TURN = ((0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
WORLD_FRAME = "world"   # the tree's parent frame when no parentPrim is set, as Isaac's nodes name it (ROS's "world")


def frames(stage, target: str) -> list[tuple[str | None, str]]:
    """``(parent path or None for the tree's parent frame, child path)`` for every frame *target* stands for."""
    if stage is None:
        return [(None, target)]
    from pxr import UsdPhysics

    root = stage.GetPrimAtPath(target)
    if not root:
        return [(None, target)]
    links, parents = [], {}
    for prim in _subtree(root):
        if prim.HasAPI(UsdPhysics.RigidBodyAPI):
            links.append(str(prim.GetPath()))
        joint = UsdPhysics.Joint(prim)
        if joint:
            body0, body1 = joint.GetBody0Rel().GetTargets(), joint.GetBody1Rel().GetTargets()
            if body0 and body1:
                parents[str(body1[0])] = str(body0[0])
    if not links or not parents:
        return [(None, target)]
    return [(parents.get(link) if parents.get(link) in links else None, link) for link in links]


def _subtree(prim):
    yield prim
    for child in prim.GetChildren():
        yield from _subtree(child)


def frame_name(stage, path: str) -> str:
    """The prim's ``isaac:nameOverride`` when authored and not empty (Isaac's getName), else its name."""
    prim = stage.GetPrimAtPath(path) if stage is not None else None
    if prim:
        override = prim.GetAttribute(NAME_OVERRIDE).Get() if prim.HasAttribute(NAME_OVERRIDE) else None
        if isinstance(override, str) and override:
            return override
    return path.rstrip("/").rsplit("/", 1)[-1] or "World"


def transform(world, parent_path: str | None, child_path: str):
    """The pose of *child_path* in *parent_path*'s frame (the world's when None); a camera's frame is turned to
    ROS's optical convention."""
    child = world.prim_pose(child_path)
    if _is_camera(world.stage, child_path):
        child = compose(child, OPTICAL_TURN)
    return relative(world.prim_pose(parent_path), child) if parent_path else child


def _is_camera(stage, path: str) -> bool:
    """A USD camera that is not an RTX lidar (which Isaac models with the camera schema too)."""
    prim = stage.GetPrimAtPath(path) if stage is not None else None
    if prim is None or not prim or prim.GetTypeName() != "Camera":
        return False
    return "IsaacRtxLidarSensorAPI" not in prim.GetPrimTypeInfo().GetAppliedAPISchemas()   # also when not registered


def pose_tree_namer(stage):
    """Frame names as Isaac's ROS 2 pose tree gives them: first come, first named; a prim whose name is taken
    by another prim gets its path with '_' for '/' (without the leading one)."""
    names: dict[str, str] = {}
    taken: set[str] = set()

    def name_of(path: str) -> str:
        if path not in names:
            name = frame_name(stage, path)
            if name in taken:
                name = path.strip("/").replace("/", "_")
            names[path] = name
            taken.add(name)
        return names[path]

    return name_of


def compute_tree_names(stage, paths: list[str]) -> list[str]:
    """Frame names for *paths* as Isaac's IsaacComputeTransformTree gives them: of the prims that want one
    name (override or prim name), the deepest path keeps it; the others take their prim name, or when that
    is taken too, '<ancestor>_<prim name>' for the first ancestor below the first path component whose
    name makes it free, else the path below that component with '_' for '/'."""
    wanted = [frame_name(stage, path) for path in paths]
    keeper: dict[str, int] = {}
    for index, (path, name) in enumerate(zip(paths, wanted)):
        if name not in keeper or len(path) > len(paths[keeper[name]]):
            keeper[name] = index
    names: list[str | None] = [name if keeper[name] == index else None for index, name in enumerate(wanted)]
    first = paths[0].find("/", 1) if paths else -1
    start = first if first > 0 else 0
    for index, path in enumerate(paths):
        if names[index] is None:
            leaf = path.rsplit("/", 1)[-1]
            names[index] = _free_name(stage, path, leaf, start, names) if leaf in names else leaf
    return [name or "" for name in names]


def _free_name(stage, path: str, leaf: str, start: int, taken) -> str:
    slash = path.find("/", start + 1)
    while slash != -1:
        ancestor = frame_name(stage, path[:slash])
        if ancestor != leaf and f"{ancestor}_{leaf}" not in taken:
            return f"{ancestor}_{leaf}"
        slash = path.find("/", slash + 1)
    return path[start:].lstrip("/").replace("/", "_")
