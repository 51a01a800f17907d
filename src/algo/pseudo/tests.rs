//! Hand-made cases of Lemmas 3 and 4, each with a triangulation chosen on purpose.

use super::minimal;
use crate::algo::{plain, Algorithm, Pseudotriangulation};
use crate::test_support::polygon;
use crate::verify::pseudo::check;
use crate::Polygon;

/// The faces as sorted input-number cycles (rotation-free), with sorted corners.
fn shape(p: &Polygon, result: &Pseudotriangulation) -> Vec<(Vec<usize>, Vec<usize>)> {
    let mut faces: Vec<(Vec<usize>, Vec<usize>)> = result
        .faces
        .iter()
        .map(|f| {
            let mut cycle: Vec<usize> = f.cycle.iter().map(|&v| p.id(v)).collect();
            let lowest = cycle
                .iter()
                .enumerate()
                .min_by_key(|&(_, v)| *v)
                .map_or(0, |(i, _)| i);
            cycle.rotate_left(lowest);
            let mut corners: Vec<usize> = f.corners.iter().map(|&v| p.id(v)).collect();
            corners.sort_unstable();
            (cycle, corners)
        })
        .collect();
    faces.sort();
    faces
}

fn assert_valid(p: &Polygon, result: &Pseudotriangulation) {
    let c = check(p, Algorithm::Pseudo, result);
    assert!(c.valid, "{:?}", c.problems);
}

#[test]
fn a_convex_quadrilateral_keeps_its_diagonal() {
    // Both angles beside the diagonal at either end add up to less than pi.
    let p = polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]);
    let result = minimal(&p, &[[0, 1, 2], [0, 2, 3]]);
    assert_eq!(
        shape(&p, &result),
        [
            (vec![0, 1, 2], vec![0, 1, 2]),
            (vec![0, 2, 3], vec![0, 2, 3])
        ]
    );
    assert_eq!(result.edge_count, 5);
    assert_valid(&p, &result);
}

#[test]
fn lemma_4a_the_diagonal_at_a_reflex_vertex_goes() {
    // An arrowhead: the only diagonal splits the reflex angle at vertex 1 into two angles below
    // pi whose sum is above pi, so removing it leaves one pseudotriangle with corners 0, 2, 3.
    let p = polygon(&[&[(0, 0), (2, 1), (4, 0), (2, 3)]]);
    let result = minimal(&p, &[[0, 1, 3], [1, 2, 3]]);
    assert_eq!(shape(&p, &result), [(vec![0, 1, 2, 3], vec![0, 2, 3])]);
    assert_eq!(result.edge_count, 4);
    assert_valid(&p, &result);
}

#[test]
fn lemma_3a_a_central_triangle_goes_as_a_whole() {
    // A pseudotriangle with corners 0 (A), 2 (B), 4 (C) and reflex vertices 1, 3, 5 on its
    // sides, cut by the triangle 1 3 5. No single edge can go (at each end the two angles beside
    // it add up to less than pi), but the triangle can: at each of its corners the three angles
    // add up to more than pi (Lemma 3 case (a), Lemma 4(b)).
    let p = polygon(&[&[(0, 0), (6, 2), (12, 0), (8, 4), (6, 10), (4, 4)]]);
    let triangles = [[0, 1, 5], [1, 2, 3], [5, 3, 4], [1, 3, 5]];
    let mut only_edges = super::Greedy::new(&p, &triangles);
    only_edges.remove_edges();
    assert_eq!(
        only_edges.faces().faces.len(),
        4,
        "no edge alone is removable"
    );
    let result = minimal(&p, &triangles);
    assert_eq!(
        shape(&p, &result),
        [(vec![0, 1, 2, 3, 4, 5], vec![0, 2, 4])]
    );
    assert_eq!(result.edge_count, 6);
    assert_valid(&p, &result);
}

#[test]
fn an_angle_of_exactly_pi_is_no_corner() {
    // Vertex 1 is flat. Removing diagonal 1-3 joins angles of 116.6 and 63.4 degrees at vertex 1
    // into exactly pi: the merged face 0 1 2 3 has corners 0, 2, 3 only, a pseudotriangle.
    let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]]);
    let result = minimal(&p, &[[0, 1, 3], [1, 2, 3], [0, 3, 4]]);
    assert_eq!(
        shape(&p, &result),
        [
            (vec![0, 1, 2, 3], vec![0, 2, 3]),
            (vec![0, 3, 4], vec![0, 3, 4])
        ]
    );
    assert_valid(&p, &result);
}

#[test]
fn minimal_is_not_minimum_the_result_depends_on_the_triangulation() {
    // The same polygon fanned from its flat vertex: at each end of 1-3 and of 1-4 the two angles
    // add up to less than pi, so all three triangles stay, and that is minimal (Theorem 2)
    // though the triangulation above gives 2 (Theorem 4(b)).
    let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]]);
    let result = minimal(&p, &[[1, 2, 3], [1, 3, 4], [0, 1, 4]]);
    assert_eq!(result.faces.len(), 3);
    assert_valid(&p, &result);
}

#[test]
fn polygon_edges_stay_and_holes_are_no_faces() {
    // A square with a square hole, from the plain triangulation: every polygon edge is a face
    // edge, nothing covers the hole (the checker's chain), and the count is at most n + 2w - 2.
    let p = polygon(&[
        &[(0, 0), (10, 0), (10, 10), (0, 10)],
        &[(3, 3), (3, 6), (7, 6), (7, 3)],
    ]);
    let start = plain::triangulate(&p).expect("plain triangulation");
    let result = minimal(&p, &start.triangles);
    assert_valid(&p, &result);
    assert!(
        result.faces.len() < start.triangles.len(),
        "{}",
        result.faces.len()
    );
    // Euler for an annulus: faces = edges - vertices.
    assert_eq!(result.faces.len(), result.edge_count - p.len());
}

#[test]
fn twins_are_matched_by_their_two_ends() {
    let p = polygon(&[&[(0, 0), (4, 0), (4, 4), (0, 4)]]);
    let greedy = super::Greedy::new(&p, &[[0, 1, 2], [0, 2, 3]]);
    // Half-edge 1 is 1 -> 2 (a polygon edge); 2 is 2 -> 0 and 3 is 0 -> 2.
    assert_eq!(greedy.twin(1), super::NONE);
    assert_eq!((greedy.twin(2), greedy.twin(3)), (3, 2));
}
