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
use std::io::{BufRead, BufReader, Read};
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

pub use crate::raw::{Dims, Location, Ordinate, Ordinates, ParseError, RawPolygon};

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

/// An input opened ([`open`]): how its polygons are to be read, decided on its name, its first
/// bytes (after gzip decompression) and the format asked for.
pub(crate) enum Opened {
    /// Read whole (WKB, WKT, a vertex list, CSV): every part in input order, with its SRID.
    Parts(wkb::PartsAndSrids),
    /// GeoJSON Lines, to be read line by line from this reader.
    Lines(BufReader<Box<dyn Read>>),
    /// GeoJSON, to be streamed feature by feature from this reader.
    GeoJson(BufReader<Box<dyn Read>>),
    /// GeoJSON found by its content once read whole, to be streamed from this text.
    GeoJsonText(String),
}

/// The one place an input is opened: `reader` decompressed when gzip (by its magic bytes), a
/// format minitri does not read named ([`foreign`]), the format taken from `from`, else decided
/// by the name's extension (`path`, `None` for standard input) and the first bytes ([`sniff`]),
/// else on the whole text ([`detect`]); then read whole (at most `limit` bytes, decompressed
/// ones for gzip; at most `max_vertices` vertices a polygon) or left to be read line by line or
/// streamed (GeoJSON).
///
/// # Errors
/// [`limits::NotRead`]: the reader failed, or the input is not one minitri reads (binary
/// data, a foreign format, too large, unreadable as its format).
pub(crate) fn open(
    reader: Box<dyn Read>,
    path: Option<&Path>,
    from: Option<Format>,
    limit: u64,
    max_vertices: usize,
) -> Result<Opened, limits::NotRead> {
    use limits::NotRead;
    let mut reader = BufReader::with_capacity(1 << 16, reader);
    // `a.geojson.gz`: the extension before `.gz` decides.
    let extension = path.and_then(extension_of);
    let mut gzip = false;
    let start = loop {
        let start = reader.fill_buf().map_err(NotRead::Io)?;
        // gzip by its magic bytes: decompressed as it is read, then judged like any input.
        if gzip || !gzip::is_gzip(start) {
            break start;
        }
        gzip = true;
        reader = BufReader::with_capacity(1 << 16, Box::new(gzip::decompress(reader)));
    };
    if let Some(error) = foreign(start) {
        return Err(NotRead::Parse(error));
    }
    let format = from.or_else(|| sniff(extension, start));
    // Read chunk by chunk, at most `limit` bytes (decompressed ones, for gzip).
    let size = path
        .filter(|_| !gzip)
        .and_then(|path| std::fs::metadata(path).map(|m| m.len()).ok())
        .unwrap_or(0);
    let note = if gzip { " decompressed" } else { "" };
    if format == Some(Format::Wkb) {
        let bytes = limits::read_bytes(reader, limit, size, note)?;
        return wkb::read_parts_srid_within(&bytes, max_vertices)
            .map(Opened::Parts)
            .map_err(NotRead::Parse);
    }
    if format == Some(Format::GeoJson) {
        if lines_by_extension(extension) || geojson_stream::looks_line_delimited(start) {
            return Ok(Opened::Lines(reader));
        }
        // Binary data is named as such, not as a JSON syntax error (judged on the start only).
        if let Some(error) = not_text(start, false) {
            return Err(NotRead::Parse(error));
        }
        return Ok(Opened::GeoJson(reader));
    }
    // Read chunk by chunk, stopping at the first byte that cannot be text (limits.rs).
    let text = limits::read_text_noted(reader, limit, size, note)?;
    let format = format.unwrap_or_else(|| detect(extension, &text));
    let parts = match format {
        Format::GeoJson => return Ok(Opened::GeoJsonText(text)),
        Format::Wkt => wkt::read_parts_srid_within(&text, max_vertices),
        _ => read_parts_within(format, &text, max_vertices).map(|parts| {
            let srids = vec![None; parts.len()];
            (parts, srids)
        }),
    };
    parts.map(Opened::Parts).map_err(NotRead::Parse)
}

/// The first line of `text` that is neither blank nor a `#` comment, without leading blanks.
fn first_meaningful(text: &str) -> Option<&str> {
    text.lines()
        .map(trim_start)
        .find(|l| !l.is_empty() && !l.starts_with('#'))
}

/// The file extensions of the input formats (lowercase), from the one table of extensions of
/// the readers and writers: a file found in a directory is read when its name ends in one of
/// these, or in one of these and `.gz` (gzip, [`gzip`]).
pub const EXTENSIONS: &[&str] = crate::io::extension::INPUT;

/// Of [`EXTENSIONS`], those of GeoJSON Lines (read line by line, whatever their content looks
/// like); the GeoJSON Lines writer's extensions are the same.
pub const LINES_EXTENSIONS: &[&str] = crate::io::extension::LINES;

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
    crate::io::extension::find(extension?)?.read
}

/// Is `extension` one of GeoJSON Lines' ([`LINES_EXTENSIONS`], any case)?
pub fn lines_by_extension(extension: Option<&str>) -> bool {
    extension
        .and_then(crate::io::extension::find)
        .is_some_and(|e| e.lines)
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
