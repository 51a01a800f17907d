//! Writers: JSON and SVG.
pub mod svg;
