"""Minimum-number triangulation of polygons, exactly: minitri for shapely and GeoPandas.

``triangulate(geom)`` triangulates one Polygon or MultiPolygon (shapely, WKT text, GeoJSON text
or mapping, ``__geo_interface__``, WKB bytes) with the fewest triangles; ``triangulate_many``
does a whole shapely array or GeoSeries in parallel. Both call the Rust library of the minitri
command-line tool: same algorithms, same exact arithmetic, same messages.

Exactness: WKT and GeoJSON text are taken exactly as written (``0.1`` is one tenth, not the
nearest binary fraction); coordinates that arrive as floats (shapely geometries, WKB, mappings)
are taken as their shortest decimal, the digits ``repr`` prints. Triangle corners come back as
the input floats, bit for bit.
"""

from __future__ import annotations

import functools
import json
from collections.abc import Mapping

import numpy as np
import shapely

from . import _minitri

__all__ = [
    "InvalidPolygon",
    "VerificationError",
    "Triangulation",
    "Part",
    "Batch",
    "triangulate",
    "triangulate_many",
]

ALGORITHMS = ("minitri", "asano", "ear")


class InvalidPolygon(ValueError):
    """The input cannot be read or is not a valid polygon. ``str(e)`` is the command-line tool's
    message without the source name (``polygon 0: self-intersection: ...``), one line per
    problem; ``e.messages`` lists them."""

    def __init__(self, messages):
        self.messages = list(messages)
        super().__init__("\n".join(self.messages))


class VerificationError(RuntimeError):
    """With ``verify=True``: an output failed the independent check or the exact algorithms
    disagree (a bug in minitri: please report it with the polygon)."""

    def __init__(self, messages):
        self.messages = list(messages)
        super().__init__("\n".join(self.messages))


def _triples(rows):
    return np.asarray(rows, dtype=np.int64).reshape(-1, 3)


class Part:
    """One polygon of the input, as the command-line tool's JSON describes it.

    ``indices`` and ``degenerate`` are ``(k, 3)`` arrays of the polygon's input vertex numbers:
    its coordinates over the rings in order (exterior, then holes), without each ring's closing
    coordinate. ``json`` is the tool's whole JSON object for the polygon."""

    def __init__(self, entry: dict):
        self.json = entry
        self.index = entry["index"]
        self.algorithm = entry["algorithm"]
        self.vertices = entry["vertices"]
        self.holes = entry["holes"]
        self.input_vertices = entry["input_vertices"]
        self.flat_vertices = entry["flat_vertices"]
        self.triangle_count = entry["triangle_count"]
        self.degenerate_count = entry["degenerate_count"]
        self.indices = _triples(entry["triangles"])
        self.degenerate = _triples(entry["degenerate_triangles"])
        self.optimal = entry["optimal"]
        self.bounds = (entry["bounds"]["lower"], entry["bounds"]["upper"])
        self.warnings = list(entry["warnings"])
        self.verification = entry.get("verification")

    def __repr__(self):
        return (
            f"<minitri.Part {self.index}: {self.triangle_count} triangles, "
            f"{self.degenerate_count} degenerate, optimal={self.optimal}>"
        )


class Triangulation:
    """The triangulation of one geometry.

    - ``triangles``: a shapely MultiPolygon of the triangles (counter-clockwise), of every
      polygon in input order; with Z when the input has Z values (each corner the Z of the input
      vertex it is; the triangulation is in x, y);
    - ``indices``, ``degenerate``: ``(k, 3)`` arrays of input vertex numbers; for a
      MultiPolygon the numbers run on over its polygons (polygon 1's first vertex follows
      polygon 0's last), so they index ``vertices``;
    - ``vertices``: the input coordinates in that numbering, an ``(n, 2)`` float array;
    - ``triangle_count``, ``degenerate_count``, ``optimal`` (every count proved minimum),
      ``bounds`` (``(lower, upper)`` on the minimum, summed over the polygons), ``warnings``
      (``polygon 0: outer ring: vertex 2 (3, 0) repeats vertex 1 and was dropped``);
    - ``parts``: one :class:`Part` per polygon (the tool's JSON, per-polygon numbering).
    """

    def __init__(self, parts, warnings, wkb, geom):
        self.parts = parts
        self.warnings = list(warnings)
        self.triangles = shapely.from_wkb(wkb)
        self.triangle_count = sum(p.triangle_count for p in parts)
        self.degenerate_count = sum(p.degenerate_count for p in parts)
        self.optimal = all(p.optimal for p in parts)
        self.bounds = (sum(p.bounds[0] for p in parts), sum(p.bounds[1] for p in parts))
        offsets = np.cumsum([0] + [p.input_vertices for p in parts])
        self.indices = _triples(np.concatenate([p.indices + o for p, o in zip(parts, offsets)]))
        self.degenerate = _triples(
            np.concatenate([p.degenerate + o for p, o in zip(parts, offsets)])
        )
        self._geom = geom

    @functools.cached_property
    def vertices(self):
        """The input coordinates in input numbering, an ``(n, 2)`` float array (made when first
        asked for)."""
        geom = self._geom
        return _vertices(geom if isinstance(geom, shapely.Geometry) else _text_shape(geom))

    def __repr__(self):
        return (
            f"<minitri.Triangulation: {self.triangle_count} triangles, "
            f"{self.degenerate_count} degenerate, optimal={self.optimal}>"
        )


def _check(algorithm):
    if algorithm not in ALGORITHMS:
        raise ValueError(
            f"unknown algorithm {algorithm!r}: expected one of {', '.join(ALGORITHMS)}"
        )


def _json_default(value):
    if isinstance(value, np.integer):
        return int(value)
    if isinstance(value, np.floating):
        return float(value)
    if isinstance(value, np.ndarray):
        return value.tolist()
    raise TypeError(f"cannot read {type(value).__name__} as a GeoJSON coordinate")


def _ring_vertices(ring):
    coords = np.asarray(ring.coords, dtype=float)[:, :2]
    if len(coords) > 1 and (coords[0] == coords[-1]).all():
        coords = coords[:-1]
    return coords


def _vertices(geom):
    """The input coordinates in input numbering (rings in order, no closing coordinate)."""
    polygons = getattr(geom, "geoms", [geom])
    rings = [r for p in polygons for r in [p.exterior, *p.interiors]]
    if not rings:
        return np.empty((0, 2))
    return np.concatenate([_ring_vertices(r) for r in rings])


def _run(geom, algorithm, verify):
    """(parts, errors, warnings, failures, wkb, shapely geometry or None)."""
    if isinstance(geom, shapely.Geometry):
        return (*_minitri.triangulate_wkb(shapely.to_wkb(geom), algorithm, verify), geom)
    if isinstance(geom, (bytes, bytearray, memoryview)):
        return (*_minitri.triangulate_wkb(bytes(geom), algorithm, verify), None)
    if isinstance(geom, str):
        fmt = "geojson" if geom.lstrip()[:1] in ("{", "[") else "wkt"
        return (*_minitri.triangulate_text(geom, fmt, algorithm, verify), None)
    if hasattr(geom, "__geo_interface__"):
        geom = geom.__geo_interface__
    if isinstance(geom, Mapping):
        # json.dumps writes each float as repr does: its shortest decimal.
        text = json.dumps(geom, default=_json_default)
        return (*_minitri.triangulate_text(text, "geojson", algorithm, verify), None)
    raise TypeError(
        "expected a shapely Polygon or MultiPolygon, WKT or GeoJSON text, a GeoJSON mapping "
        f"or WKB bytes, not {type(geom).__name__}"
    )


def triangulate(geom, algorithm: str = "minitri", verify: bool = False) -> Triangulation:
    """Triangulates a Polygon or MultiPolygon with the fewest triangles.

    ``geom``: a shapely Polygon or MultiPolygon, WKT text, GeoJSON text (a geometry, Feature
    or FeatureCollection), a GeoJSON-like mapping or an object with ``__geo_interface__``, or
    WKB bytes. ``algorithm``: ``"minitri"`` (Chen & Chang, the minimum), ``"asano"`` (the
    O(n^3) dynamic program, the minimum) or ``"ear"`` (a plain n + 2h - 2 triangulation).
    ``verify``: also run the other exact algorithm and check every output independently
    (raises :class:`VerificationError` if anything is wrong).

    Raises :class:`InvalidPolygon` (a ``ValueError``) with the command-line tool's messages when
    the input cannot be read or a polygon is invalid."""
    _check(algorithm)
    parts, errors, warnings, failures, wkb, shape = _run(geom, algorithm, verify)
    if errors:
        raise InvalidPolygon(errors)
    if failures:
        raise VerificationError(failures)
    parts = [Part(json.loads(p)) for p in parts]
    return Triangulation(parts, warnings, wkb, shape if shape is not None else geom)


def _text_shape(geom):
    """The shapely geometry of text, a mapping or WKB (for ``vertices``; floats suffice)."""
    if isinstance(geom, (bytes, bytearray, memoryview)):
        return shapely.from_wkb(bytes(geom))
    if isinstance(geom, str):
        if geom.lstrip()[:1] in ("{", "["):
            return _geojson_shape(json.loads(geom))
        return shapely.from_wkt(geom)
    if hasattr(geom, "__geo_interface__"):
        geom = geom.__geo_interface__
    return _geojson_shape(geom)


def _geojson_shape(value):
    kind = value.get("type")
    if kind == "Feature":
        return _geojson_shape(value["geometry"])
    if kind == "FeatureCollection":
        shapes = [_geojson_shape(f) for f in value["features"]]
        return shapely.MultiPolygon([p for s in shapes for p in getattr(s, "geoms", [s])])
    if kind == "GeometryCollection":
        shapes = [_geojson_shape(g) for g in value["geometries"]]
        return shapely.MultiPolygon([p for s in shapes for p in getattr(s, "geoms", [s])])
    return shapely.geometry.shape(value)


class Batch:
    """The result of :func:`triangulate_many`, one entry per input geometry, in input order.

    Arrays: ``triangle_count``, ``degenerate_count``, ``lower``, ``upper`` (int64, -1 where the
    geometry failed or is missing), ``optimal`` (bool); ``triangles`` (a GeoSeries with the
    input's index and CRS when the input is a GeoSeries, else an array of shapely
    MultiPolygons; None where the geometry failed or is missing); ``errors`` (None or the
    message), ``warnings`` (a list of messages each). ``frame()`` gives all of it as a
    GeoDataFrame with the input's index."""

    def __init__(self, columns, triangles, index, crs):
        counts, degenerate, optimal, lower, upper, _, errors, warnings, _ = columns
        self.triangle_count = np.asarray(counts, dtype=np.int64)
        self.degenerate_count = np.asarray(degenerate, dtype=np.int64)
        self.optimal = np.asarray(optimal, dtype=bool)
        self.lower = np.asarray(lower, dtype=np.int64)
        self.upper = np.asarray(upper, dtype=np.int64)
        self.errors = errors
        self.warnings = warnings
        self.index = index
        self.crs = crs
        self.triangles = triangles

    def __len__(self):
        return len(self.triangle_count)

    def frame(self):
        """A GeoDataFrame: the columns above, geometry = the triangles, the input's index."""
        import geopandas

        return geopandas.GeoDataFrame(
            {
                "triangle_count": self.triangle_count,
                "degenerate_count": self.degenerate_count,
                "optimal": self.optimal,
                "lower": self.lower,
                "upper": self.upper,
                "error": self.errors,
                "warnings": self.warnings,
            },
            geometry=np.asarray(self.triangles, dtype=object),
            index=self.index,
            crs=self.crs,
        )


def triangulate_many(
    geoms,
    algorithm: str = "minitri",
    verify: bool = False,
    jobs: int | None = None,
    errors: str = "raise",
) -> Batch:
    """Triangulates every geometry of a shapely array, a list, a GeoSeries or a GeoDataFrame (its
    geometry column), in parallel: the geometries go to Rust as WKB in one call, which releases
    the GIL and triangulates them on ``jobs`` threads (all cores by default).

    Missing geometries (None) give None. ``errors="raise"`` (default): the first invalid
    geometry raises :class:`InvalidPolygon`, its message starting with the geometry's index
    label (``geometry 'b': polygon 0: ...``); ``errors="keep"``: it gives None and -1 counts,
    and its message is in ``Batch.errors``."""
    _check(algorithm)
    if errors not in ("raise", "keep"):
        raise ValueError(f"errors must be 'raise' or 'keep', not {errors!r}")
    index = crs = None
    series = None
    if hasattr(geoms, "geometry") and hasattr(geoms, "index"):
        geoms = geoms.geometry  # a GeoDataFrame's active geometry (a GeoSeries's is itself)
    if hasattr(geoms, "index") and hasattr(geoms, "crs"):
        series, index, crs = geoms, geoms.index, geoms.crs
        array = np.asarray(geoms.values, dtype=object)
    else:
        array = np.asarray(geoms, dtype=object)
    wkbs = shapely.to_wkb(array)
    columns = _minitri.triangulate_wkb_many(list(wkbs), algorithm, verify, jobs)
    missing = shapely.is_missing(array)
    if errors == "raise":
        for k, message in enumerate(columns[6]):
            if message is not None and not missing[k]:
                label = index[k] if index is not None else k
                error = VerificationError if columns[8][k] else InvalidPolygon
                raise error([f"geometry {label!r}: {message}"])
    triangles = shapely.from_wkb(np.asarray(columns[5], dtype=object))
    if series is not None:
        import geopandas

        triangles = geopandas.GeoSeries(triangles, index=index, crs=crs)
    return Batch(columns, triangles, index, crs)
