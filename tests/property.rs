//! Property tests: random simple polygons on tiny integer grids (coordinates 0..6), where
//! collinear triples, flat vertices and long collinear runs are everywhere.
//!
//! - the DP's output passes the independent checker, its count lies within Chen & Chang's
//!   Theorem 3 bounds (generalised to flat vertices), and on polygons of up to 8 vertices equals an exhaustive search over all
//!   sets of empty vertex triangles (written here from scratch, sharing no code with the crate's
//!   algorithms);
//! - MINITRI's output passes the checker and has exactly the DP's count;
//! - Lemma 3 of Chen & Chang: fewer than 2n - 1 minimally degenerate triangles, on polygons
//!   without flat vertices (with flat vertices, see `lemma_3_with_flat_vertices` below);
//! - the plain triangulation passes the checker with exactly n - 2 triangles.
//!
//! Random polygons: "general" ones grow from a random triangle by inserting random grid points
//! into random edges (kept when the polygon stays simple); "rectilinear" ones are boundaries of
//! random polyominoes (every lattice point on the boundary is a vertex, so most are flat).
//! Either kind is used with its flat vertices, and with them removed.

use minitri::algo::{asano, ear, minitri as chen_chang};
use minitri::geom::kernel::{cross, dot, in_closed_wedge, Point};
use minitri::{verify, Decimal, Polygon, RawPolygon};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use std::collections::BTreeSet;

fn to_polygon(ring: &[(i64, i64)]) -> Option<Polygon> {
    let d = |v: i64| Decimal::parse(&v.to_string()).ok();
    let ring: Option<Vec<[Decimal; 2]>> = ring.iter().map(|&(x, y)| Some([d(x)?, d(y)?])).collect();
    Polygon::from_raw(&RawPolygon { rings: vec![ring?] })
        .ok()
        .map(|(p, _)| p)
}

/// Grows a random simple polygon from a triangle.
fn general(base: [(i64, i64); 3], ops: &[(usize, i64, i64)]) -> Option<Vec<(i64, i64)>> {
    let mut ring = base.to_vec();
    to_polygon(&ring)?;
    for &(at, x, y) in ops {
        let mut next = ring.clone();
        next.insert(at % ring.len() + 1, (x, y));
        if to_polygon(&next).is_some() {
            ring = next;
        }
    }
    Some(ring)
}

/// The boundary of a random polyomino grown from `start` by adding 4-adjacent cells; `None` if
/// a step would pinch the boundary or enclose a hole (such steps are skipped).
fn rectilinear(start: (i64, i64), ops: &[(i64, i64)]) -> Vec<(i64, i64)> {
    let mut cells: BTreeSet<(i64, i64)> = BTreeSet::from([start]);
    let mut ring = boundary(&cells).unwrap_or_default();
    for &c in ops {
        let adjacent = [(1, 0), (-1, 0), (0, 1), (0, -1)]
            .iter()
            .any(|(dx, dy)| cells.contains(&(c.0 + dx, c.1 + dy)));
        if !adjacent || cells.contains(&c) {
            continue;
        }
        cells.insert(c);
        match boundary(&cells) {
            Some(b) => ring = b,
            None => {
                cells.remove(&c);
            }
        }
    }
    ring
}

/// Traces the boundary of a set of unit cells counter-clockwise, one vertex per lattice point.
fn boundary(cells: &BTreeSet<(i64, i64)>) -> Option<Vec<(i64, i64)>> {
    let mut edges: BTreeSet<((i64, i64), (i64, i64))> = BTreeSet::new();
    for &(x, y) in cells {
        let corners = [(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)];
        for k in 0..4 {
            let e = (corners[k], corners[(k + 1) % 4]);
            if !edges.remove(&(e.1, e.0)) {
                edges.insert(e);
            }
        }
    }
    let first = *edges.iter().next()?;
    let mut ring = vec![first.0];
    let mut at = first.1;
    while at != first.0 {
        let mut out = edges.range((at, (i64::MIN, i64::MIN))..=(at, (i64::MAX, i64::MAX)));
        let e = *out.next()?;
        if out.next().is_some() {
            return None; // pinch: two cells meet at a corner only
        }
        ring.push(at);
        at = e.1;
    }
    (ring.len() == edges.len()).then_some(ring) // otherwise a hole
}

/// Removes flat vertices (middle of three collinear consecutive ones).
fn without_flat(ring: &[(i64, i64)]) -> Vec<(i64, i64)> {
    let p = |k: usize| Point::new(ring[k % ring.len()].0, ring[k % ring.len()].1);
    (0..ring.len())
        .filter(|&k| cross(p(k + ring.len() - 1), p(k), p(k + 1)) != 0)
        .map(|k| ring[k])
        .collect()
}

// ---------- an exhaustive minimum, independent of the crate's algorithms ----------

/// Is the closed segment `a b` inside the closed polygon? Straight from the definition.
fn chord(poly: &Polygon, a: usize, b: usize) -> bool {
    let (pa, pb) = (poly.point(a), poly.point(b));
    let wedge = |w: usize, t: Point| {
        in_closed_wedge(
            poly.point(poly.prev(w)),
            poly.point(w),
            poly.point(poly.next(w)),
            t,
        )
    };
    if !wedge(a, pb) || !wedge(b, pa) {
        return false;
    }
    (0..poly.len()).all(|w| {
        let (p, q) = (poly.point(w), poly.point(poly.next(w)));
        let (o1, o2, o3, o4) = (
            cross(pa, pb, p),
            cross(pa, pb, q),
            cross(p, q, pa),
            cross(p, q, pb),
        );
        let crosses = o1.signum() * o2.signum() < 0 && o3.signum() * o4.signum() < 0;
        let inside = o1 == 0 && dot(p, pa, pb) < 0;
        !crosses && (!inside || (wedge(w, pa) && wedge(w, pb)))
    })
}

/// Whether two counter-clockwise triangles have disjoint interiors (a separating side line).
fn disjoint(t: &[Point; 3], u: &[Point; 3]) -> bool {
    let separates = |s: &[Point; 3], o: &[Point; 3]| {
        (0..3).any(|k| o.iter().all(|&q| cross(s[k], s[(k + 1) % 3], q) <= 0))
    };
    separates(t, u) || separates(u, t)
}

/// The fewest triangles partitioning the polygon, by exhaustive search over sets of empty vertex
/// triangles (all sides chords, no vertex strictly inside, pairwise disjoint interiors, total
/// area equal to the polygon's). Every boundary edge must lie in a side of exactly one triangle,
/// which guides the search; interior triangles are then tried in increasing order.
fn exhaustive_minimum(poly: &Polygon) -> usize {
    let n = poly.len();
    let area = poly.twice_area().value().unwrap();
    let mut cands: Vec<([usize; 3], [Point; 3], i128)> = Vec::new();
    for a in 0..n {
        for b in a + 1..n {
            for c in b + 1..n {
                let (mut t, mut pts) = ([a, b, c], [poly.point(a), poly.point(b), poly.point(c)]);
                let mut s = cross(pts[0], pts[1], pts[2]);
                if s == 0 {
                    continue;
                }
                if s < 0 {
                    t.swap(1, 2);
                    pts.swap(1, 2);
                    s = -s;
                }
                let empty = (0..n).all(|w| {
                    let q = poly.point(w);
                    !(0..3).all(|k| cross(pts[k], pts[(k + 1) % 3], q) > 0)
                });
                if empty && chord(poly, a, b) && chord(poly, b, c) && chord(poly, a, c) {
                    cands.push((t, pts, s));
                }
            }
        }
    }
    let on_side = |e: usize, pts: &[Point; 3]| {
        let (p, q) = (poly.point(e), poly.point(poly.next(e)));
        (0..3).any(|k| {
            let (s, t) = (pts[k], pts[(k + 1) % 3]);
            cross(s, t, p) == 0 && cross(s, t, q) == 0 && dot(p, s, t) <= 0 && dot(q, s, t) <= 0
        })
    };
    #[allow(clippy::too_many_arguments)]
    fn search(
        chosen: &mut Vec<usize>,
        first_interior: usize,
        sum: i128,
        limit: usize,
        area: i128,
        cands: &[([usize; 3], [Point; 3], i128)],
        n: usize,
        on_side: &dyn Fn(usize, &[Point; 3]) -> bool,
    ) -> bool {
        if sum == area {
            return (0..n).all(|e| chosen.iter().any(|&c| on_side(e, &cands[c].1)));
        }
        if sum > area || chosen.len() == limit {
            return false;
        }
        let fits = |c: usize| chosen.iter().all(|&o| disjoint(&cands[c].1, &cands[o].1));
        // While a boundary edge is uncovered, the triangle covering it is tried in every way;
        // after that, the remaining (interior) triangles in increasing order, to skip permutations.
        let (options, interior): (Vec<usize>, bool) =
            match (0..n).find(|&e| !chosen.iter().any(|&c| on_side(e, &cands[c].1))) {
                Some(e) => (
                    (0..cands.len())
                        .filter(|&c| on_side(e, &cands[c].1) && fits(c))
                        .collect(),
                    false,
                ),
                None => (
                    (first_interior..cands.len())
                        .filter(|&c| !chosen.contains(&c) && fits(c))
                        .collect(),
                    true,
                ),
            };
        for c in options {
            chosen.push(c);
            let next_interior = if interior { c + 1 } else { first_interior };
            let found = search(
                chosen,
                next_interior,
                sum + cands[c].2,
                limit,
                area,
                cands,
                n,
                on_side,
            );
            chosen.pop();
            if found {
                return true;
            }
        }
        false
    }
    (1..=n - 2)
        .find(|&limit| search(&mut Vec::new(), 0, 0, limit, area, &cands, n, &on_side))
        .expect("n - 2 triangles always suffice")
}

// ---------- the properties ----------

fn check_all(ring: &[(i64, i64)]) -> Result<(), TestCaseError> {
    let Some(poly) = to_polygon(ring) else {
        return Ok(());
    };
    let n = poly.len();
    let dp = asano::triangulate(&poly, asano::DEFAULT_LIMIT)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    let report = verify::check(&poly, &dp);
    prop_assert!(
        report.valid,
        "DP output invalid on {:?}: {:?}",
        ring,
        report.problems
    );
    let count = dp.triangles.len();
    // Chen & Chang's Theorem 3 (no flat vertices): ceil(n/3) <= count <= n - 2. A flat vertex
    // need not be a corner of any triangle, every other vertex must be, so in general the lower
    // bound is ceil((n - f)/3) with f flat vertices (decimal_collinear.wkt: n = 4, minimum 1).
    let flat = (0..n)
        .filter(|&i| {
            cross(
                poly.point(poly.prev(i)),
                poly.point(i),
                poly.point(poly.next(i)),
            ) == 0
        })
        .count();
    prop_assert!(
        (n - flat).div_ceil(3) <= count && count <= n - 2,
        "bounds: {} for n = {}, f = {}",
        count,
        n,
        flat
    );
    if n <= 8 {
        prop_assert_eq!(
            count,
            exhaustive_minimum(&poly),
            "DP vs exhaustive on {:?}",
            ring
        );
    }
    let k = chen_chang::degenerate::minimally_degenerate(&poly).len();
    if flat == 0 {
        prop_assert!(k < 2 * n - 1, "Lemma 3: K = {} for n = {}", k, n);
    }
    let fast = chen_chang::triangulate(&poly).map_err(|e| TestCaseError::fail(e.to_string()))?;
    let report = verify::check(&poly, &fast);
    prop_assert!(
        report.valid,
        "MINITRI output invalid on {:?}: {:?}",
        ring,
        report.problems
    );
    prop_assert_eq!(fast.triangles.len(), count, "MINITRI vs DP on {:?}", ring);
    // The general method (for holes: dependency graph, exact search, cuts) on the same polygon.
    let general = chen_chang::triangulate_general(&poly, None)
        .map_err(|e| TestCaseError::fail(e.to_string()))?;
    let report = verify::check(&poly, &general);
    prop_assert!(
        report.valid,
        "general method output invalid on {:?}: {:?}",
        ring,
        report.problems
    );
    prop_assert!(general.optimal);
    prop_assert_eq!(
        general.triangles.len(),
        count,
        "general method vs DP on {:?}",
        ring
    );
    let plain = ear::triangulate(&poly).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(plain.triangles.len(), n - 2);
    let report = verify::check(&poly, &plain);
    prop_assert!(
        report.valid,
        "ear output invalid on {:?}: {:?}",
        ring,
        report.problems
    );
    Ok(())
}

fn config(cases: u32, seed: u64) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(seed),
        failure_persistence: None,
        ..Config::default()
    }
}

fn point() -> impl Strategy<Value = (i64, i64)> {
    (0i64..=6, 0i64..=6)
}

proptest! {
    #![proptest_config(config(12_000, 0x5eed_0001))]
    #[test]
    fn general_polygons(
        base in [point(), point(), point()],
        ops in prop::collection::vec((0usize..64, 0i64..=6, 0i64..=6), 2..40),
        drop_flat in any::<bool>(),
    ) {
        if let Some(ring) = general(base, &ops) {
            let ring = if drop_flat { without_flat(&ring) } else { ring };
            check_all(&ring)?;
        }
    }
}

proptest! {
    #![proptest_config(config(8_000, 0x5eed_0002))]
    #[test]
    fn rectilinear_polygons(
        start in (0i64..6, 0i64..6),
        ops in prop::collection::vec((0i64..6, 0i64..6), 0..40),
        drop_flat in any::<bool>(),
    ) {
        let ring = rectilinear(start, &ops);
        let ring = if drop_flat { without_flat(&ring) } else { ring };
        check_all(&ring)?;
    }
}

#[test]
fn the_exhaustive_search_itself_finds_known_minima() {
    let design = [
        (vec![(0, 0), (1, 0), (2, 0), (3, 0), (3, 3), (0, 3)], 2),
        (vec![(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)], 3),
        (vec![(0, 0), (1, 0), (2, -1), (3, 0), (4, 0), (2, 2)], 2),
        (
            vec![
                (3, 2),
                (6, 2),
                (6, 4),
                (5, 4),
                (5, 3),
                (4, 3),
                (4, 4),
                (3, 4),
            ],
            6,
        ),
        (vec![(0, 0), (4, 0), (4, 4), (0, 4)], 2),
    ];
    for (ring, minimum) in design {
        assert_eq!(
            exhaustive_minimum(&to_polygon(&ring).unwrap()),
            minimum,
            "{ring:?}"
        );
    }
}

#[test]
fn the_generators_make_varied_polygons() {
    let ring = rectilinear((0, 0), &[(1, 0), (2, 0), (2, 1), (0, 1)]);
    assert_eq!(
        to_polygon(&ring).map(|p| p.len()),
        Some(12),
        "the U-shape: {ring:?}"
    );
    assert_eq!(without_flat(&ring).len(), 8);
    let ring = general([(0, 0), (6, 0), (3, 6)], &[(0, 3, 0), (1, 3, 2)]).unwrap();
    assert_eq!(ring, vec![(0, 0), (3, 0), (3, 2), (6, 0), (3, 6)]);
}

/// Polygons from both generators, deterministically, for statistics over the test population.
fn population(count: usize) -> Vec<Polygon> {
    let mut seed = 0x0dd_b1a5_e5e5_u64;
    let mut rnd = move |n: i64| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n as u64) as i64
    };
    let mut out = Vec::new();
    while out.len() < count {
        let ring = if rnd(2) == 0 {
            let base = [(rnd(7), rnd(7)), (rnd(7), rnd(7)), (rnd(7), rnd(7))];
            let ops: Vec<(usize, i64, i64)> = (0..rnd(38) + 2)
                .map(|_| (rnd(64) as usize, rnd(7), rnd(7)))
                .collect();
            general(base, &ops)
        } else {
            let ops: Vec<(i64, i64)> = (0..rnd(40)).map(|_| (rnd(6), rnd(6))).collect();
            Some(rectilinear((rnd(6), rnd(6)), &ops))
        };
        if let Some(p) = ring.and_then(|r| to_polygon(&r)) {
            out.push(p);
        }
    }
    out
}

#[test]
fn the_population_has_long_3b_chains_and_large_dependency_clusters() {
    let (mut chain2, mut chain3, mut chain4) = (0, 0, 0);
    for p in population(3000) {
        let mdts = chen_chang::degenerate::minimally_degenerate(&p);
        let chains = chen_chang::mis::chains(&p, &mdts);
        let longest = chains.paths.iter().map(Vec::len).max().unwrap_or(0);
        chain2 += usize::from(longest >= 2);
        chain3 += usize::from(longest >= 3);
        chain4 += usize::from(longest >= 4);
    }
    // Measured: 834, 249 and 63 of the 3000 polygons.
    assert!(
        chain2 >= 600 && chain3 >= 150 && chain4 >= 30,
        "3b-chains: {chain2} / {chain3} / {chain4}"
    );
}

/// Lemma 3 is proved for polygons without flat vertices. With flat vertices no proof is known to
/// us; on these 3000 polygons (most with flat vertices) K < 2n - 1 still holds, and this test
/// keeps watching it: a failure would be a finding worth a fixture, not a bug by itself.
#[test]
fn lemma_3_with_flat_vertices() {
    let mut worst = 0.0f64;
    for p in population(3000) {
        let n = p.len();
        let flat = (0..n)
            .filter(|&i| cross(p.point(p.prev(i)), p.point(i), p.point(p.next(i))) == 0)
            .count();
        let k = chen_chang::degenerate::minimally_degenerate(&p).len();
        assert!(k < 2 * n - 1, "K = {k}, n = {n}, f = {flat}");
        worst = worst.max(k as f64 / n as f64);
    }
    assert!(
        worst > 0.5,
        "the population has many degenerate triangles: max K/n = {worst}"
    );
}

/// The long soak of issue 3: a million random polygons (half general, half rectilinear) through
/// every property above. Run it with `cargo test --release --test main soak -- --ignored`;
/// `MINITRI_SOAK_CASES` changes the count.
#[test]
#[ignore]
fn soak() {
    let cases: u32 = std::env::var("MINITRI_SOAK_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1_000_000);
    let mut runner = proptest::test_runner::TestRunner::new(config(cases / 2, 0x50a4_0001));
    let general_case = (
        [point(), point(), point()],
        prop::collection::vec((0usize..64, 0i64..=6, 0i64..=6), 2..40),
        any::<bool>(),
    );
    runner
        .run(&general_case, |(base, ops, drop_flat)| {
            if let Some(ring) = general(base, &ops) {
                check_all(&if drop_flat { without_flat(&ring) } else { ring })?;
            }
            Ok(())
        })
        .expect("general polygons");
    let mut runner = proptest::test_runner::TestRunner::new(config(cases / 2, 0x50a4_0002));
    let rectilinear_case = (
        (0i64..6, 0i64..6),
        prop::collection::vec((0i64..6, 0i64..6), 0..40),
        any::<bool>(),
    );
    runner
        .run(&rectilinear_case, |(start, ops, drop_flat)| {
            let ring = rectilinear(start, &ops);
            check_all(&if drop_flat { without_flat(&ring) } else { ring })
        })
        .expect("rectilinear polygons");
}
