"""omni.graph.nodes.RandomUnitVector: a random direction, uniform on the unit sphere."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._random import DRAWS, EXEC_IN, EXEC_OUT, IS_NOISE, SEED, SEEDING, USE_SEED, compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomUnitVector",
    version=1,
    description=('On each execIn, outputs:random = a unit vector uniformly distributed on the sphere and execOut fires. '
                 + SEEDING),
    categories=("math:operator",),
    ui_name="Random Unit Vector",
    inputs=(
        EXEC_IN,
        IS_NOISE,
        SEED,
        USE_SEED,
    ),
    outputs=(
        EXEC_OUT,
        Attribute("random", "vectorf[3]", description="The random unit vector"),
    ),
    state=(
        DRAWS,
    ),
)


def _unit_vector(rng):
    """Uniform on the sphere: z uniform in [-1, 1], the azimuth uniform."""
    z, azimuth = rng.uniform(-1.0, 1.0), rng.uniform(0.0, 2.0 * math.pi)
    r = math.sqrt(max(0.0, 1.0 - z * z))
    return (r * math.cos(azimuth), r * math.sin(azimuth), z)


def compute(db):
    compute_random(db, _unit_vector)
