//! The exact minimum triangulation of a polygon with 1 or 2 holes, by dynamic programming over
//! the polygon with its holes cut open.
//!
//! T. Asano and T. Asano, "Topics on triangulation of polygons",
//! §3, second part: for a polygonal
//! region with k windows (holes), cut one hole open by a triangle that has an edge on the hole
//! and its apex off it, which leaves a region with k - 1 holes, and recurse; O(n^{3+2k}).
//!
//! Input contract: a valid [`Polygon`] with 1 or 2 holes (outer ring counter-clockwise, holes
//! clockwise, interior on the left of every edge; flat vertices and any collinearity allowed).
//! Output guarantee: a [`Triangulation`] with the minimum number of triangles, in stored vertex
//! indices, with `triangles.len() == n + 2w - 2 - degenerate.len()`.
//!
//! # Overview
//! 1. The chord table of the polygon ([`super::chords`], all rings' edges take part), and which
//!    chords are *elementary* (no vertex strictly inside them).
//! 2. Cut the holes open along *bridges*: an elementary chord from a vertex of hole 1 to a
//!    vertex of another ring (the outer ring or hole 2) is a slit; removing it leaves a region
//!    with one hole fewer, whose boundary walk goes `.. v, u, (around the hole from u back to u),
//!    u, v ..` and visits `u` and `v` twice (a weakly simple polygon). With two holes, the hole
//!    that is left (hole 2, or holes 1 and 2 joined by the first slit) is cut again along a
//!    bridge to the rest. Every bridge of every choice is tried.
//! 3. On each cut walk of `m = n + 2k` positions, the DP of [`super::asano`] (`cost[i][j]` over
//!    walk positions, zero-area dummies free). Its chords are segments between two walk
//!    positions that are chords of the original polygon, cross no slit, leave each end inside
//!    that *occurrence*'s wedge (a point visited twice has its angle split by the slit between
//!    its two occurrences), pass any point visited twice inside one occurrence's wedge, and run
//!    along a slit (if they contain one) on one side of it only (the occurrences they use at its
//!    two ends are neighbours in the walk).
//! 4. The cheapest walk wins; its triangles are mapped back to stored vertices and the
//!    degenerate triangles read off them (`super::t_junctions`), as for the hole-free DP.
//!
//! Why this is exact. Every triangulation of a cut walk is one of the polygon (its triangles
//! lie in the polygon, disjoint, and cover it). Conversely, take a minimum triangulation of the
//! polygon and split its triangles' sides at the vertices lying on them: the pieces form a
//! connected plane graph containing every ring, so some piece joins hole 1 to another ring; it
//! is an elementary chord, and no triangle crosses it, so the triangulation is one of the walk
//! cut along it (and likewise for the second cut, by a piece other than the first). So the
//! minimum over all cuts is the minimum of the polygon.
//!
//! Departures from the paper: the paper removes a *triangle* with an edge on the hole and its
//! apex off the hole. With T-junctions that triangle's side may be longer than the hole edge
//! (its ends elsewhere on the hole or on another ring), and in the DP's model with dummies the
//! triangle on a hole edge may be a dummy with all corners on the hole (a flat hole vertex), so
//! no such triangle need exist. Cutting along a segment (a bridge) instead needs only that the
//! triangulation's sides connect the rings, which always holds; the walk then has `n + 2`
//! positions per cut instead of `n + 1`. A fixed hole edge with only its apex enumerated (n
//! choices instead of the paper's n^2) would not be exact: the triangle on a hole edge deep in a
//! pocket of the hole can have its apex on the hole itself, and removing it does not cut the
//! hole open.
//!
//! Complexity: with `n_1`, `n_2` the holes' sizes, at most `n_1 (n - n_1)` bridges for the first
//! cut and `n_2 (n - n_2)` for the second, each walk O(m^3) (DP) plus O(m^2) (its chords):
//! O(n^5) time with one hole, O(n^7) with two (the paper's O(n^{3+2k})); O(n^2) memory. Limits:
//! [`ONE_HOLE_LIMIT`] and [`TWO_HOLES_LIMIT`] vertices (a few seconds at most), and at most
//! [`MAX_HOLES`] holes; beyond, it refuses with an estimate.

use super::asano::solve_walk;
use super::chords::ChordTable;
use super::{Algorithm, TriangulateError, Triangulation};
use crate::geom::kernel::Coord;
use crate::geom::kernel::{in_closed_wedge, properly_cross, strictly_between};
use crate::geom::polygon::Polygon;
use std::collections::BTreeMap;

/// The most holes the DP handles (its time grows like n^(3+2k) with k holes).
pub const MAX_HOLES: usize = 2;

/// The largest polygon (vertices over all rings) the DP accepts with one hole (about a second
/// at worst; docs/benchmarks.md).
pub const ONE_HOLE_LIMIT: usize = 100;

/// The largest polygon (vertices over all rings) the DP accepts with two holes (a few seconds
/// at worst; docs/benchmarks.md).
pub const TWO_HOLES_LIMIT: usize = 40;

/// The size limit for a polygon with `holes` holes (1 or 2), at most `dp_limit`.
pub fn size_limit(holes: usize, dp_limit: usize) -> usize {
    let own = if holes <= 1 {
        ONE_HOLE_LIMIT
    } else {
        TWO_HOLES_LIMIT
    };
    own.min(dp_limit)
}

/// Estimated worst-case time for `n` vertices and `holes` holes, in words: the number of cuts
/// when the holes hold a third (two holes) or half (one hole) of the vertices and every pair is
/// a chord, times the DP on each walk.
pub fn estimate(n: usize, holes: usize) -> String {
    let n = n as f64;
    let walk = |m: f64| m.powi(3) / 6.0 + m.powi(2) / 2.0;
    let steps = if holes <= 1 {
        (n / 2.0).powi(2) * walk(n + 2.0)
    } else {
        (n / 3.0 * (2.0 * n / 3.0)).powi(2) * walk(n + 4.0)
    };
    // Calibrated on convex rings (release build; docs/benchmarks.md): an overestimate, by 2 to 5
    // times.
    let seconds = 3e-9 * steps;
    if seconds >= 86_400.0 {
        format!("{:.0} days", seconds / 86_400.0)
    } else if seconds >= 3600.0 {
        format!("{:.1} hours", seconds / 3600.0)
    } else if seconds >= 60.0 {
        format!("{:.0} minutes", seconds / 60.0)
    } else {
        format!("{seconds:.1} s")
    }
}

/// The minimum triangulation of a polygon with 1 or 2 holes.
///
/// # Errors
/// [`TriangulateError::TooManyHoles`] with more than [`MAX_HOLES`] holes (or none: use
/// [`super::asano::triangulate`]); [`TriangulateError::TooLargeWithHoles`] above
/// [`size_limit`]`(holes, dp_limit)` vertices.
///
/// # Examples
/// ```
/// # fn main() -> Result<(), Box<dyn std::error::Error>> {
/// use minitri::{algo::asano_holes, Decimal, Polygon, RawPolygon};
/// let ring = |pts: &[(i32, i32)]| -> Vec<[Decimal; 2]> {
///     pts.iter()
///         .map(|&(x, y)| [Decimal::parse(&x.to_string()).unwrap(), Decimal::parse(&y.to_string()).unwrap()])
///         .collect()
/// };
/// let raw = RawPolygon {
///     rings: vec![ring(&[(0, 0), (3, 0), (3, 3), (0, 3)]), ring(&[(1, 1), (2, 1), (2, 2), (1, 2)])],
///     ..Default::default()
/// };
/// let (square_with_hole, _) = Polygon::from_raw(&raw)?;
/// let t = asano_holes::triangulate(&square_with_hole, 3000)?;
/// assert_eq!(t.triangles.len(), 8); // n + 2w - 2: no vertex can lie inside a triangle side
/// # Ok(())
/// # }
/// ```
pub fn triangulate<P: Coord>(
    polygon: &Polygon<P>,
    dp_limit: usize,
) -> Result<Triangulation, TriangulateError> {
    let holes = polygon.holes();
    if holes == 0 || holes > MAX_HOLES {
        return Err(TriangulateError::TooManyHoles {
            holes,
            max: MAX_HOLES,
        });
    }
    let n = polygon.len();
    let limit = size_limit(holes, dp_limit);
    if n > limit {
        return Err(TriangulateError::TooLargeWithHoles {
            n,
            holes,
            limit,
            time: estimate(n, holes),
        });
    }
    let cutter = Cutter::new(polygon);
    let rings: Vec<Vec<usize>> = (0..=holes)
        .map(|r| polygon.ring_range(r).collect())
        .collect();
    let mut best: Option<Cheapest> = None;
    let lower = polygon.minimum_bounds().0;
    let done = |best: &Option<Cheapest>| best.as_ref().is_some_and(|b| b.triangles.len() <= lower);
    if holes == 1 {
        for (a, q) in cutter.bridges(&rings[1], &rings[0], &[]) {
            let walk = merge(&rings[0], q, &rings[1], a);
            cutter.solve(&walk, &[(rings[1][a], rings[0][q])], &mut best);
            if done(&best) {
                break;
            }
        }
    } else {
        'cuts: for target in [0, 2] {
            for (a, q) in cutter.bridges(&rings[1], &rings[target], &[]) {
                let first = (rings[1][a], rings[target][q]);
                let merged = merge(&rings[target], q, &rings[1], a);
                let (hole, outer) = if target == 0 {
                    (&rings[2], &merged)
                } else {
                    (&merged, &rings[0])
                };
                for (a2, q2) in cutter.bridges(hole, outer, &[first]) {
                    let walk = merge(outer, q2, hole, a2);
                    cutter.solve(&walk, &[first, (hole[a2], outer[q2])], &mut best);
                    if done(&best) {
                        break 'cuts;
                    }
                }
            }
        }
    }
    // A valid polygon has a triangulation, and its sides join every hole to another ring: some
    // cut has one (see the module documentation).
    let best = best.expect("some cut of a valid polygon has a triangulation");
    let degenerate = super::t_junctions(polygon, &best.triangles, super::Junctions::Rings);
    debug_assert_eq!(
        degenerate.len(),
        best.dummies,
        "each dummy saves exactly one triangle"
    );
    Ok(Triangulation {
        algorithm: Algorithm::Asano,
        triangles: best.triangles,
        degenerate,
        optimal: true,
        lower_bound: None,
        stopped: None,
    })
}

/// The cheapest triangulation found so far, in stored vertex indices.
struct Cheapest {
    triangles: Vec<[usize; 3]>,
    dummies: usize,
}

/// The walk `target[..=q], hole[a..], hole[..=a], target[q..]`: `hole` (a closed walk) joined
/// to `target` (a closed walk) by the slit from `hole[a]` to `target[q]`, both visited twice.
fn merge(target: &[usize], q: usize, hole: &[usize], a: usize) -> Vec<usize> {
    let mut walk = Vec::with_capacity(target.len() + hole.len() + 2);
    walk.extend_from_slice(&target[..=q]);
    walk.extend_from_slice(&hole[a..]);
    walk.extend_from_slice(&hole[..=a]);
    walk.extend_from_slice(&target[q..]);
    walk
}

/// What all cuts share: the polygon, its chord table, and its elementary chords.
struct Cutter<'a, P: Coord> {
    polygon: &'a Polygon<P>,
    chords: ChordTable,
    /// `elementary[u * n + v]`: no vertex lies strictly inside segment `u v`.
    elementary: Vec<bool>,
}

impl<'a, P: Coord> Cutter<'a, P> {
    fn new(polygon: &'a Polygon<P>) -> Cutter<'a, P> {
        let n = polygon.len();
        let chords = ChordTable::new(polygon);
        let mut elementary = vec![false; n * n];
        for u in 0..n {
            for v in u + 1..n {
                let (pu, pv) = (polygon.point(u), polygon.point(v));
                let free = chords.is_chord(u, v)
                    && (0..n).all(|w| !strictly_between(pu, polygon.point(w), pv));
                elementary[u * n + v] = free;
                elementary[v * n + u] = free;
            }
        }
        Cutter {
            polygon,
            chords,
            elementary,
        }
    }

    fn point(&self, v: usize) -> P {
        self.polygon.point(v)
    }

    /// Whether the direction from walk position `p` towards `target` lies in the closed wedge of
    /// that occurrence (between the walk's previous and next points).
    fn in_wedge(&self, walk: &[usize], p: usize, target: P) -> bool {
        let m = walk.len();
        in_closed_wedge(
            self.point(walk[(p + m - 1) % m]),
            self.point(walk[p]),
            self.point(walk[(p + 1) % m]),
            target,
        )
    }

    /// The bridges `(a, q)` from position `a` of the closed walk `hole` to position `q` of the
    /// closed walk `other`: elementary chords, leaving both occurrences inside their wedges,
    /// crossing none of the `slits` already cut.
    fn bridges(
        &self,
        hole: &[usize],
        other: &[usize],
        slits: &[(usize, usize)],
    ) -> Vec<(usize, usize)> {
        let n = self.polygon.len();
        let mut out = Vec::new();
        for (a, &u) in hole.iter().enumerate() {
            for (q, &v) in other.iter().enumerate() {
                let (pu, pv) = (self.point(u), self.point(v));
                if self.elementary[u * n + v]
                    && self.in_wedge(hole, a, pv)
                    && self.in_wedge(other, q, pu)
                    && slits
                        .iter()
                        .all(|&(x, y)| !properly_cross(pu, pv, self.point(x), self.point(y)))
                {
                    out.push((a, q));
                }
            }
        }
        out
    }

    /// Runs the DP on one cut walk (no holes left) and keeps its triangulation if it is the
    /// cheapest so far.
    fn solve(&self, walk: &[usize], slits: &[(usize, usize)], best: &mut Option<Cheapest>) {
        let m = walk.len();
        let mut occurrences: BTreeMap<usize, Vec<usize>> = BTreeMap::new();
        for (p, &v) in walk.iter().enumerate() {
            occurrences.entry(v).or_default().push(p);
        }
        occurrences.retain(|_, positions| positions.len() > 1);
        let cut = Cut {
            cutter: self,
            walk,
            slits,
            repeated: occurrences.into_iter().collect(),
        };
        let mut chord = vec![false; m * m];
        for p in 0..m {
            for q in p + 1..m {
                let is = q == p + 1 || (p == 0 && q == m - 1) || cut.is_chord(p, q);
                chord[p * m + q] = is;
                chord[q * m + p] = is;
            }
        }
        let mut lines = vec![0u16; m * m];
        for p in 0..m {
            for q in 0..m {
                lines[p * m + q] = self.chords.line(walk[p], walk[q]);
            }
        }
        let Some(result) = solve_walk(
            m,
            |p| self.point(walk[p]),
            |p, q| chord[p * m + q],
            |p| &lines[p * m..(p + 1) * m],
            None,
        ) else {
            return;
        };
        if best
            .as_ref()
            .is_some_and(|b| b.triangles.len() <= result.triangles.len())
        {
            return;
        }
        *best = Some(Cheapest {
            triangles: result
                .triangles
                .iter()
                .map(|t| t.map(|p| walk[p]))
                .collect(),
            dummies: result.dummies,
        });
    }
}

/// One cut walk: the polygon's vertices in walk order, the slits cut, and the vertices the walk
/// visits more than once with their positions.
struct Cut<'a, 'b, P: Coord> {
    cutter: &'b Cutter<'a, P>,
    walk: &'b [usize],
    slits: &'b [(usize, usize)],
    repeated: Vec<(usize, Vec<usize>)>,
}

impl<P: Coord> Cut<'_, '_, P> {
    /// Whether the segment between walk positions `p` and `q` is a chord of the cut walk: a
    /// chord of the polygon, crossing no slit, inside the wedge of each end's occurrence; at any
    /// point visited twice that it passes through, inside one occurrence's wedge; and along any
    /// slit it contains, on one side of it (its occurrences at the slit's ends are neighbours).
    fn is_chord(&self, p: usize, q: usize) -> bool {
        let c = self.cutter;
        let (vp, vq) = (self.walk[p], self.walk[q]);
        if vp == vq || !c.chords.is_chord(vp, vq) {
            return false;
        }
        let (a, b) = (c.point(vp), c.point(vq));
        if self
            .slits
            .iter()
            .any(|&(u, v)| properly_cross(a, b, c.point(u), c.point(v)))
        {
            return false;
        }
        // The occurrences the segment can use at each point visited twice that lies on it (at
        // most 4 such points, 2 slits with 2 ends, each visited at most 3 times).
        let mut on = [(usize::MAX, [0usize; 3], 0usize); 4];
        let mut count = 0;
        for (x, positions) in &self.repeated {
            let mut entry = (*x, [0usize; 3], 0usize);
            if *x == vp || *x == vq {
                let o = if *x == vp { p } else { q };
                if !c.in_wedge(self.walk, o, if *x == vp { b } else { a }) {
                    return false;
                }
                entry.1[0] = o;
                entry.2 = 1;
            } else if strictly_between(a, c.point(*x), b) {
                for &o in positions {
                    if c.in_wedge(self.walk, o, a) && c.in_wedge(self.walk, o, b) {
                        entry.1[entry.2] = o;
                        entry.2 += 1;
                    }
                }
                if entry.2 == 0 {
                    return false;
                }
            } else {
                continue;
            }
            on[count] = entry;
            count += 1;
        }
        let on = &on[..count];
        // Slits lying on the segment (both ends on it): one side only.
        let index = |v: usize| on.iter().position(|e| e.0 == v);
        let mut along = [(0usize, 0usize); 2];
        let mut slits_along = 0;
        for &(u, v) in self.slits {
            if let (Some(i), Some(j)) = (index(u), index(v)) {
                along[slits_along] = (i, j);
                slits_along += 1;
            }
        }
        let along = &along[..slits_along];
        if along.is_empty() {
            return true;
        }
        let m = self.walk.len();
        let neighbours = |o: usize, r: usize| (o + 1) % m == r || (r + 1) % m == o;
        // Try every choice of occurrences (at most 4 points with at most 3 occurrences each).
        let mut choice = [0usize; 4];
        loop {
            let chosen = |i: usize| on[i].1[choice[i]];
            if along.iter().all(|&(i, j)| neighbours(chosen(i), chosen(j))) {
                return true;
            }
            let mut k = 0;
            while k < on.len() {
                choice[k] += 1;
                if choice[k] < on[k].2 {
                    break;
                }
                choice[k] = 0;
                k += 1;
            }
            if k == on.len() {
                return false;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::polygon;
    use crate::verify;

    /// The DP's triangulation, checked independently and against the count formula.
    fn minimum(rings: &[&[(i64, i64)]]) -> usize {
        let p = polygon(rings);
        let t = triangulate(&p, usize::MAX).unwrap();
        let report = verify::check(&p, &t);
        assert!(report.valid, "{rings:?}: {:?}", report.problems);
        assert_eq!(
            t.triangles.len(),
            p.len() + 2 * p.holes() - 2 - t.degenerate.len()
        );
        t.triangles.len()
    }

    const SQUARE: [(i64, i64); 4] = [(0, 0), (3, 0), (3, 3), (0, 3)];

    #[test]
    fn a_square_with_a_square_hole_needs_eight() {
        // n + 2w - 2 = 8 + 2 - 2: no vertex lies on a line through two others inside the region
        // in a way that could save a triangle.
        assert_eq!(minimum(&[&SQUARE, &[(1, 1), (2, 1), (2, 2), (1, 2)]]), 8);
    }

    #[test]
    fn hole_vertices_collinear_with_outer_ones_save_triangles() {
        // Outer square with a midpoint on each side; the hole's sides lie on the lines through
        // those midpoints... here the hole (2,2)-(4,2)-(4,4)-(2,4) in the square 0..6 with
        // vertices (2,0), (4,0) below: the lines x = 2 and x = 4 and y = 2, y = 4 each carry an
        // outer vertex and two hole vertices.
        let outer = [
            (0, 0),
            (2, 0),
            (4, 0),
            (6, 0),
            (6, 2),
            (6, 4),
            (6, 6),
            (4, 6),
            (2, 6),
            (0, 6),
            (0, 4),
            (0, 2),
        ];
        let hole = [(2, 2), (4, 2), (4, 4), (2, 4)];
        let plain = outer.len() + hole.len(); // n + 2w - 2
        let count = minimum(&[&outer, &hole]);
        assert!(count < plain, "{count}");
        assert_eq!(count, 7);
    }

    #[test]
    fn two_holes() {
        let outer = [(0, 0), (7, 0), (7, 3), (0, 3)];
        let left = [(1, 1), (2, 1), (2, 2), (1, 2)];
        let right = [(4, 1), (5, 1), (5, 2), (4, 2)];
        // n + 2w - 2 = 14, but the holes' sides lie on the lines y = 1 and y = 2: (2,1) and
        // (4,1) lie inside the chord (1,1)-(5,1), and (2,2), (4,2) inside (1,2)-(5,2).
        assert_eq!(minimum(&[&outer, &left, &right]), 10);
        // Outer flat vertices on those lines as well: 4 more vertices, and 4 more T-junctions
        // (the exhaustive search of tests/holes_dp.rs agrees on the first case).
        let outer = [
            (0, 0),
            (7, 0),
            (7, 1),
            (7, 2),
            (7, 3),
            (0, 3),
            (0, 2),
            (0, 1),
        ];
        assert_eq!(minimum(&[&outer, &left, &right]), 10);
    }

    #[test]
    fn a_triangle_touching_a_hole_at_its_corners_does_not_swallow_it() {
        // The trap with holes (docs/algorithms.md): a big triangle with its side midpoints as flat vertices, and a
        // hole whose corners are the midpoints of the medial triangle's sides. The medial
        // triangle's sides are chords (they touch the hole at its corners only) and no vertex
        // lies strictly inside it, yet it swallows the hole: 3 corner triangles plus it would
        // make 4.
        let outer = [(0, 0), (4, 0), (8, 0), (6, 4), (4, 8), (2, 4)];
        let hole = [(5, 2), (4, 4), (3, 2)];
        assert_eq!(minimum(&[&outer, &hole]), 6);
    }

    #[test]
    fn refuses_three_holes_and_large_inputs_with_an_estimate() {
        let p = polygon(&[
            &[(0, 0), (9, 0), (9, 9), (0, 9)],
            &[(1, 1), (2, 1), (1, 2)],
            &[(4, 4), (5, 4), (4, 5)],
            &[(7, 7), (8, 7), (7, 8)],
        ]);
        let e = triangulate(&p, usize::MAX).unwrap_err();
        assert_eq!(
            e.to_string(),
            "the asano dynamic program handles polygons with at most 2 holes (its time grows \
             like n^(3+2k) with k holes), and this polygon has 3 holes"
        );
        let p = polygon(&[&SQUARE, &[(1, 1), (2, 1), (2, 2), (1, 2)]]);
        let e = triangulate(&p, 7).unwrap_err();
        assert!(
            e.to_string().contains(
                "with 1 hole needs about 0.0 s for 8 vertices (its time grows like n^5), \
                 above its limit of 7 vertices with 1 hole"
            ),
            "{e}"
        );
    }
}
