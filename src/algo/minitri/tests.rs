//! Unit tests of the MINITRI steps on hand-made polygons.

use super::chains::{chains, is_3b_pair};
use super::circle::{circle, Circle};
use super::degenerate::{minimally_degenerate, minimally_degenerate_and_mesh, Degenerate, Kind};
use super::dependency::dependent;
use super::ladder::LadderPolicy;
use super::mis::{crossing_components, maximum_independent_set_with, Effort, Method};
use super::triangulate;
use crate::algo::asano;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use crate::test_support::{plain_problems, polygon, vertex_at, U_SHAPE};

/// The minimally degenerate triangle with these three vertices (by coordinates), if found.
fn find(
    p: &Polygon,
    mdts: &[Degenerate],
    a: (i64, i64),
    b: (i64, i64),
    c: (i64, i64),
) -> Option<usize> {
    let at = |q: (i64, i64)| vertex_at(p, q);
    let (a, b, c) = (at(a), at(b), at(c));
    mdts.iter()
        .position(|m| m.b == b && ((m.a, m.c) == (a.min(c), a.max(c))))
}

fn minimum_agrees(p: &Polygon) -> usize {
    let t = triangulate(p).unwrap();
    let reference = asano::triangulate(p, asano::DEFAULT_LIMIT).unwrap();
    assert_eq!(t.triangles.len(), reference.triangles.len());
    assert!(
        crate::verify::check(p, &t).valid,
        "{:?}",
        crate::verify::check(p, &t).problems
    );
    t.degenerate.len()
}

#[test]
fn type_i_neither_side_is_an_edge() {
    // The L-shape: the reflex corner (1,1) lies on the diagonal from (2,0) to (0,2).
    let p = polygon(&[&[(0, 0), (2, 0), (2, 1), (1, 1), (1, 2), (0, 2)]]);
    let mdts = minimally_degenerate(&p);
    assert_eq!(mdts.len(), 1);
    assert_eq!(mdts[0].kind, Kind::TypeI);
    assert_eq!(minimum_agrees(&p), 1);
}

#[test]
fn type_ii_one_side_is_an_edge() {
    // The edge (2,2)-(2,1) extended through the reflex vertex (2,1) reaches the vertex (2,0).
    let p = polygon(&[&[(0, 0), (2, 0), (4, 0), (4, 2), (2, 2), (2, 1), (0, 1)]]);
    let mdts = minimally_degenerate(&p);
    let t = find(&p, &mdts, (2, 2), (2, 1), (2, 0)).expect("found");
    assert_eq!(mdts[t].kind, Kind::TypeII);
    minimum_agrees(&p);
}

#[test]
fn type_iii_a_vertex_joins_an_edge_on_the_line() {
    // (0,0)-(1,0) is an edge, (1,0) reflex, and (3,0) continues along the line to (4,0).
    let p = polygon(&[&[(0, 0), (1, 0), (2, -1), (3, 0), (4, 0), (2, 2)]]);
    let mdts = minimally_degenerate(&p);
    let t = find(&p, &mdts, (0, 0), (1, 0), (3, 0)).expect("found");
    assert_eq!(mdts[t].kind, Kind::TypeIII);
    assert_eq!(minimum_agrees(&p), 2);
}

#[test]
fn flat_vertices_are_middles_of_flat_triangles() {
    let p = polygon(&[&[(0, 0), (1, 3), (2, 6), (0, 10)]]);
    let mdts = minimally_degenerate(&p);
    assert_eq!(mdts.len(), 1);
    assert_eq!(
        (mdts[0].a, mdts[0].b, mdts[0].c, mdts[0].kind),
        (0, 1, 2, Kind::Flat)
    );
    assert_eq!(minimum_agrees(&p), 1);
}

/// A box with a notch from the top down to (2,0) and one from the bottom up to (4,0); the line
/// y = 0 holds (0,0), (2,0), (4,0), (6,0).
const ZIGZAG: [(i64, i64); 12] = [
    (0, -2),
    (3, -2),
    (4, 0),
    (5, -2),
    (6, -2),
    (6, 0),
    (6, 2),
    (3, 2),
    (2, 0),
    (1, 2),
    (0, 2),
    (0, 0),
];

#[test]
fn relationship_iii_a_sides_shared_with_180_degree_sides_opposite() {
    let p = polygon(&[&ZIGZAG]);
    let mdts = minimally_degenerate(&p);
    let s = find(&p, &mdts, (0, 0), (2, 0), (4, 0)).expect("found");
    let t = find(&p, &mdts, (2, 0), (4, 0), (6, 0)).expect("found");
    assert!(!is_3b_pair(&p, &mdts[s], &mdts[t]));
    assert!(
        !circle(&p, &mdts).cross(s, t),
        "independent and apart on the circle"
    );
    minimum_agrees(&p);
}

#[test]
fn relationship_iii_b_a_3b_chain_of_length_4() {
    // A comb whose gap bottoms (1,1) .. (6,1) lie on one line, every middle with its 180-degree
    // side below: four triangles, consecutive ones crossing on the circle, all independent.
    let ring = [
        (0, 0),
        (7, 0),
        (7, 3),
        (6, 3),
        (6, 1),
        (5, 1),
        (5, 3),
        (4, 3),
        (4, 1),
        (3, 1),
        (3, 3),
        (2, 3),
        (2, 1),
        (1, 1),
        (1, 3),
        (0, 3),
    ];
    let p = polygon(&[&ring]);
    let mdts = minimally_degenerate(&p);
    let ids: Vec<usize> = (1..=4)
        .map(|x| find(&p, &mdts, (x, 1), (x + 1, 1), (x + 2, 1)).expect("found"))
        .collect();
    let c = circle(&p, &mdts);
    for w in ids.windows(2) {
        assert!(is_3b_pair(&p, &mdts[w[0]], &mdts[w[1]]));
        assert!(c.cross(w[0], w[1]), "3b pairs cross on the circle");
    }
    let ch = chains(&p, &mdts);
    let (chain, _) = ch.place[ids[0]];
    assert_eq!(ch.paths.get(chain).len(), 4);
    assert!(ids.iter().all(|&t| ch.place[t].0 == chain));
    let t = triangulate(&p).unwrap();
    let middles: Vec<usize> = t.degenerate.iter().map(|d| d[1]).collect();
    for x in 2..=5 {
        let v = vertex_at(&p, (x, 1));
        assert!(middles.contains(&v), "the whole chain is used: ({x}, 1)");
    }
    minimum_agrees(&p);
}

#[test]
fn touching_at_a_middle_vertex_on_either_side() {
    let p = polygon(&[&U_SHAPE]);
    let mdts = minimally_degenerate(&p);
    let c: Circle = circle(&p, &mdts);
    // T = (4,2) (4,3) (4,4): middle (4,3), 180-degree side to the left (x < 4).
    let t = find(&p, &mdts, (4, 2), (4, 3), (4, 4)).expect("found");
    // U = (4,3) (5,3) (6,3) ends at T's middle and lies to the right: independent.
    let u = find(&p, &mdts, (4, 3), (5, 3), (6, 3)).expect("found");
    assert!(!c.cross(t, u));
    // The flat (3,4) (3,3) (3,2): anything ending at (3,3) is on its 180-degree side.
    let flat = find(&p, &mdts, (3, 4), (3, 3), (3, 2)).expect("found");
    assert_eq!(mdts[flat].kind, Kind::Flat);
    let w = find(&p, &mdts, (3, 3), (4, 3), (5, 3)).expect("found");
    assert!(c.cross(flat, w), "dependent on the flat triangle");
    assert_eq!(minimum_agrees(&p), 5);
}

#[test]
fn crossing_components_match_brute_force() {
    let mut seed = 0x1234_5678_9abc_def0u64;
    let mut rnd = |n: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % n as u64) as usize
    };
    for _ in 0..500 {
        let k = 1 + rnd(12);
        let mut positions: Vec<usize> = (0..2 * k).collect();
        for i in (1..positions.len()).rev() {
            positions.swap(i, rnd(i + 1));
        }
        let chords: Vec<(usize, usize)> = (0..k)
            .map(|t| {
                (
                    positions[2 * t].min(positions[2 * t + 1]),
                    positions[2 * t].max(positions[2 * t + 1]),
                )
            })
            .collect();
        let c = circle_of(chords);
        // Brute force: label propagation over crossing pairs.
        let mut label: Vec<usize> = (0..k).collect();
        loop {
            let mut changed = false;
            for s in 0..k {
                for t in 0..k {
                    if c.cross(s, t) && label[s] != label[t] {
                        let m = label[s].min(label[t]);
                        label[s] = m;
                        label[t] = m;
                        changed = true;
                    }
                }
            }
            if !changed {
                break;
            }
        }
        let mut expected: Vec<Vec<usize>> = Vec::new();
        for l in 0..k {
            let group: Vec<usize> = (0..k).filter(|&t| label[t] == l).collect();
            if !group.is_empty() {
                expected.push(group);
            }
        }
        let mut got: Vec<Vec<usize>> = crossing_components(&c)
            .iter()
            .map(<[usize]>::to_vec)
            .collect();
        got.sort();
        expected.sort();
        assert_eq!(got, expected, "{:?}", c.chords);
    }
}

/// The MIS on plain circle graphs (every chord its own 3b-chain, so dependence is crossing):
/// random chord sets, many of them long and nested as on bars, against the largest independent
/// set by enumeration.
#[test]
fn maximum_independent_set_matches_enumeration_on_random_circles() {
    let mut rnd = crate::test_support::xorshift(0x5eed_c1c1e);
    let (mut nested, mut levels, mut searches) = (0, 0, 0);
    for _ in 0..1500 {
        let k = 1 + rnd(13) as usize;
        // Half of the time a ladder: chord t joins positions t and 2k - 1 - t before shuffling a
        // few endpoints, so most chords nest.
        let mut positions: Vec<usize> = (0..2 * k).collect();
        let ladder = rnd(2) == 0;
        let swaps = if ladder { rnd(3) as usize } else { 2 * k };
        for _ in 0..swaps {
            let (i, j) = (rnd(2 * k as i64) as usize, rnd(2 * k as i64) as usize);
            positions.swap(i, j);
        }
        let chords: Vec<(usize, usize)> = (0..k)
            .map(|t| {
                let (x, y) = if ladder {
                    (positions[t], positions[2 * k - 1 - t])
                } else {
                    (positions[2 * t], positions[2 * t + 1])
                };
                (x.min(y), x.max(y))
            })
            .collect();
        let c = circle_of(chords);
        let ch = super::chains::Chains::lone(k);
        let (set, searched) = maximum_independent_set_with(&c, &ch, Method::default());
        let (laddered, effort) = maximum_independent_set_with(&c, &ch, EVERY_LEVEL);
        let (plain, _) = maximum_independent_set_with(&c, &ch, PLAIN);
        levels += effort.levels;
        searches += searched.searched;
        assert_eq!(plain.len(), laddered.len(), "{:?}", c.chords);
        for set in [&set, &laddered, &plain] {
            assert_no_crossings(&c, set);
        }
        assert_eq!(set.len(), laddered.len(), "{:?}", c.chords);
        let best = (0u32..1 << k)
            .filter(|&m| {
                (0..k).all(|s| m >> s & 1 == 0 || (0..s).all(|t| m >> t & 1 == 0 || !c.cross(s, t)))
            })
            .map(u32::count_ones)
            .max();
        assert_eq!(Some(set.len() as u32), best, "{:?}", c.chords);
        let nests = |(a, b): (usize, usize), (x, y): (usize, usize)| a < x && y < b;
        if (0..k).any(|s| {
            (0..k).any(|t| {
                (0..k).any(|u| nests(c.chords[s], c.chords[t]) && nests(c.chords[t], c.chords[u]))
            })
        }) {
            nested += 1;
        }
    }
    assert!(
        nested > 600,
        "only {nested} circles with three nested chords"
    );
    assert!(levels > 1500, "only {levels} level matrices built");
    assert!(searches > 1000, "only {searches} components searched");
}

/// A level at every range asked for: the scans jump as often as they can (`super::ladder`);
/// every component of two or more chords goes through the scans (none through
/// [`super::small`]'s search).
const EVERY_LEVEL: Method = Method {
    staircases: true,
    ladders: LadderPolicy::Every,
    small: 1,
};

/// Every piece a unit, no levels, no search of small components: the plain method the others
/// are checked against.
const PLAIN: Method = Method {
    staircases: false,
    ladders: LadderPolicy::Off,
    small: 1,
};

/// A random simple polygon on the grid 0..=8 (many collinear points and flat vertices): a
/// triangle into which up to `inserts` random points are inserted along the boundary, each kept
/// if the polygon stays valid.
fn random_ring(rnd: &mut impl FnMut(i64) -> i64, inserts: i64) -> Vec<(i64, i64)> {
    let mut ring: Vec<(i64, i64)> = vec![(0, 0), (8, 0), (4, 8)];
    for _ in 0..rnd(inserts) {
        let at = rnd(ring.len() as i64) as usize + 1;
        let mut next = ring.clone();
        next.insert(at, (rnd(9), rnd(9)));
        if Polygon::from_raw(&crate::test_support::raw(&[&next])).is_ok() {
            ring = next;
        }
    }
    ring
}

/// A random star-shaped polygon: `n` points at random angles and radii around the origin,
/// sorted by angle (exactly), on a grid of about +-`scale`.
/// A random star (every third `k`) or grid polygon, when valid.
fn star_or_grid(rnd: &mut impl FnMut(i64) -> i64, k: usize) -> Option<Polygon> {
    let size = 6 + rnd(30) as usize;
    let ring = if k.is_multiple_of(3) {
        random_star(rnd, size, 8)
    } else {
        random_ring(rnd, 40)
    };
    Polygon::from_raw(&crate::test_support::raw(&[&ring]))
        .ok()
        .map(|(p, _)| p)
}

fn random_star(rnd: &mut impl FnMut(i64) -> i64, n: usize, scale: i64) -> Vec<(i64, i64)> {
    use crate::geom::kernel::{cmp_angle, Point};
    let mut points: Vec<Point> = (0..n)
        .map(|_| {
            let (angle, radius) = (
                rnd(1 << 20) as f64,
                (3 + rnd(8)) as f64 * scale as f64 / 10.0,
            );
            let a = angle / f64::from(1 << 20) * std::f64::consts::TAU;
            Point::new(
                (radius * a.cos()).round() as i64,
                (radius * a.sin()).round() as i64,
            )
        })
        .filter(|&q| q != Point::new(0, 0))
        .collect();
    let o = Point::new(0, 0);
    points.sort_by(|&a, &b| {
        cmp_angle(o, a, b).then_with(|| (a.x * a.x + a.y * a.y).cmp(&(b.x * b.x + b.y * b.y)))
    });
    points.dedup();
    points.iter().map(|q| (q.x, q.y)).collect()
}

#[test]
fn expansion_matches_the_sweep_on_stars() {
    // Star polygons on small grids: reflex vertices seeing far in both cones, with many exactly
    // opposite directions, exercise the pruning of each cone by the other.
    let mut rnd = crate::test_support::xorshift(0x0dd5_7a75_0000_0001u64);
    let (mut tested, mut found) = (0, 0);
    for k in 0..600 {
        let ring = random_star(&mut rnd, 8 + k % 60, [6, 12, 25][k % 3]);
        let Ok((p, _)) = Polygon::from_raw(&crate::test_support::raw(&[&ring])) else {
            continue;
        };
        tested += 1;
        found += checked_against_the_sweep(&p, &ring).len();
    }
    assert!(
        tested > 300 && found > 3000,
        "{tested} stars, {found} triangles"
    );
}

#[test]
fn flipped_mesh_is_a_triangulation() {
    use super::expansion::Mesh;
    use crate::algo::plain::monotone;
    let mut rnd = crate::test_support::xorshift(0x5eed_f11b_0000_0001u64);
    let mut polygons: Vec<Polygon> = Vec::new();
    for _ in 0..1500 {
        polygons.push(polygon(&[&random_ring(&mut rnd, 40)]));
    }
    for seed in 1..=100u64 {
        polygons.push(bars(4 + (seed as usize % 60), seed));
    }
    for k in 0..100 {
        let ring = random_star(&mut rnd, 10 + k * 3, [10, 1000, 1 << 40][k % 3]);
        // Points sorted by angle from the origin may still be invalid (collinear with it).
        if let Ok((p, _)) = Polygon::from_raw(&crate::test_support::raw(&[&ring])) {
            polygons.push(p);
        }
    }
    assert!(polygons.len() > 1650);
    let mut flipped = 0;
    for p in &polygons {
        for cap in [0, 1, 5, 4 * p.len(), 100 * p.len()] {
            let mut mesh = Mesh::new(p, monotone::triangulate_rings(p.points(), &[0]));
            flipped += mesh.flip_towards_delaunay(p, cap);
            mesh.check_invariants(p);
            assert_eq!(mesh.triangle_count(), p.len() - 2);
            let problems = plain_problems(p, mesh.triangles().collect());
            assert!(problems.is_empty(), "cap {cap}: {problems:?}");
        }
    }
    assert!(flipped > 10_000, "flips happen: {flipped}");
}

/// The triangles found by expansion, after asserting that the sweep oracle finds the same.
fn checked_against_the_sweep(p: &Polygon, ring: &[(i64, i64)]) -> Vec<Degenerate> {
    let key = |m: &Degenerate| (m.a, m.b, m.c);
    let fast = minimally_degenerate(p);
    let mut by_expansion: Vec<_> = fast.iter().map(key).collect();
    let mut by_sweep: Vec<_> = super::degenerate::minimally_degenerate_by_sweep(p)
        .iter()
        .map(key)
        .collect();
    by_expansion.sort_unstable();
    by_sweep.sort_unstable();
    assert_eq!(by_expansion, by_sweep, "{ring:?}");
    fast
}

#[test]
fn expansion_finds_the_same_triangles_as_the_sweep() {
    let mut rnd = crate::test_support::xorshift(0x7777_1234_abcd_0001u64);
    let mut with_type_i = 0;
    for _ in 0..3000 {
        let ring = random_ring(&mut rnd, 30);
        let p = polygon(&[&ring]);
        let found = checked_against_the_sweep(&p, &ring);
        with_type_i += usize::from(found.iter().any(|m| m.kind == Kind::TypeI));
    }
    assert!(with_type_i > 300, "type (i) triangles occur: {with_type_i}");
}

/// A "bars" polygon: a strip whose bottom and top follow random step heights (bottom 0..=2, top
/// 3..=5), so that the plateaus at heights 2 and 3 form long 3b-chains in boundary order, crossed
/// by vertical degenerate triangles.
fn bars(columns: usize, seed: u64) -> Polygon {
    let mut rnd = crate::test_support::xorshift(seed | 1);
    let bottom: Vec<i64> = (0..columns).map(|_| rnd(3)).collect();
    let top: Vec<i64> = (0..columns).map(|_| 3 + rnd(3)).collect();
    let mut ring: Vec<(i64, i64)> = Vec::new();
    for (x, &h) in bottom.iter().enumerate() {
        ring.extend([(x as i64, h), (x as i64 + 1, h)]);
    }
    for (x, &h) in top.iter().enumerate().rev() {
        ring.extend([(x as i64 + 1, h), (x as i64, h)]);
    }
    ring.dedup();
    // Flat vertices stay (minitri allows them); only repeated points go.
    polygon(&[&ring])
}

/// The ring of a [`bars`] polygon, wide (along x) or turned a quarter-turn (tall).
fn bars_ring(columns: usize, seed: u64, tall: bool) -> Vec<(i64, i64)> {
    let p = bars(columns, seed);
    (0..p.len())
        .map(|v| {
            let q = p.point(v);
            if tall {
                (100 - q.y, q.x)
            } else {
                (q.x, q.y)
            }
        })
        .collect()
}

#[test]
fn wide_polygons_are_swept_along_their_length_and_found_alike() {
    // A wide polygon's walking mesh comes from the monotone sweep turned a quarter-turn
    // (`plain::polygon`); its tall twin's from the plain sweep. Both meshes must be
    // triangulations, and the expansion over either must find what the sweep oracle finds.
    let mut counts = [0, 0];
    for seed in 1..=150u64 {
        let columns = 6 + (seed as usize % 50);
        let mut found = [0, 0];
        for tall in [false, true] {
            let ring = bars_ring(columns, seed, tall);
            let p = polygon(&[&ring]);
            let problems = plain_problems(&p, crate::algo::plain::polygon(&p, None));
            assert!(problems.is_empty(), "seed {seed} tall {tall}: {problems:?}");
            found[usize::from(tall)] = checked_against_the_sweep(&p, &ring).len();
        }
        assert_eq!(found[0], found[1], "seed {seed}: congruent polygons");
        counts[0] += found[0];
        counts[1] += 1;
    }
    assert!(counts[0] > 3000, "{counts:?}");
}

/// No two triangles of `set` are dependent: their chords do not cross unless they are a 3b pair.
fn assert_independent(p: &Polygon, mdts: &[Degenerate], c: &Circle, set: &[usize], what: &str) {
    for (i, &s) in set.iter().enumerate() {
        for &t in &set[..i] {
            assert!(
                !c.cross(s, t) || is_3b_pair(p, &mdts[s], &mdts[t]),
                "{what}: {s} and {t} are dependent"
            );
        }
    }
}

#[test]
fn staircase_shortcut_matches_listing_every_piece() {
    let (mut stairs_seen, mut long_pieces, mut longest_trimmed, mut levels) = (0, 0, 0, 0);
    for seed in 1..=300u64 {
        let p = bars(4 + (seed as usize % 40), seed);
        let mdts = minimally_degenerate(&p);
        let c = circle(&p, &mdts);
        let ch = chains(&p, &mdts);
        let (fast, effort) = maximum_independent_set_with(&c, &ch, Method::default());
        let (laddered, every) = maximum_independent_set_with(&c, &ch, EVERY_LEVEL);
        let (slow, none) = maximum_independent_set_with(&c, &ch, PLAIN);
        assert_eq!((none.staircases, none.levels), (0, 0));
        assert_eq!(fast.len(), slow.len(), "seed {seed}");
        assert_eq!(
            laddered.len(),
            slow.len(),
            "seed {seed}, a level at every range"
        );
        levels += every.levels;
        for set in [&fast, &laddered] {
            assert_independent(&p, &mdts, &c, set, &format!("seed {seed}"));
        }
        stairs_seen += effort.staircases;
        longest_trimmed = longest_trimmed.max(effort.longest_trimmed);
        // Three consecutive members of a chain chosen together cross one after the other, so
        // they came as one staircase piece from the reconstruction (units stop at two).
        let chosen: std::collections::HashSet<usize> = fast.iter().copied().collect();
        if ch.paths.iter().any(|path| {
            path.windows(3)
                .any(|w| w.iter().all(|t| chosen.contains(t)))
        }) {
            long_pieces += 1;
        }
        if p.len() <= 60 {
            minimum_agrees(&p);
        }
    }
    assert!(
        stairs_seen >= 100,
        "only {stairs_seen} staircases were exercised"
    );
    assert!(
        long_pieces >= 100,
        "only {long_pieces} sets with a staircase piece of three or more chords"
    );
    // The bars' chains run along straight walls: a chain trimmed of an end chord would mean the
    // circle was cut in its end's pocket (its pieces are then O(L) units: bars of 82,000
    // vertices held 3 times the memory).
    assert!(
        longest_trimmed <= 6,
        "a chain of {longest_trimmed} was trimmed"
    );
    assert!(levels >= 10_000, "only {levels} level matrices built");
}

/// A "snake": `rows` corridors of `columns` unit columns (bottoms at random heights 0 or 1,
/// tops 4 or 5, as on [`bars`]), joined at alternate ends by one-column connectors, every
/// lattice point of the boundary a vertex, starting `start` vertices after the lowest-leftmost.
/// The 3b-chains along the corridors' walls end where their line meets a connector's far wall,
/// anywhere on the boundary (irregular end chords), and a ring's start can fall inside a chain.
fn snake_ring(rows: usize, columns: usize, seed: u64, start: usize) -> Vec<(i64, i64)> {
    let mut rnd = crate::test_support::xorshift(seed | 1);
    let mut cells = std::collections::HashSet::new();
    for r in 0..rows as i64 {
        let y0 = 8 * r;
        for x in 0..columns as i64 {
            let (bottom, top) = (rnd(2), 4 + rnd(2));
            cells.extend((bottom..top).map(|y| (x, y0 + y)));
        }
        if r + 1 < rows as i64 {
            let x = if r % 2 == 0 { columns as i64 - 1 } else { 0 };
            cells.extend((y0 + 1..y0 + 10).map(|y| (x, y)));
        }
    }
    // Unit edges of the cells' union, inside on the left: from each boundary point, the next.
    let mut next = std::collections::HashMap::new();
    for &(x, y) in &cells {
        let free = |dx: i64, dy: i64| !cells.contains(&(x + dx, y + dy));
        for (open, from, to) in [
            (free(0, -1), (x, y), (x + 1, y)),
            (free(1, 0), (x + 1, y), (x + 1, y + 1)),
            (free(0, 1), (x + 1, y + 1), (x, y + 1)),
            (free(-1, 0), (x, y + 1), (x, y)),
        ] {
            if open {
                next.insert(from, to);
            }
        }
    }
    let first = *next.keys().min().expect("cells");
    let mut ring = vec![first];
    while let Some(&q) = next.get(ring.last().expect("ring")) {
        if q == first {
            break;
        }
        ring.push(q);
    }
    assert_eq!(ring.len(), next.len(), "one boundary ring");
    let shift = start % ring.len();
    ring.rotate_left(shift);
    ring
}

/// Every 3b-chain along a snake's walls is valued as a staircase (all its pieces listed as
/// units, a chain cost O(L^2) units and made each position of the scans O(L): a snake of 3 x
/// 1000 columns took 11 s, now 0.3 s), whichever vertex the ring starts at; the answers are
/// those of listing every piece, and of the DP on the smaller snakes.
#[test]
fn snakes_keep_their_staircases() {
    let (mut longest_chain, mut dp_checked) = (0, 0);
    for seed in 1..=30u64 {
        let (rows, columns) = (2 + seed as usize % 2, 6 + seed as usize % 19);
        let length = snake_ring(rows, columns, seed, 0).len();
        for start in [0, length / 3, length / 2 + 1] {
            let p = polygon(&[&snake_ring(rows, columns, seed, start)]);
            let mdts = minimally_degenerate(&p);
            let (c, ch) = (circle(&p, &mdts), chains(&p, &mdts));
            let (fast, effort) = maximum_independent_set_with(&c, &ch, Method::default());
            let (laddered, _) = maximum_independent_set_with(&c, &ch, EVERY_LEVEL);
            let (slow, _) = maximum_independent_set_with(&c, &ch, PLAIN);
            assert_eq!(fast.len(), slow.len(), "seed {seed} start {start}");
            assert_eq!(
                laddered.len(),
                slow.len(),
                "seed {seed} start {start}, every level"
            );
            assert!(
                effort.longest_listed <= 8,
                "seed {seed} start {start}: a chain of {} listed piece by piece",
                effort.longest_listed
            );
            longest_chain =
                longest_chain.max(ch.paths.iter().map(<[usize]>::len).max().unwrap_or(0));
            if start == 0 && p.len() <= 130 {
                minimum_agrees(&p);
                dp_checked += 1;
            }
        }
    }
    assert!(longest_chain >= 20, "chains of up to {longest_chain}");
    assert!(dp_checked >= 10, "{dp_checked} snakes checked by the DP");
}

#[test]
fn the_dependency_relation_is_the_circle_crossing_relation_without_holes() {
    let mut pairs = [0usize; 2];
    for seed in 1..=200u64 {
        let p = bars(3 + (seed as usize % 20), seed);
        let mdts = minimally_degenerate(&p);
        let c = circle(&p, &mdts);
        for s in 0..mdts.len() {
            for t in 0..s {
                let on_circle = c.cross(s, t) && !is_3b_pair(&p, &mdts[s], &mdts[t]);
                assert_eq!(dependent(&p, &mdts[s], &mdts[t]), on_circle, "seed {seed}");
                pairs[usize::from(on_circle)] += 1;
            }
        }
    }
    assert!(pairs[0] > 1000 && pairs[1] > 1000, "{pairs:?}");
}

/// Found while building the cutting method: a 3b pair on the line x = 1, both chosen. Merging
/// the first fan leaves a T-junction at the shared end, so the second fan must be found by its
/// half-plane, not by walking shared edges.
#[test]
fn cutting_a_3b_pair_merges_both_fans() {
    let p = polygon(&[&[(1, 3), (0, 0), (1, 4), (1, 5), (2, 0), (1, 2)]]);
    let t = super::triangulate_general(&p, None).unwrap();
    assert_eq!(t.degenerate.len(), 2);
    assert_eq!(t.triangles.len(), 2);
    assert!(crate::verify::check(&p, &t).valid);
    assert_eq!(minimum_agrees(&p), 2);
}

#[test]
fn parallel_search_gives_the_sequential_result_in_the_same_order() {
    // More vertices than one parallel block, with thousands of degenerate triangles of every
    // type, so that several blocks run and are concatenated.
    let p = bars(1500, 7);
    assert!(p.len() > 4096, "{} vertices", p.len());
    let one_thread = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    let two_threads = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let (sequential, mesh_1) = one_thread.install(|| minimally_degenerate_and_mesh(&p));
    let (parallel, mesh_2) = two_threads.install(|| minimally_degenerate_and_mesh(&p));
    assert!(sequential.len() > 2000, "{} triangles", sequential.len());
    assert_eq!(sequential, parallel);
    assert_eq!(mesh_1, mesh_2);
    let key = |m: &Degenerate| (m.a, m.b, m.c);
    let mut by_sweep: Vec<_> = super::degenerate::minimally_degenerate_by_sweep(&p)
        .iter()
        .map(key)
        .collect();
    let mut found: Vec<_> = parallel.iter().map(key).collect();
    by_sweep.sort_unstable();
    found.sort_unstable();
    assert_eq!(found, by_sweep);
}

/// No two chords of `set` cross on `c` (an independent set when there are no 3b-chains).
fn assert_no_crossings(c: &Circle, set: &[usize]) {
    for (i, &s) in set.iter().enumerate() {
        for &t in &set[..i] {
            assert!(!c.cross(s, t), "{s} and {t} cross: {:?}", c.chords);
        }
    }
}

/// The circle of these chords (`(left, right)` each, every position `0..2K` used once).
fn circle_of(chords: Vec<(usize, usize)>) -> Circle {
    let mut owner = vec![0; 2 * chords.len()];
    for (t, &(l, r)) in chords.iter().enumerate() {
        owner[l] = t;
        owner[r] = t;
    }
    Circle { chords, owner }
}

/// On corridors the levels make step 3's scans linear: positions scanned per component
/// position stay flat as the bars and the snake grow, where plain scans grow with the length
/// (`super::ladder`; the bars benchmark of `docs/benchmarks.md`). Same answers, by construction and as
/// checked here.
#[test]
fn levels_make_corridor_scans_linear() {
    let mut rows = Vec::new();
    for columns in [100, 400, 1600] {
        for (name, p) in [
            ("bars", bars(columns, 7)),
            ("snake", polygon(&[&snake_ring(3, columns / 3, 7, 0)])),
        ] {
            let mdts = minimally_degenerate(&p);
            let (c, ch) = (circle(&p, &mdts), chains(&p, &mdts));
            let (laddered, auto) = maximum_independent_set_with(&c, &ch, Method::default());
            let plain_scans = Method {
                staircases: true,
                ladders: LadderPolicy::Off,
                small: 1,
            };
            let (plain, off) = maximum_independent_set_with(&c, &ch, plain_scans);
            assert_eq!(laddered.len(), plain.len(), "{name} {columns}");
            let positions = 2.0 * mdts.len() as f64;
            rows.push((
                name,
                columns,
                auto.scanned as f64 / positions,
                off.scanned as f64 / positions,
                auto.asked as f64 / positions,
            ));
        }
    }
    for name in ["bars", "snake"] {
        let per: Vec<_> = rows.iter().filter(|r| r.0 == name).collect();
        let (small, large) = (per[0], per[per.len() - 1]);
        // Ranges asked for: O(1) per position (the snake's pieces with an irregular end chord
        // are valued from one chord shorter, not from all their gaps).
        assert!(
            large.4 < 1.5 * small.4,
            "{name}: asked {small:?} -> {large:?}"
        );
        // 16 times the length: plain scans grow about as much.
        assert!(
            large.3 > 6.0 * small.3,
            "{name}: plain {small:?} -> {large:?}"
        );
        assert!(large.2 * 8.0 < large.3, "{name}: {large:?}");
    }
    // The bars' laddered scans stay flat. (The snake's still grow, about as the square root
    // of the length: with a vertex at every lattice point, long diagonal chords across the
    // corridor cross each other in bundles, and a cut through a bundle has many slots.)
    let bars: Vec<_> = rows.iter().filter(|r| r.0 == "bars").collect();
    assert!(bars[2].2 < 1.5 * bars[0].2, "{bars:?}");
}

/// Levels on general polygons: random rings on a small grid (flat vertices, collinear runs,
/// 3b-chains), a level at every range asked for against plain scans with every piece listed.
#[test]
fn a_level_at_every_range_changes_no_answer_on_random_polygons() {
    let mut rnd = crate::test_support::xorshift(0x1add_e125);
    let (mut levels, mut searched) = (0, 0);
    for case in 0..1500 {
        let p = polygon(&[&random_ring(&mut rnd, 300)]);
        let effort = agree_with_plain(&p, &[EVERY_LEVEL, Method::default()], &format!("{case}"));
        levels += effort[0].levels;
        searched += effort[1].searched;
    }
    assert!(levels >= 2000, "only {levels} level matrices built");
    // The default method searches the small components (`super::small`): checked against
    // the plain scans, two independent exact algorithms, on components with 3b-chains.
    assert!(searched >= 2000, "only {searched} components searched");
}

/// Each of `methods` gives a largest independent set of `p`'s triangles as large as plain
/// scans with every piece listed, and a truly independent one; returns what each took.
fn agree_with_plain(p: &Polygon, methods: &[Method], what: &str) -> Vec<Effort> {
    let mdts = minimally_degenerate(p);
    let (c, ch) = (circle(p, &mdts), chains(p, &mdts));
    let (plain, _) = maximum_independent_set_with(&c, &ch, PLAIN);
    methods
        .iter()
        .map(|&method| {
            let (set, effort) = maximum_independent_set_with(&c, &ch, method);
            assert_eq!(set.len(), plain.len(), "{what}, {method:?}");
            assert_independent(p, &mdts, &c, &set, what);
            effort
        })
        .collect()
}

/// A longer run of the level checks, once per change to step 3 (`cargo test --release --lib
/// levels_soak -- --ignored`): random rings, bars and snakes of many sizes and seeds, the
/// default method and a level at every range against plain scans.
#[test]
#[ignore]
fn levels_soak() {
    let mut rnd = crate::test_support::xorshift(0x50a4_1e7e);
    let mut cases: Vec<Polygon> = Vec::new();
    for _ in 0..20_000 {
        cases.push(polygon(&[&random_ring(&mut rnd, 400)]));
    }
    for seed in 1..=2_000u64 {
        cases.push(bars(4 + (seed as usize * 7) % 300, seed));
    }
    for seed in 1..=400u64 {
        let (rows, columns) = (2 + seed as usize % 4, 5 + (seed as usize * 13) % 120);
        let length = snake_ring(rows, columns, seed, 0).len();
        let start = (seed as usize * 31) % length;
        cases.push(polygon(&[&snake_ring(rows, columns, seed, start)]));
    }
    let levels: usize = cases
        .iter()
        .enumerate()
        .map(|(case, p)| {
            let methods = [Method::default(), EVERY_LEVEL];
            let effort = agree_with_plain(p, &methods, &format!("case {case}"));
            effort.iter().map(|e| e.levels).sum::<usize>()
        })
        .sum();
    eprintln!("{} polygons, {levels} level matrices", cases.len());
}

/// The search of small components (`super::small`) on larger random circles (40 to 64 chords,
/// each joining positions at most a few apart among those left, so the crossing graphs are
/// sparse, the hardest case for the search): as large as the plain scans, independent, and
/// some components over the search's budget (given back to the scans) among them.
#[test]
fn small_component_search_agrees_with_the_scans_on_random_circles() {
    let mut rnd = crate::test_support::xorshift(0x5eed_5a11);
    let (mut searched, mut over_budget) = (0, 0);
    for trial in 0..2000 {
        let k = 40 + rnd(25) as usize;
        let window = [2, 4, 6, 10][trial % 4];
        let mut free: Vec<usize> = (0..2 * k).collect();
        let mut chords = Vec::new();
        while !free.is_empty() {
            let j = 1 + rnd(window) as usize % (free.len() - 1);
            let (a, b) = (free[0], free.remove(j));
            free.remove(0);
            chords.push((a, b));
        }
        let c = circle_of(chords);
        let ch = super::chains::Chains::lone(k);
        for component in crossing_components(&c).iter() {
            if component.len() > 1
                && super::small::maximum_independent_set(&c, &ch, component).is_none()
            {
                over_budget += 1;
            }
        }
        let (set, effort) = maximum_independent_set_with(&c, &ch, Method::default());
        let (plain, _) = maximum_independent_set_with(&c, &ch, PLAIN);
        assert_eq!(set.len(), plain.len(), "{:?}", c.chords);
        assert_no_crossings(&c, &set);
        searched += effort.searched;
    }
    assert!(searched >= 2000, "only {searched} components searched");
    assert!(
        over_budget >= 3,
        "only {over_budget} components over the budget"
    );
}

/// A square with a `k` x `m` grid of tiny triangular holes (issue 24): thousands of minimally
/// degenerate triangles between aligned hole vertices, one large dependency component.
pub(crate) fn hole_grid(k: i64, m: i64) -> Polygon {
    let (w, h) = (10 * k + 10, 10 * m + 10);
    let mut rings: Vec<Vec<(i64, i64)>> = vec![vec![(0, 0), (w, 0), (w, h), (0, h)]];
    for i in 0..k {
        for j in 0..m {
            let (x, y) = (10 + 10 * i, 10 + 10 * j);
            rings.push(vec![(x, y), (x, y + 1), (x + 1, y)]);
        }
    }
    let refs: Vec<&[(i64, i64)]> = rings.iter().map(Vec::as_slice).collect();
    polygon(&refs)
}

/// Issue 24, item 1: a 15 x 15 grid of holes reported `lower_bound` 18446744073709550335 (the
/// upper bound on the independent set above n + 2w - 2, subtracted without a check; a debug
/// build panicked). The bound is now capped by the middles and checked by the verifier.
#[test]
fn a_search_cut_short_on_a_grid_of_holes_reports_a_true_lower_bound() {
    let p = hole_grid(15, 15);
    let (corners, plain) = p.minimum_bounds();
    let t = super::triangulate_general(&p, Some(std::time::Instant::now())).unwrap();
    let check = crate::verify::check(&p, &t);
    assert!(check.valid, "{:?}", check.problems);
    assert!(!t.optimal);
    let lower = t.lower_bound.expect("a search cut short has a lower bound");
    assert!(corners <= lower && lower <= t.triangles.len() && t.triangles.len() <= plain);
    // Each of the 675 hole vertices is reflex, the 4 corners convex: at most 675 middles.
    assert!(lower >= plain - 675, "{lower}");
}

/// The verifier rejects an impossible lower bound (the number of issue 24) and one beside an
/// optimal count.
#[test]
fn the_verifier_checks_the_lower_bound() {
    let p = hole_grid(2, 2);
    let mut t = super::triangulate_general(&p, None).unwrap();
    assert!(t.optimal && t.lower_bound.is_none());
    assert!(crate::verify::check(&p, &t).valid);
    t.lower_bound = Some(t.triangles.len());
    let problems = crate::verify::check(&p, &t).problems;
    assert!(problems[0].contains("claimed optimal"), "{problems:?}");
    t.optimal = false;
    t.lower_bound = Some(18_446_744_073_709_550_335);
    let problems = crate::verify::check(&p, &t).problems;
    assert!(problems[0].starts_with("the lower bound 18446744073709550335 is outside"));
    t.lower_bound = Some(t.triangles.len());
    assert!(crate::verify::check(&p, &t).valid);
}

/// Issue 24, item 3: the deadline bounds step 1 and the dependency graph too, not only the
/// search. With the deadline already past, a 30 x 30 grid of holes (its triangles Θ(n^2), its
/// graph Θ(n^4) pairs) still gives a valid triangulation, stopped by the time limit, with a
/// true lower bound.
#[test]
fn a_past_deadline_bounds_every_stage_on_a_grid_of_holes() {
    let p = hole_grid(30, 30);
    let (corners, plain) = p.minimum_bounds();
    let t = super::triangulate_general(&p, Some(std::time::Instant::now())).unwrap();
    let check = crate::verify::check(&p, &t);
    assert!(check.valid, "{:?}", check.problems);
    assert_eq!(t.stopped, Some(crate::algo::Stopped::TimeLimit));
    let lower = t.lower_bound.expect("not optimal: a lower bound");
    assert!(corners <= lower && lower <= t.triangles.len() && t.triangles.len() <= plain);
}

/// The dependency graph gives up past its pair budget (and the search then goes on with the
/// shorter triangles, "graph size"); with room it is the graph of [`dependency::graph`].
#[test]
fn the_dependency_graph_keeps_to_its_budget() {
    use super::{degenerate, dependency};
    let p = hole_grid(6, 6);
    let mdts = degenerate::minimally_degenerate(&p);
    let full = dependency::graph(&p, &mdts);
    let pairs: usize = full.iter().map(Vec::len).sum::<usize>() / 2;
    assert!(pairs > 1000, "{pairs} dependent pairs");
    assert_eq!(
        dependency::graph_within(&p, &mdts, u64::MAX, None),
        Some(full)
    );
    assert_eq!(dependency::graph_within(&p, &mdts, 100, None), None);
    let past = Some(std::time::Instant::now());
    assert_eq!(dependency::graph_within(&p, &mdts, u64::MAX, past), None);
}

/// `circle::sort_ends` (a counting sort by vertex, then the ends at each vertex by angle) gives
/// the order of the reference: one stable sort of the ends, listed by triangle, by vertex then
/// angle. On 3000 random grid polygons (many degenerate triangles sharing ends) and random stars,
/// and on a list with one vertex holding more ends than an insertion run (the standard sort's
/// branch).
#[test]
fn chord_ends_sort_like_the_reference_stable_sort() {
    use crate::geom::kernel::cmp_angle_from;
    fn reference<P: Coord>(polygon: &Polygon<P>, ends: &mut [(usize, usize, usize)]) {
        ends.sort_by(|&(v, _, x), &(w, _, y)| {
            v.cmp(&w).then_with(|| {
                let (c, r) = (polygon.point(v), polygon.point(polygon.next(v)));
                cmp_angle_from(c, r, polygon.point(x), polygon.point(y)).reverse()
            })
        });
    }
    let check = |p: &Polygon, mut ends: Vec<(usize, usize, usize)>| {
        let mut expected = ends.clone();
        reference(p, &mut expected);
        super::circle::sort_ends(p, &mut ends);
        assert_eq!(ends, expected);
    };
    let mut rnd = crate::test_support::xorshift(0x50e7_e4d5);
    let mut longest = 0;
    for k in 0..3000 {
        let Some(p) = star_or_grid(&mut rnd, k) else {
            continue;
        };
        let mdts = minimally_degenerate(&p);
        let ends: Vec<(usize, usize, usize)> = mdts
            .iter()
            .enumerate()
            .flat_map(|(t, m)| [(m.a, t, m.b), (m.c, t, m.b)])
            .collect();
        check(&p, ends);
        // Every pair of distinct vertices as an end and a direction: long runs at each vertex,
        // equal angles included (collinear vertices).
        let n = p.len();
        let all: Vec<(usize, usize, usize)> = (0..n)
            .flat_map(|v| (0..n).filter(move |&x| x != v).map(move |x| (v, 0, x)))
            .enumerate()
            .map(|(t, (v, _, x))| (v, t, x))
            .collect();
        longest = longest.max(n - 1);
        check(&p, all);
    }
    assert!(longest > 16, "a run longer than the insertion sort's");
}

/// Step 1 of a polygon without holes keeps to the deadline too (issue 22: on a comb it is
/// quadratic). With the deadline already past, the triangulation is valid, not claimed minimum,
/// stopped by the time limit, with a true lower bound; without one, the same comb is exact.
#[test]
fn a_past_deadline_bounds_step_1_without_holes() {
    let p = polygon(&[&crate::test_support::comb(300, 1, 3)]);
    let (corners, plain) = p.minimum_bounds();
    let t = super::triangulate_within(&p, Some(std::time::Instant::now())).unwrap();
    let check = crate::verify::check(&p, &t);
    assert!(check.valid, "{:?}", check.problems);
    assert!(!t.optimal);
    assert_eq!(t.stopped, Some(crate::algo::Stopped::TimeLimit));
    let lower = t.lower_bound.expect("not optimal: a lower bound");
    assert!(corners <= lower && lower <= t.triangles.len() && t.triangles.len() <= plain);
    let exact = super::triangulate_within(&p, None).unwrap();
    assert!(exact.optimal && exact.lower_bound.is_none() && exact.stopped.is_none());
    assert!(lower <= exact.triangles.len() && exact.triangles.len() <= t.triangles.len());
    assert!(crate::verify::check(&p, &exact).valid);
}

/// A large polygon is triangulated for step 1 on a second thread while the pipeline validates it
/// (`pipeline::PlainBeside`): the triangulation returned beside the polygon is the one made
/// afterwards (here through the quarter-turned sweep of a wide polygon and the usual one of a
/// tall polygon, with and without a hole), step 1 walks it, and an invalid polygon is refused
/// as before.
#[test]
fn the_mesh_made_while_validating_is_the_mesh() {
    use crate::test_support::{comb, raw};
    let beside = |rings: &[&[(i64, i64)]]| {
        let (polygon, _warnings, premade) =
            Polygon::from_raw_validated(&raw(rings), &crate::pipeline::PlainBeside)
                .expect("a valid test polygon");
        (polygon, premade)
    };
    let wide = comb(3000, 1, 3); // 12,002 vertices, 6,000 wide and 4 tall
                                 // The overlap needs two threads, whatever the machine running the tests has.
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(2)
        .build()
        .unwrap();
    let turn =
        |ring: &[(i64, i64)]| -> Vec<(i64, i64)> { ring.iter().map(|&(x, y)| (-y, x)).collect() };
    // A square hole in the base strip of a comb 4 wide and 8 tall, and the same turned.
    let (holed, hole) = (comb(3000, 4, 8), vec![(1, 2), (1, 4), (3, 4), (3, 2)]);
    let cases = [
        vec![wide.clone()],
        vec![turn(&wide)],
        vec![holed.clone(), hole.clone()],
        vec![turn(&holed), turn(&hole)],
    ];
    for rings in &cases {
        let rings: Vec<&[(i64, i64)]> = rings.iter().map(Vec::as_slice).collect();
        let (p, made) = pool.install(|| beside(&rings));
        let made = made.expect("made while validating");
        assert_eq!(crate::algo::plain::polygon(&p, None), made);
        let t = super::triangulate_premade(&p, Some(made), None).unwrap();
        assert!(crate::verify::check(&p, &t).valid);
        assert_eq!(t.triangles, super::triangulate_within(&p, None).unwrap().triangles);
        let plain = p.len() + 2 * p.holes() - 2;
        assert_eq!(t.triangles.len(), plain - t.degenerate.len());
    }
    // On one thread nothing would overlap: no triangulation is made ahead.
    let one = rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()
        .unwrap();
    assert!(one.install(|| beside(&[&wide])).1.is_none());
    // A tooth's top moved below the base: its edges cross the base.
    let mut bad = wide.clone();
    bad[4] = (bad[4].0, -1);
    assert!(pool
        .install(|| Polygon::from_raw_validated(&raw(&[&bad]), &crate::pipeline::PlainBeside))
        .is_err());
}

/// The bound on `d` after step 1 was cut short (`triangulate_within`): the maximum independent
/// set among the triangles of the middles looked from, plus one per vertex that could be a
/// middle and was not looked from, is never below `d` over all triangles. On 1,500 random grid
/// polygons and stars, each with a random half of its vertices looked from.
#[test]
fn the_bound_after_a_cut_short_step_1_holds_for_any_vertices_looked_from() {
    let mut rnd = crate::test_support::xorshift(0xb0_0d);
    let mut tight = 0;
    for k in 0..1500 {
        let Some(p) = star_or_grid(&mut rnd, k) else {
            continue;
        };
        let mdts = minimally_degenerate(&p);
        let d = super::circle_mis(&p, &mdts).len();
        let looked: Vec<bool> = (0..p.len()).map(|_| rnd(2) == 0).collect();
        let found: Vec<_> = mdts.iter().copied().filter(|m| looked[m.b]).collect();
        let unexamined = (0..p.len())
            .filter(|&v| !looked[v] && crate::algo::minitri::degenerate::can_be_middle(&p, v))
            .count();
        let bound = super::circle_mis(&p, &found).len() + unexamined;
        assert!(d <= bound, "{d} > {bound} for {:?}", p.points());
        tight += usize::from(d == bound);
    }
    assert!(tight > 100, "{tight}");
}

/// A corridor one unit wide climbing a random staircase (steps of 1 to 3 units right and up,
/// the upper wall the lower one moved by (-1, 1)), every lattice point of its walls a vertex,
/// as `bench/polygon.py stairs-lattice`.
fn lattice_stairs_ring(steps: usize, seed: u64) -> Vec<(i64, i64)> {
    let mut rnd = crate::test_support::xorshift(seed | 1);
    let mut lower = vec![(0i64, 0i64)];
    for _ in 0..steps {
        let (x, y) = lower[lower.len() - 1];
        let run = 1 + rnd(3);
        lower.extend((1..=run).map(|i| (x + i, y)));
        let rise = 1 + rnd(3);
        lower.extend((1..=rise).map(|i| (x + run, y + i)));
    }
    let upper: Vec<(i64, i64)> = lower.iter().rev().map(|&(x, y)| (x - 1, y + 1)).collect();
    // The ends joined by unit edges: the last lower point to the first upper one is one
    // diagonal step; make it two lattice edges through the corner (x, y + 1).
    let (x, y) = lower[lower.len() - 1];
    let mut ring = lower;
    ring.push((x, y + 1));
    ring.extend(upper.into_iter().skip(1));
    ring.push((-1, 0));
    ring
}

/// Step 1 finds the same set of triangles, kinds included, with every ray walked, every ray
/// shot over heavy paths (`ray_shooting`), the default hybrid, and by the angular sweep.
fn assert_policies_agree<P: Coord>(p: &Polygon<P>, what: &str) -> usize {
    super::degenerate::check_ray_policies(p).unwrap_or_else(|e| panic!("{what}: {e}"))
}

#[test]
fn step_one_is_the_same_whatever_the_ray_policy() {
    let mut found = 0;
    for teeth in [1, 2, 3, 5, 17, 60] {
        for (w, h) in [(1, 9), (2, 1), (3, 7)] {
            let ring = crate::test_support::comb(teeth, w, h);
            found += assert_policies_agree(&polygon(&[&ring]), &format!("comb {teeth} {w} {h}"));
        }
    }
    for steps in [2, 3, 4, 9, 40, 150] {
        for (w, h) in [(1, 1), (2, 1), (1, 3)] {
            let ring = crate::test_support::sliver(steps, w, h);
            found += assert_policies_agree(&polygon(&[&ring]), &format!("sliver {steps} {w} {h}"));
        }
    }
    for (m, bottom) in [(3, 1), (12, 4), (40, 40), (150, 10)] {
        let ring = crate::test_support::parabola(m, bottom);
        found += assert_policies_agree(&polygon(&[&ring]), &format!("parabola {m} {bottom}"));
    }
    for seed in 1..=12u64 {
        let ring = lattice_stairs_ring(3 + 4 * seed as usize, seed);
        found += assert_policies_agree(&polygon(&[&ring]), &format!("stairs {seed}"));
        let ring = snake_ring(1 + seed as usize % 3, 4 + 3 * seed as usize, seed, 0);
        found += assert_policies_agree(&polygon(&[&ring]), &format!("snake {seed}"));
        found += assert_policies_agree(&bars(5 + 7 * seed as usize, seed), &format!("bars {seed}"));
    }
    let mut rnd = crate::test_support::xorshift(0x35_5eed_0000_0001u64);
    for k in 0..600 {
        if let Some(p) = star_or_grid(&mut rnd, k) {
            found += assert_policies_agree(&p, &format!("random {k}"));
        }
    }
    assert!(found > 5000, "{found} triangles");
    // The same on the wide kernel (its own orientation tests).
    let rings = [
        crate::test_support::comb(30, 1, 9),
        crate::test_support::sliver(80, 1, 1),
        crate::test_support::sliver(50, 3, 2),
        lattice_stairs_ring(25, 3),
        snake_ring(2, 12, 5, 0),
    ];
    for (k, ring) in rings.iter().enumerate() {
        let raw = crate::test_support::raw(&[ring]);
        let Ok((wide, _)) = Polygon::from_raw_wide(&raw) else {
            panic!("ring {k} is valid");
        };
        assert!(assert_policies_agree(&wide, &format!("wide {k}")) > 0);
    }
}

/// Long, almost straight lines (a state boundary): a box whose bottom (and, two times out of
/// three, top) is a chain of vertices a few units off a line, sheared to other slopes. The walk
/// from a vertex of one chain crosses the box while the other cone's part opposite ends against
/// the chain, so the cones take turns (`expansion::double_cone`); the triangles found must not
/// change: the same as the sweep's, whatever the ray policy and the budget. (A soak of 1,400
/// such polygons, 170,000 triangles and 44,000 turns, agreed too when this was written.)
#[test]
fn step_one_on_state_lines_takes_turns_and_finds_the_same() {
    let mut found = 0;
    let turns_before = super::expansion::TURNS.with(|t| t.get());
    for seed in 1..=60u64 {
        let mut rnd = crate::test_support::xorshift(0x7161_0000 + seed);
        let (k, amplitude, step, height) = (20 + rnd(200), 1 + rnd(6), 3 + rnd(20), 20 + rnd(500));
        let mut ring: Vec<(i64, i64)> = (0..=k).map(|i| (step * i, rnd(amplitude))).collect();
        if seed % 3 == 0 {
            ring.extend([(step * k, height), (0, height)]);
        } else {
            ring.extend((0..=k).rev().map(|i| (step * i, height + rnd(amplitude))));
        }
        // A shear of determinant a > 0 keeps the orientation.
        let (a, c) = (1 + rnd(4), rnd(3));
        let ring: Vec<(i64, i64)> = ring.iter().map(|&(x, y)| (a * x + c * y, y)).collect();
        found += assert_policies_agree(&polygon(&[&ring]), &format!("state lines {seed}"));
    }
    let turns = super::expansion::TURNS.with(|t| t.get()) - turns_before;
    // 6,825 triangles and 1,954 turns (over the five ways of check_ray_policies) when written.
    assert!(found > 6000, "{found} triangles");
    assert!(turns > 1500, "{turns} turns taken");
}

/// On the earcut fixtures of up to 3000 vertices (holes and touching rings among them: the
/// walks' mesh, with a copy of each touch point; both kernels), step 1 finds the same triangles,
/// kinds included, whatever the ray policy, and the sweep agrees.
#[test]
fn step_one_on_the_earcut_fixtures_is_the_same_whatever_the_ray_policy() {
    use crate::geom::polygon::AnyPolygon;
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/earcut");
    let (mut fast, mut wide) = (0, 0);
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.extension().is_none_or(|e| e != "json") || path.ends_with("expected.json") {
            continue;
        }
        let text = std::fs::read_to_string(&path).unwrap();
        let Ok(raws) = crate::io::read::geojson::read(&text) else {
            continue;
        };
        for raw in raws {
            match AnyPolygon::from_raw(&raw) {
                Ok((AnyPolygon::Fast(p), _)) if p.len() <= 3000 => {
                    fast += 1;
                    over_the_walks_mesh_policies_agree(&p, &path.display().to_string());
                }
                Ok((AnyPolygon::Wide(p), _)) if p.len() <= 3000 => {
                    wide += 1;
                    over_the_walks_mesh_policies_agree(&p, &path.display().to_string());
                }
                _ => {}
            }
        }
    }
    // (All of them fit the fast kernel today; a wide one would be checked the same way.)
    assert!(fast > 25, "{fast} fast, {wide} wide");
}

/// [`assert_policies_agree`] over the mesh the pipeline walks (the walks' one for touching
/// rings).
fn over_the_walks_mesh_policies_agree<P: Coord>(p: &Polygon<P>, what: &str) {
    use super::degenerate::{
        minimally_degenerate_by_sweep, minimally_degenerate_over_budget, Budget,
    };
    use super::ray_shooting::RayPolicy;
    let key = |m: &Degenerate| (m.a, m.b, m.c);
    let mut swept = minimally_degenerate_by_sweep(p);
    swept.sort_by_key(key);
    let choices = [
        (RayPolicy::WalkOnly, Budget::WalkOnly),
        (RayPolicy::ShootOnly, Budget::WalkOnly),
        (RayPolicy::Hybrid, Budget::Hybrid),
        (RayPolicy::Hybrid, Budget::CutsOnly),
    ];
    for (policy, budget) in choices {
        let plain = if p.touches() > 0 {
            crate::algo::plain::walks(p).unwrap()
        } else {
            crate::algo::plain::polygon(p, None)
        };
        let (mut found, _, unexamined) =
            minimally_degenerate_over_budget(p, plain, None, policy, budget);
        assert_eq!(unexamined, 0);
        found.sort_by_key(key);
        assert_eq!(found, swept, "{what} {policy:?} {budget:?}");
    }
}
