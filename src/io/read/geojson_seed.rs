//! Reads one JSON value of a GeoJSON input with `serde` seeds, keeping only what GeoJSON needs:
//! positions go straight into exact decimals, never through `serde_json::Value`.
//!
//! Input contract: any JSON value, from a `serde_json` deserializer with `arbitrary_precision`
//! (a number that is not a 64-bit integer arrives as its literal text). Output guarantee: a
//! [`Node`]: a JSON object as an [`Object`] (its `type`, `coordinates`, `geometry`, `geometries`
//! and `features` members as read; other members are read and dropped), a Polygon's or
//! MultiPolygon's `coordinates` as polygons of exact [`Decimal`] rings (without the closing
//! position), anything else only as far as a message names it. What is wrong inside
//! `coordinates` is not a `serde` error: the first failure, with its path (`ring 1, position
//! 5`), is kept in place of the polygons and the rest of the array is read, so that a later JSON
//! syntax error still wins, as when whole JSON values were read first. [`super::geojson`] judges
//! a `Node` as it judged a JSON value, with the same messages.
//!
//! The nesting of `coordinates` depends on the object's `type`: when `"coordinates"` comes
//! before `"type"`, it is kept as compact JSON text (a few bytes per position) and read once the
//! type is known. That text is written by a visitor ([`TextSeed`]), not captured raw, so the
//! value goes through the same parser as any other: a JSON syntax error inside it, and
//! `serde_json`'s recursion limit (a value nested 128 deep), are reported where they are in the
//! input, with line and column, and worded as when `"type"` comes first (a raw capture used
//! `serde_json`'s skipping parser, which has no recursion limit: the limit was met only when
//! the text was read again, and the error had no location). A GeoJSON member named twice in one
//! object is recorded (and then reported), since the second could change how the first was
//! read.
//!
//! Memory: 64 bytes per position while its polygon is held (two decimals), plus the text of
//! `coordinates` that come before `"type"`. The positions of one feature (all its polygons
//! together: a MultiPolygon's, a GeometryCollection's) or of one top-level value that is not a
//! FeatureCollection are counted as they are read ([`Vertices`]): past the cap, the polygon
//! being read fails (`more than N vertices in one feature`), its positions are dropped, and the
//! rest of its array is read without being kept, so that the other features go on. Complexity:
//! linear in the input size.

use super::geojson::{json_message, Failure};
use super::limits::too_many_vertices;
use super::vertices::{excerpt, parse_number, quote};
use super::{drop_closing_vertex, RawPolygon};
use crate::geom::decimal::Decimal;
use serde::de::{self, Deserialize, DeserializeSeed, MapAccess, SeqAccess, Visitor};
use serde_json::value::RawValue;
use serde_json::{Map, Value};
use std::cell::Cell;
use std::fmt;

/// The key under which `serde_json` (`arbitrary_precision`) hands a number that is not a 64-bit
/// integer to `visit_map`, its text as the value.
const NUMBER_TOKEN: &str = "$serde_json::private::Number";

/// The members of a GeoJSON object that an [`Object`] keeps.
const MEMBERS: [&str; 5] = ["type", "coordinates", "geometry", "geometries", "features"];

/// What was read, or the first thing wrong with it.
pub(super) type Read<T> = Result<T, Failure>;

/// A JSON value as far as GeoJSON needs it.
#[derive(Debug)]
pub(super) enum Node {
    /// A JSON object.
    Object(Box<Object>),
    /// An array read as a Polygon's coordinates (a top-level array): `None` when empty.
    Rings(Read<Option<RawPolygon>>),
    /// An array read element by element (`features`, `geometries`).
    List(Vec<Node>),
    /// An array whose elements went to a [`FeatureSink`] as they were read.
    Streamed,
    /// Any other array, skipped.
    Array {
        /// Whether it has no element.
        empty: bool,
    },
    /// A string.
    String(String),
    /// A number or a boolean, as a message names it (a long number shortened).
    Scalar(String),
    /// `null`.
    Null,
}

impl Node {
    /// The value as named in an error message.
    pub(super) fn describe(&self) -> String {
        match self {
            Node::Object(_) => "an object".into(),
            Node::Rings(Ok(None)) | Node::Array { empty: true } => "an empty array".into(),
            Node::List(items) if items.is_empty() => "an empty array".into(),
            Node::Rings(_) | Node::List(_) | Node::Streamed | Node::Array { .. } => {
                "an array".into()
            }
            Node::String(s) => quote(s),
            Node::Scalar(s) => s.clone(),
            Node::Null => "null".into(),
        }
    }
}

/// A JSON object: the GeoJSON members it has, each as read.
#[derive(Debug, Default)]
pub(super) struct Object {
    /// `type`.
    pub(super) kind: Option<Node>,
    /// `coordinates`, read as the `type` before it says.
    pub(super) coordinates: Option<Coordinates>,
    /// `geometry`.
    pub(super) geometry: Option<Node>,
    /// `geometries`, element by element.
    pub(super) geometries: Option<Node>,
    /// `features`, element by element (or [`Node::Streamed`]).
    pub(super) features: Option<Node>,
    /// The first GeoJSON member named twice, if any.
    pub(super) duplicate: Option<&'static str>,
    /// `id` as written (kept for the output: [`crate::feature`]); the last one if named twice.
    pub(super) id: Option<Box<RawValue>>,
    /// `properties` as written (kept for the output); the last one if named twice.
    pub(super) properties: Option<Box<RawValue>>,
    /// `name` as written (a FeatureCollection's, kept for the output: [`crate::feature::Collection`]).
    pub(super) name: Option<Box<RawValue>>,
    /// `crs` as written (likewise).
    pub(super) crs: Option<Box<RawValue>>,
}

impl Object {
    /// The `type`, when it is a string.
    pub(super) fn kind(&self) -> Option<&str> {
        match &self.kind {
            Some(Node::String(kind)) => Some(kind),
            _ => None,
        }
    }

    /// Reads `coordinates` kept as text, now that `type` is known, counting its positions in
    /// `vertices`.
    fn finish(&mut self, vertices: &Vertices) {
        let Some(Coordinates::Text(text)) = &self.coordinates else {
            return;
        };
        let mut de = serde_json::Deserializer::from_str(text);
        // The text was written from JSON read within the recursion limit, and is nested less
        // deep than it was in its object: no error is expected here.
        let failed = |e: serde_json::Error| Failure::new(json_message(&e, None));
        self.coordinates = Some(match self.kind() {
            Some("Polygon") => Coordinates::Polygon(
                LevelSeed(PolygonLevel(vertices))
                    .deserialize(&mut de)
                    .unwrap_or_else(|e| Err(failed(e))),
            ),
            Some("MultiPolygon") => Coordinates::MultiPolygon(
                LevelSeed(MultiPolygonLevel(vertices))
                    .deserialize(&mut de)
                    .unwrap_or_else(|e| Err(failed(e))),
            ),
            _ => Coordinates::Skipped,
        });
    }
}

/// The `coordinates` member of an object.
#[derive(Debug)]
pub(super) enum Coordinates {
    /// Read as a Polygon's.
    Polygon(Read<Option<RawPolygon>>),
    /// Read as a MultiPolygon's: its non-empty polygons.
    MultiPolygon(Read<Vec<RawPolygon>>),
    /// Met before `type`: as compact JSON text ([`TextSeed`]), read when the object ends.
    Text(String),
    /// Not read: the `type` needs no coordinates.
    Skipped,
}

/// The positions one feature (or top-level value) may hold, and how many of its positions were
/// read so far: shared by the seeds that read it, reset when the next feature starts.
#[derive(Debug)]
pub(super) struct Vertices {
    max: usize,
    read: Cell<usize>,
    /// How many numbers the feature's first position has: every position of a feature must
    /// have as many (2, 3 or 4), so that its Z (and M) values hold for all its vertices.
    numbers: Cell<Option<usize>>,
}

impl Vertices {
    /// A count from 0 against a cap of `max` positions.
    pub(super) fn new(max: usize) -> Vertices {
        Vertices {
            max,
            read: Cell::new(0),
            numbers: Cell::new(None),
        }
    }

    /// A ring ended with its closing position, dropped: it is not counted.
    fn give_back(&self) {
        self.read.set(self.read.get().saturating_sub(1));
    }

    /// The next feature starts: its positions are counted from 0.
    pub(super) fn reset(&self) {
        self.read.set(0);
        self.numbers.set(None);
    }

    /// Checks that a position of `count` numbers has as many as the feature's first.
    fn numbers(&self, count: usize) -> Result<(), Failure> {
        match self.numbers.get() {
            None => self.numbers.set(Some(count)),
            Some(first) if first != count => {
                return Err(Failure::new(format!(
                "this position has {count} numbers but the feature's first position has {first}: \
                     mixed [x, y], [x, y, z] and [x, y, z, m] positions"
            )))
            }
            Some(_) => {}
        }
        Ok(())
    }

    /// The dimensions of the feature's positions read so far (`None` for `[x, y]`).
    fn dims(&self) -> Option<super::Dims> {
        self.numbers
            .get()
            .and_then(|count| super::Dims::of(count, false))
    }

    /// Counts one more position; the failure when it is one too many. A position that repeats
    /// its ring's first (`closing`) may be the ring's closing one, which the polygon does not
    /// count ([`Vertices::give_back`] once the ring ends with it): it may be one past the cap,
    /// and any position after it in the ring is then too many.
    fn take(&self, closing: bool) -> Result<(), Failure> {
        let read = self.read.get();
        if read > self.max || (read == self.max && !closing) {
            let message = too_many_vertices(self.max, "one feature");
            return Err(Failure::new(message));
        }
        self.read.set(read + 1);
        Ok(())
    }
}

/// Why a [`FeatureSink`] refused a feature; reading stops (the deserializer's error carries it
/// as its text, and the sink keeps the cause).
#[derive(Clone, Copy, Debug, PartialEq, Eq, thiserror::Error)]
pub(super) enum SinkError {
    /// Writing the feature's events failed (the sink keeps the I/O error).
    #[error("the output failed")]
    Output,
}

/// Where the elements of a FeatureCollection's `features` go as they are read.
pub(super) trait FeatureSink {
    /// Element `index` of `features`. An `Err` stops reading (its text is the `serde` error).
    fn feature(&mut self, index: usize, feature: Node) -> Result<(), SinkError>;

    /// What the bytes read from now on belong to: element `index` of `features` (`Some`,
    /// before each element and before the array's end), or the rest of the collection (`None`,
    /// after the array). A reader that bounds one feature's size starts counting here.
    fn reading(&mut self, _index: Option<usize>) {}

    /// The collection's `name` and `crs` as read before its `features` (told once, before the
    /// first feature), for the features to carry.
    fn collection(&mut self, _name: Option<Box<RawValue>>, _crs: Option<Box<RawValue>>) {}
}

/// What becomes of arrays.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Arrays {
    /// Read as a Polygon's coordinates.
    Rings,
    /// Read element by element.
    List,
    /// Features: to the sink if there is one (a streamed FeatureCollection), else read element by
    /// element, like `List`; either way each element's positions are counted alone.
    Stream,
    /// Skipped.
    Skip,
}

/// Reads a [`Node`].
pub(super) struct NodeSeed<'s> {
    arrays: Arrays,
    /// For the top-level object: where its `features` go, when it is a FeatureCollection whose
    /// `type` comes first; for [`Arrays::Stream`], where the elements go.
    sink: Option<&'s mut dyn FeatureSink>,
    /// The count of positions of the feature (or top-level value) being read.
    vertices: &'s Vertices,
}

impl<'s> NodeSeed<'s> {
    /// A top-level value, its positions counted in `vertices`; with a sink, the features of a
    /// FeatureCollection are sent to it as they are read.
    pub(super) fn top(
        sink: Option<&'s mut dyn FeatureSink>,
        vertices: &'s Vertices,
    ) -> NodeSeed<'s> {
        NodeSeed {
            arrays: Arrays::Rings,
            sink,
            vertices,
        }
    }

    /// A value whose arrays are skipped (unless it is an object).
    fn skip(vertices: &'s Vertices) -> NodeSeed<'s> {
        NodeSeed {
            arrays: Arrays::Skip,
            sink: None,
            vertices,
        }
    }

    /// A value whose arrays are read element by element.
    fn list(vertices: &'s Vertices) -> NodeSeed<'s> {
        NodeSeed {
            arrays: Arrays::List,
            sink: None,
            vertices,
        }
    }
}

impl<'de> Deserialize<'de> for Node {
    /// A top-level value, at most [`MAX_VERTICES`](super::limits::MAX_VERTICES) positions.
    fn deserialize<D: de::Deserializer<'de>>(d: D) -> Result<Node, D::Error> {
        let vertices = Vertices::new(super::limits::MAX_VERTICES);
        NodeSeed::top(None, &vertices).deserialize(d)
    }
}

impl<'de> DeserializeSeed<'de> for NodeSeed<'_> {
    type Value = Node;

    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Node, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for NodeSeed<'_> {
    type Value = Node;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Node, A::Error> {
        let vertices = self.vertices;
        match (self.arrays, self.sink) {
            (Arrays::Rings, _) => Ok(Node::Rings(PolygonLevel(vertices).array(seq)?)),
            (Arrays::Stream, Some(sink)) => {
                let mut index = 0;
                sink.reading(Some(index));
                vertices.reset();
                while let Some(feature) = seq.next_element_seed(NodeSeed::skip(vertices))? {
                    sink.feature(index, feature).map_err(de::Error::custom)?;
                    index += 1;
                    sink.reading(Some(index));
                    vertices.reset();
                }
                sink.reading(None);
                Ok(Node::Streamed)
            }
            (Arrays::List | Arrays::Stream, _) => {
                // The features of a collection read whole are counted one by one too; the
                // members of a GeometryCollection (`List`) together, as one feature.
                let features = self.arrays == Arrays::Stream;
                let mut items = Vec::new();
                while let Some(item) = seq.next_element_seed(NodeSeed::skip(vertices))? {
                    items.push(item);
                    if features {
                        vertices.reset();
                    }
                }
                Ok(Node::List(items))
            }
            (Arrays::Skip, _) => {
                let empty = seq.next_element::<Skip>()?.is_none();
                skip_rest(seq)?;
                Ok(Node::Array { empty })
            }
        }
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Node, A::Error> {
        let first = match map.next_key_seed(KeySeed)? {
            None => return Ok(Node::Object(Box::default())),
            Some(Key::Number) => return Ok(Node::Scalar(excerpt(&number_text(map)?))),
            Some(key) => key,
        };
        // Only the top-level object streams its features.
        let sink = self.sink.filter(|_| self.arrays == Arrays::Rings);
        Ok(Node::Object(Box::new(read_object(
            first,
            map,
            sink,
            self.vertices,
        )?)))
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Node, E> {
        Ok(Node::Scalar(v.to_string()))
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Node, E> {
        Ok(Node::Scalar(v.to_string()))
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Node, E> {
        Ok(Node::Scalar(v.to_string()))
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Node, E> {
        Ok(Node::Scalar(excerpt(&v.to_string())))
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Node, E> {
        Ok(Node::String(v.to_string()))
    }

    fn visit_string<E: de::Error>(self, v: String) -> Result<Node, E> {
        Ok(Node::String(v))
    }

    fn visit_unit<E: de::Error>(self) -> Result<Node, E> {
        Ok(Node::Null)
    }
}

/// The members of an object after its first key `first`.
fn read_object<'de, A: MapAccess<'de>>(
    first: Key,
    mut map: A,
    mut sink: Option<&mut dyn FeatureSink>,
    vertices: &Vertices,
) -> Result<Object, A::Error> {
    let mut object = Object::default();
    let mut seen = [false; MEMBERS.len()];
    let mut key = Some(first);
    while let Some(current) = key {
        let Key::Member(member) = current else {
            match &current {
                Key::Other(name) if name == "id" => object.id = Some(map.next_value()?),
                Key::Other(name) if name == "properties" => {
                    object.properties = Some(map.next_value()?);
                }
                Key::Other(name) if name == "name" => object.name = Some(map.next_value()?),
                Key::Other(name) if name == "crs" => object.crs = Some(map.next_value()?),
                _ => {
                    map.next_value::<Skip>()?;
                }
            }
            key = map.next_key_seed(KeySeed)?;
            continue;
        };
        if std::mem::replace(&mut seen[member], true) {
            object.duplicate = object.duplicate.or(Some(MEMBERS[member]));
        }
        match MEMBERS[member] {
            "type" => object.kind = Some(map.next_value_seed(NodeSeed::skip(vertices))?),
            "coordinates" => {
                let coordinates = match (object.kind(), &object.kind) {
                    (Some("Polygon"), _) => {
                        let seed = LevelSeed(PolygonLevel(vertices));
                        Coordinates::Polygon(map.next_value_seed(seed)?)
                    }
                    (Some("MultiPolygon"), _) => Coordinates::MultiPolygon(
                        map.next_value_seed(LevelSeed(MultiPolygonLevel(vertices)))?,
                    ),
                    (None, None) => {
                        let mut text = String::new();
                        map.next_value_seed(TextSeed(&mut text))?;
                        text.shrink_to_fit();
                        Coordinates::Text(text)
                    }
                    _ => {
                        map.next_value::<Skip>()?;
                        Coordinates::Skipped
                    }
                };
                object.coordinates = Some(coordinates);
            }
            "geometry" => {
                object.geometry = Some(map.next_value_seed(NodeSeed::skip(vertices))?);
            }
            "geometries" => {
                object.geometries = Some(map.next_value_seed(NodeSeed::list(vertices))?);
            }
            _ /* "features" */ => {
                let stream = object.kind() == Some("FeatureCollection")
                    && object.features.is_none()
                    && sink.is_some();
                let seed = match sink.as_deref_mut() {
                    Some(sink) if stream => {
                        sink.collection(object.name.clone(), object.crs.clone());
                        NodeSeed {
                            arrays: Arrays::Stream,
                            sink: Some(sink),
                            vertices,
                        }
                    }
                    // Features read whole (`"type"` after them, say): still counted one by one.
                    _ => NodeSeed {
                        arrays: Arrays::Stream,
                        sink: None,
                        vertices,
                    },
                };
                object.features = Some(map.next_value_seed(seed)?);
            }
        }
        key = map.next_key_seed(KeySeed)?;
    }
    object.finish(vertices);
    Ok(object)
}

/// A key of a JSON object, told apart without copying it when it matters.
enum Key {
    /// `serde_json`'s number token: the "object" is a number.
    Number,
    /// A GeoJSON member, by its index in [`MEMBERS`].
    Member(usize),
    /// Any other name.
    Other(String),
}

impl Key {
    fn name(self) -> String {
        match self {
            Key::Number => NUMBER_TOKEN.to_string(),
            Key::Member(member) => MEMBERS[member].to_string(),
            Key::Other(name) => name,
        }
    }
}

/// Reads a [`Key`].
struct KeySeed;

impl<'de> DeserializeSeed<'de> for KeySeed {
    type Value = Key;

    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Key, D::Error> {
        d.deserialize_str(self)
    }
}

impl<'de> Visitor<'de> for KeySeed {
    type Value = Key;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a key")
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Key, E> {
        Ok(if v == NUMBER_TOKEN {
            Key::Number
        } else if let Some(member) = MEMBERS.iter().position(|&m| m == v) {
            Key::Member(member)
        } else {
            Key::Other(v.to_string())
        })
    }
}

/// The rest of a map whose first key was [`NUMBER_TOKEN`]: the number's text.
///
/// # Errors
/// When the text is not a JSON number (an object that names a member so), as `serde_json`
/// itself does when it reads such an object into a `Value`.
fn number_text<'de, A: MapAccess<'de>>(mut map: A) -> Result<String, A::Error> {
    let text: String = map.next_value()?;
    if !is_json_number(&text) {
        return Err(de::Error::custom("invalid number"));
    }
    Ok(text)
}

/// Writes a JSON value as compact JSON text to its string: numbers as their literal text
/// (`serde_json`'s `arbitrary_precision`), strings escaped again, objects through
/// `serde_json::Value`. Read with `deserialize_any`, so that the value is checked by the same
/// parser as any other (its syntax errors and recursion limit located in the input).
struct TextSeed<'t>(&'t mut String);

impl<'de> DeserializeSeed<'de> for TextSeed<'_> {
    type Value = ();

    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<(), D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for TextSeed<'_> {
    type Value = ();

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<(), A::Error> {
        let out = self.0;
        out.push('[');
        let mut first = true;
        loop {
            let mark = out.len();
            if !first {
                out.push(',');
            }
            if seq.next_element_seed(TextSeed(&mut *out))?.is_none() {
                out.truncate(mark);
                break;
            }
            first = false;
        }
        out.push(']');
        Ok(())
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<(), A::Error> {
        let mut object = Map::new();
        match map.next_key_seed(KeySeed)? {
            None => {}
            Some(Key::Number) => {
                self.0.push_str(&number_text(map)?);
                return Ok(());
            }
            Some(key) => {
                object.insert(key.name(), map.next_value()?);
                while let Some((name, value)) = map.next_entry()? {
                    object.insert(name, value);
                }
            }
        }
        self.0.push_str(&Value::Object(object).to_string());
        Ok(())
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<(), E> {
        self.0.push_str(if v { "true" } else { "false" });
        Ok(())
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<(), E> {
        self.0.push_str(&v.to_string());
        Ok(())
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<(), E> {
        self.0.push_str(&v.to_string());
        Ok(())
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<(), E> {
        self.0.push_str(&Value::from(v).to_string());
        Ok(())
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<(), E> {
        self.0.push_str(&Value::from(v).to_string());
        Ok(())
    }

    fn visit_unit<E: de::Error>(self) -> Result<(), E> {
        self.0.push_str("null");
        Ok(())
    }
}

/// Whether `text` is a JSON number (RFC 8259, section 6).
fn is_json_number(text: &str) -> bool {
    let bytes = text.as_bytes();
    let mut at = usize::from(bytes.first() == Some(&b'-'));
    let digits = |at: &mut usize| {
        let start = *at;
        while bytes.get(*at).is_some_and(u8::is_ascii_digit) {
            *at += 1;
        }
        *at > start
    };
    match bytes.get(at) {
        Some(b'0') => at += 1,
        Some(b'1'..=b'9') => {
            digits(&mut at);
        }
        _ => return false,
    }
    if bytes.get(at) == Some(&b'.') {
        at += 1;
        if !digits(&mut at) {
            return false;
        }
    }
    if matches!(bytes.get(at), Some(b'e' | b'E')) {
        at += 1;
        if matches!(bytes.get(at), Some(b'+' | b'-')) {
            at += 1;
        }
        if !digits(&mut at) {
            return false;
        }
    }
    at == bytes.len()
}

/// Any JSON value, read and dropped. It is read with `deserialize_any`, as `serde_json::Value`
/// is, so that errors in it (a control character in a string, the recursion limit) are reported
/// where they were when whole values were read (`serde::de::IgnoredAny` takes another path in
/// `serde_json`, one column off for a string, and without the recursion limit).
struct Skip;

impl<'de> Deserialize<'de> for Skip {
    fn deserialize<D: de::Deserializer<'de>>(d: D) -> Result<Skip, D::Error> {
        d.deserialize_any(SkipVisitor)
    }
}

/// Reads a [`Skip`].
struct SkipVisitor;

impl<'de> Visitor<'de> for SkipVisitor {
    type Value = Skip;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Skip, A::Error> {
        skip_rest(seq).map(|()| Skip)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Skip, A::Error> {
        while map.next_entry::<Skip, Skip>()?.is_some() {}
        Ok(Skip)
    }

    fn visit_bool<E: de::Error>(self, _: bool) -> Result<Skip, E> {
        Ok(Skip)
    }

    fn visit_u64<E: de::Error>(self, _: u64) -> Result<Skip, E> {
        Ok(Skip)
    }

    fn visit_i64<E: de::Error>(self, _: i64) -> Result<Skip, E> {
        Ok(Skip)
    }

    fn visit_f64<E: de::Error>(self, _: f64) -> Result<Skip, E> {
        Ok(Skip)
    }

    fn visit_str<E: de::Error>(self, _: &str) -> Result<Skip, E> {
        Ok(Skip)
    }

    fn visit_unit<E: de::Error>(self) -> Result<Skip, E> {
        Ok(Skip)
    }
}

/// Reads the elements left in an array, checking only that they are JSON.
fn skip_rest<'de, A: SeqAccess<'de>>(mut seq: A) -> Result<(), A::Error> {
    while seq.next_element::<Skip>()?.is_some() {}
    Ok(())
}

/// One level of `coordinates`: what its array is read into, and the failure for anything else.
trait Level: Sized {
    type Output;

    /// Reads the array, every element of it, also after a failure.
    fn array<'de, A: SeqAccess<'de>>(self, seq: A) -> Result<Read<Self::Output>, A::Error>;

    /// The failure for a value that is not an array, named `found` (`number`: it is a number).
    fn not_array(self, found: String, number: bool) -> Failure;
}

/// Reads one level of `coordinates`.
struct LevelSeed<L>(L);

impl<'de, L: Level> DeserializeSeed<'de> for LevelSeed<L> {
    type Value = Read<L::Output>;

    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Self::Value, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de, L: Level> Visitor<'de> for LevelSeed<L> {
    type Value = Read<L::Output>;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<Self::Value, A::Error> {
        self.0.array(seq)
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
        match map.next_key_seed(KeySeed)? {
            None => {}
            Some(Key::Number) => {
                let text = number_text(map)?;
                return Ok(Err(self.0.not_array(excerpt(&text), true)));
            }
            Some(_) => {
                map.next_value::<Skip>()?;
                while map.next_entry::<Skip, Skip>()?.is_some() {}
            }
        }
        Ok(Err(self.0.not_array("an object".into(), false)))
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Self::Value, E> {
        Ok(Err(self.0.not_array(v.to_string(), false)))
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Self::Value, E> {
        Ok(Err(self.0.not_array(v.to_string(), true)))
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Self::Value, E> {
        Ok(Err(self.0.not_array(v.to_string(), true)))
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Self::Value, E> {
        Ok(Err(self.0.not_array(excerpt(&v.to_string()), true)))
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Self::Value, E> {
        Ok(Err(self.0.not_array(quote(v), false)))
    }

    fn visit_unit<E: de::Error>(self) -> Result<Self::Value, E> {
        Ok(Err(self.0.not_array("null".into(), false)))
    }
}

/// A MultiPolygon's coordinates: polygons (empty ones left out), their positions counted.
struct MultiPolygonLevel<'v>(&'v Vertices);

impl Level for MultiPolygonLevel<'_> {
    type Output = Vec<RawPolygon>;

    fn array<'de, A: SeqAccess<'de>>(self, mut seq: A) -> Result<Read<Self::Output>, A::Error> {
        let mut polygons = Vec::new();
        let mut index = 0;
        while let Some(polygon) = seq.next_element_seed(LevelSeed(PolygonLevel(self.0)))? {
            match polygon {
                Ok(polygon) => polygons.extend(polygon),
                Err(failure) => {
                    drop(polygons);
                    skip_rest(seq)?;
                    return Ok(Err(failure.within("polygon", index)));
                }
            }
            index += 1;
        }
        Ok(Ok(polygons))
    }

    fn not_array(self, found: String, _: bool) -> Failure {
        Failure::new(format!(
            "expected an array of polygons [[[[x, y], ...], ...], ...], found {found}"
        ))
    }
}

/// A Polygon's coordinates: rings; `None` for an empty array (an empty polygon). Its positions
/// are counted.
struct PolygonLevel<'v>(&'v Vertices);

impl Level for PolygonLevel<'_> {
    type Output = Option<RawPolygon>;

    fn array<'de, A: SeqAccess<'de>>(self, mut seq: A) -> Result<Read<Self::Output>, A::Error> {
        let mut rings = Vec::new();
        let mut values = Vec::new();
        while let Some(ring) = seq.next_element_seed(LevelSeed(RingLevel(self.0)))? {
            match ring {
                Ok((ring, extra)) => {
                    rings.push(ring);
                    values.extend(extra);
                }
                Err(failure) => {
                    let index = rings.len();
                    drop(rings);
                    skip_rest(seq)?;
                    return Ok(Err(failure.within("ring", index)));
                }
            }
        }
        let ordinates = self.0.dims().map(|dims| super::Ordinates { dims, values });
        Ok(Ok(
            (!rings.is_empty()).then_some(RawPolygon { rings, ordinates })
        ))
    }

    fn not_array(self, found: String, _: bool) -> Failure {
        Failure::new(format!(
            "expected an array of rings [[[x, y], ...], ...], found {found}"
        ))
    }
}

/// A ring: its positions, without the repeated closing one, counted as they are read.
struct RingLevel<'v>(&'v Vertices);

impl Level for RingLevel<'_> {
    /// The ring's positions, and their z and m values (none for `[x, y]` positions).
    type Output = (Vec<[Decimal; 2]>, Vec<super::Ordinate>);

    fn array<'de, A: SeqAccess<'de>>(self, mut seq: A) -> Result<Read<Self::Output>, A::Error> {
        let mut ring = Vec::new();
        let mut values = Vec::new();
        while let Some(position) = seq.next_element_seed(LevelSeed(PositionLevel))? {
            // One position too many for the feature: the ring is dropped, the rest not kept.
            let position = position.and_then(|(p, extra, count)| {
                self.0.numbers(count)?;
                let closing = ring.first() == Some(&p);
                self.0.take(closing).map(|()| {
                    values.extend(extra.into_iter().take(count - 2).map(Some));
                    p
                })
            });
            match position {
                // Memory refused is this polygon's failure (reading goes on), not an abort.
                Ok(_) if ring.try_reserve(1).is_err() => {
                    let index = ring.len();
                    drop(ring);
                    skip_rest(seq)?;
                    let message = format!("not enough memory to hold the ring: {index} positions read, no room for more");
                    return Ok(Err(Failure::new(message).within("position", index)));
                }
                Ok(position) => ring.push(position),
                Err(failure) => {
                    let index = ring.len();
                    drop(ring); // its memory back before the rest is read
                    skip_rest(seq)?;
                    return Ok(Err(failure.within("position", index)));
                }
            }
        }
        if ring.is_empty() {
            return Ok(Err(Failure::new("empty ring: expected positions [x, y]")));
        }
        if drop_closing_vertex(&mut ring) {
            self.0.give_back(); // the closing position, not a vertex of the polygon
            let extra = self.0.numbers.get().unwrap_or(2).saturating_sub(2);
            values.truncate(values.len().saturating_sub(extra));
        }
        ring.shrink_to_fit();
        Ok(Ok((ring, values)))
    }

    fn not_array(self, found: String, _: bool) -> Failure {
        Failure::new(format!("expected a ring [[x, y], ...], found {found}"))
    }
}

/// A position `[x, y]`, `[x, y, z]` or `[x, y, z, m]`: `x` and `y`.
struct PositionLevel;

impl Level for PositionLevel {
    /// `[x, y]`, the z and m values (as many as given), and how many numbers in all.
    type Output = ([Decimal; 2], [Decimal; 2], usize);

    fn array<'de, A: SeqAccess<'de>>(self, mut seq: A) -> Result<Read<Self::Output>, A::Error> {
        // The first four elements, and how many there are in all.
        let mut items: [Option<Item>; 4] = [None, None, None, None];
        let mut count = 0;
        for slot in &mut items {
            match seq.next_element_seed(ItemSeed)? {
                Some(item) => *slot = Some(item),
                None => break,
            }
            count += 1;
        }
        if count == items.len() {
            while seq.next_element::<Skip>()?.is_some() {
                count += 1;
            }
        }
        Ok(position(items, count))
    }

    fn not_array(self, found: String, number: bool) -> Failure {
        let hint = if number {
            " (the coordinates are nested one level too shallow)"
        } else {
            ""
        };
        Failure::new(format!("expected [x, y], found {found}{hint}"))
    }
}

/// The position whose first elements are `items`, `count` elements in all.
fn position(
    [x, y, z, m]: [Option<Item>; 4],
    count: usize,
) -> Read<([Decimal; 2], [Decimal; 2], usize)> {
    if let Some(Item::Array { .. }) = x {
        return Err(Failure::new(
            "expected [x, y], found an array of arrays (the coordinates are nested one level too deep)",
        ));
    }
    let (Some(x), Some(y)) = (&x, &y) else {
        let text = match &x {
            Some(item) => format!("[{}]", item.json()),
            None => "[]".to_string(),
        };
        return Err(Failure::new(format!(
            "expected [x, y], found {}",
            excerpt(&text)
        )));
    };
    if count > 4 {
        return Err(Failure::new(format!(
            "a position has at most 4 numbers [x, y, z, m], found {count}"
        )));
    }
    let x = x.decimal("x")?;
    let y = y.decimal("y")?;
    let mut extra = [Decimal::from(0u64), Decimal::from(0u64)];
    for ((item, axis), slot) in [(z, "z"), (m, "m")].into_iter().zip(&mut extra) {
        if let Some(item) = item {
            *slot = item.decimal(axis)?;
        }
    }
    Ok(([x, y], extra, count))
}

/// An element of a position.
enum Item {
    /// A number: a 64-bit integer, or the literal text of any other.
    Number(Number),
    /// An array, skipped.
    Array { empty: bool },
    /// Anything else (a wrong position).
    Other(Value),
}

/// A JSON number as `serde_json` hands it over.
enum Number {
    Unsigned(u64),
    Signed(i64),
    Text(String),
}

impl Item {
    /// The element as a number for `axis`, exactly.
    fn decimal(&self, axis: &str) -> Read<Decimal> {
        match self {
            Item::Number(Number::Unsigned(v)) => Ok(Decimal::from(*v)),
            Item::Number(Number::Signed(v)) => Ok(Decimal::from(*v)),
            Item::Number(Number::Text(text)) => parse_number(text).map_err(Failure::new),
            other => Err(Failure::new(format!(
                "expected a number for {axis}, found {}",
                other.describe()
            ))),
        }
    }

    /// The element as named in an error message.
    fn describe(&self) -> String {
        match self {
            Item::Number(_) => excerpt(&self.json()),
            Item::Array { empty: true } => "an empty array".into(),
            Item::Array { empty: false } => "an array".into(),
            Item::Other(Value::String(s)) => quote(s),
            Item::Other(Value::Object(_)) => "an object".into(),
            Item::Other(other) => other.to_string(),
        }
    }

    /// The element as JSON text; an array, which no message quotes, as `[...]`.
    fn json(&self) -> String {
        match self {
            Item::Number(Number::Unsigned(v)) => v.to_string(),
            Item::Number(Number::Signed(v)) => v.to_string(),
            Item::Number(Number::Text(text)) => text.clone(),
            Item::Array { .. } => "[...]".into(),
            Item::Other(value) => value.to_string(),
        }
    }
}

/// Reads an [`Item`].
struct ItemSeed;

impl<'de> DeserializeSeed<'de> for ItemSeed {
    type Value = Item;

    fn deserialize<D: de::Deserializer<'de>>(self, d: D) -> Result<Item, D::Error> {
        d.deserialize_any(self)
    }
}

impl<'de> Visitor<'de> for ItemSeed {
    type Value = Item;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("a JSON value")
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<Item, E> {
        Ok(Item::Number(Number::Unsigned(v)))
    }

    fn visit_i64<E: de::Error>(self, v: i64) -> Result<Item, E> {
        Ok(Item::Number(Number::Signed(v)))
    }

    fn visit_f64<E: de::Error>(self, v: f64) -> Result<Item, E> {
        Ok(Item::Number(Number::Text(v.to_string())))
    }

    fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Item, A::Error> {
        let empty = seq.next_element::<Skip>()?.is_none();
        skip_rest(seq)?;
        Ok(Item::Array { empty })
    }

    fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Item, A::Error> {
        let mut object = Map::new();
        match map.next_key_seed(KeySeed)? {
            None => {}
            Some(Key::Number) => return Ok(Item::Number(Number::Text(number_text(map)?))),
            Some(key) => {
                object.insert(key.name(), map.next_value()?);
                while let Some((name, value)) = map.next_entry()? {
                    object.insert(name, value);
                }
            }
        }
        Ok(Item::Other(Value::Object(object)))
    }

    fn visit_bool<E: de::Error>(self, v: bool) -> Result<Item, E> {
        Ok(Item::Other(Value::Bool(v)))
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<Item, E> {
        Ok(Item::Other(Value::String(v.to_string())))
    }

    fn visit_string<E: de::Error>(self, v: String) -> Result<Item, E> {
        Ok(Item::Other(Value::String(v)))
    }

    fn visit_unit<E: de::Error>(self) -> Result<Item, E> {
        Ok(Item::Other(Value::Null))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reliance on serde_json's private number token, checked: with `arbitrary_precision`,
    /// a number that is not a 64-bit integer reaches a visitor as a map whose one key is
    /// [`NUMBER_TOKEN`] and whose value is the number's text. Cargo.toml pins serde_json to the
    /// version this holds for; a new version that changes it fails here, not in the readers.
    #[test]
    fn serde_json_still_hands_numbers_over_as_its_private_token() {
        struct FirstEntry;
        impl<'de> Visitor<'de> for FirstEntry {
            type Value = Option<(String, String)>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a number")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Self::Value, A::Error> {
                let key: Option<String> = map.next_key()?;
                let value: Option<String> = match key {
                    Some(_) => Some(map.next_value()?),
                    None => None,
                };
                Ok(key.zip(value))
            }
            fn visit_f64<E: de::Error>(self, _: f64) -> Result<Self::Value, E> {
                Ok(None)
            }
        }
        let text = "0.1000000000000000000001";
        let mut json = serde_json::Deserializer::from_str(text);
        let entry = de::Deserializer::deserialize_any(&mut json, FirstEntry);
        assert_eq!(
            entry.ok().flatten(),
            Some((NUMBER_TOKEN.to_string(), text.to_string())),
            "serde_json no longer hands a number over as {NUMBER_TOKEN:?} with its text: \
             io/read/geojson_seed.rs reads every GeoJSON coordinate through that token. Keep \
             the serde_json version pinned in Cargo.toml, or update NUMBER_TOKEN and this test"
        );
        // And the readers built on it keep the decimal exactly.
        let polygons = super::super::geojson::read(
            r#"{"type": "Polygon", "coordinates": [[[0, 0], [0.1000000000000000000001, 0], [0, 1]]]}"#,
        );
        let x = polygons.ok().map(|p| p[0].rings[0][1][0].to_string());
        assert_eq!(x.as_deref(), Some(text));
    }

    #[test]
    fn json_numbers_are_recognised_by_the_grammar() {
        for good in ["0", "-0", "12", "-3.25", "1e5", "1E+5", "2.5e-3", "0.0"] {
            assert!(is_json_number(good), "{good}");
        }
        for bad in [
            "", "-", "01", "1.", ".5", "+1", "1e", "1e+", "NaN", "1 ", "0x1", "abc",
        ] {
            assert!(!is_json_number(bad), "{bad}");
        }
    }
}
