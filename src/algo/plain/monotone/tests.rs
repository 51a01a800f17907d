use super::*;
use crate::geom::kernel::Point;
use crate::geom::polygon::Polygon;
use crate::test_support::{polygon, raw, FLAT_SQUARE, U_SHAPE};
use std::collections::HashSet;

/// Checks a triangulation of the cycle `pts` completely and exactly: n - 2 triangles, each
/// counter-clockwise with `cross > 0`, twice-areas summing to the polygon's twice-area; every
/// directed side is a boundary edge `i -> i+1` or is matched by its reverse in another triangle,
/// every boundary edge is used once and never backwards (so the triangles' boundaries add up to
/// the polygon's, and with all triangles positive, winding numbers show that they cover the
/// polygon once); and for small inputs, pairwise disjoint interiors by a separating-axis test.
fn check_cycle(pts: &[Point]) -> Vec<[usize; 3]> {
    let n = pts.len();
    let t = triangulate_rings(pts, &[0]);
    assert_eq!(t.len(), n - 2, "wrong count for {pts:?}");
    let mut area = 0i128;
    for &[a, b, c] in &t {
        assert!(a < n && b < n && c < n);
        let s = cross(pts[a], pts[b], pts[c]);
        assert!(s > 0, "triangle {a} {b} {c} not positive in {pts:?}");
        area += s;
    }
    let twice: i128 = (0..n)
        .map(|i| cross(Point::default(), pts[i], pts[(i + 1) % n]))
        .sum();
    assert_eq!(area, twice, "areas differ for {pts:?}");
    let mut sides = HashSet::with_capacity(3 * t.len());
    for &[a, b, c] in &t {
        for side in [(a, b), (b, c), (c, a)] {
            assert!(sides.insert(side), "side {side:?} used twice in {pts:?}");
        }
    }
    for &(a, b) in &sides {
        assert!(
            b == (a + 1) % n || sides.contains(&(b, a)),
            "side {a} {b} unmatched in {pts:?}"
        );
    }
    for i in 0..n {
        let j = (i + 1) % n;
        assert!(sides.contains(&(i, j)), "edge {i} {j} missing in {pts:?}");
        assert!(!sides.contains(&(j, i)), "edge {i} {j} reversed in {pts:?}");
    }
    if n <= 200 {
        for (k, s) in t.iter().enumerate() {
            for r in &t[k + 1..] {
                assert!(separated(pts, s, r), "{s:?} and {r:?} overlap in {pts:?}");
            }
        }
    }
    t
}

/// Whether two counter-clockwise triangles have disjoint interiors: some side's line has the
/// other triangle on its closed outer side.
fn separated(pts: &[Point], s: &[usize; 3], r: &[usize; 3]) -> bool {
    let splits = |s: &[usize; 3], r: &[usize; 3]| {
        (0..3).any(|k| {
            let (a, b) = (pts[s[k]], pts[s[(k + 1) % 3]]);
            r.iter().all(|&q| cross(a, b, pts[q]) <= 0)
        })
    };
    splits(s, r) || splits(r, s)
}

/// Builds the polygon through the real constructor (so it is valid) and checks its cycle.
fn check(ring: &[(i64, i64)]) {
    let p = polygon(&[ring]);
    assert_eq!(p.holes(), 0);
    let t = check_cycle(p.points());
    let sum: i128 = t
        .iter()
        .map(|&[a, b, c]| cross(p.point(a), p.point(b), p.point(c)))
        .sum();
    assert_eq!(Some(sum), p.twice_area().value());
}

fn pt(x: i64, y: i64) -> Point {
    Point::new(x, y)
}

#[test]
fn classification_in_the_lexicographic_order() {
    // A rectangle: the horizontal edges rise to the east.
    let (a, b, c, d) = (pt(0, 0), pt(4, 0), pt(4, 2), pt(0, 2));
    assert_eq!(Kind::of(d, a, b), Kind::Start);
    assert_eq!(Kind::of(a, b, c), Kind::Upward);
    assert_eq!(Kind::of(b, c, d), Kind::End);
    assert_eq!(Kind::of(c, d, a), Kind::Downward);
    // Flat vertices are regular, also on horizontal edges.
    assert_eq!(Kind::of(pt(0, 0), pt(1, 0), pt(2, 0)), Kind::Upward);
    assert_eq!(Kind::of(pt(2, 3), pt(1, 3), pt(0, 3)), Kind::Downward);
    // A notch from above with a horizontal bottom, boundary (2, 3) (2, 1) (1, 1) (1, 3): regular
    // at its east corner, split at its west corner.
    assert_eq!(Kind::of(pt(2, 3), pt(2, 1), pt(1, 1)), Kind::Downward);
    assert_eq!(Kind::of(pt(2, 1), pt(1, 1), pt(1, 3)), Kind::Split);
    assert_eq!(Kind::of(pt(1, 3), pt(1, 1), pt(2, 1)), Kind::Start);
    // A notch from below with a horizontal top, boundary (1, 0) (1, 2) (2, 2) (2, 0): regular at
    // its west corner, merge at its east corner.
    assert_eq!(Kind::of(pt(1, 0), pt(1, 2), pt(2, 2)), Kind::Upward);
    assert_eq!(Kind::of(pt(1, 2), pt(2, 2), pt(2, 0)), Kind::Merge);
    assert_eq!(Kind::of(pt(2, 0), pt(2, 2), pt(1, 2)), Kind::End);
}

#[test]
fn status_order_is_exact() {
    // Two disjoint edges cut by one sweep line, and probes between and beside them.
    let west = Cut::new(pt(0, 0), pt(1, 10), 0);
    let east = Cut::new(pt(5, 3), pt(2, 9), 1);
    assert_eq!(west.cmp(&east), Ordering::Less);
    assert_eq!(east.cmp(&west), Ordering::Greater);
    assert_eq!(Cut::probe(pt(1, 5)).cmp(&west), Ordering::Greater);
    assert_eq!(Cut::probe(pt(1, 5)).cmp(&east), Ordering::Less);
    assert_eq!(west.cmp(&Cut::probe(pt(0, 5))), Ordering::Greater);
    // A horizontal edge in the (y, x) order: the probe (3, 4) is above (2, 4) and below (6, 4).
    let flat = Cut::new(pt(6, 4), pt(2, 4), 2);
    let steep = Cut::new(pt(7, 0), pt(7, 9), 3);
    assert_eq!(Cut::probe(pt(3, 4)).cmp(&steep), Ordering::Less);
    assert_eq!(flat.cmp(&steep), Ordering::Less);
}

#[test]
fn triangles_and_convex_polygons() {
    check(&[(0, 0), (1, 0), (0, 1)]);
    check(&[(0, 0), (5, 0), (5, 5), (0, 5)]);
    check(&[(0, 0), (3, 1), (0, 2)]);
    // The convex polygon whose edges are all primitive vectors with coordinates in -3..=3.
    let mut dirs: Vec<(i64, i64)> = Vec::new();
    for dx in -3i64..=3 {
        for dy in -3i64..=3 {
            if (dx, dy) != (0, 0) && gcd(dx.abs(), dy.abs()) == 1 {
                dirs.push((dx, dy));
            }
        }
    }
    dirs.sort_by(|&a, &b| around(pt(0, 0), pt(1, 0), pt(a.0, a.1), pt(b.0, b.1)));
    let walk = |steps: &[(i64, i64)]| {
        let mut at = (100, 100);
        let mut ring = Vec::new();
        for &(dx, dy) in steps {
            ring.push(at);
            at = (at.0 + dx, at.1 + dy);
        }
        assert_eq!(at, (100, 100));
        ring
    };
    check(&walk(&dirs));
    // The same with every edge doubled: a flat vertex in the middle of each.
    let doubled: Vec<(i64, i64)> = dirs.iter().flat_map(|&d| [d, d]).collect();
    check(&walk(&doubled));
    // Every cyclic rotation of the start vertex.
    let ring = walk(&dirs);
    for k in 0..ring.len() {
        let mut r = ring.clone();
        r.rotate_left(k);
        check(&r);
    }
}

#[test]
fn square_with_flat_vertices_on_every_side() {
    check(&[
        (0, 0),
        (1, 0),
        (2, 0),
        (3, 0),
        (3, 1),
        (3, 2),
        (3, 3),
        (2, 3),
        (1, 3),
        (0, 3),
        (0, 2),
        (0, 1),
    ]);
    check(&FLAT_SQUARE);
    // A diamond with flat vertices on every side.
    check(&[
        (2, 0),
        (3, 1),
        (4, 2),
        (3, 3),
        (2, 4),
        (1, 3),
        (0, 2),
        (1, 1),
    ]);
}

#[test]
fn u_shape() {
    check(&U_SHAPE);
    // And upside down, and turned by a quarter (so the notch opens sideways).
    let down: Vec<(i64, i64)> = U_SHAPE.iter().map(|&(x, y)| (-x, -y)).collect();
    check(&down);
    let side: Vec<(i64, i64)> = U_SHAPE.iter().map(|&(x, y)| (-y, x)).collect();
    check(&side);
}

/// `ring` turned by k quarter turns about the origin.
fn turned(ring: &[(i64, i64)], k: usize) -> Vec<(i64, i64)> {
    ring.iter()
        .map(|&(x, y)| match k % 4 {
            0 => (x, y),
            1 => (-y, x),
            2 => (-x, -y),
            _ => (y, -x),
        })
        .collect()
}

#[test]
fn combs() {
    // Ten teeth of width 2 over gaps of width 2, all gap bottoms on one line, in all four
    // directions (teeth up, left, down, right).
    let comb = crate::test_support::comb(10, 2, 4);
    for q in 0..4 {
        check(&turned(&comb, q));
    }
    // Teeth up and down from a common spine.
    let mut double = Vec::new();
    for k in 0..10 {
        double.extend([(4 * k, -1), (4 * k, -5), (4 * k + 2, -5), (4 * k + 2, -1)]);
    }
    double.push((40, -1));
    for k in (0..10).rev() {
        double.extend([
            (4 * k + 4, 1),
            (4 * k + 4, 5),
            (4 * k + 2, 5),
            (4 * k + 2, 1),
        ]);
    }
    double.push((0, 1));
    for q in 0..4 {
        check(&turned(&double, q));
    }
    // Slanted teeth with pointed tips, tips at one height.
    let mut saw = vec![(0, 0), (30, 0)];
    for k in (0..10).rev() {
        saw.extend([(3 * k + 3, 2), (3 * k + 2, 6), (3 * k + 1, 2)]);
    }
    for q in 0..4 {
        check(&turned(&saw, q));
    }
}

/// The boundary of a polyomino (cells `(x, y)` of unit squares), counter-clockwise from its
/// lowest-leftmost corner, with every unit step kept (flat vertices) or merged (`merge`); `None`
/// if the outer boundary pinches (two cells touching at a corner only).
fn polyomino(cells: &HashSet<(i64, i64)>, merge: bool) -> Option<Vec<(i64, i64)>> {
    use std::collections::HashMap;
    let mut out: HashMap<(i64, i64), Vec<(i64, i64)>> = HashMap::new();
    for &(x, y) in cells {
        let sides = [
            ((x, y - 1), (x, y), (x + 1, y)),
            ((x + 1, y), (x + 1, y), (x + 1, y + 1)),
            ((x, y + 1), (x + 1, y + 1), (x, y + 1)),
            ((x - 1, y), (x, y + 1), (x, y)),
        ];
        for (neighbour, a, b) in sides {
            if !cells.contains(&neighbour) {
                out.entry(a).or_default().push(b);
            }
        }
    }
    if out.values().any(|v| v.len() > 1) {
        return None;
    }
    let first = *out.keys().min_by_key(|&&(x, y)| (y, x))?;
    let mut ring = vec![first];
    let mut at = out[&first][0];
    while at != first {
        ring.push(at);
        at = out[&at][0];
    }
    if merge {
        let n = ring.len();
        let keep: Vec<(i64, i64)> = (0..n)
            .filter(|&i| {
                let (p, v, q) = (ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]);
                (v.0 - p.0) * (q.1 - v.1) - (v.1 - p.1) * (q.0 - v.0) != 0
            })
            .map(|i| ring[i])
            .collect();
        ring = keep;
    }
    Some(ring)
}

#[test]
fn spirals() {
    // A square spiral corridor of width 1 between walls of width 1 (a polyomino).
    for arms in [4, 9, 20] {
        let (mut x, mut y) = (0i64, 0i64);
        let mut cells = HashSet::from([(0, 0)]);
        let dirs = [(1, 0), (0, 1), (-1, 0), (0, -1)];
        for arm in 0..arms {
            let (dx, dy) = dirs[arm % 4];
            for _ in 0..2 * (arm / 2 + 1) {
                x += dx;
                y += dy;
                cells.insert((x, y));
            }
        }
        for merge in [false, true] {
            let ring = polyomino(&cells, merge).expect("a spiral does not pinch");
            check(&ring);
        }
    }
    // A smooth spiral: out along one arm, back along a parallel one.
    for turns in [1.5f64, 3.0, 6.0] {
        let steps = (turns * 40.0) as usize;
        let point = |k: usize, r0: f64| {
            let a = k as f64 / 40.0 * std::f64::consts::TAU;
            let r = 1000.0 * (r0 + a);
            ((r * a.cos()).round() as i64, (r * a.sin()).round() as i64)
        };
        let mut ring: Vec<(i64, i64)> = (0..=steps).map(|k| point(k, 3.0)).collect();
        ring.extend((0..=steps).rev().map(|k| point(k, 5.0)));
        check(&ring);
    }
}

#[test]
fn horizontal_edges_and_equal_heights() {
    // A staircase, up to the west.
    for steps in [1i64, 2, 5, 20] {
        let mut stairs = vec![(0, 0), (steps, 0)];
        for k in 0..steps {
            stairs.extend([(steps - k, k + 1), (steps - k - 1, k + 1)]);
        }
        for q in 0..4 {
            check(&turned(&stairs, q));
        }
    }
    // A ziggurat: stairs up on both sides.
    let mut zig = vec![(0, 0), (20, 0)];
    for k in 0..5 {
        zig.extend([(20 - 2 * k, 2 * k + 2), (18 - 2 * k, 2 * k + 2)]);
    }
    for k in (0..5).rev() {
        zig.extend([(2 + 2 * k, 2 * k + 2), (2 * k, 2 * k + 2)]);
    }
    zig.dedup();
    for q in 0..4 {
        check(&turned(&zig, q));
    }
    // A zigzag top with all tops at one height, all valleys at another.
    for teeth in [1i64, 3, 12] {
        let mut zz = vec![(0, 0), (2 * teeth, 0)];
        for k in (0..teeth).rev() {
            zz.extend([(2 * k + 2, 5), (2 * k + 1, 3)]);
        }
        zz.push((0, 5));
        for q in 0..4 {
            check(&turned(&zz, q));
        }
        // Zigzag on top and bottom: merge and split vertices at equal heights.
        let mut both = Vec::new();
        for k in 0..teeth {
            both.extend([(2 * k, -5), (2 * k + 1, -3)]);
        }
        both.push((2 * teeth, -5));
        both.extend(zz[1..].iter().copied());
        check(&both);
    }
}

#[test]
fn long_collinear_run_on_one_chain() {
    // Eleven vertices on x = 0 on the west chain, an east chain that zigzags beside it.
    let mut ring = vec![(0, 0), (6, 2), (3, 4), (6, 6), (2, 8), (5, 11)];
    ring.extend((0..=10).rev().map(|y| (0, y)));
    ring.pop(); // (0, 0) is already first
    check(&ring);
    for q in 0..4 {
        check(&turned(&ring, q));
    }
    // A slanted run of ten collinear vertices with a reflex east chain facing it.
    let mut slant: Vec<(i64, i64)> = (0..10).map(|k| (3 * k, 2 * k)).collect();
    slant.extend([(27, 30), (20, 22), (18, 15), (14, 12)]);
    slant.reverse();
    for q in 0..4 {
        check(&turned(&slant, q));
    }
    // Runs on both chains, vertices interleaved in height.
    let mut two: Vec<(i64, i64)> = (0..10).map(|k| (10, 2 * k)).collect();
    two.extend((0..10).rev().map(|k| (0, 2 * k + 1)));
    check(&two);
}

/// A small deterministic generator (SplitMix64).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }

    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + self.below((hi - lo + 1) as u64) as i64
    }
}

fn gcd(a: i64, b: i64) -> i64 {
    if b == 0 {
        a
    } else {
        gcd(b, a % b)
    }
}

fn collinear(a: (i64, i64), b: (i64, i64), c: (i64, i64)) -> bool {
    (b.0 - a.0) * (c.1 - a.1) - (b.1 - a.1) * (c.0 - a.0) == 0
}

/// Whether `ring` is a valid polygon as given (no dropped duplicates).
fn valid(ring: &[(i64, i64)]) -> bool {
    matches!(Polygon::from_raw(&raw(&[ring])), Ok((_, warnings)) if warnings.is_empty())
}

/// A random simple polygon on the grid `0..=size`, grown from a triangle by inserting points into
/// edges while it stays simple; with `flat`, biased towards flat vertices, without, free of them.
fn random_polygon(rng: &mut Rng, size: i64, target: usize, flat: bool) -> Vec<(i64, i64)> {
    let mut ring = loop {
        let t: Vec<(i64, i64)> = (0..3)
            .map(|_| (rng.int(0, size), rng.int(0, size)))
            .collect();
        if !collinear(t[0], t[1], t[2]) {
            break t;
        }
    };
    for _ in 0..20 * target {
        if ring.len() >= target {
            break;
        }
        let n = ring.len();
        let i = rng.below(n as u64) as usize;
        let (a, b) = (ring[i], ring[(i + 1) % n]);
        let p = if flat && rng.below(3) == 0 {
            let (dx, dy) = (b.0 - a.0, b.1 - a.1);
            let g = gcd(dx.abs(), dy.abs());
            let (sx, sy) = (dx / g, dy / g);
            match rng.below(3) {
                // A lattice point inside the edge: the new vertex is flat.
                0 if g > 1 => {
                    let k = rng.int(1, g - 1);
                    (a.0 + k * sx, a.1 + k * sy)
                }
                // Continue the previous edge past `a`: `a` becomes flat.
                1 => {
                    let z = ring[(i + n - 1) % n];
                    let (ex, ey) = (a.0 - z.0, a.1 - z.1);
                    let h = gcd(ex.abs(), ey.abs());
                    let k = rng.int(1, 3);
                    (a.0 + k * ex / h, a.1 + k * ey / h)
                }
                _ => (rng.int(0, size), rng.int(0, size)),
            }
        } else {
            (rng.int(0, size), rng.int(0, size))
        };
        let mut next = ring.clone();
        next.insert(i + 1, p);
        if !flat {
            let m = next.len();
            let at = |k: usize| next[(i + 1 + m + k - 2) % m];
            if (0..3).any(|k| collinear(at(k), at(k + 1), at(k + 2))) {
                continue;
            }
        }
        if valid(&next) {
            ring = next;
        }
    }
    ring
}

#[test]
fn random_simple_polygons() {
    let mut rng = Rng(0x5EED_0001);
    let mut flats = 0;
    for case in 0..3000 {
        let flat = case % 2 == 0;
        let size = [4, 6, 10, 20][case % 4];
        let target = 4 + (case / 4) % 24;
        let ring = random_polygon(&mut rng, size, target, flat);
        let p = polygon(&[&ring]);
        let pts = p.points();
        let n = pts.len();
        let has_flat = (0..n).any(|i| cross(pts[(i + n - 1) % n], pts[i], pts[(i + 1) % n]) == 0);
        assert!(flat || !has_flat);
        flats += usize::from(has_flat);
        check_cycle(pts);
    }
    assert!(flats > 500, "too few polygons with flat vertices: {flats}");
}

#[test]
fn random_rectilinear_polygons() {
    let mut rng = Rng(0x5EED_0002);
    let mut done = 0;
    while done < 2000 {
        let size = [4i64, 6, 10][done % 3];
        let mut cells = HashSet::from([(rng.int(0, size), rng.int(0, size))]);
        let grow = 1 + rng.below(3 * size as u64) as usize;
        while cells.len() < grow {
            let all: Vec<(i64, i64)> = cells.iter().copied().collect();
            let (x, y) = all[rng.below(all.len() as u64) as usize];
            let (dx, dy) = [(1, 0), (-1, 0), (0, 1), (0, -1)][rng.below(4) as usize];
            let c = (x + dx, y + dy);
            if (0..=size).contains(&c.0) && (0..=size).contains(&c.1) {
                cells.insert(c);
            }
        }
        let Some(ring) = polyomino(&cells, done % 2 == 0) else {
            continue;
        };
        if !valid(&ring) {
            continue;
        }
        check(&ring);
        done += 1;
    }
}

#[test]
fn large_random_star() {
    let mut rng = Rng(0x5EED_0003);
    let n = 200_000;
    let radius = 1_000_000_000f64;
    let mut pts: Vec<(i64, i64)> = (0..n)
        .map(|_| {
            let a = (rng.next() >> 11) as f64 / (1u64 << 53) as f64 * std::f64::consts::TAU;
            let r = radius * (0.2 + 0.8 * (rng.next() >> 11) as f64 / (1u64 << 53) as f64);
            ((r * a.cos()).round() as i64, (r * a.sin()).round() as i64)
        })
        .collect();
    // Exact angular order about the origin; one point per direction.
    let key = |&(x, y): &(i64, i64)| pt(x, y);
    let o = pt(0, 0);
    pts.sort_by(|a, b| around(o, pt(1, 0), key(a), key(b)));
    pts.dedup_by(|b, a| cross(o, key(a), key(b)) == 0 && dot(o, key(a), key(b)) > 0);
    let p = polygon(&[&pts]);
    let started = std::time::Instant::now();
    let t = triangulate_rings(p.points(), &[0]);
    let elapsed = started.elapsed();
    println!(
        "monotone: random star with {} vertices triangulated in {elapsed:?}",
        p.len()
    );
    assert_eq!(t.len(), p.len() - 2);
    let sum: i128 = t
        .iter()
        .map(|&[a, b, c]| {
            let s = cross(p.point(a), p.point(b), p.point(c));
            assert!(s > 0);
            s
        })
        .sum();
    assert_eq!(Some(sum), p.twice_area().value());
    check_cycle(p.points());
}

// ---------- polygons with holes ----------

/// Builds the polygon through the real constructor (so it is valid: holes may be given either
/// way round) and checks [`triangulate_rings`] on its rings completely: n + 2w - 2 positive
/// triangles; every directed side a ring edge `i -> next(i)` or matched by its reverse; every ring
/// edge used once, never backwards; twice-areas summing to the polygon's; pairwise disjoint
/// interiors for small inputs; and the independent checker of `verify.rs`.
fn check_holed(rings: &[&[(i64, i64)]]) -> Vec<[usize; 3]> {
    let p = polygon(rings);
    p.check_invariants();
    let (n, w) = (p.len(), p.holes());
    let pts = p.points();
    let t = triangulate_rings(pts, p.ring_starts());
    assert_eq!(t.len(), n + 2 * w - 2, "wrong count for {rings:?}");
    let mut area = 0i128;
    for &[a, b, c] in &t {
        let s = cross(pts[a], pts[b], pts[c]);
        assert!(s > 0, "triangle {a} {b} {c} not positive in {rings:?}");
        area += s;
    }
    assert_eq!(
        Some(area),
        p.twice_area().value(),
        "areas differ for {rings:?}"
    );
    let mut sides = HashSet::with_capacity(3 * t.len());
    for &[a, b, c] in &t {
        for side in [(a, b), (b, c), (c, a)] {
            assert!(sides.insert(side), "side {side:?} used twice in {rings:?}");
        }
    }
    for &(a, b) in &sides {
        assert!(
            b == p.next(a) || sides.contains(&(b, a)),
            "side {a} {b} unmatched in {rings:?}"
        );
    }
    for i in 0..n {
        let j = p.next(i);
        assert!(sides.contains(&(i, j)), "edge {i} {j} missing in {rings:?}");
        assert!(
            !sides.contains(&(j, i)),
            "edge {i} {j} reversed in {rings:?}"
        );
    }
    if n <= 200 {
        for (k, s) in t.iter().enumerate() {
            for r in &t[k + 1..] {
                assert!(separated(pts, s, r), "{s:?} and {r:?} overlap in {rings:?}");
            }
        }
    }
    let problems = crate::test_support::plain_problems(&p, t.clone());
    assert!(problems.is_empty(), "{rings:?}: {problems:?}");
    t
}

/// `check_holed` on the rings turned by 0, 1, 2 and 3 quarter turns, and mirrored (which turns
/// every ring's orientation: the constructor normalises it).
fn check_holed_all_ways(rings: &[Vec<(i64, i64)>]) {
    for q in 0..4 {
        let turned_rings: Vec<Vec<(i64, i64)>> = rings.iter().map(|r| turned(r, q)).collect();
        let refs: Vec<&[(i64, i64)]> = turned_rings.iter().map(Vec::as_slice).collect();
        check_holed(&refs);
        let mirrored: Vec<Vec<(i64, i64)>> = turned_rings
            .iter()
            .map(|r| r.iter().map(|&(x, y)| (-x, y)).collect())
            .collect();
        let refs: Vec<&[(i64, i64)]> = mirrored.iter().map(Vec::as_slice).collect();
        check_holed(&refs);
    }
}

/// An axis-parallel rectangle ring, counter-clockwise from its lower-left corner.
fn rect(x0: i64, y0: i64, x1: i64, y1: i64) -> Vec<(i64, i64)> {
    vec![(x0, y0), (x1, y0), (x1, y1), (x0, y1)]
}

#[test]
#[should_panic(expected = "fewer than 3")]
fn ring_starts_must_describe_rings_of_three_points() {
    let pts: Vec<Point> = U_SHAPE.iter().map(|&(x, y)| pt(x, y)).collect();
    triangulate_rings(&pts, &[0, 10]);
}

#[test]
fn square_with_a_square_hole() {
    let t = check_holed(&[&rect(0, 0, 4, 4), &rect(1, 1, 3, 3)]);
    assert_eq!(t.len(), 8);
    // Off centre, thin, and touching nothing but close to every side.
    check_holed_all_ways(&[rect(0, 0, 10, 10), rect(1, 6, 9, 9)]);
    check_holed_all_ways(&[rect(0, 0, 3, 3), rect(1, 1, 2, 2)]);
    check_holed_all_ways(&[rect(0, 0, 100, 3), rect(1, 1, 99, 2)]);
    // A triangle in a triangle, and a hole that is a triangle in a square.
    check_holed_all_ways(&[vec![(0, 0), (12, 0), (6, 12)], vec![(4, 2), (8, 2), (6, 6)]]);
    check_holed_all_ways(&[rect(0, 0, 6, 6), vec![(1, 1), (5, 2), (2, 5)]]);
}

#[test]
fn holes_with_flat_vertices() {
    // Every lattice point of the hole's boundary is a vertex (8 vertices, 4 of them flat).
    let hole = vec![
        (1, 1),
        (2, 1),
        (3, 1),
        (3, 2),
        (3, 3),
        (2, 3),
        (1, 3),
        (1, 2),
    ];
    check_holed_all_ways(&[rect(0, 0, 4, 4), hole.clone()]);
    // The same with flat vertices on the outer ring too, on the same lines as the hole's.
    let outer: Vec<(i64, i64)> = (0..4)
        .map(|x| (x, 0))
        .chain((0..4).map(|y| (4, y)))
        .chain((0..4).map(|x| (4 - x, 4)))
        .chain((0..4).map(|y| (0, 4 - y)))
        .collect();
    check_holed_all_ways(&[outer.clone(), hole]);
    // A diamond hole with a flat vertex in the middle of every side, and a long flat run.
    let diamond = vec![
        (4, 1),
        (5, 2),
        (6, 3),
        (5, 4),
        (4, 5),
        (3, 4),
        (2, 3),
        (3, 2),
    ];
    check_holed_all_ways(&[rect(0, 0, 8, 6), diamond]);
    let run: Vec<(i64, i64)> = (1..10).map(|x| (x, 1)).chain([(9, 2), (5, 3)]).collect();
    check_holed_all_ways(&[rect(0, 0, 10, 4), run]);
}

#[test]
fn holes_level_with_outer_vertices() {
    // A notch from the top down to y = 2, level with the holes' bottoms (their tops at y = 4);
    // in the second case one more hole whose top edge, at y = 2, lies on the line of the notch's
    // bottom, which it does not touch, and whose bottom is level with nothing.
    let outer = vec![
        (0, 0),
        (12, 0),
        (12, 6),
        (8, 6),
        (8, 2),
        (7, 2),
        (7, 6),
        (0, 6),
    ];
    check_holed_all_ways(&[outer.clone(), rect(2, 2, 4, 4), rect(9, 2, 11, 4)]);
    check_holed_all_ways(&[
        outer.clone(),
        rect(2, 2, 4, 4),
        rect(9, 2, 11, 4),
        rect(5, 1, 6, 2),
    ]);
    // Hole corners collinear with outer corners along verticals, horizontals and diagonals: a
    // diamond whose tip points at an outer corner, and a hole whose vertices share both lines of
    // an outer reflex corner.
    check_holed_all_ways(&[rect(0, 0, 8, 8), vec![(2, 2), (4, 1), (6, 2), (4, 4)]]);
    let l = vec![(0, 0), (8, 0), (8, 4), (4, 4), (4, 8), (0, 8)];
    check_holed_all_ways(&[l.clone(), vec![(1, 4), (3, 4), (2, 6)]]);
    check_holed_all_ways(&[l.clone(), vec![(4, 1), (4, 3), (6, 2)]]);
    check_holed_all_ways(&[
        l.clone(),
        vec![(1, 1), (3, 3), (1, 3)],
        vec![(5, 1), (7, 1), (7, 3)],
    ]);
    // Split and merge vertices of different holes at the same height, and a hole's lowest vertex
    // level with the outer ring's lowest-but-one.
    check_holed_all_ways(&[
        vec![(0, 0), (10, 0), (10, 10), (5, 9), (0, 10)],
        vec![(2, 2), (3, 4), (1, 4)],
        vec![(5, 4), (6, 2), (7, 4)],
        vec![(8, 2), (9, 4), (8, 6), (7, 5)],
        vec![(2, 6), (4, 6), (3, 8)],
    ]);
}

#[test]
fn many_holes_in_a_row_at_equal_heights() {
    for k in [1i64, 2, 5, 20] {
        // Square holes in a row: all bottoms at one height, all tops at another.
        let mut rings = vec![rect(0, 0, 4 * k + 1, 5)];
        rings.extend((0..k).map(|i| rect(4 * i + 1, 1, 4 * i + 3, 3)));
        check_holed_all_ways(&rings);
        // Triangles pointing up and down alternately, and diamonds: split and merge vertices
        // level with each other and with the outer ring's flat vertices.
        let mut outer = vec![(0, 0)];
        outer.extend((1..=k).map(|i| (4 * i, 0)));
        outer.extend([(4 * k + 2, 0), (4 * k + 2, 8)]);
        outer.extend((0..=k).rev().map(|i| (4 * i, 8)));
        let mut rings = vec![outer];
        for i in 0..k {
            let x = 4 * i + 1;
            rings.push(if i % 2 == 0 {
                vec![(x, 1), (x + 2, 1), (x + 1, 3)]
            } else {
                vec![(x, 3), (x + 1, 1), (x + 2, 3)]
            });
            rings.push(vec![(x + 1, 4), (x + 2, 5), (x + 1, 6), (x, 5)]);
        }
        check_holed_all_ways(&rings);
    }
    // A 10 x 10 grid of unit-square holes with flat vertices on every hole side.
    let mut rings = vec![rect(0, 0, 31, 31)];
    for i in 0..10 {
        for j in 0..10 {
            let (x, y) = (3 * i + 1, 3 * j + 1);
            rings.push(vec![
                (x, y),
                (x + 1, y),
                (x + 2, y),
                (x + 2, y + 2),
                (x + 1, y + 2),
                (x, y + 2),
            ]);
        }
    }
    let refs: Vec<&[(i64, i64)]> = rings.iter().map(Vec::as_slice).collect();
    check_holed(&refs);
}

#[test]
fn jittered_grid_of_triangular_holes() {
    // The benchmark family: many small triangles, each in its own cell, randomly placed.
    let mut rng = Rng(0x5EED_0004);
    for (cells, span) in [(5i64, 4i64), (30, 8), (60, 1000)] {
        let side = cells * span;
        let mut rings = vec![rect(0, 0, side + 2, side + 2)];
        for i in 0..cells {
            for j in 0..cells {
                let (x, y) = (i * span + 1, j * span + 1);
                let hole = loop {
                    let t: Vec<(i64, i64)> = (0..3)
                        .map(|_| (x + rng.int(0, span - 1), y + rng.int(0, span - 1)))
                        .collect();
                    if !collinear(t[0], t[1], t[2]) {
                        break t;
                    }
                };
                rings.push(hole);
            }
        }
        let refs: Vec<&[(i64, i64)]> = rings.iter().map(Vec::as_slice).collect();
        check_holed(&refs);
    }
}

/// `try_triangulate_rings` runs on rings not yet validated (while the validation runs, for
/// large polygons): on any rings, crossing, touching, with spikes and equal points, it must end
/// without a panic (this test runs with debug assertions on), and on valid ones it gives what
/// `triangulate_rings` gives. Random points on small grids, one to three rings, and valid
/// polygons with one vertex moved.
#[test]
fn rings_outside_the_contract_never_panic() {
    let mut rng = Rng(0x5EED_0BAD);
    let (mut none, mut some) = (0, 0);
    for case in 0..20_000 {
        let size = [2, 3, 5, 8, 20][case % 5];
        let mut pts = Vec::new();
        let mut starts = Vec::new();
        if case % 4 == 3 {
            // A valid polygon with one vertex moved anywhere on its grid.
            let mut ring = random_polygon(&mut rng, size, 4 + case % 20, case % 8 == 3);
            let k = rng.below(ring.len() as u64) as usize;
            ring[k] = (rng.int(0, size), rng.int(0, size));
            starts.push(0);
            pts.extend(ring.iter().map(|&(x, y)| pt(x, y)));
        } else {
            for _ in 0..1 + case % 3 {
                starts.push(pts.len());
                for _ in 0..3 + rng.below(30) {
                    pts.push(pt(rng.int(0, size), rng.int(0, size)));
                }
            }
        }
        match try_triangulate_rings(&pts, &starts) {
            None => none += 1,
            Some(triangles) => {
                some += 1;
                assert!(triangles.iter().flatten().all(|&v| v < pts.len()));
            }
        }
    }
    assert!(
        none > 1000 && some > 300,
        "{none} refused, {some} triangulated"
    );
    // On valid rings the two entries agree.
    for case in 0..500 {
        let ring = random_polygon(&mut rng, 20, 4 + case % 30, case % 2 == 0);
        let p = polygon(&[&ring]);
        let expected = triangulate_rings(p.points(), p.ring_starts());
        assert_eq!(
            try_triangulate_rings(p.points(), p.ring_starts()),
            Some(expected)
        );
    }
}
