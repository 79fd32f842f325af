"""isaacsim.core.nodes.OgnIsaacScaleToFromStageUnit: metres to and from the stage's units.

The stage's ``metersPerUnit`` (1 when the graph has no stage) divides a value
in metres into stage units (toStage) or multiplies stage units into metres
(toMeters), elementwise for tuples and arrays.
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise

TO_STAGE, TO_METERS = "Convert to stage units", "Convert to meters"

SPEC = NodeSpec(
    id="isaacsim.core.nodes.OgnIsaacScaleToFromStageUnit",
    version=1,
    aliases=("omni.isaac.core_nodes.OgnIsaacScaleToFromStageUnit",),
    description=(
        "outputs:result = value in stage units (value / metersPerUnit) or in metres (value x metersPerUnit), "
        "for numbers, tuples and arrays elementwise; metersPerUnit is the stage's (1 without a stage)."),
    categories=("isaacCore",),
    ui_name="Isaac Scale To/From Stage Units",
    inputs=(
        Attribute("conversion", "token", default=TO_STAGE, allowed_tokens=(TO_STAGE, TO_METERS),
                  description="Which way to convert"),
        Attribute("value", "any", description="The value (number, tuple or array)"),
    ),
    outputs=(
        Attribute("result", "any", description="The converted value"),
    ),
)


def compute(db):
    if db.inputs.value is None:
        db.error("inputs:value has no value; connect it or set a value")
    scale = meters_per_unit(db.world)
    factor = scale if db.inputs.conversion == TO_METERS else 1.0 / scale
    try:
        db.outputs.result = elementwise(lambda x: x * factor, [db.inputs.value], ("value",))
    except MathError as error:
        db.error(str(error))


def meters_per_unit(world) -> float:
    """The stage's metersPerUnit (its authored value, else USD's 0.01 fallback; 1 without a stage)."""
    stage = getattr(world, "stage", None)
    if stage is None:
        return 1.0
    from pxr import UsdGeom

    return float(UsdGeom.GetStageMetersPerUnit(stage))
