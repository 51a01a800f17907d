//! minitri: polygon triangulation with the minimum number of triangles, exactly.
//!
//! The path is read ([`io::read`]) -> validate ([`Polygon::from_raw`]) -> triangulate
//! ([`algo`]) -> verify ([`verify`]) -> write ([`io::write`]); [`pipeline`] runs it.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod algo;
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
