//! minitri: polygon triangulation with the minimum number of triangles, exactly.
#![forbid(unsafe_code)]
#![deny(missing_docs)]

pub mod geom;
pub mod io;

pub use geom::decimal::{Decimal, NumberError};
