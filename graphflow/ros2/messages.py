"""ROS 2 messages as plain dicts, checked against the standard definitions.

Message definitions come from rosbags' type store (ROS 2 Humble's standard
interfaces: std_msgs, geometry_msgs, sensor_msgs, nav_msgs, rosgraph_msgs, ...)
so no .msg text is written here. Messages travel on the bus as nested dicts
with every field present; ``complete`` fills defaults and rejects unknown
fields or wrong kinds of values, naming the field.
"""
from __future__ import annotations

import math
from functools import lru_cache

from graphflow.errors import EXTRAS, BadInput, MissingExtra

INTEGER_TYPES = {"byte", "char", "int8", "uint8", "int16", "uint16", "int32", "uint32", "int64", "uint64", "octet"}
FLOAT_TYPES = {"float32", "float64"}
STRING_TYPES = {"string", "wstring"}


class MessageError(BadInput):
    """A message or type name that does not fit the ROS 2 definitions; the text names the field."""


# message packages Isaac's bridge uses that rosbags' Humble store lacks, from their published .msg files
EXTRA_DEFINITIONS = {
    "ackermann_msgs/msg/AckermannDrive": (
        "float32 steering_angle\nfloat32 steering_angle_velocity\nfloat32 speed\nfloat32 acceleration\nfloat32 jerk\n"),
    "ackermann_msgs/msg/AckermannDriveStamped": "std_msgs/Header header\nackermann_msgs/AckermannDrive drive\n",
}


@lru_cache(maxsize=None)
def type_store():
    """rosbags' store of the standard ROS 2 (Humble) message definitions, with ``EXTRA_DEFINITIONS``."""
    try:
        from rosbags.typesys import Stores, get_types_from_msg, get_typestore
    except ImportError:
        raise MissingExtra("ROS 2 messages", "ros", EXTRAS["ros"]) from None
    store = get_typestore(Stores.ROS2_HUMBLE)
    for name, text in EXTRA_DEFINITIONS.items():
        store.register(get_types_from_msg(text, name))
    return store


def type_name(name: str) -> str:
    """``pkg/msg/Name`` for ``pkg/msg/Name`` or ``pkg/Name``; MessageError when the store has no such type."""
    parts = name.strip().split("/")
    if len(parts) == 2:
        parts = [parts[0], "msg", parts[1]]
    full = "/".join(parts)
    if len(parts) != 3 or full not in type_store().fielddefs:
        raise MessageError(f"unknown ROS 2 message type {name!r} (standard types such as "
                           "sensor_msgs/msg/JointState, geometry_msgs/msg/Twist, std_msgs/msg/String)")
    return full


def definition(name: str) -> str:
    """The message definition text with its dependencies (``ros2msg`` schema encoding, as MCAP wants it)."""
    return type_store().generate_msgdef(type_name(name), ros_version=2)[0]


def complete(name: str, message: dict | None, where: str = "message") -> dict:
    """*message* with every field of type *name*, defaults filled in; MessageError names a bad field."""
    return _complete_fields(type_name(name), message or {}, where)


def _complete_fields(full_name: str, message, where: str) -> dict:
    if not isinstance(message, dict):
        raise MessageError(f"{where}: expected an object of {full_name} fields, got {message!r}")
    _consts, fields = type_store().fielddefs[full_name]
    names = [field for field, _ in fields]
    unknown = sorted(set(message) - set(names))
    if unknown:
        raise MessageError(f"{where}: {full_name} has no field {', '.join(unknown)} (fields: {', '.join(names)})")
    return {field: _complete_value(kind, message.get(field), f"{where}.{field}") for field, kind in fields}


def _complete_value(kind, value, where: str):
    node_type, details = kind
    node_name = getattr(node_type, "name", str(node_type))
    if node_name == "BASE":
        return primitive(details[0], value, where)
    if node_name == "NAME":
        return _complete_fields(details, {} if value is None else value, where)
    element, length = details
    if value is None:
        value = []
    if isinstance(value, (str, bytes, dict)) or not hasattr(value, "__iter__"):
        raise MessageError(f"{where}: expected a list, got {value!r}")
    items = [_complete_value(element, item, f"{where}[{index}]") for index, item in enumerate(value)]
    if node_name == "ARRAY":
        if not items:
            items = [_complete_value(element, None, f"{where}[{index}]") for index in range(length)]
        if len(items) != length:
            raise MessageError(f"{where}: expected exactly {length} values, got {len(items)}")
    elif length and len(items) > length:
        raise MessageError(f"{where}: at most {length} values, got {len(items)}")
    return items


def primitive(base: str, value, where: str):
    """*value* as a ROS 2 primitive of type *base* (default when None); MessageError names *where*."""
    if base in STRING_TYPES:
        if value is None:
            return ""
        if not isinstance(value, str):
            raise MessageError(f"{where}: expected a string, got {value!r}")
        return value
    if base == "bool":
        if value is None:
            return False
        if not isinstance(value, bool):
            raise MessageError(f"{where}: expected true or false, got {value!r}")
        return value
    if value is None:
        return 0.0 if base in FLOAT_TYPES else 0
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise MessageError(f"{where}: expected a number, got {value!r}")
    if base in FLOAT_TYPES:
        return float(value)
    if not float(value).is_integer():
        raise MessageError(f"{where}: expected an integer ({base}), got {value!r}")
    return int(value)


def stamp(seconds: float) -> dict:
    """builtin_interfaces/Time for *seconds* (sec, nanosec), rounded to the nanosecond."""
    nanoseconds = round(seconds * 1e9) if math.isfinite(seconds) else 0
    return {"sec": nanoseconds // 1_000_000_000, "nanosec": nanoseconds % 1_000_000_000}


def unflatten(fields: dict) -> dict:
    """Isaac's generic-publisher attribute names (``pose:pose:position:x``) as a nested message dict."""
    nested: dict = {}
    for path, value in fields.items():
        *parents, leaf = path.split(":")
        target = nested
        for parent in parents:
            target = target.setdefault(parent, {})
        target[leaf] = value
    return nested
