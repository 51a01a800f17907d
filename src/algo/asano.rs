//! The exact minimum triangulation of a polygon without holes, by dynamic programming.
//!
//! T. Asano, T. Asano and R. Y. Pinter, "Polygon triangulation: efficiency and minimality",
//! *Journal of Algorithms* 7 (1986) 221-231; as presented in T. Asano and T. Asano, "Topics on
//! triangulation of polygons", §3.
//!
//! # Overview
//! 1. The chord table ([`super::chords`], O(n^2 log n)): which closed segments between vertices
//!    lie in the closed polygon (they may touch the boundary and run along edges).
//! 2. The table `cost[i][j]`, for `i < j` with `i j` a chord or edge: the fewest nondegenerate
//!    triangles partitioning the subpolygon `P(i..j)` bounded by the boundary chain
//!    `i, i+1, .., j` and the chord `j i`. Any triangulation of `P(i..j)` has a triangle on side
//!    `i j`, with apex `k` strictly between: `cost[i][j] = min_k cost[i][k] + cost[k][j] +
//!    d(i, k, j)`, where `d` is 0 for a "dummy" triangle of zero area and 1 otherwise (§3, the
//!    formula for `p_{i,t}`; we index by end points `(i, j = i + t - 1)` instead of `(i, t)`,
//!    which is the same table, and fold the cases `k = i + 1` and `k = j - 1` in through
//!    `cost[i][i+1] = 0`). Apexes making a clockwise triangle are skipped.
//! 3. Back-pointers (`choice[i][j] = k`) recover the triangles. The dummies used are as many as
//!    the degenerate triangles saved, but need not be minimally degenerate themselves (a dummy
//!    `(4,2) (3,2) (1,2)` may have the vertex `(2,2)` on its long side, and two dummies may
//!    share it); so the reported degenerate triangles are read off the final triangles: every
//!    vertex inside a triangle side, with its neighbours along that side (`super::t_junctions`).
//!
//! Departures from the paper: the polygon is counter-clockwise (the paper: clockwise); the
//! answer is `cost[0][n-1]` because `n-1 -> 0` is an edge.
//!
//! Speed: the inner minimum over `k` is branch-free integer arithmetic on two table rows (one
//! stored transposed) and the chord table's line numbers (collinearity of `i, k, j` is
//! `line(i, k) == line(i, j)`), so the compiler vectorises it; the exact orientation test runs
//! only on the chosen apex (with an exact fallback scan if that apex turns clockwise).
//!
//! Complexity: O(n^3) time, O(n^2) memory (four `n x n` tables of `u16`, 8 n^2 bytes, plus the
//! chord bits). Above [`DEFAULT_LIMIT`] vertices (configurable) it refuses, with an estimate.

use super::chords::ChordTable;
use super::{Algorithm, TriangulateError, Triangulation};
use crate::geom::kernel::cross;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use std::time::Instant;

/// The default largest number of vertices the DP accepts (seconds and tens of MB at 3000;
/// docs/benchmarks.md).
pub const DEFAULT_LIMIT: usize = 3000;

const INF: u16 = u16::MAX;

/// Estimated memory and time of the DP on `n` vertices, in words.
pub fn estimate(n: usize) -> (String, String) {
    let bytes = 8.0 * (n as f64).powi(2) + (n as f64).powi(2) / 8.0;
    // Measured end to end on convex polygons, the worst case: about 1.3 ns per step (`docs/benchmarks.md`).
    let seconds = 1.3e-9 * (n as f64).powi(3) / 6.0;
    // Small sizes (a low --dp-limit) in kB and ms or µs, rounded up: never "0 MB and 0.0 s".
    let memory = if bytes >= 1e9 {
        format!("{:.1} GB", bytes / 1e9)
    } else if bytes >= 0.5e6 {
        format!("{:.0} MB", bytes / 1e6)
    } else {
        format!("{:.0} kB", (bytes / 1e3).ceil())
    };
    let time = if seconds >= 3600.0 {
        format!("{:.1} hours", seconds / 3600.0)
    } else if seconds >= 60.0 {
        format!("{:.0} minutes", seconds / 60.0)
    } else if seconds >= 0.05 {
        format!("{seconds:.1} s")
    } else if seconds >= 0.5e-3 {
        format!("{:.0} ms", seconds * 1e3)
    } else {
        format!("{:.0} µs", (seconds * 1e6).ceil())
    };
    (memory, time)
}

/// The minimum triangulation of a polygon; with 1 or 2 holes by [`super::asano_holes`].
///
/// # Errors
/// [`TriangulateError::TooLarge`] above `limit` vertices without holes (or above 65,000, the
/// table's range); for polygons with holes, those of [`super::asano_holes::triangulate`]
/// ([`TriangulateError::TooManyHoles`] above 2 holes, [`TriangulateError::TooLargeWithHoles`]
/// above its size limits).
pub fn triangulate<P: Coord>(
    polygon: &Polygon<P>,
    limit: usize,
) -> Result<Triangulation, TriangulateError> {
    let n = polygon.len();
    if polygon.touches() > 0 {
        // The search on walks with hole walks left has the default time limit here; the
        // command line passes its own (`--time-limit`) to `super::touching` directly.
        let deadline = Instant::now().checked_add(super::minitri::DEFAULT_TIME_LIMIT);
        return super::touching(polygon, Algorithm::Asano, limit, deadline);
    }
    if polygon.holes() > 0 {
        return super::asano_holes::triangulate(polygon, limit);
    }
    let limit = limit.min(65_000);
    if n > limit {
        let (memory, time) = estimate(n);
        return Err(TriangulateError::TooLarge {
            n,
            limit,
            memory,
            time,
        });
    }
    // The tables are reserved, not assumed: a polygon whose tables cannot be had (an address
    // space limit, `--dp-limit` raised far) is reported, and the run goes on.
    let no_room = || TriangulateError::OutOfMemory {
        algorithm: Algorithm::Asano,
        n,
        memory: estimate(n).0,
    };
    // The DP's tables first: they are the larger (6 n^2 bytes), and take no time to make.
    let tables = Tables::try_new(n).ok_or_else(no_room)?;
    let chords = ChordTable::try_new(polygon).ok_or_else(no_room)?;
    let walk = solve_walk_in(
        tables,
        n,
        |i| polygon.point(i),
        |i, j| chords.is_chord(i, j),
        |i| chords.lines_through(i),
        None,
    )
    .expect("`n-1 -> 0` is an edge, so the whole polygon always has a triangulation");
    let degenerate = super::t_junctions(polygon, &walk.triangles, super::Junctions::Rings);
    debug_assert_eq!(
        degenerate.len(),
        walk.dummies,
        "each dummy saves exactly one triangle"
    );
    Ok(Triangulation {
        algorithm: Algorithm::Asano,
        triangles: walk.triangles,
        degenerate,
        optimal: true,
        lower_bound: None,
        stopped: None,
    })
}

/// The DP's answer for one boundary walk: the nondegenerate triangles (counter-clockwise, as
/// walk positions) and the number of dummies used.
pub(crate) struct WalkTriangulation {
    /// Nondegenerate triangles, counter-clockwise, as positions of the walk.
    pub triangles: Vec<[usize; 3]>,
    /// Zero-area triangles used (each saves one triangle).
    pub dummies: usize,
}

/// The DP (steps 2 and 3 above) on a closed boundary walk of `m` positions `0..m`, interior on
/// the left of `p -> p + 1` and of `m-1 -> 0`: a simple polygon, or a weakly simple one (a
/// polygon with holes cut open, whose walk visits some points twice; see `super::asano_holes`).
/// `point(p)` is the position's point, `is_chord(p, q)` (for `q >= p + 2`) whether the segment
/// between positions `p` and `q` is a chord of the walk, `lines_through(p)[q]` numbers the lines
/// through `p` (equal for `q` and `r` exactly when `p`, `q`, `r` are collinear; `q` at `p`'s
/// own point must get a number no other position on a line through `p` gets).
///
/// Returns `None` when the walk has no triangulation (cannot happen for a valid walk), or when
/// `deadline` passes (read once per chord length, i.e. every O(m^2) steps at most).
pub(crate) fn solve_walk<'a, P: Coord>(
    m: usize,
    point: impl Fn(usize) -> P,
    is_chord: impl Fn(usize, usize) -> bool,
    lines_through: impl Fn(usize) -> &'a [u16],
    deadline: Option<Instant>,
) -> Option<WalkTriangulation> {
    solve_walk_in(Tables::new(m), m, point, is_chord, lines_through, deadline)
}

/// The DP's tables for a walk of `m` positions, `6 m^2` bytes: the cost of each sub-walk
/// (row-major, and transposed) and the apex chosen for it.
pub(crate) struct Tables {
    cost: Vec<u16>,
    cost_t: Vec<u16>,
    choice: Vec<u16>,
}

impl Tables {
    /// The tables, allocated as usual (an allocation failure aborts).
    fn new(m: usize) -> Tables {
        Tables {
            cost: vec![INF; m * m],
            cost_t: vec![INF; m * m],
            choice: vec![0; m * m],
        }
    }

    /// The tables, or `None` when their memory cannot be had.
    pub(crate) fn try_new(m: usize) -> Option<Tables> {
        let cells = m.checked_mul(m)?;
        Some(Tables {
            cost: super::try_filled(cells, INF)?,
            cost_t: super::try_filled(cells, INF)?,
            choice: super::try_filled(cells, 0)?,
        })
    }
}

/// [`solve_walk`] in `tables` (made for `m` positions).
pub(crate) fn solve_walk_in<'a, P: Coord>(
    tables: Tables,
    m: usize,
    point: impl Fn(usize) -> P,
    is_chord: impl Fn(usize, usize) -> bool,
    lines_through: impl Fn(usize) -> &'a [u16],
    deadline: Option<Instant>,
) -> Option<WalkTriangulation> {
    let n = m;
    let at = |i: usize, j: usize| i * n + j;
    let Tables {
        mut cost,   // cost[i][j], row-major
        mut cost_t, // the same, transposed: cost_t[j][i] = cost[i][j]
        mut choice,
    } = tables;
    for i in 0..n - 1 {
        cost[at(i, i + 1)] = 0;
        cost_t[at(i + 1, i)] = 0;
    }
    for gap in 2..n {
        if crate::algo::past(deadline) {
            return None;
        }
        for i in 0..n - gap {
            let j = i + gap;
            if !is_chord(i, j) {
                continue;
            }
            let (pi, pj) = (point(i), point(j));
            let row = &cost[at(i, 0)..at(i, 0) + n];
            let col = &cost_t[at(j, 0)..at(j, 0) + n];
            let lines = lines_through(i);
            let line_j = lines[j];
            // The cost through apex k: both parts, plus 1 unless i, k, j are collinear (a
            // dummy). INF parts make the sum exceed any real cost. Branch-free, so it vectorises.
            let through =
                |k: usize| u32::from(row[k]) + u32::from(col[k]) + u32::from(lines[k] != line_j);
            let mut best = (i + 1..j).map(through).min().unwrap_or(u32::MAX);
            // The apex must not make a clockwise triangle; collinear ones have zero area.
            let valid = |k: usize| cross(pi, point(k), pj) >= 0;
            let mut arg = (i + 1..j).find(|&k| through(k) == best && valid(k));
            if arg.is_none() && best < u32::from(INF) {
                // Every cheapest apex turns clockwise: an exact scan over the valid ones.
                let cheapest = (i + 1..j).filter(|&k| valid(k)).min_by_key(|&k| through(k));
                best = cheapest.map_or(u32::MAX, through);
                arg = cheapest;
            }
            let arg = arg.unwrap_or(0);
            if best < u32::from(INF) {
                cost[at(i, j)] = best as u16;
                cost_t[at(j, i)] = best as u16;
                choice[at(i, j)] = arg as u16;
            }
        }
    }
    if cost[at(0, n - 1)] == INF {
        return None;
    }
    // `m-1 -> 0` is an edge, so the whole walk is P(0..m-1).
    let mut triangles = Vec::new();
    let mut dummies = 0;
    let mut stack = vec![(0, n - 1)];
    while let Some((i, j)) = stack.pop() {
        if j - i < 2 {
            continue;
        }
        let k = usize::from(choice[at(i, j)]);
        let (a, b, c) = (point(i), point(k), point(j));
        if cross(a, b, c) > 0 {
            triangles.push([i, k, j]);
        } else {
            dummies += 1;
        }
        stack.push((i, k));
        stack.push((k, j));
    }
    Some(WalkTriangulation { triangles, dummies })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::kernel::strictly_between;
    use crate::test_support::{polygon, U_SHAPE};

    fn count(ring: &[(i64, i64)]) -> usize {
        triangulate(&polygon(&[ring]), DEFAULT_LIMIT)
            .unwrap()
            .triangles
            .len()
    }

    #[test]
    fn design_md_worked_examples() {
        assert_eq!(count(&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]), 2);
        assert_eq!(count(&[(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]), 3);
        assert_eq!(count(&[(0, 0), (1, 0), (2, -1), (3, 0), (4, 0), (2, 2)]), 2);
        assert_eq!(count(&U_SHAPE), 5);
        assert_eq!(
            count(&[
                (3, 2),
                (6, 2),
                (6, 4),
                (5, 4),
                (5, 3),
                (4, 3),
                (4, 4),
                (3, 4)
            ]),
            6
        );
    }

    #[test]
    fn degenerate_triangles_name_their_middle_vertex() {
        let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]]);
        let t = triangulate(&p, DEFAULT_LIMIT).unwrap();
        assert_eq!(t.degenerate.len(), 2);
        for [a, b, c] in &t.degenerate {
            assert!(strictly_between(p.point(*a), p.point(*b), p.point(*c)));
        }
        assert_eq!(t.triangles.len() + t.degenerate.len(), p.len() - 2);
    }

    #[test]
    fn degenerate_triangles_are_the_t_junctions_of_the_output() {
        // Found by the property test: four collinear vertices on y = 2; the DP's dummies were
        // (4,2)(3,2)(1,2) and (4,2)(2,2)(1,2), neither a T-junction of the final triangles.
        let p = polygon(&[&[
            (1, 1),
            (2, 1),
            (3, 1),
            (3, 2),
            (4, 2),
            (4, 3),
            (3, 3),
            (2, 3),
            (2, 2),
            (1, 2),
        ]]);
        let t = triangulate(&p, DEFAULT_LIMIT).unwrap();
        assert_eq!(t.triangles.len() + t.degenerate.len(), p.len() - 2);
        let mut middles: Vec<usize> = t.degenerate.iter().map(|d| d[1]).collect();
        middles.sort();
        // The flat vertices (2,1) and (3,3), and the reflex (3,2) and (2,2) on y = 2.
        assert_eq!(middles, vec![1, 3, 6, 8]);
        assert!(
            crate::verify::check(&p, &t).valid,
            "{:?}",
            crate::verify::check(&p, &t).problems
        );
    }

    #[test]
    fn holes_go_to_the_holed_dp_and_oversized_inputs_are_refused_with_an_estimate() {
        let p = polygon(&[&[(0, 0), (9, 0), (9, 9), (0, 9)], &[(1, 1), (2, 1), (1, 2)]]);
        let t = triangulate(&p, DEFAULT_LIMIT).unwrap();
        assert_eq!(t.triangles.len(), 7, "n + 2w - 2: nothing collinear");
        assert!(crate::verify::check(&p, &t).valid);
        let p = polygon(&[
            &[(0, 0), (9, 0), (9, 9), (0, 9)],
            &[(1, 1), (2, 1), (1, 2)],
            &[(4, 4), (5, 4), (4, 5)],
            &[(7, 7), (8, 7), (7, 8)],
        ]);
        let e = triangulate(&p, DEFAULT_LIMIT).unwrap_err();
        assert!(e.to_string().contains("at most 2 holes"), "{e}");
        let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]]);
        let e = triangulate(&p, 5).unwrap_err();
        assert!(
            e.to_string()
                .contains("above its limit of 5 vertices; use --algorithm minitri"),
            "{e}"
        );
        assert_eq!(
            estimate(10_000).0,
            "812 MB",
            "8 n^2 bytes of tables plus n^2 bits"
        );
        // A small polygon over a low --dp-limit: no "0 MB and 0.0 s".
        assert_eq!(estimate(12), ("2 kB".to_string(), "1 µs".to_string()));
        assert_eq!(estimate(400).1, "14 ms");
    }
}
