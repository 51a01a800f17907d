//! Writers: JSON and SVG. They consume results and never call algorithms.
pub mod json;
pub mod svg;
