//! WKB in: a Polygon or MultiPolygon (2D; Z and M are dropped) read by the `wkb` crate, its
//! `f64` coordinates taken as their shortest decimals by the library's geo-types path
//! ([`minitri::geo`]), so a float means what Python's `repr` prints for it.

use geo_traits::to_geo::{ToGeoMultiPolygon, ToGeoPolygon};
use geo_traits::{GeometryTrait, GeometryType};
use minitri::pipeline::Error;
use minitri::RawPolygon;

/// The polygons of one WKB geometry, as exact decimals, not yet validated.
///
/// # Errors
/// [`Error::Parse`] for bytes that are not WKB, a geometry that is neither a Polygon nor a
/// MultiPolygon, an empty one, or a NaN or infinite coordinate (naming polygon, ring, vertex).
pub fn raw_polygons(bytes: &[u8]) -> Result<Vec<RawPolygon>, Error> {
    let geometry = wkb::reader::read_wkb(bytes)
        .map_err(|e| crate::parse_error(format!("not a valid WKB geometry: {e}")))?;
    let multi = match geometry.as_type() {
        GeometryType::Polygon(p) => geo_types::MultiPolygon::new(vec![p.to_polygon()]),
        GeometryType::MultiPolygon(m) => m.to_multi_polygon(),
        other => {
            let name = match other {
                GeometryType::Point(_) => "Point",
                GeometryType::LineString(_) => "LineString",
                GeometryType::MultiPoint(_) => "MultiPoint",
                GeometryType::MultiLineString(_) => "MultiLineString",
                GeometryType::GeometryCollection(_) => "GeometryCollection",
                _ => "another geometry type",
            };
            return Err(crate::parse_error(format!(
                "expected a Polygon or MultiPolygon, found a {name}"
            )));
        }
    };
    if multi.0.is_empty() || multi.iter().any(|p| p.exterior().0.is_empty()) {
        return Err(crate::parse_error(
            "no polygon found: the geometry is EMPTY".into(),
        ));
    }
    minitri::geo::raw_polygons(&multi)
}
