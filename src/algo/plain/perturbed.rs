//! The copies of touch points moved symbolically into their sectors, so that the monotone sweep
//! of [`super::monotone`] triangulates boundary walks whose rings touch (`docs/touching.md`) in
//! O(N log N), as it does simple polygons with holes.
//!
//! Input contract: a valid [`Polygon`] (walks: the outer one counter-clockwise, hole walks
//! clockwise, interior on the left of every edge; the stored vertices at one point, the
//! *copies*, have closed angles, their *sectors*, that meet only at the point, separated by
//! wedges of positive angle outside the region; no two consecutive stored vertices share a
//! point). Output guarantee: [`moved`] gives one [`Moved`] per stored vertex, whose height
//! order and orientation tests ([`SweepPoint`]) are those of the polygon except between copies
//! of one point, where they are those of the copies moved infinitesimally into their sectors.
//! Every decision is a sign of an exact [`cross`] or [`dot`] of input points.
//!
//! # The perturbation
//!
//! A copy `a` at point `P`, with `w_a` the vector to its next vertex along its walk, moves to
//! `P + ε_a d_a` with the formal direction `d_a = s_a w_a + η rot(w_a)`: `rot` the quarter-turn
//! counter-clockwise, `s_a = +1` when the sector is at most a half-turn (then `d_a` is `w_a`
//! turned slightly into the sector, which runs counter-clockwise from `w_a`) and `s_a = -1` when
//! it is reflex (then `d_a` is `-w_a` turned slightly clockwise: inside the mirror image of the
//! outside wedge, so the moved sector lies inside the old one and misses the point itself).
//! The infinitesimals are ordered `1 >> η >> ε_1 >> ε_2 >> ...`, `ε_k` for the copy of stored
//! index `k - 1`, with `ε_(k+1) << ε_k η` and every product of smaller ones below a larger one
//! (as `ε_k = δ^(2^k)`, Edelsbrunner and Mücke's *simulation of simplicity*): monomials compare
//! by their largest index first. Moved so, every sector lies inside its old self and away from
//! the point by about `ε_a η`, while a copy of higher index sits within `ε_(a+1) << ε_a η` of the
//! point: the moved copies' sectors are pairwise disjoint and the moved walks are simple rings
//! (a hole walk touching the outer walk becomes part of it through the gap opened at the point,
//! as the walks already say).
//!
//! Heights: two copies of one point compare by the larger displacement, `ε_a` for the smaller
//! index `a`, so `a` is above exactly when `d_a` points up (`s_a w_a.y`, or `w_a.x` when `w_a`
//! is horizontal; never zero). Orientation: with `e_i = ε_i d_i`,
//! `cross(X0', X1', X2') = cross(X0, X1, X2) + Σ e_i × (X_(i+1) - X_(i+2)) + Σ e_i × e_(i+1)`
//! (indices mod 3); the sign is that of the first monomial with a non-zero coefficient, each
//! coefficient a polynomial in `η` read from its lowest power:
//! `d_a × V = s_a (w_a × V) - η (w_a · V)` and
//! `d_a × d_b = s_a s_b (w_a × w_b) + η (s_a - s_b)(w_a · w_b) + η² (w_a × w_b)`.
//!
//! Only triples with two arguments at one point are perturbed; a triple of three distinct
//! collinear points keeps its zero, as in the polygon: the sweep's proofs use such tests only on
//! flat vertices and the stack algorithm's collinear waits, where the polygon's own answer keeps
//! every triangle of positive area. The result is checked all the same by [`tiles`] (every
//! triangle positive, the triangles' boundary exactly the walks), so an error here could only
//! cost time, never give a wrong triangulation ([`super::walks`] then takes its fallback).

use super::monotone::SweepPoint;
use crate::geom::kernel::{cross, dot, Coord};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;

/// A stored vertex for the sweep: its point and, for a copy of a touch point, how it is moved
/// (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Moved<P> {
    at: P,
    /// 0 for a vertex alone at its point, else 1 + its stored index (the `k` of `ε_k`).
    rank: u32,
    /// The next vertex along its walk (`w = next - at`).
    next: P,
    /// Whether the sector is reflex (`s = -1`).
    reflex: bool,
}

/// The stored vertices of `polygon` as [`Moved`] points, the copies those marked when the rings
/// were relinked ([`Polygon::is_copy`]): O(N).
/// With `turned`, the points are those (the polygon's turned by a rotation, as
/// [`super::turned_for_walking`] does: the same orientations, another sweep direction).
///
/// # Panics
/// Never on a polygon of fewer than 2^32 - 1 stored vertices (far beyond any polygon the
/// readers accept).
pub(crate) fn moved<P: Coord>(polygon: &Polygon<P>, turned: Option<&[P]>) -> Vec<Moved<P>> {
    let n = polygon.len();
    let pt = |i: usize| turned.map_or_else(|| polygon.point(i), |t| t[i]);
    (0..n)
        .map(|i| {
            let (prev, at, next) = (pt(polygon.prev(i)), pt(i), pt(polygon.next(i)));
            // The copies were found while the rings were relinked (`Polygon::is_copy`).
            let rank = if polygon.is_copy(i) {
                u32::try_from(i + 1).expect("fewer than 2^32 - 1 stored vertices")
            } else {
                0
            };
            Moved {
                at,
                rank,
                next,
                reflex: cross(prev, at, next) < 0,
            }
        })
        .collect()
}

impl<P: Coord> Moved<P> {
    /// `s_a`, as a sign.
    fn s(self) -> i32 {
        if self.reflex {
            -1
        } else {
            1
        }
    }

    /// Whether the moved copy lies above its point: the sign of `d.y` (see the module
    /// documentation).
    fn moves_up(self) -> bool {
        match P::cmp_y(self.next, self.at) {
            Ordering::Equal => P::cmp_x(self.next, self.at) == Ordering::Greater,
            up => (up == Ordering::Greater) == (self.s() > 0),
        }
    }

    /// The sign of `d × (to - from)` as a polynomial in `η`: its lowest non-zero coefficient.
    fn d_cross(self, from: P, to: P) -> i32 {
        let (w, v) = (P::vector(self.at, self.next), P::vector(from, to));
        let c = signum(P::vector_cross(w, v)) * self.s();
        if c != 0 {
            c
        } else {
            -signum(P::vector_dot(w, v))
        }
    }

    /// The sign of `d_a × d_b` as a polynomial in `η`.
    fn d_cross_d(a: Self, b: Self) -> i32 {
        let (wa, wb) = (P::vector(a.at, a.next), P::vector(b.at, b.next));
        let c = signum(P::vector_cross(wa, wb));
        if c != 0 {
            return c * a.s() * b.s();
        }
        if a.s() != b.s() {
            return a.s() * signum(P::vector_dot(wa, wb));
        }
        0 // η² (w_a × w_b), zero too
    }
}

fn signum(v: i128) -> i32 {
    v.signum() as i32
}

fn to_ordering(sign: i32) -> Ordering {
    sign.cmp(&0)
}

impl<P: Coord> SweepPoint for Moved<P> {
    fn cmp_height(self, other: Self) -> Ordering {
        let plain = self.at.cmp_height(other.at);
        if plain != Ordering::Equal || self.rank == other.rank {
            return plain;
        }
        // The smaller index moves further and decides.
        if self.rank < other.rank {
            if self.moves_up() {
                Ordering::Greater
            } else {
                Ordering::Less
            }
        } else if other.moves_up() {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }

    fn orient(a: Self, b: Self, c: Self) -> Ordering {
        let plain = cross(a.at, b.at, c.at);
        if plain != 0 {
            return plain.cmp(&0);
        }
        let x = [a, b, c];
        let shared = a.at == b.at || b.at == c.at || a.at == c.at;
        if !shared || a == b || b == c || a == c {
            return Ordering::Equal;
        }
        // The perturbed arguments, by rank (largest displacement first).
        let mut args: Vec<usize> = (0..3).filter(|&i| x[i].rank > 0).collect();
        args.sort_unstable_by_key(|&i| x[i].rank);
        // Monomials largest first: {1}, {2}, {1,2}, {3}, {1,3}, {2,3} (ranks of `args`).
        for k in 0..args.len() {
            let i = args[k];
            let single = x[i].d_cross(x[(i + 2) % 3].at, x[(i + 1) % 3].at);
            if single != 0 {
                return to_ordering(single);
            }
            for &j in &args[..k] {
                // The pair term is e_i × e_(i+1) for the cyclic pair.
                let pair = if j == (i + 1) % 3 {
                    Moved::d_cross_d(x[i], x[j])
                } else {
                    Moved::d_cross_d(x[j], x[i])
                };
                if pair != 0 {
                    return to_ordering(pair);
                }
            }
        }
        Ordering::Equal
    }

    fn same_side(w: Self, reference: Self, q: Self) -> bool {
        dot(w.at, reference.at, q.at) > 0
    }
}

/// The monotone sweep of [`super::monotone`] over the walks, the copies of touch points moved
/// symbolically into their sectors ([`moved`]): O(N log N). `None` when the result fails
/// [`tiles`] (the theory excludes it; checked so that a mistake costs time, not a wrong
/// answer).
pub(crate) fn swept<P: Coord>(polygon: &Polygon<P>) -> Option<Vec<[usize; 3]>> {
    let turned = super::turned_for_walking(polygon);
    let points = moved(polygon, turned.as_deref());
    let triangles = super::monotone::try_triangulate_rings(&points, polygon.ring_starts())?;
    tiles(polygon, &triangles).then_some(triangles)
}

/// Whether `triangles` triangulate the walks: `N + 2w - 2` of them, each of positive area, and
/// their boundary, as a chain of stored-index edges, exactly the walks (every walk edge once in
/// its direction, every other edge as often in each direction). Then every point of the plane
/// off the edges lies in as many triangles as the walks wind around it (a positive triangle
/// counts once, and the count changes only across the chain's boundary): one inside the region,
/// none outside; and around each copy the triangles turn from its next edge to its previous one
/// through its own sector alone (their angles sum to the sectors'). O(T log T).
pub(crate) fn tiles<P: Coord>(polygon: &Polygon<P>, triangles: &[[usize; 3]]) -> bool {
    let n = polygon.len();
    if triangles.len() + 2 != n + 2 * polygon.holes() {
        return false;
    }
    let pt = |i: usize| polygon.point(i);
    // The edges bucketed by their smaller end (a counting sort), each bucket then sorted: the
    // buckets are as small as the vertices' degrees.
    let mut start = vec![0usize; n + 1];
    for t in triangles {
        if t.iter().any(|&v| v >= n) || cross(pt(t[0]), pt(t[1]), pt(t[2])) <= 0 {
            return false;
        }
        for k in 0..3 {
            start[t[k].min(t[(k + 1) % 3]) + 1] += 1;
        }
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let mut fill = start.clone();
    let mut edges: Vec<(usize, i32)> = vec![(0, 0); start[n]];
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            let (low, entry) = if a < b { (a, (b, 1)) } else { (b, (a, -1)) };
            edges[fill[low]] = entry;
            fill[low] += 1;
        }
    }
    let mut walk_edges = 0;
    for a in 0..n {
        let bucket = &mut edges[start[a]..start[a + 1]];
        bucket.sort_unstable_by_key(|&(b, _)| b);
        for run in bucket.chunk_by(|x, y| x.0 == y.0) {
            let b = run[0].0;
            let net: i32 = run.iter().map(|e| e.1).sum();
            let expected = if polygon.next(a) == b {
                1
            } else if polygon.next(b) == a {
                -1
            } else {
                0
            };
            if net != expected {
                return false;
            }
            walk_edges += usize::from(expected != 0);
        }
    }
    walk_edges == n
}
