//! Property tests of `pseudo` and `pseudo-hull` (issue 7) on random polygons, in general position
//! and not (the grids of `property.rs`, full of collinear triples and flat vertices), with and
//! without holes:
//!
//! - `pseudo`: the independent checker accepts every result (faces partition the polygon, each
//!   a simple counter-clockwise polygon with exactly three corners, no removable edge or triangle
//!   by Theorem 2, the edge count); Euler's formula for a region with w holes,
//!   faces = edges - n + 1 - w; at most as many faces as the n + 2w - 2 triangles started from;
//! - `pseudo-hull`: the checker accepts every result (partition of the hull, three corners per
//!   face, every polygon edge kept, 2n - N - 2 faces); in general position exactly Corollary 1's
//!   2n - r - 2 = n - 2 faces and 3n - r - 3 = 2n - 3 edges, with r = N = n.

use crate::property::{config, general, holed, holed_recipe, rectilinear, without_flat};
use crate::util::polygon_from_rings;
use minitri::algo::{ear, pseudo, pseudo_hull, Algorithm};
use minitri::geom::kernel::{cross, Point};
use minitri::verify::pseudo::check;
use minitri::Polygon;
use proptest::prelude::*;

fn check_pseudo(poly: &Polygon, rings: &[Vec<(i64, i64)>]) -> Result<(), TestCaseError> {
    let start = ear::triangulate(poly).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let result = pseudo::minimal(poly, &start.triangles);
    let report = check(poly, Algorithm::Pseudo, &result);
    prop_assert!(
        report.valid,
        "pseudo invalid on {:?}: {:?}",
        rings,
        report.problems
    );
    let (n, w, f) = (poly.len(), poly.holes(), result.faces.len());
    prop_assert_eq!(f + n, result.edge_count + 1 - w, "Euler on {:?}", rings);
    prop_assert!(f <= start.triangles.len());
    Ok(())
}

fn check_hull(poly: &Polygon, rings: &[Vec<(i64, i64)>]) -> Result<(), TestCaseError> {
    let result = pseudo_hull::pseudotriangulate(poly, pseudo_hull::DEFAULT_LIMIT)
        .map_err(|e| TestCaseError::fail(format!("{e} on {rings:?}")))?;
    let report = check(poly, Algorithm::PseudoHull, &result);
    prop_assert!(
        report.valid,
        "pseudo-hull invalid on {:?}: {:?}",
        rings,
        report.problems
    );
    let n = poly.len();
    if general_position(poly) {
        let counts = result.hull.expect("pseudo-hull counts");
        prop_assert_eq!(counts.reflex_vertices, n);
        prop_assert_eq!(counts.big_angles, n);
        prop_assert_eq!(result.faces.len(), 2 * n - counts.reflex_vertices - 2);
        prop_assert_eq!(result.edge_count, 2 * n - 3);
    }
    Ok(())
}

/// No three vertices on a line (the paper's general position), by brute force.
fn general_position(poly: &Polygon) -> bool {
    let p: Vec<Point> = poly.points().to_vec();
    let n = p.len();
    (0..n).all(|a| (a + 1..n).all(|b| (b + 1..n).all(|c| cross(p[a], p[b], p[c]) != 0)))
}

fn both(rings: &[Vec<(i64, i64)>]) -> Result<(), TestCaseError> {
    if let Some(poly) = polygon_from_rings(rings) {
        check_pseudo(&poly, rings)?;
        check_hull(&poly, rings)?;
    }
    Ok(())
}

fn wide_point() -> impl Strategy<Value = (i64, i64)> {
    (0i64..=1000, 0i64..=1000)
}

proptest! {
    #![proptest_config(config(1_500, 0x5eed_0701))]
    #[test]
    fn general_position_polygons(
        base in [wide_point(), wide_point(), wide_point()],
        ops in prop::collection::vec((0usize..64, 0i64..=1000, 0i64..=1000), 2..30),
    ) {
        if let Some(ring) = general(base, &ops) {
            let rings = vec![ring];
            if let Some(poly) = polygon_from_rings(&rings) {
                prop_assume!(general_position(&poly));
                check_pseudo(&poly, &rings)?;
                check_hull(&poly, &rings)?;
            }
        }
    }
}

proptest! {
    #![proptest_config(config(1_500, 0x5eed_0702))]
    #[test]
    fn small_grid_polygons(
        base in [(0i64..=6, 0i64..=6), (0i64..=6, 0i64..=6), (0i64..=6, 0i64..=6)],
        ops in prop::collection::vec((0usize..64, 0i64..=6, 0i64..=6), 2..40),
        drop_flat in any::<bool>(),
    ) {
        if let Some(ring) = general(base, &ops) {
            let ring = if drop_flat { without_flat(&ring) } else { ring };
            both(&[ring])?;
        }
    }
}

proptest! {
    #![proptest_config(config(1_000, 0x5eed_0703))]
    #[test]
    fn rectilinear_polygons(
        start in (0i64..6, 0i64..6),
        ops in prop::collection::vec((0i64..6, 0i64..6), 0..40),
        drop_flat in any::<bool>(),
    ) {
        let ring = rectilinear(start, &ops);
        let ring = if drop_flat { without_flat(&ring) } else { ring };
        both(&[ring])?;
    }
}

proptest! {
    #![proptest_config(config(600, 0x5eed_0704))]
    #[test]
    fn polygons_with_holes(recipe in holed_recipe()) {
        if let Some(rings) = holed(&recipe) {
            both(&rings)?;
        }
    }
}

/// The random cases are not trivial: general-position polygons of many sizes, `pseudo` merges
/// faces (faces with more than three vertices), and `pseudo-hull` meets collinear input (more
/// angles of at least pi than vertices).
#[test]
fn the_cases_are_varied() {
    let mut rnd = crate::util::xorshift(0x7e57_0707);
    let (mut general_count, mut big, mut merged, mut collinear_hull) = (0, 0, 0, 0);
    for _ in 0..400 {
        let base = [
            (rnd(1001), rnd(1001)),
            (rnd(1001), rnd(1001)),
            (rnd(1001), rnd(1001)),
        ];
        let ops: Vec<(usize, i64, i64)> = (0..2 + rnd(28))
            .map(|_| (rnd(64) as usize, rnd(1001), rnd(1001)))
            .collect();
        let Some(ring) = general(base, &ops) else {
            continue;
        };
        let Some(poly) = polygon_from_rings(&[ring]) else {
            continue;
        };
        if !general_position(&poly) {
            continue;
        }
        general_count += 1;
        big += usize::from(poly.len() >= 12);
        let start = ear::triangulate(&poly).expect("plain");
        let result = pseudo::minimal(&poly, &start.triangles);
        merged += result.faces.iter().filter(|f| f.cycle.len() > 3).count();
    }
    for _ in 0..200 {
        let ring = rectilinear(
            (rnd(6), rnd(6)),
            &(0..rnd(40)).map(|_| (rnd(6), rnd(6))).collect::<Vec<_>>(),
        );
        let Some(poly) = polygon_from_rings(&[ring]) else {
            continue;
        };
        let result =
            pseudo_hull::pseudotriangulate(&poly, pseudo_hull::DEFAULT_LIMIT).expect("hull");
        let counts = result.hull.expect("counts");
        collinear_hull += usize::from(counts.big_angles > poly.len());
    }
    eprintln!("general {general_count}, n >= 12: {big}, merged faces {merged}, collinear hull {collinear_hull}");
    assert!(general_count >= 200 && big >= 50, "{general_count} {big}");
    assert!(merged >= 100, "{merged}");
    assert!(collinear_hull >= 100, "{collinear_hull}");
}
