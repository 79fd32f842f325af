"""omni.graph.nodes curve and tube nodes on small curves whose answers are worked out by hand."""
import math

import pytest

from graphflow.build import og
from graphflow.executor import GraphRuntimeError
from graphflow.testing import NodeHarness
from graphflow.usd.omnigraph import import_graph


def outputs(type_id, **inputs):
    return NodeHarness(f"omni.graph.nodes.{type_id}", inputs).compute().outputs


def flat(vectors) -> list[float]:
    return [float(c) for vector in vectors for c in vector]


def test_source_indices_expand_run_ends_into_source_numbers():
    # runs end at 2, 3, 5, 6, 6: slots 0-1 are source 0, 2 source 1, 3-4 source 2, 5 source 3, none for 4
    assert outputs("SourceIndices", sourceStartsInTarget=[1, 2, 3, 5, 6, 6])["sourceIndices"] == (0, 0, 1, 2, 2, 3)
    assert outputs("SourceIndices", sourceStartsInTarget=[0, 4])["sourceIndices"] == (0, 0, 0, 0)
    assert outputs("SourceIndices", sourceStartsInTarget=[3])["sourceIndices"] == ()
    assert outputs("SourceIndices", sourceStartsInTarget=[0, -1])["sourceIndices"] == ()


def test_length_along_a_3_4_5_polyline_and_a_second_curve():
    points = [(0, 0, 0), (3, 0, 0), (3, 4, 0), (10, 10, 10), (10, 10, 12)]
    lengths = outputs("LengthAlongCurve", curvePoints=points, curveVertexStarts=[0, 3], curveVertexCounts=[3, 2])
    assert lengths["length"] == pytest.approx((0.0, 3.0, 7.0, 0.0, 2.0))
    normalized = outputs("LengthAlongCurve", curvePoints=points[:3], curveVertexStarts=[0], curveVertexCounts=[3],
                         normalize=True)
    assert normalized["length"] == pytest.approx((0.0, 3 / 7, 1.0))
    assert outputs("LengthAlongCurve", curvePoints=points)["length"] == ()


def test_curve_frames_follow_an_l_shaped_curve_without_twisting():
    frames = outputs("CurveToFrame", curvePoints=[(0, 0, 0), (1, 0, 0), (1, 1, 0)], curveVertexStarts=[0],
                     curveVertexCounts=[3])
    half = math.sqrt(0.5)
    assert flat(frames["tangent"]) == pytest.approx(flat(((1, 0, 0), (half, half, 0), (0, 1, 0))))
    # the first up is +Z (the tangent's smallest component), and a turn in the XY plane keeps it
    assert flat(frames["up"]) == pytest.approx(flat(((0, 0, 1), (0, 0, 1), (0, 0, 1))))
    # out = up x tangent at every point: +Y, then the bisector, then -X
    assert flat(frames["out"]) == pytest.approx(flat(((0, 1, 0), (-half, half, 0), (-1, 0, 0))))
    single = outputs("CurveToFrame", curvePoints=[(5, 5, 5)], curveVertexStarts=[0], curveVertexCounts=[1])
    assert (single["tangent"], single["up"], single["out"]) == (((0, 0, 1),), ((0, 1, 0),), ((1, 0, 0),))


def test_create_tube_topology_two_rows_of_three_columns():
    topology = outputs("CreateTubeTopology", rows=[2], cols=[3])
    # rings of 3 points: ring 0 = 0,1,2, ring 1 = 3,4,5, ring 2 = 6,7,8; each ring closes on itself
    assert topology["faceVertexCounts"] == (4,) * 6
    assert topology["faceVertexIndices"] == (0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5,
                                             3, 4, 7, 6, 4, 5, 8, 7, 5, 3, 6, 8)
    two_tubes = outputs("CreateTubeTopology", rows=[1, 1], cols=[2])
    assert two_tubes["faceVertexIndices"] == (0, 1, 3, 2, 1, 0, 2, 3, 4, 5, 7, 6, 5, 4, 6, 7)
    assert outputs("CreateTubeTopology", rows=[1, 2], cols=[3, 4, 5])["faceVertexIndices"] == ()


def test_tube_positions_are_rings_of_half_the_width_around_each_point():
    points = outputs("CurveTubePositions", curvePoints=[(0, 0, 0), (0, 0, 2)], curveVertexStarts=[0],
                     curveVertexCounts=[2], tubePointStarts=[0, 8], cols=[4], width=[2.0, 4.0],
                     up=[(0, 1, 0)], out=[(1, 0, 0)])["points"]
    expected = [(1, 0, 0), (0, 1, 0), (-1, 0, 0), (0, -1, 0), (2, 0, 2), (0, 2, 2), (-2, 0, 2), (0, -2, 2)]
    assert flat(points) == pytest.approx(flat(expected), abs=1e-12)
    wrong_size = outputs("CurveTubePositions", curvePoints=[(0, 0, 0), (0, 0, 2)], curveVertexStarts=[0],
                         curveVertexCounts=[2], tubePointStarts=[0, 6], cols=[4], width=[2.0], up=[(0, 1, 0)],
                         out=[(1, 0, 0)])["points"]
    assert wrong_size == ((0, 0, 0),) * 6


def test_tube_st_runs_s_around_and_t_along_with_the_seam_twice():
    st = outputs("CurveTubeST", curveVertexStarts=[0], curveVertexCounts=[2], tubeSTStarts=[0, 10],
                 tubeQuadStarts=[0, 4], cols=[4], t=[0.0, 3.0])
    assert st["primvars_st"] == tuple((s, t) for t in (0.0, 3.0) for s in (0.0, 0.25, 0.5, 0.75, 1.0))
    assert st["primvars_st_indices"] == (0, 1, 6, 5, 1, 2, 7, 6, 2, 3, 8, 7, 3, 4, 9, 8)
    # scaled like s: t over the square's perimeter, 4 sides of width * sin(pi / 4) for a tube of width 2
    scaled = outputs("CurveTubeST", curveVertexStarts=[0], curveVertexCounts=[2], tubeSTStarts=[0, 10],
                     tubeQuadStarts=[0, 4], cols=[4], t=[0.0, 3.0], scaleTLikeS=True, width=[2.0])
    assert scaled["primvars_st"][5][1] == pytest.approx(3.0 / (4 * 2.0 * math.sin(math.pi / 4)))


SQUARE = [(0, 0, 0), (1, 0, 0), (1, 0, 1), (0, 0, 1)]   # in the XZ plane, Y up, 4 long when closed


@pytest.mark.parametrize("fraction, location, heading_degrees", [
    (0.0, (0, 0, 0), 0.0), (0.125, (0.5, 0, 0), 0.0), (0.375, (1, 0, 0.5), -90.0), (0.625, (0.5, 0, 1), 180.0),
    (0.875, (0, 0, 0.5), 90.0), (1.3, (1, 0, 0.2), -90.0), (-0.4, (0.6, 0, 1), 180.0),
])
def test_location_at_a_fraction_of_a_closed_square(fraction, location, heading_degrees):
    found = outputs("GetLocationAtDistanceOnCurve2", curve=SQUARE, distance=fraction)
    assert found["location"] == pytest.approx(location)
    # forward X turned about up Y onto the edge: a rotation of heading_degrees about +Y
    half = math.radians(heading_degrees) / 2
    x, y, z, w = found["orientation"]
    assert abs(x) + abs(z) == pytest.approx(0.0, abs=1e-9)
    assert abs(y * math.cos(half) - w * math.sin(half)) == pytest.approx(0.0, abs=1e-9)   # same rotation, either sign
    rx, ry, rz = (math.radians(a) for a in found["rotateXYZ"])
    turned_forward = (math.cos(ry) * math.cos(rz), math.cos(ry) * math.sin(rz), -math.sin(ry))  # Rz Ry Rx applied to X
    assert turned_forward == pytest.approx((math.cos(2 * half), 0.0, -math.sin(2 * half)), abs=1e-9)


def test_location_array_form_and_degenerate_curves():
    found = outputs("GetLocationAtDistanceOnCurve", curve=SQUARE, distance=[0.125, 0.875])
    assert flat(found["location"]) == pytest.approx(flat([(0.5, 0, 0), (0, 0, 0.5)]))
    assert outputs("GetLocationAtDistanceOnCurve2", curve=[(2, 3, 4)], distance=0.7)["location"] == (2, 3, 4)
    with pytest.raises(GraphRuntimeError, match="inputs:curve is empty"):
        outputs("GetLocationAtDistanceOnCurve2", distance=0.5)


def test_kit_colon_port_names_connect_through_import_and_og(tmp_path):
    stage = tmp_path / "tube.usda"
    stage.write_text('''#usda 1.0
def OmniGraph "Graph"
{
    token evaluator:type = "execution"
    def OmniGraphNode "st"
    {
        token node:type = "omni.graph.nodes.CurveTubeST"
        int node:typeVersion = 1
        custom float2[] outputs:primvars:st
        custom int[] outputs:primvars:st:indices
    }
    def OmniGraphNode "size"
    {
        token node:type = "omni.graph.nodes.ArrayGetSize"
        int node:typeVersion = 1
        custom token inputs:array
        prepend token inputs:array.connect = </Graph/st.outputs:primvars:st:indices>
    }
}
''')
    connections = import_graph(str(stage)).document.connections
    assert [(c.src_node, c.src_attr, c.dst_node) for c in connections] == [("st", "outputs:primvars_st_indices", "size")]
    graph, *_ = og.Controller.edit("/CurveTubeSTGraph", {
        og.Controller.Keys.CREATE_NODES: [("st", "omni.graph.nodes.CurveTubeST"),
                                          ("size", "omni.graph.nodes.ArrayGetSize")],
        og.Controller.Keys.CONNECT: [("st.outputs:primvars:st", "size.inputs:array")]})
    assert [(c.src_node, c.src_attr) for c in graph.document.connections] == [("st", "outputs:primvars_st")]
