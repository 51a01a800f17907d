//! The plain triangulation: a polygon of n stored vertices and w holes (or hole walks) cut into
//! exactly n + 2w - 2 triangles (`--algorithm ear`, and the start of the other algorithms:
//! MINITRI's step 1 walks it, the pseudotriangulations grow from it, the minimum's chosen
//! triangles are cut into it).
//!
//! One entry point per contract:
//! - `rings`: the points of simple rings, the outer one counter-clockwise first, holes
//!   clockwise; rings pairwise disjoint, no two points equal, flat vertices and any other
//!   collinearity allowed (a [`Polygon`] whose rings do not touch, or a piece another algorithm
//!   cut out). `polygon` is `rings` of such a [`Polygon`], swept along its longer side for
//!   the walks of step 1, or the `Premade` copy made while it was validated; `try_polygon`
//!   the same on rings still being validated.
//! - `walks`: the boundary walks of touching rings (copies of a touch point as vertices of
//!   their own, `docs/touching.md`).
//! - [`triangulate`]: the `ear` algorithm on any valid polygon, as a [`Triangulation`].
//!
//! Guarantee: exactly n + 2w - 2 counter-clockwise triangles of positive area (none of zero
//! area, flat vertices included), disjoint, covering the polygon, as indices into the points;
//! every side an edge or a proper diagonal; on walks each corner is the copy whose sector holds
//! the triangle. Every decision is an exact orientation test or coordinate comparison.
//!
//! Method and bound: monotone pieces ([`monotone`]: Lee & Preparata 1977; Garey, Johnson,
//! Preparata & Tarjan 1978; de Berg et al., *Computational Geometry*, ch. 3), O(n log n) time
//! and O(n) memory whatever the number of holes; ear clipping (`ear_clipping.rs`: Meisters 1975)
//! for rings without holes of up to 32 vertices (`CLIP_UP_TO`), where it is quicker. Walks: the
//! same sweep over the copies moved symbolically into their sectors (`perturbed`, simulation
//! of simplicity: Edelsbrunner & Mücke 1990), checked in O(N log N); if the check failed (never
//! seen), the ear clipper of the bridged cycle ([`super::walks`]), O(N^2) to O(N^3).

mod ear_clipping;
pub mod monotone;
pub(crate) mod perturbed;

use super::walks::WalksError;
use super::{Algorithm, TriangulateError, Triangulation};
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use ear_clipping::CLIP_UP_TO;
use std::cmp::Ordering;

/// Triangulates a valid polygon with w holes (possibly none; rings may touch) into
/// n + 2w - 2 nondegenerate counter-clockwise triangles, in O(n log n): the `ear` algorithm.
///
/// # Errors
/// None for a valid polygon whose rings do not touch: the `Result` keeps the signature of the
/// other algorithms. With touching rings, [`TriangulateError::Touching`] if the walks' check and
/// fallback both fail (a broken invariant, never seen).
///
/// # Examples
/// ```
/// use minitri::{algo::plain, Decimal, Polygon, RawPolygon};
/// let ring = |pts: &[(i32, i32)]| -> Result<Vec<[Decimal; 2]>, minitri::NumberError> {
///     pts.iter()
///         .map(|&(x, y)| Ok([Decimal::parse(&x.to_string())?, Decimal::parse(&y.to_string())?]))
///         .collect()
/// };
/// let raw = RawPolygon {
///     rings: vec![
///         ring(&[(0, 0), (4, 0), (4, 4), (0, 4)])?,
///         ring(&[(1, 1), (1, 3), (3, 3), (3, 1)])?,
///     ],
///     ..Default::default()
/// };
/// let (polygon, _warnings) = Polygon::from_raw(&raw)?;
/// let t = plain::triangulate(&polygon)?;
/// assert_eq!(t.triangles.len(), 8); // n + 2w - 2 = 8 + 2 - 2
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn triangulate<P: Coord>(polygon: &Polygon<P>) -> Result<Triangulation, TriangulateError> {
    triangulate_premade(polygon, None)
}

/// [`triangulate`], taking `premade`'s triangles when the caller made them already.
///
/// # Errors
/// As [`triangulate`].
pub(crate) fn triangulate_premade<P: Coord>(
    polygon: &Polygon<P>,
    premade: Premade,
) -> Result<Triangulation, TriangulateError> {
    if polygon.touches() > 0 {
        return super::touching(polygon, Algorithm::Ear, 0, None);
    }
    Ok(Triangulation {
        algorithm: Algorithm::Ear,
        // The triangulation MINITRI's step 1 walks (fatter triangles on wide polygons, and on
        // large ones made while the polygon was validated).
        triangles: self::polygon(polygon, premade),
        degenerate: Vec::new(),
        optimal: false,
        lower_bound: None,
        stopped: None,
    })
}

/// A plain triangulation of a valid polygon whose rings do not touch, made ahead of its use
/// (by the pipeline, beside the validation sweep: [`try_polygon`]): exactly the triangles
/// `polygon` makes for it, or `None` to have them made there.
pub(crate) type Premade = Option<Vec<[usize; 3]>>;

/// The plain triangulation of simple rings given as points one after another (see the module
/// documentation): `ring_starts[k]` is the index of the first point of ring `k` (`[0]` for one
/// cycle). Ear clipping for one ring of up to `CLIP_UP_TO` points (none for fewer than 3),
/// monotone pieces otherwise.
///
/// # Panics
/// As [`monotone::triangulate_rings`], if `ring_starts` does not describe rings of at least 3
/// points (one ring of more than `CLIP_UP_TO` points or several rings), and on a broken
/// invariant (rings outside the contract).
pub(crate) fn rings<P: Coord>(pts: &[P], ring_starts: &[usize]) -> Vec<[usize; 3]> {
    if ring_starts.len() == 1 && pts.len() <= CLIP_UP_TO {
        ear_clipping::clip(pts)
    } else {
        monotone::triangulate_rings(pts, ring_starts)
    }
}

/// `rings` of a valid polygon whose rings do not touch, as stored vertex indices: the
/// triangulation MINITRI's step 1 walks. Above `CLIP_UP_TO` vertices it is swept along x when
/// the bounding box is more than twice as wide as tall, else along y as always; the triangles
/// of `premade` (made while the polygon was validated, `try_polygon`) are returned instead when
/// there are some.
///
/// The monotone pieces are swept bottom to top, so a long horizontal corridor is one wide piece
/// whose walls, vertices at nearly the same heights, get joined by long fans; walks through
/// such fans are slow, and flipping them towards Delaunay takes quadratically many flips (the
/// `bars` benchmark). Sweeping along the corridor instead (the polygon turned a quarter-turn,
/// `(x, y) -> (MAX_COORD - y, x)`: exact, orientation and grid kept, the stored indices
/// unchanged) meets its walls' vertices alternately: short fans. A corridor crossing the sweep
/// elsewhere in the same polygon is still slow, never wrong. A polygon about as wide as tall
/// keeps the usual sweep, which needs no turned copy of its points (16 bytes per vertex).
pub(crate) fn polygon<P: Coord>(polygon: &Polygon<P>, premade: Premade) -> Vec<[usize; 3]> {
    if let Some(plain) = premade {
        return plain; // the same triangles, made while the polygon was validated
    }
    if polygon.len() <= CLIP_UP_TO {
        return rings(polygon.points(), polygon.ring_starts());
    }
    try_polygon(polygon).expect("monotone triangulation of a valid polygon: invariant broken")
}

/// `polygon` of a polygon of more than `CLIP_UP_TO` vertices whose validation is still
/// running: the same triangles if it turns out valid, and on any rings no panic and an end in
/// the same time bound (`None` where they break the monotone sweep's contract; `None` for
/// small polygons too).
pub(crate) fn try_polygon<P: Coord>(polygon: &Polygon<P>) -> Option<Vec<[usize; 3]>> {
    if polygon.len() <= CLIP_UP_TO {
        return None;
    }
    match turned_for_walking(polygon) {
        None => monotone::try_triangulate_rings(polygon.points(), polygon.ring_starts()),
        Some(turned) => monotone::try_triangulate_rings(&turned, polygon.ring_starts()),
    }
}

/// The plain triangulation of the boundary walks of a valid polygon whose rings touch
/// (`touches() > 0`): the monotone sweep over the copies moved into their sectors
/// ([`perturbed::swept`], checked), else the ear clipper of the bridged cycle
/// ([`super::walks::clipped_bridged`]; never seen in the tests).
///
/// # Errors
/// [`WalksError`] if the fallback finds no ear or bridge, which the theory excludes (a broken
/// invariant, reported rather than a wrong answer).
pub(crate) fn walks<P: Coord>(polygon: &Polygon<P>) -> Result<Vec<[usize; 3]>, WalksError> {
    match perturbed::swept(polygon) {
        Some(triangles) => Ok(triangles),
        None => super::walks::clipped_bridged(polygon),
    }
}

/// The points turned a quarter-turn when the bounding box is more than twice as wide as tall
/// (see `polygon`), else `None`.
fn turned_for_walking<P: Coord>(polygon: &Polygon<P>) -> Option<Vec<P>> {
    let pts = polygon.points();
    // The points of least and greatest x, then y.
    let mut ends = [pts[0]; 4];
    for &p in pts {
        for (k, end) in ends.iter_mut().enumerate() {
            let order = if k < 2 {
                P::cmp_x(p, *end)
            } else {
                P::cmp_y(p, *end)
            };
            if order == [Ordering::Less, Ordering::Greater][k % 2] {
                *end = p;
            }
        }
    }
    let (width, height) = (
        ends[1].offset_f64(ends[0])[0],
        ends[3].offset_f64(ends[2])[1],
    );
    (width > 2.0 * height).then(|| pts.iter().map(|p| p.quarter_turn()).collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::kernel::cross;
    use crate::test_support::polygon as valid;

    #[test]
    fn holes_give_n_plus_2w_minus_2_triangles_even_when_small() {
        // Small polygons with holes must not reach the ear clipper (which knows no holes).
        let cases: [&[&[(i64, i64)]]; 3] = [
            &[
                &[(0, 0), (4, 0), (4, 4), (0, 4)],
                &[(1, 1), (1, 3), (3, 3), (3, 1)],
            ],
            &[&[(0, 0), (9, 0), (9, 9), (0, 9)], &[(1, 1), (2, 1), (1, 2)]],
            // Flat vertices on the outer ring and a hole, all on the line x = 4 with the apexes.
            &[
                &[(0, 0), (4, 0), (8, 0), (8, 8), (0, 8)],
                &[(2, 2), (4, 2), (6, 2), (4, 4)],
                &[(2, 6), (6, 6), (4, 5)],
            ],
        ];
        for rings in cases {
            let p = valid(rings);
            let t = triangulate(&p).unwrap();
            assert_eq!(t.triangles.len(), p.len() + 2 * p.holes() - 2, "{rings:?}");
            let report = crate::verify::check(&p, &t);
            assert!(report.valid, "{rings:?}: {:?}", report.problems);
        }
    }

    /// Combs of 42 and 82 vertices (beyond the ear clipper), every gap bottom on one line.
    #[test]
    fn combs_beyond_the_ear_clipper() {
        for teeth in [10, 20] {
            let p = valid(&[&crate::test_support::comb(teeth, 2, 4)]);
            let t = triangulate(&p).unwrap();
            assert_eq!(t.triangles.len(), p.len() - 2);
            let area: i128 = t
                .triangles
                .iter()
                .map(|&[a, b, c]| cross(p.point(a), p.point(b), p.point(c)))
                .inspect(|&s| assert!(s > 0))
                .sum();
            assert_eq!(Some(area), p.twice_area().value());
        }
    }

    #[test]
    fn fewer_than_three_points_give_no_triangle() {
        let p = valid(&[&[(0, 0), (1, 0), (0, 1)]]);
        assert!(rings(&p.points()[..2], &[0]).is_empty());
        assert_eq!(rings(p.points(), &[0]), [[2, 0, 1]]);
    }
}
