//! Exact geometry: decimal numbers, the integer grid, predicates, polygons and their validation.
pub mod decimal;
pub mod kernel;
pub mod polygon;
pub mod repair;
pub(crate) mod stabbing;
pub mod status;
pub(crate) mod touch;
pub mod validate;
pub mod wide;
