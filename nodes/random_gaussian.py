"""omni.graph.nodes.RandomGaussian: normally (or log-normally) distributed random numbers.

mean and stdev may be numbers, vectors, matrices or arrays of them; the lower
one is broadcast over the other, one draw per element, as Kit. With neither
set the node draws one double from the standard normal (Kit's default). useLog
draws exp(N(mean, stdev)): mean and stdev are those of the underlying normal.
Draws follow graphflow's reproducible Random* contract (see nodes/_random.py).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise
from graphflow_nodes._random import compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomGaussian",
    version=1,
    description=(
        "On each execIn, outputs:random = a draw from the normal distribution N(mean, stdev) per element "
        "(log-normal exp(N(mean, stdev)) with useLog), the lower-dimension input broadcast over the other; "
        "with mean and stdev unset, one standard normal double. useSeed: the draws follow inputs:seed; "
        "otherwise the run's seed (graphflow run --seed) and the node's name, so a run repeats exactly; "
        "isNoise: the same value for a given seed every time. (Kit's generator is not published: values "
        "differ from Kit's.)"),
    categories=("math:operator",),
    ui_name="Random Gaussian",
    inputs=(
        Attribute("execIn", "execution", description="Draws a new value"),
        Attribute("isNoise", "bool", default=False, description="Always output the value of the given seed"),
        Attribute("mean", "any", optional=True, description="The mean(s): a number, vector, or array of them"),
        Attribute("stdev", "any", optional=True,
                  description="The standard deviation(s): a number, vector, or array of them"),
        Attribute("seed", "uint64", default=0, description="The seed used when useSeed (or isNoise) is set"),
        Attribute("useSeed", "bool", default=False, description="Draw from inputs:seed instead of the run's seed"),
        Attribute("useLog", "bool", default=False, description="Draw from the log-normal distribution instead"),
    ),
    outputs=(
        Attribute("execOut", "execution", description="Fires after each draw"),
        Attribute("random", "any", description="The random value(s), shaped as mean and stdev"),
    ),
    state=(
        Attribute("draws", "int", default=0, description="Values drawn so far"),
    ),
)


def compute(db):
    mean, stdev = db.inputs.mean, db.inputs.stdev
    if mean is None and stdev is None:
        compute_random(db, lambda rng: rng.gauss(0.0, 1.0))
        return
    operands = [0.0 if mean is None else mean, 1.0 if stdev is None else stdev]

    def draw(rng):
        sample = rng.lognormvariate if db.inputs.useLog else rng.gauss
        return elementwise(lambda m, s: sample(float(m), float(s)), operands, ("mean", "stdev"))

    try:
        compute_random(db, draw)
    except MathError as error:
        db.error(str(error))
