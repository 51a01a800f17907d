//! `--algorithm pseudo-hull`: a MINIMUM pseudotriangulation of the convex hull of the polygon's
//! vertices that contains the polygon's edges (outer ring and holes) as the given segment set L,
//! after Rote, Wang, Wang & Xu, "On constrained minimum pseudotriangulations", COCOON 2003,
//! LNCS 2697, pp. 445-454, doi:10.1007/3-540-45071-8_45, Section 6
//! (`papers/rote-wang-wang-xu-constrained-minimum-pseudotriangulations.txt`).
//!
//! The region is the whole convex hull: the polygon's interior, the interiors of its holes and
//! the pockets between the outer ring and the hull are all cut into pseudotriangles (Section 1: a
//! pseudotriangulation of a point set partitions the interior of its convex hull).
//!
//! # Overview
//!
//! 1. Theorem 6, first step: L plus the hull edges (the hull's boundary with every vertex on it,
//!    so a vertex inside a hull side splits it). This keeps every angle of at least pi.
//! 2. Theorem 6's invariant, the set of reflex vertices, kept while adding edges: an edge is
//!    added only if it splits no angle of at least pi into two angles below pi, at either end.
//!    Edges are tried shortest first, each checked against every vertex (none strictly inside)
//!    and every edge (no contact but at a shared end), until the count of Corollary 1 is reached.
//!
//! Departure from the paper: the proof of Theorem 6 finds each new edge on a shortest path
//! homotopic to a boundary walk among the obstacles of a face; here the edges are found by the
//! search of step 2 instead, which keeps the same invariant, so the proof's count holds. Why the
//! count is reached: with N the number of angles of at least pi (the outer angles at hull
//! vertices included), Euler's formula and three corners per face give `2n - N - 2` faces and
//! `3n - N - 3` edges for every pseudotriangulation; adding an edge never increases N, so no
//! pseudotriangulation containing L has fewer faces than `2n - N0 - 2` (N0: N of step 1), and one
//! with `3n - N0 - 3` edges that keeps N = N0 has exactly that many. In general position
//! (Section 2) every vertex has one angle of at least pi, so N0 = r = n and this is Corollary 1's
//! `2n - r - 2 = n - 2`; that a graph keeping every vertex pointed can always be extended until
//! it is a pseudotriangulation is Streinu's theorem (reference 5 of the paper), and the
//! construction of Theorem 6 shows it with L given.
//!
//! Collinear input (the paper assumes general position): a flat vertex keeps both its angles of
//! pi (N0 counts both), and no edge passes through a vertex; the answer, when reached, has
//! `2n - N0 - 2` faces, the least possible by the argument above. If the search stops short of
//! that count (not seen in the tests, but not excluded by a proof for collinear points), the
//! polygon gets [`TriangulateError::PseudoHullIncomplete`], never a wrong answer.
//!
//! Complexity: O(n^3) time (O(n^2) candidate edges, each checked against O(n) vertices and
//! edges; usually the count is reached in one pass), O(n^2) memory; hence [`DEFAULT_LIMIT`].

use super::{HullCounts, Pseudotriangle, Pseudotriangulation, TriangulateError};
use crate::geom::kernel::SegmentContact;
use crate::geom::kernel::{cmp_angle, cross, dot, segment_contact, strictly_between, Point};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;

/// The largest polygon (vertices over all rings) accepted: the search is O(n^3).
pub const DEFAULT_LIMIT: usize = 2000;

/// A minimum pseudotriangulation of the convex hull of `polygon`'s vertices containing its edges.
///
/// # Errors
/// [`TriangulateError::PseudoHullTooLarge`] above `limit` vertices;
/// [`TriangulateError::PseudoHullIncomplete`] if the search stops short (see the module docs).
///
/// # Examples
/// ```
/// use minitri::{algo::pseudo_hull, Decimal, Polygon, RawPolygon};
/// let ring: Result<Vec<[Decimal; 2]>, minitri::NumberError> = [(0, 0), (4, 0), (2, 1), (2, 4)]
///     .iter()
///     .map(|&(x, y)| Ok([Decimal::parse(&x.to_string())?, Decimal::parse(&y.to_string())?]))
///     .collect();
/// let (polygon, _warnings) = Polygon::from_raw(&RawPolygon { rings: vec![ring?] })?;
/// let p = pseudo_hull::pseudotriangulate(&polygon, pseudo_hull::DEFAULT_LIMIT)?;
/// assert_eq!(p.faces.len(), 2); // n - 2: the polygon and the pocket under vertex (2, 1)
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn pseudotriangulate(
    polygon: &Polygon,
    limit: usize,
) -> Result<Pseudotriangulation, TriangulateError> {
    let n = polygon.len();
    if n > limit {
        return Err(TriangulateError::PseudoHullTooLarge { n, limit });
    }
    let points = polygon.points();
    let hull = hull_cycle(points);
    let mut graph = Graph::new(points);
    for i in 0..n {
        graph.add(i, polygon.next(i));
    }
    for (k, &h) in hull.iter().enumerate() {
        graph.add(h, hull[(k + 1) % hull.len()]);
    }
    let counts = HullCounts {
        reflex_vertices: (0..n).filter(|&v| graph.big_angles(v) > 0).count(),
        big_angles: (0..n).map(|v| graph.big_angles(v)).sum(),
    };
    let target = (3 * n).saturating_sub(counts.big_angles + 3);
    let mut candidates: Vec<(i128, usize, usize)> = Vec::new();
    for u in 0..n {
        for v in u + 1..n {
            if !graph.adjacent(u, v) {
                candidates.push((dot(points[u], points[v], points[v]), u, v));
            }
        }
    }
    candidates.sort_unstable();
    let mut added = true;
    while added && graph.edges.len() < target {
        added = false;
        for &(_, u, v) in &candidates {
            if graph.edges.len() >= target {
                break;
            }
            if !graph.adjacent(u, v) && graph.addable(u, v) {
                graph.add(u, v);
                added = true;
            }
        }
    }
    if graph.edges.len() != target {
        return Err(TriangulateError::PseudoHullIncomplete {
            edges: graph.edges.len(),
            target,
        });
    }
    let faces = graph.faces(hull[1], hull[0]);
    Ok(Pseudotriangulation {
        faces,
        edge_count: graph.edges.len(),
        hull: Some(counts),
    })
}

/// The convex hull's boundary, counter-clockwise, with every point on it (collinear ones too):
/// Andrew's monotone chain, popping only strict right turns.
fn hull_cycle(points: &[Point]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_unstable_by_key(|&i| points[i]);
    let chain = |order: &mut dyn Iterator<Item = usize>| {
        let mut h: Vec<usize> = Vec::new();
        for i in order {
            while h.len() >= 2
                && cross(points[h[h.len() - 2]], points[h[h.len() - 1]], points[i]) < 0
            {
                h.pop();
            }
            h.push(i);
        }
        h.pop();
        h
    };
    let mut lower = chain(&mut order.iter().copied());
    let upper = chain(&mut order.iter().rev().copied());
    lower.extend(upper);
    lower
}

/// A plane straight-line graph with each vertex's neighbours in counter-clockwise order.
struct Graph<'a> {
    points: &'a [Point],
    around: Vec<Vec<usize>>,
    edges: Vec<(usize, usize)>,
}

impl<'a> Graph<'a> {
    fn new(points: &'a [Point]) -> Graph<'a> {
        Graph {
            points,
            around: vec![Vec::new(); points.len()],
            edges: Vec::new(),
        }
    }

    fn adjacent(&self, u: usize, v: usize) -> bool {
        self.around[u].contains(&v)
    }

    /// Where `v` goes (or is) among the neighbours of `u`, counter-clockwise.
    fn slot(&self, u: usize, v: usize) -> usize {
        let c = self.points[u];
        self.around[u]
            .partition_point(|&a| cmp_angle(c, self.points[a], self.points[v]) == Ordering::Less)
    }

    /// Adds edge `u v` (once, whatever was added before).
    fn add(&mut self, u: usize, v: usize) {
        if self.adjacent(u, v) {
            return;
        }
        for (a, b) in [(u, v), (v, u)] {
            let at = self.slot(a, b);
            self.around[a].insert(at, b);
        }
        self.edges.push((u, v));
    }

    /// The neighbours before and after direction `u -> v` around `u` (counter-clockwise).
    fn sides(&self, u: usize, v: usize) -> (usize, usize) {
        let around = &self.around[u];
        let d = around.len();
        let at = self.slot(u, v);
        (around[(at + d - 1) % d], around[at % d])
    }

    /// The number of angles of at least pi at `v` between consecutive neighbours.
    fn big_angles(&self, v: usize) -> usize {
        let around = &self.around[v];
        let c = self.points[v];
        match around.len() {
            0 => 0,
            1 => 1,
            d => (0..d)
                .filter(|&k| {
                    cross(c, self.points[around[k]], self.points[around[(k + 1) % d]]) <= 0
                })
                .count(),
        }
    }

    /// Whether direction `u -> v` splits no angle of at least pi at `u` into two below pi.
    fn keeps_big_angle(&self, u: usize, v: usize) -> bool {
        let (p, q) = self.sides(u, v);
        let [c, pp, pq, pv] = [u, p, q, v].map(|i| self.points[i]);
        cross(c, pp, pq) > 0 || cross(c, pp, pv) <= 0 || cross(c, pv, pq) <= 0
    }

    /// Whether segment `u v` can be added: nothing on it, no contact with an edge but at a
    /// shared end, and every angle of at least pi kept at both ends.
    fn addable(&self, u: usize, v: usize) -> bool {
        if !self.keeps_big_angle(u, v) || !self.keeps_big_angle(v, u) {
            return false; // the cheap test first: O(log degree)
        }
        let (pu, pv) = (self.points[u], self.points[v]);
        if self.points.iter().any(|&w| strictly_between(pu, w, pv)) {
            return false;
        }
        self.edges.iter().all(|&(a, b)| {
            let shared = a == u || a == v || b == u || b == v;
            shared
                || segment_contact(pu, pv, self.points[a], self.points[b])
                    == SegmentContact::Disjoint
        })
    }

    /// The bounded faces, each counter-clockwise; `outer_from -> outer_to` is a half-edge of the
    /// unbounded face (a hull edge run clockwise).
    fn faces(&self, outer_from: usize, outer_to: usize) -> Vec<Pseudotriangle> {
        let n = self.points.len();
        let mut start = vec![0; n + 1];
        for u in 0..n {
            start[u + 1] = start[u] + self.around[u].len();
        }
        let id = |u: usize, v: usize| start[u] + self.slot(u, v);
        // The face on the left of u -> v goes on along v -> w, w the neighbour of v just
        // clockwise of u.
        let mut seen = vec![false; start[n]];
        let mut faces = Vec::new();
        let walk = |u0: usize, v0: usize, seen: &mut Vec<bool>| {
            let mut cycle = Vec::new();
            let (mut u, mut v) = (u0, v0);
            while !seen[id(u, v)] {
                seen[id(u, v)] = true;
                cycle.push(u);
                let around = &self.around[v];
                let d = around.len();
                let w = around[(self.slot(v, u) + d - 1) % d];
                (u, v) = (v, w);
            }
            cycle
        };
        walk(outer_from, outer_to, &mut seen);
        for u in 0..n {
            for &v in &self.around[u] {
                if !seen[id(u, v)] {
                    let cycle = walk(u, v, &mut seen);
                    faces.push(Pseudotriangle::from_cycle(self.points, cycle));
                }
            }
        }
        faces
    }
}

#[cfg(test)]
mod tests;
