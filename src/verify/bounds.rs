//! Check 7: every number reported about a triangulation besides its triangles, recounted.
//!
//! The writers print, beside the triangles, the polygon's flat vertices `f`, the bounds
//! `ceil((n - f) / 3) <= minimum <= n + 2w - 2` (Chen & Chang's Theorem 3, generalised to flat
//! vertices), and for a search cut short (`optimal` false) a proved `lower_bound` on the
//! minimum. This module recounts `f` and the bounds from the rings alone (its own walk, the
//! kernel's sign only) and requires
//!
//! `ceil((n - f) / 3) <= lower_bound <= triangle count <= n + 2w - 2`,
//!
//! and no `lower_bound` at all when the count is claimed optimal (it would be the count).
//!
//! Why these hold for every correct output: every vertex that is not flat is a corner of some
//! triangle (a vertex inside a side of a triangle has a straight angle there; a vertex whose
//! angle is not straight keeps a corner of the remaining part of its angle, or is a corner
//! outright), and each triangle has three corners, so `3 T >= n - f` for any triangulation, in
//! particular the minimum; a lower bound above the count found would contradict the count
//! (the count is that of a valid triangulation, checks 1-6); and `T = n + 2w - 2 - d` with
//! `d >= 0` (check 5). A wrapped subtraction (a bound near 2^64) fails the second inequality.
//!
//! Complexity: O(n).

use crate::algo::Triangulation;
use crate::geom::kernel::{cross, Coord};
use crate::geom::polygon::Polygon;

/// The bounds recounted: `(ceil((n - f) / 3), n + 2w - 2, f)`.
pub fn recount<P: Coord>(polygon: &Polygon<P>) -> (usize, usize, usize) {
    let mut flat = 0;
    let starts = polygon.ring_starts();
    let n = polygon.len();
    for (r, &start) in starts.iter().enumerate() {
        let end = starts.get(r + 1).copied().unwrap_or(n);
        let len = end - start;
        for k in 0..len {
            let at = |j: usize| polygon.point(start + (k + j) % len);
            if cross(at(len - 1), at(0), at(1)) == 0 {
                flat += 1;
            }
        }
    }
    let holes = starts.len().saturating_sub(1);
    ((n - flat).div_ceil(3), n + 2 * holes - 2, flat)
}

/// The problems with the numbers reported about `t` (none when all are right).
pub fn problems<P: Coord>(polygon: &Polygon<P>, t: &Triangulation) -> Vec<String> {
    let mut out = Vec::new();
    let (corners, plain, flat) = recount(polygon);
    if polygon.flat_vertices() != flat {
        out.push(format!(
            "the polygon reports {} flat vertices but has {flat}",
            polygon.flat_vertices()
        ));
    }
    if polygon.minimum_bounds() != (corners, plain) {
        let (l, u) = polygon.minimum_bounds();
        out.push(format!(
            "the reported bounds are {l} to {u} but ceil((n - f)/3) = {corners} and n + 2w - 2 = {plain}"
        ));
    }
    let count = t.triangles.len();
    // (A count breaking check 5 is reported there; one that passes it is at most n + 2w - 2.)
    let counted = count + t.degenerate.len() == plain;
    if counted && count < corners {
        out.push(format!(
            "{count} triangles is outside the bounds {corners} to {plain}"
        ));
    }
    match t.lower_bound {
        Some(_) if t.optimal => out.push(format!(
            "a lower bound is reported although the count {count} is claimed optimal"
        )),
        Some(lower) if lower < corners || lower > count => out.push(format!(
            "the lower bound {lower} is outside {corners} (ceil((n - f)/3)) to {count} (the count)"
        )),
        _ => {}
    }
    if let (Some(stopped), true) = (t.stopped, t.optimal) {
        out.push(format!(
            "the count {count} is claimed optimal and also stopped by the {}",
            stopped.name()
        ));
    }
    out
}
