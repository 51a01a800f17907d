//! WKB and EWKB in: binary, or hex text as PostGIS prints a geometry (`0103000000...`), one
//! geometry per line.
//!
//! Input contract: the bytes of an OGC WKB geometry (ISO or extended: Z, M and ZM variants, an
//! EWKB SRID; either byte order), or several in a row; or text of one hex-encoded geometry per
//! line (blank lines skipped; an optional `\x` or `0x` before each, as `bytea` values print).
//! The bytes are decoded by the `wkb` crate.
//!
//! Exactness: WKB holds binary doubles, not decimals, so each coordinate is taken as its
//! SHORTEST decimal, the decimal that converts back to the same double (`0.1` stays 0.1, not the
//! binary fraction it stands for), through [`crate::geo`], exactly as the library's geo-types
//! API and the Python package take floats. Z and M values (Z, M and ZM geometries) are kept
//! the same way, each vertex's beside it ([`super::Ordinates`]; a NaN Z or M is "no value").
//! A NaN or infinite x or y, or an infinite Z or M, is an error naming the polygon, ring, vertex
//! and axis.
//!
//! Output guarantee: the polygons of each geometry in input order (a MultiPolygon's polygons, a
//! GeometryCollection's polygons at any depth), each ring without its closing coordinate, as
//! every reader gives them ([`RawPolygon`]); an EMPTY polygon is skipped, as in WKT. Any other
//! geometry type is an error in its place (a member of a collection: a failed part; the other
//! geometries go on). Complexity: linear in the input.

use super::{limits, Dims, Location, Ordinates, ParseError, RawPolygon};
use crate::geo::ExactCoord;
use geo_traits::to_geo::ToGeoPolygon;
use geo_traits::{
    CoordTrait, Dimensions, GeometryCollectionTrait, GeometryTrait, GeometryType, LineStringTrait,
    MultiPolygonTrait, PolygonTrait,
};
use wkb::reader::Wkb;

/// One polygon of a WKB geometry: as exact decimals (not yet validated) and its input floats
/// in input numbering (the rings' coordinates in order, each ring's closing one dropped as
/// [`crate::geo`] drops it).
#[derive(Clone, Debug)]
pub struct WkbPolygon {
    /// The polygon as exact decimals.
    pub raw: RawPolygon,
    /// Its coordinates as read, in input numbering.
    pub floats: Vec<[f64; 2]>,
}

/// The polygons of one binary WKB geometry, a Polygon or a MultiPolygon, with their input
/// floats (the Python package's reader; bytes after the geometry are ignored).
///
/// # Errors
/// [`ParseError`] for bytes that are not WKB, a geometry that is neither a Polygon nor a
/// MultiPolygon, an empty one, or a NaN or infinite coordinate (naming polygon, ring, vertex).
///
/// # Examples
/// ```
/// use minitri::io::read::wkb::polygons;
/// // POLYGON ((0 0, 1 0, 0.1 1, 0 0)), little-endian.
/// let mut wkb = vec![1, 3, 0, 0, 0, 1, 0, 0, 0, 4, 0, 0, 0];
/// for c in [0.0f64, 0.0, 1.0, 0.0, 0.1, 1.0, 0.0, 0.0] {
///     wkb.extend(c.to_le_bytes());
/// }
/// let polygons = polygons(&wkb)?;
/// assert_eq!(polygons[0].raw.rings[0][2][0].to_string(), "0.1");
/// assert_eq!(polygons[0].floats, [[0.0, 0.0], [1.0, 0.0], [0.1, 1.0]]);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn polygons(bytes: &[u8]) -> Result<Vec<WkbPolygon>, ParseError> {
    let geometry = wkb::reader::read_wkb(bytes)
        .map_err(|e| ParseError::new(format!("not a valid WKB geometry: {e}")))?;
    let polygons: Vec<(geo_types::Polygon<f64>, ZmValues)> = match geometry.as_type() {
        GeometryType::Polygon(p) => vec![(p.to_polygon(), ordinates(p, 0))],
        GeometryType::MultiPolygon(m) => m
            .polygons()
            .enumerate()
            .map(|(i, p)| (p.to_polygon(), ordinates(&p, i)))
            .collect(),
        _ => {
            return Err(ParseError::new(format!(
                "expected a Polygon or MultiPolygon, found a {}",
                type_name(&geometry)
            )))
        }
    };
    if polygons.is_empty() || polygons.iter().any(|(p, _)| p.exterior().0.is_empty()) {
        return Err(ParseError::new("no polygon found: the geometry is EMPTY"));
    }
    polygons
        .into_iter()
        .enumerate()
        .map(|(i, (polygon, ordinates))| {
            let mut raw = exact(&polygon, i)?;
            raw.ordinates = ordinates.map_err(ParseError::new)?;
            Ok(WkbPolygon {
                raw,
                floats: floats(&polygon),
            })
        })
        .collect()
}

/// Is `start`, the first bytes of an input, WKB: binary (a byte-order byte, 0 or 1, and a
/// known geometry code) or hex text of it (its first word hex digits, optionally after `\x` or
/// `0x`, encoding such a header)?
///
/// # Examples
/// ```
/// use minitri::io::read::wkb::looks_like_wkb;
/// assert!(looks_like_wkb(b"0103000000010000000400000000"));
/// assert!(looks_like_wkb(b"\n0103000020E6100000010000000400000000"), "EWKB, SRID 4326");
/// assert!(looks_like_wkb(&[0, 0, 0, 0, 3, 0, 0, 0, 1]), "binary, big-endian");
/// assert!(!looks_like_wkb(b"0 0\n1 0\n0 1\n"), "a vertex list");
/// assert!(!looks_like_wkb(b"01234567890123"), "not a geometry code");
/// ```
pub fn looks_like_wkb(start: &[u8]) -> bool {
    if header_is_plausible(start) {
        return true;
    }
    let text = start.trim_ascii_start();
    let text = strip_hex_prefix(text);
    let word = text
        .iter()
        .position(|b| !b.is_ascii_hexdigit())
        .map_or(text, |end| {
            if text[end].is_ascii_whitespace() {
                &text[..end]
            } else {
                &[]
            }
        });
    if word.len() < 18 {
        return false;
    }
    let header: Option<Vec<u8>> = word[..10].chunks(2).map(hex_byte).collect();
    header.is_some_and(|h| header_is_plausible(&h))
}

/// Does `bytes` start with a WKB header: byte order 0 or 1, then a geometry code of the seven
/// OGC types, in the ISO (1000s for Z, M, ZM) or the extended (high flag bits) numbering?
fn header_is_plausible(bytes: &[u8]) -> bool {
    let (Some(&order), Some(code)) = (bytes.first(), bytes.get(1..5)) else {
        return false;
    };
    let code: [u8; 4] = [code[0], code[1], code[2], code[3]];
    let code = match order {
        0 => u32::from_be_bytes(code),
        1 => u32::from_le_bytes(code),
        _ => return false,
    };
    let (flags, base) = (code & 0xF000_0000, code & 0x0FFF_FFFF);
    (1..=7).contains(&(base % 1000)) && base / 1000 <= 3 && (flags == 0 || base < 1000)
}

/// `text` without a leading `\x` or `0x`.
fn strip_hex_prefix(text: &[u8]) -> &[u8] {
    text.strip_prefix(b"\\x")
        .or_else(|| text.strip_prefix(b"0x"))
        .unwrap_or(text)
}

/// The byte two hex digits stand for.
fn hex_byte(pair: &[u8]) -> Option<u8> {
    let digit = |b: u8| (b as char).to_digit(16);
    match pair {
        [high, low] => Some((digit(*high)? * 16 + digit(*low)?) as u8),
        _ => None,
    }
}

/// The EWKB SRID of a binary geometry, if its header has one.
///
/// # Examples
/// ```
/// use minitri::io::read::wkb::srid;
/// assert_eq!(srid(&[1, 3, 0, 0, 0x20, 0xE6, 0x10, 0, 0]), Some(4326));
/// assert_eq!(srid(&[1, 3, 0, 0, 0]), None);
/// ```
pub fn srid(bytes: &[u8]) -> Option<i32> {
    let word = |at: usize| -> Option<[u8; 4]> { bytes.get(at..at + 4)?.try_into().ok() };
    let (code, value) = match bytes.first()? {
        0 => (
            u32::from_be_bytes(word(1)?),
            i32::from_be_bytes(word(5).unwrap_or_default()),
        ),
        1 => (
            u32::from_le_bytes(word(1)?),
            i32::from_le_bytes(word(5).unwrap_or_default()),
        ),
        _ => return None,
    };
    (code & 0x2000_0000 != 0 && word(5).is_some()).then_some(value)
}

/// Does `bytes`, a whole input, hold hex text (or only blanks) rather than binary WKB? (Binary
/// WKB starts with a byte-order byte, 0 or 1, never a printable character.)
fn is_hex_text(bytes: &[u8]) -> bool {
    bytes
        .iter()
        .find(|b| !b.is_ascii_whitespace())
        .is_none_or(|b| b.is_ascii_hexdigit() || *b == b'\\')
}

/// Every part of a WKB input (binary, or hex text one geometry per line), in input order: its
/// polygons, numbered over the whole input, and an error in the place of each geometry or
/// member that is not a polygon, or that is not WKB (a bad hex line; the other lines go on).
/// `max_vertices` caps one polygon (its rings together): past it that polygon is an error.
///
/// Errors are named by where they are: `line 3, column 1: ` (hex) or `byte 77: ` (binary, the
/// geometry's first byte, from 1), then `geometry 1: ` for a member of a collection.
///
/// # Errors
/// An empty input, one holding only EMPTY geometries, and binary bytes that are not WKB (the
/// geometries after them cannot be found).
///
/// # Examples
/// ```
/// use minitri::io::read::wkb::read_parts_within;
/// let text = "0103000000010000000400000000000000000000000000000000000000000000000000F03F0000000000000000000000000000F03F000000000000F03F00000000000000000000000000000000\n\
///             0101000000000000000000F03F000000000000F03F\n";
/// let parts = read_parts_within(text.as_bytes(), 1000)?;
/// assert_eq!(parts[0].as_ref().map(|p| p.rings[0].len()), Ok(3));
/// assert_eq!(parts[1].as_ref().unwrap_err().to_string(),
///            "line 2, column 1: expected a Polygon or MultiPolygon, found a Point");
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts_within(
    bytes: &[u8],
    max_vertices: usize,
) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    read_parts_srid_within(bytes, max_vertices).map(|(parts, _)| parts)
}

/// [`read_parts_within`] with each part's EWKB SRID (`None` without one), in the order of the
/// parts: those of a geometry share its SRID.
///
/// # Errors
/// As [`read_parts_within`].
///
/// # Examples
/// ```
/// use minitri::io::read::wkb::read_parts_srid_within;
/// let hex = b"0103000020E6100000010000000300000000000000000000000000000000000000000000000000F03F00000000000000000000000000000000000000000000F03F\n";
/// let (parts, srids) = read_parts_srid_within(hex, 100)?;
/// assert!(parts[0].is_ok());
/// assert_eq!((parts.len(), srids), (1, vec![Some(4326)]));
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts_srid_within(
    bytes: &[u8],
    max_vertices: usize,
) -> Result<PartsAndSrids, ParseError> {
    let mut srids = Vec::new();
    let mut reading = Reading {
        parts: Vec::new(),
        polygons: 0,
        geometries: 0,
        max_vertices,
    };
    if is_hex_text(bytes) {
        for (k, line) in bytes.split(|&b| b == b'\n').enumerate() {
            let at = |column: usize| Location {
                line: k + 1,
                column,
            };
            let indent = line.len() - line.trim_ascii_start().len();
            let word = line.trim_ascii();
            if word.is_empty() {
                continue;
            }
            let digits = strip_hex_prefix(word);
            let skipped = indent + word.len() - digits.len();
            let decoded = match decode_hex(digits) {
                Ok(decoded) => decoded,
                Err((offset, message)) => {
                    let error = ParseError::at(at(skipped + offset + 1), message);
                    reading.parts.push(Err(error));
                    reading.geometries += 1;
                    continue;
                }
            };
            let place = |message: String| ParseError::at(at(1), message);
            match wkb::reader::read_wkb(&decoded) {
                Ok(geometry) => {
                    let size = size_of(&geometry);
                    reading.geometry(&geometry, &place, &[]);
                    let srid = srid(&decoded).and_then(|s| u32::try_from(s).ok());
                    srids.resize(reading.parts.len(), srid);
                    if size.is_some_and(|s| s < decoded.len()) {
                        let extra = decoded.len() - size.unwrap_or(0);
                        reading.parts.push(Err(place(format!(
                            "{extra} bytes after the geometry (one hex geometry per line)"
                        ))));
                    }
                }
                Err(e) => {
                    reading.geometries += 1;
                    reading
                        .parts
                        .push(Err(place(format!("not a valid WKB geometry: {e}"))));
                }
            }
        }
    } else {
        let mut at = 0;
        while at < bytes.len() {
            let place = |message: String| ParseError::new(format!("byte {}: {message}", at + 1));
            let geometry = wkb::reader::read_wkb(&bytes[at..])
                .map_err(|e| place(format!("not a valid WKB geometry: {e}")))?;
            let Some(size) = size_of(&geometry).filter(|&s| s > 0) else {
                return Err(place("not a valid WKB geometry".into()));
            };
            reading.geometry(&geometry, &place, &[]);
            let srid = srid(&bytes[at..]).and_then(|s| u32::try_from(s).ok());
            srids.resize(reading.parts.len(), srid);
            at += size;
        }
    }
    if reading.parts.is_empty() {
        return Err(ParseError::new(if reading.geometries == 0 {
            "empty input: no polygon found"
        } else {
            "no polygon found: the geometry is EMPTY"
        }));
    }
    srids.resize(reading.parts.len(), None);
    Ok((reading.parts, srids))
}

/// Parts (each a polygon or the error of a member that is not one) and each one's SRID.
pub type PartsAndSrids = (Vec<Result<RawPolygon, ParseError>>, Vec<Option<u32>>);

/// The parts read so far.
struct Reading {
    parts: Vec<Result<RawPolygon, ParseError>>,
    /// Polygons numbered so far (the next one's index).
    polygons: usize,
    /// Top-level geometries met.
    geometries: usize,
    max_vertices: usize,
}

impl Reading {
    /// The parts of `geometry`, at `path` (member numbers) within its top-level geometry;
    /// `place` names where that top-level geometry is.
    fn geometry(&mut self, geometry: &Wkb, place: &dyn Fn(String) -> ParseError, path: &[usize]) {
        if path.is_empty() {
            self.geometries += 1;
        }
        let named = |message: String| {
            let members: String = path.iter().map(|k| format!("geometry {k}: ")).collect();
            place(format!("{members}{message}"))
        };
        match geometry.as_type() {
            GeometryType::Polygon(p) => self.polygon(p, &named),
            GeometryType::MultiPolygon(m) => {
                for p in m.polygons() {
                    self.polygon(p, &named);
                }
            }
            GeometryType::GeometryCollection(c) => {
                for (k, member) in c.geometries().enumerate() {
                    let mut inner = path.to_vec();
                    inner.push(k);
                    self.geometry(member, place, &inner);
                }
            }
            _ => self.parts.push(Err(named(format!(
                "expected a Polygon or MultiPolygon, found a {}",
                type_name(geometry)
            )))),
        }
    }

    /// One polygon: skipped when EMPTY, an error past the vertex cap.
    fn polygon(&mut self, polygon: &wkb::reader::Polygon, named: &dyn Fn(String) -> ParseError) {
        let exterior = polygon.exterior().map_or(0, |r| r.num_coords());
        if exterior == 0 {
            return;
        }
        let index = self.polygons;
        self.polygons += 1;
        let vertices = exterior + polygon.interiors().map(|r| r.num_coords()).sum::<usize>();
        if vertices > self.max_vertices {
            let message = limits::too_many_vertices(self.max_vertices, "one polygon");
            self.parts
                .push(Err(named(format!("polygon {index}: {message}"))));
            return;
        }
        let part = exact(&polygon.to_polygon(), index).and_then(|mut raw| {
            raw.ordinates = ordinates(polygon, index).map_err(ParseError::new)?;
            Ok(raw)
        });
        self.parts.push(part.map_err(|e| named(e.message)));
    }
}

/// The bytes of a geometry (header, EWKB SRID and body), when its type has a known size.
fn size_of(geometry: &Wkb) -> Option<usize> {
    let size = match geometry.as_type() {
        GeometryType::Point(g) => g.size(),
        GeometryType::LineString(g) => g.size(),
        GeometryType::Polygon(g) => g.size(),
        GeometryType::MultiPoint(g) => g.size(),
        GeometryType::MultiLineString(g) => g.size(),
        GeometryType::MultiPolygon(g) => g.size(),
        GeometryType::GeometryCollection(g) => g.size(),
        _ => return None,
    };
    usize::try_from(size).ok()
}

/// The bytes hex `digits` stand for, or the offset of the first fault and why.
fn decode_hex(digits: &[u8]) -> Result<Vec<u8>, (usize, String)> {
    if let Some(bad) = digits.iter().position(|b| !b.is_ascii_hexdigit()) {
        let shown = String::from_utf8_lossy(&digits[bad..]);
        let shown: String = shown.chars().take(1).collect();
        return Err((
            bad,
            format!("`{shown}` is not a hexadecimal digit (one hex WKB geometry per line)"),
        ));
    }
    if digits.len() % 2 == 1 {
        return Err((
            digits.len() - 1,
            format!(
                "an odd number of hexadecimal digits ({}): a byte is cut in half",
                digits.len()
            ),
        ));
    }
    Ok(digits.chunks(2).filter_map(hex_byte).collect())
}

/// The name of a geometry's type, as OGC spells it.
fn type_name(geometry: &Wkb) -> &'static str {
    match geometry.as_type() {
        GeometryType::Point(_) => "Point",
        GeometryType::LineString(_) => "LineString",
        GeometryType::Polygon(_) => "Polygon",
        GeometryType::MultiPoint(_) => "MultiPoint",
        GeometryType::MultiLineString(_) => "MultiLineString",
        GeometryType::MultiPolygon(_) => "MultiPolygon",
        GeometryType::GeometryCollection(_) => "GeometryCollection",
        _ => "another geometry type",
    }
}

/// Polygon `index` as exact decimals (the shortest decimal of each double).
fn exact(polygon: &geo_types::Polygon<f64>, index: usize) -> Result<RawPolygon, ParseError> {
    crate::geo::raw_polygon(polygon, index).map_err(|e| match e {
        crate::outcome::Error::Parse(e) => e,
        other => ParseError::new(other.to_string()),
    })
}

/// A polygon's Z and M values ([`ordinates`]), or why they cannot be read.
type ZmValues = Result<Option<Ordinates>, String>;

/// The Z and M values of polygon `index`'s vertices in input numbering (each ring's closing
/// coordinate dropped as [`crate::geo`] drops it: its x and y equal to the first's), each the
/// shortest decimal of its double, NaN as `None`; `None` for an XY polygon.
///
/// # Errors
/// An infinite Z or M, naming the polygon, ring and vertex.
fn ordinates<P: PolygonTrait<T = f64>>(polygon: &P, index: usize) -> ZmValues {
    let (dims, axes): (Dims, &[(usize, &str)]) = match polygon.dim() {
        Dimensions::Xyz => (Dims::Z, &[(2, "z")]),
        Dimensions::Xym => (Dims::M, &[(2, "m")]),
        Dimensions::Xyzm => (Dims::Zm, &[(2, "z"), (3, "m")]),
        _ => return Ok(None),
    };
    let mut values = Vec::new();
    let rings = polygon.exterior().into_iter().chain(polygon.interiors());
    for (r, ring) in rings.enumerate() {
        let coords: Vec<_> = ring.coords().collect();
        let mut kept = &coords[..];
        if let (Some(first), Some(last), true) = (coords.first(), coords.last(), coords.len() > 1) {
            if first.x() == last.x() && first.y() == last.y() {
                kept = &coords[..coords.len() - 1];
            }
        }
        for (k, c) in kept.iter().enumerate() {
            for &(n, axis) in axes {
                let value = c.nth(n).unwrap_or(f64::NAN);
                if value.is_nan() {
                    values.push(None);
                    continue;
                }
                let decimal = value.to_decimal().map_err(|e| {
                    let ring = crate::geom::polygon::Ring::from_index(r);
                    format!("polygon {index}, {ring}, vertex {k}: {axis} coordinate {e}")
                })?;
                values.push(Some(decimal));
            }
        }
    }
    Ok(Some(Ordinates { dims, values }))
}

/// The coordinates of `polygon` in input numbering.
fn floats(polygon: &geo_types::Polygon<f64>) -> Vec<[f64; 2]> {
    let mut out = Vec::new();
    for ring in std::iter::once(polygon.exterior()).chain(polygon.interiors()) {
        let mut coords = &ring.0[..];
        // The same closing-coordinate rule as `crate::geo` (exact equality).
        if coords.len() > 1 && coords.first() == coords.last() {
            coords = &coords[..coords.len() - 1];
        }
        out.extend(coords.iter().map(|c| [c.x, c.y]));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// POLYGON ((0 0, 4 0, 0.1 3, 0 0)) as little-endian WKB, with `code` as its type.
    fn triangle(code: u32, srid: Option<i32>) -> Vec<u8> {
        let mut out = vec![1];
        out.extend(code.to_le_bytes());
        if let Some(srid) = srid {
            out.extend(srid.to_le_bytes());
        }
        out.extend(1u32.to_le_bytes());
        out.extend(4u32.to_le_bytes());
        for c in [0.0f64, 0.0, 4.0, 0.0, 0.1, 3.0, 0.0, 0.0] {
            out.extend(c.to_le_bytes());
        }
        out
    }

    fn hex(bytes: &[u8]) -> String {
        bytes.iter().map(|b| format!("{b:02X}")).collect()
    }

    #[test]
    fn binary_hex_and_ewkb_read_alike_with_shortest_decimals() {
        let plain = triangle(3, None);
        let ewkb = triangle(0x2000_0003, Some(4326));
        for input in [
            plain.clone(),
            ewkb.clone(),
            hex(&plain).into_bytes(),
            format!("  \\x{}\r\n\n", hex(&ewkb).to_lowercase()).into_bytes(),
        ] {
            assert!(looks_like_wkb(&input));
            let parts = read_parts_within(&input, 100).unwrap();
            assert_eq!(parts.len(), 1);
            let ring = &parts[0].as_ref().unwrap().rings[0];
            let text: Vec<String> = ring.iter().flatten().map(|d| d.to_string()).collect();
            assert_eq!(text, ["0", "0", "4", "0", "0.1", "3"]);
        }
        assert_eq!(srid(&ewkb), Some(4326));
        assert_eq!(srid(&plain), None);
    }

    #[test]
    fn binary_geometries_in_a_row_are_numbered_on() {
        let mut two = triangle(3, None);
        two.extend(triangle(3, None));
        let parts = read_parts_within(&two, 100).unwrap();
        assert_eq!(parts.len(), 2);
        // Cut short: the second one cannot be read, and nothing after it could be found.
        let error = read_parts_within(&two[..two.len() - 3], 100).unwrap_err();
        assert!(
            error.to_string().starts_with(&format!(
                "byte {}: not a valid WKB geometry",
                two.len() / 2 + 1
            )),
            "{error}"
        );
    }

    #[test]
    fn bad_lines_are_named_and_the_others_go_on() {
        let good = hex(&triangle(3, None));
        let text = format!("{good}\n{}zz\n{}\n{good}00\n", &good[..10], &good[..11]);
        let parts = read_parts_within(text.as_bytes(), 100).unwrap();
        let errors: Vec<String> = parts
            .iter()
            .filter_map(|p| p.as_ref().err().map(ToString::to_string))
            .collect();
        assert_eq!(
            errors,
            [
                "line 2, column 11: `z` is not a hexadecimal digit (one hex WKB geometry per line)",
                "line 3, column 11: an odd number of hexadecimal digits (11): a byte is cut in half",
                "line 4, column 1: 1 bytes after the geometry (one hex geometry per line)",
            ]
        );
        assert_eq!(parts.iter().filter(|p| p.is_ok()).count(), 2);
    }

    #[test]
    fn caps_empties_and_non_finite_numbers() {
        let error = read_parts_within(&triangle(3, None), 2).unwrap()[0]
            .clone()
            .unwrap_err();
        assert!(
            error
                .to_string()
                .starts_with("byte 1: polygon 0: too many vertices: more than 2 in one polygon"),
            "{error}"
        );
        // POLYGON EMPTY: no ring.
        let mut empty = vec![1];
        empty.extend(3u32.to_le_bytes());
        empty.extend(0u32.to_le_bytes());
        assert_eq!(
            read_parts_within(&empty, 10).unwrap_err().to_string(),
            "no polygon found: the geometry is EMPTY"
        );
        assert_eq!(
            read_parts_within(b" \n", 10).unwrap_err().to_string(),
            "empty input: no polygon found"
        );
        let mut nan = triangle(3, None);
        let at = nan.len() - 16 - 16;
        nan[at..at + 8].copy_from_slice(&f64::NAN.to_le_bytes());
        let error = read_parts_within(&nan, 10).unwrap()[0].clone().unwrap_err();
        assert!(
            error
                .to_string()
                .starts_with("byte 1: polygon 0, outer ring, vertex 2: x coordinate"),
            "{error}"
        );
    }
}
