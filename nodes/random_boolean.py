"""omni.graph.nodes.RandomBoolean: a random bool, each with probability 1/2."""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._random import compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomBoolean",
    version=1,
    description=(
        "On each execIn, outputs:random = true or false with equal chance and execOut fires. useSeed: the draws follow inputs:seed; "
        "otherwise the run's seed (graphflow run --seed) and the node's name, so a run repeats exactly; isNoise: the same value "
        "for a given seed every time. (Kit's generator is not published: values differ from Kit's.)"),
    categories=("math:operator",),
    ui_name="Random Boolean",
    inputs=(
        Attribute("execIn", "execution", description="Draws a new value"),
        Attribute("isNoise", "bool", default=False, description="Always output the value of the given seed"),
        Attribute("seed", "uint64", default=0, description="The seed used when useSeed (or isNoise) is set"),
        Attribute("useSeed", "bool", default=False, description="Draw from inputs:seed instead of the run's seed"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after each draw"),
        Attribute("random", "bool", description="The random bool"),
    ),
    state=(
        Attribute("draws", "int", default=0, description="Values drawn so far"),
    ),
)


def compute(db):
    compute_random(db, lambda rng: rng.random() < 0.5)
