"""The command line's geometry outputs as shapely reads them (issue 36): `--to geojson`,
`geojsonl` and `wkt` give each feature's triangles as a GeometryCollection of Polygons, which
is valid (a MultiPolygon of triangles sharing edges is not), covering the input exactly; `--to
csv`'s WKT column likewise; and minitri's WKB reader, shared with this package, reads the hex
EWKB that shapely writes."""

import json
import subprocess

import pytest
import shapely

from conftest import FIXTURES, cli_path

U_SHAPE = FIXTURES / "valid" / "u_shape.wkt"
HOLE = FIXTURES / "holes" / "square_with_hole.wkt"


def cli(*args, stdin=None):
    """(exit status, standard output) of the command line."""
    done = subprocess.run(
        [str(cli_path()), *map(str, args)],
        input=stdin,
        capture_output=True,
        check=False,
    )
    return done.returncode, done.stdout.decode()


@pytest.mark.parametrize("path", [U_SHAPE, HOLE], ids=lambda p: p.name)
def test_wkt_lines_are_valid_collections_of_triangles_covering_the_polygon(path):
    code, out = cli("--to", "wkt", path)
    assert code == 0
    polygon = shapely.from_wkt(path.read_text())
    (line,) = out.splitlines()
    triangles = shapely.from_wkt(line)
    assert triangles.geom_type == "GeometryCollection"
    assert all(t.geom_type == "Polygon" and len(t.exterior.coords) == 4 for t in triangles.geoms)
    assert shapely.is_valid(triangles)
    # As a MultiPolygon the same triangles would be invalid: they share edges.
    assert not shapely.is_valid(shapely.MultiPolygon(list(triangles.geoms)))
    assert shapely.union_all(triangles.geoms).symmetric_difference(polygon).area == pytest.approx(0)
    assert sum(t.area for t in triangles.geoms) == pytest.approx(polygon.area)


@pytest.mark.parametrize("to", ["geojson", "geojsonl"])
def test_geojson_features_hold_a_valid_geometry_collection(to):
    code, out = cli("--to", to, U_SHAPE)
    assert code == 0
    feature = json.loads(out)["features"][0] if to == "geojson" else json.loads(out)
    triangles = shapely.from_geojson(json.dumps(feature["geometry"]))
    assert triangles.geom_type == "GeometryCollection"
    assert len(triangles.geoms) == feature["properties"]["minitri"]["triangle_count"] == 5
    assert shapely.is_valid(triangles)


def test_csv_wkt_column_reads_in_shapely_and_back_into_minitri():
    code, out = cli("--to", "csv", U_SHAPE)
    assert code == 0
    header, row = out.split("\r\n")[:2]
    assert header.startswith("WKT,")
    wkt = row[1 : row.index('"', 1)]
    assert shapely.is_valid(shapely.from_wkt(wkt))
    # Read back, each triangle is a polygon of its own (one WKT line each), the same ones.
    code, back = cli("--to", "wkt", stdin=out.encode())
    assert code == 0
    lines = back.splitlines()
    assert len(lines) == 5
    again = [g for line in lines for g in shapely.from_wkt(line).geoms]
    normal = lambda gs: sorted(shapely.normalize(g).wkt for g in gs)  # noqa: E731
    assert normal(again) == normal(shapely.from_wkt(wkt).geoms)


def test_hex_ewkb_as_shapely_writes_it_reads_on_the_command_line():
    polygon = shapely.set_srid(shapely.from_wkt("POLYGON ((0 0, 0.1 0.3, 0.2 0.6, 0 1, 0 0))"), 4326)
    ewkb = shapely.to_wkb(polygon, hex=True, include_srid=True)
    assert ewkb.startswith("0103000020E6100000")
    code, out = cli("--to", "wkt", stdin=(ewkb + "\n").encode())
    assert code == 0
    # The doubles are taken as their shortest decimals: three collinear points, one triangle;
    # the SRID is kept, as EWKT.
    assert out == "SRID=4326;GEOMETRYCOLLECTION (POLYGON ((0 0, 0.2 0.6, 0 1, 0 0)))\n"


U_SHAPE_Z = (
    "POLYGON Z ((3 2 0.5, 4 2 1.5, 5 2 2.5, 6 2 3.5, 6 3 4.5, 6 4 5.5, 5 4 6.5, 5 3 7.5, "
    "4 3 8.5, 4 4 9.5, 3 4 10.5, 3 3 11.5, 3 2 0.5))"
)


@pytest.mark.parametrize("to", ["wkt", "geojson", "csv"])
def test_z_values_reach_shapely_through_every_geometry_output(to):
    """Each triangle corner has the Z of the input vertex it is (issue 36, point 5)."""
    code, out = cli("--to", to, "-", stdin=U_SHAPE_Z.encode())
    assert code == 0
    if to == "wkt":
        triangles = shapely.from_wkt(out.strip())
    elif to == "geojson":
        triangles = shapely.from_geojson(json.dumps(json.loads(out)["features"][0]["geometry"]))
    else:
        header, row = out.split("\r\n")[:2]
        assert header.startswith("WKT,")
        triangles = shapely.from_wkt(row.split('",')[0].strip('"'))
    assert triangles.geom_type == "GeometryCollection"
    assert shapely.has_z(triangles)
    assert shapely.is_valid(triangles)
    heights = {c[:2]: c[2] for c in shapely.from_wkt(U_SHAPE_Z).exterior.coords}
    for t in triangles.geoms:
        assert shapely.has_z(t)
        for x, y, z in t.exterior.coords:
            assert heights[(x, y)] == z
    # Read back by minitri, the heights stay.
    code, back = cli("--to", "wkt", "-", stdin=out.encode())
    assert code == 0
    assert shapely.has_z(shapely.from_wkt(back.splitlines()[0]))
