//! minitri: polygon triangulation with the minimum number of triangles, exactly.
//!
//! The path is read ([`io::read`]) -> validate ([`Polygon::from_raw`]) -> triangulate
//! ([`algo`]) -> verify ([`verify`]) -> write ([`io::write`]); [`pipeline`] runs it.
#![forbid(unsafe_code)]
#![deny(missing_docs)]
#![deny(rustdoc::broken_intra_doc_links)]

/// Implements `PartialEq`, `Eq` and `PartialOrd` from a type's hand-written `Ord::cmp`, for the
/// sweep-status keys whose order is geometric (`chords`, `validate`, `monotone`).
macro_rules! order_from_cmp {
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

pub mod algo;
pub mod batch;
pub mod geom;
pub mod io;
pub mod pipeline;
#[cfg(test)]
pub(crate) mod test_support;
pub mod verify;

pub use algo::{Algorithm, TriangulateError, Triangulation};
pub use geom::decimal::{Decimal, NumberError};
pub use geom::polygon::{Polygon, Ring, Warning};
pub use geom::validate::InvalidPolygon;
pub use io::read::{Format, ParseError, RawPolygon};
pub use pipeline::{process, solve, triangulate, Error, Options, Outcome};
