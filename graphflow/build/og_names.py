"""The names Isaac scripts pass to ``og.Controller`` (``og.Controller.Keys``, ``og.Type``, the enums), as graphflow
spells them: edit keys are the command names, types graphflow's type names."""
from __future__ import annotations

from graphflow.types import parse_type
from graphflow.usd.graph_parts import graphflow_type


class Keys:
    """The edit keys Isaac scripts use (``og.Controller.Keys``)."""

    CREATE_NODES = "create_nodes"
    CREATE_VARIABLES = "create_variables"
    CREATE_ATTRIBUTES = "create_attributes"
    CONNECT = "connect"
    DISCONNECT = "disconnect"
    DELETE_NODES = "delete_nodes"
    SET_VALUES = "set_values"
    DISCONNECT_ALL = "disconnect_all"
    # Kit's other keys: named so a script reaches the one line saying they are not built here
    CREATE_PRIMS = "create_prims"
    EXPOSE_PRIMS = "expose_prims"
    PROMOTE_ATTRIBUTES = "promote_attributes"


SUPPORTED = (Keys.DELETE_NODES, Keys.CREATE_VARIABLES, Keys.CREATE_NODES, Keys.CREATE_ATTRIBUTES, Keys.CONNECT,
             Keys.DISCONNECT, Keys.DISCONNECT_ALL, Keys.SET_VALUES)   # OmniGraph's order of operations within one edit


# Inputs Isaac 4.x scripts set that later versions of the node removed (the 4.x .ogn against today's):
# dropped with one line saying what replaced them.
REMOVED_INPUTS = {
    "isaacsim.core.nodes.IsaacArticulationController": {
        "usePath": "Isaac 4.x's switch between robotPath and targetPrim; since 4.5 robotPath is used when set, "
                   "else targetPrim"},
}


class GraphPipelineStage:
    """``og.GraphPipelineStage`` members scripts pass as ``pipeline_stage``."""

    GRAPH_PIPELINE_STAGE_SIMULATION = "simulation"
    GRAPH_PIPELINE_STAGE_PRERENDER = "prerender"
    GRAPH_PIPELINE_STAGE_POSTRENDER = "postrender"
    GRAPH_PIPELINE_STAGE_ONDEMAND = "ondemand"


class BaseDataType:
    """``og.BaseDataType`` members scripts pass to ``og.Type`` for variables, as graphflow type names."""

    BOOL, UCHAR, INT, UINT, INT64, UINT64 = "bool", "uchar", "int", "uint", "int64", "uint64"
    FLOAT, DOUBLE, HALF, TOKEN, PATH = "float", "double", "half", "token", "path"
    RELATIONSHIP = "target"


class AttributeRole:
    """``og.AttributeRole`` members scripts pass to ``og.Type``: how the role shows in graphflow's type name."""

    NONE = ""
    VECTOR, NORMAL, POSITION, COLOR, TEXCOORD = "vector", "normal", "point", "color", "texcoord"
    QUATERNION, MATRIX = "quat", "matrix"
    TIMECODE, TEXT, PATH, EXECUTION, TARGET, BUNDLE = "timecode", "string", "path", "execution", "target", "bundle"


_WHOLE_TYPE_ROLES = {AttributeRole.TIMECODE, AttributeRole.TEXT, AttributeRole.PATH, AttributeRole.EXECUTION,
                     AttributeRole.TARGET, AttributeRole.BUNDLE}   # the role is the whole type name
_CHARACTER_ARRAYS = {AttributeRole.TEXT, AttributeRole.PATH}        # Kit's uchar[]: one string, not an array


class Type:
    """``og.Type(base, tuple_count=1, array_depth=0, role=NONE)``: a variable's type, spelled as graph files spell it
    (``og.Type(DOUBLE, 3, 0, VECTOR)`` is ``vectord[3]``)."""

    def __init__(self, base: str, tuple_count: int = 1, array_depth: int = 0, role: str = AttributeRole.NONE):
        if role in _WHOLE_TYPE_ROLES:
            self.name = role
            array_depth -= 1 if role in _CHARACTER_ARRAYS and array_depth else 0
        else:
            prefix = f"{role}{base[0]}" if role and base in ("double", "float", "half") else base
            self.name = prefix + (f"[{tuple_count}]" if tuple_count > 1 else "")
        self.name += "[]" * array_depth

    def __str__(self) -> str:
        return self.name


def variable_type(spec: object) -> str:
    """graphflow's name for a variable type given as ``og.Type``, an OGN name (``float[3]``) or the USD name Kit
    also accepts (``float3``, ``vector3d``, ``token[]``); an unknown name is returned for the builder to refuse."""
    name = str(spec)
    try:
        parse_type(name)
        return name
    except ValueError:
        return graphflow_type(name) or name
