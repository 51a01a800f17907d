//! WKB in: a Polygon or MultiPolygon (2D; Z and M are dropped) read by the `wkb` crate, its
//! `f64` coordinates taken as their shortest decimals by the library's geo-types path
//! ([`minitri::geo`]), so a float means what Python's `repr` prints for it.

use geo_traits::to_geo::{ToGeoMultiPolygon, ToGeoPolygon};
use geo_traits::{GeometryTrait, GeometryType};
use minitri::pipeline::Error;
use minitri::RawPolygon;

/// One polygon of a WKB geometry: as exact decimals (not yet validated) and its input floats in
/// input numbering (the rings' coordinates in order, each ring's closing one dropped as
/// [`minitri::geo`] drops it).
pub struct WkbPolygon {
    pub raw: RawPolygon,
    pub floats: Vec<[f64; 2]>,
}

/// The polygons of one WKB geometry.
///
/// # Errors
/// [`Error::Parse`] for bytes that are not WKB, a geometry that is neither a Polygon nor a
/// MultiPolygon, an empty one, or a NaN or infinite coordinate (naming polygon, ring, vertex).
pub fn polygons(bytes: &[u8]) -> Result<Vec<WkbPolygon>, Error> {
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
    let raws = minitri::geo::raw_polygons(&multi)?;
    Ok(raws
        .into_iter()
        .zip(&multi)
        .map(|(raw, polygon)| WkbPolygon {
            floats: floats(polygon),
            raw,
        })
        .collect())
}

/// The coordinates of `polygon` in input numbering.
fn floats(polygon: &geo_types::Polygon<f64>) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    for ring in std::iter::once(polygon.exterior()).chain(polygon.interiors()) {
        let mut coords = &ring.0[..];
        // The same closing-coordinate rule as `minitri::geo` (exact equality).
        if coords.len() > 1 && coords.first() == coords.last() {
            coords = &coords[..coords.len() - 1];
        }
        out.extend(coords.iter().map(|c| [c.x, c.y]));
    }
    out
}
