"""ROS 2 services on the topic bus: a request topic and a response topic per service.

Headless there is no DDS to carry a call, so a service ``/name`` is the pair of
bus topics ``/name/request`` and ``/name/response``: a client node publishes its
request on the first and takes the newest response from the second; a server
node takes requests from the first and answers on the second. A scripted
timeline can deliver requests as it delivers messages, and the trace shows
both directions.

rosbags' store holds message definitions only, no ``.srv``, so the service
types below (the standard ones Isaac's samples use) are written out from
their published ``.srv`` files; any other service type is refused by name.
"""
from __future__ import annotations

from graphflow.ros2.messages import MessageError, primitive

# service type -> (request fields, response fields); each field: (name, ROS 2 primitive type, or T[] a sequence)
SERVICE_TYPES: dict[str, tuple[tuple[tuple[str, str], ...], tuple[tuple[str, str], ...]]] = {
    "std_srvs/srv/Empty": ((), ()),
    "std_srvs/srv/SetBool": ((("data", "bool"),), (("success", "bool"), ("message", "string"))),
    "std_srvs/srv/Trigger": ((), (("success", "bool"), ("message", "string"))),
    "example_interfaces/srv/AddTwoInts": ((("a", "int64"), ("b", "int64")), (("sum", "int64"),)),
    "example_interfaces/srv/SetBool": ((("data", "bool"),), (("success", "bool"), ("message", "string"))),
    "example_interfaces/srv/Trigger": ((), (("success", "bool"), ("message", "string"))),
    # Isaac's own prim services (ROS2ServicePrim), from isaac_ros2_messages' published .srv sources
    "isaac_ros2_messages/srv/GetPrims": (
        (("path", "string"),),
        (("paths", "string[]"), ("types", "string[]"), ("success", "bool"), ("message", "string"))),
    "isaac_ros2_messages/srv/GetPrimAttributes": (
        (("path", "string"),),
        (("names", "string[]"), ("displays", "string[]"), ("types", "string[]"), ("success", "bool"),
         ("message", "string"))),
    "isaac_ros2_messages/srv/GetPrimAttribute": (
        (("path", "string"), ("attribute", "string")),
        (("value", "string"), ("type", "string"), ("success", "bool"), ("message", "string"))),
    "isaac_ros2_messages/srv/SetPrimAttribute": (
        (("path", "string"), ("attribute", "string"), ("value", "string")),
        (("success", "bool"), ("message", "string"))),
}
REQUEST, RESPONSE = "request", "response"


def service_type(package: str, subfolder: str, name: str) -> str:
    """``pkg/srv/Name`` from Isaac's three inputs; MessageError for a type graphflow does not know."""
    full = f"{package.strip()}/{subfolder.strip() or 'srv'}/{name.strip()}"
    if full not in SERVICE_TYPES:
        raise MessageError(f"unknown ROS 2 service type {full!r} (known: {', '.join(sorted(SERVICE_TYPES))})")
    return full


def topic(service: str, part: str) -> str:
    """The bus topic that carries *part* (``request`` or ``response``) of *service*."""
    return f"{service.rstrip('/')}/{part}"


def complete(full_type: str, part: str, fields: dict, where: str) -> dict:
    """*fields* as a whole request or response of *full_type*: defaults filled, unknown or mistyped refused."""
    declared = SERVICE_TYPES[full_type][0 if part == REQUEST else 1]
    if not isinstance(fields, dict):
        raise MessageError(f"{where}: expected an object of {full_type} {part} fields, got {fields!r}")
    names = [name for name, _ in declared]
    unknown = sorted(set(fields) - set(names))
    if unknown:
        raise MessageError(f"{where}: the {full_type} {part} has no field {', '.join(unknown)} "
                           f"(fields: {', '.join(names) or 'none'})")
    return {name: _field(kind, fields.get(name), f"{where}.{name}") for name, kind in declared}


def _field(kind: str, value, where: str):
    """A primitive, or for ``T[]`` a list of them (an unset sequence is empty)."""
    if not kind.endswith("[]"):
        return primitive(kind, value, where)
    if value is None:
        return []
    if not isinstance(value, (list, tuple)):
        raise MessageError(f"{where}: expected a list, got {value!r}")
    return [primitive(kind[:-2], item, f"{where}[{index}]") for index, item in enumerate(value)]


class ServiceServers:
    """Server handles of one world (a ``WorldService``): Isaac's request node hands its response node an
    opaque uint64; here it is the 1-based order in which servers first ran, the same on every run."""

    def __init__(self):
        self._servers: list[tuple[str, str]] = []

    def handle_for(self, service: str, full_type: str) -> int:
        if (service, full_type) not in self._servers:
            self._servers.append((service, full_type))
        return self._servers.index((service, full_type)) + 1

    def server(self, handle: int) -> tuple[str, str] | None:
        """(service, type) of *handle*, or None when no server has it."""
        return self._servers[handle - 1] if 1 <= handle <= len(self._servers) else None

    def after_step(self, dt: float) -> None:
        """Handles outlive steps."""

    def reset(self) -> None:
        self._servers.clear()


def servers_of(world) -> ServiceServers:
    return world.services.require(ServiceServers, ServiceServers)
