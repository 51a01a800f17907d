"""triangulate_many(): the same answers as a loop of triangulate(), GeoPandas in and out with
the index and CRS kept, errors, and the documentation's Dask snippet on a small frame."""

import geopandas
import numpy as np
import pandas as pd
import pytest
import shapely

import minitri
from polygons import buildings

BOWTIE = shapely.from_wkt("POLYGON ((0 0, 2 2, 2 0, 0 2, 0 0))")


@pytest.fixture(scope="module")
def shapes():
    multi = shapely.from_wkt("MULTIPOLYGON (((0 0, 1 0, 2 0, 2 2, 0 2, 0 0)), ((5 5, 6 5, 6 6, 5 5)))")
    holed = shapely.from_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 2, 3 1, 1 1))")
    return np.array(buildings(300, seed=7) + [multi, holed], dtype=object)


@pytest.mark.parametrize("jobs", [None, 1, 2])
def test_vectorised_equals_a_loop(shapes, jobs):
    batch = minitri.triangulate_many(shapes, jobs=jobs)
    loop = [minitri.triangulate(g) for g in shapes]
    assert batch.triangle_count.tolist() == [r.triangle_count for r in loop]
    assert batch.degenerate_count.tolist() == [r.degenerate_count for r in loop]
    assert batch.optimal.tolist() == [r.optimal for r in loop]
    assert list(zip(batch.lower, batch.upper)) == [r.bounds for r in loop]
    assert all(shapely.equals_exact(a, r.triangles, 0) for a, r in zip(batch.triangles, loop))
    assert batch.errors == [None] * len(shapes)
    # Building outlines have collinear vertices: some T-junctions are used.
    assert batch.degenerate_count.sum() > 0
    assert (batch.triangle_count >= batch.lower).all() and (batch.triangle_count <= batch.upper).all()


def test_errors_raise_with_the_label_or_are_kept():
    series = geopandas.GeoSeries([buildings(1)[0], BOWTIE, None], index=["a", "b", "c"])
    with pytest.raises(minitri.InvalidPolygon) as caught:
        minitri.triangulate_many(series)
    assert str(caught.value) == (
        "geometry 'b': polygon 0: self-intersection: outer ring edge 2-3 (2, 0)-(0, 2) crosses "
        "outer ring edge 0-1 (0, 0)-(2, 2) near (1, 1)"
    )
    batch = minitri.triangulate_many(series, errors="keep")
    assert batch.triangle_count[1:].tolist() == [-1, -1]
    assert batch.triangles.isna().tolist() == [False, True, True]
    assert batch.errors[0] is None and batch.errors[1].startswith("polygon 0: self-intersection")
    assert batch.errors[2] == "missing geometry (None)"


def test_geopandas_round_trip_keeps_index_and_crs():
    gdf = geopandas.GeoDataFrame(
        {"name": ["x", "y", "z"]},
        geometry=buildings(3, seed=3),
        index=pd.Index([30, 10, 20], name="building"),
        crs="EPSG:2056",
    )
    batch = minitri.triangulate_many(gdf.geometry)
    assert batch.triangles.index.equals(gdf.index)
    assert batch.triangles.crs == gdf.crs
    # The triangles cover each footprint exactly.
    assert np.allclose(batch.triangles.area, gdf.area)
    assert all(batch.triangles.covers(gdf.geometry.representative_point()))
    frame = batch.frame()
    assert frame.index.equals(gdf.index) and frame.crs == gdf.crs
    assert frame["triangle_count"].tolist() == [len(t.geoms) for t in batch.triangles]
    joined = gdf.join(frame.drop(columns="geometry"))
    assert joined.loc[10, "triangle_count"] == minitri.triangulate(gdf.geometry.loc[10]).triangle_count
    # A GeoDataFrame itself stands for its geometry column.
    assert minitri.triangulate_many(gdf).triangle_count.tolist() == frame["triangle_count"].tolist()


def test_empty_input():
    batch = minitri.triangulate_many([])
    assert len(batch) == 0 and batch.triangle_count.dtype == np.int64


# The snippet of docs/python.md ("Dask"), word for word between the markers.
# --- snippet: dask ---
import dask.dataframe as dd


def minimum_triangles(frame: pd.DataFrame) -> pd.DataFrame:
    """One partition: polygons as hex WKB in, the minimum triangulation's count and triangles
    (hex WKB) out. Hex, not bytes: Dask turns object columns into text."""
    batch = minitri.triangulate_many(shapely.from_wkb(frame["wkb"]), jobs=1)
    return frame.assign(
        triangle_count=batch.triangle_count,
        triangles=shapely.to_wkb(batch.triangles, hex=True),
    )


def triangulate_dask(polygons: dd.DataFrame) -> dd.DataFrame:
    return polygons.map_partitions(
        minimum_triangles,
        meta=polygons._meta.assign(triangle_count=np.int64(0), triangles=""),
    )
# --- end snippet ---


def test_dask_snippet_on_a_small_frame():
    shapes = buildings(200, seed=11)
    wkb = shapely.to_wkb(np.array(shapes, dtype=object), hex=True)
    frame = pd.DataFrame({"id": range(200), "wkb": wkb})
    polygons = dd.from_pandas(frame, npartitions=4)
    out = triangulate_dask(polygons).compute(scheduler="threads")
    expected = [minitri.triangulate(s).triangle_count for s in shapes]
    assert out["id"].tolist() == list(range(200))
    assert out["triangle_count"].tolist() == expected
    assert [len(shapely.from_wkb(w).geoms) for w in out["triangles"]] == expected


def test_the_docs_carry_this_snippet():
    from conftest import ROOT

    source = open(__file__).read()
    snippet = source.split("# --- snippet: dask ---\n")[1].split("# --- end snippet ---")[0]
    docs = (ROOT / "docs" / "python.md").read_text()
    assert snippet.strip() in docs
