//! The JSON writer: the document of `spec/CLI.md`.
//!
//! Output: `{"polygons": [...], "errors": [...]}`, one object per triangulated polygon with the
//! spec's fields (vertex numbers are INPUT numbers, triangles counter-clockwise), plus
//! `input_vertices` (vertex numbers used, including dropped duplicates), `flat_vertices`,
//! `bounds` (Theorem 3's bounds on the minimum, generalised to flat vertices), `warnings`, and
//! `verification` with `--verify`. Every polygon or input that failed is listed under `errors`
//! with its source, index and message. Pretty at the top level, one line per triangle list, so
//! files stay small and diffable. Complexity: linear in the output size.

use crate::geom::polygon::Polygon;
use crate::pipeline::Outcome;
use serde::Serialize;
use std::io::{self, Write};

/// Writes the JSON document for `outcomes`.
///
/// # Errors
/// Any I/O error of `out`.
pub fn write_json(outcomes: &[Outcome], out: &mut impl Write) -> io::Result<()> {
    writeln!(out, "{{")?;
    let entries: Vec<_> = outcomes
        .iter()
        .filter_map(|o| match (&o.result, &o.polygon, o.index) {
            (Ok(s), Some(p), Some(i)) => Some((o, s, p, i)),
            _ => None,
        })
        .collect();
    writeln!(
        out,
        "  \"polygons\": [{}",
        if entries.is_empty() { "]," } else { "" }
    )?;
    for (k, (outcome, solved, polygon, index)) in entries.iter().enumerate() {
        let t = &solved.triangulation;
        let fields: Vec<(&str, String)> = vec![
            ("source", json(&outcome.source)),
            ("index", json(index)),
            ("algorithm", json(t.algorithm.name())),
            ("vertices", json(&polygon.len())),
            ("holes", json(&polygon.holes())),
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
        let mut fields = fields;
        if let Some(lower) = t.lower_bound {
            // A search cut short: what is proved about the minimum, right after `optimal`.
            let after = fields.iter().position(|(name, _)| *name == "optimal");
            let at = after.map_or(fields.len(), |i| i + 1);
            fields.insert(at, ("lower_bound", json(&lower)));
        }
        writeln!(out, "    {{")?;
        for (name, value) in &fields {
            writeln!(out, "      \"{name}\": {value},")?;
        }
        let warnings: Vec<String> = outcome.warnings.iter().map(ToString::to_string).collect();
        write!(out, "      \"warnings\": {}", json(&warnings))?;
        if let Some(v) = &solved.verification {
            write!(out, ",\n      \"verification\": {}", json(v))?;
        }
        writeln!(
            out,
            "\n    }}{}",
            if k + 1 < entries.len() { "," } else { "" }
        )?;
    }
    if !entries.is_empty() {
        writeln!(out, "  ],")?;
    }
    #[derive(Serialize)]
    struct ErrorEntry<'a> {
        source: &'a str,
        #[serde(skip_serializing_if = "Option::is_none")]
        index: Option<usize>,
        message: String,
    }
    let errors: Vec<ErrorEntry> = outcomes
        .iter()
        .filter_map(|o| {
            o.result.as_ref().err().map(|e| ErrorEntry {
                source: &o.source,
                index: o.index,
                message: e.to_string(),
            })
        })
        .collect();
    writeln!(out, "  \"errors\": {}", json(&errors))?;
    writeln!(out, "}}")
}

/// Triangles as input vertex numbers.
fn ids(polygon: &Polygon, triangles: &[[usize; 3]]) -> Vec<[usize; 3]> {
    triangles.iter().map(|t| t.map(|i| polygon.id(i))).collect()
}

fn json<T: Serialize + ?Sized>(value: &T) -> String {
    serde_json::to_string(value).unwrap_or_else(|e| format!("\"unserialisable: {e}\""))
}
