//! The CSV writer (`--to csv`): one row per input feature, its triangles as WKT beside its
//! identity and minitri's facts, the delimited text that GIS tools import with a WKT geometry
//! column (GDAL's CSV driver takes a column named `WKT` as the geometry; QGIS's delimited-text
//! layer lets one pick it).
//!
//! Input contract: as [`super::wkt`]. Output guarantee: RFC 4180 CSV, UTF-8, records ending in
//! CRLF; a header, then one row per input feature in input order (the rows of `--to wkt`'s
//! lines, in the same order), and a row for each failure about an input as a whole (an
//! unreadable file, a syntax error that stops a FeatureCollection), which has no feature
//! number. The columns:
//!
//! | column | value |
//! |---|---|
//! | `WKT` | the feature's line of `--to wkt` (`GEOMETRYCOLLECTION EMPTY` when nothing was triangulated); empty for a failure of an input as a whole |
//! | `source` | the input name (`-` for standard input) |
//! | `feature` | the feature's number in its source, from 0; for an input without features (WKT, vertex lists) the polygon's; empty for a failure of an input as a whole |
//! | `line` | for GeoJSON Lines, the feature's line (from 1) |
//! | `id` | the feature's `id`: a string as its text (`b-1`), a number exactly as written (`12.50`); empty when the feature has none (the JSON output keeps the id's JSON text, where `"17"` and `17` differ) |
//! | `properties` | the feature's `properties`, the JSON text exactly as written; empty when it has none |
//! | `ok` | `true` when every part was triangulated, else `false` |
//! | `algorithm`, `parts`, `triangle_count`, `degenerate_count`, `pseudotriangle_count`, `optimal` | as the members of the same name of `--to geojson`'s `properties.minitri`: empty where that member is absent (no part triangulated; `triangle_count` and `degenerate_count` for `pseudo` and `pseudo-hull`, `pseudotriangle_count` for the others) |
//! | `errors` | the messages, joined by `; ` (each prefixed with `part k: ` for a feature of several parts, `piece k: ` for a piece of a polygon that `--repair` split) |
//!
//! A field is quoted when it holds a comma, a double quote, a CR or a LF, its double quotes
//! doubled (RFC 4180, 2.6 and 2.7); so a `WKT` field is always quoted, and an `id` or
//! `properties` written across lines stays one field.
//!
//! Streamed: a row is written as soon as its feature's last outcome is pushed; the triangles'
//! text is made ahead, in parallel, by [`super::wkt::render`]. Memory: one feature's outcomes.

use super::group::{Records, Rendered, Summary};
use super::wkt::{self, is_feature};
use super::{Renderer, Sink};
use crate::outcome::Outcome;
use std::io::{self, Write};

/// The header row's columns, in order.
pub const COLUMNS: [&str; 14] = [
    "WKT",
    "source",
    "feature",
    "line",
    "id",
    "properties",
    "ok",
    "algorithm",
    "parts",
    "triangle_count",
    "degenerate_count",
    "pseudotriangle_count",
    "optimal",
    "errors",
];

/// Writes a header, then one row per input feature.
pub struct CsvWriter<W: Write> {
    out: W,
    records: Records,
}

impl<W: Write> CsvWriter<W> {
    /// Starts the document: writes the header.
    ///
    /// # Errors
    /// Any I/O error of `out`.
    pub fn new(mut out: W) -> io::Result<CsvWriter<W>> {
        write_row(&mut out, COLUMNS.iter().map(|c| c.to_string()))?;
        Ok(CsvWriter {
            out,
            records: Records::new(),
        })
    }

    /// Takes the next outcome with its rendered triangles ([`wkt::render`]).
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        let CsvWriter { out, records } = self;
        records.push(outcome, rendered, |record| write_record(out, &record))
    }

    /// Writes what is gathered and flushes.
    ///
    /// # Errors
    /// Any I/O error of the output.
    pub fn finish(mut self) -> io::Result<()> {
        if let Some(record) = self.records.finish() {
            write_record(&mut self.out, &record)?;
        }
        self.out.flush()
    }
}

/// Writes the row of one record.
fn write_record(out: &mut impl Write, record: &[Rendered]) -> io::Result<()> {
    match record.first() {
        Some((first, _)) => write_row(out, row(first, record).into_iter()),
        None => Ok(()),
    }
}

/// The `id` field: a string id as its text (`b-1`, what a join in a GIS compares with), any
/// other id (a number) as written (`12.50` stays `12.50`).
fn id_text(value: Option<&serde_json::value::RawValue>) -> String {
    let Some(value) = value else {
        return String::new();
    };
    serde_json::from_str::<String>(value.get()).unwrap_or_else(|_| value.get().to_string())
}

/// The fields of one record's row (`first` its first outcome), in the order of [`COLUMNS`].
fn row(first: &Outcome, record: &[Rendered]) -> [String; COLUMNS.len()] {
    let identity = first.feature.as_ref();
    let feature = identity.map(|id| id.feature.number).or(first.index);
    let raw = |value: Option<&serde_json::value::RawValue>| {
        value.map(|v| v.get().to_string()).unwrap_or_default()
    };
    let summary = Summary::of(record);
    let solved = summary.algorithm.is_some();
    let count = |value: usize, shown: bool| {
        if shown {
            value.to_string()
        } else {
            String::new()
        }
    };
    let triangulated = solved && summary.faces.is_none();
    [
        if is_feature(first) {
            wkt::collection(record)
        } else {
            String::new()
        },
        first.source.clone(),
        feature.map(|k| k.to_string()).unwrap_or_default(),
        identity
            .and_then(|id| id.feature.line)
            .map(|l| l.to_string())
            .unwrap_or_default(),
        id_text(identity.and_then(|id| id.feature.id.as_deref())),
        raw(identity.and_then(|id| id.feature.properties.as_deref())),
        summary.ok().to_string(),
        summary.algorithm.unwrap_or_default().to_string(),
        summary.parts.to_string(),
        count(summary.triangles, triangulated),
        count(summary.degenerate, triangulated),
        count(
            summary.faces.unwrap_or(0),
            solved && summary.faces.is_some(),
        ),
        if solved {
            summary.optimal.to_string()
        } else {
            String::new()
        },
        summary.errors.join("; "),
    ]
}

/// Writes one record: the fields, quoted where needed, comma-separated, then CRLF.
fn write_row(out: &mut impl Write, fields: impl Iterator<Item = String>) -> io::Result<()> {
    for (k, field) in fields.enumerate() {
        if k > 0 {
            out.write_all(b",")?;
        }
        out.write_all(quote(&field).as_bytes())?;
    }
    out.write_all(b"\r\n")
}

/// One field as RFC 4180 writes it: in double quotes, its own doubled, when it holds a comma,
/// a double quote, a CR or a LF; as it is otherwise.
pub fn quote(field: &str) -> std::borrow::Cow<'_, str> {
    if field.contains([',', '"', '\r', '\n']) {
        format!("\"{}\"", field.replace('"', "\"\"")).into()
    } else {
        field.into()
    }
}

impl<W: Write> Sink for CsvWriter<W> {
    fn push(&mut self, outcome: Outcome) -> io::Result<()> {
        let rendered = wkt::render(&outcome);
        self.push_rendered(outcome, rendered)
    }

    fn renderer(&self) -> Option<Renderer> {
        Some(wkt::render)
    }

    fn push_rendered(&mut self, outcome: Outcome, rendered: Option<String>) -> io::Result<()> {
        CsvWriter::push_rendered(self, outcome, rendered)
    }

    fn finish(self: Box<Self>) -> io::Result<()> {
        CsvWriter::finish(*self)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_are_quoted_as_rfc_4180_says() {
        assert_eq!(quote("abc"), "abc");
        assert_eq!(quote(""), "");
        assert_eq!(quote("a,b"), "\"a,b\"");
        assert_eq!(quote("\"b-1\""), "\"\"\"b-1\"\"\"");
        assert_eq!(quote("a\nb"), "\"a\nb\"");
        assert_eq!(quote("a\rb"), "\"a\rb\"");
        let mut out = Vec::new();
        write_row(&mut out, ["x", "1,2", ""].iter().map(|s| s.to_string())).unwrap();
        assert_eq!(out, b"x,\"1,2\",\r\n");
    }
}
