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
//! The FeatureCollection carries the `name` and `crs` of the input collection its first
//! Feature comes from ([`crate::feature::Collection`]), as written, before `features` (as GDAL
//! orders them): its opening is written with that first Feature. A later Feature from an input
//! of another `crs` is written as it is, with a warning ([`FeatureWriter::take_warnings`]).
//! GeoJSON Lines has no place for them.
//!
//! Streamed: a feature is written as soon as its last part is pushed ([`super::group`]; memory:
//! one feature's outcomes); the part geometries are made ahead, in parallel, by [`render`].

use super::group::{Records, Rendered, Summary};
use super::json::json;
use super::{Renderer, Sink};
use crate::feature::{properties_with, Collection};
use crate::outcome::Outcome;
use serde_json::Value;
use std::fmt::Write as _;
use std::io::{self, Write};
use std::sync::Arc;

/// Writes one Feature per input feature, as a FeatureCollection or as GeoJSON Lines.
pub struct FeatureWriter<W: Write> {
    output: Output<W>,
    /// The outcomes of the feature being gathered, each with its rendered geometry.
    records: Records,
}

/// Where the Features go, and what was said of the collection.
struct Output<W: Write> {
    out: W,
    lines: bool,
    written: usize,
    /// For a FeatureCollection, once its opening is written: the `crs` it carries.
    header: Option<Header>,
    /// Warnings not yet taken ([`Sink::warnings`]).
    warnings: Vec<String>,
}

/// What the opening of the FeatureCollection said.
struct Header {
    /// Its `crs` (`None`: none written), as a JSON value (compared as values, not bytes).
    crs: Option<Value>,
    /// The input it came from.
    source: String,
    /// The inputs already warned of a different `crs`.
    warned: Vec<String>,
}

impl<W: Write> FeatureWriter<W> {
    /// Starts a FeatureCollection (`lines` false) or GeoJSON Lines (`lines` true). The
    /// collection's opening is written with its first Feature (or at the end, when there is
    /// none), carrying the `name` and `crs` of the first feature's input collection.
    ///
    /// # Errors
    /// None yet: the signature keeps room for a writer that writes at once.
    pub fn new(out: W, lines: bool) -> io::Result<FeatureWriter<W>> {
        Ok(FeatureWriter {
            output: Output {
                out,
                lines,
                written: 0,
                header: None,
                warnings: Vec::new(),
            },
            records: Records::new(),
        })
    }

    /// Takes the next outcome with its rendered geometry ([`render`]).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        let FeatureWriter { output, records } = self;
        records.push(outcome, rendered, |record| output.write_feature(&record))
    }

    /// Warnings about what was written so far, each once: an input whose collection's `crs`
    /// differs from the one the output's collection carries.
    pub fn take_warnings(&mut self) -> Vec<String> {
        std::mem::take(&mut self.output.warnings)
    }

    /// Writes what is gathered, ends the document and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        if let Some(record) = self.records.finish() {
            self.output.write_feature(&record)?;
        }
        let output = &mut self.output;
        if !output.lines {
            if output.header.is_none() {
                output.open(None, "")?;
            }
            writeln!(output.out, "\n]}}")?;
        }
        output.out.flush()
    }
}

/// The `name` and `crs` an outcome's input said, if any: its feature's collection's, else
/// for an SRID (EWKT, EWKB) the `crs` naming it (`urn:ogc:def:crs:EPSG::<srid>`).
fn collection_of(outcome: &Outcome) -> Option<Arc<Collection>> {
    let given = outcome
        .feature
        .as_ref()
        .and_then(|id| id.feature.collection.clone());
    given.or_else(|| {
        let srid = outcome.srid?;
        Collection::of(None, Some(Collection::epsg(srid)))
    })
}

/// A `crs` as a message names it: the name of a named crs (`urn:ogc:def:crs:EPSG::3857`),
/// else its JSON text; `none (WGS 84)` when absent (GeoJSON's default).
fn describe(crs: Option<&Value>) -> String {
    match crs {
        None => "none (WGS 84)".to_string(),
        Some(crs) => match crs.pointer("/properties/name") {
            Some(Value::String(name)) => name.clone(),
            _ => crs.to_string(),
        },
    }
}

/// A `crs` as a JSON value (`None` when absent or not JSON).
fn crs_value(collection: Option<&Collection>) -> Option<Value> {
    serde_json::from_str(collection?.crs.as_deref()?.get()).ok()
}

impl<W: Write> Output<W> {
    /// Writes the opening of the FeatureCollection, with `collection`'s members (from `source`).
    fn open(&mut self, collection: Option<&Collection>, source: &str) -> io::Result<()> {
        let mut members = String::new();
        if let Some(name) = collection.and_then(|c| c.name.as_deref()) {
            let _ = write!(members, ", \"name\": {}", name.get());
        }
        if let Some(crs) = collection.and_then(|c| c.crs.as_deref()) {
            let _ = write!(members, ", \"crs\": {}", crs.get());
        }
        write!(
            self.out,
            "{{\"type\": \"FeatureCollection\"{members}, \"features\": ["
        )?;
        self.header = Some(Header {
            crs: crs_value(collection),
            source: source.to_string(),
            warned: Vec::new(),
        });
        Ok(())
    }

    /// Writes the Feature of one input feature's outcomes (the collection's opening first,
    /// before the first one).
    fn write_feature(&mut self, record: &[Rendered]) -> io::Result<()> {
        let Some((first, _)) = record.first() else {
            return Ok(());
        };
        if !self.lines {
            let said = collection_of(first);
            let said = said.as_deref();
            match &mut self.header {
                None => self.open(said, &first.source)?,
                // A feature of another input collection (or a polygon of an SRID), under
                // another crs than the output's.
                Some(header) if first.feature.is_some() || first.srid.is_some() => {
                    let crs = crs_value(said);
                    if crs != header.crs && !header.warned.contains(&first.source) {
                        header.warned.push(first.source.clone());
                        self.warnings.push(format!(
                            "warning: {}: its \"crs\" ({}) is not the output's ({}, from {}): its features are written under the output's; give each input its own output (-o DIR)",
                            first.source,
                            describe(crs.as_ref()),
                            describe(header.crs.as_ref()),
                            header.source
                        ));
                    }
                }
                Some(_) => {}
            }
        }
        let text = feature_text(first, record);
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
    let ordinates = outcome.ordinates.as_deref();
    let ring = |out: &mut String, vertices: &mut dyn Iterator<Item = usize>| {
        if !out.is_empty() {
            out.push_str(", ");
        }
        out.push_str("{\"type\": \"Polygon\", \"coordinates\": [[");
        let mut first = None;
        for v in vertices {
            let [x, y] = polygon.coordinates(v);
            // The input vertex's Z (GeoJSON positions hold no M: the JSON output has it).
            let z = ordinates
                .map(|o| o.geojson(polygon.id(v)))
                .unwrap_or_default();
            let text = format!("[{x}, {y}{z}]");
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

    fn warnings(&mut self) -> Vec<String> {
        self.take_warnings()
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        FeatureWriter::finish(*self)
    }
}
