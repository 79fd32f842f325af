"""The shared compute of Kit's Random* nodes: reproducible draws, one per execIn.

Not a node type. Kit's reference does not publish its generator, so values
differ from Kit's; what carries over is the contract: useSeed draws a fixed
sequence from inputs:seed; without it the sequence comes from the run's seed
(``graphflow run --seed``), so the same run gives the same values; isNoise gives
the same value on every compute for a given seed. Draw k of seed s comes from
Python's Mersenne Twister seeded with "s:k" (the state is two integers).
"""
import random

from graphflow.types import ExecState


def compute_random(db, draw) -> None:
    """outputs:random = draw(generator) and fire execOut, on each execIn."""
    if db.inputs.execIn != ExecState.ENABLED:
        return
    state = db.state
    if db.inputs.useSeed or db.inputs.isNoise:
        seed = db.inputs.seed
    else:
        if not state.seeded:
            state.seed, state.seeded = random.getrandbits(63), True
        seed = state.seed
    draws = 0 if db.inputs.isNoise else state.draws
    db.outputs.random = draw(random.Random(f"{seed}:{draws}"))
    state.draws = draws + 1
    db.outputs.execOut = ExecState.ENABLED
