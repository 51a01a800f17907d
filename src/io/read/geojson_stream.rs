//! Streaming GeoJSON reader: the features of a FeatureCollection, and the values of a
//! newline-delimited (or concatenated) GeoJSON input, one at a time, with exact numbers
//! (`serde_json` with `arbitrary_precision`, never through `f64`). docs/cli.md ("Streaming")
//! says what is streamed and why the `geojson` crate's reader is not used.
//!
//! Input contract: the same documents as [`super::geojson`], from any [`BufRead`]. Output
//! guarantee: [`Event`]s in input order, pushed to a callback as each feature (or top-level
//! value) is read: each top-level value in turn, and inside a FeatureCollection whose `"type"`
//! comes before `"features"` each feature in turn; anything else is one value. A feature, value
//! or GeometryCollection member that is not a polygon is an [`Event::Failed`] (or a failed
//! part) and reading goes on, unlike [`super::geojson::read`]'s all or nothing; a JSON syntax
//! error stops reading ([`Stop::Parse`]) after the events pushed. Messages are those of
//! [`super::geojson::read`] (`feature 3, ring 1: ...`; `line 5, column 1: ...` for a value of
//! several). [`read_line`] reads one line of GeoJSON Lines alone; [`looks_line_delimited`]
//! recognises such an input by its start.
//!
//! Bounds: one feature or top-level value may take at most a cap of bytes
//! ([`super::limits::MAX_TEXT`], [`stream_within`] to choose; past it reading stops, naming the
//! feature and the byte) and hold at most [`MAX_VERTICES`] positions (past it that feature
//! fails and reading goes on): docs/reliability.md, section 5. Time linear in the input; memory
//! proportional to the largest feature, at most 64 bytes per position kept.

use super::geojson::{
    collection_feature, json_message, top_level, type_of, Failure, Part, JSON_WHITESPACE,
};
use super::geojson_seed::{FeatureSink, Node, NodeSeed, Object, SinkError, Vertices};
use super::limits::{too_large, MAX_TEXT, MAX_VERTICES};
use super::{locate, Location, ParseError, RawPolygon};
use crate::feature::{Collection, Feature, Geometry};
use serde::de::{self, DeserializeSeed};
use serde_json::value::RawValue;
use std::cell::RefCell;
use std::collections::VecDeque;
use std::io::{self, BufRead, Read};
use std::rc::Rc;
use std::sync::Arc;

/// One thing read from the stream.
#[derive(Debug)]
pub enum Event {
    /// A feature starts (a Feature of a collection, or a top-level value): its identity and
    /// what its geometry is. Its events follow: for [`Geometry::Parts`]`(k)`, `k` parts in
    /// order, each a [`Event::Polygon`] or, for a member of a GeometryCollection that is not a
    /// polygon (a Point, ...), an [`Event::Failed`]; for [`Geometry::Failed`], one failure; for
    /// [`Geometry::Null`], none.
    Feature(Arc<Feature>),
    /// The next polygon.
    Polygon(RawPolygon),
    /// A feature or top-level value that is not a polygon (its polygons, if any, are skipped),
    /// or a part of a feature that is not a polygon (a member of a GeometryCollection), or
    /// something wrong with the input outside any feature.
    Failed(ParseError),
}

/// Why reading stopped before the end of the input.
#[derive(Debug, thiserror::Error)]
pub enum Stop {
    /// The input is not JSON from here on (or holds no polygon at all): what is wrong.
    #[error("{0}")]
    Parse(ParseError),
    /// The input could not be read.
    #[error("cannot read the input: {0}")]
    Read(io::Error),
    /// The callback failed (writing the output, say); its error.
    #[error("the output failed: {0}")]
    Output(io::Error),
}

/// Reads a GeoJSON input, pushing each polygon (or failure) to `emit` as it is read: as
/// [`stream_within`] with the default caps, [`MAX_TEXT`] bytes and [`MAX_VERTICES`] positions a
/// feature or top-level value.
///
/// # Errors
/// [`Stop::Parse`] for a JSON syntax error (with line and column), an empty input, an input
/// that holds no polygon and no failure, or a feature or value above the cap; [`Stop::Read`]
/// for an I/O error of `reader`; [`Stop::Output`] when `emit` fails.
///
/// # Examples
/// ```
/// use minitri::io::read::geojson_stream::{stream, Event};
/// let text = r#"{"type": "FeatureCollection", "features": [
///   {"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}},
///   {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}}]}"#;
/// let mut events = Vec::new();
/// stream(text.as_bytes(), &mut |e| Ok(events.push(e)))?;
/// // Each feature is announced (its id, properties, geometry kind), then its polygons or failure.
/// assert!(matches!(&events[0], Event::Feature(f) if f.number == 0));
/// assert!(matches!(&events[1], Event::Failed(e) if e.to_string().starts_with("feature 0: ")));
/// assert!(matches!(&events[2], Event::Feature(f) if f.number == 1));
/// assert!(matches!(&events[3], Event::Polygon(p) if p.rings[0].len() == 3));
/// # Ok::<(), minitri::io::read::geojson_stream::Stop>(())
/// ```
pub fn stream<R: BufRead>(
    reader: R,
    emit: &mut dyn FnMut(Event) -> io::Result<()>,
) -> Result<(), Stop> {
    stream_within(reader, MAX_TEXT, MAX_VERTICES, emit)
}

/// [`stream`] with a cap of `limit` bytes for one feature of a streamed FeatureCollection, or
/// one top-level value and the blank space before it, and of `max_vertices` positions for one
/// feature (all its polygons together) or top-level value other than a FeatureCollection.
///
/// # Errors
/// Those of [`stream`]; past the cap on bytes, [`Stop::Parse`] naming the feature (or the line
/// and column where the value starts) and the byte of the input where reading stopped, after
/// the events of what came before. Past the cap on positions, the feature fails
/// ([`Event::Failed`]) and reading goes on.
///
/// # Examples
/// ```
/// use minitri::io::read::geojson_stream::{stream_within, Event, Stop};
/// use std::io::Read;
/// // A FeatureCollection whose second feature never ends, though valid so far.
/// let head = r#"{"type": "FeatureCollection", "features": [
///   {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}},
///   {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0]"#;
/// let endless = head.as_bytes().chain(std::io::repeat(b' ').take(1 << 40));
/// let mut polygons = 0;
/// let stop = stream_within(std::io::BufReader::new(endless), 1000, 1 << 25, &mut |e| {
///     polygons += usize::from(matches!(e, Event::Polygon(_)));
///     Ok(())
/// });
/// let Err(Stop::Parse(error)) = stop else { panic!("{stop:?}") };
/// assert!(error.to_string().starts_with("feature 1: too large: more than 1000 bytes"));
/// assert_eq!(polygons, 1, "the first feature was read");
/// // At most 3 positions a feature: the 4-position one fails, the others go on.
/// let text = r#"[[[0, 0], [1, 0], [0, 1], [0, 2]]]
/// [[[0, 0], [1, 0], [0, 1]]]"#;
/// let mut events = Vec::new();
/// stream_within(text.as_bytes(), 1000, 3, &mut |e| Ok(events.push(e)))?;
/// assert!(matches!(&events[1], Event::Failed(e) if e.to_string().starts_with(
///     "line 1, column 1: ring 0, position 3: too many vertices: more than 3 in one feature")));
/// assert!(matches!(&events[3], Event::Polygon(_)));
/// # Ok::<(), minitri::io::read::geojson_stream::Stop>(())
/// ```
pub fn stream_within<R: BufRead>(
    mut reader: R,
    limit: u64,
    max_vertices: usize,
    emit: &mut dyn FnMut(Event) -> io::Result<()>,
) -> Result<(), Stop> {
    let bom = "\u{feff}".len();
    let skipped = reader
        .fill_buf()
        .map_err(Stop::Read)?
        .starts_with("\u{feff}".as_bytes());
    if skipped {
        reader.consume(bom);
    }
    let mut position = Position::default();
    position.budget.limit = limit;
    position.budget.total = if skipped { bom as u64 } else { 0 };
    let position = Rc::new(RefCell::new(position));
    let counting = Counting {
        inner: reader,
        position: Rc::clone(&position),
    };
    let mut de = serde_json::Deserializer::from_reader(counting);
    let mut sink = Sink {
        emit,
        output_error: None,
        polygons: 0,
        failures: 0,
        features: 0,
        position: Rc::clone(&position),
        within: None,
        collection: None,
    };
    // The first value's parts wait until we know whether the input holds several values,
    // which decides whether its failures carry a location (as in `geojson::read`).
    let mut held: Option<(Location, Vec<Deferred>)> = None;
    let mut values = 0usize;
    let vertices = Vertices::new(max_vertices);
    loop {
        // The blank space before a value counts with it.
        position.borrow_mut().budget.start();
        match de.end() {
            Ok(()) => break,
            Err(e) if e.is_io() => {
                // The value before stands (alone so far: its failures without location).
                if let Some((_, parts)) = held.take() {
                    sink.parts(parts, None).map_err(Stop::Output)?;
                }
                let here = position.borrow().location();
                return Err(sink.stopped(e, here, "the blank space after a GeoJSON value"));
            }
            Err(_) => {} // trailing characters: another value starts here
        }
        let start = position.borrow().location();
        if let Some((location, parts)) = held.take() {
            sink.parts(parts, Some(location)).map_err(Stop::Output)?;
        }
        vertices.reset();
        sink.collection = None;
        match NodeSeed::top(Some(&mut sink), &vertices).deserialize(&mut de) {
            Ok(node) => {
                let parts = sink.value(node).map_err(Stop::Output)?;
                if values == 0 {
                    held = Some((start, parts));
                } else {
                    sink.parts(parts, Some(start)).map_err(Stop::Output)?;
                }
            }
            Err(e) if e.is_io() => return Err(sink.stopped(e, start, "one GeoJSON value")),
            Err(e) => {
                return Err(match sink.output_error.take() {
                    Some(output) => Stop::Output(output),
                    None => Stop::Parse(syntax_error(&e, &position.borrow())),
                })
            }
        }
        values += 1;
    }
    if let Some((_, parts)) = held {
        sink.parts(parts, None).map_err(Stop::Output)?;
    }
    if values == 0 {
        return Err(Stop::Parse(ParseError::new(
            "empty input: no polygon found",
        )));
    }
    if sink.polygons == 0 && sink.failures == 0 {
        return Err(Stop::Parse(ParseError::new(
            "no polygon found: the input holds no non-empty Polygon or MultiPolygon",
        )));
    }
    Ok(())
}

/// Reads one line of a GeoJSON Lines input (line `number` of it, from 1): its polygons, none
/// for a blank line or a Feature without geometry.
///
/// # Errors
/// [`ParseError`] located at the line (and column) when the line is not JSON or not a polygon,
/// or holds a GeometryCollection with a member that is not a polygon ([`read_line_feature`]
/// keeps the collection's polygons then).
///
/// # Examples
/// ```
/// use minitri::io::read::geojson_stream::read_line;
/// let line = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}"#;
/// assert_eq!(read_line(line, 7)?.len(), 1);
/// let error = read_line(r#"  {"type": "Point", "coordinates": [0, 0]}"#, 7).unwrap_err();
/// assert!(error.to_string().starts_with("line 7, column 3: expected a Polygon"));
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_line(line: &str, number: usize) -> Result<Vec<RawPolygon>, ParseError> {
    read_line_feature(line, number, 0)
        .1
        .and_then(|parts| parts.into_iter().collect())
}

/// The parts of a feature: each a polygon, or the error of a member of a GeometryCollection
/// that is not a polygon.
pub type Parts = Vec<Result<RawPolygon, ParseError>>;

/// [`read_line`] with the line's feature (numbered `feature`): its `id`, `properties` and
/// geometry, `None` for a blank line or a line that is not JSON; and its parts, each a polygon
/// or, for a member of a GeometryCollection that is not a polygon, its error (located at the
/// line, as the line's own errors are).
///
/// # Examples
/// ```
/// use minitri::io::read::geojson_stream::read_line_feature;
/// use minitri::feature::Geometry;
/// let line = r#"{"type": "GeometryCollection", "geometries": [{"type": "Point", "coordinates": [1, 2]},
///   {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}]}"#;
/// let (feature, parts) = read_line_feature(line, 7, 0);
/// assert_eq!(feature.unwrap().geometry, Geometry::Parts(2));
/// let parts = parts?;
/// assert_eq!(
///     parts[0].as_ref().unwrap_err().to_string(),
///     "line 7, column 1: geometry 0: expected a Polygon or MultiPolygon geometry, found \"Point\""
/// );
/// assert!(parts[1].is_ok());
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_line_feature(
    line: &str,
    number: usize,
    feature: usize,
) -> (Option<Feature>, Result<Parts, ParseError>) {
    read_line_feature_within(line, number, feature, MAX_VERTICES)
}

/// [`read_line_feature`] with a cap of `max_vertices` positions for the line (all its polygons
/// together): past it, the polygon being read fails, as a part of the line's feature.
///
/// # Examples
/// ```
/// use minitri::io::read::geojson_stream::read_line_feature_within;
/// let line = r#"{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1], [0, 2]]]}"#;
/// let (_, parts) = read_line_feature_within(line, 7, 0, 3);
/// assert!(parts.unwrap_err().to_string().starts_with(
///     "line 7, column 1: ring 0, position 3: too many vertices: more than 3 in one feature"));
/// ```
pub fn read_line_feature_within(
    line: &str,
    number: usize,
    feature: usize,
    max_vertices: usize,
) -> (Option<Feature>, Result<Parts, ParseError>) {
    let line = line.strip_prefix('\u{feff}').unwrap_or(line);
    let body = line.trim_start_matches(JSON_WHITESPACE);
    if body.trim_end_matches(JSON_WHITESPACE).is_empty() {
        return (None, Ok(Vec::new()));
    }
    let at = |column: usize| Location {
        line: number,
        column: column.max(1),
    };
    let mut de = serde_json::Deserializer::from_str(body);
    let vertices = Vertices::new(max_vertices);
    let read = NodeSeed::top(None, &vertices).deserialize(&mut de);
    let node = read.and_then(|node| de.end().map(|()| node)).map_err(|e| {
        if e.is_eof() {
            // The line ends too soon: the column just after its last character.
            let end = line.trim_end_matches(['\n', '\r']).chars().count() + 1;
            let message = json_message(&e, None).replace("the input ends", "the line ends");
            return ParseError::at(at(end), message);
        }
        // `serde_json` counts bytes; the column is in characters.
        let before = line.len() - body.len();
        let column = locate(line, before + e.column().saturating_sub(1)).column;
        let found = (e.line() == 1 && e.column() > 0)
            .then(|| body.as_bytes().get(e.column() - 1).copied())
            .flatten();
        ParseError::at(at(column), json_message(&e, found))
    });
    let mut node = match node {
        Ok(node) => node,
        Err(e) => return (None, Err(e)),
    };
    let column = line.chars().count() - body.chars().count() + 1;
    // A FeatureCollection is one record of the line: its features would be merged into one,
    // their ids and properties lost. Refused, as a line of its own (the others go on).
    if matches!(&node, Node::Object(object) if object.kind() == Some("FeatureCollection")) {
        let message = "a FeatureCollection on one line of GeoJSON Lines: its features would be \
                       merged into one record, their ids and properties lost; give one Feature \
                       per line";
        return (None, Err(ParseError::at(at(column), message)));
    }
    let (id, properties, null) = identity(&mut node);
    let mut parts = Vec::new();
    let located = |failure: Failure| ParseError::at(at(column), failure.to_string());
    let result = top_level(node, &mut parts).map_err(located);
    let geometry = geometry_of(result.is_ok(), null, parts.len());
    let feature = Feature {
        number: feature,
        line: Some(number),
        id,
        properties,
        geometry,
        collection: None,
    };
    let parts = result.map(|()| {
        parts
            .into_iter()
            .map(|part| part.map_err(located))
            .collect()
    });
    (Some(feature), parts)
}

/// A Feature object's `id` and `properties` (taken out of it), and whether its geometry is
/// `null`; nothing for any other value.
fn identity(node: &mut Node) -> (Option<Box<RawValue>>, Option<Box<RawValue>>, bool) {
    match node {
        Node::Object(object) if object.kind() == Some("Feature") => (
            object.id.take(),
            object.properties.take(),
            matches!(object.geometry, Some(Node::Null)),
        ),
        _ => (None, None, false),
    }
}

/// What a feature's geometry is, from how it was read.
fn geometry_of(read: bool, null: bool, parts: usize) -> Geometry {
    match (read, null) {
        (false, _) => Geometry::Failed,
        (true, true) => Geometry::Null,
        (true, false) => Geometry::Parts(parts),
    }
}

/// Does `start` (the first bytes of an input) look like GeoJSON Lines: a first line that is a
/// whole JSON value by itself, then another line?
pub fn looks_line_delimited(start: &[u8]) -> bool {
    let start = start.strip_prefix("\u{feff}".as_bytes()).unwrap_or(start);
    let blank = |b: &u8| JSON_WHITESPACE.contains(&char::from(*b));
    let Some(first) = start.iter().position(|b| !blank(b)) else {
        return false;
    };
    let Some(end) = start[first..].iter().position(|&b| b == b'\n') else {
        return false;
    };
    let (line, rest) = start[first..].split_at(end);
    !rest.iter().all(blank) && serde_json::from_slice::<de::IgnoredAny>(line).is_ok()
}

/// A `serde_json` syntax error at its line and column, the column in characters (`serde_json`
/// counts bytes; `read` says how many characters they are, when it still knows).
fn syntax_error(error: &serde_json::Error, read: &Position) -> ParseError {
    let found = read.byte_at(error.line(), error.column());
    let message = json_message(error, found);
    if error.line() == 0 {
        return ParseError::new(message);
    }
    let column = read
        .char_column(error.line(), error.column())
        .unwrap_or(error.column());
    // At the end of the input: the column after the last character (as in `geojson::read`).
    let column = column + usize::from(error.is_eof());
    ParseError::at(
        Location {
            line: error.line(),
            column: column.max(1),
        },
        message,
    )
}

/// How many of the last bytes read [`Position`] keeps.
const RECENT: usize = 256;

/// What a [`Counting`] reader has delivered: the position of the last byte (line from 1; column
/// in bytes and in characters, 0 right after a newline), the previous line's length, and the
/// last [`RECENT`] bytes. `serde_json` may read a little past an error before reporting it (it
/// closes the open object); these let the error's byte column be turned into characters.
#[derive(Debug)]
struct Position {
    line: usize,
    bytes: usize,
    chars: usize,
    /// The previous line's length in bytes and in characters, without its newline.
    previous: (usize, usize),
    recent: VecDeque<u8>,
    /// The bytes delivered, against the cap on one feature or value.
    budget: Budget,
}

/// How many bytes one feature or top-level value may take ([`stream_within`]), counted from
/// where it starts.
#[derive(Debug)]
struct Budget {
    /// The cap, in bytes.
    limit: u64,
    /// Bytes of the input read so far (a skipped byte-order mark included).
    total: u64,
    /// `total` where the current feature or value started.
    mark: u64,
    /// The byte of the input (from 1) that went past the cap, once one did.
    over: Option<u64>,
}

impl Budget {
    /// A feature or value starts after the bytes read so far.
    fn start(&mut self) {
        self.mark = self.total;
    }

    /// Counts `count` more bytes; an error (and [`Budget::over`] set) past the cap.
    fn take(&mut self, count: usize) -> io::Result<()> {
        let total = self.total + count as u64;
        if total - self.mark > self.limit {
            let byte = self.mark + self.limit + 1;
            self.over = Some(byte);
            return Err(io::Error::other(format!(
                "more than {} bytes in one feature, at byte {byte}",
                self.limit
            )));
        }
        self.total = total;
        Ok(())
    }
}

impl Default for Position {
    fn default() -> Position {
        Position {
            line: 1,
            bytes: 0,
            chars: 0,
            previous: (0, 0),
            recent: VecDeque::with_capacity(RECENT),
            budget: Budget {
                limit: MAX_TEXT,
                total: 0,
                mark: 0,
                over: None,
            },
        }
    }
}

impl Position {
    /// Where the next byte is: the line and (character) column.
    fn location(&self) -> Location {
        Location {
            line: self.line,
            column: self.chars.max(1),
        }
    }

    fn push(&mut self, byte: u8) {
        if self.recent.len() == RECENT {
            self.recent.pop_front();
        }
        self.recent.push_back(byte);
        if byte == b'\n' {
            self.previous = (self.bytes, self.chars);
            self.line += 1;
            self.bytes = 0;
            self.chars = 0;
        } else {
            self.bytes += 1;
            if byte & 0xc0 != 0x80 {
                self.chars += 1; // not a UTF-8 continuation byte: a new character
            }
        }
    }

    /// How many bytes were read after byte column `column` of line `line`, if still known.
    fn read_after(&self, line: usize, column: usize) -> Option<usize> {
        let after = if line == self.line {
            self.bytes.checked_sub(column)?
        } else if line + 1 == self.line {
            self.previous.0.checked_sub(column)? + 1 + self.bytes
        } else {
            return None;
        };
        (after < self.recent.len()).then_some(after)
    }

    /// The byte at byte column `column` (from 1) of line `line`, if still known.
    fn byte_at(&self, line: usize, column: usize) -> Option<u8> {
        let after = self.read_after(line, column)?;
        self.recent.iter().rev().nth(after).copied()
    }

    /// The character column of byte column `column` of line `line`, if still known.
    fn char_column(&self, line: usize, column: usize) -> Option<usize> {
        let after = self.read_after(line, column)?;
        let characters = |skip: usize, take: usize| {
            self.recent
                .iter()
                .rev()
                .skip(skip)
                .take(take)
                .filter(|&&b| b & 0xc0 != 0x80)
                .count()
        };
        if line == self.line {
            Some(self.chars - characters(0, after))
        } else {
            Some(self.previous.1 - characters(self.bytes + 1, after - self.bytes - 1))
        }
    }
}

/// A reader that records what it delivers in a [`Position`].
struct Counting<R> {
    inner: R,
    position: Rc<RefCell<Position>>,
}

impl<R: Read> Read for Counting<R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let n = self.inner.read(buf)?;
        let mut position = self.position.borrow_mut();
        position.budget.take(n)?;
        for &byte in buf.get(..n).unwrap_or_default() {
            position.push(byte);
        }
        Ok(n)
    }
}

/// Where events go, with what the deserializer cannot carry: the callback's own error.
struct Sink<'e> {
    emit: &'e mut dyn FnMut(Event) -> io::Result<()>,
    output_error: Option<io::Error>,
    polygons: usize,
    failures: usize,
    features: usize,
    /// What the reader delivered (for the cap on one feature or value).
    position: Rc<RefCell<Position>>,
    /// The element of a streamed `features` array being read, if one is.
    within: Option<usize>,
    /// The members of the FeatureCollection being read that its features carry, if any.
    collection: Option<Arc<Collection>>,
}

/// A part of a top-level value not pushed yet: a polygon, or a failure (a failed part, or the
/// whole value), which is located once it is known whether the input holds several values.
type Deferred = Part;

impl Sink<'_> {
    /// Why reading stopped on `error`, an I/O error of the deserializer: the cap on one
    /// feature (the one being read, by its index) or on `what` (at `start`) when that was
    /// reached, else the reader's error.
    fn stopped(&mut self, error: serde_json::Error, start: Location, what: &str) -> Stop {
        if let Some(output) = self.output_error.take() {
            return Stop::Output(output);
        }
        let position = self.position.borrow();
        let budget = &position.budget;
        let Some(byte) = budget.over else {
            return Stop::Read(error.into());
        };
        Stop::Parse(match self.within {
            Some(index) => ParseError::new(format!(
                "feature {index}: {}",
                too_large(budget.limit, "one GeoJSON feature", byte)
            )),
            None => ParseError::at(start, too_large(budget.limit, what, byte)),
        })
    }

    /// Announces the next feature ([`Event::Feature`]).
    fn announce(
        &mut self,
        (id, properties, null): (Option<Box<RawValue>>, Option<Box<RawValue>>, bool),
        read: bool,
        polygons: usize,
    ) -> io::Result<()> {
        let feature = Feature {
            number: self.features,
            line: None,
            id,
            properties,
            geometry: geometry_of(read, null, polygons),
            collection: self.collection.clone(),
        };
        self.features += 1;
        (self.emit)(Event::Feature(Arc::new(feature)))
    }

    fn polygon(&mut self, polygon: RawPolygon) -> io::Result<()> {
        self.polygons += 1;
        (self.emit)(Event::Polygon(polygon))
    }

    fn fail(&mut self, error: ParseError) -> io::Result<()> {
        self.failures += 1;
        (self.emit)(Event::Failed(error))
    }

    /// Pushes the parts of a top-level value, its failures at `location`.
    fn parts(&mut self, parts: Vec<Deferred>, location: Option<Location>) -> io::Result<()> {
        parts.into_iter().try_for_each(|part| match part {
            Ok(polygon) => self.polygon(polygon),
            Err(failure) => self.fail(ParseError {
                location,
                message: failure.to_string(),
            }),
        })
    }

    /// Element `index` of a FeatureCollection's `features`: its parts, or why not.
    fn feature(&mut self, index: usize, mut node: Node) -> io::Result<()> {
        let identity = identity(&mut node);
        let mut parts: Vec<Part> = Vec::new();
        let read = collection_feature(node, &mut parts);
        self.announce(identity, read.is_ok(), parts.len())?;
        match read {
            Ok(()) => parts.into_iter().try_for_each(|part| match part {
                Ok(polygon) => self.polygon(polygon),
                Err(failure) => self.fail(ParseError::new(
                    failure.within("feature", index).to_string(),
                )),
            }),
            Err(failure) => self.fail(ParseError::new(
                failure.within("feature", index).to_string(),
            )),
        }
    }

    /// A whole top-level value (its features already pushed if it streamed them): it is
    /// announced, and its parts returned, to be pushed by [`Sink::parts`]: its polygons and
    /// failed parts, or the one failure of the value.
    fn value(&mut self, node: Node) -> io::Result<Vec<Deferred>> {
        let collection = |object: &Object| {
            type_of(object).is_ok_and(|kind| kind == "FeatureCollection")
                && matches!(object.features, Some(Node::List(_)))
        };
        match node {
            // Only a member named twice can be wrong with the object itself.
            Node::Object(object) if matches!(object.features, Some(Node::Streamed)) => {
                Ok(type_of(&object).err().map(Err).into_iter().collect())
            }
            // `"features"` came before `"type"`: read whole, but judged feature by feature too.
            Node::Object(mut object) if collection(&object) => {
                self.collection = Collection::of(object.name.take(), object.crs.take());
                if let Some(Node::List(features)) = object.features {
                    for (index, feature) in features.into_iter().enumerate() {
                        self.feature(index, feature)?;
                    }
                }
                Ok(Vec::new())
            }
            mut node => {
                let identity = identity(&mut node);
                let mut parts = Vec::new();
                let read = top_level(node, &mut parts);
                self.announce(identity, read.is_ok(), parts.len())?;
                Ok(match read {
                    Ok(()) => parts,
                    Err(failure) => vec![Err(failure)],
                })
            }
        }
    }
}

impl FeatureSink for Sink<'_> {
    /// Pushes the feature's polygons (or failure); a callback error is kept, and stops reading.
    fn feature(&mut self, index: usize, feature: Node) -> Result<(), SinkError> {
        Sink::feature(self, index, feature).map_err(|e| {
            self.output_error = Some(e);
            SinkError::Output
        })
    }

    /// Starts counting the next feature's bytes (or the rest of the collection's).
    fn reading(&mut self, index: Option<usize>) {
        self.within = index;
        self.position.borrow_mut().budget.start();
    }

    /// Keeps the collection's members for its features.
    fn collection(&mut self, name: Option<Box<RawValue>>, crs: Option<Box<RawValue>>) {
        self.collection = Collection::of(name, crs);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::read::geojson;

    /// Polygons and failure messages, in order, and the stop if any.
    fn events(text: &str) -> (Vec<Result<RawPolygon, String>>, Option<String>) {
        let mut out = Vec::new();
        let stop = stream(text.as_bytes(), &mut |e| {
            match e {
                Event::Feature(_) => {}
                Event::Polygon(p) => out.push(Ok(p)),
                Event::Failed(e) => out.push(Err(e.to_string())),
            }
            Ok(())
        })
        .err()
        .map(|s| match s {
            Stop::Parse(e) => e.to_string(),
            other => format!("{other:?}"),
        });
        (out, stop)
    }

    const A: &str =
        r#"{"type": "Polygon", "coordinates": [[[0, 0], [0.1, 0.3], [0.2, 0.6], [0, 1]]]}"#;
    const B: &str = r#"{"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]], [[[5, 5], [6, 5], [5, 6]]]]}"#;

    #[test]
    fn gives_the_polygons_of_the_whole_reader_exactly() {
        let collection = format!(
            r#"{{"type": "FeatureCollection", "bbox": [0, 0, 6, 6], "features": [{{"type": "Feature", "geometry": {A}, "properties": {{"id": 7}}}}, {{"type": "Feature", "geometry": null}}, {{"type": "Feature", "geometry": {B}}}], "id": 12.5}}"#
        );
        let lines = format!("{A}\n\n{B}\n");
        let reversed = format!(
            r#"{{"features": [{{"type": "Feature", "geometry": {A}}}, {{"type": "Feature", "geometry": {B}}}], "type": "FeatureCollection"}}"#
        );
        for text in [
            collection.as_str(),
            &lines,
            &reversed,
            A,
            &format!("\u{feff}{B}"),
        ] {
            let (got, stop) = events(text);
            assert_eq!(stop, None, "{text}");
            let got: Vec<RawPolygon> = got.into_iter().map(Result::unwrap).collect();
            assert_eq!(got, geojson::read(text).unwrap(), "{text}");
        }
    }

    #[test]
    fn a_bad_feature_or_line_is_reported_and_reading_goes_on() {
        let text = format!(
            r#"{{"type": "FeatureCollection", "features": [{{"type": "Feature", "geometry": {{"type": "Point", "coordinates": [1, 2]}}}}, {{"type": "Feature", "geometry": {A}}}]}}"#
        );
        let (got, stop) = events(&text);
        assert_eq!(stop, None);
        assert_eq!(
            got[0].as_ref().unwrap_err(),
            "feature 0: expected a Polygon or MultiPolygon geometry, found \"Point\""
        );
        assert!(got[1].is_ok());
        // Several top-level values: the failure carries the line where its value starts, as in
        // the whole reader; a single bad value does not.
        let lines = format!("{A}\n  {{\"type\": \"LineString\", \"coordinates\": []}}\n{B}\n");
        let (got, stop) = events(&lines);
        assert_eq!(stop, None);
        assert_eq!(got.len(), 4);
        assert_eq!(
            got[1].as_ref().unwrap_err(),
            "line 2, column 3: expected a Polygon or MultiPolygon geometry, found \"LineString\""
        );
        let one = r#"{"type": "LineString", "coordinates": []}"#;
        assert_eq!(
            events(one).0[0].as_ref().unwrap_err(),
            &geojson::read(one).unwrap_err().to_string()
        );
        // Integers too (they once stopped the stream with "invalid type: integer").
        for scalar in ["12.50", "7", "-3", "\"x\"", "true", "null", "[]"] {
            assert_eq!(
                events(scalar).0[0].as_ref().unwrap_err(),
                &geojson::read(scalar).unwrap_err().to_string(),
                "{scalar}"
            );
        }
    }

    #[test]
    fn a_collection_member_that_is_not_a_polygon_is_a_failed_part() {
        let point = r#"{"type": "Point", "coordinates": [1, 2]}"#;
        let collection =
            format!(r#"{{"type": "GeometryCollection", "geometries": [{point}, {A}, {B}]}}"#);
        let message = "geometry 0: expected a Polygon or MultiPolygon geometry, found \"Point\"";
        // Announced as 4 parts (the Point, A, B's two), then the parts in order.
        let announced = |text: &str| {
            let mut kinds = Vec::new();
            stream(text.as_bytes(), &mut |e| {
                kinds.push(match e {
                    Event::Feature(f) => format!("feature {} {:?}", f.number, f.geometry),
                    Event::Polygon(_) => "polygon".into(),
                    Event::Failed(e) => e.to_string(),
                });
                Ok(())
            })
            .unwrap();
            kinds
        };
        assert_eq!(
            announced(&collection),
            [
                "feature 0 Parts(4)",
                message,
                "polygon",
                "polygon",
                "polygon"
            ]
        );
        // In a FeatureCollection (streamed or not) and in concatenated values, named and located
        // as the whole reader names them.
        let feature = format!(r#"{{"type": "Feature", "geometry": {collection}}}"#);
        let features =
            format!(r#"{{"type": "FeatureCollection", "features": [{feature}, {feature}]}}"#);
        let reversed =
            format!(r#"{{"features": [{feature}, {feature}], "type": "FeatureCollection"}}"#);
        let several = format!("{A} {collection}\n{collection}");
        for text in [collection.as_str(), &features, &reversed, &several] {
            let (got, stop) = events(text);
            assert_eq!(stop, None, "{text}");
            let expected: Vec<_> = geojson::read_parts(text)
                .unwrap()
                .into_iter()
                .map(|part| part.map_err(|e| e.to_string()))
                .collect();
            assert_eq!(got, expected, "{text}");
        }
        assert_eq!(
            announced(&features)[6],
            format!("feature 1, {message}"),
            "feature 1's Point"
        );
        assert_eq!(
            events(&several).0[1].as_ref().unwrap_err(),
            &format!("line 1, column 80: {message}")
        );
        // A line: its parts, the failed one located at the line.
        let (read, parts) = read_line_feature(&collection, 3, 0);
        assert_eq!(read.unwrap().geometry, Geometry::Parts(4));
        let parts = parts.unwrap();
        assert_eq!(
            parts[0].as_ref().unwrap_err().to_string(),
            format!("line 3, column 1: {message}")
        );
        assert!(parts[1..].iter().all(Result::is_ok));
        // `read_line`, all or nothing, fails on it.
        assert_eq!(
            read_line(&collection, 3).unwrap_err().to_string(),
            format!("line 3, column 1: {message}")
        );
    }

    #[test]
    fn deep_coordinates_before_the_type_are_located() {
        let text = format!(
            "{{\"coordinates\": {}0{}, \"type\": \"Polygon\"}}",
            "[".repeat(200),
            "]".repeat(200)
        );
        let expected = "line 1, column 143: invalid JSON: recursion limit exceeded";
        assert_eq!(events(&text).1.as_deref(), Some(expected));
        assert_eq!(geojson::read(&text).unwrap_err().to_string(), expected);
        assert_eq!(read_line(&text, 1).unwrap_err().to_string(), expected);
        let feature = format!(
            "{{\"type\": \"FeatureCollection\", \"features\": [\n{{\"type\": \"Feature\", \"geometry\": {text}}}]}}"
        );
        let expected = "line 2, column 172: invalid JSON: recursion limit exceeded";
        assert_eq!(events(&feature).1.as_deref(), Some(expected));
        assert_eq!(geojson::read(&feature).unwrap_err().to_string(), expected);
    }

    #[test]
    fn a_collection_is_judged_as_the_whole_reader_judges_it() {
        // "features" that are not an array: the whole reader's message, not a syntax error.
        for features in ["7", "{}", "null"] {
            let text = format!(r#"{{"type": "FeatureCollection", "features": {features}}}"#);
            let (got, stop) = events(&text);
            assert_eq!(stop, None, "{text}");
            assert_eq!(
                got[0].as_ref().unwrap_err(),
                &geojson::read(&text).unwrap_err().to_string()
            );
        }
        // A member named twice after the features were streamed: they stand, the object fails.
        let text = format!(
            r#"{{"type": "FeatureCollection", "features": [{{"type": "Feature", "geometry": {A}}}], "features": []}}"#
        );
        let (got, stop) = events(&text);
        assert_eq!(stop, None);
        assert_eq!(got.len(), 2);
        assert!(got[0].is_ok());
        assert_eq!(
            got[1].as_ref().unwrap_err(),
            "duplicate \"features\" member: each may appear once in an object"
        );
        assert_eq!(
            geojson::read(&text).unwrap_err().to_string(),
            "duplicate \"features\" member: each may appear once in an object"
        );
    }

    #[test]
    fn a_syntax_error_stops_after_what_was_read() {
        let text = format!("{A}\n{B}\n{{\"type\": \"Polygon\",, }}\n{A}\n");
        let (got, stop) = events(&text);
        assert_eq!(got.len(), 3, "A and the two parts of B");
        assert_eq!(
            stop.as_deref(),
            Some(geojson::read(&text).unwrap_err().to_string().as_str())
        );
        let (got, stop) = events(&A[..A.len() - 3]);
        assert!(got.is_empty());
        assert!(
            stop.is_some_and(|s| s.contains("the input ends in the middle of")),
            "truncated"
        );
        // Columns count characters, not bytes: `x` is the 15th character (the 19th byte).
        let accents = r#"{"a": "éééé", x}"#;
        let expected = "line 1, column 15: invalid JSON: key must be a string";
        assert_eq!(events(accents).1.as_deref(), Some(expected));
        assert_eq!(read_line(accents, 1).unwrap_err().to_string(), expected);
        assert_eq!(geojson::read(accents).unwrap_err().to_string(), expected);
        // `serde_json` reads past the error (closing the object) before reporting it; the column
        // is still the error's, in characters: the second comma, character 71 (byte 72).
        let ahead =
            r#"{"type": "FeatureCollection", "features": [{"type": "Feature", "é": 1,, }]}"#;
        let expected = "line 1, column 71: invalid JSON: key must be a string";
        assert_eq!(events(ahead).1.as_deref(), Some(expected));
        assert_eq!(geojson::read(ahead).unwrap_err().to_string(), expected);
        let across = ahead.replace(",, }", ",,\n }");
        let expected = "line 1, column 71: invalid JSON: key must be a string";
        assert_eq!(events(&across).1.as_deref(), Some(expected));
        // Cut short: located just after the last character, streamed and line by line alike.
        assert_eq!(
            events(r#"{"type": "Polygon""#).1.as_deref(),
            Some("line 1, column 19: invalid JSON: the input ends in the middle of an object")
        );
        assert_eq!(
            read_line("{\"type\": \"Polygon\"\n", 7)
                .unwrap_err()
                .to_string(),
            "line 7, column 19: invalid JSON: the line ends in the middle of an object"
        );
        assert_eq!(
            events(" \n ").1.as_deref(),
            Some("empty input: no polygon found")
        );
        assert!(events(r#"{"type": "FeatureCollection", "features": []}"#)
            .1
            .is_some_and(|s| s.starts_with("no polygon found")));
    }

    #[test]
    fn lines_are_read_alone_and_recognised_by_their_start() {
        assert_eq!(read_line(A, 1).unwrap(), geojson::read(A).unwrap());
        assert_eq!(read_line(" \r\n", 4).unwrap(), []);
        let null = r#"{"type": "Feature", "geometry": null}"#;
        assert_eq!(read_line(null, 4).unwrap(), []);
        assert_eq!(
            read_line(r#" {"type": "Polygon",, }"#, 9)
                .unwrap_err()
                .to_string(),
            "line 9, column 21: invalid JSON: key must be a string"
        );
        assert!(looks_line_delimited(format!("{A}\n{B}\n").as_bytes()));
        assert!(looks_line_delimited(format!("\n{A}\r\n{A}").as_bytes()));
        assert!(
            !looks_line_delimited(format!("{A}\n\n").as_bytes()),
            "one value"
        );
        assert!(
            !looks_line_delimited(b"{\n  \"type\": \"Polygon\"\n}\n"),
            "pretty"
        );
        assert!(!looks_line_delimited(A.as_bytes()), "no end of line seen");
    }

    /// Found by the `read_geojson` fuzz target: a line starting with form feeds (not JSON
    /// whitespace) was read by `read_line`, which trimmed it as Unicode whitespace, while the
    /// streaming and whole readers rejected the same text as invalid JSON.
    #[test]
    fn only_json_whitespace_is_skipped_around_a_line() {
        let line = format!("\u{c}\u{c}{A}");
        let expected = "line 3, column 1: invalid JSON: expected value";
        assert_eq!(read_line(&line, 3).unwrap_err().to_string(), expected);
        assert!(events(&line).1.is_some_and(|s| s.contains("invalid JSON")));
        assert!(geojson::read(&line).is_err());
        assert!(
            read_line("\u{c}", 3).is_err(),
            "a form feed is not a blank line"
        );
        assert!(read_line(" \t\r", 3).unwrap().is_empty());
        assert!(!looks_line_delimited(format!("\u{c}{A}\n{A}\n").as_bytes()));
    }

    #[test]
    fn each_feature_is_announced_with_its_id_and_properties_as_written() {
        let text = format!(
            r#"{{"type": "FeatureCollection", "features": [{{"type": "Feature", "id": "a", "properties": {{"h": 12.50}}, "geometry": {B}}}, {{"type": "Feature", "id": 1e400, "geometry": null}}, {{"type": "Feature", "geometry": {{"type": "Point", "coordinates": [0, 0]}}}}]}}"#
        );
        let mut announced = Vec::new();
        stream(text.as_bytes(), &mut |e| {
            if let Event::Feature(f) = e {
                let raw = |v: &Option<Box<RawValue>>| v.as_ref().map(|v| v.get().to_string());
                announced.push((f.number, raw(&f.id), raw(&f.properties), f.geometry));
            }
            Ok(())
        })
        .unwrap();
        let some = |s: &str| Some(s.to_string());
        assert_eq!(
            announced,
            [
                (0, some("\"a\""), some("{\"h\": 12.50}"), Geometry::Parts(2)),
                (1, some("1e400"), None, Geometry::Null),
                (2, None, None, Geometry::Failed),
            ]
        );
        let (feature, read) = read_line_feature(A, 4, 9);
        let feature = feature.unwrap();
        assert_eq!((feature.number, feature.line), (9, Some(4)));
        assert_eq!(feature.geometry, Geometry::Parts(1));
        assert_eq!(read.unwrap().len(), 1);
        assert!(
            read_line_feature("{", 4, 9).0.is_none(),
            "not JSON: no feature"
        );
    }

    #[test]
    fn a_collections_name_and_crs_before_its_features_go_with_each_feature() {
        let crs = r#"{"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::3857"}}"#;
        let feature =
            format!(r#"{{"type": "Feature", "name": "not the layer's", "geometry": {A}}}"#);
        let collected = |text: &str| {
            let mut found = Vec::new();
            stream(text.as_bytes(), &mut |e| {
                if let Event::Feature(f) = e {
                    found.push(f.collection.as_ref().map(|c| {
                        let raw =
                            |v: &Option<Box<RawValue>>| v.as_ref().map(|v| v.get().to_string());
                        (raw(&c.name), raw(&c.crs))
                    }));
                }
                Ok(())
            })
            .unwrap();
            found
        };
        let members = Some((Some("\"parcels\"".to_string()), Some(crs.to_string())));
        // Streamed, then read whole ("features" first), then a second value without them.
        let text = format!(
            r#"{{"type": "FeatureCollection", "name": "parcels", "crs": {crs}, "features": [{feature}, {feature}]}}
{{"features": [{feature}], "crs": {crs}, "type": "FeatureCollection", "name": "parcels"}}
{{"type": "FeatureCollection", "features": [{feature}]}}"#
        );
        assert_eq!(
            collected(&text),
            [members.clone(), members.clone(), members, None]
        );
        // After the features of a streamed collection: too late for them.
        let text =
            format!(r#"{{"type": "FeatureCollection", "features": [{feature}], "crs": {crs}}}"#);
        assert_eq!(collected(&text), [None]);
    }

    /// Polygons read and the stop, with a cap of `limit` bytes.
    fn capped(text: &str, limit: u64) -> (usize, Option<String>) {
        let mut polygons = 0;
        let stop = stream_within(text.as_bytes(), limit, MAX_VERTICES, &mut |e| {
            polygons += usize::from(matches!(e, Event::Polygon(_)));
            Ok(())
        });
        let stop = stop.err().map(|s| match s {
            Stop::Parse(e) => e.to_string(),
            other => format!("{other:?}"),
        });
        (polygons, stop)
    }

    #[test]
    fn a_feature_or_value_above_the_cap_stops_reading() {
        let feature = format!(r#"{{"type": "Feature", "geometry": {A}}}"#);
        let collection =
            format!(r#"{{"type": "FeatureCollection", "features": [{feature}, {feature}]}}"#);
        // Each feature is counted alone: a cap just above one feature's size reads them all.
        let each = feature.len() as u64 + 2;
        assert_eq!(capped(&collection, each), (2, None));
        let (polygons, stop) = capped(&collection, each - 3);
        assert_eq!(polygons, 0);
        let stop = stop.unwrap();
        assert!(
            stop.starts_with("feature 0: too large: more than"),
            "{stop}"
        );
        // The byte where reading stopped, counted in the input (a byte-order mark included).
        let start = collection.find('[').unwrap() as u64 + 1;
        let expected = format!("reading stopped at byte {} of the input", start + each - 2);
        assert!(stop.ends_with(&expected), "{stop}");
        let marked = format!("\u{feff}{collection}");
        let expected = format!("reading stopped at byte {} of the input", start + each + 1);
        assert!(capped(&marked, each - 3).1.unwrap().ends_with(&expected));
        // Several values: each counted alone, the one too large named by where it starts.
        let lines = format!("{A}\n{A}\n  {B}\n");
        assert_eq!(capped(&lines, A.len() as u64 + 1), (2, Some(format!(
            "line 3, column 3: too large: more than {} bytes in one GeoJSON value (the most read before it is parsed); reading stopped at byte {} of the input",
            A.len() + 1,
            // After the second value's last byte, the blank space before the third counted.
            (2 * A.len() + 1) + (A.len() + 1) + 1
        ))));
        assert_eq!(capped(&lines, B.len() as u64 + 3), (4, None));
    }

    /// Polygons and failure messages, in order, with a cap of `max` positions, and the stop.
    fn counted(text: &str, max: usize) -> (Vec<Result<usize, String>>, Option<String>) {
        let mut out = Vec::new();
        let stop = stream_within(text.as_bytes(), MAX_TEXT, max, &mut |e| {
            match e {
                Event::Feature(_) => {}
                Event::Polygon(p) => out.push(Ok(p.rings.iter().map(Vec::len).sum())),
                Event::Failed(e) => out.push(Err(e.to_string())),
            }
            Ok(())
        });
        (out, stop.err().map(|s| format!("{s:?}")))
    }

    #[test]
    fn positions_are_counted_per_feature_all_its_polygons_together() {
        let too_many = |max: &str| {
            format!("too many vertices: more than {max} in one feature (the most held while reading; --max-vertices raises it); the rest of it was read but not kept")
        };
        // B: two triangles; A: 4 positions.
        let feature = |g: &str| format!(r#"{{"type": "Feature", "geometry": {g}}}"#);
        let collection = format!(
            r#"{{"type": "FeatureCollection", "features": [{}, {}, {}]}}"#,
            feature(B),
            feature(A),
            feature(B)
        );
        assert_eq!(
            counted(&collection, 6),
            (vec![Ok(3), Ok(3), Ok(4), Ok(3), Ok(3)], None)
        );
        let (got, stop) = counted(&collection, 5);
        assert_eq!(stop, None);
        let expected = format!(
            "feature 0, polygon 1, ring 0, position 2: {}",
            too_many("5")
        );
        assert_eq!(
            got,
            vec![
                Err(expected.clone()),
                Ok(4),
                Err(expected.replace("feature 0", "feature 2"))
            ]
        );
        // Features before "type": read whole, still counted feature by feature.
        let reversed = format!(
            r#"{{"features": [{}, {}], "type": "FeatureCollection"}}"#,
            feature(A),
            feature(A)
        );
        assert_eq!(counted(&reversed, 4).0, vec![Ok(4), Ok(4)]);
        // A GeometryCollection's members together: the second member fails, and with it the
        // collection (as for any member whose coordinates are wrong).
        let members = format!(r#"{{"type": "GeometryCollection", "geometries": [{A}, {A}]}}"#);
        assert_eq!(counted(&members, 8).0, vec![Ok(4), Ok(4)]);
        let expected = format!("geometry 1, ring 0, position 3: {}", too_many("7"));
        assert_eq!(counted(&members, 7).0, vec![Err(expected)]);
        // Coordinates before "type", and top-level values, each counted alone.
        let late = r#"{"coordinates": [[[0, 0], [1, 0], [0, 1], [0, 2]]], "type": "Polygon"}"#;
        let (got, _) = counted(&format!("{late}\n{late}\n{B}"), 4);
        assert_eq!(
            got,
            vec![
                Ok(4),
                Ok(4),
                Err(format!(
                    "line 3, column 1: polygon 1, ring 0, position 1: {}",
                    too_many("4")
                ))
            ]
        );
        // A line of GeoJSON Lines.
        let (_, parts) = read_line_feature_within(B, 2, 0, 5);
        assert!(parts
            .unwrap_err()
            .to_string()
            .starts_with("line 2, column 1: polygon 1, ring 0, position 2: too many vertices"));
    }

    #[test]
    fn an_output_error_stops_reading_and_is_returned() {
        let mut calls = 0;
        let stop = stream(format!("{A}\n{A}\n").as_bytes(), &mut |_| {
            calls += 1;
            Err(io::Error::other("disk full"))
        });
        assert!(matches!(stop, Err(Stop::Output(e)) if e.to_string() == "disk full"));
        assert_eq!(calls, 1);
    }
}
