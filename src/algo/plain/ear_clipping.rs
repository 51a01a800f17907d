//! Ear clipping of one small counter-clockwise simple polygon (Meisters, "Polygons have ears",
//! *Amer. Math. Monthly* 82 (1975); the lecture notes of Goldwasser (1991) and Toussaint
//! (1993)): what [`super::rings`] runs on a polygon without holes of up to [`CLIP_UP_TO`]
//! vertices, where it is quicker than the monotone sweep.
//!
//! Input contract: the cycle of points of one counter-clockwise simple polygon, at most
//! [`MAX_CLIP`] of them, no two equal; flat vertices allowed. No holes.
//! Output guarantee: exactly `len - 2` counter-clockwise triangles of positive area, as indices
//! into the points; no zero-area triangle ever, also with flat vertices.
//!
//! An ear is a vertex `v` with a strict left turn `prev, v, next` whose CLOSED triangle contains
//! no other remaining vertex. Then `prev next` is a proper diagonal (nothing on it), so the rest
//! is again a simple polygon of positive area. An ear always exists: any triangulation by proper
//! diagonals (which exists even with flat vertices: split at the lowest-leftmost vertex) has at
//! least two triangles with two polygon edges, and those are ears by this definition. A naive
//! clipper that accepts `cross >= 0` emits zero-area triangles at flat vertices; one that tests
//! only the open triangle can cut a diagonal through a vertex.
//!
//! Complexity: O(n^2) to O(n^3) (each ear test looks at every remaining vertex, a bit set), with
//! no allocation but the result.

use crate::geom::kernel::cross;
use crate::geom::kernel::Coord;

/// The most vertices [`clip`] takes (the remaining vertices are a bit set).
pub(crate) const MAX_CLIP: usize = 64;

/// Polygons of up to this many vertices are ear-clipped ([`super::rings`]), larger ones
/// cut into monotone pieces: the batch benchmark's small polygons are cheaper clipped up to 32
/// than up to 16 (docs/benchmarks.md); larger limits gain nothing and worsen the worst case,
/// O(n^3).
pub(crate) const CLIP_UP_TO: usize = 32;

/// Ear clipping of one counter-clockwise simple polygon given as its cycle of points (flat
/// vertices allowed): exactly `len - 2` triangles of positive area, as indices into `pts`.
/// Meant for small polygons (at most [`CLIP_UP_TO`] vertices in practice): each ear test looks at
/// every remaining vertex, O(n^2) at best and O(n^3) at worst, with no allocation but the result.
///
/// # Panics
/// With more than [`MAX_CLIP`] points, or if no ear is left (not a simple counter-clockwise
/// polygon).
pub(crate) fn clip<P: Coord>(pts: &[P]) -> Vec<[usize; 3]> {
    let n = pts.len();
    assert!(
        n <= MAX_CLIP,
        "ear clipping takes at most {MAX_CLIP} vertices"
    );
    let mut next = [0u8; MAX_CLIP];
    let mut prev = [0u8; MAX_CLIP];
    for i in 0..n {
        next[i] = ((i + 1) % n) as u8;
        prev[i] = ((i + n - 1) % n) as u8;
    }
    let mut remaining_set: u64 = u64::MAX >> (64 - n.max(1));
    let mut triangles = Vec::with_capacity(n.saturating_sub(2));
    let mut remaining = n;
    let mut v = 0;
    let mut misses = 0; // vertices tested since the last clip
    while remaining > 3 {
        let (p, q) = (usize::from(prev[v]), usize::from(next[v]));
        if is_ear(pts, remaining_set, p, v, q) {
            triangles.push([p, v, q]);
            next[p] = q as u8;
            prev[q] = p as u8;
            remaining_set &= !(1 << v);
            remaining -= 1;
            misses = 0;
            v = p; // p may have become an ear
        } else {
            misses += 1;
            // A valid polygon always has an ear (see the module documentation); the guard only
            // keeps a broken invariant from looping forever.
            assert!(
                misses <= remaining,
                "no ear in a valid polygon: invariant broken"
            );
            v = q;
        }
    }
    if remaining == 3 {
        triangles.push([usize::from(prev[v]), v, usize::from(next[v])]);
    }
    triangles
}

/// Whether `v` (between `p` and `q`) is an ear: a strict left turn whose closed triangle holds
/// no other vertex of `remaining` (a bit set).
fn is_ear<P: Coord>(pts: &[P], remaining: u64, p: usize, v: usize, q: usize) -> bool {
    let (a, b, c) = (pts[p], pts[v], pts[q]);
    if cross(a, b, c) <= 0 {
        return false;
    }
    let mut others = remaining & !(1 << p | 1 << v | 1 << q);
    while others != 0 {
        let s = pts[others.trailing_zeros() as usize];
        others &= others - 1;
        if cross(a, b, s) >= 0 && cross(b, c, s) >= 0 && cross(c, a, s) >= 0 {
            return false;
        }
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::kernel::Point;
    use crate::test_support::{polygon, FLAT_SQUARE, U_SHAPE};

    /// Clips `ring` and checks the result: `n - 2` positive triangles whose twice-areas sum to
    /// the polygon's.
    fn check(ring: &[(i64, i64)]) {
        let p = polygon(&[ring]);
        let pts: Vec<Point> = (0..p.len()).map(|v| p.point(v)).collect();
        let triangles = clip(&pts);
        assert_eq!(triangles.len(), p.len() - 2);
        let area: i128 = triangles
            .iter()
            .map(|&[a, b, c]| cross(pts[a], pts[b], pts[c]))
            .inspect(|&s| assert!(s > 0, "a triangle of {ring:?} is not positive"))
            .sum();
        assert_eq!(Some(area), p.twice_area().value());
    }

    #[test]
    fn flat_vertices_never_give_zero_area_triangles() {
        check(&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]);
        check(&U_SHAPE);
        check(&FLAT_SQUARE);
        check(&[
            (0, 0),
            (2, 0),
            (4, 0),
            (2, 1),
            (4, 2),
            (2, 2),
            (0, 2),
            (0, 1),
        ]);
    }

    /// The clipper at its largest: combs of 30 and 62 vertices with every gap bottom on one line
    /// (up to where [`super::super::rings`] sends polygons to it, and beyond).
    #[test]
    fn combs_up_to_64_vertices() {
        for teeth in [7, 15] {
            check(&crate::test_support::comb(teeth, 2, 4));
        }
    }

    #[test]
    fn fewer_than_three_points_give_no_triangle() {
        let pts = [Point::new(0, 0), Point::new(1, 0)];
        assert!(clip(&pts).is_empty());
        assert!(clip(&pts[..1]).is_empty());
    }
}
