//! Gathering outcomes into records: one per input feature, for the writers that give one record
//! per feature (`--to geojson`, `geojsonl`, `wkt`, `csv`).
//!
//! Input contract: outcomes in order, the outcomes of one record together: a GeoJSON feature's
//! parts in order (each part, with `--repair`, its pieces in order), or the pieces of one
//! polygon of an input without features. Output guarantee: each record's outcomes, in order, as
//! soon as its last outcome is pushed: the last piece ([`Outcome::pieces`]) of the feature's last
//! part ([`crate::feature::Feature::outcomes`]). A record cut short (a syntax error that stops
//! a FeatureCollection inside a feature) ends when an outcome of another record comes, or at
//! [`Records::finish`]. An outcome about an input as a whole (no feature and no polygon
//! number: an unreadable file, a member of a WKT collection that is not a polygon) is a record
//! of its own.
//!
//! Memory: one record's outcomes.

use crate::outcome::Outcome;
use std::sync::Arc;

/// One outcome with the text a writer made of it ahead ([`super::Sink::renderer`]).
pub type Rendered = (Outcome, Option<String>);

/// Outcomes gathered into the records they belong to.
#[derive(Default)]
pub struct Records {
    pending: Vec<Rendered>,
}

impl Records {
    /// No record begun.
    pub fn new() -> Records {
        Records::default()
    }

    /// Takes the next outcome; calls `write` with each record it completes, in order (the
    /// record before it, when this outcome begins another one, then its own when it is its
    /// last).
    ///
    /// # Errors
    /// The first error of `write`.
    pub fn push<E>(
        &mut self,
        outcome: Outcome,
        rendered: Option<String>,
        mut write: impl FnMut(Vec<Rendered>) -> Result<(), E>,
    ) -> Result<(), E> {
        if let Some((last, _)) = self.pending.last() {
            if !same_record(last, &outcome) {
                write(std::mem::take(&mut self.pending))?;
            }
        }
        let complete = ends_record(&outcome);
        self.pending.push((outcome, rendered));
        if complete {
            write(std::mem::take(&mut self.pending))?;
        }
        Ok(())
    }

    /// The record begun and not completed, if any (at the end of the output).
    pub fn finish(&mut self) -> Option<Vec<Rendered>> {
        (!self.pending.is_empty()).then(|| std::mem::take(&mut self.pending))
    }
}

/// What a record's outcomes add up to: the facts every per-feature output gives.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Summary {
    /// The algorithm, when some outcome was solved.
    pub algorithm: Option<&'static str>,
    /// Triangles and degenerate triangles over the solved outcomes (for `pseudo` and
    /// `pseudo-hull`, those of the plain triangulations they started from).
    pub triangles: usize,
    /// See [`Summary::triangles`].
    pub degenerate: usize,
    /// For `pseudo` and `pseudo-hull`: the pseudotriangles; `None` for a triangulation.
    pub faces: Option<usize>,
    /// Every solved outcome's count is proved minimum (as in the JSON output).
    pub optimal: bool,
    /// The failed outcomes' messages, each prefixed with `part k: ` for a feature of several
    /// parts and `piece k: ` for a piece of a repaired polygon.
    pub errors: Vec<String>,
    /// The feature's parts (1 for an outcome without feature).
    pub parts: usize,
}

impl Summary {
    /// The summary of one record's outcomes.
    pub fn of(record: &[Rendered]) -> Summary {
        let mut summary = Summary {
            algorithm: None,
            triangles: 0,
            degenerate: 0,
            faces: None,
            optimal: true,
            errors: Vec::new(),
            parts: record
                .first()
                .and_then(|(o, _)| o.feature.as_ref())
                .map_or(1, |id| id.feature.outcomes()),
        };
        for (outcome, _) in record {
            match &outcome.result {
                Ok(solved) => {
                    let t = &solved.triangulation;
                    summary.algorithm = Some(t.algorithm.name());
                    summary.triangles += t.triangles.len();
                    summary.degenerate += t.degenerate.len();
                    if let Some(p) = &solved.pseudo {
                        *summary.faces.get_or_insert(0) += p.faces.len();
                        summary.optimal &= p.optimal(); // as in the JSON output
                    } else {
                        summary.optimal &= t.optimal;
                    }
                }
                Err(_) => {
                    let prefix = prefix(outcome);
                    let messages = outcome.error_messages().into_iter();
                    summary
                        .errors
                        .extend(messages.map(|m| format!("{prefix}{m}")));
                }
            }
        }
        summary
    }

    /// Every outcome of the record was solved.
    pub fn ok(&self) -> bool {
        self.errors.is_empty()
    }
}

/// `part k: ` for a part of a feature of several, `piece k: ` for a piece of a repaired
/// polygon, both in that order, or nothing: where in its record an outcome's error is.
fn prefix(outcome: &Outcome) -> String {
    let part = outcome
        .feature
        .as_ref()
        .filter(|id| id.multipart())
        .map(|id| format!("part {}: ", id.part));
    let piece = outcome.piece.map(|k| format!("piece {k}: "));
    part.into_iter().chain(piece).collect()
}

/// Whether `next` continues the record `last` belongs to: the same input feature, or the next
/// piece of the same polygon of an input without features.
fn same_record(last: &Outcome, next: &Outcome) -> bool {
    match (&last.feature, &next.feature) {
        (Some(a), Some(b)) => Arc::ptr_eq(&a.feature, &b.feature),
        (None, None) => {
            last.index.is_some()
                && last.index == next.index
                && last.source == next.source
                && next.piece.is_some_and(|k| k > 0)
        }
        _ => false,
    }
}

/// Whether `outcome` is the last of its record: the last piece of its polygon, and for a
/// feature, of the feature's last part.
fn ends_record(outcome: &Outcome) -> bool {
    let last_piece = outcome.piece.is_none_or(|k| k + 1 >= outcome.pieces);
    let last_part = outcome
        .feature
        .as_ref()
        .is_none_or(|id| id.part + 1 >= id.feature.outcomes());
    last_piece && last_part
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::feature::{Feature, Geometry, Identity};
    use crate::pipeline::{unreadable, Error};

    /// A failed outcome of polygon `index` (piece `piece` of `pieces`), of `feature`'s `part`.
    fn outcome(
        index: Option<usize>,
        piece: Option<usize>,
        pieces: usize,
        feature: Option<(&Arc<Feature>, usize)>,
    ) -> Outcome {
        let mut o = unreadable("s", Error::Read(String::new()));
        o.index = index;
        o.piece = piece;
        o.pieces = pieces;
        o.feature = feature.map(|(f, part)| Identity {
            feature: Arc::clone(f),
            part,
        });
        o
    }

    fn feature(number: usize, parts: usize) -> Arc<Feature> {
        Arc::new(Feature {
            number,
            line: None,
            id: None,
            properties: None,
            geometry: Geometry::Parts(parts),
            collection: None,
        })
    }

    /// The records written for `outcomes`, each as its outcomes' polygon numbers.
    fn records(outcomes: Vec<Outcome>) -> Vec<Vec<Option<usize>>> {
        let mut records = Records::new();
        let mut out = Vec::new();
        for o in outcomes {
            records
                .push(o, None, |r| {
                    out.push(r.iter().map(|(o, _)| o.index).collect());
                    Ok::<(), ()>(())
                })
                .unwrap();
            // Each record is written as soon as it is complete: nothing waits for the next.
        }
        assert!(records.finish().is_none(), "every record was complete");
        out
    }

    #[test]
    fn a_feature_is_one_record_of_its_parts_and_their_pieces() {
        let (a, b) = (feature(0, 2), feature(1, 1));
        let got = records(vec![
            outcome(Some(0), None, 1, Some((&a, 0))),
            outcome(Some(1), Some(0), 2, Some((&a, 1))),
            outcome(Some(1), Some(1), 2, Some((&a, 1))),
            outcome(Some(2), Some(0), 2, Some((&b, 0))),
            outcome(Some(2), Some(1), 2, Some((&b, 0))),
        ]);
        assert_eq!(
            got,
            vec![vec![Some(0), Some(1), Some(1)], vec![Some(2), Some(2)]]
        );
    }

    #[test]
    fn without_features_a_polygon_is_a_record_and_an_input_failure_one_of_its_own() {
        let got = records(vec![
            outcome(Some(0), Some(0), 2, None),
            outcome(Some(0), Some(1), 2, None),
            outcome(None, None, 1, None),
            outcome(Some(1), None, 1, None),
            // The same source given twice: its polygon 1 again is another record.
            outcome(Some(1), None, 1, None),
        ]);
        assert_eq!(
            got,
            vec![
                vec![Some(0), Some(0)],
                vec![None],
                vec![Some(1)],
                vec![Some(1)]
            ]
        );
    }

    #[test]
    fn a_record_cut_short_ends_at_the_next_record_or_at_the_end() {
        let a = feature(0, 3);
        let mut records = Records::new();
        let mut out = Vec::new();
        let mut write = |r: Vec<Rendered>| {
            out.push(r.len());
            Ok::<(), ()>(())
        };
        records
            .push(outcome(Some(0), None, 1, Some((&a, 0))), None, &mut write)
            .unwrap();
        records
            .push(outcome(None, None, 1, None), None, &mut write)
            .unwrap();
        assert_eq!(out, vec![1, 1]);
        records
            .push(outcome(Some(1), None, 1, Some((&a, 1))), None, |_| Err(()))
            .unwrap();
        assert_eq!(records.finish().map(|r| r.len()), Some(1));
    }
}
