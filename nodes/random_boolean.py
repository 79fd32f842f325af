"""omni.graph.nodes.RandomBoolean: a random bool, each with probability 1/2."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._random import DRAWS, EXEC_IN, EXEC_OUT, IS_NOISE, SEED, SEEDING, USE_SEED, compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomBoolean",
    version=1,
    description='On each execIn, outputs:random = true or false with equal chance and execOut fires. ' + SEEDING,
    categories=("math:operator",),
    ui_name="Random Boolean",
    inputs=(
        EXEC_IN,
        IS_NOISE,
        SEED,
        USE_SEED,
    ),
    outputs=(
        EXEC_OUT,
        Attribute("random", "bool", description="The random bool"),
    ),
    state=(
        DRAWS,
    ),
)


def compute(db):
    compute_random(db, lambda rng: rng.random() < 0.5)
