"""omni.graph.nodes.SourceIndices: decode run starts into the source index of every target slot."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.SourceIndices",
    version=1,
    description=(
        "outputs:sourceIndices has sourceStartsInTarget[-1] entries: slot t holds the source i whose run "
        "[sourceStartsInTarget[i], sourceStartsInTarget[i+1]) contains t (the first entry is not read: slots "
        "before sourceStartsInTarget[1] are source 0). [1, 2, 3, 5, 6, 6] gives [0, 0, 1, 2, 2, 3]: Kit's "
        "reference page says [0, 0, 2, 3, 3, 3] in its prose, which its own rule does not produce. Fewer than "
        "two entries, or a negative last entry, give an empty array."),
    categories=("math:operator",),
    ui_name="Extract Source Index Array",
    inputs=(
        Attribute("sourceStartsInTarget", "int[]", default=(),
                  description="Where each source's run of target slots ends (the last entry: the output size)"),
    ),
    outputs=(
        Attribute("sourceIndices", "int[]", description="The source index of every target slot"),
    ),
)


def compute(db):
    starts = db.inputs.sourceStartsInTarget
    size = starts[-1] if len(starts) > 1 else -1
    if size < 0:
        db.outputs.sourceIndices = ()
        return
    indices = [0] * size
    slot = 0
    for source, end in enumerate(starts[1:]):
        while slot < min(end, size):
            indices[slot] = source
            slot += 1
    db.outputs.sourceIndices = tuple(indices)
