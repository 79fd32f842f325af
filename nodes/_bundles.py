"""What the bundle nodes of omni.graph.nodes share: name lists, reading prims, Fabric's type codes.

Kit's wildcard lists (``"* ^points"``) are ``find_prims.wildcard``; plain name
lists (RenameAttribute, CopyAttribute) are separated by commas or spaces.
Reading goes through the world (``World.read_prim``), so a bundle read while
running holds the simulated pose and joint state. Fabric's type of an
attribute (AttributeType, BundleInspector) is its base type, component count,
array depth and role, packed as Kit packs them into one integer
(``base | count << 8 | depth << 16 | role << 24``).
"""
from __future__ import annotations

import math
import re

from graphflow.bundles import DERIVED, PRIM_INTERNAL, Bundle, BundleAttribute
from graphflow.node_api import NodeDb
from graphflow.types import parse_type
from graphflow.world import WorldError

from .find_prims import wildcard

PATTERN_HELP = ("space-separated wildcards ('*' any characters, '?' one character, a leading '^' excludes what "
                "it matches)")
TIME_HELP = "The time (time codes) at which to read authored USD values; NaN: USD's default time"
# Fabric's BaseDataType and AttributeRole numbers (omni/fabric/Type.h) and the role names Kit prints
BASE_TYPES = {"bool": 1, "uchar": 2, "int": 3, "uint": 4, "int64": 5, "uint64": 6, "half": 7, "float": 8,
              "double": 9, "token": 10, "path": 16}
ROLES = ("none", "vector", "normal", "position", "color", "texCoord", "quaternion", "transform", "frame",
         "timecode", "text", "appliedSchema", "primTypeName", "execution", "matrix", "objectId", "bundle", "path",
         "instancedAttribute", "ancestorPrimTypeName", "target")
_ROLE_OF_PREFIX = (("point", "position"), ("normal", "normal"), ("vector", "vector"), ("color", "color"),
                   ("texcoord", "texCoord"), ("quat", "quaternion"), ("matrix", "matrix"))


def names(text: str) -> list[str]:
    """A comma- or space-separated name list."""
    return [name for name in re.split(r"[,\s]+", text) if name]


def usd_time(value: float) -> float | None:
    """The authored-value time an input asks for: None for NaN (USD's default time)."""
    return None if math.isnan(value) else float(value)


def filtered(bundle: Bundle, patterns: str) -> Bundle:
    """*bundle* with only the prim attributes *patterns* match; the marks (sourcePrimPath, sourcePrimType) and
    what the reader derives (worldMatrix, the bbox asked for) are always kept."""
    kept = PRIM_INTERNAL + DERIVED
    return Bundle(tuple(a for a in bundle if a.name in kept or wildcard(patterns, a.name)), bundle.children)


def read(db: NodeDb, path: str, patterns: str, bounding_box: bool = False, time: float | None = None) -> Bundle:
    """One prim's bundle through the world, attributes filtered by *patterns*; a refusal fails the node."""
    try:
        return filtered(db.world.read_prim(path, bounding_box, time), patterns)
    except WorldError as error:
        db.error(str(error))


def read_all(db: NodeDb, paths, patterns: str, bounding_box: bool = False, time: float | None = None) -> Bundle:
    """A bundle with one child bundle per prim of *paths*, in order (Kit's multiple prims in a bundle)."""
    return Bundle((), tuple(read(db, path, patterns, bounding_box, time) for path in paths))


def search(db: NodeDb, roots: tuple[str, ...], path_pattern: str, type_pattern: str) -> list[str]:
    """Prims at or under *roots* (the stage's root when none) whose path and type match, in stage order."""
    stage = db.world.stage
    if stage is None:
        db.error("this graph names no stage, so there are no prims to search")
    found: list[str] = []
    for root_path in roots or ("/",):
        root = stage.GetPrimAtPath(root_path)
        if not root:
            db.error(f"no prim {root_path} on the stage to search under")
        for prim in ([root] if root_path != "/" else []) + list(_descendants(root)):
            path = str(prim.GetPath())
            if path not in found and wildcard(path_pattern, path) and wildcard(type_pattern, prim.GetTypeName()):
                found.append(path)
    return found


def _descendants(prim):
    for child in prim.GetChildren():
        yield child
        yield from _descendants(child)


def attribute(db: NodeDb, bundle: Bundle, name: str) -> BundleAttribute:
    """The attribute *name* of *bundle*, or the node fails naming what the bundle holds."""
    found = bundle.get(name)
    if found is None:
        held = ", ".join(bundle.names) or "nothing"
        db.error(f"no attribute '{name}' in the bundle (it holds: {held})")
    return found


def write(db: NodeDb, path: str, bundle: Bundle, patterns: str = "*") -> None:
    """Write the attributes of *bundle* that *patterns* match to the prim *path* through the world.

    The prim marks (sourcePrimPath, sourcePrimType) and what a reader derives (worldMatrix, bbox*) are no
    attributes of the prim and are not written; a value equal to what the world holds is left alone (a
    bundle read from the prim writes back as a no-op); any other value the world cannot honour fails the
    node, naming the attribute."""
    world = db.world
    for item in bundle:
        if item.name in PRIM_INTERNAL or item.name in DERIVED or not wildcard(patterns, item.name):
            continue
        try:
            if _same(world.get_attribute(path, item.name), item.value):
                continue
        except WorldError:
            pass
        try:
            world.set_attribute(path, item.name, item.value)
        except WorldError as error:
            db.error(f"attribute '{item.name}': {error}")


def _same(a, b) -> bool:
    """Equal values, NaN matching NaN (a value read back unchanged is no write)."""
    if isinstance(a, tuple) and isinstance(b, tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return a == b or (isinstance(a, float) and isinstance(b, float) and a != a and b != b)


def fabric_type(type_name: str) -> tuple[int, int, int, int]:
    """(base type, component count, array depth, role) of a graphflow type as Fabric stores it."""
    attr_type = parse_type(type_name)
    depth = 1 if attr_type.is_array else 0
    count = attr_type.tuple_size or 1
    if attr_type.base in ("string", "path"):     # Fabric keeps text as an array of uchar with a role
        return BASE_TYPES["uchar"], 1, depth + 1, ROLES.index("text" if attr_type.base == "string" else "path")
    if attr_type.base == "timecode":
        return BASE_TYPES["double"], 1, depth, ROLES.index("timecode")
    role = next((role for prefix, role in _ROLE_OF_PREFIX if type_name.startswith(prefix)), "none")
    return BASE_TYPES[attr_type.base], count, depth, ROLES.index(role)


def full_type(type_name: str) -> int:
    base, count, depth, role = fabric_type(type_name)
    return base | count << 8 | depth << 16 | role << 24


def base_type_name(type_name: str) -> str:
    """Fabric's name of the base type (``double`` for ``pointd[3][]``, ``uchar`` for a string)."""
    base = fabric_type(type_name)[0]
    return next(name for name, number in BASE_TYPES.items() if number == base)
