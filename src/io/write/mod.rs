//! Writers: JSON and SVG.
