//! What happened to one polygon: its [`Outcome`] (the validated polygon, the triangulation or
//! the [`Error`] naming what is wrong, the warnings, where it came from), what the pipeline
//! makes and the writers consume. Below both: the writers depend on this module, never on the
//! pipeline that reads and solves.

use crate::algo::{Pseudotriangulation, TriangulateError, Triangulation};
use crate::feature::Identity;
use crate::geom::polygon::{AnyPolygon, Warning};
use crate::geom::repair::Repair;
use crate::geom::validate::InvalidPolygon;
use crate::raw::{Ordinates, ParseError};
use crate::verify::Check;
use serde::Serialize;
use std::fmt;

/// Any error of the library, naming what is wrong.
#[derive(Clone, Debug, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// The input could not be read.
    #[error(transparent)]
    Parse(#[from] ParseError),
    /// The polygon is not valid (all problems found).
    #[error("{}", .0.iter().map(ToString::to_string).collect::<Vec<_>>().join("; "))]
    Invalid(Vec<InvalidPolygon>),
    /// The algorithm cannot triangulate this polygon.
    #[error(transparent)]
    Triangulate(#[from] TriangulateError),
    /// The input could not be read from its file or stream.
    #[error("cannot read: {0}")]
    Read(String),
    /// The input was not read, and why, in full (`cannot read: Permission denied`, `skipped: a
    /// FIFO, not a regular file ...`): what a directory walk reports.
    #[error("{0}")]
    NotRead(String),
    /// Even the least memory a polygon of this size needs could not be had.
    #[error("not enough memory: {n} vertices need at least {memory} to be validated and triangulated, and a reservation of that much failed")]
    OutOfMemory {
        /// The polygon's number of vertices, as read.
        n: usize,
        /// The memory reserved, in words.
        memory: String,
    },
}

impl Error {
    /// Each problem as its own message (an invalid polygon may have several).
    pub fn messages(&self) -> Vec<String> {
        match self {
            Error::Invalid(errors) => errors.iter().map(ToString::to_string).collect(),
            other => vec![other.to_string()],
        }
    }
}

/// The result of checking one polygon's triangulations (`--verify`).
#[derive(Clone, Debug, Serialize)]
pub struct Verification {
    /// Every check passed and every exact algorithm gave the same count.
    pub ok: bool,
    /// One independent check per algorithm run (none for a pseudotriangulation).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub checks: Vec<AlgorithmCheck>,
    /// For `pseudo` and `pseudo-hull`: the independent check of the pseudotriangulation.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub pseudotriangulation: Option<Check>,
    /// How the exact algorithms disagree, if they do.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub disagreement: Option<String>,
    /// Exact algorithms that could not run on this polygon, and why.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub skipped: Vec<String>,
}

/// One algorithm's output, checked.
#[derive(Clone, Debug, Serialize)]
pub struct AlgorithmCheck {
    /// The algorithm.
    pub algorithm: &'static str,
    /// Its number of triangles.
    pub triangle_count: usize,
    /// Its number of degenerate triangles used.
    pub degenerate_count: usize,
    /// The independent checker's verdict.
    #[serde(flatten)]
    pub check: Check,
    /// The output checked (for drawing it; not serialised).
    #[serde(skip)]
    pub triangulation: Triangulation,
}

/// A triangulated polygon.
#[derive(Clone, Debug)]
pub struct Solved {
    /// The triangulation by the chosen algorithm; for `pseudo`, the plain triangulation it
    /// started from; for `pseudo-hull`, the polygon's plain triangulation (not part of its
    /// answer).
    pub triangulation: Triangulation,
    /// For `pseudo` and `pseudo-hull`: the answer.
    pub pseudo: Option<Pseudotriangulation>,
    /// The verification report, with `--verify`.
    pub verification: Option<Verification>,
}

/// What happened to one polygon (or to an input that could not be read).
#[derive(Clone, Debug)]
pub struct Outcome {
    /// The source name (`-` for standard input).
    pub source: String,
    /// The polygon's position in its source; `None` when the source could not be read.
    pub index: Option<usize>,
    /// With `--repair`, when the polygon was split into several: this piece's position among
    /// them (from 0).
    pub piece: Option<usize>,
    /// How many outcomes the polygon gave: with `--repair`, the pieces it was split into; 1
    /// otherwise. With [`Outcome::piece`], it tells the writers which piece is the polygon's
    /// last (so that a feature's line or Feature is written as soon as it is complete).
    pub pieces: usize,
    /// The validated polygon, when it is valid (on the kernel chosen for it).
    pub polygon: Option<AnyPolygon>,
    /// The triangulation, or what went wrong.
    pub result: Result<Solved, Error>,
    /// What the tool changed in the input (dropped duplicate vertices). For a polygon split into
    /// pieces by `--repair`, the warnings about the input polygon are its first piece's.
    pub warnings: Vec<Warning>,
    /// With `--repair`: what was repaired in the input polygon, listed once, with its first
    /// piece (piece 0, or the only outcome); the later pieces of a polygon split in several
    /// have an empty list (their repairs are piece 0's); `None` without `--repair`.
    pub repaired: Option<Vec<Repair>>,
    /// The input feature and part this outcome is (GeoJSON inputs; see [`Identity`]).
    pub feature: Option<Identity>,
    /// The SRID its input gave it (EWKT `SRID=4326;`, an EWKB header's), which `--to wkt`
    /// writes back as EWKT and `--to geojson` as a `crs`.
    pub srid: Option<u32>,
    /// The Z and M values of the input polygon's vertices, by input vertex number, when its
    /// positions had them: the writers give each output vertex its input vertex's values.
    pub ordinates: Option<std::sync::Arc<Ordinates>>,
}

impl Outcome {
    /// The lines to show a user about this outcome, in order: each warning (unless `quiet`) as
    /// `warning: source: polygon 2: ...`, then each error as `source: polygon 2: ...`.
    pub fn messages(&self, quiet: bool) -> Vec<String> {
        let mut lines = Vec::new();
        if !quiet {
            for warning in &self.warnings {
                lines.push(format!("warning: {self}: {warning}"));
            }
            // Once for a polygon split into pieces, before its first piece's other messages,
            // naming the polygon (or feature) as read, without the piece.
            if self.piece.unwrap_or(0) == 0 {
                let polygon = self.label(false);
                for repair in self.repaired.iter().flatten() {
                    lines.push(format!("warning: {polygon}: repaired: {repair}"));
                }
            }
        }
        for message in self.error_messages() {
            lines.push(format!("{self}: {message}"));
        }
        lines
    }

    /// The messages of this outcome's error (none when it succeeded), one per problem. With
    /// `--repair` (`repaired` is `Some`), a hint that `--repair` would mend the problem is
    /// replaced by the fact that it did not: `...; --repair splits it there` becomes `...
    /// (not mended by --repair)`.
    pub fn error_messages(&self) -> Vec<String> {
        let Err(e) = &self.result else {
            return Vec::new();
        };
        let mut messages = e.messages();
        if self.repaired.is_some() {
            for message in &mut messages {
                if let Some(at) = message.find("; --repair ") {
                    message.truncate(at);
                    message.push_str(" (not mended by --repair)");
                }
            }
        }
        messages
    }

    /// [`Outcome::error_messages`] joined by `; `, as one line (the JSON's `errors`).
    pub fn error_message(&self) -> Option<String> {
        self.result
            .is_err()
            .then(|| self.error_messages().join("; "))
    }
}

impl fmt::Display for Outcome {
    /// `source: polygon 2` (or `source: feature 3`, `source: feature 3, part 1` for a
    /// GeoJSON feature, `source: line 4` for a line of GeoJSON Lines; ` piece 1` added for a
    /// piece of a polygon split by `--repair`) as a prefix for messages about this outcome. A
    /// failure to read names its feature or line in its own message.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.label(true))
    }
}

impl Outcome {
    /// The name of [`Outcome`]'s `Display`, with or without ` piece k`.
    fn label(&self, with_piece: bool) -> String {
        let mut label = match (self.index, &self.feature) {
            (Some(_), Some(id)) => {
                // GeoJSON Lines: by line, as their reading errors are.
                let mut label = match id.feature.line {
                    Some(line) => format!("{}: line {line}", self.source),
                    None => format!("{}: feature {}", self.source, id.feature.number),
                };
                if id.multipart() {
                    label.push_str(&format!(", part {}", id.part));
                }
                label
            }
            (Some(i), None) => format!("{}: polygon {i}", self.source),
            (None, _) => return self.source.clone(),
        };
        if let Some(k) = self.piece.filter(|_| with_piece) {
            label.push_str(&format!(" piece {k}"));
        }
        label
    }
}
