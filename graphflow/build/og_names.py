"""The names Isaac scripts pass to ``og.Controller`` (``og.Controller.Keys``, ``og.Type``, the enums), as graphflow
spells them: edit keys are the command names, types graphflow's type names."""
from __future__ import annotations


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


class Type:
    """``og.Type(base, tuple_count=1, array_depth=0)``: a variable's type, spelled as graph files spell it."""

    def __init__(self, base: str, tuple_count: int = 1, array_depth: int = 0):
        self.name = base + (f"[{tuple_count}]" if tuple_count > 1 else "") + "[]" * array_depth

    def __str__(self) -> str:
        return self.name
