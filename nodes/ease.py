"""omni.graph.nodes.Ease: a value eased from start to end by a normalised time."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise

FUNCTIONS = ("EaseIn", "EaseOut", "EaseInOut", "Linear", "SinIn", "SinOut", "SinInOut")

SPEC = NodeSpec(
    id="omni.graph.nodes.Ease",
    version=2,
    description=(
        "outputs:result = start + (end - start) * f(alpha), alpha clamped to [0, 1], componentwise for tuples. "
        "f: Linear a; EaseIn a^p; EaseOut 1 - (1 - a)^p; EaseInOut EaseIn on the first half and EaseOut on the "
        "second ((2a)^p / 2, then 1 - (2 - 2a)^p / 2); SinIn 1 - cos(a pi/2); SinOut sin(a pi/2); SinInOut "
        "(1 - cos(a pi)) / 2; p = blendExponent. An alpha array gives one result per alpha."),
    categories=("math:operator",),
    ui_name="Easing Function",
    inputs=(
        Attribute("alpha", "any", default=0.0, description="Normalised time in [0, 1] (float or float[])"),
        Attribute("blendExponent", "int", default=2, description="The degree p of the Ease* curves"),
        Attribute("easeFunc", "token", default="EaseInOut", allowed_tokens=FUNCTIONS, description="The easing curve"),
        Attribute("end", "any", description="The value at alpha 1"),
        Attribute("start", "any", description="The value at alpha 0"),
    ),
    outputs=(
        Attribute("result", "any", description="The eased value"),
    ),
)


def eased(name: str, a: float, p: int) -> float:
    a = min(max(a, 0.0), 1.0)
    if name == "Linear":
        return a
    if name == "EaseIn":
        return a ** p
    if name == "EaseOut":
        return 1.0 - (1.0 - a) ** p
    if name == "EaseInOut":
        return (2.0 * a) ** p / 2.0 if a < 0.5 else 1.0 - (2.0 - 2.0 * a) ** p / 2.0
    if name == "SinIn":
        return 1.0 - math.cos(a * math.pi / 2.0)
    if name == "SinOut":
        return math.sin(a * math.pi / 2.0)
    return (1.0 - math.cos(a * math.pi)) / 2.0


def compute(db):
    start, end, alpha = db.inputs.start, db.inputs.end, db.inputs.alpha
    if start is None or end is None:
        db.error("inputs:start and inputs:end need values; connect them or set values")

    def at(a):
        f = eased(db.inputs.easeFunc, float(a), db.inputs.blendExponent)
        return elementwise(lambda s, e: s + (e - s) * f, [start, end], ("start", "end"))

    try:
        db.outputs.result = tuple(at(a) for a in alpha) if isinstance(alpha, tuple) else at(alpha)
    except MathError as error:
        db.error(str(error))
