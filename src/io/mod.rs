//! Input and output: readers produce [`read::RawPolygon`]s, writers consume results; one table
//! of file extensions serves both (`io/extension.rs`).
pub(crate) mod extension;
pub mod read;
pub mod write;
