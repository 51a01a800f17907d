//! Independent checks of a pseudotriangulation (`--algorithm pseudo` and `pseudo-hull`), exact,
//! sharing no code with the algorithms (kernel, polygon accessors and, for big faces, the
//! validation sweep of the input only).
//!
//! Input contract: a valid [`Polygon`] and ANY [`Pseudotriangulation`] (indices may be out of
//! range or repeated; nothing here panics on them). The region is the polygon for
//! [`Algorithm::Pseudo`] and the convex hull of its vertices for [`Algorithm::PseudoHull`].
//!
//! Output guarantee: [`check`] is valid exactly when
//! 1. every face is a cycle of at least 3 distinct vertices of the polygon, a simple polygon
//!    (no two of its edges meet but consecutive ones at their common end, no fold-back),
//!    counter-clockwise (positive area);
//! 2. each face has exactly three corners (angle below pi; pi or more, flat, is no corner), and
//!    the listed corners are those;
//! 3. the faces partition the region: the boundary chain of the faces minus the region's is zero
//!    (the argument of [`crate::verify`] holds for simple counter-clockwise faces as for
//!    triangles), and the areas add up; for `pseudo-hull` every polygon edge is a face edge;
//! 4. `edge_count` is the number of distinct face edges;
//! 5. minimality (Theorem 2): no edge but a polygon edge (L) can be removed leaving a
//!    pseudotriangulation, nor the three sides of a triangular face. Removing an edge merges its
//!    two faces; the merged face's corners are those of both faces except at the edge's ends,
//!    where the two angles become one (a corner if it is below pi). The edge is removable when
//!    the merged face has exactly 3 corners (Lemma 4(a)); likewise for a triangle and its three
//!    neighbours (Lemma 4(b), 12 corners down to 3);
//! 6. for `pseudo-hull`: the number of faces is 2n - N - 2, N the number of angles of at least pi
//!    between neighbouring segments of L and the hull edges, the least possible (see
//!    `algo::pseudo_hull`); in general position N = r = n and this is Corollary 1's
//!    2n - r - 2.
//!
//! Complexity: O(F log F) for the chain and the adjacency (F: total face size), including the
//! simplicity test (`geom::validate` on each face: pair by pair up to 32 vertices, by the exact
//! sweep above); for `pseudo-hull`, O(n log n) for the hull.

use super::{check_sides_cancel, plural, Check, Problems};
use crate::algo::{Algorithm, Pseudotriangulation};
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cmp_angle, cross, dot, Area};
use crate::geom::polygon::Polygon;
use std::collections::BTreeMap;

/// Checks, exactly, that `p` is a minimal pseudotriangulation of `polygon` (`pseudo`), or a
/// minimum one of its vertices' convex hull containing its edges (`pseudo-hull`); see the
/// module documentation.
pub fn check<P: Coord>(
    polygon: &Polygon<P>,
    algorithm: Algorithm,
    p: &Pseudotriangulation,
) -> Check {
    let mut problems = Problems::default();
    let hull_region = algorithm == Algorithm::PseudoHull;
    // 1, 2: each face alone; the other checks use the faces whose indices are usable, and those
    // on all the faces only when every face is.
    let mut good: Vec<usize> = Vec::new();
    for (k, face) in p.faces.iter().enumerate() {
        if face_ok(polygon, k, face, &mut problems) {
            good.push(k);
        }
    }
    let all = good.len() == p.faces.len();
    let hull = hull_cycle(polygon.points());
    let region = hull_region.then_some(hull.as_slice());
    check_partition(polygon, p, &good, region, &mut problems);
    let half = face_edges(p, &good);
    if hull_region {
        check_polygon_edges(polygon, &half, &mut problems);
    }
    // 4: the edge count.
    let distinct = half
        .keys()
        .filter(|&&(a, b)| a < b || !half.contains_key(&(b, a)))
        .count();
    if all && distinct != p.edge_count {
        problems.add(|| {
            format!(
                "edge_count is {} but the faces have {distinct} edges",
                p.edge_count
            )
        });
    }
    if all {
        check_minimal(polygon, p, &good, &half, &mut problems);
    }
    if hull_region {
        check_count(polygon, p, &hull, &mut problems);
    }
    problems.finish()
}

/// Directed face edges `(a, b)` -> (face, position of `a` in its cycle).
type HalfEdges = BTreeMap<(usize, usize), (usize, usize)>;

/// The directed edges of faces `good`.
fn face_edges(p: &Pseudotriangulation, good: &[usize]) -> HalfEdges {
    let mut half = HalfEdges::new();
    for &k in good {
        let c = &p.faces[k].cycle;
        for i in 0..c.len() {
            half.insert((c[i], c[(i + 1) % c.len()]), (k, i));
        }
    }
    half
}

/// Check 3: the faces `good` partition the region (the polygon, or its vertices' convex hull
/// `hull`): the boundary chain cancels and the areas add up, when every face is good.
fn check_partition<P: Coord>(
    polygon: &Polygon<P>,
    p: &Pseudotriangulation,
    good: &[usize],
    hull: Option<&[usize]>,
    problems: &mut Problems,
) {
    let mut sides: Vec<[usize; 2]> = Vec::new();
    let mut area = Area::default();
    for &k in good {
        let c = &p.faces[k].cycle;
        for i in 0..c.len() {
            sides.push([c[i], c[(i + 1) % c.len()]]);
            area.add(
                polygon.point(c[0]),
                polygon.point(c[i]),
                polygon.point(c[(i + 1) % c.len()]),
            );
        }
    }
    let mut region = Area::default();
    if let Some(hull) = hull {
        if !is_hull(polygon, hull) {
            problems.add(|| "the checker's own convex hull is wrong (a checker bug)".to_string());
        }
        for i in 0..hull.len() {
            let (a, b) = (hull[i], hull[(i + 1) % hull.len()]);
            sides.push([b, a]);
            region.add(polygon.point(hull[0]), polygon.point(a), polygon.point(b));
        }
    } else {
        sides.extend((0..polygon.len()).map(|i| [polygon.next(i), i]));
        region = polygon.twice_area();
    }
    if good.len() == p.faces.len() {
        if area != region {
            problems.add(|| "the faces' total area differs from the region's".to_string());
        }
        check_sides_cancel(polygon, sides, problems);
    }
}

/// Check 3 for `pseudo-hull`: every polygon edge is a face edge.
fn check_polygon_edges<P: Coord>(polygon: &Polygon<P>, half: &HalfEdges, problems: &mut Problems) {
    for i in 0..polygon.len() {
        let (a, b) = (i, polygon.next(i));
        if !half.contains_key(&(a, b)) && !half.contains_key(&(b, a)) {
            problems.add(|| {
                format!(
                    "polygon edge {}-{} is no face edge",
                    polygon.id(a),
                    polygon.id(b)
                )
            });
        }
    }
}

/// Check 5, Theorem 2: no edge but a polygon edge can be removed leaving a pseudotriangulation
/// (Lemma 4(a)), nor the three sides of a triangular face (Lemma 4(b)).
fn check_minimal<P: Coord>(
    polygon: &Polygon<P>,
    p: &Pseudotriangulation,
    good: &[usize],
    half: &HalfEdges,
    problems: &mut Problems,
) {
    let is_ring_edge = |a: usize, b: usize| polygon.next(a) == b || polygon.next(b) == a;
    let pt = |i: usize| polygon.point(i);
    let corner = |u: usize, a: usize, w: usize| usize::from(cross(pt(u), pt(a), pt(w)) > 0);
    let at = |k: usize, i: usize| {
        let c = &p.faces[k].cycle;
        c[i % c.len()]
    };
    let before = |k: usize, i: usize| {
        let c = &p.faces[k].cycle;
        c[(i + c.len() - 1) % c.len()]
    };
    // Corners lost where the angle `u a b` (one face) and `b' a w` (the next face round a, across
    // the removed edge a b') become the single angle `u a w`.
    let lost = |u: usize, a: usize, b: usize, b2: usize, w: usize| {
        corner(u, a, b) + corner(b2, a, w) - corner(u, a, w)
    };
    for (&(a, b), &(f, i)) in half {
        if a > b || is_ring_edge(a, b) {
            continue;
        }
        let Some(&(g, j)) = half.get(&(b, a)) else {
            continue;
        };
        if f == g {
            continue;
        }
        // f: u -> a -> b -> y; g: x -> b -> a -> w.
        let (u, y) = (before(f, i), at(f, i + 2));
        let (x, w) = (before(g, j), at(g, j + 2));
        let merged = 6 - lost(u, a, b, b, w) - lost(x, b, a, a, y);
        if merged == 3 {
            problems.add(|| {
                format!(
                    "edge {}-{} can be removed (Lemma 4(a)): its two faces merge into a \
                     pseudotriangle, so the result is not minimal",
                    polygon.id(a),
                    polygon.id(b)
                )
            });
        }
    }
    for &k in good {
        let c = &p.faces[k].cycle;
        if c.len() != 3 || (0..3).any(|i| is_ring_edge(c[i], c[(i + 1) % 3])) {
            continue;
        }
        let mut merged = 12;
        for i in 0..3 {
            let (cc, a, b) = (c[(i + 2) % 3], c[i], c[(i + 1) % 3]);
            // The face across c -> a runs u -> a -> c; the one across a -> b runs b -> a -> w.
            let (Some(&(g, j)), Some(&(h, l))) = (half.get(&(a, cc)), half.get(&(b, a))) else {
                merged = 0;
                break;
            };
            let u = before(g, j);
            let w = at(h, l + 2);
            merged -= corner(u, a, cc) + 1 + corner(b, a, w) - corner(u, a, w);
        }
        if merged == 3 {
            let [a, b, cc] = [c[0], c[1], c[2]].map(|v| polygon.id(v));
            problems.add(|| {
                format!(
                    "triangle [{a}, {b}, {cc}] can be removed (Lemma 4(b)): it and its three \
                     neighbours merge into a pseudotriangle, so the result is not minimal"
                )
            });
        }
    }
}

/// Check 6, for `pseudo-hull`: the count of Corollary 1; a result stopped by the time limit
/// claims only minimality (5), and no pseudotriangulation has fewer faces.
fn check_count<P: Coord>(
    polygon: &Polygon<P>,
    p: &Pseudotriangulation,
    hull: &[usize],
    problems: &mut Problems,
) {
    let n = polygon.len();
    let big = big_angles(polygon, hull);
    let want = (2 * n).saturating_sub(big + 2);
    let wrong = if p.stopped.is_some() {
        p.faces.len() < want
    } else {
        p.faces.len() != want
    };
    if wrong {
        problems.add(|| {
            format!(
                "{} but 2n - N - 2 = {} - {big} - 2 = {want} (N: angles of at least pi of the \
                 polygon's and the hull's edges; Corollary 1)",
                plural(p.faces.len(), "pseudotriangle"),
                2 * n
            )
        });
    }
}

/// Checks 1 and 2 for face `k`; whether its indices are usable for the other checks.
fn face_ok<P: Coord>(
    polygon: &Polygon<P>,
    k: usize,
    face: &crate::algo::Pseudotriangle,
    problems: &mut Problems,
) -> bool {
    let c = &face.cycle;
    let n = polygon.len();
    if c.len() < 3 || c.iter().any(|&v| v >= n) {
        problems.add(|| format!("face {k} has {} vertices or an index out of range", c.len()));
        return false;
    }
    let name = || {
        let ids: Vec<String> = c.iter().map(|&v| polygon.id(v).to_string()).collect();
        format!("face {k} [{}]", ids.join(", "))
    };
    let mut sorted = c.clone();
    sorted.sort_unstable();
    if sorted.windows(2).any(|w| w[0] == w[1]) {
        problems.add(|| format!("{} repeats a vertex", name()));
        return false;
    }
    let pt = |i: usize| polygon.point(c[i % c.len()]);
    let m = c.len();
    let mut area = Area::default();
    for i in 0..m {
        area.add(pt(0), pt(i), pt(i + 1));
    }
    if area.signum() <= 0 {
        problems.add(|| format!("{} is not counter-clockwise", name()));
    }
    if !simple(polygon, (0..m).map(pt).collect()) {
        problems.add(|| format!("{} is not a simple polygon", name()));
        return false;
    }
    let corners: Vec<usize> = (0..m)
        .filter(|&i| cross(pt(i + m - 1), pt(i), pt(i + 1)) > 0)
        .map(|i| c[i])
        .collect();
    if corners.len() != 3 {
        problems.add(|| {
            format!(
                "{} has {} (angles below pi), so it is no pseudotriangle",
                name(),
                plural(corners.len(), "corner")
            )
        });
    }
    let mut listed = face.corners.clone();
    listed.sort_unstable();
    let mut found = corners;
    found.sort_unstable();
    if listed != found {
        problems.add(|| format!("{} lists corners that are not its corners", name()));
    }
    true
}

/// Whether the closed polyline through `pts` (distinct points) is simple: consecutive edges meet
/// only at their common end (no fold-back), others not at all. Decided by
/// [`crate::geom::validate`] on the cycle as one ring (edges pair by pair up to 32 points, the
/// exact sweep above: O(k log k)).
fn simple<P: Coord>(polygon: &Polygon<P>, pts: Vec<P>) -> bool {
    let ring = Polygon::ring_of_points(pts, *polygon.grid());
    crate::geom::validate::errors(&ring).is_empty()
}

/// The convex hull's boundary, counter-clockwise, every point on it included (written again
/// here, apart from the algorithm's).
fn hull_cycle<P: Coord>(points: &[P]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_unstable_by_key(|&i| points[i]);
    let mut lower: Vec<usize> = Vec::new();
    let mut upper: Vec<usize> = Vec::new();
    for (list, seq) in [
        (&mut lower, order.clone()),
        (&mut upper, order.into_iter().rev().collect()),
    ] {
        for i in seq {
            while list.len() >= 2
                && cross(
                    points[list[list.len() - 2]],
                    points[list[list.len() - 1]],
                    points[i],
                ) < 0
            {
                list.pop();
            }
            list.push(i);
        }
        list.pop();
    }
    lower.extend(upper);
    lower
}

/// Whether `hull` is the convex hull's boundary with every point on it, a cross-check of the
/// monotone chain above by other means, in O(n log h): `hull` is h >= 3 distinct indices, a
/// counter-clockwise cycle turning left or going straight on (no fold-back) at each vertex,
/// rising lexicographically (x, then y) from its least point to its greatest and falling back (so
/// it winds once round a convex region); and every point lies inside it or is one of its
/// vertices, none on a side otherwise (located by binary search on the two chains).
fn is_hull<P: Coord>(polygon: &Polygon<P>, hull: &[usize]) -> bool {
    let h = hull.len();
    let n = polygon.len();
    if h < 3 || hull.iter().any(|&v| v >= n) {
        return false;
    }
    let mut seen = vec![false; n];
    for &v in hull {
        if std::mem::replace(&mut seen[v], true) {
            return false;
        }
    }
    let pt = |k: usize| polygon.point(hull[k % h]);
    let turns = (0..h).all(|k| {
        let (a, b, c) = (pt(k), pt(k + 1), pt(k + 2));
        let side = cross(a, b, c);
        side > 0 || (side == 0 && dot(b, a, c) < 0)
    });
    if !turns {
        return false;
    }
    // The least point, then a rise to the greatest and a fall back.
    let low = (0..h).min_by_key(|&k| pt(k)).unwrap_or(0);
    let mut k = 0;
    while k + 1 < h && pt(low + k) < pt(low + k + 1) {
        k += 1;
    }
    let top = k;
    while k + 1 < h && pt(low + k) > pt(low + k + 1) {
        k += 1;
    }
    if k + 1 != h || top == 0 {
        return false;
    }
    // Lower chain rising, upper chain (reversed) rising, both from the least to the greatest.
    let lower: Vec<P> = (0..=top).map(|i| pt(low + i)).collect();
    let upper: Vec<P> = (top..=h).rev().map(|i| pt(low + i)).collect();
    // Whether `p` is on the inner side of `chain` (`sign` 1 for the lower chain, -1 for the
    // upper) or one of its vertices, not on a side otherwise.
    let within = |chain: &[P], sign: i32, p: P| {
        let at = chain.partition_point(|&q| q < p);
        if at < chain.len() && chain[at] == p {
            return true;
        }
        if at == 0 || at == chain.len() {
            return false;
        }
        let side = cross(chain[at - 1], chain[at], p);
        match sign {
            1 => side > 0,
            _ => side < 0,
        }
    };
    polygon
        .points()
        .iter()
        .enumerate()
        .all(|(v, &p)| seen[v] || (within(&lower, 1, p) && within(&upper, -1, p)))
}

/// N: the angles of at least pi between neighbouring segments among the polygon's edges and the
/// hull's, over all vertices.
fn big_angles<P: Coord>(polygon: &Polygon<P>, hull: &[usize]) -> usize {
    let n = polygon.len();
    let mut around: Vec<Vec<usize>> = (0..n)
        .map(|i| vec![polygon.next(i), polygon.prev(i)])
        .collect();
    for k in 0..hull.len() {
        let (a, b) = (hull[k], hull[(k + 1) % hull.len()]);
        around[a].push(b);
        around[b].push(a);
    }
    let mut total = 0;
    for (v, list) in around.iter_mut().enumerate() {
        let c = polygon.point(v);
        list.sort_unstable();
        list.dedup();
        list.sort_by(|&a, &b| cmp_angle(c, polygon.point(a), polygon.point(b)));
        let d = list.len();
        total += (0..d)
            .filter(|&k| cross(c, polygon.point(list[k]), polygon.point(list[(k + 1) % d])) <= 0)
            .count();
    }
    total
}

#[cfg(test)]
mod tests {
    use super::check;
    use crate::algo::{Algorithm, Pseudotriangle, Pseudotriangulation};
    use crate::test_support::polygon;

    fn faces(list: &[(&[usize], &[usize])], edge_count: usize) -> Pseudotriangulation {
        Pseudotriangulation {
            faces: list
                .iter()
                .map(|(c, k)| Pseudotriangle {
                    cycle: c.to_vec(),
                    corners: k.to_vec(),
                })
                .collect(),
            edge_count,
            hull: None,
            stopped: None,
        }
    }

    fn problems(p: &crate::Polygon, a: Algorithm, t: &Pseudotriangulation) -> Vec<String> {
        let c = check(p, a, t);
        assert_eq!(c.valid, c.problems.is_empty());
        c.problems
    }

    #[test]
    fn a_removable_edge_is_reported() {
        // The arrowhead left as two triangles: diagonal 1-3 can go (Lemma 4(a)).
        let p = polygon(&[&[(0, 0), (2, 1), (4, 0), (2, 3)]]);
        let two = faces(&[(&[0, 1, 3], &[0, 1, 3]), (&[1, 2, 3], &[1, 2, 3])], 5);
        let found = problems(&p, Algorithm::Pseudo, &two);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].contains("edge 1-3 can be removed"), "{found:?}");
        let one = faces(&[(&[0, 1, 2, 3], &[0, 2, 3])], 4);
        assert!(problems(&p, Algorithm::Pseudo, &one).is_empty());
    }

    #[test]
    fn a_removable_triangle_is_reported() {
        let p = polygon(&[&[(0, 0), (6, 2), (12, 0), (8, 4), (6, 10), (4, 4)]]);
        let four = faces(
            &[
                (&[0, 1, 5], &[0, 1, 5]),
                (&[1, 2, 3], &[1, 2, 3]),
                (&[5, 3, 4], &[5, 3, 4]),
                (&[1, 3, 5], &[1, 3, 5]),
            ],
            9,
        );
        let found = problems(&p, Algorithm::Pseudo, &four);
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(
            found[0].contains("triangle [1, 3, 5] can be removed"),
            "{found:?}"
        );
    }

    #[test]
    fn four_corners_a_gap_and_wrong_corners_are_reported() {
        let p = polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]);
        let square = faces(&[(&[0, 1, 2, 3], &[0, 1, 2])], 4);
        let found = problems(&p, Algorithm::Pseudo, &square);
        assert!(
            found.iter().any(|m| m.contains("has 4 corners")),
            "{found:?}"
        );
        assert!(
            found.iter().any(|m| m.contains("lists corners")),
            "{found:?}"
        );
        let half = faces(&[(&[0, 1, 2], &[0, 1, 2])], 3);
        let found = problems(&p, Algorithm::Pseudo, &half);
        assert!(
            found.iter().any(|m| m.contains("do not cancel")),
            "{found:?}"
        );
        let miscounted = faces(&[(&[0, 1, 2], &[0, 1, 2]), (&[0, 2, 3], &[0, 2, 3])], 4);
        let found = problems(&p, Algorithm::Pseudo, &miscounted);
        assert_eq!(found, ["edge_count is 4 but the faces have 5 edges"]);
    }

    #[test]
    fn a_clockwise_or_self_crossing_face_and_bad_indices_are_reported() {
        let p = polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]);
        let clockwise = faces(&[(&[0, 2, 1], &[0, 2, 1]), (&[0, 3, 2], &[0, 3, 2])], 5);
        let found = problems(&p, Algorithm::Pseudo, &clockwise);
        assert!(
            found.iter().any(|m| m.contains("not counter-clockwise")),
            "{found:?}"
        );
        let bowtie = faces(&[(&[0, 1, 3, 2], &[])], 5);
        let found = problems(&p, Algorithm::Pseudo, &bowtie);
        assert!(
            found.iter().any(|m| m.contains("not a simple polygon")),
            "{found:?}"
        );
        let nonsense = faces(&[(&[0, 9, 1], &[]), (&[0, 0, 1], &[])], 5);
        assert_eq!(problems(&p, Algorithm::Pseudo, &nonsense).len(), 2);
    }

    #[test]
    fn a_big_face_is_tested_by_the_sweep() {
        // A pseudotriangle of 42 vertices (above the pair-by-pair limit): corners (0, 0),
        // (1000, 0), (500, 2000); the bottom side bends inwards along y = i (40 - i) at
        // x = 25 i, a constant second difference of -2, so every vertex on it is reflex.
        let mut ring: Vec<(i64, i64)> = vec![(0, 0)];
        ring.extend((1..40).map(|i| (25 * i, i * (40 - i))));
        ring.extend([(1000, 0), (500, 2000)]);
        let p = polygon(&[&ring]);
        let n = p.len();
        assert_eq!(n, 42);
        let whole: Vec<usize> = (0..n).collect();
        let one = faces(&[(&whole, &[0, 40, 41])], n);
        assert!(problems(&p, Algorithm::Pseudo, &one).is_empty());
        // The same vertices with two neighbours swapped: the cycle crosses itself.
        let mut crossed = whole.clone();
        crossed.swap(5, 6);
        let bad = faces(&[(&crossed, &[0, 40, 41])], n);
        let found = problems(&p, Algorithm::Pseudo, &bad);
        assert!(
            found.iter().any(|m| m.contains("not a simple polygon")),
            "{found:?}"
        );
    }

    #[test]
    fn the_hull_cross_check_takes_collinear_points_and_refuses_wrong_hulls() {
        use super::{hull_cycle, is_hull};
        // A triangle with every side cut into 300 collinear pieces: all 900 points on the hull
        // (the O(n h) check this replaced took minutes on 10^5 such points).
        let m = 300;
        let mut ring: Vec<(i64, i64)> = (0..m).map(|t| (t, 0)).collect();
        ring.extend((0..m).map(|t| (m - t, t)));
        ring.extend((0..m).map(|t| (0, m - t)));
        let p = polygon(&[&ring]);
        let hull = hull_cycle(p.points());
        assert_eq!(hull.len(), 3 * m as usize);
        assert!(is_hull(&p, &hull));
        // A point left out (then inside a side), the cycle turned clockwise, a repeated vertex.
        let mut short = hull.clone();
        short.remove(5);
        assert!(!is_hull(&p, &short));
        let mut reversed = hull.clone();
        reversed.reverse();
        assert!(!is_hull(&p, &reversed));
        let mut repeated = hull.clone();
        repeated[7] = repeated[6];
        assert!(!is_hull(&p, &repeated));
        // The hull of the arrowhead skips (2, 1); the ring itself turns right there.
        let arrow = polygon(&[&[(0, 0), (4, 0), (2, 1), (2, 4)]]);
        let hull = hull_cycle(arrow.points());
        assert_eq!(hull.len(), 3);
        assert!(is_hull(&arrow, &hull));
        assert!(!is_hull(&arrow, &[0, 1, 2, 3]));
        // A square (vertical sides), and a triangle of it (a corner left outside).
        let square = polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]);
        assert!(is_hull(&square, &hull_cycle(square.points())));
        assert!(is_hull(&square, &[0, 1, 2, 3]));
        assert!(!is_hull(&square, &[0, 1, 2]));
    }

    #[test]
    fn pseudo_hull_needs_the_count_and_the_polygon_edges() {
        // The arrowhead: the polygon and its pocket are the minimum (2 = 2n - N - 2).
        let p = polygon(&[&[(0, 0), (4, 0), (2, 1), (2, 4)]]);
        let good = faces(&[(&[0, 1, 2, 3], &[0, 1, 3]), (&[1, 3, 2], &[1, 3, 2])], 5);
        assert!(problems(&p, Algorithm::PseudoHull, &good).is_empty());
        // The hull cut by 0-... : triangles 0 1 3 and the pocket, but polygon edges 0-1... kept;
        // leaving out edges 1-2 and 2-3 (a triangulation of the hull alone) is caught.
        let hull_only = faces(&[(&[0, 1, 3], &[0, 1, 3])], 3);
        let found = problems(&p, Algorithm::PseudoHull, &hull_only);
        assert!(
            found
                .iter()
                .any(|m| m.contains("polygon edge 1-2 is no face edge")),
            "{found:?}"
        );
        assert!(
            found
                .iter()
                .any(|m| m.contains("1 pseudotriangle but 2n - N - 2")),
            "{found:?}"
        );
    }
}
