//! Input and output: readers produce [`read::RawPolygon`]s, writers consume results.
pub mod read;
pub mod write;
