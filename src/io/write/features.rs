//! The per-feature GeoJSON writers: `--to geojson` (one RFC 7946 FeatureCollection) and
//! `--to geojsonl` (GeoJSON Lines, RFC 8142's one-Feature-per-line form without the record
//! separator, as GDAL's GeoJSONSeq driver and `ndjson` tools read it).
//!
//! Input contract: outcomes in order; the outcomes of one input feature ([`crate::feature`])
//! come together, its parts in order. Output guarantee: one Feature per input feature, in input
//! order, whatever happened to it:
//!
//! ```text
//! {"type": "Feature", "id": 17, "geometry": {"type": "MultiPolygon", "coordinates": [...]},
//!  "properties": {"name": "a", "minitri": {"source": "a.geojsonl", "feature": 0, "ok": true,
//!  "algorithm": "minitri", "parts": 1, "triangle_count": 6, "degenerate_count": 0, "optimal": true}}}
//! ```
//!
//! `id` and the input's `properties` members are the input's bytes as written; minitri's facts
//! go in one member `minitri` added to the properties (so no name of the input's is taken).
//! The geometry is a MultiPolygon of every triangle of every part (each a closed
//! counter-clockwise ring, exact decimals as in the input), `null` when nothing was
//! triangulated. A feature that failed (in any part, or a `null` geometry, or a line that is not
//! JSON) still gets its Feature, with `"ok": false` and `errors` (the messages); an outcome with
//! no input feature (WKT or vertex input, a syntax error that stops a FeatureCollection) gets a
//! Feature of its own, without `id`. With `pseudo` and `pseudo-hull`, the pseudotriangles
//! instead, counted in `pseudotriangle_count`.
//!
//! Streamed: a feature is written as soon as its last part is pushed (memory: one feature's
//! outcomes); the part geometries are made ahead, in parallel, by [`render`].

use super::json::json;
use super::{Renderer, Sink};
use crate::feature::{properties_with, Identity};
use crate::pipeline::Outcome;
use std::fmt::Write as _;
use std::io::{self, Write};
use std::sync::Arc;

/// Writes one Feature per input feature, as a FeatureCollection or as GeoJSON Lines.
pub struct FeatureWriter<W: Write> {
    out: W,
    lines: bool,
    written: usize,
    /// The outcomes of the feature being gathered, each with its rendered geometry.
    pending: Vec<(Outcome, Option<String>)>,
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
            pending: Vec::new(),
        })
    }

    /// Takes the next outcome with its rendered geometry ([`render`]).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        let same = |a: &Option<Identity>, b: &Option<Identity>| match (a, b) {
            (Some(a), Some(b)) => Arc::ptr_eq(&a.feature, &b.feature),
            _ => false,
        };
        if let Some((last, _)) = self.pending.last() {
            if !same(&last.feature, &outcome.feature) {
                self.write_pending()?;
            }
        }
        let complete = outcome
            .feature
            .as_ref()
            .is_none_or(|id| self.pending.len() + 1 >= id.feature.outcomes());
        self.pending.push((outcome, rendered));
        if complete {
            self.write_pending()?;
        }
        Ok(())
    }

    /// Writes the gathered feature.
    fn write_pending(&mut self) -> io::Result<()> {
        let pending = std::mem::take(&mut self.pending);
        let Some((first, _)) = pending.first() else {
            return Ok(());
        };
        let text = feature_text(first, &pending);
        let separator = match (self.lines, self.written) {
            (true, _) => "",
            (false, 0) => "\n",
            (false, _) => ",\n",
        };
        self.written += 1;
        write!(self.out, "{separator}{text}")?;
        if self.lines {
            writeln!(self.out)?;
        }
        Ok(())
    }

    /// Writes what is gathered, ends the document and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        self.write_pending()?;
        if !self.lines {
            writeln!(self.out, "\n]}}")?;
        }
        self.out.flush()
    }
}

/// One Feature's text for the outcomes of one input feature (`first` among them).
fn feature_text(first: &Outcome, outcomes: &[(Outcome, Option<String>)]) -> String {
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
    let mut errors: Vec<String> = Vec::new();
    let mut geometries: Vec<&str> = Vec::new();
    let (mut triangles, mut degenerate, mut faces) = (0, 0, 0);
    let mut optimal = true;
    let mut algorithm = None;
    let mut pseudo = false;
    for (outcome, rendered) in outcomes {
        match &outcome.result {
            Ok(solved) => {
                let t = &solved.triangulation;
                algorithm = Some(t.algorithm.name());
                triangles += t.triangles.len();
                degenerate += t.degenerate.len();
                if let Some(p) = &solved.pseudo {
                    pseudo = true;
                    faces += p.faces.len();
                    optimal &= p.hull.is_some(); // as in the JSON output
                } else {
                    optimal &= t.optimal;
                }
            }
            Err(e) => {
                let part = outcome
                    .feature
                    .as_ref()
                    .filter(|id| id.multipart())
                    .map(|id| format!("part {}: ", id.part))
                    .unwrap_or_default();
                errors.extend(e.messages().into_iter().map(|m| format!("{part}{m}")));
            }
        }
        geometries.extend(rendered.as_deref().filter(|g| !g.is_empty()));
    }
    let _ = write!(facts, ", \"ok\": {}", errors.is_empty());
    if let Some(name) = algorithm {
        let _ = write!(facts, ", \"algorithm\": {}", json(name));
    }
    let parts = identity.map_or(1, |id| id.feature.outcomes());
    let _ = write!(facts, ", \"parts\": {parts}");
    if algorithm.is_some() {
        if pseudo {
            let _ = write!(facts, ", \"pseudotriangle_count\": {faces}");
        } else {
            let _ = write!(
                facts,
                ", \"triangle_count\": {triangles}, \"degenerate_count\": {degenerate}"
            );
        }
        let _ = write!(facts, ", \"optimal\": {optimal}");
    }
    if !errors.is_empty() {
        let _ = write!(facts, ", \"errors\": {}", json(&errors));
    }
    facts.push('}');
    let geometry = if geometries.is_empty() {
        "null".to_string()
    } else {
        format!(
            "{{\"type\": \"MultiPolygon\", \"coordinates\": [{}]}}",
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

/// The MultiPolygon members of a solved outcome: its triangles (or pseudotriangles) as
/// polygons `[[[x, y], ...]]`, comma-separated; `None` for a failed outcome.
pub fn render(outcome: &Outcome) -> Option<String> {
    let (Ok(solved), Some(polygon)) = (&outcome.result, &outcome.polygon) else {
        return None;
    };
    let mut out = String::new();
    let ring = |out: &mut String, vertices: &mut dyn Iterator<Item = usize>| {
        if !out.is_empty() {
            out.push_str(", ");
        }
        out.push_str("[[");
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
        out.push_str("]]");
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
