//! Hand-made cases for `pseudo-hull`: counts worked out by hand from Corollary 1 and Euler.

use super::{hull_cycle, pseudotriangulate};
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

#[test]
fn debug_case() {
    let p = polygon(&[
        &[
            (0, 4),
            (2, 4),
            (2, 2),
            (2, 0),
            (3, 0),
            (5, 0),
            (7, 0),
            (9, 0),
            (11, 0),
            (12, 0),
            (12, 1),
            (12, 3),
            (12, 5),
            (12, 6),
            (12, 9),
            (12, 10),
            (12, 11),
            (12, 12),
            (12, 14),
            (12, 15),
            (12, 16),
            (12, 17),
            (11, 20),
            (9, 20),
            (7, 20),
            (6, 20),
            (4, 20),
            (0, 18),
            (0, 11),
        ],
        &[(3, 16), (4, 16), (4, 18), (2, 18)],
        &[(9, 14), (10, 15), (8, 15)],
    ]);
    solve(&p);
}
