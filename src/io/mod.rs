//! Input and output: readers produce [`read::RawPolygon`]s, writers consume results; one table
//! of file extensions serves both (`io/extension.rs`).
pub(crate) mod extension;
pub mod read;
// The writers serve the command line (and the Python package) alone: a library build without
// the `internals` feature does not compile them (the extension table holds their formats).
#[cfg(feature = "internals")]
pub mod write;
