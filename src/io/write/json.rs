//! The JSON writer: the document of `docs/cli.md`.
//!
//! Output: `{"polygons": [...], "errors": [...]}`, one object per triangulated polygon with the
//! spec's fields (vertex numbers are INPUT numbers, triangles counter-clockwise), plus
//! `input_vertices` (vertex numbers used, including dropped duplicates), `flat_vertices`,
//! `bounds` (Theorem 3's bounds on the minimum, generalised to flat vertices), `warnings`, and
//! `verification` with `--verify`. Every polygon or input that failed is listed under `errors`
//! with its source, index and message. Pretty at the top level, one line per triangle list, so
//! files stay small and diffable. [`JsonWriter`] writes the same document incrementally, one
//! polygon at a time (memory: the error list only). Complexity: linear in the output size.

use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use crate::pipeline::Outcome;
use serde::Serialize;
use std::io::{self, Write};

/// Writes the JSON document for `outcomes`.
///
/// # Errors
/// Any I/O error of `out`.
pub fn write_json(outcomes: &[Outcome], out: &mut impl Write) -> io::Result<()> {
    let mut writer = JsonWriter::new(out)?;
    for outcome in outcomes {
        writer.push(outcome)?;
    }
    writer.finish()
}

/// The same document written incrementally: each solved polygon as soon as it is pushed, the
/// errors (which the document lists after the polygons) kept until [`JsonWriter::finish`].
/// The bytes are exactly those of [`write_json`] on the same outcomes.
pub struct JsonWriter<W: Write> {
    out: W,
    polygons: usize,
    errors: Vec<ErrorEntry>,
}

/// One entry of `errors`.
#[derive(Serialize)]
struct ErrorEntry {
    source: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    index: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    piece: Option<usize>,
    /// The input feature's number, part, line (GeoJSON Lines) and `id` as written.
    #[serde(skip_serializing_if = "Option::is_none")]
    feature: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    part: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    line: Option<usize>,
    #[serde(skip_serializing_if = "Option::is_none")]
    id: Option<Box<serde_json::value::RawValue>>,
    message: String,
}

impl<W: Write> JsonWriter<W> {
    /// Starts the document.
    ///
    /// # Errors
    /// Any I/O error of `out`.
    pub fn new(mut out: W) -> io::Result<JsonWriter<W>> {
        write!(out, "{{\n  \"polygons\": [")?;
        Ok(JsonWriter {
            out,
            polygons: 0,
            errors: Vec::new(),
        })
    }

    /// Writes one outcome (a solved polygon now, an error at the end).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push(&mut self, outcome: &Outcome) -> io::Result<()> {
        let text = render(outcome);
        self.push_rendered(outcome, text)
    }

    /// [`JsonWriter::push`] with the outcome's text made already ([`render`] of it, on any
    /// thread).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push_rendered(&mut self, outcome: &Outcome, text: Option<String>) -> io::Result<()> {
        let Some(text) = text else {
            if let Err(e) = &outcome.result {
                let feature = outcome.feature.as_ref();
                self.errors.push(ErrorEntry {
                    source: outcome.source.clone(),
                    index: outcome.index,
                    piece: outcome.piece,
                    feature: feature.map(|f| f.feature.number),
                    part: feature.filter(|f| f.multipart()).map(|f| f.part),
                    line: feature.and_then(|f| f.feature.line),
                    id: feature.and_then(|f| f.feature.id.clone()),
                    message: e.to_string(),
                });
            }
            return Ok(());
        };
        let separator = if self.polygons == 0 { "" } else { "," };
        self.polygons += 1;
        write!(self.out, "{separator}\n{text}")
    }

    /// Ends the document: closes `polygons`, writes `errors`, and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        let out = &mut self.out;
        if self.polygons == 0 {
            writeln!(out, "],")?;
        } else {
            writeln!(out, "\n  ],")?;
        }
        writeln!(out, "  \"errors\": {}", json(&self.errors))?;
        writeln!(out, "}}")?;
        out.flush()
    }
}

/// The text of a solved outcome in the `polygons` list (`None` for an error, which goes to the
/// `errors` list at the end). Depends on the outcome only, so a batch makes it in parallel.
pub fn render(outcome: &Outcome) -> Option<String> {
    use std::fmt::Write as _;
    let (Ok(solved), Some(polygon), Some(index)) =
        (&outcome.result, &outcome.polygon, outcome.index)
    else {
        return None;
    };
    let t = &solved.triangulation;
    let fields: Vec<(&str, String)> = match &solved.pseudo {
        Some(p) => {
            crate::with_polygon!(polygon, q => pseudo_fields(outcome, index, q, t.algorithm, p))
        }
        None => crate::with_polygon!(polygon, q => triangle_fields(outcome, index, q, t)),
    };
    let mut fields = fields;
    if let Some(feature) = &outcome.feature {
        // Which input feature this is, right after `index`.
        let mut identity = vec![("feature", json(&feature.feature.number))];
        if feature.multipart() {
            identity.push(("part", json(&feature.part)));
        }
        if let Some(line) = feature.feature.line {
            identity.push(("line", json(&line)));
        }
        if let Some(id) = &feature.feature.id {
            identity.push(("id", id.get().to_string()));
        }
        if let Some(properties) = &feature.feature.properties {
            identity.push(("properties", properties.get().to_string()));
        }
        fields.splice(2..2, identity);
    }
    let mut out = String::from("    {\n");
    // `piece` only for a repaired polygon split into several.
    for (name, value) in fields.iter().filter(|(_, value)| !value.is_empty()) {
        let _ = writeln!(out, "      \"{name}\": {value},");
    }
    let warnings: Vec<String> = outcome.warnings.iter().map(ToString::to_string).collect();
    let _ = write!(out, "      \"warnings\": {}", json(&warnings));
    if let Some(repaired) = &outcome.repaired {
        let _ = write!(out, ",\n      \"repaired\": {}", json(repaired));
    }
    if let Some(v) = &solved.verification {
        let _ = write!(out, ",\n      \"verification\": {}", json(v));
    }
    out.push_str("\n    }");
    Some(out)
}

/// The fields of a triangulated polygon, in order.
fn triangle_fields<P: Coord>(
    outcome: &Outcome,
    index: usize,
    polygon: &Polygon<P>,
    t: &crate::algo::Triangulation,
) -> Vec<(&'static str, String)> {
    let mut fields: Vec<(&str, String)> = vec![
        ("source", json(&outcome.source)),
        ("index", json(&index)),
        ("piece", outcome.piece.map_or(String::new(), |k| json(&k))),
        ("algorithm", json(t.algorithm.name())),
        ("vertices", json(&polygon.len())),
        ("holes", json(&polygon.input_holes())),
        ("triangle_count", json(&t.triangles.len())),
        ("degenerate_count", json(&t.degenerate.len())),
        ("triangles", json(&ids(polygon, &t.triangles))),
        ("degenerate_triangles", json(&ids(polygon, &t.degenerate))),
        ("optimal", json(&t.optimal)),
        ("input_vertices", json(&polygon.input_vertices())),
        ("flat_vertices", json(&polygon.flat_vertices())),
        ("bounds", {
            let (lower, upper) = polygon.minimum_bounds();
            format!("{{\"lower\": {lower}, \"upper\": {upper}}}")
        }),
    ];
    touches_field(&mut fields, polygon);
    if let Some(lower) = t.lower_bound {
        // A search cut short: what is proved about the minimum, right after `optimal`.
        let after = fields.iter().position(|(name, _)| *name == "optimal");
        let at = after.map_or(fields.len(), |i| i + 1);
        fields.insert(at, ("lower_bound", json(&lower)));
    }
    if let Some(stopped) = t.stopped {
        // Why the count is not proved minimum, right after `optimal` (and `lower_bound`).
        let after = ["lower_bound", "optimal"]
            .iter()
            .find_map(|field| fields.iter().position(|(name, _)| name == field));
        let at = after.map_or(fields.len(), |i| i + 1);
        fields.insert(at, ("stopped_by", json(stopped.name())));
    }
    fields
}

/// `touches` (how many touches join rings into boundary walks), right after `holes`, for a
/// polygon whose rings touch (absent otherwise, so outputs without touches are unchanged).
fn touches_field<P: Coord>(fields: &mut Vec<(&'static str, String)>, polygon: &Polygon<P>) {
    if polygon.touches() > 0 {
        let at = fields
            .iter()
            .position(|(name, _)| *name == "holes")
            .map_or(fields.len(), |i| i + 1);
        fields.insert(at, ("touches", json(&polygon.touches())));
    }
}

/// The fields of a pseudotriangulated polygon (`pseudo`, `pseudo-hull`), in order: no triangle
/// fields, but `pseudotriangle_count`, `edge_count` and `pseudotriangles` (each `cycle`
/// counter-clockwise from a corner, and its three `corners`); for `pseudo-hull` also
/// `reflex_vertices` (r), `big_angles` (N), `corollary_count` (2n - r - 2) and `minimum_count`
/// (2n - N - 2, the same in general position). `optimal` says whether the count is proved minimum (`pseudo-hull`) rather than
/// only minimal (`pseudo`).
fn pseudo_fields<P: Coord>(
    outcome: &Outcome,
    index: usize,
    polygon: &Polygon<P>,
    algorithm: crate::algo::Algorithm,
    p: &crate::algo::Pseudotriangulation,
) -> Vec<(&'static str, String)> {
    let faces: Vec<String> = p
        .faces
        .iter()
        .map(|f| {
            let cycle: Vec<usize> = f.cycle.iter().map(|&v| polygon.id(v)).collect();
            let corners: Vec<usize> = f.corners.iter().map(|&v| polygon.id(v)).collect();
            format!(
                "{{\"cycle\": {}, \"corners\": {}}}",
                json(&cycle),
                json(&corners)
            )
        })
        .collect();
    let n = polygon.len();
    let mut fields: Vec<(&str, String)> = vec![
        ("source", json(&outcome.source)),
        ("index", json(&index)),
        ("piece", outcome.piece.map_or(String::new(), |k| json(&k))),
        ("algorithm", json(algorithm.name())),
        ("vertices", json(&n)),
        ("holes", json(&polygon.input_holes())),
        ("pseudotriangle_count", json(&p.faces.len())),
        ("edge_count", json(&p.edge_count)),
    ];
    touches_field(&mut fields, polygon);
    if let Some(h) = &p.hull {
        fields.push(("reflex_vertices", json(&h.reflex_vertices)));
        fields.push(("big_angles", json(&h.big_angles)));
        fields.push(("corollary_count", json(&h.corollary(n))));
        fields.push(("minimum_count", json(&h.minimum(n))));
    }
    fields.push(("pseudotriangles", format!("[{}]", faces.join(", "))));
    fields.push(("optimal", json(&p.hull.is_some())));
    fields.push(("input_vertices", json(&polygon.input_vertices())));
    fields.push(("flat_vertices", json(&polygon.flat_vertices())));
    fields
}

/// Triangles as input vertex numbers (shared with the GeoJSON writer).
pub(crate) fn ids<P: Coord>(polygon: &Polygon<P>, triangles: &[[usize; 3]]) -> Vec<[usize; 3]> {
    triangles.iter().map(|t| t.map(|i| polygon.id(i))).collect()
}

/// `value` as compact JSON text (shared with the GeoJSON writer).
pub(crate) fn json<T: Serialize + ?Sized>(value: &T) -> String {
    serde_json::to_string(value).unwrap_or_else(|e| format!("\"unserialisable: {e}\""))
}
