//! The chord table: for every pair of vertices, is the closed segment between them a chord?
//!
//! A chord (`docs/algorithms.md`; Chen & Chang §1; Asano & Asano §3) is a closed segment between two
//! vertices that lies in the closed polygon: it may touch the boundary and run along edges.
//! Exactly: segment `v u` is a chord iff (1) at `v` and at `u` its direction lies in the closed
//! interior angle, (2) no edge crosses it properly, and (3) at every vertex inside it, both of its
//! directions lie in that vertex's closed interior angle.
//!
//! Method: an angular sweep around each vertex `v` (a rotational plane sweep, as in Lee's
//! visibility-graph algorithm, Lee 1978; de Berg et al., *Computational Geometry*, §15.2). The
//! other vertices are sorted by angle around `v`, then by distance. The sweep keeps the edges
//! whose open interior is cut by the ray from `v`, ordered by distance along the ray (a
//! `BTreeSet` compared by orientation tests only: edges never cross, so their order along any
//! common ray is the same). At each direction, edges ending there leave first, then the nearest
//! edge cut by the ray bounds what is visible, then edges starting there enter. Walking out along
//! the ray through the vertices in that direction applies (1) and (3) with the exact wedge test.
//! Works for polygons with holes as well (all rings' edges take part), and for the boundary walks
//! of touching rings, where a point may hold several stored vertices (`walk_out`).
//!
//! The same angular order also numbers the lines through each vertex ([`ChordTable::line`]):
//! `k` lies on the line through `i` and `j` exactly when `line(i, k) == line(i, j)`, which
//! lets the DP test collinearity with one comparison instead of an orientation test.
//!
//! Complexity: O(n log n) per vertex, O(n^2 log n) time in all; n^2 bits plus 2 n^2 bytes.

use crate::geom::kernel::Coord;
use crate::geom::kernel::{cmp_angle, cross, in_closed_wedge};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;
use std::collections::BTreeSet;

/// Which vertex pairs are chords, as a symmetric bit matrix over stored vertex indices, and the
/// numbering of the lines through each vertex.
#[derive(Clone, Debug)]
pub struct ChordTable {
    n: usize,
    bits: Vec<u64>,
    lines: Vec<u16>,
}

impl ChordTable {
    /// Computes the table for `polygon`.
    ///
    /// # Panics
    /// Above 65,536 vertices (line numbers are `u16`); the DP refuses far smaller inputs.
    pub fn new<P: Coord>(polygon: &Polygon<P>) -> ChordTable {
        let n = polygon.len();
        assert!(
            n <= 1 << 16,
            "the chord table is for polygons up to 65,536 vertices"
        );
        ChordTable::fill(polygon, vec![0; (n * n).div_ceil(64)], vec![0; n * n])
    }

    /// [`ChordTable::new`], or `None` when the memory of its tables (`n^2 (2 + 1/8)` bytes)
    /// cannot be had, or above 65,536 vertices.
    pub fn try_new<P: Coord>(polygon: &Polygon<P>) -> Option<ChordTable> {
        let n = polygon.len();
        if n > 1 << 16 {
            return None;
        }
        let bits = super::try_filled((n * n).div_ceil(64), 0)?;
        let lines = super::try_filled(n * n, 0)?;
        Some(ChordTable::fill(polygon, bits, lines))
    }

    /// The table for `polygon`, in `bits` and `lines` (zeroed, of the right sizes).
    fn fill<P: Coord>(polygon: &Polygon<P>, bits: Vec<u64>, lines: Vec<u16>) -> ChordTable {
        let n = polygon.len();
        let mut table = ChordTable { n, bits, lines };
        let mut visible = Vec::new();
        for v in 0..n {
            let order = visible_from(polygon, v, &mut visible);
            number_lines(polygon, v, &order, &mut table.lines[v * n..(v + 1) * n]);
            for &u in &visible {
                table.set(v, u);
            }
        }
        table
    }

    /// The number of the line through vertices `i` and `k` among the lines through `i`: equal
    /// for `k` and `j` exactly when `i`, `k`, `j` are collinear. Zero for `k == i`; a copy of
    /// `i`'s point (touching rings) has a number no other vertex has.
    #[inline]
    pub fn line(&self, i: usize, k: usize) -> u16 {
        self.lines[i * self.n + k]
    }

    /// The line numbers of all vertices around `i` (`line(i, k)` for every `k`).
    #[inline]
    pub fn lines_through(&self, i: usize) -> &[u16] {
        &self.lines[i * self.n..(i + 1) * self.n]
    }

    /// Whether the closed segment between stored vertices `a` and `b` is a chord (edges are).
    #[inline]
    pub fn is_chord(&self, a: usize, b: usize) -> bool {
        let k = a * self.n + b;
        self.bits[k / 64] >> (k % 64) & 1 == 1
    }

    fn set(&mut self, a: usize, b: usize) {
        for k in [a * self.n + b, b * self.n + a] {
            self.bits[k / 64] |= 1 << (k % 64);
        }
    }
}

/// An edge cut by the ray from `v`, oriented so that `v` lies on its left (`a -> b` turns
/// counter-clockwise around `v`).
#[derive(Clone, Copy, Debug)]
struct Cut<P> {
    a: P,
    b: P,
    edge: usize,
}

order_from_cmp!(Cut<P>);

impl<P: Coord> Ord for Cut<P> {
    /// Nearer to `v` along the common ray is Less. `f` lies wholly on `v`'s side of `e`'s line:
    /// `f` is nearer; wholly beyond: farther; otherwise `f` straddles `e`'s line, so (as edges do
    /// not cross) `e` lies wholly on one side of `f`'s line, which decides.
    fn cmp(&self, other: &Self) -> Ordering {
        if self.edge == other.edge {
            return Ordering::Equal;
        }
        let (s1, s2) = (
            cross(self.a, self.b, other.a),
            cross(self.a, self.b, other.b),
        );
        let self_nearer = if s1 >= 0 && s2 >= 0 {
            false
        } else {
            (s1 <= 0 && s2 <= 0)
                || (cross(other.a, other.b, self.a) >= 0 && cross(other.a, other.b, self.b) >= 0)
        };
        if self_nearer {
            Ordering::Less
        } else {
            Ordering::Greater
        }
    }
}

/// Numbers the lines through `v`: `order` holds the other vertices sorted by angle around `v`
/// (from the positive x axis, counter-clockwise). Directions in the upper half `[0, pi)` get new
/// numbers in order; each direction in the lower half takes the number of its opposite direction
/// if there is one (found by a merge, both halves being sorted), else a new one.
fn number_lines<P: Coord>(polygon: &Polygon<P>, v: usize, order: &[usize], out: &mut [u16]) {
    let c = polygon.point(v);
    let upper = |u: usize| crate::geom::kernel::above(c, polygon.point(u));
    let split = order.partition_point(|&u| upper(u));
    let (mut next_id, mut last): (u16, Option<usize>) = (0, None);
    for &u in &order[..split] {
        if last.is_none_or(|l| cross(c, polygon.point(l), polygon.point(u)) != 0) {
            next_id += 1;
        }
        out[u] = next_id;
        last = Some(u);
    }
    let (mut j, mut last) = (0, None::<usize>);
    for &u in &order[split..] {
        if let Some(l) = last {
            if cross(c, polygon.point(l), polygon.point(u)) == 0 {
                out[u] = out[l];
                continue;
            }
        }
        last = Some(u);
        // Upper directions before the opposite of u turn clockwise-of-opposite: cross(c, a, u) < 0.
        while j < split && cross(c, polygon.point(order[j]), polygon.point(u)) < 0 {
            j += 1;
        }
        if j < split && cross(c, polygon.point(order[j]), polygon.point(u)) == 0 {
            out[u] = out[order[j]];
        } else {
            next_id += 1;
            out[u] = next_id;
        }
    }
    // Copies of `v`'s point lie on no line through `v` with any other vertex: numbers of their
    // own (as `solve_walk` requires).
    for u in (0..polygon.len()).filter(|&u| u != v && polygon.point(u) == c) {
        next_id += 1;
        out[u] = next_id;
    }
}

/// Fills `out` with the vertices `u` such that `v u` is a chord; returns all other vertices
/// sorted by angle around `v`, then by distance.
pub(crate) fn visible_from<P: Coord>(
    polygon: &Polygon<P>,
    v: usize,
    out: &mut Vec<usize>,
) -> Vec<usize> {
    out.clear();
    let c = polygon.point(v);
    let (vp, vn) = (
        polygon.point(polygon.prev(v)),
        polygon.point(polygon.next(v)),
    );
    // Copies of `v`'s point (touching rings: one stored vertex per interior sector) are never
    // joined to `v` (a zero-length segment); every other vertex has a direction from `c`.
    let mut order: Vec<usize> = (0..polygon.len())
        .filter(|&u| polygon.point(u) != c)
        .collect();
    order.sort_unstable_by(|&a, &b| {
        let (pa, pb) = (polygon.point(a), polygon.point(b));
        cmp_angle(c, pa, pb).then_with(|| P::cmp_dist(c, pa, pb))
    });
    // The edge leaving vertex e, oriented counter-clockwise around v; None if it touches v or
    // lies on a line through v (it can then cut no ray from v in its interior).
    let cut = |e: usize| -> Option<Cut<P>> {
        let f = polygon.next(e);
        if e == v || f == v {
            return None;
        }
        let (p, q) = (polygon.point(e), polygon.point(f));
        match cross(c, p, q).cmp(&0) {
            Ordering::Greater => Some(Cut {
                a: p,
                b: q,
                edge: e,
            }),
            Ordering::Less => Some(Cut {
                a: q,
                b: p,
                edge: e,
            }),
            Ordering::Equal => None,
        }
    };
    let mut status: BTreeSet<Cut<P>> = (0..polygon.len())
        .filter_map(cut)
        .filter(|k| cmp_angle(c, k.a, k.b) == Ordering::Greater) // wraps past the +x axis
        .collect();
    let mut start = 0;
    while start < order.len() {
        let mut end = start + 1;
        let first = polygon.point(order[start]);
        while end < order.len() && cmp_angle(c, first, polygon.point(order[end])) == Ordering::Equal
        {
            end += 1;
        }
        let group = &order[start..end];
        for &u in group {
            for e in [polygon.prev(u), u] {
                if let Some(k) = cut(e) {
                    if k.b == polygon.point(u) {
                        status.remove(&k);
                    }
                }
            }
        }
        if in_closed_wedge(vp, c, vn, first) {
            walk_out(polygon, c, group, status.first(), out);
        }
        for &u in group {
            for e in [polygon.prev(u), u] {
                if let Some(k) = cut(e) {
                    if k.a == polygon.point(u) {
                        status.insert(k);
                    }
                }
            }
        }
        start = end;
    }
    order
}

/// Walks out from `c` along one direction through `group` (the vertices there, sorted by
/// distance), pushing onto `out` each vertex `u` such that `c u` is a chord, given `nearest`, the
/// nearest edge cut by the ray in its interior. A point may hold several stored vertices (the
/// copies of a touch point, each with its own angle): each copy whose closed angle holds the
/// direction back to `c` is seen, and the segment goes on beyond the point only through a copy
/// whose closed angle holds both directions (`crate::algo::walks::is_chord`'s definition; with
/// one vertex per point, as in a simple polygon, this is the plain test).
fn walk_out<P: Coord>(
    polygon: &Polygon<P>,
    c: P,
    group: &[usize],
    nearest: Option<&Cut<P>>,
    out: &mut Vec<usize>,
) {
    let wedge = |v: usize, target: P| polygon.angle_holds(v, target);
    let mut start = 0;
    while start < group.len() {
        let p = polygon.point(group[start]);
        if nearest.is_some_and(|k| cross(k.a, k.b, p) < 0) {
            return; // an edge crosses the segment before p
        }
        let end = start
            + group[start..]
                .iter()
                .take_while(|&&u| polygon.point(u) == p)
                .count();
        let beyond = group.get(end).map(|&w| polygon.point(w));
        let mut through = false;
        for &u in &group[start..end] {
            if wedge(u, c) {
                out.push(u);
                through |= beyond.is_some_and(|b| wedge(u, b));
            }
        }
        if !through {
            return;
        }
        start = end;
    }
}

/// The chord test straight from the definition, in O(n) per pair (the sweep's test oracle).
#[cfg(test)]
pub(crate) fn is_chord_naive<P: Coord>(polygon: &Polygon<P>, v: usize, u: usize) -> bool {
    use crate::geom::kernel::{properly_cross, strictly_between};
    let (a, b) = (polygon.point(v), polygon.point(u));
    let wedge = |v: usize, target: P| polygon.angle_holds(v, target);
    if !wedge(v, b) || !wedge(u, a) {
        return false;
    }
    (0..polygon.len()).all(|w| {
        let (p, q) = (polygon.point(w), polygon.point(polygon.next(w)));
        !properly_cross(a, b, p, q) && (!strictly_between(a, p, b) || (wedge(w, a) && wedge(w, b)))
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polygon, raw, U_SHAPE};

    fn assert_matches_naive(p: &Polygon) {
        let table = ChordTable::new(p);
        for a in 0..p.len() {
            for b in 0..p.len() {
                if a != b {
                    assert_eq!(
                        table.is_chord(a, b),
                        is_chord_naive(p, a, b),
                        "{a}-{b} in {:?}",
                        p.points()
                    );
                    for k in (0..p.len()).filter(|&k| k != a && k != b) {
                        let collinear = cross(p.point(a), p.point(b), p.point(k)) == 0;
                        assert_eq!(
                            table.line(a, k) == table.line(a, b),
                            collinear,
                            "lines {a} {b} {k}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn chords_of_a_u_shape_with_flat_vertices() {
        let p = polygon(&[&U_SHAPE]);
        let t = ChordTable::new(&p);
        assert!(
            t.is_chord(0, 3),
            "along the bottom edges, through two flat vertices"
        );
        assert!(
            t.is_chord(11, 8),
            "from (3,3) to (4,3): along the notch bottom"
        );
        assert!(
            t.is_chord(11, 7),
            "(3,3)-(5,3) passes through the reflex vertex (4,3)"
        );
        assert!(!t.is_chord(10, 6), "(3,4)-(5,4) crosses the notch");
        assert!(!t.is_chord(9, 6), "(4,4)-(5,4) is outside");
        assert_matches_naive(&p);
    }

    #[test]
    fn sweep_matches_the_definition_on_random_polygons() {
        // Random simple polygons on a small grid by growing a triangle one vertex at a time.
        let mut seed = 0x2545_F491_4F6C_DD1Du64;
        let mut rnd = |n: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed % n) as i64
        };
        let mut tested = 0;
        for _ in 0..400 {
            let mut ring = vec![(0, 0), (6, 0), (3, 6)];
            for _ in 0..rnd(12) {
                let at = rnd(ring.len() as u64) as usize + 1;
                let mut next = ring.clone();
                next.insert(at, (rnd(7), rnd(7)));
                if Polygon::from_raw(&raw(&[&next])).is_ok() {
                    ring = next;
                }
            }
            assert_matches_naive(&polygon(&[&ring]));
            tested += 1;
        }
        assert_eq!(tested, 400);
    }
}
