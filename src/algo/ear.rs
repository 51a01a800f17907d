//! The plain triangulation (`--algorithm ear`) of a polygon with w holes into n + 2w - 2
//! nondegenerate triangles: [`crate::algo::monotone`] pieces in O(n log n) (holes included), and,
//! for small polygons without holes (up to 16 vertices, where it is quickest), ear clipping
//! (Meisters, "Polygons have
//! ears", *Amer. Math. Monthly* 82 (1975); the lecture notes
//! `papers/goldwasser-1991-lecture-triangulating-simple-polygons.txt` and
//! `papers/toussaint-1993-lecture-triangulations.txt`), which this module implements.
//!
//! Input contract: a valid polygon, with or without holes; flat vertices allowed, on any ring.
//! Output guarantee: exactly n + 2w - 2 counter-clockwise triangles of positive area (n - 2
//! without holes); no zero-area triangle ever, also with flat vertices and with vertices of
//! different rings collinear.
//!
//! An ear is a vertex `v` with a strict left turn `prev, v, next` whose CLOSED triangle contains
//! no other remaining vertex. Then `prev next` is a proper diagonal (nothing on it), so the rest
//! is again a simple polygon of positive area. An ear always exists: any triangulation by proper
//! diagonals (which exists even with flat vertices: split at the lowest-leftmost vertex) has at
//! least two triangles with two polygon edges, and those are ears by this definition. A naive
//! clipper that accepts `cross >= 0` emits zero-area triangles at flat vertices; one that tests
//! only the open triangle can cut a diagonal through a vertex.
//!
//! Complexity: O(n log n) for [`triangulate`] (monotone pieces; the ear clipper only ever sees at
//! most 16 vertices), whatever the number of holes. The ear clipper itself (`clip`) is O(n^2)
//! worst case (each ear test looks at the remaining vertices in the triangle's bounding box,
//! found through a uniform grid); it handles no holes, so holes never reach it.

use super::{Algorithm, TriangulateError, Triangulation};
use crate::geom::kernel::{cross, Point};
use crate::geom::polygon::Polygon;

/// Triangulates a polygon with w holes (possibly none) into n + 2w - 2 nondegenerate
/// counter-clockwise triangles, in O(n log n).
///
/// # Errors
/// None for a valid polygon: the `Result` keeps the signature of the other algorithms.
///
/// # Examples
/// ```
/// use minitri::{algo::ear, Decimal, Polygon, RawPolygon};
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
/// };
/// let (polygon, _warnings) = Polygon::from_raw(&raw)?;
/// let t = ear::triangulate(&polygon)?;
/// assert_eq!(t.triangles.len(), 8); // n + 2w - 2 = 8 + 2 - 2
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn triangulate(polygon: &Polygon) -> Result<Triangulation, TriangulateError> {
    Ok(Triangulation {
        algorithm: Algorithm::Ear,
        triangles: super::plain_polygon(polygon),
        degenerate: Vec::new(),
        optimal: false,
        lower_bound: None,
    })
}

/// Ear clipping of one counter-clockwise simple polygon given as its cycle of points (flat
/// vertices allowed): exactly `len - 2` triangles of positive area, as indices into `pts`.
pub(crate) fn clip(pts: &[Point]) -> Vec<[usize; 3]> {
    let n = pts.len();
    let mut next: Vec<usize> = (0..n).map(|i| (i + 1) % n).collect();
    let mut prev: Vec<usize> = (0..n).map(|i| (i + n - 1) % n).collect();
    let mut grid = Grid::new(pts);
    let mut triangles = Vec::with_capacity(n.saturating_sub(2));
    let mut remaining = n;
    let mut v = 0;
    let mut misses = 0; // vertices tested since the last clip
    while remaining > 3 {
        let (p, q) = (prev[v], next[v]);
        if is_ear(pts, &grid, p, v, q) {
            triangles.push([p, v, q]);
            next[p] = q;
            prev[q] = p;
            grid.remove(pts[v], v);
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
        triangles.push([prev[v], v, next[v]]);
    }
    triangles
}

fn is_ear(pts: &[Point], grid: &Grid, p: usize, v: usize, q: usize) -> bool {
    let (a, b, c) = (pts[p], pts[v], pts[q]);
    if cross(a, b, c) <= 0 {
        return false;
    }
    let lo = Point::new(a.x.min(b.x).min(c.x), a.y.min(b.y).min(c.y));
    let hi = Point::new(a.x.max(b.x).max(c.x), a.y.max(b.y).max(c.y));
    !grid.any_in_box(lo, hi, |w| {
        w != p && w != v && w != q && {
            let s = pts[w];
            cross(a, b, s) >= 0 && cross(b, c, s) >= 0 && cross(c, a, s) >= 0
        }
    })
}

/// Up to this many vertices, the grid is a single cell.
const SMALL: usize = 16;

/// Remaining vertices bucketed in a uniform grid of about n cells.
struct Grid {
    cells: Vec<Vec<usize>>,
    side: usize,
    min: Point,
    cell_w: i128,
    cell_h: i128,
}

impl Grid {
    fn new(pts: &[Point]) -> Grid {
        // A small polygon is one cell: testing its few vertices costs less than bucketing them.
        let side = if pts.len() <= SMALL {
            1
        } else {
            (pts.len() as f64).sqrt().ceil() as usize
        };
        let min = Point::new(
            pts.iter().map(|p| p.x).min().unwrap_or(0),
            pts.iter().map(|p| p.y).min().unwrap_or(0),
        );
        let max_x = pts.iter().map(|p| p.x).max().unwrap_or(0);
        let max_y = pts.iter().map(|p| p.y).max().unwrap_or(0);
        let cell = |span: i64| (i128::from(span) / side as i128) + 1;
        let mut grid = Grid {
            cells: vec![Vec::new(); side * side],
            side,
            min,
            cell_w: cell(max_x - min.x),
            cell_h: cell(max_y - min.y),
        };
        for (i, &p) in pts.iter().enumerate() {
            let k = grid.cell(p);
            grid.cells[k.1 * side + k.0].push(i);
        }
        grid
    }

    fn cell(&self, p: Point) -> (usize, usize) {
        if self.side == 1 {
            return (0, 0); // small polygons: one cell, no division
        }
        let cx = (i128::from(p.x - self.min.x) / self.cell_w) as usize;
        let cy = (i128::from(p.y - self.min.y) / self.cell_h) as usize;
        (cx.min(self.side - 1), cy.min(self.side - 1))
    }

    fn remove(&mut self, p: Point, i: usize) {
        let (cx, cy) = self.cell(p);
        let bucket = &mut self.cells[cy * self.side + cx];
        if let Some(pos) = bucket.iter().position(|&j| j == i) {
            bucket.swap_remove(pos);
        }
    }

    fn any_in_box(&self, lo: Point, hi: Point, mut hit: impl FnMut(usize) -> bool) -> bool {
        let (x0, y0) = self.cell(lo);
        let (x1, y1) = self.cell(hi);
        (y0..=y1)
            .any(|cy| (x0..=x1).any(|cx| self.cells[cy * self.side + cx].iter().any(|&w| hit(w))))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{polygon, U_SHAPE};

    fn check(ring: &[(i64, i64)]) {
        let p = polygon(&[ring]);
        let t = triangulate(&p).unwrap();
        assert_eq!(t.triangles.len(), p.len() - 2);
        let mut area = 0i128;
        for &[a, b, c] in &t.triangles {
            let s = cross(p.point(a), p.point(b), p.point(c));
            assert!(s > 0, "triangle {a} {b} {c} of {ring:?} is not positive");
            area += s;
        }
        assert_eq!(Some(area), p.twice_area().value());
    }

    #[test]
    fn flat_vertices_never_give_zero_area_triangles() {
        check(&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]);
        check(&U_SHAPE);
        check(&[
            (0, 0),
            (1, 0),
            (2, 0),
            (2, 1),
            (2, 2),
            (1, 2),
            (0, 2),
            (0, 1),
        ]);
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

    #[test]
    fn combs() {
        // Ten teeth of width 2 over gaps of width 2, all gap bottoms on one line.
        let mut comb = vec![(0, 0), (40, 0)];
        for k in (0..10).rev() {
            comb.extend([(4 * k + 4, 1), (4 * k + 2, 1), (4 * k + 2, 5), (4 * k, 5)]);
        }
        check(&comb);
    }

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
            let p = polygon(rings);
            let t = triangulate(&p).unwrap();
            assert_eq!(t.triangles.len(), p.len() + 2 * p.holes() - 2, "{rings:?}");
            let report = crate::verify::check(&p, &t);
            assert!(report.valid, "{rings:?}: {:?}", report.problems);
        }
    }
}
