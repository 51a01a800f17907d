//! The WKT writer: one `GEOMETRYCOLLECTION` of triangles per line, one line per input feature.
//!
//! Input contract: outcomes in order, the outcomes of one input feature together
//! ([`super::group`]); a solved outcome carries its
//! [`Polygon`](crate::geom::polygon::Polygon) and its triangles, counter-clockwise.
//!
//! Output guarantee: one line per input feature, in input order, whatever happened to it, so
//! that line k + 1 of the output is feature k of the input (features are numbered from 0; for
//! several inputs, their features in turn):
//!
//! - a GeoJSON feature: `GEOMETRYCOLLECTION (POLYGON ((x y, x y, x y, x y)), ...)`, the
//!   triangles of all its parts (a MultiPolygon's polygons, in order), like the geometry of its
//!   `--to geojson` Feature; an input without features (WKT, vertex lists): one line per
//!   polygon. A collection of polygons, not a `MULTIPOLYGON`: the triangles share edges, which
//!   the polygons of a valid MultiPolygon may not (OGC); PostGIS's `ST_TriangulatePolygon`
//!   gives the same form;
//! - each triangle a closed counter-clockwise ring (first corner repeated), in the order of
//!   the JSON output, coordinates the input decimals exactly
//!   ([`crate::geom::polygon::Grid::format`]); for `pseudo` and `pseudo-hull`, the
//!   pseudotriangles instead, in the order of the JSON output; with `--repair`, every piece's;
//! - `GEOMETRYCOLLECTION EMPTY` when nothing of the feature was triangulated: an invalid polygon, a
//!   feature that is not a polygon, a `null` geometry, a line that is not JSON, a feature all
//!   of whose parts failed;
//! - a feature with some failed parts: the triangles of the parts that were triangulated, as
//!   in its GeoJSON Feature (the line alone does not say that a part is missing: the errors go
//!   to standard error, the exit status is 1, and `--to csv` says it in `ok` and `errors`).
//!
//! A failure about an input as a whole (an unreadable file, a syntax error that stops a
//! FeatureCollection, a member of a WKT collection that is not a polygon) is no feature and
//! has no line; its error goes to standard error. The format has no place for identity: the
//! `id` and `properties` are in `--to csv` ([`super::csv`]), whose `WKT` column holds the same
//! lines.
//!
//! A polygon whose input gave it an SRID (EWKT `SRID=4326;POLYGON (...)`, an EWKB header's)
//! is written as EWKT, `SRID=4326;GEOMETRYCOLLECTION (...)`, as PostGIS's `ST_AsEWKT` does.
//!
//! The lines read back into minitri (its WKT reader takes one geometry per line, and its SRID).
//!
//! Why lines and not one `GEOMETRYCOLLECTION` for the run: each line is a complete WKT geometry standing for
//! one input feature, the one-geometry-per-record form of WKT-lines files and of WKT columns in
//! delimited text (which GIS tools import), and what shell tools (`wc -l`, `grep`, `split`,
//! `paste` with the input's ids) take; it streams with nothing to close at the end. A
//! collection would put a whole run on one line and lose the feature boundaries.
//!
//! Streamed: each line is written when its feature's last outcome is pushed; the triangles'
//! text is made ahead, in parallel, by [`render`]. Complexity: linear in the output.

use super::group::{Records, Rendered};
use super::{Renderer, Sink};
use crate::outcome::Outcome;
use std::io::{self, Write};

/// Writes one `GEOMETRYCOLLECTION` line per input feature.
pub struct WktWriter<W: Write> {
    out: W,
    records: Records,
}

impl<W: Write> WktWriter<W> {
    /// Starts the (headerless) document.
    pub fn new(out: W) -> WktWriter<W> {
        WktWriter {
            out,
            records: Records::new(),
        }
    }

    /// Takes the next outcome with its rendered triangles ([`render`]).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        let WktWriter { out, records } = self;
        records.push(outcome, rendered, |record| write_line(out, &record))
    }

    /// Writes what is gathered and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        if let Some(record) = self.records.finish() {
            write_line(&mut self.out, &record)?;
        }
        self.out.flush()
    }
}

/// Writes the line of one record: none for a failure about an input as a whole.
fn write_line(out: &mut impl Write, record: &[Rendered]) -> io::Result<()> {
    match record.first() {
        Some((first, _)) if is_feature(first) => match first.srid {
            Some(srid) => writeln!(out, "SRID={srid};{}", collection(record)),
            None => writeln!(out, "{}", collection(record)),
        },
        _ => Ok(()),
    }
}

/// Whether an outcome belongs to an input feature (a GeoJSON feature, or a polygon of an
/// input without features), not to an input as a whole.
pub fn is_feature(outcome: &Outcome) -> bool {
    outcome.feature.is_some() || outcome.index.is_some()
}

/// The `GEOMETRYCOLLECTION` of a record's rendered outcomes: every triangle of every solved
/// outcome, in order, or `GEOMETRYCOLLECTION EMPTY` when none was solved. With the input's
/// Z and M values, `GEOMETRYCOLLECTION Z (POLYGON Z ((x y z, ...)), ...)` (`M`, `ZM`): the
/// positions of one feature, or one polygon, all have the same dimensions.
pub fn collection(record: &[Rendered]) -> String {
    let members: Vec<&str> = record
        .iter()
        .filter_map(|(_, rendered)| rendered.as_deref().filter(|m| !m.is_empty()))
        .collect();
    let tag = record
        .iter()
        .find_map(|(outcome, rendered)| rendered.as_ref().and(outcome.ordinates.as_ref()))
        .map(|o| format!(" {}", o.dims.tag()))
        .unwrap_or_default();
    if members.is_empty() {
        "GEOMETRYCOLLECTION EMPTY".to_string()
    } else {
        format!("GEOMETRYCOLLECTION{tag} ({})", members.join(", "))
    }
}

/// The `GEOMETRYCOLLECTION` members of a solved outcome: its triangles (or pseudotriangles) as
/// `POLYGON ((x y, x y, x y, x y))`, comma-separated (`POLYGON Z ((x y z, ...))` with the
/// input vertices' Z, likewise `M`, `ZM`); `None` for a failed outcome.
pub fn render(outcome: &Outcome) -> Option<String> {
    let (Ok(solved), Some(polygon)) = (&outcome.result, &outcome.polygon) else {
        return None;
    };
    let ordinates = outcome.ordinates.as_deref();
    let coordinate = |i: usize| {
        let [x, y] = polygon.coordinates(i);
        let extra = ordinates.map(|o| o.wkt(polygon.id(i))).unwrap_or_default();
        format!("{x} {y}{extra}")
    };
    let keyword = match ordinates {
        Some(o) => format!("POLYGON {}", o.dims.tag()),
        None => "POLYGON".to_string(),
    };
    let rings: Vec<String> = match &solved.pseudo {
        // A pseudotriangulation: its faces, each a closed counter-clockwise ring.
        Some(p) => p
            .faces
            .iter()
            .map(|face| {
                let ring: Vec<String> = face.cycle.iter().map(|&v| coordinate(v)).collect();
                let first = ring.first().cloned().unwrap_or_default();
                format!("{keyword} (({}, {first}))", ring.join(", "))
            })
            .collect(),
        None => solved
            .triangulation
            .triangles
            .iter()
            .map(|tri| {
                let [a, b, c] = tri.map(coordinate);
                format!("{keyword} (({a}, {b}, {c}, {a}))")
            })
            .collect(),
    };
    Some(rings.join(", "))
}

impl<W: Write> Sink for WktWriter<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        let rendered = render(&outcome);
        self.push_rendered(outcome, rendered)
    }

    fn renderer(&self) -> Option<Renderer> {
        Some(render)
    }

    fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        WktWriter::push_rendered(self, outcome, rendered)
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        WktWriter::finish(*self)
    }
}
