"""triangulate(): the U-shape, holes, each input form, exact decimals, numbering, errors."""

import json

import numpy as np
import pytest
import shapely

import minitri

U = "POLYGON ((0 0, 3 0, 3 2, 2 2, 2 1, 1 1, 1 2, 0 2, 0 0))"
# The same U with its 4 flat vertices: 5 triangles by 5 T-junctions.
U_FLAT = "POLYGON ((0 0, 1 0, 2 0, 3 0, 3 1, 3 2, 2 2, 2 1, 1 1, 1 2, 0 2, 0 1, 0 0))"


def test_u_shape_from_shapely_is_the_minimum():
    result = minitri.triangulate(shapely.from_wkt(U))
    assert (result.triangle_count, result.degenerate_count, result.optimal) == (6, 0, True)
    assert result.bounds == (3, 6)
    assert isinstance(result.triangles, shapely.MultiPolygon)
    assert len(result.triangles.geoms) == 6
    assert result.triangles.area == pytest.approx(5.0)
    assert shapely.equals(shapely.union_all(result.triangles.geoms), shapely.from_wkt(U))
    assert result.indices.shape == (6, 3) and result.degenerate.shape == (0, 3)


def test_u_with_flat_vertices_uses_t_junctions():
    result = minitri.triangulate(shapely.from_wkt(U_FLAT))
    assert (result.triangle_count, result.degenerate_count) == (5, 5)
    # Each degenerate triple (a, b, c) has b on the segment a-c.
    for a, b, c in result.degenerate:
        pa, pb, pc = (shapely.Point(result.vertices[i]) for i in (a, b, c))
        assert shapely.LineString([pa, pc]).distance(pb) == 0
    # Each triangle's corners are the input vertices its indices name, counter-clockwise.
    for triangle, triple in zip(result.triangles.geoms, result.indices):
        corners = np.asarray(triangle.exterior.coords)[:3]
        assert (corners == result.vertices[triple]).all()
        assert triangle.exterior.is_ccw


def test_every_input_form_gives_the_same_answer():
    shape = shapely.from_wkt(U_FLAT)
    forms = [
        shape,
        U_FLAT,
        shapely.to_wkb(shape),
        shapely.to_geojson(shape),
        shape.__geo_interface__,
        json.loads(shapely.to_geojson(shape)),
        {"type": "Feature", "properties": {}, "geometry": shape.__geo_interface__},
    ]
    answers = {
        (r.triangle_count, r.degenerate_count, tuple(map(tuple, r.indices)))
        for r in map(minitri.triangulate, forms)
    }
    assert len(answers) == 1


def test_holes():
    square_with_hole = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))"
    result = minitri.triangulate(square_with_hole)
    # n + 2w - 2 = 8 + 2 - 2 = 8, and no T-junction to save one.
    assert (result.triangle_count, result.degenerate_count, result.optimal) == (8, 0, True)
    assert result.parts[0].holes == 1
    assert result.triangles.area == pytest.approx(12.0)
    hole = shapely.from_wkt("POLYGON ((1 1, 1 3, 3 3, 3 1, 1 1))")
    assert all(t.intersection(hole).area == 0 for t in result.triangles.geoms)
    # A hole with a vertex on the middle of its side saves a triangle (9 vertices, 8 triangles).
    flat_hole = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 2, 3 1, 1 1))"
    result = minitri.triangulate(flat_hole, verify=True)
    assert (result.triangle_count, result.degenerate_count) == (8, 1)
    assert result.parts[0].verification["ok"] is True


def test_decimal_text_is_exact_and_floats_are_their_shortest_decimal():
    # (0.1, 0.3) lies on the segment (0, 0)-(0.2, 0.6) as decimals, not as binary floats.
    wkt = "POLYGON ((0 0, 0.1 0.3, 0.2 0.6, 0 1, 0 0))"
    for form in (wkt, shapely.from_wkt(wkt)):
        result = minitri.triangulate(form)
        assert (result.triangle_count, result.degenerate_count) == (1, 1)
    # The middle corner comes back as the input float, bit for bit.
    result = minitri.triangulate(shapely.from_wkt(wkt))
    assert tuple(result.vertices[result.degenerate[0][1]]) == (0.1, 0.3)


def test_multipolygon_numbering_runs_on_and_warnings_name_the_polygon():
    multi = "MULTIPOLYGON (((0 0, 1 0, 2 0, 2 2, 0 2, 0 0)), ((5 5, 6 5, 6 5, 6 6, 5 5)))"
    result = minitri.triangulate(shapely.from_wkt(multi))
    assert [p.triangle_count for p in result.parts] == [2, 1]
    assert result.triangle_count == 3 and len(result.triangles.geoms) == 3
    # Polygon 1's vertices are numbered 5.. (after polygon 0's five).
    assert sorted(result.indices[-1]) == [5, 6, 8]
    assert result.warnings == [
        "polygon 1: outer ring: vertex 2 (6, 5) repeats vertex 1 and was dropped"
    ]
    assert result.parts[1].warnings == ["outer ring: vertex 2 (6, 5) repeats vertex 1 and was dropped"]


@pytest.mark.parametrize(
    "geom, message",
    [
        (
            shapely.from_wkt("POLYGON ((0 0, 2 2, 2 0, 0 2, 0 0))"),
            "polygon 0: self-intersection: outer ring edge 2-3 (2, 0)-(0, 2) crosses outer ring "
            "edge 0-1 (0, 0)-(2, 2) near (1, 1)",
        ),
        ("POLYGON ((0 0, 1 0", "line 1, column 19: expected ')' or ',' but reached the end of the input"),
        (shapely.Point(0, 0), "expected a Polygon or MultiPolygon, found a Point"),
        (shapely.Polygon(), "no polygon found: the geometry is EMPTY"),
        (
            # WKB whose first 1.0 (vertex 1's x) is replaced by NaN.
            shapely.to_wkb(shapely.Polygon([(0, 0), (1, 0), (0, 1)])).replace(
                np.float64(1).tobytes(), np.float64("nan").tobytes(), 1
            ),
            "polygon 0, outer ring, vertex 1: x coordinate `NaN` is not a finite number",
        ),
        (b"\x01\x03", "not a valid WKB geometry: failed to fill whole buffer"),
    ],
)
def test_invalid_input_raises_invalid_polygon(geom, message):
    with pytest.raises(minitri.InvalidPolygon) as caught:
        minitri.triangulate(geom)
    assert str(caught.value) == message
    assert isinstance(caught.value, ValueError)


def test_several_problems_give_one_line_each():
    two_bowties = "MULTIPOLYGON (((0 0, 2 2, 2 0, 0 2, 0 0)), ((0 0, 1 0, 1 1, 0 1, 0 0)), ((0 0, 2 2, 2 0, 0 2, 0 0)))"
    with pytest.raises(minitri.InvalidPolygon) as caught:
        minitri.triangulate(two_bowties)
    assert [m.split(":")[0] for m in caught.value.messages] == ["polygon 0", "polygon 2"]


def test_unknown_algorithm_and_type():
    with pytest.raises(ValueError, match="unknown algorithm 'pseudo'"):
        minitri.triangulate(U, algorithm="pseudo")
    with pytest.raises(TypeError, match="not int"):
        minitri.triangulate(3)


@pytest.mark.parametrize("algorithm, count", [("minitri", 5), ("asano", 5), ("ear", 10)])
def test_algorithms(algorithm, count):
    result = minitri.triangulate(U_FLAT, algorithm=algorithm)
    assert result.triangle_count == count
    assert result.parts[0].algorithm == algorithm


def test_a_failed_verification_raises(monkeypatch):
    # The library's fault injection for tests: with verify, the chosen output loses a triangle.
    monkeypatch.setenv("MINITRI_CORRUPT_FOR_TESTS", "drop")
    with pytest.raises(minitri.VerificationError) as caught:
        minitri.triangulate(U_FLAT, verify=True)
    assert caught.value.messages == ["polygon 0: minitri gives 4 triangles but asano gives 5"]
    with pytest.raises(minitri.VerificationError, match="^geometry 0: polygon 0: minitri gives"):
        minitri.triangulate_many([shapely.from_wkt(U_FLAT)], verify=True)
    # Without verify nothing is checked, and nothing is corrupted.
    assert minitri.triangulate(U_FLAT).triangle_count == 5


def test_full_precision_doubles_and_touching_holes():
    # Shortest round-trip doubles at both ends of the range (the wide exact kernel: no
    # "coordinates too large"), a hole touching the outer ring at a vertex, and a vertex
    # exactly on the middle of the outer ring's bottom edge (a T-junction as written).
    a, b = 1.2345678901234567e-5, 0.012345678901234567
    outer = [(-170.5, -80.25), (a, -80.25), (179.75, -80.25), (179.75, 84.5), (-170.5, 84.5)]
    outer[1] = (4.625, -80.25)  # the midpoint of (-170.5, -80.25)-(179.75, -80.25)
    hole = [(-170.5, 0.0), (b, 10.0), (b, -10.0)]  # touches the outer ring's left edge
    shape = shapely.Polygon(outer, [hole])
    assert shape.is_valid  # OGC-valid: the hole touches the shell at one point
    result = minitri.triangulate(shape, verify=True)
    assert result.parts[0].verification["ok"] is True
    assert result.optimal is True
    assert result.triangles.area == pytest.approx(shape.area)
    # Every corner is an input coordinate, bit for bit.
    inputs = {tuple(p) for p in outer + hole}
    assert {tuple(v) for v in result.vertices} <= inputs
    # The vertex on the bottom edge is the middle of a degenerate triangle.
    assert any(tuple(result.vertices[t[1]]) == (4.625, -80.25) for t in result.degenerate)
    # A coordinate like 1.2345678901234567e-5 beside coordinates in the tens is taken exactly.
    tiny = shapely.Polygon([(0, 0), (a, 0), (20, 0), (20, 20)])
    assert minitri.triangulate(tiny).degenerate_count == 1


@pytest.mark.parametrize("form", ["wkt", "shapely", "wkb"])
def test_z_values_are_kept_on_the_triangles(form):
    """Each triangle corner has the Z of the input vertex it is (issue 36, point 5)."""
    text = "POLYGON Z ((0 0 1.5, 1 0 2, 2 0 2.5, 2 2 3, 0 2 4, 0 0 1.5))"
    geom = {"wkt": text, "shapely": shapely.from_wkt(text), "wkb": shapely.to_wkb(shapely.from_wkt(text))}[form]
    t = minitri.triangulate(geom)
    assert t.triangle_count == 2
    assert shapely.has_z(t.triangles)
    heights = {(x, y): z for x, y, z in shapely.from_wkt(text).exterior.coords}
    for triangle in t.triangles.geoms:
        for x, y, z in triangle.exterior.coords:
            assert heights[(x, y)] == z
    if form == "wkt":
        assert t.parts[0].json["vertices_z"] == [1.5, 2, 2.5, 3, 4]
    assert not shapely.has_z(minitri.triangulate(U).triangles)
