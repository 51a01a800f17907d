//! `geo-types` in and out: polygons from [`geo_types::Polygon`] and [`geo_types::MultiPolygon`],
//! triangles out as [`geo_types::Triangle<f64>`] and [`geo_types::MultiPolygon<f64>`].
//!
//! # Exactness
//!
//! The library computes on exact decimals ([`Decimal`]), so each coordinate first becomes one:
//! - integers (`i8` to `i64`, `isize`, `u8` to `u64`, `usize`) exactly;
//! - `f64` and `f32`: the SHORTEST decimal that converts back to the same float, which is what
//!   Rust's `{}` prints: `0.1_f64` is taken as 0.1, not as the binary fraction
//!   0.1000000000000000055511151231257827... it stands for. So a coordinate typed as a literal,
//!   or read from text with `str::parse`, means the number as written, like in the files the
//!   command line reads. NaN and infinities are rejected with [`Error::Parse`] naming the
//!   polygon, ring, vertex and axis.
//!
//! On the way out, each corner is the input vertex's exact decimal rounded to the nearest `f64`;
//! for `f64` input that is the input coordinate itself, bit for bit (the shortest decimal of a
//! float converts back to that float), except that `-0.0` comes out as `0.0`.
//!
//! Rings: geo-types closes every ring (last coordinate = first); the closing coordinate is dropped,
//! so input vertex `k` of a ring is its `k`-th coordinate, numbered over the rings in order
//! (exterior, then interiors), as on the command line (`docs/cli.md`). Any orientation is accepted.
//! A consecutive duplicate vertex is dropped, keeping its number: [`polygon_with_warnings`] says
//! which, and [`Triangulation::input_triangles`] gives triangles in these input numbers.
//!
//! Complexity: linear in the number of coordinates (one shortest-decimal formatting each).

use crate::algo::Triangulation;
use crate::geom::decimal::{Decimal, NumberError};
use crate::geom::polygon::{AnyPolygon, Polygon, Ring, Warning};
use crate::io::read::ParseError;
use crate::outcome::Error;
use crate::raw::RawPolygon;
use geo_types::{Coord, CoordNum, LineString, MultiPolygon, Triangle};

/// A coordinate type taken exactly as a decimal (see the module documentation).
pub trait ExactCoord: CoordNum {
    /// The exact decimal this coordinate stands for.
    ///
    /// # Errors
    /// [`NumberError::NonFinite`] for NaN and infinities.
    fn to_decimal(self) -> Result<Decimal, NumberError>;
}

macro_rules! exact_integer {
    ($($t:ty),*) => {$(
        impl ExactCoord for $t {
            fn to_decimal(self) -> Result<Decimal, NumberError> {
                Decimal::parse(&self.to_string())
            }
        }
    )*};
}
exact_integer!(i8, i16, i32, i64, isize, u8, u16, u32, u64, usize);

macro_rules! shortest_float {
    ($($t:ty),*) => {$(
        impl ExactCoord for $t {
            fn to_decimal(self) -> Result<Decimal, NumberError> {
                if !self.is_finite() {
                    return Err(NumberError::NonFinite(self.to_string()));
                }
                // `{:e}` prints the same shortest round-trip digits as `{}`, without writing out
                // hundreds of zeros for 1e300.
                Decimal::parse(&format!("{self:e}"))
            }
        }
    )*};
}
shortest_float!(f32, f64);

/// One ring as exact decimals, without its closing coordinate.
fn ring<T: ExactCoord>(
    line: &LineString<T>,
    polygon: usize,
    ring: Ring,
) -> Result<Vec<[Decimal; 2]>, Error> {
    let mut coords = &line.0[..];
    if coords.len() > 1 && coords.first() == coords.last() {
        coords = &coords[..coords.len() - 1];
    }
    coords
        .iter()
        .enumerate()
        .map(|(k, c)| {
            let axis = |value: T, name: &str| {
                value.to_decimal().map_err(|e| {
                    Error::Parse(ParseError::new(format!(
                        "polygon {polygon}, {ring}, vertex {k}: {name} coordinate {e}"
                    )))
                })
            };
            Ok([axis(c.x, "x")?, axis(c.y, "y")?])
        })
        .collect()
}

/// Polygon `index` of a multipolygon (0 for a lone polygon) as exact decimals.
fn raw<T: ExactCoord>(polygon: &geo_types::Polygon<T>, index: usize) -> Result<RawPolygon, Error> {
    let mut rings = vec![ring(polygon.exterior(), index, Ring::Outer)?];
    for (h, hole) in polygon.interiors().iter().enumerate() {
        rings.push(ring(hole, index, Ring::Hole(h + 1))?);
    }
    Ok(RawPolygon {
        rings,
        ordinates: None,
    })
}

/// Polygon `index` of a multipolygon as exact decimals, not yet validated (the readers of
/// floating-point formats, WKB, share this path with the geo-types API).
///
/// # Errors
/// [`Error::Parse`] for a NaN or infinite coordinate, naming the polygon, ring and vertex.
pub(crate) fn raw_polygon<T: ExactCoord>(
    polygon: &geo_types::Polygon<T>,
    index: usize,
) -> Result<RawPolygon, Error> {
    raw(polygon, index)
}

/// Validates a polygon on the kernel its coordinates need (duplicate consecutive vertices are
/// dropped silently).
fn valid(raw: &RawPolygon) -> Result<AnyPolygon, Error> {
    AnyPolygon::from_raw_all_errors(raw)
        .map(|(polygon, _warnings)| polygon)
        .map_err(Error::Invalid)
}

/// The validated polygon, as `Polygon::try_from`, with the warnings about what validation
/// changed: each consecutive duplicate vertex dropped (it keeps its input number, which then
/// appears in no triangle), as the command line prints them.
///
/// # Errors
/// [`Error::Parse`] for a NaN or infinite coordinate, [`Error::Invalid`] with every problem of
/// an invalid polygon.
///
/// # Examples
/// ```
/// use geo_types::polygon;
/// let square = polygon![(x: 0, y: 0), (x: 1, y: 0), (x: 1, y: 0), (x: 1, y: 1), (x: 0, y: 1)];
/// let (polygon, warnings) = minitri::geo::polygon_with_warnings(&square)?;
/// assert_eq!((polygon.len(), polygon.input_vertices()), (4, 5));
/// assert_eq!(warnings.len(), 1);
/// assert!(warnings[0].to_string().contains("vertex 2 (1, 0) repeats vertex 1"), "{}", warnings[0]);
/// # Ok::<(), minitri::Error>(())
/// ```
pub fn polygon_with_warnings<T: ExactCoord>(
    polygon: &geo_types::Polygon<T>,
) -> Result<(Polygon, Vec<Warning>), Error> {
    Polygon::from_raw_all_errors(&raw(polygon, 0)?).map_err(Error::Invalid)
}

impl<T: ExactCoord> TryFrom<&geo_types::Polygon<T>> for RawPolygon {
    type Error = Error;

    /// The polygon as exact decimals, not yet validated.
    ///
    /// # Errors
    /// [`Error::Parse`] for a NaN or infinite coordinate.
    fn try_from(polygon: &geo_types::Polygon<T>) -> Result<RawPolygon, Error> {
        raw(polygon, 0)
    }
}

impl<T: ExactCoord> TryFrom<&geo_types::Polygon<T>> for Polygon {
    type Error = Error;

    /// The validated polygon on the fast kernel (consecutive duplicate vertices are dropped, as
    /// [`Polygon::from_raw`] does, without a warning: [`polygon_with_warnings`] returns them).
    ///
    /// # Errors
    /// [`Error::Parse`] for a NaN or infinite coordinate, [`Error::Invalid`] with every problem
    /// of an invalid polygon, or with [`crate::InvalidPolygon::CoordinatesTooLarge`] when its
    /// coordinates need the wide kernel: [`AnyPolygon`] takes every polygon.
    fn try_from(polygon: &geo_types::Polygon<T>) -> Result<Polygon, Error> {
        Polygon::from_raw_all_errors(&raw(polygon, 0)?)
            .map(|(polygon, _warnings)| polygon)
            .map_err(Error::Invalid)
    }
}

impl<T: ExactCoord> TryFrom<&geo_types::Polygon<T>> for AnyPolygon {
    type Error = Error;

    /// The validated polygon on the kernel its coordinates need: any coordinates, e.g. `f64`s
    /// of full precision (consecutive duplicate vertices are dropped without a warning).
    ///
    /// # Errors
    /// [`Error::Parse`] for a NaN or infinite coordinate, [`Error::Invalid`] with every problem
    /// of an invalid polygon.
    fn try_from(polygon: &geo_types::Polygon<T>) -> Result<AnyPolygon, Error> {
        valid(&raw(polygon, 0)?)
    }
}

/// Every polygon of a multipolygon as exact decimals, not yet validated.
///
/// # Errors
/// [`Error::Parse`] for a NaN or infinite coordinate, naming the polygon (from 0).
pub fn raw_polygons<T: ExactCoord>(multi: &MultiPolygon<T>) -> Result<Vec<RawPolygon>, Error> {
    multi.iter().enumerate().map(|(i, p)| raw(p, i)).collect()
}

/// Every polygon of a multipolygon, validated on the kernel its coordinates need, in order: one
/// bad polygon does not stop the others. Each error is [`Error::Parse`] for a NaN or infinite
/// coordinate or [`Error::Invalid`] with every problem of an invalid polygon.
pub fn polygons<T: ExactCoord>(multi: &MultiPolygon<T>) -> Vec<Result<AnyPolygon, Error>> {
    multi
        .iter()
        .enumerate()
        .map(|(i, p)| valid(&raw(p, i)?))
        .collect()
}

/// Each stored vertex as `f64` coordinates: the input decimal, correctly rounded.
fn corners<P: crate::geom::kernel::Coord>(polygon: &Polygon<P>) -> Vec<Coord<f64>> {
    let grid = polygon.grid();
    polygon
        .points()
        .iter()
        .map(|&p| {
            // The exact decimal text parses to the nearest f64; it is always a valid literal.
            let [x, y] = [p.format(grid, 0), p.format(grid, 1)].map(|text| {
                text.parse::<f64>()
                    .unwrap_or_else(|_| Decimal::parse(&text).map_or(f64::NAN, |d| d.to_f64()))
            });
            Coord { x, y }
        })
        .collect()
}

/// The triples of `list` as geo-types triangles; triples with an index out of range are skipped.
fn to_triangles<P: crate::geom::kernel::Coord>(
    polygon: &Polygon<P>,
    list: &[[usize; 3]],
) -> Vec<Triangle<f64>> {
    let at = corners(polygon);
    list.iter()
        .filter_map(|&[a, b, c]| Some(Triangle::new(*at.get(a)?, *at.get(b)?, *at.get(c)?)))
        .collect()
}

/// The triangles of `t`, counter-clockwise, with the input coordinates (see the module
/// documentation for their exactness).
pub fn triangles<P: crate::geom::kernel::Coord>(
    polygon: &Polygon<P>,
    t: &Triangulation,
) -> Vec<Triangle<f64>> {
    to_triangles(polygon, &t.triangles)
}

/// The degenerate triangles `[a, b, c]` of `t` (zero area: `b` lies between `a` and `c`, a
/// T-junction), in that order of corners.
pub fn degenerate<P: crate::geom::kernel::Coord>(
    polygon: &Polygon<P>,
    t: &Triangulation,
) -> Vec<Triangle<f64>> {
    to_triangles(polygon, &t.degenerate)
}

/// The triangles of `t` as one multipolygon of closed counter-clockwise rings, e.g. for WKT or
/// GeoJSON output.
pub fn multi_polygon<P: crate::geom::kernel::Coord>(
    polygon: &Polygon<P>,
    t: &Triangulation,
) -> MultiPolygon<f64> {
    triangles(polygon, t)
        .into_iter()
        .map(|triangle| triangle.to_polygon())
        .collect()
}

impl AnyPolygon {
    /// The triangles of `t` (made for this polygon) with the input coordinates, as [`triangles`].
    pub fn geo_triangles(&self, t: &Triangulation) -> Vec<Triangle<f64>> {
        crate::with_polygon!(self, p => triangles(p, t))
    }

    /// The triangles of `t` as one multipolygon, as [`multi_polygon`].
    pub fn geo_multi_polygon(&self, t: &Triangulation) -> MultiPolygon<f64> {
        crate::with_polygon!(self, p => multi_polygon(p, t))
    }
}
