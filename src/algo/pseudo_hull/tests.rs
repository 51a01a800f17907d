//! Hand-made cases for `pseudo-hull`: counts worked out by hand from Corollary 1 and Euler, and
//! single steps of Theorem 6's construction whose taut string is worked out by hand.

use super::{hull_cycle, hull_triangles, pseudotriangulate, pseudotriangulate_within, setup, step};
use crate::algo::{Algorithm, Pseudotriangulation};
use crate::test_support::polygon;
use crate::verify::pseudo::check;
use crate::Polygon;

fn solve(p: &Polygon) -> Pseudotriangulation {
    let result = pseudotriangulate(p).expect("pseudo-hull");
    let c = check(p, Algorithm::PseudoHull, &result);
    assert!(c.valid, "{:?}", c.problems);
    result
}

#[test]
fn a_square_needs_one_diagonal() {
    // n = 4, every vertex pointed (r = 4): 2n - r - 2 = 2 faces, 3n - r - 3 = 5 edges.
    let result = solve(&polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]));
    assert_eq!((result.faces.len(), result.edge_count), (2, 5));
    let h = result.hull.expect("counts");
    assert_eq!((h.reflex_vertices, h.big_angles, h.corollary(4)), (4, 4, 2));
}

#[test]
fn a_pocket_is_a_face() {
    // The arrowhead is a pseudotriangle; the pocket under its reflex vertex is the other face.
    let p = polygon(&[&[(0, 0), (4, 0), (2, 1), (2, 4)]]);
    let result = solve(&p);
    assert_eq!((result.faces.len(), result.edge_count), (2, 5));
}

#[test]
fn a_hole_interior_is_cut_too() {
    // n = 7 in general position: n - 2 = 5 pseudotriangles and 2n - 3 = 11 edges.
    let p = polygon(&[&[(0, 0), (8, 0), (8, 8), (0, 8)], &[(2, 2), (3, 6), (6, 2)]]);
    let result = solve(&p);
    assert_eq!((result.faces.len(), result.edge_count), (5, 11));
    // The hole's triangle is one of the faces.
    assert!(result.faces.iter().any(|f| {
        let mut c = f.cycle.clone();
        c.sort_unstable();
        c == [4, 5, 6]
    }));
}

#[test]
fn a_flat_vertex_keeps_both_straight_angles() {
    // Vertex 1 is flat on the bottom side: N = 4 + 2 = 6 angles of at least pi, so 2n - N - 2 =
    // 2 faces (Corollary 1 alone, for general position, would say n - 2 = 3). The one diagonal
    // must avoid vertex 1.
    let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]]);
    let result = solve(&p);
    assert_eq!((result.faces.len(), result.edge_count), (2, 6));
    let h = result.hull.expect("counts");
    assert_eq!((h.big_angles, h.minimum(5), h.corollary(5)), (6, 2, 3));
    assert!(result
        .faces
        .iter()
        .all(|f| f.cycle.len() != 3 || !f.cycle.contains(&1)));
}

#[test]
fn the_hull_keeps_collinear_points() {
    let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (2, 2), (1, 1), (0, 2)]]);
    let hull = hull_cycle(p.points());
    assert_eq!(hull, [0, 1, 2, 3, 5]);
}

/// The vertex at `(x, y)`.
#[test]
fn past_the_deadline_the_greedy_on_the_hull_is_given() {
    // A deadline already passed: the construction stops before its first step, and the result
    // is `pseudo`'s greedy on the hull's triangulation, valid (every polygon edge kept, the hull
    // partitioned, minimal), marked stopped and not optimal unless it reaches the minimum.
    let cases = [
        polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]),
        polygon(&[&[(0, 0), (4, 0), (2, 1), (2, 4)]]),
        polygon(&[&[(0, 0), (8, 0), (8, 8), (0, 8)], &[(2, 2), (3, 6), (6, 2)]]),
        polygon(&[&[(0, 0), (2, 0), (4, 0), (4, 4), (2, 1), (0, 4)]]),
        polygon(&[&[(0, 0), (10, 0), (6, 2), (10, 8), (5, 4), (0, 8), (3, 3)]]),
    ];
    for p in &cases {
        let past = std::time::Instant::now();
        let result = pseudotriangulate_within(p, Some(past)).expect("fallback");
        let c = check(p, Algorithm::PseudoHull, &result);
        assert!(c.valid, "{:?}", c.problems);
        let h = result.hull.expect("counts");
        assert!(result.faces.len() >= h.minimum(p.len()));
        // Marked stopped (not optimal) exactly when above the minimum's count.
        let above = result.faces.len() > h.minimum(p.len());
        assert_eq!(result.stopped.is_some(), above);
        assert_eq!(result.optimal(), !above);
        // Without a deadline: the minimum, optimal.
        let full = solve(p);
        assert!(full.optimal() && full.stopped.is_none());
        assert_eq!(full.faces.len(), h.minimum(p.len()));
    }
}

fn at(p: &Polygon, x: i64, y: i64) -> usize {
    (0..p.len())
        .find(|&v| p.point(v) == crate::geom::kernel::Point::new(x, y))
        .expect("a vertex there")
}

/// One step on the polygon's interior from the outer ring's first edge: the pseudotriangles
/// reported, and the boundary of the face left of the first new edge (what is left of F).
fn first_step(p: &Polygon) -> (Vec<Vec<usize>>, Vec<usize>) {
    let hull = hull_cycle(p.points());
    let (triangles, fixed, _) = hull_triangles(p, &hull, None);
    let (mut mesh, guard) = setup(p, &triangles, &fixed, None);
    let h = mesh.half_from(0, p.next(0)).expect("outer edge");
    let (mut faces, mut work) = (Vec::new(), Vec::new());
    step(&mut mesh, h, guard, &mut faces, &mut work).expect("a step");
    let (u, v) = work[0];
    let start = mesh.half_from(u, v).expect("new edge");
    let mut rest = Vec::new();
    let mut g = start;
    loop {
        rest.push(mesh.tail(g));
        g = mesh.next_boundary(g, |_, _| {});
        if g == start {
            break;
        }
    }
    (faces, rest)
}

fn sorted(mut v: Vec<usize>) -> Vec<usize> {
    v.sort_unstable();
    v
}

#[test]
fn figure_5_the_string_follows_a1_wraps_the_hole_and_follows_a1_again() {
    // B: x1 (0,0), p (10,9), x2 (40,0), q (30,30), x3 (40,40), (0,40); p and q reflex, so
    // A1 = x1 p x2 q x3. The hole (14,10) (24,16) (20,24) (10,20) sits across the segment x1 x3.
    // Pulled taut below and right of the hole, the string is
    //   (a) x1 -> p along B (p sticks out above the line from x1 to (14,10): 10 * 10 < 9 * 14),
    //   (b) p -> (14,10), (c) along the hole's hull to (24,16) (a hole edge), (d) -> q
    //   ((6, 14) turns left of (16, 24): q sticks out), (e) q -> x3 along B.
    // R is what lies between: corners p (where S leaves A1), x2 and q.
    let p = polygon(&[
        &[(0, 0), (10, 9), (40, 0), (30, 30), (40, 40), (0, 40)],
        &[(14, 10), (24, 16), (20, 24), (10, 20)],
    ]);
    let (faces, rest) = first_step(&p);
    let [pv, x2, q, h1, h2] =
        [(10, 9), (40, 0), (30, 30), (14, 10), (24, 16)].map(|(x, y)| at(&p, x, y));
    assert_eq!(faces.len(), 1);
    assert_eq!(sorted(faces[0].clone()), sorted(vec![pv, x2, q, h1, h2]));
    // What is left: x1, p, the hole the long way round from (14,10) to (24,16), q, x3, (0,40).
    let [h3, h4, x3, top] = [(20, 24), (10, 20), (40, 40), (0, 40)].map(|(x, y)| at(&p, x, y));
    assert_eq!(
        sorted(rest),
        sorted(vec![0, pv, h1, h4, h3, h2, q, x3, top])
    );
    // And the whole construction: n - 2 faces in general position (n = 10).
    assert_eq!(solve(&p).faces.len(), 8);
}

#[test]
fn the_string_touches_a_hole_at_one_vertex_which_the_rest_visits_twice() {
    // Square x1 (0,0), x2 (20,0), x3 (20,20), (0,20); the hole (12,8) (10,16) (4,10) has only
    // (12,8) below the diagonal y = x, so S = x1 -> (12,8) -> x3 and R = x1 x2 x3 (12,8). The
    // face left over goes round the hole from (12,8) back to (12,8): its boundary visits (12,8)
    // twice, and the next steps run on it.
    let p = polygon(&[
        &[(0, 0), (20, 0), (20, 20), (0, 20)],
        &[(12, 8), (10, 16), (4, 10)],
    ]);
    let h = at(&p, 12, 8);
    let (faces, rest) = first_step(&p);
    assert_eq!(faces.len(), 1);
    assert_eq!(sorted(faces[0].clone()), vec![0, 1, 2, h]);
    assert_eq!(rest.len(), 7, "{rest:?}");
    assert_eq!(rest.iter().filter(|&&v| v == h).count(), 2, "{rest:?}");
    let result = solve(&p);
    assert_eq!((result.faces.len(), result.edge_count), (5, 11));
}

#[test]
fn a_string_straight_through_a_vertex_is_split_there() {
    // Square x1 (0,0), x2 (20,0), x3 (20,20), (0,20) with the hole (10,10) (8,16) (4,8): its
    // vertex (10,10) lies exactly on the diagonal, so S = x1 -> (10,10) -> x3 goes straight
    // through it (angle pi) and must be split there; (10,10) keeps an angle of pi in R, no
    // corner, and N = n (general position is broken only by that collinear triple).
    let p = polygon(&[
        &[(0, 0), (20, 0), (20, 20), (0, 20)],
        &[(10, 10), (8, 16), (4, 8)],
    ]);
    let h = at(&p, 10, 10);
    let (faces, _) = first_step(&p);
    assert_eq!(sorted(faces[0].clone()), vec![0, 1, 2, h]);
    let result = solve(&p);
    assert_eq!(result.hull.expect("counts").big_angles, 7);
    assert_eq!(result.faces.len(), 5);
    assert!(result
        .faces
        .iter()
        .any(|f| sorted(f.cycle.clone()) == vec![0, 1, 2, h] && f.corners.len() == 3));
}
