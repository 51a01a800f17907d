use super::*;
use crate::test_support::polygon;

fn triangulation(triangles: &[[usize; 3]], degenerate: &[[usize; 3]]) -> Triangulation {
    Triangulation {
        algorithm: Algorithm::Ear,
        triangles: triangles.to_vec(),
        degenerate: degenerate.to_vec(),
        optimal: false,
        lower_bound: None,
        stopped: None,
    }
}

fn problems(p: &Polygon, triangles: &[[usize; 3]], degenerate: &[[usize; 3]]) -> Vec<String> {
    let result = check(p, &triangulation(triangles, degenerate));
    assert_eq!(result.valid, result.problems.is_empty(), "{result:?}");
    result.problems
}

fn assert_valid(p: &Polygon, triangles: &[[usize; 3]], degenerate: &[[usize; 3]]) {
    assert_eq!(problems(p, triangles, degenerate), Vec::<String>::new());
}

/// The stretches reported by the chain check, as `"(x, y) -> (x, y) by w"`.
fn stretches(problems: &[String]) -> Vec<String> {
    problems
        .iter()
        .filter_map(|s| {
            let rest = s.strip_prefix("the boundaries do not cancel on the stretch ")?;
            let (stretch, rest) = rest.split_once(": ")?;
            let by = rest
                .strip_prefix("(triangles covering) - (polygon) is ")?
                .split(' ')
                .next()?;
            Some(format!("{stretch} by {by}"))
        })
        .collect()
}

fn unit_square() -> Polygon {
    polygon(&[&[(0, 0), (1, 0), (1, 1), (0, 1)]])
}

/// `0 0, 1 0, 2 0, 2 2, 0 2`: vertex 1 is flat.
fn flat_square() -> Polygon {
    polygon(&[&[(0, 0), (1, 0), (2, 0), (2, 2), (0, 2)]])
}

#[test]
fn a_square_split_in_two_is_valid() {
    let p = unit_square();
    assert_valid(&p, &[[0, 1, 2], [0, 2, 3]], &[]);
    assert_valid(&p, &[[1, 2, 3], [3, 0, 1]], &[]);
    let result = check(&p, &triangulation(&[[0, 1, 2], [2, 3, 0]], &[]));
    assert_eq!(
        result,
        Check {
            valid: true,
            problems: vec![],
            faults: Faults::default(),
        }
    );
}

#[test]
fn a_missing_triangle_is_reported_by_count_area_and_chain() {
    let p = unit_square();
    let found = problems(&p, &[[0, 1, 2]], &[]);
    assert_eq!(
        found[0],
        "1 triangle, but n + 2w - d - 2 = 4 + 0 - 0 - 2 = 2"
    );
    assert_eq!(
        found[1],
        "the triangles' total twice-area is 1 but the polygon's is 2 (in units of the exact grid)"
    );
    // The uncovered half (left of (0, 1) -> (0, 0) -> (1, 1)): its two polygon edges and its
    // diagonal, each oriented with the uncovered side on its right.
    assert_eq!(
        found[2],
        "the boundaries do not cancel on the stretch (0, 0) -> (0, 1): (triangles covering) - \
         (polygon) is 1 higher on its left than on its right, so beside it there is a gap, an \
         overlap, or a triangle outside the polygon"
    );
    assert_eq!(
        stretches(&found),
        [
            "(0, 0) -> (0, 1) by 1",
            "(0, 1) -> (1, 1) by 1",
            "(1, 1) -> (0, 0) by 1"
        ]
    );
    assert_eq!(found.len(), 5);
}

#[test]
fn overlap_plus_outside_with_the_right_area_and_count_fails_the_chain_check() {
    // A square with a notch at the top, reaching down to (2, 2); bottom vertices at x = 0, 2, 4.
    let p = polygon(&[&[(0, 0), (2, 0), (4, 0), (4, 4), (2, 2), (0, 4)]]);
    // [1, 2, 3] and [1, 2, 4] overlap; [3, 5, 4] is the notch, outside; [2, 3, 4] and [0, 4, 5]
    // are left uncovered. Twice-areas 4 + 4 + 8 + 8 = 24 = the polygon's; 4 = n - 2 triangles.
    let found = problems(&p, &[[0, 1, 4], [1, 2, 4], [1, 2, 3], [3, 5, 4]], &[]);
    assert!(!found.is_empty());
    assert_eq!(
        stretches(&found).len(),
        found.len(),
        "only the chain check objects: {found:?}"
    );
    // The notch triangle's top side runs along nothing of the polygon's interior.
    assert!(
        stretches(&found).contains(&"(4, 4) -> (0, 4) by 1".to_string()),
        "{found:?}"
    );
    // Along the bottom edge from (2, 0) to (4, 0), two triangles are stacked above.
    assert!(
        stretches(&found).contains(&"(2, 0) -> (4, 0) by 1".to_string()),
        "{found:?}"
    );
}

#[test]
fn clockwise_triangles_are_named_by_input_vertex_numbers() {
    // Given clockwise, stored counter-clockwise: stored 0, 1, 2, 3 are input 0, 3, 2, 1.
    let p = polygon(&[&[(0, 0), (0, 1), (1, 1), (1, 0)]]);
    assert_eq!((p.id(1), p.id(3)), (3, 1));
    assert_valid(&p, &[[0, 1, 2], [0, 2, 3]], &[]);
    let found = problems(&p, &[[0, 1, 2], [0, 3, 2]], &[]);
    assert!(
        found.contains(&"triangle 1 [0, 1, 2] is clockwise".to_string()),
        "{found:?}"
    );
}

#[test]
fn a_zero_area_triangle_is_reported_even_where_the_chain_cancels() {
    let p = flat_square();
    // The zero-area [0, 1, 2] balances the count, and its sides cancel on their line.
    let found = problems(&p, &[[0, 1, 2], [0, 2, 3], [0, 3, 4]], &[]);
    assert_eq!(found, ["triangle 0 [0, 1, 2] has zero area"]);
}

#[test]
fn bad_indices_are_reported_without_panicking() {
    let p = unit_square();
    let found = problems(&p, &[[0, 1, 7], [0, 2, 3]], &[]);
    assert!(
        found.contains(
            &"triangle 0 with stored indices [0, 1, 7] uses index 7, but the polygon has only 4 vertices"
                .to_string()
        ),
        "{found:?}"
    );
    let found = problems(&p, &[[0, 1, 2], [0, 2, 2]], &[]);
    assert!(
        found.contains(&"triangle 1 [0, 2, 2] repeats vertex 2".to_string()),
        "{found:?}"
    );
    let found = problems(&p, &[[usize::MAX, 0, 1], [0, 1, 2]], &[[9, 1, 2]]);
    assert!(found
        .iter()
        .any(|s| s.starts_with("triangle 0 with stored indices")));
    assert!(found.contains(
        &"degenerate triangle 0 with stored indices [9, 1, 2] uses index 9, but the polygon has only 4 vertices"
            .to_string()
    ));
}

/// Outer square 0..8; a triangular hole whose edge (2, 2)-(6, 6) lies on the diagonal.
fn hole_on_the_diagonal() -> Polygon {
    polygon(&[&[(0, 0), (8, 0), (8, 8), (0, 8)], &[(2, 2), (6, 6), (5, 2)]])
}

#[test]
fn triangles_swallowing_a_hole_are_invalid() {
    let p = hole_on_the_diagonal();
    assert_eq!((p.len(), p.holes()), (7, 1));
    // Both sides of [0, 1, 2] are chords (the diagonal runs along a hole edge), yet it swallows
    // the hole.
    let found = problems(&p, &[[0, 1, 2], [0, 2, 3]], &[]);
    assert_eq!(
        found[0],
        "2 triangles, but n + 2w - d - 2 = 7 + 2 - 0 - 2 = 7"
    );
    assert_eq!(
        found[1],
        "the triangles' total twice-area is 128 but the polygon's is 116 (in units of the exact grid)"
    );
    // Every hole edge is left over: the hole's inside is covered once, where it should be 0.
    assert_eq!(
        stretches(&found),
        [
            "(2, 2) -> (5, 2) by 1",
            "(6, 6) -> (2, 2) by 1",
            "(5, 2) -> (6, 6) by 1"
        ]
    );
}

#[test]
fn a_square_with_a_square_hole_in_eight_triangles_is_valid() {
    // The hole is given clockwise, so it is stored as given: 4 (2, 2), 5 (2, 4), 6 (4, 4), 7 (4, 2).
    let p = polygon(&[
        &[(0, 0), (6, 0), (6, 6), (0, 6)],
        &[(2, 2), (2, 4), (4, 4), (4, 2)],
    ]);
    let triangles = [
        [0, 1, 7],
        [0, 7, 4],
        [1, 2, 6],
        [1, 6, 7],
        [2, 3, 5],
        [2, 5, 6],
        [3, 0, 4],
        [3, 4, 5],
    ];
    assert_valid(&p, &triangles, &[]);
    // Covering the hole as well (two more triangles) is caught.
    let mut swallowing = triangles.to_vec();
    swallowing.extend([[4, 7, 6], [4, 6, 5]]);
    let found = problems(&p, &swallowing, &[]);
    assert_eq!(
        found[0],
        "10 triangles, but n + 2w - d - 2 = 8 + 2 - 0 - 2 = 8"
    );
    assert_eq!(stretches(&found).len(), 4, "{found:?}");
}

#[test]
fn t_junctions_need_their_degenerate_triangles() {
    let p = flat_square();
    // The plain triangulation: 3 = n - 2 triangles, no T-junction.
    assert_valid(&p, &[[0, 1, 3], [1, 2, 3], [0, 3, 4]], &[]);
    // The minimum: side 0-2 holds the flat vertex 1, listed as degenerate [0, 1, 2].
    let minimum = [[0, 2, 3], [0, 3, 4]];
    assert_valid(&p, &minimum, &[[0, 1, 2]]);
    assert_valid(&p, &minimum, &[[2, 1, 0]]);
    // Without it the count is wrong.
    assert_eq!(
        problems(&p, &minimum, &[]),
        ["2 triangles, but n + 2w - d - 2 = 5 + 0 - 0 - 2 = 3"]
    );
    // A degenerate triangle whose middle is not between its ends.
    let found = problems(&p, &minimum, &[[1, 0, 2]]);
    assert_eq!(
        found,
        ["degenerate triangle 0 [1, 0, 2]: vertex 0 does not lie strictly between vertices 1 and 2"]
    );
    // Listed, but no triangle side holds the segment 0-2.
    let found = problems(&p, &[[0, 1, 3], [1, 2, 3], [0, 3, 4]], &[[0, 1, 2]]);
    assert_eq!(
        found,
        [
            "3 triangles, but n + 2w - d - 2 = 5 + 0 - 1 - 2 = 2",
            "degenerate triangle 0 [0, 1, 2]: no triangle side contains the segment from vertex 0 \
             (0, 0) to vertex 2 (2, 0), so vertex 1 is not a T-junction there"
        ]
    );
    // Listed twice.
    let found = problems(&p, &minimum, &[[0, 1, 2], [2, 1, 0]]);
    assert!(
        found
            .contains(&"degenerate triangle 1 [2, 1, 0] repeats degenerate triangle 0".to_string()),
        "{found:?}"
    );
}

#[test]
fn two_t_junctions_on_one_side() {
    // The first worked example of docs/algorithms.md: minimum 2, vertices 1 and 2 both inside side 0-3.
    let p = polygon(&[&[(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)]]);
    let minimum = [[0, 3, 4], [0, 4, 5]];
    assert_valid(&p, &minimum, &[[0, 1, 2], [1, 2, 3]]);
    assert_valid(&p, &minimum, &[[0, 1, 3], [0, 2, 3]]);
    // Count, area and chain are right, each listed triangle lies on side 0-3, but vertex 1 is
    // counted twice and vertex 2 not at all.
    let found = problems(&p, &minimum, &[[0, 1, 2], [0, 1, 3]]);
    assert_eq!(
        found,
        ["degenerate triangle 1 [0, 1, 3] has the same middle vertex 1 as degenerate triangle 0, \
          but a vertex lies inside at most one triangle side"]
    );
    // A degenerate segment longer than any side on its line.
    let found = problems(
        &p,
        &[[0, 1, 5], [1, 2, 5], [2, 3, 4], [2, 4, 5]],
        &[[0, 2, 3]],
    );
    assert!(
        found
            .iter()
            .any(|s| s.contains("no triangle side contains")),
        "{found:?}"
    );
}

#[test]
fn the_chain_finds_a_gap_and_a_double_cover_on_a_10_by_10_grid() {
    // 0 (0, 0), 1 (5, 0), 2 (10, 0), 3 (10, 5), 4 (10, 10), 5 (0, 10); twice-area 200.
    let p = polygon(&[&[(0, 0), (5, 0), (10, 0), (10, 5), (10, 10), (0, 10)]]);
    let fan = [[5, 0, 1], [5, 1, 2], [5, 2, 3], [5, 3, 4]];
    assert_valid(&p, &fan, &[]);

    // A gap: without [5, 1, 2], the triangle (0, 10), (5, 0), (10, 0) is uncovered. Its three
    // sides are reported, each oriented with the uncovered side on the right.
    let gap = [fan[0], fan[2], fan[3]];
    let found = problems(&p, &gap, &[]);
    assert_eq!(
        found[0],
        "3 triangles, but n + 2w - d - 2 = 6 + 0 - 0 - 2 = 4"
    );
    assert_eq!(
        found[1],
        "the triangles' total twice-area is 150 but the polygon's is 200 (in units of the exact grid)"
    );
    assert_eq!(
        stretches(&found),
        [
            "(5, 0) -> (0, 10) by 1",
            "(0, 10) -> (10, 0) by 1",
            "(10, 0) -> (5, 0) by 1"
        ]
    );
    assert_eq!(found.len(), 5);

    // A double cover: [5, 0, 2] covers [5, 0, 1] and [5, 1, 2], and [5, 1, 2] is there too. The
    // count is right; the doubly covered triangle (0, 10), (5, 0), (10, 0) is on the left of each
    // reported stretch.
    let double = [[5, 0, 2], [5, 1, 2], [5, 2, 3], [5, 3, 4]];
    let found = problems(&p, &double, &[]);
    assert_eq!(
        found[0],
        "the triangles' total twice-area is 250 but the polygon's is 200 (in units of the exact grid)"
    );
    assert_eq!(
        stretches(&found),
        [
            "(0, 10) -> (5, 0) by 1",
            "(10, 0) -> (0, 10) by 1",
            "(5, 0) -> (10, 0) by 1"
        ]
    );
    assert_eq!(found.len(), 4);

    // The same triangle listed twice: its three sides are left over once each.
    let twice = [fan[0], fan[1], fan[1], fan[2], fan[3]];
    let found = problems(&p, &twice, &[]);
    assert_eq!(
        stretches(&found),
        [
            "(0, 10) -> (5, 0) by 1",
            "(10, 0) -> (0, 10) by 1",
            "(5, 0) -> (10, 0) by 1"
        ]
    );
}

#[test]
fn problems_are_capped() {
    let p = unit_square();
    let found = problems(&p, &[[0, 0, 1]; 30], &[]);
    // Count, area, 30 repeated vertices, 4 uncovered edges.
    assert_eq!(found.len(), MAX_PROBLEMS + 1);
    assert_eq!(found[MAX_PROBLEMS], "... and 16 more");
}

#[test]
fn a_fan_of_a_convex_200000_gon_is_checked_quickly() {
    const N: i64 = 200_000;
    let ring: Vec<(i64, i64)> = (0..N).map(|x| (x, x * x)).collect();
    let p = polygon(&[&ring]);
    assert_eq!(p.len(), N as usize);
    let fan: Vec<[usize; 3]> = (1..p.len() - 1).map(|i| [0, i, i + 1]).collect();
    assert_valid(&p, &fan, &[]);
    // One triangle dropped from the middle is found.
    let mut broken = fan.clone();
    broken.remove(1000);
    let found = problems(&p, &broken, &[]);
    assert_eq!(stretches(&found).len(), 3, "{found:?}");
}

#[test]
fn agreement_of_exact_algorithms() {
    use Algorithm::*;
    assert_eq!(agreement(&[]), None);
    assert_eq!(agreement(&[(Minitri, 5, None), (Asano, 5, None)]), None);
    assert_eq!(
        agreement(&[(Asano, 5, None), (Minitri, 6, None)]).as_deref(),
        Some("asano gives 5 triangles but minitri gives 6")
    );
    assert_eq!(
        agreement(&[(Minitri, 1, None), (Asano, 2, None)]).as_deref(),
        Some("minitri gives 1 triangle but asano gives 2")
    );
    // A plain triangulation is not a minimum and is not compared.
    assert_eq!(
        agreement(&[(Ear, 7, None), (Minitri, 5, None), (Asano, 5, None)]),
        None
    );
    // Searches cut short by the time limit may differ within each other's bounds...
    assert_eq!(
        agreement(&[(Minitri, 9, Some(7)), (Asano, 8, Some(6))]),
        None
    );
    assert_eq!(agreement(&[(Minitri, 9, Some(7)), (Asano, 7, None)]), None);
    // ...but no count may go below a bound another proved, or below a proved minimum.
    assert_eq!(
        agreement(&[(Minitri, 9, Some(7)), (Asano, 6, Some(5))]).as_deref(),
        Some("asano gives 6 triangles but minitri proves at least 7")
    );
    assert_eq!(
        agreement(&[(Minitri, 8, None), (Asano, 7, Some(5))]).as_deref(),
        Some("asano gives 7 triangles but minitri gives 8 as the minimum")
    );
}

fn faults(p: &Polygon, triangles: &[[usize; 3]], degenerate: &[[usize; 3]]) -> Faults {
    let result = check(p, &triangulation(triangles, degenerate));
    assert_eq!(result.valid, result.faults.is_empty(), "{result:?}");
    result.faults
}

#[test]
fn faults_of_a_missing_triangle_are_the_gap_sides_with_the_gap_on_their_right() {
    let p = unit_square();
    let found = faults(&p, &[[0, 1, 2]], &[]);
    assert!(found.triangles.is_empty() && found.degenerate.is_empty());
    // The gap is the triangle (0, 0), (1, 1), (0, 1): three sides, each once.
    let mut sides: Vec<[Point; 2]> = found
        .stretches
        .iter()
        .map(|&[a, b]| [a.min(b), a.max(b)])
        .collect();
    sides.sort();
    let pt = Point::new;
    assert_eq!(
        sides,
        [
            [pt(0, 0), pt(0, 1)],
            [pt(0, 0), pt(1, 1)],
            [pt(0, 1), pt(1, 1)]
        ]
    );
    // The gap's centroid (1/3, 2/3), tripled to stay on the grid, is right of every stretch.
    for [a, b] in found.stretches {
        let tripled = |q: Point| Point::new(3 * q.x, 3 * q.y);
        assert!(
            cross(tripled(a), tripled(b), Point::new(1, 2)) < 0,
            "{a:?} -> {b:?}"
        );
    }
}

#[test]
fn faults_name_bad_triangles_and_degenerate_triangles_by_position() {
    let p = unit_square();
    // Triangle 1 repeats a vertex, triangle 2 is clockwise, triangle 3 is out of range.
    let found = faults(&p, &[[0, 1, 2], [0, 2, 2], [0, 3, 2], [0, 1, 9]], &[]);
    assert_eq!(found.triangles, [1, 2, 3]);
    let flat = flat_square();
    let minimum = [[0, 2, 3], [0, 3, 4]];
    assert!(faults(&flat, &minimum, &[[0, 1, 2]]).is_empty());
    // Listed twice: the second is at fault; not between its ends: the first.
    assert_eq!(
        faults(&flat, &minimum, &[[0, 1, 2], [2, 1, 0]]).degenerate,
        [1]
    );
    assert_eq!(
        faults(&flat, &minimum, &[[1, 0, 2], [0, 1, 2]]).degenerate,
        [0]
    );
    // Not on a triangle side.
    let plain = [[0, 1, 3], [1, 2, 3], [0, 3, 4]];
    let found = faults(&flat, &plain, &[[0, 1, 2]]);
    assert_eq!(found.degenerate, [0]);
    assert!(found.stretches.is_empty() && found.triangles.is_empty());
}

#[test]
fn faults_are_not_capped_like_the_sentences() {
    let p = unit_square();
    let result = check(&p, &triangulation(&[[0, 0, 1]; 30], &[]));
    assert_eq!(result.problems.len(), MAX_PROBLEMS + 1);
    assert_eq!(result.faults.triangles, (0..30).collect::<Vec<_>>());
    assert_eq!(result.faults.stretches.len(), 4);
}
