//! Property tests: random simple polygons on tiny integer grids (coordinates 0..6), where
//! collinear triples, flat vertices and long collinear runs are everywhere.
//!
//! - the DP's output passes the independent checker, its count lies within Chen & Chang's
//!   Theorem 3 bounds (generalised to flat vertices), and on polygons of up to 8 vertices equals an exhaustive search over all
//!   sets of empty vertex triangles (written here from scratch, sharing no code with the crate's
//!   algorithms);
//! - MINITRI's output passes the checker and has exactly the DP's count;
//! - step 1 finds the same minimally degenerate triangles, kinds included, with the walk alone,
//!   the bounded method alone (balanced cuts and shortest-path trees), the default hybrid and
//!   every ray policy, and the angular sweep agrees;
//! - Lemma 3 of Chen & Chang: fewer than 2n - 1 minimally degenerate triangles, on polygons
//!   without flat vertices (with flat vertices, see `lemma_3_with_flat_vertices` below);
//! - the plain triangulation passes the checker with exactly n - 2 triangles, and on random
//!   polygons with 1 to 3 holes (polyomino regions with polyomino holes carved strictly inside,
//!   corners cut diagonally, flat vertices kept or dropped per ring) with exactly n + 2w - 2.
//!
//! Random polygons: "general" ones grow from a random triangle by inserting random grid points
//! into random edges (kept when the polygon stays simple); "rectilinear" ones are boundaries of
//! random polyominoes (every lattice point on the boundary is a vertex, so most are flat).
//! Either kind is used with its flat vertices, and with them removed.

use crate::util::{chord, polygon_from_rings, xorshift};
use minitri::algo::{asano, minitri as chen_chang, plain};
use minitri::geom::kernel::{cross, dot, Point};
use minitri::{verify, Decimal, Polygon, RawPolygon};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use std::collections::BTreeSet;

fn to_polygon(ring: &[(i64, i64)]) -> Option<Polygon> {
    let d = |v: i64| Decimal::parse(&v.to_string()).ok();
    let ring: Option<Vec<[Decimal; 2]>> = ring.iter().map(|&(x, y)| Some([d(x)?, d(y)?])).collect();
    Polygon::from_raw(&RawPolygon {
        rings: vec![ring?],
        ..Default::default()
    })
    .ok()
    .map(|(p, _)| p)
}

/// Grows a random simple polygon from a triangle.
pub(crate) fn general(base: [(i64, i64); 3], ops: &[(usize, i64, i64)]) -> Option<Vec<(i64, i64)>> {
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
pub(crate) fn rectilinear(start: (i64, i64), ops: &[(i64, i64)]) -> Vec<(i64, i64)> {
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
pub(crate) fn without_flat(ring: &[(i64, i64)]) -> Vec<(i64, i64)> {
    let p = |k: usize| Point::new(ring[k % ring.len()].0, ring[k % ring.len()].1);
    (0..ring.len())
        .filter(|&k| cross(p(k + ring.len() - 1), p(k), p(k + 1)) != 0)
        .map(|k| ring[k])
        .collect()
}

// ---------- an exhaustive minimum, independent of the crate's algorithms ----------

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
    // Step 1 finds the same set of triangles, kinds included, whatever the ray policy and the
    // walk's budget (the walk alone, the bounded method alone, the hybrid), and the angular
    // sweep agrees.
    chen_chang::degenerate::check_ray_policies(&poly).map_err(TestCaseError::fail)?;
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
    let plain = plain::triangulate(&poly).map_err(|e| TestCaseError::fail(e.to_string()))?;
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

pub(crate) fn config(cases: u32, seed: u64) -> Config {
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
    let mut rnd = xorshift(0x0dd_b1a5_e5e5_u64);
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
        let longest = chains.paths.iter().map(<[usize]>::len).max().unwrap_or(0);
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

// ---------- plain triangulation of polygons with holes (issue 4) ----------

const NEIGHBOURS_8: [(i64, i64); 8] = [
    (-1, -1),
    (0, -1),
    (1, -1),
    (-1, 0),
    (1, 0),
    (-1, 1),
    (0, 1),
    (1, 1),
];

/// Deletes the vertices of `ring` whose bit is set in `cuts` (bit k for vertex k, cyclically),
/// cutting the corner off: first the lattice points one unit from the vertex along both of its
/// edges become vertices (if they are not already), then the vertex goes. A deletion that would
/// leave the ring with fewer than 3 vertices is skipped; validity is checked by the caller.
fn cut_corners(ring: &[(i64, i64)], cuts: u64) -> Vec<(i64, i64)> {
    let n = ring.len();
    let mut out = Vec::with_capacity(2 * n);
    for k in 0..n {
        let (p, v, q) = (ring[(k + n - 1) % n], ring[k], ring[(k + 1) % n]);
        if cuts >> (k % 64) & 1 == 0 || n < 4 {
            out.push(v);
            continue;
        }
        let step = |to: (i64, i64)| {
            let (dx, dy) = (to.0 - v.0, to.1 - v.1);
            let g = gcd(dx.abs(), dy.abs()).max(1);
            (v.0 + dx / g, v.1 + dy / g)
        };
        let (a, b) = (step(p), step(q));
        if a != p {
            out.push(a);
        }
        if b != q {
            out.push(b);
        }
    }
    out.dedup();
    while out.len() > 1 && out.first() == out.last() {
        out.pop();
    }
    out
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

/// The recipe for a random polygon with holes on a grid of cells of side 2: an outer region of
/// `width x height` cells with the cells of `notches` carved from its boundary (kept only while
/// its boundary stays simple), then up to three polyomino holes, each grown from a start cell (the
/// `start`-th free cell, modulo their number) by adding 4-adjacent cells, all strictly inside
/// (every cell's eight neighbours are outer cells), with a gap of at least one cell between holes.
/// Every lattice point on a ring is a vertex (flat vertices in the middle of every cell side);
/// then some corners of each ring are cut off diagonally (`cuts`, one word per ring) and the
/// flat vertices of some rings dropped (`plain`, one bit per ring). Any modification that makes
/// the polygon invalid is undone.
#[derive(Clone, Debug)]
pub(crate) struct HoledRecipe {
    width: i64,
    height: i64,
    notches: Vec<(i64, i64)>,
    holes: Vec<(usize, Vec<(i64, i64)>)>,
    cuts: [u64; 4],
    plain: u8,
}

pub(crate) fn holed(recipe: &HoledRecipe) -> Option<Vec<Vec<(i64, i64)>>> {
    let mut outer: BTreeSet<(i64, i64)> = BTreeSet::new();
    for x in 0..recipe.width {
        for y in 0..recipe.height {
            outer.insert((x, y));
        }
    }
    for &c in &recipe.notches {
        let on_boundary = [(1, 0), (-1, 0), (0, 1), (0, -1)]
            .iter()
            .any(|(dx, dy)| !outer.contains(&(c.0 + dx, c.1 + dy)));
        if on_boundary && outer.len() > 1 && outer.remove(&c) && boundary(&outer).is_none() {
            outer.insert(c);
        }
    }
    let mut taken: BTreeSet<(i64, i64)> = BTreeSet::new(); // cells of all holes
    let mut holes: Vec<BTreeSet<(i64, i64)>> = Vec::new();
    for (start, ops) in &recipe.holes {
        let free = |c: &(i64, i64), own: &BTreeSet<(i64, i64)>| {
            outer.contains(c)
                && NEIGHBOURS_8.iter().all(|(dx, dy)| {
                    let m = (c.0 + dx, c.1 + dy);
                    outer.contains(&m) && (own.contains(&m) || !taken.contains(&m))
                })
                && !taken.contains(c)
        };
        let mut cells = BTreeSet::new();
        let candidates: Vec<(i64, i64)> =
            outer.iter().filter(|c| free(c, &cells)).copied().collect();
        if candidates.is_empty() {
            break;
        }
        cells.insert(candidates[start % candidates.len()]);
        for &c in ops {
            let adjacent = [(1, 0), (-1, 0), (0, 1), (0, -1)]
                .iter()
                .any(|(dx, dy)| cells.contains(&(c.0 + dx, c.1 + dy)));
            if adjacent && !cells.contains(&c) && free(&c, &cells) {
                cells.insert(c);
                if boundary(&cells).is_none() {
                    cells.remove(&c);
                }
            }
        }
        taken.extend(cells.iter().copied());
        holes.push(cells);
    }
    if holes.is_empty() {
        return None;
    }
    let mut rings: Vec<Vec<(i64, i64)>> = std::iter::once(&outer)
        .chain(&holes)
        .map(|cells| {
            let ring = boundary(cells).expect("simple by construction");
            let m = ring.len();
            (0..m)
                .flat_map(|k| {
                    let (a, b) = (ring[k], ring[(k + 1) % m]);
                    [(2 * a.0, 2 * a.1), (a.0 + b.0, a.1 + b.1)]
                })
                .collect()
        })
        .collect();
    polygon_from_rings(&rings).expect("valid by construction");
    for (r, &bits) in recipe.cuts.iter().enumerate().take(rings.len()) {
        let before = rings[r].clone();
        rings[r] = cut_corners(&before, bits);
        if polygon_from_rings(&rings).is_none() {
            rings[r] = before;
        }
    }
    for r in 0..rings.len() {
        if recipe.plain >> r & 1 == 1 {
            let before = rings[r].clone();
            rings[r] = without_flat(&before);
            if polygon_from_rings(&rings).is_none() {
                rings[r] = before;
            }
        }
    }
    Some(rings)
}

pub(crate) fn holed_recipe() -> impl Strategy<Value = HoledRecipe> {
    (
        3i64..=10,
        3i64..=10,
        prop::collection::vec((0i64..10, 0i64..10), 0..16),
        prop::collection::vec(
            (
                any::<usize>(),
                prop::collection::vec((1i64..9, 1i64..9), 0..10),
            ),
            1..=3,
        ),
        any::<[u64; 4]>(),
        any::<u8>(),
    )
        .prop_map(|(width, height, notches, holes, cuts, plain)| HoledRecipe {
            width,
            height,
            notches,
            holes,
            cuts,
            plain,
        })
}

/// `--algorithm ear` on a polygon with holes: exactly n + 2w - 2 triangles, none degenerate,
/// passing the independent checker.
fn check_plain_with_holes(rings: &[Vec<(i64, i64)>]) -> Result<(), TestCaseError> {
    let poly = polygon_from_rings(rings).ok_or_else(|| TestCaseError::fail("invalid polygon"))?;
    let (n, w) = (poly.len(), poly.holes());
    let t = plain::triangulate(&poly).map_err(|e| TestCaseError::fail(e.to_string()))?;
    prop_assert_eq!(t.triangles.len(), n + 2 * w - 2, "count on {:?}", rings);
    prop_assert!(t.degenerate.is_empty());
    let report = verify::check(&poly, &t);
    prop_assert!(
        report.valid,
        "ear output invalid on {:?}: {:?}",
        rings,
        report.problems
    );
    Ok(())
}

proptest! {
    #![proptest_config(config(4_000, 0x5eed_0004))]
    #[test]
    fn plain_triangulation_of_polygons_with_holes(recipe in holed_recipe()) {
        if let Some(rings) = holed(&recipe) {
            check_plain_with_holes(&rings)?;
        }
    }
}

/// Recipes drawn deterministically (as the proptest strategy draws them), for statistics.
fn holed_population(count: usize) -> Vec<Vec<Vec<(i64, i64)>>> {
    let mut rnd = xorshift(0x401e_5eed_u64);
    let mut out = Vec::new();
    let mut tries = 0;
    while out.len() < count {
        tries += 1;
        assert!(tries < 3 * count, "the generator fails too often");
        let recipe = HoledRecipe {
            width: 3 + rnd(8),
            height: 3 + rnd(8),
            notches: (0..rnd(16)).map(|_| (rnd(10), rnd(10))).collect(),
            holes: (0..1 + rnd(3))
                .map(|_| {
                    let ops = (0..rnd(10)).map(|_| (1 + rnd(8), 1 + rnd(8))).collect();
                    (rnd(1000) as usize, ops)
                })
                .collect(),
            cuts: [0; 4].map(|_| (rnd(1 << 16) as u64) << 16 | rnd(1 << 16) as u64),
            plain: rnd(256) as u8,
        };
        out.extend(holed(&recipe));
    }
    out
}

#[test]
fn the_holes_generator_makes_varied_valid_polygons() {
    // A hand-checked recipe: a 5 x 5 square, notched at a corner, with a 1 x 2 hole (the
    // centre cell (2, 2) is the 4th free cell; (0, 0) is not deep inside).
    let square = HoledRecipe {
        width: 5,
        height: 5,
        notches: vec![(4, 4)],
        holes: vec![(4, vec![(2, 3), (0, 0)])],
        cuts: [0; 4],
        plain: 0b01,
    };
    let rings = holed(&square).unwrap();
    assert_eq!(rings.len(), 2);
    assert_eq!(
        rings[0].len(),
        6,
        "notched outer ring, flat vertices dropped"
    );
    assert_eq!(
        rings[1],
        [
            (4, 4),
            (5, 4),
            (6, 4),
            (6, 5),
            (6, 6),
            (6, 7),
            (6, 8),
            (5, 8),
            (4, 8),
            (4, 7),
            (4, 6),
            (4, 5)
        ],
        "the hole keeps every lattice point"
    );
    // The population: many hole counts, flat vertices and diagonal edges on holes, hole vertices
    // level with outer vertices and with other holes' vertices (the sweep's ties).
    let population = holed_population(2000);
    let (mut holes, mut flat_on_hole, mut diagonal_hole, mut diagonal_outer) = ([0; 4], 0, 0, 0);
    let (mut level_with_outer, mut holes_level, mut sizes) = (0, 0, BTreeSet::new());
    for rings in &population {
        let poly = polygon_from_rings(rings).expect("valid");
        holes[poly.holes()] += 1;
        sizes.insert(poly.len());
        let pts = |r: usize| -> Vec<Point> { poly.ring_range(r).map(|i| poly.point(i)).collect() };
        let flat = |i: usize| {
            cross(
                poly.point(poly.prev(i)),
                poly.point(i),
                poly.point(poly.next(i)),
            ) == 0
        };
        let diagonal = |r: usize| {
            poly.ring_range(r).any(|i| {
                let (p, q) = (poly.point(i), poly.point(poly.next(i)));
                p.x != q.x && p.y != q.y
            })
        };
        flat_on_hole += usize::from((poly.ring_range(0).end..poly.len()).any(flat));
        diagonal_hole += usize::from((1..=poly.holes()).any(diagonal));
        diagonal_outer += usize::from(diagonal(0));
        let outer_ys: BTreeSet<i64> = pts(0).iter().map(|p| p.y).collect();
        let hole_ys: Vec<BTreeSet<i64>> = (1..=poly.holes())
            .map(|r| pts(r).iter().map(|p| p.y).collect())
            .collect();
        level_with_outer += usize::from(hole_ys.iter().flatten().any(|y| outer_ys.contains(y)));
        holes_level += usize::from(
            (0..hole_ys.len())
                .any(|a| (a + 1..hole_ys.len()).any(|b| !hole_ys[a].is_disjoint(&hole_ys[b]))),
        );
    }
    // Measured: holes [0, 856, 724, 420], flat on a hole 871, diagonal hole edge 1743, diagonal
    // outer edge 1859, hole level with outer 1549, holes level with each other 584, 74 distinct
    // n from 7 to 82.
    let varied = holes[1] > 600
        && holes[2] > 500
        && holes[3] > 300
        && flat_on_hole > 600
        && diagonal_hole > 1200
        && diagonal_outer > 1200
        && level_with_outer > 1000
        && holes_level > 400
        && sizes.len() > 50;
    let stats = format!(
        "holes {holes:?}, flat on a hole {flat_on_hole}, diagonal hole edge {diagonal_hole}, \
         diagonal outer edge {diagonal_outer}, hole level with outer {level_with_outer}, holes \
         level with each other {holes_level}, distinct n {} ({}..={})",
        sizes.len(),
        sizes.first().unwrap_or(&0),
        sizes.last().unwrap_or(&0)
    );
    println!("{stats}");
    assert!(varied, "{stats}");
    for rings in population.iter().take(300) {
        check_plain_with_holes(rings).unwrap();
    }
}
