//! minitri: polygon triangulation with the minimum number of triangles, exactly.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod algo;
pub mod geom;
pub mod io;
pub mod verify;

pub use algo::{Algorithm, Triangulation, TriangulateError};
pub use geom::decimal::{Decimal, NumberError};
pub use geom::polygon::{Polygon, Ring, Warning};
pub use geom::validate::InvalidPolygon;
