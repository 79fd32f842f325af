"""omni.graph.nodes.CreateTubeTopology: the quads of tubes, rows x cols each, as mesh face counts and indices."""
from graphflow.spec import Attribute, NodeSpec

SPEC = NodeSpec(
    id="omni.graph.nodes.CreateTubeTopology",
    version=1,
    description=(
        "For each tube (rows and cols: one value each, or one per tube, or one of them single): rows x cols "
        "quads over (rows + 1) rings of cols points, numbered ring by ring (CurveTubePositions' order). The quad "
        "at ring r, column c has the points (p, p + 1, p + cols + 1, p + cols) with p = r * cols + c, the last "
        "column closing the ring (p, p - cols + 1, p + 1, p + cols); the next tube's points follow the last "
        "ring. faceVertexCounts is 4 per quad. A tube with rows < 1 or cols < 2 has no quads; row and column "
        "lists of different lengths (neither single) give empty arrays."),
    categories=("geometry:generator",),
    ui_name="Create Tube Topology",
    inputs=(
        Attribute("cols", "int[]", default=(), description="Points around each tube"),
        Attribute("rows", "int[]", default=(), description="Quad rows along each tube (its rings minus one)"),
    ),
    outputs=(
        Attribute("faceVertexCounts", "int[]", description="4 for every quad"),
        Attribute("faceVertexIndices", "int[]", description="The four point indices of every quad"),
    ),
)


def compute(db):
    rows, cols = db.inputs.rows, db.inputs.cols
    if len(cols) == 1 or len(cols) == len(rows):
        tubes = len(rows)
    elif len(rows) == 1:
        tubes = len(cols)
    else:
        db.outputs.faceVertexCounts = db.outputs.faceVertexIndices = ()
        return
    indices: list[int] = []
    point = 0
    for tube in range(tubes):
        tube_rows, tube_cols = rows[0 if len(rows) == 1 else tube], cols[0 if len(cols) == 1 else tube]
        if tube_rows <= 0 or tube_cols <= 1:
            continue
        for _row in range(tube_rows):
            for _col in range(tube_cols - 1):
                indices += (point, point + 1, point + tube_cols + 1, point + tube_cols)
                point += 1
            indices += (point, point - tube_cols + 1, point + 1, point + tube_cols)
            point += 1
        point += tube_cols
    db.outputs.faceVertexIndices = tuple(indices)
    db.outputs.faceVertexCounts = (4,) * (len(indices) // 4)
