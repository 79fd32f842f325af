"""omni.graph.nodes.Noise: gradient (Perlin) noise of one to four dimensions, sampled at given positions.

Kit's page states the field's properties, not its function: for a seed the field is
static (a position always gives the same value), locally smooth, and zero at every
integer lattice point. This is classic gradient noise with those properties: at each
lattice corner a pseudo-random gradient drawn from the seed and the corner's
coordinates, the corners' dot products with the offset blended by Perlin's quintic
fade, scaled to lie within [-1, 1]. Kit's own function is not published, so the
values differ from Kit's, as those of the Random* nodes do.
"""
import math
from itertools import product

from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.Noise",
    version=1,
    description=(
        "outputs:result = Perlin (gradient) noise of the seed's field at position: a float for a float or a "
        "2-, 3- or 4-vector, an array of them for an array (a flat list of 2 to 4 numbers is one vector; a "
        "float[] of 2 to 4 values is given as one-number positions). The same position and seed always give the same "
        "value, small moves give small changes, integral positions give 0 (offset by 0.5 to avoid them), and "
        "every value lies in [-1, 1]. Kit's noise function is not published: values differ from Kit's."),
    categories=("math:operator",),
    ui_name="Noise",
    inputs=(
        Attribute("position", "any",
                  description="Where to sample: a float, a float[2], float[3] or float[4], or an array of them"),
        Attribute("seed", "uint", default=0, description="Which noise field to sample"),
    ),
    outputs=(
        Attribute("result", "any", description="The noise value(s): a float, or a float[] for an array"),
    ),
)

_MASK = (1 << 64) - 1


def _mix(value: int) -> int:
    """splitmix64's finaliser: every input bit flips about half of the output bits."""
    value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9 & _MASK
    value = (value ^ (value >> 27)) * 0x94D049BB133111EB & _MASK
    return value ^ (value >> 31)


def _gradient(seed: int, corner: tuple[int, ...]) -> tuple[float, ...]:
    """The corner's gradient: one 16-bit draw per axis from the hash of seed and corner, normalised (2-4 axes)."""
    hashed = _mix(seed & _MASK)
    for coordinate in corner:
        hashed = _mix(hashed ^ (coordinate & _MASK))
    components = [((hashed >> (16 * axis)) & 0xFFFF) / 32767.5 - 1.0 for axis in range(len(corner))]
    if len(components) == 1:
        return (components[0],)     # a slope in [-1, 1]: unit slopes (+-1 only) would cancel at every half
    norm = math.sqrt(sum(c * c for c in components))
    if norm == 0.0:
        return (1.0,) + (0.0,) * (len(corner) - 1)
    return tuple(c / norm for c in components)


def _fade(t: float) -> float:
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0)


def noise(position: tuple[float, ...], seed: int) -> float:
    """Gradient noise at *position* (1 to 4 numbers), within [-1, 1] (the largest blend is sqrt(d) / 2)."""
    cell = [math.floor(c) for c in position]
    offset = [c - f for c, f in zip(position, cell)]
    weights = [_fade(o) for o in offset]
    total = 0.0
    for corner in product((0, 1), repeat=len(position)):
        weight, dot = 1.0, 0.0
        gradient = _gradient(seed, tuple(f + k for f, k in zip(cell, corner)))
        for axis, k in enumerate(corner):
            weight *= weights[axis] if k else 1.0 - weights[axis]
            dot += gradient[axis] * (offset[axis] - k)
        total += weight * dot
    return max(-1.0, min(1.0, total * 2.0 / math.sqrt(len(position))))


def _sample(value, seed: int, db) -> float:
    point = (value,) if isinstance(value, (int, float)) else tuple(value)
    if not 1 <= len(point) <= 4 or not all(isinstance(c, (int, float)) for c in point):
        db.error(f"inputs:position must be a float or a 2-, 3- or 4-vector of floats, not {value!r}")
    return noise(tuple(float(c) for c in point), seed)


def _is_vector(position) -> bool:
    """One position: a number, or 2 to 4 numbers (float[2..4]); a flat run of any other length is a float[]."""
    if isinstance(position, (int, float)):
        return True
    return 2 <= len(position) <= 4 and all(isinstance(c, (int, float)) for c in position)


def compute(db):
    position, seed = db.inputs.position, int(db.inputs.seed)
    if position is None:
        db.error("inputs:position has no value: set or connect the position(s) to sample")
    if _is_vector(position):
        db.outputs.result = _sample(position, seed, db)
    else:
        db.outputs.result = tuple(_sample(point, seed, db) for point in position)
