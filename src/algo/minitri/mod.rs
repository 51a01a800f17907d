//! Algorithm MINITRI: the minimum triangulation of a polygon without holes.
//!
//! C. Chen and R.-C. Chang, "On the minimality of polygon triangulation", *BIT* 30 (1990)
//! 570-582, §3.
//!
//! The minimum number of triangles is `n - 2 - d`, `d` the size of a maximum set of mutually
//! independent minimally degenerate triangles (Theorem 2). Departures from the paper: flat
//! vertices are allowed (each is the middle of the degenerate triangle formed with its two
//! neighbours), and collinear runs of any length.
//!
//! # Overview
//! 1. [`degenerate`]: all minimally degenerate triangles, of types (i), (ii), (iii) and flat.
//! 2. [`circle`]: the circular representation C(P), endpoints at a shared vertex ordered by angle.
//! 3. [`mis`]: a maximum independent set, by the circle-graph recurrence extended to 3b-chains
//!    (Algorithm MISMDT).
//! 4. and 5. [`partition`]: cut P along the chosen triangles and triangulate every piece.

pub mod branch_and_bound;
pub mod chains;
pub mod circle;
pub mod cut;
pub mod degenerate;
pub mod dependency;
pub mod expansion;
pub mod ladder;
pub mod lists;
pub(crate) mod local_search;
pub mod mis;
pub mod partition;
pub mod polygon_cutting;
pub mod ray_shooting;
pub mod small;
mod staircase;

use super::plain::Premade;
use super::{Algorithm, Stopped, TriangulateError, Triangulation};
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use std::time::{Duration, Instant};

/// How long the exact method may run on one polygon by default (`--time-limit`): step 1
/// without holes, every stage of the search with holes or touching rings.
pub const DEFAULT_TIME_LIMIT: Duration = Duration::from_secs(10);

/// The minimum triangulation of a polygon, with the default time limit
/// ([`DEFAULT_TIME_LIMIT`], [`triangulate_within`]).
///
/// # Errors
/// Those of [`triangulate_within`].
pub fn triangulate<P: Coord>(polygon: &Polygon<P>) -> Result<Triangulation, TriangulateError> {
    triangulate_within(polygon, Instant::now().checked_add(DEFAULT_TIME_LIMIT))
}

/// The minimum triangulation of a polygon: by Chen & Chang's steps without holes (exact, no
/// search); with holes by [`triangulate_general`], searching until `deadline`.
///
/// Without holes `deadline` bounds step 1 (O(n log^2 n) in the worst case, the costliest stage
/// on most inputs): past it the triangles found so far are used, and the result is valid but
/// `optimal` only if it meets the lower bound, else with `lower_bound` and
/// [`Stopped::TimeLimit`]. `None`: no limit, always exact.
///
/// # Errors
/// Without holes, none for valid polygons; with holes, those of [`triangulate_general`] (not
/// seen in the tests).
pub fn triangulate_within<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<Instant>,
) -> Result<Triangulation, TriangulateError> {
    triangulate_premade(polygon, None, deadline)
}

/// [`triangulate_within`], step 1 walking `premade`'s triangles when the caller made them
/// already (the pipeline, beside the validation sweep).
///
/// # Errors
/// As [`triangulate_within`].
pub(crate) fn triangulate_premade<P: Coord>(
    polygon: &Polygon<P>,
    premade: Premade,
    deadline: Option<Instant>,
) -> Result<Triangulation, TriangulateError> {
    if polygon.touches() > 0 {
        return super::touching(polygon, Algorithm::Minitri, 0, deadline);
    }
    if polygon.holes() > 0 {
        return triangulate_general_premade(polygon, premade, deadline);
    }
    let plain = super::plain::polygon(polygon, premade);
    let (mdts, base, unexamined) =
        degenerate::minimally_degenerate_over_until(polygon, plain, deadline);
    let chosen = circle_mis(polygon, &mdts);
    drop(mdts);
    // With nothing chosen the only piece is P itself, and step 1's plain triangulation is one;
    // otherwise it is dropped before the pieces are made (peak memory).
    let triangles = if chosen.is_empty() {
        base
    } else {
        drop(base);
        partition::triangulate_pieces(polygon, &chosen)
    };
    let degenerate = chosen.iter().map(|m| [m.a, m.b, m.c]).collect();
    // Step 1 cut short by the deadline: the triangles chosen among those found are independent
    // all the same (dependence is a relation between pairs), so the triangulation is valid, but
    // not proved minimum. A maximum independent set of all the triangles is, on the middles
    // looked from (all of whose triangles were found), an independent set of the found ones,
    // at most as large as the chosen maximum one; and on the others at most one triangle per
    // middle (triangles sharing their middle are dependent). So `d <= chosen + unexamined`.
    let lower = (unexamined > 0).then(|| lower_bound(polygon, chosen.len() + unexamined));
    let optimal = lower.is_none_or(|lower| lower >= triangles.len());
    Ok(Triangulation {
        algorithm: Algorithm::Minitri,
        triangles,
        degenerate,
        optimal,
        lower_bound: lower.filter(|_| !optimal),
        stopped: (!optimal).then_some(Stopped::TimeLimit),
    })
}

/// The minimum triangulation of any valid polygon, holes allowed, by the general method: all
/// minimally degenerate triangles, their dependency graph ([`dependency`], Theorem 1), a maximum
/// independent set by exact search ([`branch_and_bound`], until `deadline`), and the chosen
/// triangles cut into a plain triangulation ([`cut`]). `optimal` is true only when the search
/// finished; otherwise `lower_bound` holds the proved bound `n + 2w - 2 - (upper bound on d)`
/// and `stopped` says why. Without holes it gives the same count as [`triangulate`] (the tests
/// compare them).
///
/// Time and memory stay bounded whatever the polygon: the deadline is read while the
/// triangles are found and while their graph is built, not only during the search, and the
/// graph may compare at most [`dependency::pair_budget`] pairs. When either runs out, the search
/// goes on with the shorter half of the triangles (by the extent of their long side), halving
/// again until the graph fits, after the deadline within a budget of [`LATE_PAIRS`] pairs per
/// try (so the run ends a small constant after the deadline). Any subset of the triangles gives
/// a valid answer (dependence is a relation between pairs, so a set independent within a subset
/// is independent), and the lower bound is taken over all of them: the number of distinct middle
/// vertices bounds `d` from above (triangles sharing their middle are pairwise dependent).
///
/// # Errors
/// [`TriangulateError::MinitriCutFailed`] if a self-check of the cut step fails (see [`cut`];
/// not seen in the tests).
pub fn triangulate_general<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<Instant>,
) -> Result<Triangulation, TriangulateError> {
    triangulate_general_premade(polygon, None, deadline)
}

/// [`triangulate_general`], step 1 walking `premade`'s triangles when the caller made them
/// already.
fn triangulate_general_premade<P: Coord>(
    polygon: &Polygon<P>,
    premade: Premade,
    deadline: Option<Instant>,
) -> Result<Triangulation, TriangulateError> {
    let plain = super::plain::polygon(polygon, premade);
    let (mdts, base, unexamined) =
        degenerate::minimally_degenerate_over_until(polygon, plain, deadline);
    general_from(polygon, mdts, base, unexamined, deadline)
}

/// Chen & Chang's steps on the boundary walks of touching rings (`crate::algo::walks`,
/// `docs/touching.md`), a copy of a touch point being a vertex of its own. Step 1 by triangular
/// expansion over the plain triangulation of the walks (`crate::algo::plain::walks`;
/// [`degenerate::minimally_degenerate_over_until`]: a copy has its own fan of triangles), which
/// is also the one the chosen triangles are cut into ([`cut`]). On one walk (a weakly simple
/// polygon, stored vertices in walk order), steps 2 and 3 as for a simple polygon, the walk
/// read as the circle: polynomial, no search (the tests compare it with the walk DP and an
/// exhaustive search). With hole walks left, the dependency graph and the exact search of
/// [`triangulate_general`], until `deadline`: at a touch point at most one copy can be a middle
/// (its angle is 180 degrees or more; the copies' angles are disjoint), and a triangle ending at
/// another copy of a middle's point comes from the side that is not straight, so Theorem 1's
/// cases apply unchanged. The count is `N + 2(w - t) - 2 - d` (`docs/touching.md`).
///
/// # Errors
/// [`TriangulateError::Touching`] if the walks' plain triangulation fails, and those of
/// [`triangulate_general`] (neither seen in the tests).
pub fn triangulate_walks<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<Instant>,
) -> Result<Triangulation, TriangulateError> {
    let plain = crate::algo::plain::walks(polygon).map_err(|e| TriangulateError::Touching {
        algorithm: Algorithm::Minitri,
        detail: e.to_string(),
    })?;
    let (mdts, base, unexamined) =
        degenerate::minimally_degenerate_over_until(polygon, plain, deadline);
    if polygon.holes() > 0 || unexamined > 0 {
        return general_from(polygon, mdts, base, unexamined, deadline);
    }
    // One walk (a weakly simple polygon): steps 2 and 3 as for a simple polygon, the walk read
    // as the circle (stored vertices are in walk order): polynomial, no search.
    let chosen = circle_mis(polygon, &mdts);
    let triangles = cut::triangulate_with_cuts(polygon, base, &chosen)?;
    Ok(Triangulation {
        algorithm: Algorithm::Minitri,
        triangles,
        degenerate: chosen.iter().map(|m| [m.a, m.b, m.c]).collect(),
        optimal: true,
        lower_bound: None,
        stopped: None,
    })
}

/// Steps 2 and 3 without holes (one boundary): the circle, its 3b-chains, and a maximum
/// independent set on them, as triangles.
fn circle_mis<P: Coord>(
    polygon: &Polygon<P>,
    mdts: &[degenerate::Degenerate],
) -> Vec<degenerate::Degenerate> {
    let circle = circle::circle(polygon, mdts);
    let chains = chains::chains(polygon, mdts);
    mis::maximum_independent_set(&circle, &chains)
        .into_iter()
        .map(|t| mdts[t])
        .collect()
}

/// Steps 2 to 5 of [`triangulate_general`], from the minimally degenerate triangles found
/// (all of those whose middle was looked from; `unexamined` vertices that could be a middle
/// were not) and a plain triangulation `base`.
fn general_from<P: Coord>(
    polygon: &Polygon<P>,
    mut mdts: Vec<degenerate::Degenerate>,
    base: Vec<[usize; 3]>,
    unexamined: usize,
    deadline: Option<Instant>,
) -> Result<Triangulation, TriangulateError> {
    // An upper bound on `d` over ALL the minimally degenerate triangles: on the middles looked
    // from, the search's bound over the triangles found, or (once some are dropped to fit the
    // graph) their distinct middles, taken before any is dropped; plus one per vertex that
    // could be a middle and was not looked from (triangles sharing a middle are dependent).
    let mut examined_bound: Option<usize> = None;
    let mut stopped = (unexamined > 0).then_some(Stopped::TimeLimit);
    let mut sorted = false;
    let graph = loop {
        let late = crate::algo::past(deadline);
        let (budget, until) = if late {
            (LATE_PAIRS, None)
        } else {
            (dependency::pair_budget(polygon.len()), deadline)
        };
        if let Some(graph) = dependency::graph_within(polygon, &mdts, budget, until) {
            break graph;
        }
        let late = crate::algo::past(deadline);
        stopped.get_or_insert(if late {
            Stopped::TimeLimit
        } else {
            Stopped::GraphSize
        });
        if !sorted {
            examined_bound.get_or_insert_with(|| distinct_middles(&mdts));
            mdts.sort_by(|m, o| extent(polygon, m).total_cmp(&extent(polygon, o)));
            sorted = true;
        }
        mdts.truncate(mdts.len() / 2);
    };
    let middles: Vec<usize> = mdts.iter().map(|m| m.b).collect();
    let found = branch_and_bound::maximum_independent_set_labelled(&graph, &middles, deadline);
    let chosen: Vec<degenerate::Degenerate> = found.set.iter().map(|&t| mdts[t]).collect();
    let triangles = cut::triangulate_with_cuts(polygon, base, &chosen)?;
    let lower = lower_bound(
        polygon,
        examined_bound.unwrap_or(found.upper_bound) + unexamined,
    );
    // A search cut short whose bound meets its count has found the minimum all the same.
    let stopped = stopped.or(found.stopped);
    let optimal = stopped.is_none() || lower >= triangles.len();
    Ok(Triangulation {
        algorithm: Algorithm::Minitri,
        triangles,
        degenerate: chosen.iter().map(|m| [m.a, m.b, m.c]).collect(),
        optimal,
        lower_bound: (!optimal).then_some(lower),
        stopped: if optimal { None } else { stopped },
    })
}

/// The pairs the dependency graph may compare per try once the deadline has passed: a small
/// fixed amount of work (docs/benchmarks.md).
pub const LATE_PAIRS: u64 = 1 << 20;

/// The number of distinct middle vertices of `mdts`.
fn distinct_middles(mdts: &[degenerate::Degenerate]) -> usize {
    let mut middles: Vec<usize> = mdts.iter().map(|m| m.b).collect();
    middles.sort_unstable();
    middles.dedup();
    middles.len()
}

/// How far a triangle's long side reaches, roughly: `|dx| + |dy|` in floating point (shorter
/// triangles cross fewer others). Only an order of preference: any subset gives a valid answer.
fn extent<P: Coord>(polygon: &Polygon<P>, m: &degenerate::Degenerate) -> f64 {
    let [dx, dy] = polygon.point(m.c).offset_f64(polygon.point(m.a));
    dx.abs() + dy.abs()
}

/// The proved lower bound on the minimum from an upper bound `d_upper` on the number of
/// mutually independent minimally degenerate triangles: `n + 2w - 2 - d_upper`, never below
/// `ceil((n - f) / 3)` (every vertex but a flat one is a corner of a triangle). No subtraction
/// can wrap: `d_upper` is at most the number of distinct middle vertices (each component's bound
/// is capped by its middles), which is below `n`, and the subtraction saturates all the same.
fn lower_bound<P: Coord>(polygon: &Polygon<P>, d_upper: usize) -> usize {
    let (corners, plain) = polygon.minimum_bounds();
    plain.saturating_sub(d_upper).max(corners)
}

#[cfg(test)]
mod tests;
