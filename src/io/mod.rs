//! Input and output: readers produce [`read::RawPolygon`]s, writers consume results; one table
//! of file extensions serves both (`io/extension.rs`).
pub(crate) mod extension;
pub mod read;
// The writers serve the command line (and the Python package) alone: public (and hidden) with
// `internals`; without it only the extension table reads their formats.
#[cfg(feature = "internals")]
pub mod write;
#[cfg(not(feature = "internals"))]
#[allow(dead_code)]
pub(crate) mod write;
