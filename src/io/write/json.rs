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
use crate::outcome::Outcome;
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
            if let Some(message) = outcome.error_message() {
                let feature = outcome.feature.as_ref();
                self.errors.push(ErrorEntry {
                    source: outcome.source.clone(),
                    index: outcome.index,
                    piece: outcome.piece,
                    feature: feature.map(|f| f.feature.number),
                    part: feature.filter(|f| f.multipart()).map(|f| f.part),
                    line: feature.and_then(|f| f.feature.line),
                    id: feature.and_then(|f| f.feature.id.clone()),
                    message,
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
/// Written field by field into one string (numbers and triangle lists without `format!` or
/// intermediate strings: this is most of a small polygon's output cost).
pub fn render(outcome: &Outcome) -> Option<String> {
    let (Ok(solved), Some(polygon), Some(index)) =
        (&outcome.result, &outcome.polygon, outcome.index)
    else {
        return None;
    };
    let t = &solved.triangulation;
    let mut out = Fields(String::with_capacity(512 + 24 * t.triangles.len()));
    out.0.push_str("    {\n");
    out.text("source", &json(&outcome.source));
    out.number("index", index);
    if let Some(feature) = &outcome.feature {
        // Which input feature this is, right after `index`.
        out.number("feature", feature.feature.number);
        if feature.multipart() {
            out.number("part", feature.part);
        }
        if let Some(line) = feature.feature.line {
            out.number("line", line);
        }
        if let Some(id) = &feature.feature.id {
            out.text("id", id.get());
        }
        if let Some(properties) = &feature.feature.properties {
            out.text("properties", properties.get());
        }
    }
    // `piece` only for a repaired polygon split into several.
    if let Some(piece) = outcome.piece {
        out.number("piece", piece);
    }
    match &solved.pseudo {
        Some(p) => {
            let fields = crate::with_polygon!(polygon, q => pseudo_fields(q, t.algorithm, p));
            for (name, value) in &fields {
                out.text(name, value);
            }
        }
        None => crate::with_polygon!(polygon, q => triangle_fields(&mut out, q, t)),
    }
    if let Some(ordinates) = &outcome.ordinates {
        ordinate_fields(&mut out, ordinates);
    }
    let mut out = out.0;
    out.push_str("      \"warnings\": ");
    if outcome.warnings.is_empty() {
        out.push_str("[]");
    } else {
        let warnings: Vec<String> = outcome.warnings.iter().map(ToString::to_string).collect();
        out.push_str(&json(&warnings));
    }
    match (&outcome.repaired, outcome.piece) {
        // A later piece of a polygon split in several: its repairs are listed once, with
        // piece 0 (a copy for every piece grew as k^2 for a ring touching itself k times).
        (Some(_), Some(piece)) if piece > 0 => {
            out.push_str(",\n      \"repaired_in_piece\": 0");
        }
        (Some(repaired), _) => {
            out.push_str(",\n      \"repaired\": ");
            out.push_str(&json(repaired));
        }
        (None, _) => {}
    }
    if let Some(v) = &solved.verification {
        out.push_str(",\n      \"verification\": ");
        out.push_str(&json(v));
    }
    out.push_str("\n    }");
    Some(out)
}

/// The lines `      "name": value,` of a polygon's object, written into one string.
struct Fields(String);

impl Fields {
    /// The field `name` with `value`, JSON text already.
    fn text(&mut self, name: &str, value: &str) {
        self.name(name);
        self.0.push_str(value);
        self.0.push_str(",\n");
    }

    /// The field `name` with a number.
    fn number(&mut self, name: &str, value: usize) {
        self.name(name);
        push_number(&mut self.0, value);
        self.0.push_str(",\n");
    }

    /// The field `name` with `true` or `false`.
    fn boolean(&mut self, name: &str, value: bool) {
        self.text(name, if value { "true" } else { "false" });
    }

    /// The field `name` with triangles as input vertex numbers: `[[a,b,c],...]`, as
    /// `json(&ids(polygon, triangles))` writes it.
    fn triangles<P: Coord>(&mut self, name: &str, polygon: &Polygon<P>, triangles: &[[usize; 3]]) {
        self.name(name);
        self.0.push('[');
        for (k, triangle) in triangles.iter().enumerate() {
            self.0.push_str(if k == 0 { "[" } else { ",[" });
            for (j, &v) in triangle.iter().enumerate() {
                if j > 0 {
                    self.0.push(',');
                }
                push_number(&mut self.0, polygon.id(v));
            }
            self.0.push(']');
        }
        self.0.push_str("],\n");
    }

    /// The start of a line: `      "name": `.
    fn name(&mut self, name: &str) {
        self.0.push_str("      \"");
        self.0.push_str(name);
        self.0.push_str("\": ");
    }
}

/// Appends `value` in decimal, as `serde_json` writes an unsigned number (with the same `itoa`).
pub(crate) fn push_number(out: &mut String, value: usize) {
    out.push_str(itoa::Buffer::new().format(value));
}

/// The fields of a triangulated polygon after its identity and `piece`, in order.
fn triangle_fields<P: Coord>(
    out: &mut Fields,
    polygon: &Polygon<P>,
    t: &crate::algo::Triangulation,
) {
    out.text("algorithm", &json(t.algorithm.name()));
    out.number("vertices", polygon.len());
    out.number("holes", polygon.input_holes());
    // How many touches join rings into boundary walks, for a polygon whose rings touch (absent
    // otherwise, so outputs without touches are unchanged).
    if polygon.touches() > 0 {
        out.number("touches", polygon.touches());
    }
    out.number("triangle_count", t.triangles.len());
    out.number("degenerate_count", t.degenerate.len());
    out.triangles("triangles", polygon, &t.triangles);
    out.triangles("degenerate_triangles", polygon, &t.degenerate);
    out.boolean("optimal", t.optimal);
    // A search cut short: what is proved about the minimum, and why it is not proved minimum.
    if let Some(lower) = t.lower_bound {
        out.number("lower_bound", lower);
    }
    if let Some(stopped) = t.stopped {
        out.text("stopped_by", &json(stopped.name()));
    }
    out.number("input_vertices", polygon.input_vertices());
    out.number("flat_vertices", polygon.flat_vertices());
    let (lower, upper) = polygon.minimum_bounds();
    out.name("bounds");
    out.0.push_str("{\"lower\": ");
    push_number(&mut out.0, lower);
    out.0.push_str(", \"upper\": ");
    push_number(&mut out.0, upper);
    out.0.push_str("},\n");
}

/// `vertices_z` and `vertices_m` (as the input has them): each input vertex's Z and M value, by
/// input vertex number (as `triangles` numbers them), decimals as written (`null` for NaN).
fn ordinate_fields(out: &mut Fields, ordinates: &crate::io::read::Ordinates) {
    let k = ordinates.dims.count();
    // Every k-th value from `first`: Z is first, M last.
    let list = |first: usize| {
        let items: Vec<String> = ordinates
            .values
            .iter()
            .skip(first)
            .step_by(k)
            .map(|value| match value {
                Some(d) => d.to_string(),
                None => "null".to_string(),
            })
            .collect();
        format!("[{}]", items.join(","))
    };
    if ordinates.dims.has_z() {
        out.text("vertices_z", &list(0));
    }
    if ordinates.dims.has_m() {
        out.text("vertices_m", &list(k - 1));
    }
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

/// The fields of a pseudotriangulated polygon (`pseudo`, `pseudo-hull`) after its identity and
/// `piece`, in order: no triangle fields, but `pseudotriangle_count`, `edge_count` and
/// `pseudotriangles` (each `cycle` counter-clockwise from a corner, and its three `corners`); for
/// `pseudo-hull` also `reflex_vertices` (r), `big_angles` (N), `corollary_count` (2n - r - 2) and
/// `minimum_count` (2n - N - 2, the same in general position). `optimal` says whether the count
/// is proved minimum (`pseudo-hull`) rather than only minimal (`pseudo`, and `pseudo-hull`
/// stopped by `--time-limit`, which then also has `"stopped_by": "time limit"`).
fn pseudo_fields<P: Coord>(
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
    fields.push(("optimal", json(&p.optimal())));
    if let Some(stopped) = p.stopped {
        fields.push(("stopped_by", json(stopped.name())));
    }
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
