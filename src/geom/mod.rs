//! Exact geometry: decimal numbers, the integer grid, predicates, polygons and their validation.
pub mod decimal;
