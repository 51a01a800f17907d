//! minitri: polygon triangulation with the minimum number of triangles, exactly.
//!
//! The path is read ([`read`]) -> validate ([`Polygon::from_raw`]) -> triangulate
//! ([`triangulate`], [`pseudotriangulate`]) -> verify ([`verify`]); [`process`] runs it on text
//! and [`solve`] on a polygon, as [`Options`] say.
//!
//! # Library use
//!
//! Build a [`Polygon`] (from a [`geo_types::Polygon`], see [`geo`] for how coordinates are taken
//! exactly, or from text with [`read`]), then [`triangulate`] it with a [`Triangulator`] (or
//! [`pseudotriangulate`] it with a [`Pseudotriangulator`]). No public function panics, whatever
//! the input: a polygon that is not valid, or an algorithm that does not apply, is an error. A vertex lying inside
//! a triangle side (a T-junction, listed as a degenerate triangle) saves one triangle, so
//! `triangles = n + 2w - 2 - d` for `n` vertices, `w` holes and `d` degenerate triangles.
//!
//! ```
//! use geo_types::polygon;
//! use minitri::{Polygon, Triangulator};
//!
//! // A U: a 3 x 1 bar with two 1 x 1 arms; 12 vertices, 4 of them flat (on a straight side).
//! let u = polygon![
//!     (x: 0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 2.0, y: 0.0), (x: 3.0, y: 0.0),
//!     (x: 3.0, y: 1.0), (x: 3.0, y: 2.0), (x: 2.0, y: 2.0), (x: 2.0, y: 1.0),
//!     (x: 1.0, y: 1.0), (x: 1.0, y: 2.0), (x: 0.0, y: 2.0), (x: 0.0, y: 1.0),
//! ];
//! let polygon = Polygon::try_from(&u)?;
//! assert_eq!((polygon.len(), polygon.holes()), (12, 0));
//!
//! let t = minitri::triangulate(&polygon, Triangulator::Minitri)?;
//! // Every T-junction saves a triangle: n + 2w - 2 - d.
//! assert_eq!(t.triangles.len(), 12 + 0 - 2 - t.degenerate.len());
//! // 5 is the minimum: 5 T-junctions; the O(n^3) dynamic program finds the same count.
//! assert_eq!((t.triangles.len(), t.degenerate.len()), (5, 5));
//! assert!(t.optimal);
//! assert_eq!(minitri::triangulate(&polygon, Triangulator::Asano)?.triangles.len(), 5);
//! // The independent checker accepts it.
//! assert!(minitri::verify::check(&polygon, &t).valid);
//!
//! // Out as geo-types, with the input coordinates: 5 triangles covering the U's area, 5.
//! let triangles = minitri::geo::triangles(&polygon, &t);
//! let area: f64 = triangles.iter().map(|t| t.to_polygon().exterior().0.windows(2)
//!     .map(|w| w[0].x * w[1].y - w[1].x * w[0].y).sum::<f64>() / 2.0).sum();
//! assert_eq!((triangles.len(), area), (5, 5.0));
//! # Ok::<(), minitri::Error>(())
//! ```
//!
//! Coordinates are the decimals as written: `(0.1, 0.3)` lies exactly on the segment from
//! `(0, 0)` to `(0.2, 0.6)`, although not in binary floating point, so this quadrilateral needs
//! only 1 triangle.
//!
//! ```
//! use geo_types::polygon;
//! let quad = polygon![(x: 0.0, y: 0.0), (x: 0.1, y: 0.3), (x: 0.2, y: 0.6), (x: 0.0, y: 1.0)];
//! let polygon = minitri::Polygon::try_from(&quad)?;
//! let t = minitri::triangulate(&polygon, minitri::Triangulator::Minitri)?;
//! assert_eq!((t.triangles.len(), t.degenerate.len()), (1, 1));
//! // The degenerate triangle, out as geo-types: (0.1, 0.3) is its middle corner, bit for bit.
//! let [_, b, _] = minitri::geo::degenerate(&polygon, &t)[0].to_array();
//! assert_eq!((b.x, b.y), (0.1, 0.3));
//! // NaN is refused with a message naming the place.
//! let bad = polygon![(x: 0.0, y: 0.0), (x: f64::NAN, y: 0.0), (x: 0.0, y: 1.0)];
//! let error = minitri::Polygon::try_from(&bad).unwrap_err();
//! assert_eq!(error.to_string(), "polygon 0, outer ring, vertex 1: x coordinate `NaN` is not a finite number");
//! # Ok::<(), minitri::Error>(())
//! ```
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]

/// Implements `PartialEq`, `Eq` and `PartialOrd` from a type's hand-written `Ord::cmp`, for the
/// sweep-status keys whose order is geometric (`chords`, `validate`, `monotone`).
macro_rules! order_from_cmp {
    ($t:ident<$p:ident>) => {
        impl<$p: crate::geom::kernel::Coord> PartialEq for $t<$p> {
            fn eq(&self, other: &Self) -> bool {
                self.cmp(other) == std::cmp::Ordering::Equal
            }
        }
        impl<$p: crate::geom::kernel::Coord> Eq for $t<$p> {}
        impl<$p: crate::geom::kernel::Coord> PartialOrd for $t<$p> {
            fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
                Some(self.cmp(other))
            }
        }
    };
    ($t:ty) => {
        impl PartialEq for $t {
            fn eq(&self, other: &Self) -> bool {
                self.cmp(other) == std::cmp::Ordering::Equal
            }
        }
        impl Eq for $t {}
        impl PartialOrd for $t {
            fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
                Some(self.cmp(other))
            }
        }
    };
}

/// Declares internal modules: crate-private, or, with the `internals` feature, public but hidden
/// from the documentation, for the command line, the integration tests, the benchmarks and the
/// fuzz targets, which reach below the curated API. They are no API: nothing under them is stable
/// (docs/library.md). Without the feature, what only those use is dead code here.
macro_rules! internal {
    ($($name:ident),*) => {$(
        #[cfg(feature = "internals")]
        #[doc(hidden)]
        pub mod $name;
        #[cfg(not(feature = "internals"))]
        #[allow(dead_code)]
        pub(crate) mod $name;
    )*};
}

internal!(algo, feature, io, pipeline);
// `batch` serves the command line alone: a library build without the feature does not compile
// it.
#[cfg(feature = "internals")]
#[doc(hidden)]
pub mod batch;
pub mod geo;
// As `internal!` would declare it; written out, since a `#[macro_export]` macro (`with_polygon!`,
// in `geom/polygon.rs`) inside a macro-expanded module could not be named by path.
#[cfg(feature = "internals")]
#[doc(hidden)]
pub mod geom;
#[cfg(not(feature = "internals"))]
#[allow(dead_code)]
pub(crate) mod geom;
mod outcome;
mod raw;
#[cfg(test)]
pub(crate) mod test_support;
pub mod verify;

pub use algo::{
    Algorithm, HullCounts, Pseudotriangle, Pseudotriangulation, Pseudotriangulator, Stopped,
    TriangulateError, Triangulation, Triangulator,
};
pub use feature::{Collection, Feature, Geometry as FeatureGeometry, Identity};
pub use geom::decimal::{Decimal, NumberError};
pub use geom::kernel::{Coord, Point, SegmentContact};
pub use geom::polygon::{AnyPolygon, Grid, Polygon, Ring, Warning};
pub use geom::repair::{Repair, RepairKind};
pub use geom::validate::{EdgeContact, InvalidPolygon};
pub use geom::wide::WidePoint;
pub use io::read::{read, read_parts, Dims, Format, Location, Ordinate, Ordinates, ParseError};
pub use pipeline::{
    process, process_raw, pseudotriangulate, solve, triangulate, triangulate_with, AlgorithmCheck,
    Error, Options, Outcome, Solved, Verification,
};
pub use raw::RawPolygon;
