"""omni.graph.nodes.RandomUnitQuaternion: a random rotation, uniform over rotations."""
import math

from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._random import DRAWS, EXEC_IN, EXEC_OUT, IS_NOISE, SEED, SEEDING, USE_SEED, compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomUnitQuaternion",
    version=1,
    description=(
        'On each execIn, outputs:random = a unit quaternion (x, y, z, w) uniformly distributed over rotations'
        ' and execOut fires. '
        + SEEDING),
    categories=("math:operator",),
    ui_name="Random Unit Quaternion",
    inputs=(
        EXEC_IN,
        IS_NOISE,
        SEED,
        USE_SEED,
    ),
    outputs=(
        EXEC_OUT,
        Attribute("random", "quatf[4]", description="The random unit quaternion (x, y, z, w)"),
    ),
    state=(
        DRAWS,
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
