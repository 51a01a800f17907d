//! Counting a run: files, polygons, triangles, triangles saved, errors; and the summary line.

use crate::pipeline::Outcome;
use std::fmt;
use std::time::Duration;

/// What a run (or one input of it) did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    /// Input files (or standard input) processed, whether or not they could be read.
    pub files: usize,
    /// Polygons read (valid or not).
    pub polygons: usize,
    /// Polygons triangulated.
    pub solved: usize,
    /// Triangles of the triangulated polygons.
    pub triangles: usize,
    /// Pseudotriangles of the polygons pseudotriangulated (`pseudo`, `pseudo-hull`; their
    /// triangles are not counted above).
    pub pseudotriangles: usize,
    /// Over the triangulated polygons, the sum of (n + 2w - 2) - triangles: what the minimum
    /// saves against any plain triangulation.
    pub saved: usize,
    /// Error lines reported: one per problem of a polygon that could not be triangulated (an
    /// invalid polygon may have several), per input (or part) that could not be read, per output
    /// that could not be written.
    pub errors: usize,
    /// Files of directory inputs skipped because their names end in no input format's extension.
    pub skipped: usize,
    /// Triangulated polygons whose `--verify` report is not ok.
    pub verify_failures: usize,
}

impl Tally {
    /// Counts one outcome.
    pub fn add(&mut self, outcome: &Outcome) {
        if outcome.index.is_some() {
            self.polygons += 1;
        }
        match (&outcome.result, &outcome.polygon) {
            (Ok(solved), Some(polygon)) => {
                self.solved += 1;
                if let Some(p) = &solved.pseudo {
                    self.pseudotriangles += p.faces.len();
                } else {
                    let count = solved.triangulation.triangles.len();
                    self.triangles += count;
                    let plain = (polygon.len() + 2 * polygon.holes()).saturating_sub(2);
                    self.saved += plain.saturating_sub(count);
                }
                if solved.verification.as_ref().is_some_and(|v| !v.ok) {
                    self.verify_failures += 1;
                }
            }
            (Ok(_), None) => {}
            (Err(e), _) => self.errors += e.messages().len().max(1),
        }
    }

    /// Adds another tally to this one.
    pub fn merge(&mut self, other: &Tally) {
        self.files += other.files;
        self.polygons += other.polygons;
        self.solved += other.solved;
        self.triangles += other.triangles;
        self.pseudotriangles += other.pseudotriangles;
        self.saved += other.saved;
        self.errors += other.errors;
        self.skipped += other.skipped;
        self.verify_failures += other.verify_failures;
    }

    /// The summary line of a run that took `elapsed`.
    pub fn summary(&self, elapsed: Duration) -> Summary {
        Summary {
            tally: *self,
            elapsed,
        }
    }
}

/// The summary line: `3 files, 120 polygons triangulated, 1402 triangles (318 saved against
/// n + 2w - 2), 2 errors, 0.41 s`, with `(1 skipped: ...)` after the files when a directory held
/// files of no input format. The polygons are those triangulated (not those rejected), the
/// errors are the error lines printed.
#[derive(Clone, Copy, Debug)]
pub struct Summary {
    tally: Tally,
    elapsed: Duration,
}

impl fmt::Display for Summary {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let t = &self.tally;
        let plural = |n: usize, word: &str| format!("{n} {word}{}", if n == 1 { "" } else { "s" });
        write!(f, "{}", plural(t.files, "file"))?;
        if t.skipped > 0 {
            write!(f, " ({} skipped: no input format's extension)", t.skipped)?;
        }
        let done = if t.triangles == 0 && t.pseudotriangles > 0 {
            "pseudotriangulated"
        } else {
            "triangulated"
        };
        write!(f, ", {} {done}, ", plural(t.solved, "polygon"))?;
        if t.triangles > 0 || t.pseudotriangles == 0 {
            write!(
                f,
                "{} ({} saved against n + 2w - 2), ",
                plural(t.triangles, "triangle"),
                t.saved
            )?;
        }
        if t.pseudotriangles > 0 {
            write!(f, "{}, ", plural(t.pseudotriangles, "pseudotriangle"))?;
        }
        write!(f, "{}", plural(t.errors, "error"))?;
        if t.verify_failures > 0 {
            write!(f, ", {}", plural(t.verify_failures, "verification failure"))?;
        }
        write!(f, ", {:.2} s", self.elapsed.as_secs_f64())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_summary_line_names_every_count() {
        let tally = Tally {
            files: 3,
            polygons: 1,
            solved: 1,
            triangles: 5,
            pseudotriangles: 0,
            saved: 5,
            errors: 2,
            skipped: 0,
            verify_failures: 0,
        };
        assert_eq!(
            tally.summary(Duration::from_millis(1234)).to_string(),
            "3 files, 1 polygon triangulated, 5 triangles (5 saved against n + 2w - 2), 2 errors, 1.23 s"
        );
        let skipping = Tally {
            skipped: 4,
            ..tally
        };
        assert_eq!(
            skipping.summary(Duration::from_millis(1234)).to_string(),
            "3 files (4 skipped: no input format's extension), 1 polygon triangulated, \
             5 triangles (5 saved against n + 2w - 2), 2 errors, 1.23 s"
        );
        let pseudo = Tally {
            triangles: 0,
            saved: 0,
            pseudotriangles: 4,
            ..tally
        };
        assert_eq!(
            pseudo.summary(Duration::from_millis(10)).to_string(),
            "3 files, 1 polygon pseudotriangulated, 4 pseudotriangles, 2 errors, 0.01 s"
        );
    }
}
