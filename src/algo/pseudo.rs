//! `--algorithm pseudo`: a MINIMAL pseudotriangulation of a polygon (holes allowed) contained in a
//! triangulation, by the linear-time greedy of Rote, Wang, Wang & Xu, "On constrained minimum
//! pseudotriangulations", COCOON 2003, LNCS 2697, pp. 445-454, doi:10.1007/3-540-45071-8_45.
//!
//! A pseudotriangle is a simple polygon with exactly three corners, a corner being a vertex whose
//! interior angle is strictly less than pi; a vertex whose angle in a face is pi or more (a flat
//! vertex included) is not a corner. The region is the polygon, not the convex hull of its
//! vertices: polygon edges are never removed and the outside of the polygon (holes included) is
//! no face.
//!
//! # Overview
//!
//! 0. The start: the plain triangulation of [`crate::algo::plain::triangulate`] (monotone pieces, O(n log n)),
//!    n + 2w - 2 nondegenerate triangles with no vertex inside a side. Why not MINITRI's minimum
//!    triangulation: its degenerate triangles are T-junctions (a vertex inside a triangle side),
//!    so it is no triangulation of the vertex set in the paper's sense (Section 2: a maximal
//!    planar straight-line graph), MINITRI is not linear, and a minimum triangulation does not
//!    give a smaller minimal pseudotriangulation in general (Theorem 4(b): which minimal one is
//!    reached depends on the triangulation and on the order of removals anyway).
//! 1. Removable edges (Section 5, Lemma 4(a)): a diagonal `ab` whose removal merges its two
//!    faces into a pseudotriangle. With `alpha1`, `alpha2` the angles at `a` on either side of
//!    `ab` and `beta1`, `beta2` those at `b`, that is exactly when `alpha1 < pi`, `alpha2 < pi`
//!    and `alpha1 + alpha2 >= pi`, or the same at `b` (the merged face keeps 6 - 3 corners;
//!    `>=` and not the paper's `>` because an angle of exactly pi is no corner). Each test is
//!    three exact orientation signs ([`crate::geom::kernel::cross`]). A work list holds the
//!    edges to test, initially every diagonal; removing `ab` re-queues the (at most four) edges
//!    beside it at `a` and `b`, the only ones whose test reads a changed angle.
//! 2. Removable triangles (Lemma 4(b)): a triangular face whose three sides are diagonals and
//!    whose three corners each have both outer neighbouring angles below pi and their sum with
//!    the triangle's angle at least pi; removing its three sides merges four faces into one
//!    pseudotriangle. One scan of the faces: by the paper, and because every vertex of a removed
//!    triangle becomes a non-corner of the merged face, no edge or triangle becomes removable.
//!
//! By Theorem 2 the result is minimal: no edge and no triangle can be removed. The faces are
//! simple: a merged face of two (or four) simple faces joined along edges is simply connected,
//! and a closed boundary walk touching itself would have to turn once clockwise around what it
//! encloses, which three corners cannot allow (the right turns of a pseudotriangle total less
//! than pi). [`crate::verify::pseudo::check`] checks all of it independently.
//!
//! Complexity: O(n) after the triangulation (Theorem 5): linear-time twin matching (the half-edge
//! mesh of `algo/mesh.rs`), one work list, one face scan. With the triangulation, O(n log n) in
//! all.

use super::mesh::Mesh;
use super::{Pseudotriangle, Pseudotriangulation};
use crate::geom::kernel::cross;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;

/// No twin: a polygon edge (its other side is outside the polygon).
const NONE: usize = usize::MAX;

/// A minimal pseudotriangulation of `polygon` contained in `triangles` (a triangulation of it by
/// nondegenerate counter-clockwise triangles with no vertex inside a side, such as
/// [`crate::algo::plain::triangulate`] gives), by the greedy of Section 5.
///
/// `triangles` may instead triangulate the convex hull of the vertices, every polygon edge an
/// edge (what `pseudo-hull` falls back to at its deadline): the result is then a minimal
/// pseudotriangulation of the hull containing the polygon's edges, whose `edge_count` counts a
/// polygon edge with a face on both sides twice (the caller corrects it).
///
/// # Examples
/// ```
/// use minitri::{algo::{plain, pseudo}, Decimal, Polygon, RawPolygon};
/// let ring: Result<Vec<[Decimal; 2]>, minitri::NumberError> = [(0, 0), (4, 0), (4, 4), (0, 4)]
///     .iter()
///     .map(|&(x, y)| Ok([Decimal::parse(&x.to_string())?, Decimal::parse(&y.to_string())?]))
///     .collect();
/// let (polygon, _warnings) = Polygon::from_raw(&RawPolygon { rings: vec![ring?], ..Default::default() })?;
/// let start = plain::triangulate(&polygon)?;
/// let p = pseudo::minimal(&polygon, &start.triangles);
/// assert_eq!(p.faces.len(), 2); // a square has four corners: one diagonal must stay
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn minimal<P: Coord>(polygon: &Polygon<P>, triangles: &[[usize; 3]]) -> Pseudotriangulation {
    let mut greedy = Greedy::new(polygon, triangles);
    greedy.remove_edges();
    greedy.remove_triangles();
    greedy.faces()
}

/// The faces of the greedy over the triangulation's [`Mesh`] (polygon edges unlinked from their
/// twins, so that no face crosses them): each face a cycle of half-edges, `next`/`prev` walking
/// it counter-clockwise (at first the triangles, [`Mesh::next_in_triangle`]), merged as edges
/// are removed.
struct Greedy<'a, P: Coord> {
    points: &'a [P],
    mesh: Mesh,
    next: Vec<usize>,
    prev: Vec<usize>,
    removed: Vec<bool>,
}

impl<'a, P: Coord> Greedy<'a, P> {
    fn new(polygon: &'a Polygon<P>, triangles: &[[usize; 3]]) -> Greedy<'a, P> {
        let h = 3 * triangles.len();
        let mut mesh = Mesh::from_triangles(polygon.len(), triangles);
        // A polygon edge in either direction: a triangulation of the convex hull (the fallback
        // of `pseudo-hull`) has both sides of a polygon edge inside the hull.
        mesh.separate(|u, w| polygon.next(u) == w || polygon.next(w) == u);
        Greedy {
            points: polygon.points(),
            mesh,
            next: (0..h).map(Mesh::next_in_triangle).collect(),
            prev: (0..h).map(Mesh::prev_in_triangle).collect(),
            removed: vec![false; h],
        }
    }

    /// The opposite half-edge, or [`NONE`] on a polygon edge.
    fn twin(&self, e: usize) -> usize {
        self.mesh.twin_of(e).unwrap_or(NONE)
    }

    fn origin(&self, e: usize) -> usize {
        self.mesh.tail(e)
    }

    fn dest(&self, e: usize) -> usize {
        self.mesh.head(e)
    }

    /// Whether the turn `u -> a -> w` leaves an angle below pi on its left (a corner there).
    fn corner(&self, u: usize, a: usize, w: usize) -> bool {
        cross(self.points[u], self.points[a], self.points[w]) > 0
    }

    /// Lemma 4 at the vertex where `incoming` (of one face) meets `outgoing` (of the face on the
    /// other side of the removed edges): both faces' angles there are corners, and the merged
    /// angle `prev(incoming) .. dest(outgoing)` is not. `first` and `last` are the angles'
    /// other sides (the removed edges' far ends).
    fn loses_both(&self, u: usize, a: usize, w: usize, first: usize, last: usize) -> bool {
        self.corner(u, a, first) && self.corner(last, a, w) && !self.corner(u, a, w)
    }

    /// Lemma 4(a) for the diagonal of half-edge `e` (`a -> b`).
    fn edge_removable(&self, e: usize) -> bool {
        let t = self.twin(e);
        if t == NONE || self.removed[e] || self.next[e] == t || self.next[t] == e {
            return false;
        }
        let (a, b) = (self.origin(e), self.origin(t));
        // At a: u -> a -> b in e's face, b -> a -> w in t's face, merged u -> a -> w.
        let u = self.origin(self.prev[e]);
        let w = self.dest(self.next[t]);
        // At b: x -> b -> a in t's face, a -> b -> y in e's face, merged x -> b -> y.
        let x = self.origin(self.prev[t]);
        let y = self.dest(self.next[e]);
        self.loses_both(u, a, w, b, b) || self.loses_both(x, b, y, a, a)
    }

    /// Step 1: removes removable edges until none is left.
    fn remove_edges(&mut self) {
        let mut work: Vec<usize> = (0..self.next.len())
            .filter(|&e| self.twin(e) != NONE && e < self.twin(e))
            .collect();
        while let Some(e) = work.pop() {
            if !self.edge_removable(e) {
                continue;
            }
            let t = self.twin(e);
            let (pe, ne, pt, nt) = (self.prev[e], self.next[e], self.prev[t], self.next[t]);
            self.link(pe, nt);
            self.link(pt, ne);
            self.removed[e] = true;
            self.removed[t] = true;
            work.extend([pe, ne, pt, nt]);
        }
    }

    fn link(&mut self, from: usize, to: usize) {
        self.next[from] = to;
        self.prev[to] = from;
    }

    /// Lemma 4(b) for the triangular face of `sides` (each `sides[i]` from corner i to i + 1).
    fn triangle_removable(&self, sides: [usize; 3]) -> bool {
        if sides.iter().any(|&s| self.twin(s) == NONE) {
            return false;
        }
        (0..3).all(|i| {
            let (incoming, outgoing) = (sides[(i + 2) % 3], sides[i]);
            let a = self.origin(outgoing);
            // The face across `incoming` (c -> a) has a -> c, after u -> a.
            let across_in = self.twin(incoming);
            let u = self.origin(self.prev[across_in]);
            let c = self.dest(across_in);
            // The face across `outgoing` (a -> b) has b -> a, before a -> w.
            let across_out = self.twin(outgoing);
            let b = self.origin(across_out);
            let w = self.dest(self.next[across_out]);
            self.loses_both(u, a, w, c, b)
        })
    }

    /// Step 2: one scan of the faces, removing every removable triangle.
    fn remove_triangles(&mut self) {
        for e in 0..self.next.len() {
            if self.removed[e] {
                continue;
            }
            let sides = [e, self.next[e], self.next[self.next[e]]];
            if self.next[sides[2]] != e || !self.triangle_removable(sides) {
                continue;
            }
            // At each corner, the face across the incoming side continues into the face across
            // the outgoing side.
            let links: Vec<(usize, usize)> = (0..3)
                .map(|i| {
                    let (incoming, outgoing) = (sides[(i + 2) % 3], sides[i]);
                    (
                        self.prev[self.twin(incoming)],
                        self.next[self.twin(outgoing)],
                    )
                })
                .collect();
            for (from, to) in links {
                self.link(from, to);
            }
            for s in sides {
                self.removed[s] = true;
                let t = self.twin(s);
                self.removed[t] = true;
            }
        }
    }

    /// The faces left, each from its first corner (by vertex order of the walk).
    fn faces(&self) -> Pseudotriangulation {
        let mut seen = vec![false; self.next.len()];
        let mut faces = Vec::new();
        let mut edges = 0;
        for start in 0..self.next.len() {
            if self.removed[start] {
                continue;
            }
            if self.twin(start) == NONE || start < self.twin(start) {
                edges += 1;
            }
            if seen[start] {
                continue;
            }
            let mut cycle = Vec::new();
            let mut e = start;
            loop {
                seen[e] = true;
                cycle.push(self.origin(e));
                e = self.next[e];
                if e == start {
                    break;
                }
            }
            faces.push(Pseudotriangle::from_cycle(self.points, cycle));
        }
        Pseudotriangulation {
            faces,
            edge_count: edges,
            hull: None,
            stopped: None,
        }
    }
}

#[cfg(test)]
mod tests;
