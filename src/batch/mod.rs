//! Batches: many inputs, many polygons, in parallel, with outputs in input order.
//!
//! Input contract: paths (files, directories, `-` for standard input) and [`Settings`]. Output
//! guarantee: one document of every input ([`run_document`]) or one output file per input
//! mirroring the input tree (`run_tree` with `plan`), byte for byte the same for any number
//! of threads; every failure an outcome naming its source and polygon, never a stop; output files
//! written whole or not at all ([`AtomicFile`]). Parallelism: rayon, on the pool the caller
//! installs (`ThreadPool::install`), across polygons and, for a tree, across files. Memory: one
//! chunk of polygons at a time per input being read, GeoJSON streamed feature by feature (see
//! [`run`]). Complexity: that of the polygons' triangulations, plus linear reading and writing.
//!
//! The steps, in order: `discover` the input files, `plan` their outputs (for a tree),
//! [`run_document`] or [`run_tree`], and [`Tally::summary`] for the summary line.

mod atomic;
mod dir;
mod discover;
mod guard;
mod plan;
pub mod run;
mod tally;

pub use atomic::{exit_removing_temporaries, write_atomically, AtomicFile};
pub use discover::{discover, discover_counting, Input, Unreadable, EXTENSIONS};
#[cfg(unix)]
pub use guard::file_id_of;
pub use guard::{file_id, input_that_is, same_file, FileId};
pub use plan::plan;
pub use run::{run_document, run_tree, DocumentReport, Observer, Settings, Silent, TreeJob};
pub use tally::{Summary, Tally};
