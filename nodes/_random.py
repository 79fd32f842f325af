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
from graphflow.types import ExecState


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
