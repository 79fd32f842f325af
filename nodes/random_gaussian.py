"""omni.graph.nodes.RandomGaussian: normally (or log-normally) distributed random numbers.

mean and stdev may be numbers, vectors, matrices or arrays of them; the lower
one is broadcast over the other, one draw per element, as Kit. With neither
set the node draws one double from the standard normal (Kit's default). useLog
draws exp(N(mean, stdev)): mean and stdev are those of the underlying normal.
Draws follow graphflow's reproducible Random* contract (see nodes/_random.py).
"""
from graphflow.spec import Attribute, NodeSpec
from graphflow_nodes._math import MathError, elementwise
from graphflow_nodes._random import DRAWS, EXEC_IN, EXEC_OUT, IS_NOISE, SEED, SEEDING, USE_SEED, compute_random

SPEC = NodeSpec(
    id="omni.graph.nodes.RandomGaussian",
    version=1,
    description=(
        'On each execIn, outputs:random = a draw from the normal distribution N(mean, stdev) per element '
        '(log-normal exp(N(mean, stdev)) with useLog), the lower-dimension input broadcast over the other; '
        'with mean and stdev unset, one standard normal double. '
        + SEEDING),
    categories=("math:operator",),
    ui_name="Random Gaussian",
    inputs=(
        EXEC_IN,
        IS_NOISE,
        Attribute("mean", "any", optional=True, description="The mean(s): a number, vector, or array of them"),
        Attribute("stdev", "any", optional=True,
                  description="The standard deviation(s): a number, vector, or array of them"),
        SEED,
        USE_SEED,
        Attribute("useLog", "bool", default=False, description="Draw from the log-normal distribution instead"),
    ),
    outputs=(
        EXEC_OUT,
        Attribute("random", "any", description="The random value(s), shaped as mean and stdev"),
    ),
    state=(
        DRAWS,
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
