"""omni.graph.nodes.RandomUnitQuaternion: a random rotation, uniform over rotations."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._random import compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomUnitQuaternion",
    version=1,
    description=(
        "On each execIn, outputs:random = a unit quaternion (x, y, z, w) uniformly distributed over rotations and execOut fires. useSeed: the draws follow inputs:seed; "
        "otherwise the run's seed (graphflow run --seed) and the node's name, so a run repeats exactly; isNoise: the same value "
        "for a given seed every time. (Kit's generator is not published: values differ from Kit's.)"),
    categories=("math:operator",),
    ui_name="Random Unit Quaternion",
    inputs=(
        Attribute("execIn", "execution", description="Draws a new value"),
        Attribute("isNoise", "bool", default=False, description="Always output the value of the given seed"),
        Attribute("seed", "uint64", default=0, description="The seed used when useSeed (or isNoise) is set"),
        Attribute("useSeed", "bool", default=False, description="Draw from inputs:seed instead of the run's seed"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after each draw"),
        Attribute("random", "quatf[4]", description="The random unit quaternion (x, y, z, w)"),
    ),
    state=(
        Attribute("draws", "int", default=0, description="Values drawn so far"),
    ),
)


def _unit_quaternion(rng):
    """Shoemake's method: uniform over rotations."""
    u1, u2, u3 = rng.random(), rng.random(), rng.random()
    a, b = math.sqrt(1.0 - u1), math.sqrt(u1)
    return (a * math.sin(2 * math.pi * u2), a * math.cos(2 * math.pi * u2),
            b * math.sin(2 * math.pi * u3), b * math.cos(2 * math.pi * u3))


def compute(db):
    compute_random(db, _unit_quaternion)
