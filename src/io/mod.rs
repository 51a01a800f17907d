//! Input and output: readers produce [`read::RawPolygon`]s, writers consume results.
pub mod read;
// The writers serve the command line (and the Python package) alone: built with `internals`.
#[cfg(feature = "internals")]
pub mod write;
