//! The per-feature GeoJSON writers: `--to geojson` (one RFC 7946 FeatureCollection) and
//! `--to geojsonl` (GeoJSON Lines, RFC 8142's one-Feature-per-line form without the record
//! separator, as GDAL's GeoJSONSeq driver and `ndjson` tools read it).
//!
//! Input contract: outcomes in order; the outcomes of one input feature ([`crate::feature`])
//! come together, its parts in order. Output guarantee: one Feature per input feature, in input
//! order, whatever happened to it:
//!
//! ```text
//! {"type": "Feature", "id": 17, "geometry": {"type": "GeometryCollection", "geometries": [...]},
//!  "properties": {"name": "a", "minitri": {"source": "a.geojsonl", "feature": 0, "ok": true,
//!  "algorithm": "minitri", "parts": 1, "triangle_count": 6, "degenerate_count": 0, "optimal": true}}}
//! ```
//!
//! `id` and the input's `properties` members are the input's bytes as written; minitri's facts
//! go in one member `minitri` added to the properties (so no name of the input's is taken).
//! The geometry is a GeometryCollection of Polygons, one per triangle of every part (each a
//! closed counter-clockwise ring, exact decimals as in the input), `null` when nothing was
//! triangulated. Not a MultiPolygon: the triangles share edges, which the parts of a valid
//! MultiPolygon may not (OGC Simple Features; shapely and PostGIS call such a MultiPolygon
//! invalid), and a GeometryCollection of Polygons is what PostGIS's `ST_TriangulatePolygon` and
//! shapely's `constrained_delaunay_triangles` return. A feature that failed (in any part, or a `null` geometry, or a line that is not
//! JSON) still gets its Feature, with `"ok": false` and `errors` (the messages); a polygon of an
//! input without features (WKT or vertex input; with `--repair`, all its pieces) gets a Feature
//! of its own, without `id`, and so does an outcome about an input as a whole (an unreadable
//! file, a syntax error that stops a FeatureCollection). With `pseudo` and `pseudo-hull`, the pseudotriangles
//! instead, counted in `pseudotriangle_count`.
//!
//! Streamed: a feature is written as soon as its last part is pushed ([`super::group`]; memory:
//! one feature's outcomes); the part geometries are made ahead, in parallel, by [`render`].

use super::group::{Records, Rendered, Summary};
use super::json::json;
use super::{Renderer, Sink};
use crate::feature::properties_with;
use crate::pipeline::Outcome;
use std::fmt::Write as _;
use std::io::{self, Write};

/// Writes one Feature per input feature, as a FeatureCollection or as GeoJSON Lines.
pub struct FeatureWriter<W: Write> {
    out: W,
    lines: bool,
    written: usize,
    /// The outcomes of the feature being gathered, each with its rendered geometry.
    records: Records,
}

impl<W: Write> FeatureWriter<W> {
    /// Starts a FeatureCollection (`lines` false) or GeoJSON Lines (`lines` true).
    ///
    /// # Errors
    /// Any I/O error of `out`.
    pub fn new(mut out: W, lines: bool) -> io::Result<FeatureWriter<W>> {
        if !lines {
            write!(out, "{{\"type\": \"FeatureCollection\", \"features\": [")?;
        }
        Ok(FeatureWriter {
            out,
            lines,
            written: 0,
            records: Records::new(),
        })
    }

    /// Takes the next outcome with its rendered geometry ([`render`]).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        let FeatureWriter {
            out,
            lines,
            written,
            records,
        } = self;
        records.push(outcome, rendered, |record| {
            write_feature(out, *lines, written, &record)
        })
    }

    /// Writes what is gathered, ends the document and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        if let Some(record) = self.records.finish() {
            write_feature(&mut self.out, self.lines, &mut self.written, &record)?;
        }
        if !self.lines {
            writeln!(self.out, "\n]}}")?;
        }
        self.out.flush()
    }
}

/// Writes the Feature of one input feature's outcomes (`written` Features before it).
fn write_feature(
    out: &mut impl Write,
    lines: bool,
    written: &mut usize,
    record: &[Rendered],
) -> io::Result<()> {
    let Some((first, _)) = record.first() else {
        return Ok(());
    };
    let text = feature_text(first, record);
    let separator = match (lines, *written) {
        (true, _) => "",
        (false, 0) => "\n",
        (false, _) => ",\n",
    };
    *written += 1;
    write!(out, "{separator}{text}")?;
    if lines {
        writeln!(out)?;
    }
    Ok(())
}

/// One Feature's text for the outcomes of one input feature (`first` among them).
fn feature_text(first: &Outcome, outcomes: &[Rendered]) -> String {
    let identity = first.feature.as_ref();
    let mut facts = format!("{{\"source\": {}", json(&first.source));
    match identity {
        Some(id) => {
            let _ = write!(facts, ", \"feature\": {}", id.feature.number);
            if let Some(line) = id.feature.line {
                let _ = write!(facts, ", \"line\": {line}");
            }
        }
        None => {
            if let Some(index) = first.index {
                let _ = write!(facts, ", \"polygon\": {index}");
            }
        }
    }
    let summary = Summary::of(outcomes);
    let _ = write!(facts, ", \"ok\": {}", summary.ok());
    if let Some(name) = summary.algorithm {
        let _ = write!(facts, ", \"algorithm\": {}", json(name));
    }
    let _ = write!(facts, ", \"parts\": {}", summary.parts);
    if summary.algorithm.is_some() {
        match summary.faces {
            Some(faces) => {
                let _ = write!(facts, ", \"pseudotriangle_count\": {faces}");
            }
            None => {
                let _ = write!(
                    facts,
                    ", \"triangle_count\": {}, \"degenerate_count\": {}",
                    summary.triangles, summary.degenerate
                );
            }
        }
        let _ = write!(facts, ", \"optimal\": {}", summary.optimal);
    }
    if !summary.ok() {
        let _ = write!(facts, ", \"errors\": {}", json(&summary.errors));
    }
    facts.push('}');
    let geometries: Vec<&str> = outcomes
        .iter()
        .filter_map(|(_, rendered)| rendered.as_deref().filter(|g| !g.is_empty()))
        .collect();
    let geometry = if geometries.is_empty() {
        "null".to_string()
    } else {
        format!(
            "{{\"type\": \"GeometryCollection\", \"geometries\": [{}]}}",
            geometries.join(", ")
        )
    };
    let id = identity
        .and_then(|id| id.feature.id.as_deref())
        .map(|id| format!(", \"id\": {}", id.get()))
        .unwrap_or_default();
    let properties = identity.and_then(|id| id.feature.properties.as_deref());
    format!(
        "{{\"type\": \"Feature\"{id}, \"geometry\": {geometry}, \"properties\": {}}}",
        properties_with(properties, "minitri", &facts)
    )
}

/// The GeometryCollection members of a solved outcome: its triangles (or pseudotriangles) as
/// Polygons `{"type": "Polygon", "coordinates": [[[x, y], ...]]}`, comma-separated; `None` for
/// a failed outcome.
pub fn render(outcome: &Outcome) -> Option<String> {
    let (Ok(solved), Some(polygon)) = (&outcome.result, &outcome.polygon) else {
        return None;
    };
    let mut out = String::new();
    let ring = |out: &mut String, vertices: &mut dyn Iterator<Item = usize>| {
        if !out.is_empty() {
            out.push_str(", ");
        }
        out.push_str("{\"type\": \"Polygon\", \"coordinates\": [[");
        let mut first = None;
        for v in vertices {
            let [x, y] = polygon.coordinates(v);
            let text = format!("[{x}, {y}]");
            if first.is_some() {
                out.push_str(", ");
            }
            out.push_str(&text);
            first.get_or_insert(text);
        }
        if let Some(first) = first {
            let _ = write!(out, ", {first}");
        }
        out.push_str("]]}");
    };
    match &solved.pseudo {
        Some(p) => {
            for face in &p.faces {
                ring(&mut out, &mut face.cycle.iter().copied());
            }
        }
        None => {
            for tri in &solved.triangulation.triangles {
                ring(&mut out, &mut tri.iter().copied());
            }
        }
    }
    Some(out)
}

impl<W: Write> Sink for FeatureWriter<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        let rendered = render(&outcome);
        self.push_rendered(outcome, rendered)
    }

    fn renderer(&self) -> Option<Renderer> {
        Some(render)
    }

    fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        FeatureWriter::push_rendered(self, outcome, rendered)
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        FeatureWriter::finish(*self)
    }
}
