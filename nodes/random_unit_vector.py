"""omni.graph.nodes.RandomUnitVector: a random direction, uniform on the unit sphere."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._random import compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomUnitVector",
    version=1,
    description=(
        "On each execIn, outputs:random = a unit vector uniformly distributed on the sphere and execOut fires. useSeed: the draws follow inputs:seed; "
        "otherwise the run's seed (graphflow run --seed) and the node's name, so a run repeats exactly; isNoise: the same value "
        "for a given seed every time. (Kit's generator is not published: values differ from Kit's.)"),
    categories=("math:operator",),
    ui_name="Random Unit Vector",
    inputs=(
        Attribute("execIn", "execution", description="Draws a new value"),
        Attribute("isNoise", "bool", default=False, description="Always output the value of the given seed"),
        Attribute("seed", "uint64", default=0, description="The seed used when useSeed (or isNoise) is set"),
        Attribute("useSeed", "bool", default=False, description="Draw from inputs:seed instead of the run's seed"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after each draw"),
        Attribute("random", "vectorf[3]", description="The random unit vector"),
    ),
    state=(
        Attribute("draws", "int", default=0, description="Values drawn so far"),
    ),
)


def _unit_vector(rng):
    """Uniform on the sphere: z uniform in [-1, 1], the azimuth uniform."""
    z, azimuth = rng.uniform(-1.0, 1.0), rng.uniform(0.0, 2.0 * math.pi)
    r = math.sqrt(max(0.0, 1.0 - z * z))
    return (r * math.cos(azimuth), r * math.sin(azimuth), z)


def compute(db):
    compute_random(db, _unit_vector)
