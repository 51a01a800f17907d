//! Readers: WKT, GeoJSON, the plain vertex list and WKB, all producing [`RawPolygon`]s.
//!
//! Input contract: UTF-8 text (WKB: bytes, or hex text; see [`wkb`]); a gzip-compressed input
//! is decompressed first ([`gzip`]), and what it is is decided on its decompressed bytes. Output guarantee: each polygon as rings of exact decimal
//! coordinates (outer ring first, then the holes in input order), each ring WITHOUT its repeated
//! closing vertex (a ring whose last vertex equals its first, exactly, loses the last one), so that
//! the vertex numbering of `docs/cli.md` is simply the order of vertices over the rings, and
//! the Z and M values of the vertices, when the input has them, in that numbering
//! ([`Ordinates`]; a polygon, or a GeoJSON feature, mixing 2-, 3- and 4-number positions is an
//! error). Nothing
//! else is cleaned here: duplicates, winding and validity are the business of
//! [`crate::geom::polygon`].
//!
//! The `wkt` and `geojson` crates both turn coordinates into `f64`, which loses the decimal value
//! as written (`0.1` is not a binary fraction), and `wkt` reports neither positions nor trailing
//! text; so the readers here are small hand-written parsers that keep the literal text of every
//! number ([`Decimal`]) and report line and column. The tests cross-check them against both crates.
//!
//! Complexity: linear in the input size.

use crate::geom::decimal::Decimal;
use std::fmt;
use std::path::Path;

pub mod csv;
pub mod geojson;
mod geojson_seed;
pub mod geojson_stream;
pub mod gzip;
pub mod limits;
pub mod vertices;
pub mod wkb;
pub mod wkt;

/// A polygon as read: rings of exact coordinates, outer ring first.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct RawPolygon {
    /// `rings[0]` is the outer boundary, `rings[1..]` the holes; no repeated closing vertex.
    pub rings: Vec<Vec<[Decimal; 2]>>,
    /// The Z and M values of its vertices, when its positions have them (`POLYGON Z`,
    /// `[x, y, z]`, WKB Z/M/ZM); `None` for plain `x y` positions. Triangulation is in x, y
    /// only; the writers give each output vertex its input vertex's values.
    pub ordinates: Option<Ordinates>,
}

/// Which values besides x and y each position of a polygon has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dims {
    /// `x y z`.
    Z,
    /// `x y m` (WKT `POLYGON M`, WKB M).
    M,
    /// `x y z m`.
    Zm,
}

impl Dims {
    /// The dimensions of a position of `count` numbers (3 or 4), `measured` when its geometry
    /// is tagged `M` (then 3 numbers are `x y m`); `None` for 2 numbers.
    pub fn of(count: usize, measured: bool) -> Option<Dims> {
        match count {
            3 if measured => Some(Dims::M),
            3 => Some(Dims::Z),
            4 => Some(Dims::Zm),
            _ => None,
        }
    }

    /// How many values a vertex has besides x and y (1 or 2).
    pub fn count(self) -> usize {
        if self == Dims::Zm {
            2
        } else {
            1
        }
    }

    /// Whether the positions have a Z value.
    pub fn has_z(self) -> bool {
        self != Dims::M
    }

    /// Whether the positions have an M value.
    pub fn has_m(self) -> bool {
        self != Dims::Z
    }

    /// The WKT dimension tag: `Z`, `M` or `ZM`.
    pub fn tag(self) -> &'static str {
        match self {
            Dims::Z => "Z",
            Dims::M => "M",
            Dims::Zm => "ZM",
        }
    }
}

/// A Z or M value as read: its exact decimal, or `None` for NaN (which WKT and WKB use for
/// "no value").
pub type Ordinate = Option<Decimal>;

/// The Z and M values of a polygon's vertices, in input vertex numbering (the order of the
/// vertices over the rings, without the closing ones).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ordinates {
    /// Which values each vertex has.
    pub dims: Dims,
    /// `dims.count()` values per vertex (Z before M), vertex after vertex.
    pub values: Vec<Ordinate>,
}

impl Ordinates {
    /// No values yet, of `dims`.
    pub fn new(dims: Dims) -> Ordinates {
        Ordinates {
            dims,
            values: Vec::new(),
        }
    }

    /// The Z value of input vertex `vertex` (`None` without Z, or out of range).
    pub fn z(&self, vertex: usize) -> Option<&Ordinate> {
        self.dims
            .has_z()
            .then(|| self.values.get(vertex * self.dims.count()))
            .flatten()
    }

    /// The M value of input vertex `vertex` (`None` without M, or out of range).
    pub fn m(&self, vertex: usize) -> Option<&Ordinate> {
        let k = self.dims.count();
        self.dims
            .has_m()
            .then(|| self.values.get(vertex * k + k - 1))
            .flatten()
    }

    /// Vertex `vertex`'s values as WKT writes them after `x y`: ` 5` or ` 5 7` (NaN for a
    /// missing value); empty when out of range.
    pub fn wkt(&self, vertex: usize) -> String {
        let k = self.dims.count();
        let mut out = String::new();
        for value in self.values.iter().skip(vertex * k).take(k) {
            out.push(' ');
            match value {
                Some(d) => out.push_str(&d.to_string()),
                None => out.push_str("NaN"),
            }
        }
        out
    }

    /// Vertex `vertex`'s Z as a JSON number after `x, y` in a GeoJSON position: `, 5`
    /// (`, null` for NaN); empty without Z. GeoJSON positions have no M.
    pub fn geojson(&self, vertex: usize) -> String {
        match self.z(vertex) {
            Some(Some(z)) => format!(", {z}"),
            Some(None) => ", null".to_string(),
            None => String::new(),
        }
    }
}

/// An input format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Well-known text: `POLYGON`, `MULTIPOLYGON`, `GEOMETRYCOLLECTION`.
    Wkt,
    /// GeoJSON geometry, Feature, FeatureCollection, or newline-delimited GeoJSON.
    GeoJson,
    /// One `x y` or `x,y` vertex per line (see `docs/cli.md`).
    Vertices,
    /// Well-known binary (WKB, EWKB), binary or hex text, one geometry per line.
    Wkb,
    /// CSV with a `WKT` geometry column, as `--to csv` writes it.
    Csv,
}

/// A position in the input text, both 1-based.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Location {
    /// Line number, from 1.
    pub line: usize,
    /// Column in characters, from 1.
    pub column: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}", self.line, self.column)
    }
}

/// Why an input could not be read. `Display`: `line 3, column 14: expected ')' but found 'x'`.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}{message}", location.map(|l| format!("{l}: ")).unwrap_or_default())]
pub struct ParseError {
    /// Where the problem is, when the format allows saying so.
    pub location: Option<Location>,
    /// What is wrong, in words a user can act on (lowercase, no trailing period).
    pub message: String,
}

impl ParseError {
    /// An error at a known position.
    pub fn at(location: Location, message: impl Into<String>) -> ParseError {
        ParseError {
            location: Some(location),
            message: message.into(),
        }
    }

    /// An error without position.
    pub fn new(message: impl Into<String>) -> ParseError {
        ParseError {
            location: None,
            message: message.into(),
        }
    }
}

/// The 1-based line and column of byte offset `offset` in `text`.
pub fn locate(text: &str, offset: usize) -> Location {
    let offset = offset.min(text.len());
    let before = &text[..text.floor_char_boundary(offset)];
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    Location {
        line,
        column: before[line_start..].chars().count() + 1,
    }
}

/// Why `bytes` is not text, if it is not: a NUL byte (binary data) or a byte sequence that is
/// not UTF-8, whichever comes first, at its line and column. With `whole` false, `bytes` is only
/// the start of the input, and a character cut off at its end is not judged.
///
/// # Examples
/// ```
/// use minitri::io::read::not_text;
/// let error = not_text(b"POLYGON ((0 0,\n 1\xff", true).map(|e| e.to_string());
/// assert_eq!(error.as_deref(), Some("line 2, column 3: not UTF-8 text (byte 0xFF)"));
/// let error = not_text(b"\x7fELF\x02\x01\x00", true).map(|e| e.to_string());
/// assert_eq!(error.as_deref(), Some("line 1, column 7: binary data, not text (a NUL byte)"));
/// assert!(not_text("0 0\n1 0\n0 1 # \u{e9}".as_bytes(), true).is_none());
/// assert!(not_text(&"\u{e9}".as_bytes()[..1], false).is_none(), "cut off");
/// ```
pub fn not_text(bytes: &[u8], whole: bool) -> Option<ParseError> {
    let utf8 = match std::str::from_utf8(bytes) {
        Ok(_) => None,
        Err(e) if e.error_len().is_none() && !whole => None,
        Err(e) => Some(e.valid_up_to()),
    };
    let nul = bytes.iter().position(|&b| b == 0);
    let (at, message) = match (nul, utf8) {
        (Some(n), Some(u)) if u < n => (u, format!("not UTF-8 text (byte 0x{:02X})", bytes[u])),
        (Some(n), _) => (n, "binary data, not text (a NUL byte)".to_string()),
        (None, Some(u)) => (u, format!("not UTF-8 text (byte 0x{:02X})", bytes[u])),
        (None, None) => return None,
    };
    // The bytes before `at` are UTF-8.
    let before = std::str::from_utf8(&bytes[..at]).unwrap_or_default();
    Some(ParseError::at(locate(before, at), message))
}

/// Drops a ring's last vertex when it repeats the first exactly (the optional closing vertex);
/// returns whether it did.
pub(crate) fn drop_closing_vertex(ring: &mut Vec<[Decimal; 2]>) -> bool {
    if ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
        return true;
    }
    false
}

/// Decides the format from a file extension (`None` for standard input or an unknown extension),
/// falling back to the content.
pub fn detect(extension: Option<&str>, text: &str) -> Format {
    by_extension(extension).unwrap_or_else(|| detect_content(text))
}

/// Decides the format from a file extension, or else from the start of the content: `None`
/// when `start` holds no meaningful character yet (only blanks and `#` comments), so that a
/// reader can look further before deciding.
pub fn detect_start(extension: Option<&str>, start: &str) -> Option<Format> {
    let meaningful = || {
        start
            .lines()
            .map(trim_start)
            .any(|l| !l.is_empty() && !l.starts_with('#'))
    };
    // A first line cut off at the end of `start` that may still become a CSV header (`x,y`,
    // or one with a `WKT` column: any line starting with a letter or a quote may) is decided
    // on more text: `x` alone would look like WKT. (WKT and CSV are read whole anyway; GeoJSON,
    // which is streamed, starts with `{` or `[` and is never kept waiting.)
    let undecided = || {
        let (done, last) = match start.rfind('\n') {
            Some(i) => start.split_at(i + 1),
            None => ("", start),
        };
        let last = trim_start(last);
        first_meaningful(done).is_none()
            && (vertices::may_become_header(last)
                || last.starts_with(|c: char| c.is_ascii_alphabetic() || c == '"'))
    };
    by_extension(extension)
        .or_else(|| (meaningful() && !undecided()).then(|| detect_content(start)))
}

/// Decides the format from a file extension, or else from the first bytes of the input
/// (`start`, after gzip decompression): WKB (binary or hex, [`wkb::looks_like_wkb`]), or else
/// as [`detect_start`] decides on the text. `None` when more text is needed to decide.
///
/// # Examples
/// ```
/// use minitri::io::read::{sniff, Format};
/// assert_eq!(sniff(None, b"0103000000010000000400000000"), Some(Format::Wkb));
/// assert_eq!(sniff(None, b"POLYGON ((0 0, 1 0, 0 1))\n"), Some(Format::Wkt));
/// assert_eq!(sniff(None, b"WKT,id\r\n"), Some(Format::Csv));
/// assert_eq!(sniff(None, b"POLYGON ((0 0, 1 0,"), None, "the first line may still be a CSV header");
/// assert_eq!(sniff(Some("txt"), b"0103000000010000000400000000"), Some(Format::Vertices));
/// ```
pub fn sniff(extension: Option<&str>, start: &[u8]) -> Option<Format> {
    by_extension(extension)
        .or_else(|| wkb::looks_like_wkb(start).then_some(Format::Wkb))
        .or_else(|| detect_start(None, &String::from_utf8_lossy(start)))
}

/// The error for an input in a format minitri does not read, recognised by its first bytes
/// (`start`, after gzip decompression), whatever its name and `--from` say: KML, GML and other
/// XML, a shapefile, FlatGeobuf, a GeoPackage or other SQLite database, (Geo)Parquet, a ZIP
/// archive (KMZ, a zipped shapefile), or a compression other than gzip.
///
/// # Examples
/// ```
/// use minitri::io::read::foreign;
/// let kml = "<?xml version=\"1.0\"?>\n<kml xmlns=\"http://www.opengis.net/kml/2.2\">";
/// assert_eq!(
///     foreign(kml.as_bytes()).map(|e| e.to_string()).as_deref(),
///     Some("not a format minitri reads (KML); convert it first, e.g. to GeoJSON with \
///           `ogr2ogr -f GeoJSON out.geojson INPUT`")
/// );
/// assert!(foreign(b"POLYGON ((0 0, 1 0, 0 1))").is_none());
/// ```
pub fn foreign(start: &[u8]) -> Option<ParseError> {
    let text = start
        .strip_prefix("\u{feff}".as_bytes())
        .unwrap_or(start)
        .trim_ascii_start();
    let has = |needle: &str| {
        let head = &start[..start.len().min(4096)];
        head.windows(needle.len())
            .any(|w| w.eq_ignore_ascii_case(needle.as_bytes()))
    };
    let name = if start.starts_with(b"SQLite format 3\0") {
        "a GeoPackage or other SQLite database"
    } else if start.starts_with(b"fgb\x03") {
        "FlatGeobuf"
    } else if start.starts_with(&[0x00, 0x00, 0x27, 0x0A]) {
        "a shapefile"
    } else if start.starts_with(b"PAR1") {
        "Parquet or GeoParquet"
    } else if start.starts_with(b"PK\x03\x04") {
        "a ZIP archive, such as KMZ or a zipped shapefile"
    } else if text.starts_with(b"<") {
        if has("<kml") {
            "KML"
        } else if has("gml") {
            "GML"
        } else {
            "XML"
        }
    } else {
        let other = if start.starts_with(b"BZh") && start.get(3).is_some_and(u8::is_ascii_digit) {
            "bzip2"
        } else if start.starts_with(b"\xFD7zXZ\0") {
            "xz"
        } else if start.starts_with(&[0x28, 0xB5, 0x2F, 0xFD]) {
            "zstd"
        } else {
            return None;
        };
        return Some(ParseError::new(format!(
            "compressed with {other}, which minitri does not read (only gzip); decompress it first"
        )));
    };
    Some(ParseError::new(format!(
        "not a format minitri reads ({name}); convert it first, e.g. to GeoJSON with \
         `ogr2ogr -f GeoJSON out.geojson INPUT`"
    )))
}

/// The first line of `text` that is neither blank nor a `#` comment, without leading blanks.
fn first_meaningful(text: &str) -> Option<&str> {
    text.lines()
        .map(trim_start)
        .find(|l| !l.is_empty() && !l.starts_with('#'))
}

/// The file extensions of the input formats (lowercase), the one list that both the readers
/// ([`by_extension`]) and the walk of a directory use: a file found in a directory is read when
/// its name ends in one of these, or in one of these and `.gz` (gzip, [`gzip`]).
pub const EXTENSIONS: &[&str] = &[
    "wkt", "geojson", "json", "geojsonl", "geojsons", "ndjson", "jsonl", "txt", "xy", "vertices",
    "wkb",
];

/// Of [`EXTENSIONS`], those of GeoJSON Lines (read line by line, whatever their content looks
/// like); the GeoJSON Lines writer's extensions are the same.
pub const LINES_EXTENSIONS: &[&str] = &["geojsonl", "geojsons", "ndjson", "jsonl"];

/// The format a file extension stands for, if any (one of [`EXTENSIONS`], any case).
///
/// # Examples
/// ```
/// use minitri::io::read::{by_extension, Format, EXTENSIONS};
/// assert_eq!(by_extension(Some("JSONL")), Some(Format::GeoJson));
/// assert_eq!(by_extension(Some("wkb")), Some(Format::Wkb));
/// assert!(EXTENSIONS.iter().all(|e| by_extension(Some(e)).is_some()));
/// assert_eq!(by_extension(Some("gz")), None);
/// ```
pub fn by_extension(extension: Option<&str>) -> Option<Format> {
    let extension = extension?.to_ascii_lowercase();
    if !EXTENSIONS.contains(&extension.as_str()) {
        return None;
    }
    Some(match extension.as_str() {
        "wkt" => Format::Wkt,
        "txt" | "xy" | "vertices" => Format::Vertices,
        "wkb" => Format::Wkb,
        _ => Format::GeoJson,
    })
}

/// Is `extension` one of GeoJSON Lines' ([`LINES_EXTENSIONS`], any case)?
pub fn lines_by_extension(extension: Option<&str>) -> bool {
    extension.is_some_and(|e| LINES_EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
}

/// The extension that decides a file's format: its last one, or for a gzip-compressed name
/// (`a.geojson.gz`) the one before `.gz` (`None` when there is none: then the content decides).
///
/// # Examples
/// ```
/// use minitri::io::read::extension_of;
/// assert_eq!(extension_of("d/a.wkt".as_ref()), Some("wkt"));
/// assert_eq!(extension_of("d/a.GeoJSON.GZ".as_ref()), Some("GeoJSON"));
/// assert_eq!(extension_of("d/a.gz".as_ref()), None);
/// assert_eq!(extension_of("-".as_ref()), None);
/// ```
pub fn extension_of(path: &Path) -> Option<&str> {
    let extension = path.extension()?.to_str()?;
    if extension.eq_ignore_ascii_case("gz") {
        Path::new(path.file_stem()?).extension()?.to_str()
    } else {
        Some(extension)
    }
}

/// Is `path` the name of an input file, read when found in a directory: its extension, or the
/// one before `.gz`, one of [`EXTENSIONS`]?
///
/// # Examples
/// ```
/// use minitri::io::read::is_input_name;
/// assert!(is_input_name("a.jsonl".as_ref()) && is_input_name("a.wkt.gz".as_ref()));
/// assert!(!is_input_name("a.gz".as_ref()) && !is_input_name("a.csv".as_ref()));
/// ```
pub fn is_input_name(path: &Path) -> bool {
    by_extension(extension_of(path)).is_some()
}

/// A line without its leading blanks and byte-order marks (a file may start with one, and the
/// format is then decided by what follows it).
fn trim_start(line: &str) -> &str {
    line.trim_start_matches(|c: char| c.is_whitespace() || c == '\u{feff}')
}

/// Decides the format from the first meaningful line: a CSV header with a `WKT` column is CSV
/// with geometries ([`csv`]); a CSV header (`x,y`, two names and a
/// comma) is a vertex list; else by its first character: `{`/`[` is GeoJSON, a letter is WKT,
/// anything else (digits, signs) is a vertex list.
fn detect_content(text: &str) -> Format {
    let line = first_meaningful(text);
    if line.is_some_and(csv::is_wkt_header) {
        return Format::Csv;
    }
    if line.is_some_and(vertices::is_header) {
        return Format::Vertices;
    }
    match line.and_then(|l| l.chars().next()) {
        Some('{' | '[') => Format::GeoJson,
        Some(c) if c.is_ascii_alphabetic() => Format::Wkt,
        _ => Format::Vertices,
    }
}

/// Reads every polygon of `text` in the given format.
///
/// # Errors
/// [`ParseError`] for malformed text, non-finite or unreadable numbers, wrong geometry types
/// (a `LINESTRING`, a GeoJSON `Point`), an empty ring, empty input, trailing text after a WKT
/// geometry. Rings with fewer than 3 vertices are read; validation reports them.
pub fn read(format: Format, text: &str) -> Result<Vec<RawPolygon>, ParseError> {
    match format {
        Format::Wkt => wkt::read(text),
        Format::GeoJson => geojson::read(text),
        Format::Vertices => vertices::read(text),
        Format::Wkb => wkb::read_parts_within(text.as_bytes(), limits::MAX_VERTICES)?
            .into_iter()
            .collect(),
        Format::Csv => csv::read_parts_within(text, limits::MAX_VERTICES)?
            .into_iter()
            .collect(),
    }
}

/// Reads every part of `text` in the given format, in input order: its polygons, and for each
/// member of a geometry collection that is not a polygon (a WKT `POINT`, a GeoJSON `LineString`,
/// ...) the error that names it; the collection's polygons stand.
///
/// # Errors
/// As [`read`], but for those members.
///
/// # Examples
/// ```
/// use minitri::io::read::{read_parts, Format};
/// let parts = read_parts(Format::Wkt, "GEOMETRYCOLLECTION (LINESTRING (0 0, 1 1), POLYGON ((0 0, 1 0, 0 1)))")?;
/// assert_eq!(parts.len(), 2);
/// assert!(parts[0].is_err() && parts[1].is_ok());
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts(
    format: Format,
    text: &str,
) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    read_parts_within(format, text, limits::MAX_VERTICES)
}

/// [`read_parts`] with a cap of `max_vertices` vertices a polygon (WKT, vertex list): a polygon
/// past it is an error in its place, and the other polygons stand. GeoJSON read whole keeps
/// the default cap, [`limits::MAX_VERTICES`] positions a top-level value (the command streams
/// GeoJSON with its own cap: [`geojson_stream::stream_within`]).
///
/// # Errors
/// As [`read_parts`].
pub fn read_parts_within(
    format: Format,
    text: &str,
    max_vertices: usize,
) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    match format {
        Format::Wkt => wkt::read_parts_within(text, max_vertices),
        Format::GeoJson => geojson::read_parts(text),
        Format::Vertices => vertices::read_parts_within(text, max_vertices),
        Format::Wkb => wkb::read_parts_within(text.as_bytes(), max_vertices),
        Format::Csv => csv::read_parts_within(text, max_vertices),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_decision_on_a_prefix_is_the_decision_on_the_whole() {
        // What the read_auto fuzz target requires: whatever `detect_start` decides on a prefix,
        // `detect` decides on the whole text.
        for text in [
            "a,b,WKT\nPOLYGON ((0 0, 1 0, 0 1))\n",
            "\"WKT\",id\n\"POLYGON ((0 0, 1 0, 0 1))\",1\n",
            "ab(,WKT\n",
            "x,y\n0,0\n1,0\n0,1\n",
            "POLYGON ((0 0, 1 0, 0 1))\n",
            "# comment\n\u{feff}lon,lat\n0 0\n",
            "{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [0, 1]]]}",
        ] {
            let whole = detect(None, text);
            for end in (0..=text.len()).filter(|&e| text.is_char_boundary(e)) {
                if let Some(early) = detect_start(None, &text[..end]) {
                    assert_eq!(early, whole, "{text:?} cut at {end}");
                }
            }
        }
        assert_eq!(detect(None, "a,b,WKT\n"), Format::Csv);
        assert_eq!(detect(None, "x,y\n"), Format::Vertices);
        // GeoJSON is decided on its first character, however long its first line.
        assert_eq!(
            detect_start(None, "{\"type\": \"Poly"),
            Some(Format::GeoJson)
        );
    }
}
