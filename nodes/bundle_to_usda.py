"""omni.graph.BundleToUSDA: a bundle written out as .usda text (for reading what a bundle holds)."""
import json
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow.types import parse_type

SPEC = NodeSpec(
    id="omni.graph.BundleToUSDA",
    version=1,
    aliases=("omni.graph.nodes.BundleToUSDA",),
    description=(
        "outputs:text = the bundle as .usda prim definitions: one prim for the bundle (and one per child "
        "bundle) holding each attribute with its USD type and, with outputValues, its value. usePrimPath names "
        "the prim after the attribute primPath (else sourcePrimPath), nested under its ancestors with "
        "outputAncestors; usePrimType types it by primType (else sourcePrimType); usePrimvarMetadata writes an "
        "attribute NAME:interpolation as the interpolation metadata of the primvar NAME."),
    categories=("bundle",),
    ui_name="Bundle to USDA Text",
    inputs=(
        Attribute("bundle", "bundle", description="The bundle to write out"),
        Attribute("outputAncestors", "bool", default=False, description="Nest the prim under its path's ancestors"),
        Attribute("outputValues", "bool", default=True, description="Write attribute values"),
        Attribute("usePrimPath", "bool", default=True, description="Name the prim after its path attribute"),
        Attribute("usePrimType", "bool", default=True, description="Type the prim by its type attribute"),
        Attribute("usePrimvarMetadata", "bool", default=True,
                  description="Write NAME:interpolation attributes as primvar metadata"),
    ),
    outputs=(
        Attribute("text", "string", description="The .usda text"),
    ),
)

MARKS = ("primPath", "primType", "sourcePrimPath", "sourcePrimType")
INTERPOLATION = ":interpolation"


def _usd_type(type_name: str) -> str:
    """graphflow's type name as USD's (``pointf[3][]`` -> ``point3f[]``, ``matrixd[16]`` -> ``matrix4d``)."""
    array = "[]" if type_name.endswith("[]") else ""
    base = type_name[:-2] if array else type_name
    if "[" not in base:
        return ("asset" if base == "path" else base) + array
    head, size = base[:-1].split("[")
    if head.startswith("quat"):
        return head + array
    if head == "matrixd":
        return f"matrix{math.isqrt(int(size))}d{array}"
    role = {"point": "point", "normal": "normal", "vector": "vector", "color": "color", "texcoord": "texCoord"}
    for prefix, usd in role.items():
        if head.startswith(prefix):
            return f"{usd}{size}{head[len(prefix):]}{array}"
    return f"{head}{size}{array}"


def _usd_value(value, type_name: str) -> str:
    attr_type = parse_type(type_name)
    if attr_type.is_array:
        element = type_name[:-2]
        return "[" + ", ".join(_usd_value(item, element) for item in value) + "]"
    if type_name.startswith("quat"):
        x, y, z, w = value
        return f"({_number(w)}, {_number(x)}, {_number(y)}, {_number(z)})"
    if type_name.startswith("matrixd"):
        size = math.isqrt(len(value))
        rows = [value[i * size:(i + 1) * size] for i in range(size)]
        return "(" + ", ".join("(" + ", ".join(_number(c) for c in row) + ")" for row in rows) + ")"
    if attr_type.tuple_size:
        return "(" + ", ".join(_number(c) for c in value) + ")"
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, str):
        return f"@{value}@" if attr_type.base == "path" else json.dumps(value)
    return _number(value)


def _number(value) -> str:
    if isinstance(value, float) and not math.isfinite(value):
        return "nan" if math.isnan(value) else ("inf" if value > 0 else "-inf")
    return repr(value)


def _prim(bundle, inputs, indent: str, index: int) -> list[str]:
    marks = {a.name: a.value for a in bundle if a.name in MARKS}
    path = marks.get("primPath") or marks.get("sourcePrimPath") or ""
    name = path.rsplit("/", 1)[-1] if inputs.usePrimPath and path else f"bundle{index}"
    prim_type = (marks.get("primType") or marks.get("sourcePrimType") or "") if inputs.usePrimType else ""
    lines = [f'{indent}def {prim_type + " " if prim_type else ""}"{name}"', f"{indent}{{"]
    shown = [a for a in bundle if a.name not in MARKS]
    interpolations = {a.name[:-len(INTERPOLATION)]: a.value for a in shown
                      if inputs.usePrimvarMetadata and a.name.endswith(INTERPOLATION)}
    for attribute in shown:
        if attribute.name[:-len(INTERPOLATION)] in interpolations and attribute.name.endswith(INTERPOLATION):
            continue
        line = f"{indent}    {_usd_type(attribute.type)} {attribute.name}"
        if inputs.outputValues:
            line += f" = {_usd_value(attribute.value, attribute.type)}"
        if attribute.name in interpolations:
            line += f' (\n{indent}        interpolation = "{interpolations[attribute.name]}"\n{indent}    )'
        lines.append(line)
    for child_index, child in enumerate(bundle.children):
        lines += _prim(child, inputs, indent + "    ", child_index)
    lines.append(f"{indent}}}")
    if inputs.outputAncestors and inputs.usePrimPath and path.count("/") > 1:
        for ancestor in reversed(path.strip("/").split("/")[:-1]):
            lines = [f'def "{ancestor}"', "{"] + ["    " + line for line in lines] + ["}"]
    return lines


def compute(db):
    db.outputs.text = "\n".join(_prim(db.inputs.bundle, db.inputs, "", 0)) + "\n"
