"""The shared compute of Kit's Random* nodes: reproducible draws, one per execIn.

Not a node type. Kit's reference does not publish its generator, so values
differ from Kit's; what carries over is the contract: useSeed draws a fixed
sequence from inputs:seed; without it the sequence comes from the run's seed
(``graphflow run --seed``) and the node's name, so the same run gives the same
values and two nodes differ; isNoise gives the same value on every compute for
a given seed. Draw k comes from Python's Mersenne Twister seeded with the text
"seed:k" (the state is the draw count, so a reset starts the sequence again).
"""
import random

from graphflow.seeding import run_seed
from graphflow.spec import Attribute
from graphflow.types import ExecState

# the ports every Random* node has, named in each node's SPEC
EXEC_IN = Attribute("execIn", "execution", description="Draws a new value")
IS_NOISE = Attribute("isNoise", "bool", default=False, description="Always output the value of the given seed")
SEED = Attribute("seed", "uint64", default=0, description="The seed used when useSeed (or isNoise) is set")
USE_SEED = Attribute("useSeed", "bool", default=False, description="Draw from inputs:seed instead of the run's seed")
EXEC_OUT = Attribute("execOut", "execution", description="Fires after each draw")
DRAWS = Attribute("draws", "int", default=0, description="Values drawn so far")
SEEDING = ("useSeed: the draws follow inputs:seed; otherwise the run's seed (graphflow run --seed) and the node's "
           "name, so a run repeats exactly; isNoise: the same value for a given seed every time. (Kit's generator "
           "is not published: values differ from Kit's.)")


def compute_random(db, draw) -> None:
    """outputs:random = draw(generator) and fire execOut, on each execIn."""
    if db.inputs.execIn != ExecState.ENABLED:
        return
    seeded = db.inputs.useSeed or db.inputs.isNoise
    seed = db.inputs.seed if seeded else f"run {run_seed()} {db.node_name}"
    draws = 0 if db.inputs.isNoise else db.state.draws
    db.outputs.random = draw(random.Random(f"{seed}:{draws}"))
    db.state.draws = draws + 1
    db.outputs.execOut = ExecState.ENABLED
