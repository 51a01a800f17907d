//! Reader for GeoJSON (RFC 7946), on `serde_json` with exact numbers.
//!
//! # Accepted input
//!
//! One JSON value, or several concatenated or newline-delimited (GeoJSON Lines / NDJSON), each:
//!
//! - a `Polygon` or `MultiPolygon` geometry (each MultiPolygon part is one polygon), or a
//!   `GeometryCollection` of those (nested up to 64 levels); a member of another type (a
//!   `Point`, a `LineString`, ...) is a failed part: [`read_parts`] gives its error in its place
//!   among the polygons, which stand (`geometry 0: expected a Polygon or MultiPolygon geometry,
//!   found "Point"`), and [`read`] fails on it;
//! - a `Feature` whose `geometry` is one of the above, or `null` (which yields no polygon);
//! - a `FeatureCollection` of such Features;
//! - a bare array of rings `[[[x, y], ...], ...]` (a Polygon's `coordinates`, the layout of the
//!   earcut fixtures), read as one polygon.
//!
//! A position is `[x, y]`, `[x, y, z]` or `[x, y, z, m]`; z and m must be numbers and are ignored.
//! An empty `coordinates` array is an empty geometry and yields no polygon; an empty ring is an
//! error. Other members (`bbox`, `properties`, `id`, foreign members) are ignored. Members come in
//! any order, but `type`, `coordinates`, `geometry`, `geometries` and `features` may each appear
//! once in an object (a second `type` could change how `coordinates` before it should be read).
//!
//! Output guarantee: the polygons in input order, coordinates as exact decimals
//! ([`Decimal`](crate::Decimal)) parsed from the literal text of each JSON number
//! (`serde_json`'s `arbitrary_precision`, never through `f64`; it keeps the digits and only
//! spells the exponent as `e+5`, so error messages quote `1E5` as `1e+5`), each ring without
//! its repeated closing vertex. JSON syntax errors carry line and column; errors in a
//! well-formed document name the path to the offending value (`feature 3, ring 1, position 5:
//! expected [x, y], found "abc"`), and, when the input holds several JSON values, the line and
//! column where the offending value starts.
//!
//! Each JSON value is read by the `serde` seeds of `geojson_seed.rs` (positions straight into
//! decimals, 64 bytes per vertex; never a `serde_json::Value` for coordinates), then judged here.
//!
//! Complexity: linear in the input size.

use super::geojson_seed::{Coordinates, Node, Object};
use super::vertices::quote;
use super::{locate, Location, ParseError};
use crate::io::read::RawPolygon;

/// The whitespace JSON allows between tokens (RFC 8259): not form feed or other Unicode spaces,
/// which `str::trim` would also remove.
pub(crate) const JSON_WHITESPACE: [char; 4] = [' ', '\t', '\r', '\n'];

/// Deepest nesting of `GeometryCollection`s accepted (`serde_json` also limits JSON nesting).
const MAX_DEPTH: usize = 64;

/// Reads every polygon of a GeoJSON text (one or several JSON values).
///
/// # Errors
/// [`ParseError`] for malformed JSON (with line and column), a GeoJSON object of another type
/// (`Point`, `LineString`, ...), a missing `type`, `coordinates`, `geometry`, `geometries` or
/// `features` member, coordinates of the wrong nesting depth, a position that is not 2 to 4
/// numbers, a number that is not a finite decimal, an empty ring, an empty input, or an input
/// holding no polygon.
///
/// # Examples
/// ```
/// use minitri::io::read::geojson;
/// let text = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1], [0, 0]]]}"#;
/// let polygons = geojson::read(text)?;
/// assert_eq!(polygons[0].rings[0].len(), 3);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read(text: &str) -> Result<Vec<RawPolygon>, ParseError> {
    // All or nothing: the first failed part is the error.
    read_parts(text)?.into_iter().collect()
}

/// Reads every part of a GeoJSON text: its polygons, and each member of a GeometryCollection
/// that is not a polygon (a Point, a LineString, ...) as the error that names it by its path
/// (`geometry 0: expected a Polygon or MultiPolygon geometry, found "Point"`), in input order.
/// Anything else wrong is an error of the whole input, as in [`read`] (which is this, failing
/// at the first failed part).
///
/// # Errors
/// As [`read`], but for the members of GeometryCollections that are not polygons; an input
/// without any part is an error.
///
/// # Examples
/// ```
/// use minitri::io::read::geojson;
/// let text = r#"{"type": "GeometryCollection", "geometries": [{"type": "Point", "coordinates": [1, 2]},
///   {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}]}"#;
/// let parts = geojson::read_parts(text)?;
/// assert_eq!(
///     parts[0].as_ref().unwrap_err().to_string(),
///     "geometry 0: expected a Polygon or MultiPolygon geometry, found \"Point\""
/// );
/// assert_eq!(parts[1].as_ref().unwrap().rings[0].len(), 3);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts(text: &str) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    let (values, several) = values(text)?;
    let mut out = Vec::new();
    for (start, value) in values {
        let mut parts = Vec::new();
        let located = |failure: Failure| ParseError {
            location: several.then(|| locate(text, start)),
            message: failure.to_string(),
        };
        top_level(value, &mut parts).map_err(located)?;
        out.extend(parts.into_iter().map(|part| part.map_err(located)));
    }
    if out.is_empty() {
        return Err(no_polygon());
    }
    Ok(out)
}

/// The error of an input without any polygon.
fn no_polygon() -> ParseError {
    ParseError::new("no polygon found: the input holds no non-empty Polygon or MultiPolygon")
}

/// The JSON values of a GeoJSON text, each with the byte offset where it starts, and whether
/// there are several.
fn values(text: &str) -> Result<(Vec<(usize, Node)>, bool), ParseError> {
    let bom = if text.starts_with('\u{feff}') {
        '\u{feff}'.len_utf8()
    } else {
        0
    };
    let body = text.get(bom..).unwrap_or_default();
    let mut values = Vec::new();
    let mut stream = serde_json::Deserializer::from_str(body).into_iter::<Node>();
    loop {
        let before = stream.byte_offset();
        match stream.next() {
            None => break,
            Some(Ok(value)) => {
                let rest = body.get(before..).unwrap_or_default();
                let start = before + rest.len() - rest.trim_start_matches(JSON_WHITESPACE).len();
                values.push((bom + start, value));
            }
            Some(Err(error)) => return Err(json_error(text, bom, &error)),
        }
    }
    if values.is_empty() {
        return Err(ParseError::new("empty input: no polygon found"));
    }
    let several = values.len() > 1;
    Ok((values, several))
}

/// A `serde_json` syntax error as a [`ParseError`] at its line and (character) column.
fn json_error(text: &str, bom: usize, error: &serde_json::Error) -> ParseError {
    if error.is_eof() {
        return ParseError::at(locate(text, text.len()), json_message(error, None));
    }
    if error.line() == 0 {
        return ParseError::new(json_message(error, None));
    }
    // serde_json counts bytes from the start of the line (after the byte-order mark on line 1),
    // and its column is that of the last byte read, or 0 right after a newline.
    let line_start = if error.line() == 1 {
        bom
    } else {
        text.match_indices('\n')
            .nth(error.line() - 2)
            .map_or(text.len(), |(i, _)| i + 1)
    };
    let offset = line_start + error.column().saturating_sub(1);
    let location = locate(text, offset);
    let message = json_message(error, text.as_bytes().get(offset).copied());
    ParseError::at(
        Location {
            line: error.line(),
            column: location.column,
        },
        message,
    )
}

/// A `serde_json` syntax error in words, without its position: `invalid JSON: ...`; `found` is
/// the byte where it was detected, if known (to name `NaN` and `Infinity`, which JSON lacks).
pub(super) fn json_message(error: &serde_json::Error, found: Option<u8>) -> String {
    let full = error.to_string();
    let suffix = format!(" at line {} column {}", error.line(), error.column());
    let message = full.strip_suffix(&suffix).unwrap_or(&full);
    let message = match message.strip_prefix("EOF while parsing ") {
        Some(what) => format!("the input ends in the middle of {what}"),
        None => message.to_string(),
    };
    let hint = match found {
        Some(b'N' | b'I') if !error.is_eof() => {
            " (NaN and Infinity are not JSON numbers; coordinates must be finite)"
        }
        _ => "",
    };
    format!("invalid JSON: {message}{hint}")
}

/// What is wrong with a well-formed document, and the path to where (outermost first).
#[derive(Debug)]
pub(super) struct Failure {
    path: Vec<(&'static str, usize)>,
    message: String,
}

impl Failure {
    pub(super) fn new(message: impl Into<String>) -> Failure {
        Failure {
            path: Vec::new(),
            message: message.into(),
        }
    }

    /// The same failure, inside element `index` of a list of `name`s.
    pub(super) fn within(mut self, name: &'static str, index: usize) -> Failure {
        self.nest(name, index);
        self
    }

    /// Puts this failure inside element `index` of a list of `name`s.
    pub(super) fn nest(&mut self, name: &'static str, index: usize) {
        self.path.insert(0, (name, index));
    }
}

/// One part of a feature as read: a polygon, or a member of a GeometryCollection that is not a
/// polygon (a Point, a LineString, ...), which fails alone: the collection's polygons stand.
pub(super) type Part = Result<RawPolygon, Failure>;

/// Puts the failed parts among `parts` inside element `index` of a list of `name`s.
pub(super) fn nest_parts(parts: &mut [Part], name: &'static str, index: usize) {
    for failure in parts.iter_mut().filter_map(|part| part.as_mut().err()) {
        failure.nest(name, index);
    }
}

impl std::fmt::Display for Failure {
    /// `feature 3, ring 1: message`.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let mut separator = "";
        for (name, index) in &self.path {
            write!(f, "{separator}{name} {index}")?;
            separator = ", ";
        }
        if !self.path.is_empty() {
            f.write_str(": ")?;
        }
        f.write_str(&self.message)
    }
}

/// A top-level JSON value: a GeoJSON object or a bare array of rings. Its parts go to `out`;
/// the `Err` is a failure of the whole value (then `out` is to be dropped).
pub(super) fn top_level(node: Node, out: &mut Vec<Part>) -> Result<(), Failure> {
    match node {
        Node::Object(object) => match type_of(&object)?.as_str() {
            "Feature" => feature(*object, out),
            "FeatureCollection" => feature_collection(*object, out),
            kind => geometry(*object, kind, 0, out),
        },
        Node::Rings(Ok(None)) => Err(Failure::new(
            "expected an array of rings [[[x, y], ...], ...], found an empty array",
        )),
        Node::Rings(polygon) => {
            out.extend(polygon?.map(Ok));
            Ok(())
        }
        other => Err(Failure::new(format!(
            "expected a GeoJSON object or an array of rings [[[x, y], ...], ...], found {}",
            other.describe()
        ))),
    }
}

/// The `type` member of a GeoJSON object (whose GeoJSON members must each appear once).
pub(super) fn type_of(object: &Object) -> Result<String, Failure> {
    if let Some(name) = object.duplicate {
        return Err(Failure::new(format!(
            "duplicate \"{name}\" member: each may appear once in an object"
        )));
    }
    match &object.kind {
        Some(Node::String(kind)) => Ok(kind.clone()),
        Some(other) => Err(Failure::new(format!(
            "\"type\" must be a string, found {}",
            other.describe()
        ))),
        None => Err(Failure::new(
            "missing \"type\": expected a GeoJSON object such as {\"type\": \"Polygon\", \"coordinates\": ...}",
        )),
    }
}

/// A member that must be present.
fn member<T>(value: Option<T>, name: &str, kind: &str) -> Result<T, Failure> {
    value.ok_or_else(|| Failure::new(format!("missing \"{name}\" member in a {kind}")))
}

/// A member that must be an array, read element by element.
fn list_member(value: Option<Node>, name: &str, kind: &str) -> Result<Vec<Node>, Failure> {
    match member(value, name, kind)? {
        Node::List(items) => Ok(items),
        // Sent elsewhere as they were read.
        Node::Streamed => Ok(Vec::new()),
        other => Err(Failure::new(format!(
            "\"{name}\" of a {kind} must be an array, found {}",
            other.describe()
        ))),
    }
}

/// A FeatureCollection: each feature in order.
fn feature_collection(object: Object, out: &mut Vec<Part>) -> Result<(), Failure> {
    let features = list_member(object.features, "features", "FeatureCollection")?;
    for (index, item) in features.into_iter().enumerate() {
        let start = out.len();
        collection_feature(item, out).map_err(|failure| failure.within("feature", index))?;
        nest_parts(&mut out[start..], "feature", index);
    }
    Ok(())
}

/// An element of a FeatureCollection's `features`: a Feature.
pub(super) fn collection_feature(item: Node, out: &mut Vec<Part>) -> Result<(), Failure> {
    let object = object_of(item, "a Feature object")?;
    match type_of(&object)?.as_str() {
        "Feature" => feature(object, out),
        kind => Err(Failure::new(format!(
            "expected a Feature, found {}",
            quote(kind)
        ))),
    }
}

/// An element of a GeometryCollection's `geometries`, `depth` collections deep. A geometry of
/// another type (a Point, a LineString, ...) is one failed part; anything else wrong with it
/// (not an object, no `type`, bad coordinates) fails the whole collection.
fn collection_geometry(item: Node, depth: usize, out: &mut Vec<Part>) -> Result<(), Failure> {
    let object = object_of(item, "a geometry object")?;
    let kind = type_of(&object)?;
    match kind.as_str() {
        "Polygon" | "MultiPolygon" | "GeometryCollection" => geometry(object, &kind, depth, out),
        other => {
            out.push(Err(not_a_polygon(other)));
            Ok(())
        }
    }
}

/// The failure of a geometry of type `kind`, which is no polygon.
fn not_a_polygon(kind: &str) -> Failure {
    Failure::new(format!(
        "expected a Polygon or MultiPolygon geometry, found {}",
        quote(kind)
    ))
}

/// A value that must be a JSON object; `what` names it in the error.
fn object_of(node: Node, what: &str) -> Result<Object, Failure> {
    match node {
        Node::Object(object) => Ok(*object),
        other => Err(Failure::new(format!(
            "expected {what}, found {}",
            other.describe()
        ))),
    }
}

/// A Feature: its geometry, if not `null`.
fn feature(object: Object, out: &mut Vec<Part>) -> Result<(), Failure> {
    match member(object.geometry, "geometry", "Feature")? {
        Node::Null => Ok(()),
        Node::Object(geometry_object) => {
            let kind = type_of(&geometry_object)?;
            geometry(*geometry_object, &kind, 0, out)
        }
        other => Err(Failure::new(format!(
            "\"geometry\" must be an object or null, found {}",
            other.describe()
        ))),
    }
}

/// A geometry object of type `kind`, `depth` collections deep.
fn geometry(object: Object, kind: &str, depth: usize, out: &mut Vec<Part>) -> Result<(), Failure> {
    match kind {
        "Polygon" | "MultiPolygon" => match member(object.coordinates, "coordinates", kind)? {
            Coordinates::Polygon(polygon) => out.extend(polygon?.map(Ok)),
            Coordinates::MultiPolygon(polygons) => out.extend(polygons?.into_iter().map(Ok)),
            // Read for another `type`: only when "type" was named twice, reported before this.
            Coordinates::Text(_) | Coordinates::Skipped => {
                return Err(Failure::new(format!(
                    "\"coordinates\" were not read as those of a {kind}"
                )))
            }
        },
        "GeometryCollection" => {
            if depth >= MAX_DEPTH {
                return Err(Failure::new(format!(
                    "geometry collections nested deeper than {MAX_DEPTH} levels"
                )));
            }
            let geometries = list_member(object.geometries, "geometries", "GeometryCollection")?;
            for (index, item) in geometries.into_iter().enumerate() {
                let start = out.len();
                collection_geometry(item, depth + 1, out)
                    .map_err(|failure| failure.within("geometry", index))?;
                nest_parts(&mut out[start..], "geometry", index);
            }
        }
        other => return Err(not_a_polygon(other)),
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{as_f64, d, ring};
    use serde::de::value::{Error as DeError, MapDeserializer, SeqDeserializer};
    use serde::de::{Deserializer, Error as _, IntoDeserializer, Visitor};
    use serde::Deserialize;
    use serde_json::Value;

    fn error(text: &str) -> String {
        read(text).expect_err(text).to_string()
    }

    const SQUARE: &str = r#"{"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4], [0, 0]], [[1, 1], [2, 1], [2, 2]]]}"#;

    #[test]
    fn reads_a_polygon_with_holes_and_optional_closing_position() {
        let polygons = read(SQUARE).unwrap();
        assert_eq!(polygons.len(), 1);
        assert_eq!(
            polygons[0].rings,
            vec![
                ring(&[("0", "0"), ("4", "0"), ("4", "4"), ("0", "4")]),
                ring(&[("1", "1"), ("2", "1"), ("2", "2")])
            ]
        );
    }

    #[test]
    fn keeps_decimals_exact() {
        let text = r#"{"type": "Polygon", "coordinates": [[[0, 0], [0.1, 0.3], [0.2, 0.6], [-1.5E-3, 1e2], [0.1000000000000000000001, 7]]]}"#;
        let r = &read(text).unwrap()[0].rings[0];
        assert_eq!(r[1], [d("0.1"), d("0.3")]);
        assert_eq!(r[2], [d("0.2"), d("0.6")]);
        assert_eq!(r[3], [d("-0.0015"), d("100")]);
        assert_eq!(r[4][0], d("0.1000000000000000000001"));
        assert_ne!(r[4][0], d("0.1"));
    }

    #[test]
    fn keeps_z_and_m_values_and_ignores_other_members() {
        use crate::io::read::{Dims, Ordinates};
        let text = r#"{"type": "Polygon", "bbox": [0, 0, 1, 1], "crs": null,
            "coordinates": [[[0, 0, 10], [1, 0, 11.50], [0, 1, -1e-1], [0, 0, 10]]]}"#;
        let polygons = read(text).unwrap();
        assert_eq!(
            polygons[0].rings[0],
            ring(&[("0", "0"), ("1", "0"), ("0", "1")])
        );
        let z = Ordinates {
            dims: Dims::Z,
            values: vec![Some(d("10")), Some(d("11.5")), Some(d("-0.1"))],
        };
        assert_eq!(polygons[0].ordinates, Some(z));
        let zm = r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0, 1, 2], [1, 0, 3, 4], [0, 1, 5, 6]]]]}"#;
        let values = read(zm).unwrap()[0]
            .ordinates
            .clone()
            .map(|o| (o.dims, o.values.len()));
        assert_eq!(values, Some((Dims::Zm, 6)));
        assert_eq!(read(SQUARE).unwrap()[0].ordinates, None);
        // One feature's positions all have as many numbers, across its polygons too.
        let mixed = r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0, 1], [1, 0, 1], [0, 1, 1]]], [[[0, 0, 1], [1, 0, 1], [0, 1, 1, 2]]]]}"#;
        assert_eq!(
            error(mixed),
            "polygon 1, ring 0, position 2: this position has 4 numbers but the feature's first \
             position has 3: mixed [x, y], [x, y, z] and [x, y, z, m] positions"
        );
    }

    #[test]
    fn reads_every_container() {
        let multi = r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]], [], [[[5, 5], [6, 5], [5, 6], [5, 5]]]]}"#;
        assert_eq!(read(multi).unwrap().len(), 2);
        let collection = r#"{"type": "GeometryCollection", "geometries": [
            {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]},
            {"type": "GeometryCollection", "geometries": [{"type": "MultiPolygon", "coordinates": [[[[2, 2], [3, 2], [2, 3]]]]}]},
            {"type": "Polygon", "coordinates": []}]}"#;
        let polygons = read(collection).unwrap();
        assert_eq!(polygons.len(), 2);
        assert_eq!(polygons[1].rings[0][0], [d("2"), d("2")]);
        let feature = r#"{"type": "Feature", "properties": {"name": "x"}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}}"#;
        assert_eq!(read(feature).unwrap().len(), 1);
        let features = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "properties": {}, "geometry": null},
            {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}},
            {"type": "Feature", "properties": null, "geometry": {"type": "MultiPolygon", "coordinates": [[[[7, 7], [8, 7], [7, 8]]], [[[9, 9], [10, 9], [9, 10]]]]}}]}"#;
        let polygons = read(features).unwrap();
        let firsts: Vec<_> = polygons.iter().map(|p| p.rings[0][0]).collect();
        assert_eq!(
            firsts,
            vec![[d("0"), d("0")], [d("7"), d("7")], [d("9"), d("9")]]
        );
    }

    #[test]
    fn reads_newline_delimited_and_concatenated_values() {
        let ndjson = "{\"type\": \"Feature\", \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [0, 1]]]}, \"properties\": {}}\r\n\
                      {\"type\": \"Polygon\", \"coordinates\": [[[2, 2], [3, 2], [2, 3]]]}\r\n\r\n\
                      {\"type\": \"Feature\", \"geometry\": null, \"properties\": {}}{\"type\": \"Polygon\", \"coordinates\": [[[4, 4], [5, 4], [4, 5]]]}\n";
        let polygons = read(ndjson).unwrap();
        let firsts: Vec<_> = polygons.iter().map(|p| p.rings[0][0]).collect();
        assert_eq!(
            firsts,
            vec![[d("0"), d("0")], [d("2"), d("2")], [d("4"), d("4")]]
        );
    }

    #[test]
    fn reads_a_bare_array_of_rings_as_one_polygon() {
        let polygons =
            read("[[[0,0],[10,0],[10,10],[0,10]],[[2,2],[3,3],[2,3],[2,2]],[[5,5]]]").unwrap();
        assert_eq!(polygons.len(), 1);
        assert_eq!(polygons[0].rings.len(), 3);
        assert_eq!(polygons[0].rings[1].len(), 3);
        assert_eq!(polygons[0].rings[2], ring(&[("5", "5")]));
        assert_eq!(
            read("\u{feff}[[[0,0],[1,0],[0,1]]]").unwrap()[0].rings[0].len(),
            3
        );
    }

    #[test]
    fn reads_every_earcut_fixture() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/earcut");
        let mut read_count = 0;
        for entry in std::fs::read_dir(dir).unwrap().flatten() {
            let path = entry.path();
            if path.extension().is_some_and(|e| e == "json") && !path.ends_with("expected.json") {
                let text = std::fs::read_to_string(&path).unwrap();
                let polygons = read(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
                assert_eq!(polygons.len(), 1, "{}", path.display());
                read_count += 1;
            }
        }
        assert_eq!(
            read_count, 59,
            "all mapbox/earcut fixtures are in fixtures/earcut"
        );
    }

    #[test]
    fn rejects_wrong_types_naming_where() {
        assert_eq!(
            error(r#"{"type": "LineString", "coordinates": [[0, 0], [1, 1]]}"#),
            "expected a Polygon or MultiPolygon geometry, found \"LineString\""
        );
        let features = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": null}, {"type": "Feature", "geometry": null}, {"type": "Feature", "geometry": null},
            {"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[0, 0], [1, 1]]}}]}"#;
        assert_eq!(
            error(features),
            "feature 3: expected a Polygon or MultiPolygon geometry, found \"LineString\""
        );
        let ndjson = "{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [0, 1]]]}\n\n\n  {\"type\": \"Point\", \"coordinates\": [0, 0]}\n";
        assert_eq!(
            error(ndjson),
            "line 4, column 3: expected a Polygon or MultiPolygon geometry, found \"Point\""
        );
        assert_eq!(
            error(r#"{"coordinates": [[[0, 0], [1, 0], [0, 1]]]}"#),
            "missing \"type\": expected a GeoJSON object such as {\"type\": \"Polygon\", \"coordinates\": ...}"
        );
        assert_eq!(
            error(r#"{"type": 7}"#),
            "\"type\" must be a string, found 7"
        );
        assert_eq!(
            error(r#"{"type": "FeatureCollection", "features": [{"type": "Polygon"}]}"#),
            "feature 0: expected a Feature, found \"Polygon\""
        );
        assert_eq!(
            error("42"),
            "expected a GeoJSON object or an array of rings [[[x, y], ...], ...], found 42"
        );
        assert_eq!(
            error(
                r#"{"type": "GeometryCollection", "geometries": [{"type": "Feature", "geometry": null}]}"#
            ),
            "geometry 0: expected a Polygon or MultiPolygon geometry, found \"Feature\""
        );
    }

    #[test]
    fn rejects_missing_members() {
        assert_eq!(
            error(r#"{"type": "Polygon"}"#),
            "missing \"coordinates\" member in a Polygon"
        );
        assert_eq!(
            error(r#"{"type": "Feature", "properties": {}}"#),
            "missing \"geometry\" member in a Feature"
        );
        assert_eq!(
            error(r#"{"type": "FeatureCollection"}"#),
            "missing \"features\" member in a FeatureCollection"
        );
        assert_eq!(
            error(r#"{"type": "GeometryCollection", "geometries": {}}"#),
            "\"geometries\" of a GeometryCollection must be an array, found an object"
        );
        assert_eq!(
            error(r#"{"type": "Feature", "geometry": [1]}"#),
            "\"geometry\" must be an object or null, found an array"
        );
    }

    #[test]
    fn rejects_bad_coordinates_naming_the_path() {
        let bad = |rings: &str| error(&format!(r#"{{"type": "Polygon", "coordinates": {rings}}}"#));
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], "abc"]]"#),
            "ring 0, position 2: expected [x, y], found \"abc\""
        );
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [0, "NaN"]]]"#),
            "ring 0, position 2: expected a number for y, found \"NaN\""
        );
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [null, 1]]]"#),
            "ring 0, position 2: expected a number for x, found null"
        );
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [1, 1, "z"]]]"#),
            "ring 0, position 2: expected a number for z, found \"z\""
        );
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [1]]]"#),
            "ring 0, position 2: expected [x, y], found [1]"
        );
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [1, 2, 3, 4, 5]]]"#),
            "ring 0, position 2: a position has at most 4 numbers [x, y, z, m], found 5"
        );
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [0, 1]], []]"#),
            "ring 1: empty ring: expected positions [x, y]"
        );
        assert_eq!(bad(r#"[[0, 0], [1, 0], [0, 1]]"#), "ring 0, position 0: expected [x, y], found 0 (the coordinates are nested one level too shallow)");
        assert_eq!(
            bad(r#"[[[[0, 0], [1, 0], [0, 1]]]]"#),
            "ring 0, position 0: expected [x, y], found an array of arrays (the coordinates are nested one level too deep)"
        );
        assert_eq!(
            bad("7"),
            "expected an array of rings [[[x, y], ...], ...], found 7"
        );
        assert_eq!(bad("[7]"), "ring 0: expected a ring [[x, y], ...], found 7");
        assert_eq!(
            bad(r#"[[[0, 0], [1, 0], [0, 1e99999]]]"#),
            "ring 0, position 2: `1e+99999` has an exponent outside -1000..1000"
        );
        let multi = r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]], [[[0, 0], [1, 0], [true, 1]]]]}"#;
        assert_eq!(
            error(multi),
            "polygon 1, ring 0, position 2: expected a number for x, found true"
        );
        let features = r#"{"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 0], [0, 1], [0, 1], [0, 1], "abc"]]}}]}"#;
        assert_eq!(
            error(features),
            "feature 0, ring 1, position 5: expected [x, y], found \"abc\""
        );
    }

    #[test]
    fn rejects_malformed_json_with_line_and_column() {
        assert_eq!(
            error("{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0], [1, 0]"),
            "line 2, column 33: invalid JSON: the input ends in the middle of a list"
        );
        assert_eq!(
            error("{\"type\": \"Polygon\",\n \"coordinates\": [[[0, 0] [1, 0]]]}"),
            "line 2, column 26: invalid JSON: expected `,` or `]`"
        );
        assert_eq!(
            error("[[[0, 0], [1, 0], [0, NaN]]]"),
            "line 1, column 23: invalid JSON: expected value (NaN and Infinity are not JSON numbers; coordinates must be finite)"
        );
        assert_eq!(
            error("[[[0, 0], [1, 0], [0, 1],]]"),
            "line 1, column 26: invalid JSON: trailing comma"
        );
        assert_eq!(
            error("{\"é\": 1, x}"),
            "line 1, column 10: invalid JSON: key must be a string"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1))"),
            "line 1, column 1: invalid JSON: expected value"
        );
    }

    #[test]
    fn reads_coordinates_that_come_before_the_type() {
        let rings = "[[[0, 0], [4, 0.5], [4, 4], [0, 0]], [[1, 1], [2, 1], [1, 2]]]";
        let first =
            format!(r#"{{"coordinates": {rings}, "bbox": [0, 0, 4, 4], "type": "Polygon"}}"#);
        let expected = vec![
            ring(&[("0", "0"), ("4", "0.5"), ("4", "4")]),
            ring(&[("1", "1"), ("2", "1"), ("1", "2")]),
        ];
        assert_eq!(read(&first).unwrap()[0].rings, expected);
        let multi = format!(r#"{{"coordinates": [{rings}, [], {rings}], "type": "MultiPolygon"}}"#);
        let polygons = read(&multi).unwrap();
        assert_eq!(polygons.len(), 2);
        assert_eq!(polygons[1].rings, expected);
        // The messages are those of the usual order.
        let bad = r#"[[[0, 0], [1, 0], [0, 1]], [[0, 0], [1, 0], [0, "y"]]]"#;
        assert_eq!(
            error(&format!(r#"{{"coordinates": {bad}, "type": "Polygon"}}"#)),
            "ring 1, position 2: expected a number for y, found \"y\""
        );
        assert_eq!(
            error(&format!(
                r#"{{"coordinates": [{bad}], "type": "MultiPolygon"}}"#
            )),
            "polygon 0, ring 1, position 2: expected a number for y, found \"y\""
        );
        assert_eq!(
            error(&format!(r#"{{"coordinates": {rings}, "type": "Point"}}"#)),
            "expected a Polygon or MultiPolygon geometry, found \"Point\""
        );
        // Kept as text, they are still read within `serde_json`'s recursion limit, which is
        // reported where it is met, with its line and column, as when "type" comes first (it
        // used to be met only when the text was read again, without a location).
        let nest = |depth: usize| format!("{}0{}", "[".repeat(depth), "]".repeat(depth));
        let deep = format!(r#"{{"coordinates": {}, "type": "Polygon"}}"#, nest(202));
        assert_eq!(
            error(&deep),
            "line 1, column 143: invalid JSON: recursion limit exceeded"
        );
        let deep = format!(
            "{{\n  \"bbox\": [],\n  \"coordinates\":\n  {}, \"type\": \"Polygon\"}}",
            nest(200)
        );
        assert_eq!(
            error(&deep),
            "line 4, column 129: invalid JSON: recursion limit exceeded"
        );
        let first = format!(r#"{{"type": "Polygon", "coordinates": {}}}"#, nest(200));
        assert_eq!(
            error(&first),
            "line 1, column 162: invalid JSON: recursion limit exceeded"
        );
        // Nested just within the limit: an error of the coordinates, not of the JSON.
        let within = format!(r#"{{"coordinates": {}, "type": "Polygon"}}"#, nest(126));
        assert_eq!(
            error(&within),
            "ring 0, position 0: expected [x, y], found an array of arrays (the coordinates are nested one level too deep)"
        );
        // A syntax error in them is one, located and worded as when "type" comes first.
        let cut = r#"{"coordinates": [[[0, 0], [1, 0], [5,]]], "type": "Polygon"}"#;
        let cut_after = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [5,]]]}"#;
        assert_eq!(
            error(cut),
            "line 1, column 38: invalid JSON: trailing comma"
        );
        assert_eq!(
            error(cut_after),
            "line 1, column 57: invalid JSON: trailing comma"
        );
        // Strings, objects and numbers in them keep what the messages quote.
        let odd = r#"{"coordinates": [[[0, 0], [1, 0], [{"a": "\u00e9\"", "b": 1.50}]]], "type": "Polygon"}"#;
        assert_eq!(
            error(odd),
            r#"ring 0, position 2: expected [x, y], found [{"a":"é\"","b":1.50}]"#
        );
        let odd = r#"{"coordinates": [[[0, 0], [1, 0], [1E5, "\ty"]]], "type": "Polygon"}"#;
        assert_eq!(
            error(odd),
            "ring 0, position 2: expected a number for y, found \"\\ty\""
        );
    }

    /// The messages of the failed parts, and the number of polygons, in order (`None` for a
    /// polygon).
    fn parts(text: &str) -> Vec<Option<String>> {
        read_parts(text)
            .unwrap()
            .into_iter()
            .map(|part| part.err().map(|e| e.to_string()))
            .collect()
    }

    #[test]
    fn a_collection_member_that_is_not_a_polygon_fails_alone() {
        let point = r#"{"type": "Point", "coordinates": [1, 2]}"#;
        let triangle = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}"#;
        let two = r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]], [[[5, 5], [6, 5], [5, 6]]]]}"#;
        let collection =
            format!(r#"{{"type": "GeometryCollection", "geometries": [{point}, {triangle}]}}"#);
        let message = "geometry 0: expected a Polygon or MultiPolygon geometry, found \"Point\"";
        assert_eq!(parts(&collection), [Some(message.to_string()), None]);
        let polygons = read_parts(&collection).unwrap();
        assert_eq!(polygons[1].as_ref().unwrap(), &read(triangle).unwrap()[0]);
        // The whole reader fails on it, as before.
        assert_eq!(error(&collection), message);
        // Nested, among a MultiPolygon's parts, in a Feature of a collection: named by its path,
        // in its place among the parts.
        let nested = format!(
            r#"{{"type": "FeatureCollection", "features": [{{"type": "Feature", "geometry": null}}, {{"type": "Feature", "geometry": {{"type": "GeometryCollection", "geometries": [{two}, {{"type": "GeometryCollection", "geometries": [{{"type": "LineString", "coordinates": []}}, {triangle}]}}, {{"type": "Feature"}}]}}}}]}}"#
        );
        assert_eq!(
            parts(&nested),
            [
                None,
                None,
                Some("feature 1, geometry 1, geometry 0: expected a Polygon or MultiPolygon geometry, found \"LineString\"".into()),
                None,
                Some("feature 1, geometry 2: expected a Polygon or MultiPolygon geometry, found \"Feature\"".into()),
            ]
        );
        // Several values: located at the value, as the value's own failures are.
        let several = format!("{triangle}\n  {collection}\n");
        assert_eq!(
            parts(&several),
            [None, Some(format!("line 2, column 3: {message}")), None]
        );
        // Only members of collections: the value itself, or a Feature's geometry, still fails.
        assert!(read_parts(point).is_err());
        let feature = format!(r#"{{"type": "Feature", "geometry": {point}}}"#);
        assert!(read_parts(&feature).is_err());
        // Only members of another type: a member that is no geometry object, or a polygon
        // member with bad coordinates, fails the whole collection.
        for member in [
            "7",
            r#"{"coordinates": []}"#,
            r#"{"type": "Polygon", "coordinates": [[]]}"#,
        ] {
            let text = format!(
                r#"{{"type": "GeometryCollection", "geometries": [{triangle}, {member}]}}"#
            );
            assert!(
                read_parts(&text)
                    .unwrap_err()
                    .to_string()
                    .starts_with("geometry 1"),
                "{text}"
            );
        }
        // A collection of points only: no polygon, one error each.
        let points =
            format!(r#"{{"type": "GeometryCollection", "geometries": [{point}, {point}]}}"#);
        assert_eq!(parts(&points).len(), 2);
        assert!(parts(&points).iter().all(Option::is_some));
    }

    #[test]
    fn rejects_a_member_named_twice() {
        let twice = |member: &str| {
            error(&format!(
                r#"{{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]], {member}}}"#
            ))
        };
        // A second "type" could change how "coordinates" before it should have been read.
        assert_eq!(
            twice(r#""type": "MultiPolygon""#),
            "duplicate \"type\" member: each may appear once in an object"
        );
        assert_eq!(
            twice(r#""coordinates": [[[0, 0], [2, 0], [0, 2]]]"#),
            "duplicate \"coordinates\" member: each may appear once in an object"
        );
        let features = r#"{"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": null, "geometry": null}]}"#;
        assert_eq!(
            error(features),
            "feature 0: duplicate \"geometry\" member: each may appear once in an object"
        );
        // Other members may repeat.
        let other =
            r#"{"type": "Polygon", "id": 1, "id": 2, "coordinates": [[[0, 0], [1, 0], [0, 1]]]}"#;
        assert_eq!(read(other).unwrap().len(), 1);
    }

    /// A ring of 200,000 positions on one line: integers (negative too), decimals and
    /// exponents, the closing position repeated, then a hole.
    #[test]
    fn reads_a_large_single_line_polygon_exactly() {
        const N: i64 = 200_000;
        let x = |k: i64| k - N / 2;
        let y = |k: i64| match k % 3 {
            0 => format!("{}.{:03}", k / 7, k % 1000),
            1 => format!("-{}e-2", k),
            _ => format!("{}", k * k),
        };
        let mut text = String::from(r#"{"type":"Polygon","coordinates":[["#);
        for k in 0..N {
            text.push_str(&format!("[{},{}],", x(k), y(k)));
        }
        text.push_str(&format!("[{},{}]],[[1,1],[2,1],[1,2]]]}}", x(0), y(0)));
        assert!(!text.contains('\n'));
        let polygons = read(&text).unwrap();
        assert_eq!(polygons.len(), 1);
        let rings = &polygons[0].rings;
        assert_eq!(rings.len(), 2);
        assert_eq!(rings[0].len(), N as usize, "the closing position dropped");
        assert_eq!(rings[1].len(), 3);
        for k in (0..N).step_by(997).chain([1, 2, N - 1]) {
            assert_eq!(
                rings[0][k as usize],
                [d(&x(k).to_string()), d(&y(k))],
                "{k}"
            );
        }
        assert_eq!(rings[0][3][1], d("0.003"));
        assert_eq!(rings[0][4][1], d("-0.04"));
        assert_eq!(rings[0][5][1], d("25"));
        // The streaming and line readers give the same polygon.
        let mut streamed = Vec::new();
        crate::io::read::geojson_stream::stream(
            std::io::BufReader::with_capacity(4096, text.as_bytes()),
            &mut |event| {
                if !matches!(event, crate::io::read::geojson_stream::Event::Feature(_)) {
                    streamed.push(event);
                }
                Ok(())
            },
        )
        .unwrap();
        assert!(
            matches!(streamed.as_slice(), [crate::io::read::geojson_stream::Event::Polygon(p)] if *p == polygons[0])
        );
        assert_eq!(
            crate::io::read::geojson_stream::read_line(&text, 1).unwrap(),
            polygons
        );
    }

    #[test]
    fn rejects_empty_input_and_inputs_without_polygons() {
        for text in ["", "  \n\r\n", "\u{feff}"] {
            assert_eq!(error(text), "empty input: no polygon found");
        }
        for text in [
            r#"{"type": "FeatureCollection", "features": []}"#,
            r#"{"type": "Feature", "geometry": null}"#,
            r#"{"type": "MultiPolygon", "coordinates": []}"#,
        ] {
            assert_eq!(
                error(text),
                "no polygon found: the input holds no non-empty Polygon or MultiPolygon"
            );
        }
        assert_eq!(
            error("[]"),
            "expected an array of rings [[[x, y], ...], ...], found an empty array"
        );
    }

    #[test]
    fn never_panics_on_hostile_input() {
        let deep = format!("{}{}", "[".repeat(100_000), "]".repeat(100_000));
        assert!(
            error(&deep).contains("recursion limit exceeded"),
            "{}",
            error(&deep)
        );
        let deep = format!(
            "{}{}",
            r#"{"geometry": "#.repeat(100_000),
            "}".repeat(100_000)
        );
        assert!(
            error(&deep).contains("recursion limit exceeded"),
            "{}",
            error(&deep)
        );
        let nested = format!(
            "{}{{\"type\": \"Polygon\", \"coordinates\": [[[0, 0], [1, 0], [0, 1]]]}}{}",
            r#"{"type": "GeometryCollection", "geometries": ["#.repeat(70),
            "]}".repeat(70)
        );
        assert!(read(&nested).is_err());
        let long = format!("[[[0, {}]]]", "1".repeat(10_000_000));
        let message = error(&long);
        assert!(message.starts_with("ring 0, position 0: `111"), "{message}");
        assert!(message.len() < 120, "{message}");
        let binary: String = (0u8..=255).map(char::from).collect();
        assert!(read(&binary).is_err());
    }

    /// A JSON value that hands its numbers to a visitor as `f64`.
    ///
    /// The `geojson` crate reads coordinates with `deserialize_any`, which under `serde_json`'s
    /// `arbitrary_precision` (enabled in this crate) yields a private map for every non-integer
    /// number, so `geojson::GeoJson::from_str` fails on `0.5`. This adapter parses each number's
    /// text with `str::parse::<f64>` (independently of [`Decimal`]) and feeds the crate that.
    struct F64Json<'de>(&'de Value);

    impl<'de> IntoDeserializer<'de, DeError> for F64Json<'de> {
        type Deserializer = Self;
        fn into_deserializer(self) -> Self {
            self
        }
    }

    impl<'de> Deserializer<'de> for F64Json<'de> {
        type Error = DeError;

        fn deserialize_any<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
            match self.0 {
                Value::Null => visitor.visit_unit(),
                Value::Bool(b) => visitor.visit_bool(*b),
                Value::Number(n) => visitor.visit_f64(n.as_str().parse().map_err(DeError::custom)?),
                Value::String(s) => visitor.visit_borrowed_str(s),
                Value::Array(items) => {
                    visitor.visit_seq(SeqDeserializer::new(items.iter().map(F64Json)))
                }
                Value::Object(members) => visitor.visit_map(MapDeserializer::new(
                    members.iter().map(|(k, v)| (k.as_str(), F64Json(v))),
                )),
            }
        }

        fn deserialize_option<V: Visitor<'de>>(self, visitor: V) -> Result<V::Value, DeError> {
            match self.0 {
                Value::Null => visitor.visit_none(),
                _ => visitor.visit_some(self),
            }
        }

        fn deserialize_newtype_struct<V: Visitor<'de>>(
            self,
            _name: &'static str,
            visitor: V,
        ) -> Result<V::Value, DeError> {
            visitor.visit_newtype_struct(self)
        }

        fn deserialize_enum<V: Visitor<'de>>(
            self,
            _name: &'static str,
            _variants: &'static [&'static str],
            visitor: V,
        ) -> Result<V::Value, DeError> {
            match self.0 {
                Value::String(s) => visitor.visit_enum(s.as_str().into_deserializer()),
                _ => self.deserialize_any(visitor),
            }
        }

        serde::forward_to_deserialize_any! {
            bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string bytes byte_buf
            unit unit_struct seq tuple tuple_struct map struct identifier ignored_any
        }
    }

    /// The polygons of a geometry parsed by the `geojson` crate, closing positions dropped.
    fn geojson_crate_polygons(geometry: &geojson::Geometry, out: &mut Vec<Vec<Vec<[f64; 2]>>>) {
        let polygon = |rings: &geojson::PolygonType| -> Vec<Vec<[f64; 2]>> {
            rings
                .iter()
                .map(|r| {
                    let mut ring: Vec<[f64; 2]> = r
                        .iter()
                        .map(|p| [p.as_slice()[0], p.as_slice()[1]])
                        .collect();
                    if ring.len() > 1 && ring.first() == ring.last() {
                        ring.pop();
                    }
                    ring
                })
                .collect()
        };
        match &geometry.value {
            geojson::GeometryValue::Polygon { coordinates } if !coordinates.is_empty() => {
                out.push(polygon(coordinates))
            }
            geojson::GeometryValue::MultiPolygon { coordinates } => {
                out.extend(coordinates.iter().filter(|p| !p.is_empty()).map(polygon))
            }
            geojson::GeometryValue::GeometryCollection { geometries } => geometries
                .iter()
                .for_each(|g| geojson_crate_polygons(g, out)),
            _ => {}
        }
    }

    #[test]
    fn agrees_with_the_geojson_crate() {
        let texts = [
            SQUARE.to_string(),
            r#"{"type": "Polygon", "coordinates": [[[0.1, 0.3], [0.2, 0.6], [-1e-3, 7.25], [123456.789, -0.000001]]]}"#.to_string(),
            r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1], [0, 0]]], [[[2, 2], [3, 2], [2, 3]], [[2.1, 2.1], [2.2, 2.1], [2.1, 2.2]]]]}"#.to_string(),
            r#"{"type": "Feature", "properties": {}, "geometry": {"type": "GeometryCollection", "geometries": [{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}]}}"#.to_string(),
            r#"{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0.5, 0.25], [1, 0], [0, 1e1]]]}}, {"type": "Feature", "properties": {}, "geometry": null}]}"#.to_string(),
        ];
        for text in &texts {
            let ours = as_f64(&read(text).unwrap());
            let mut expected = Vec::new();
            let value: Value = serde_json::from_str(text).unwrap();
            match geojson::GeoJson::deserialize(F64Json(&value)).unwrap() {
                geojson::GeoJson::Geometry(g) => geojson_crate_polygons(&g, &mut expected),
                geojson::GeoJson::Feature(f) => f
                    .geometry
                    .iter()
                    .for_each(|g| geojson_crate_polygons(g, &mut expected)),
                geojson::GeoJson::FeatureCollection(c) => c
                    .features
                    .iter()
                    .flat_map(|f| f.geometry.iter())
                    .for_each(|g| geojson_crate_polygons(g, &mut expected)),
            }
            assert_eq!(ours, expected, "{text}");
        }
    }
}
