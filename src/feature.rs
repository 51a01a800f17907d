//! Feature identity: which input feature an outcome comes from, so that results join back.
//!
//! A GeoJSON input is a sequence of features (the Features of a FeatureCollection, or the
//! top-level values of GeoJSON Lines and of concatenated GeoJSON, each one feature). Each gets
//! a [`Feature`]: its number in its source (from 0, in input order), its `id` and `properties`
//! exactly as written (the JSON text, byte for byte: `serde_json`'s [`RawValue`]), and what its
//! geometry is: `k` parts (a Polygon is 1 part, a MultiPolygon or GeometryCollection `k`),
//! `null`, or unreadable. Each part of it is then one [`Identity`]: the feature and the part's
//! number within it. A part is a polygon, or a member of a GeometryCollection that is not one
//! (a Point, a LineString): a failed part, one error outcome in its place among the parts, so
//! that the collection's polygons are triangulated and the member reported, numbered like them. The writers use them: JSON entries carry `feature`, `part`, `id`
//! and `properties`; `--to geojson` and `--to geojsonl` give one Feature per input feature.
//!
//! Inputs without features (WKT, vertex lists) have no identity: each polygon stands alone.
//! A feature of a FeatureCollection also carries the collection's `name` and `crs` as written
//! ([`Collection`]), which `--to geojson` keeps.

use serde_json::value::RawValue;
use std::sync::Arc;

/// One input feature, as far as the output needs it.
#[derive(Clone, Debug)]
pub struct Feature {
    /// Its number in its source, from 0 (features of a collection, or values of GeoJSON Lines).
    pub number: usize,
    /// For GeoJSON Lines: the line it was read from (from 1).
    pub line: Option<usize>,
    /// `id` as written, if the feature has one.
    pub id: Option<Box<RawValue>>,
    /// `properties` as written, if the feature has the member (`null` included).
    pub properties: Option<Box<RawValue>>,
    /// What its geometry is.
    pub geometry: Geometry,
    /// The FeatureCollection it belongs to, when that collection has members to carry to the
    /// output (`name`, `crs`); `None` otherwise.
    pub collection: Option<Arc<Collection>>,
}

/// The members of an input FeatureCollection that the `--to geojson` output carries over, each
/// as written (the JSON text, byte for byte): its `name` (the layer's name, as GDAL writes it)
/// and its `crs` (GeoJSON 2008's `{"type": "name", "properties": {"name":
/// "urn:ogc:def:crs:EPSG::3857"}}`, which GDAL still writes for a layer not in WGS 84).
/// Only those that come before `features` in a streamed collection are known to its features.
#[derive(Clone, Debug, Default)]
pub struct Collection {
    /// `name` as written, if the collection has one.
    pub name: Option<Box<RawValue>>,
    /// `crs` as written, if the collection has one.
    pub crs: Option<Box<RawValue>>,
}

impl Collection {
    /// The members, when there is any (`None` for neither).
    pub fn of(name: Option<Box<RawValue>>, crs: Option<Box<RawValue>>) -> Option<Arc<Collection>> {
        (name.is_some() || crs.is_some()).then(|| Arc::new(Collection { name, crs }))
    }

    /// A `crs` member naming EPSG code `srid` (`urn:ogc:def:crs:EPSG::<srid>`), as GDAL writes it.
    pub fn epsg(srid: u32) -> Box<RawValue> {
        let text = format!(
            "{{\"type\": \"name\", \"properties\": {{\"name\": \"urn:ogc:def:crs:EPSG::{srid}\"}}}}"
        );
        RawValue::from_string(text).unwrap_or_else(|_| unreachable!("valid JSON"))
    }
}

/// What a feature's geometry is, as read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Geometry {
    /// This many parts, each one outcome, in input order: the polygons (a MultiPolygon's in
    /// order), and the members of a GeometryCollection that are not polygons (failed parts).
    Parts(usize),
    /// `"geometry": null`: nothing to triangulate (reported as an error of the feature).
    Null,
    /// Not a polygon, or unreadable: one failed outcome.
    Failed,
}

impl Feature {
    /// How many outcomes this feature gives: its parts, or one failure.
    pub fn outcomes(&self) -> usize {
        match self.geometry {
            Geometry::Parts(parts) => parts.max(1),
            Geometry::Null | Geometry::Failed => 1,
        }
    }

    /// The message of a null geometry (no location: the outcome names the feature).
    pub fn null_message() -> &'static str {
        "\"geometry\" is null: nothing to triangulate"
    }
}

/// Which part of which input feature an outcome is.
#[derive(Clone, Debug)]
pub struct Identity {
    /// The feature.
    pub feature: Arc<Feature>,
    /// The part's number within it, from 0 (always 0 for a Polygon).
    pub part: usize,
}

impl Identity {
    /// Whether the feature has several parts (so that messages name the part).
    pub fn multipart(&self) -> bool {
        matches!(self.feature.geometry, Geometry::Parts(k) if k > 1)
    }
}

/// `properties` as written with the member `name` set to `value` (JSON text): the input's bytes
/// kept, `value` appended before the closing brace. When the input has no properties (or
/// `null`), an object of that member alone; when its properties are not an object (not
/// GeoJSON), they are kept whole under `"input"`. A member already named `name` is replaced
/// (then the other members are written again by `serde_json`, still as written).
pub fn properties_with(properties: Option<&RawValue>, name: &str, value: &str) -> String {
    let key = serde_json::to_string(name).unwrap_or_default();
    let text = properties.map_or("null", RawValue::get).trim();
    if text == "null" {
        return format!("{{{key}: {value}}}");
    }
    if !text.starts_with('{') {
        return format!("{{\"input\": {text}, {key}: {value}}}");
    }
    let mut members: Option<serde_json::Map<String, serde_json::Value>> = text
        .contains(&key)
        .then(|| serde_json::from_str(text).ok())
        .flatten();
    // The name appears as a member (not only inside a string or a nested object).
    let text = match members.as_mut().filter(|m| m.contains_key(name)) {
        Some(members) => {
            members.remove(name);
            serde_json::to_string(&members).unwrap_or_else(|_| "{}".into())
        }
        None => text.to_string(),
    };
    let body = text[1..text.len() - 1].trim();
    if body.is_empty() {
        format!("{{{key}: {value}}}")
    } else {
        format!("{{{body}, {key}: {value}}}")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn raw(text: &str) -> Box<RawValue> {
        RawValue::from_string(text.to_string()).unwrap()
    }

    #[test]
    fn properties_keep_their_bytes_and_gain_one_member() {
        let p = raw(r#"{"name": "Hôtel",  "height": 12.50, "n": 1e400}"#);
        assert_eq!(
            properties_with(Some(&p), "minitri", "{\"ok\": true}"),
            r#"{"name": "Hôtel",  "height": 12.50, "n": 1e400, "minitri": {"ok": true}}"#
        );
        assert_eq!(properties_with(None, "m", "1"), r#"{"m": 1}"#);
        assert_eq!(properties_with(Some(&raw("null")), "m", "1"), r#"{"m": 1}"#);
        assert_eq!(properties_with(Some(&raw("{ }")), "m", "1"), r#"{"m": 1}"#);
        assert_eq!(
            properties_with(Some(&raw("[1, 2]")), "m", "1"),
            r#"{"input": [1, 2], "m": 1}"#
        );
        // Named inside a string only: kept as written.
        let p = raw(r#"{"note": "\"m\" is here"}"#);
        assert_eq!(
            properties_with(Some(&p), "m", "1"),
            r#"{"note": "\"m\" is here", "m": 1}"#
        );
        // A member of that name is replaced, never duplicated.
        let p = raw(r#"{"m": 0, "a": 2}"#);
        assert_eq!(properties_with(Some(&p), "m", "1"), r#"{"a":2, "m": 1}"#);
    }
}
