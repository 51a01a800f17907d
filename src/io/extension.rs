//! The one table of file extensions, for the readers and the writers alike: what a name ending
//! in each stands for when read (a directory walk reads only these, also before `.gz`) and when
//! written (`-o FILE` names the output format). Lookups ignore case.

use super::read::Format;

/// An output format (its writer: `io/write/`, `OutputFormat::sink`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputFormat {
    /// The JSON document of `docs/cli.md`.
    Json,
    /// A GeoJSON FeatureCollection, one Feature per input feature (a GeometryCollection of its
    /// triangles as Polygons; `io/write/features.rs`).
    GeoJson,
    /// GeoJSON Lines: the same Features, one per line (`io/write/features.rs`).
    GeoJsonLines,
    /// A GeoJSON FeatureCollection, one Feature per triangle (`io/write/geojson.rs`).
    GeoJsonTriangles,
    /// WKT, one GEOMETRYCOLLECTION of triangle POLYGONs per line and input feature
    /// (`io/write/wkt.rs`).
    Wkt,
    /// CSV, one row per input feature: its triangles as WKT, its id and properties, minitri's
    /// facts (`io/write/csv.rs`).
    Csv,
    /// An SVG picture, drawn in this style (`io/write/svg.rs`).
    Svg(Style),
}

/// How to draw an SVG picture, beyond what the outcomes say.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Style {
    /// Write vertex numbers at any size (`--labels`); otherwise only up to `svg::LABELS_MAX`
    /// vertices.
    pub labels: bool,
}

impl OutputFormat {
    /// The format a file name's extension stands for (`None` for an unknown one): `json`,
    /// `geojson`, `geojsonl` (or `geojsons`, `ndjson`, `jsonl`), `wkt`, `csv`, `svg`; from the
    /// table below.
    pub fn from_extension(extension: &str) -> Option<OutputFormat> {
        find(extension)?.write
    }

    /// The file extension of this format, without the dot: its first row in the table
    /// (per-triangle GeoJSON: GeoJSON's; any SVG style: SVG's).
    pub fn extension(self) -> &'static str {
        let format = match self {
            OutputFormat::GeoJsonTriangles => OutputFormat::GeoJson,
            OutputFormat::Svg(_) => OutputFormat::Svg(Style::default()),
            other => other,
        };
        TABLE
            .iter()
            .find(|e| e.write == Some(format))
            .map_or("json", |e| e.name)
    }
}

/// One file extension (lowercase, without the dot) and what it stands for.
pub(crate) struct Extension {
    /// The extension.
    pub name: &'static str,
    /// The input format a file of this name is read as; `None`: not an input name.
    pub read: Option<Format>,
    /// Read as GeoJSON Lines, line by line, whatever its content looks like.
    pub lines: bool,
    /// The output format `-o` with this extension stands for; `None`: none.
    pub write: Option<OutputFormat>,
}

const fn entry(
    name: &'static str,
    read: Option<Format>,
    lines: bool,
    write: Option<OutputFormat>,
) -> Extension {
    Extension {
        name,
        read,
        lines,
        write,
    }
}

const GEOJSON: Option<Format> = Some(Format::GeoJson);
const VERTICES: Option<Format> = Some(Format::Vertices);
const GEOJSONL: Option<OutputFormat> = Some(OutputFormat::GeoJsonLines);
const SVG: OutputFormat = OutputFormat::Svg(Style { labels: false });

/// Every extension minitri knows; an output format's own extension is its first row.
pub(crate) const TABLE: &[Extension] = &[
    entry("wkt", Some(Format::Wkt), false, Some(OutputFormat::Wkt)),
    entry("geojson", GEOJSON, false, Some(OutputFormat::GeoJson)),
    entry("json", GEOJSON, false, Some(OutputFormat::Json)),
    entry("geojsonl", GEOJSON, true, GEOJSONL),
    entry("geojsons", GEOJSON, true, GEOJSONL),
    entry("ndjson", GEOJSON, true, GEOJSONL),
    entry("jsonl", GEOJSON, true, GEOJSONL),
    entry("txt", VERTICES, false, None),
    entry("xy", VERTICES, false, None),
    entry("vertices", VERTICES, false, None),
    entry("wkb", Some(Format::Wkb), false, None),
    entry("csv", None, false, Some(OutputFormat::Csv)),
    entry("svg", None, false, Some(SVG)),
];

/// The row of `extension`, any case.
pub(crate) fn find(extension: &str) -> Option<&'static Extension> {
    TABLE
        .iter()
        .find(|e| e.name.eq_ignore_ascii_case(extension))
}

/// The names of the input extensions (`lines`: of GeoJSON Lines only), in table order: the
/// first `.1` of `.0`.
const fn select(lines: bool) -> ([&'static str; TABLE.len()], usize) {
    let mut out = [""; TABLE.len()];
    let (mut k, mut i) = (0, 0);
    while i < TABLE.len() {
        if TABLE[i].read.is_some() && (TABLE[i].lines || !lines) {
            out[k] = TABLE[i].name;
            k += 1;
        }
        i += 1;
    }
    (out, k)
}

const INPUT_NAMES: &([&str; TABLE.len()], usize) = &select(false);
const LINES_NAMES: &([&str; TABLE.len()], usize) = &select(true);

/// The input extensions, in table order.
pub(crate) const INPUT: &[&str] = INPUT_NAMES.0.split_at(INPUT_NAMES.1).0;

/// The GeoJSON Lines extensions, in table order.
pub(crate) const LINES: &[&str] = LINES_NAMES.0.split_at(LINES_NAMES.1).0;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_once_lowercase_and_every_output_format_has_its_own() {
        for (i, e) in TABLE.iter().enumerate() {
            assert_eq!(e.name, e.name.to_ascii_lowercase());
            assert!(TABLE[..i].iter().all(|f| f.name != e.name), "{}", e.name);
            assert!(e.read.is_some() || e.write.is_some(), "{}", e.name);
            assert!(!e.lines || e.read == Some(Format::GeoJson), "{}", e.name);
            if let Some(format) = e.write {
                assert_eq!(find(format.extension()).and_then(|f| f.write), Some(format));
            }
        }
        assert_eq!(OutputFormat::GeoJsonTriangles.extension(), "geojson");
        assert_eq!(LINES, ["geojsonl", "geojsons", "ndjson", "jsonl"]);
        assert_eq!(INPUT.len(), 11);
    }
}
