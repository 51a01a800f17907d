//! Helpers shared by the unit tests: small polygons and exact numbers from literals.

use crate::geom::decimal::Decimal;
use crate::geom::polygon::Polygon;
use crate::raw::RawPolygon;

/// The U-shape of the README: 12 vertices, counter-clockwise from (3, 2), four of them flat, with
/// a notch from the top down to y = 3.
pub(crate) const U_SHAPE: [(i64, i64); 12] = [
    (3, 2),
    (4, 2),
    (5, 2),
    (6, 2),
    (6, 3),
    (6, 4),
    (5, 4),
    (5, 3),
    (4, 3),
    (4, 4),
    (3, 4),
    (3, 3),
];

/// The 2 x 2 square with a flat vertex in the middle of every side, counter-clockwise from the
/// origin.
pub(crate) const FLAT_SQUARE: [(i64, i64); 8] = [
    (0, 0),
    (1, 0),
    (2, 0),
    (2, 1),
    (2, 2),
    (1, 2),
    (0, 2),
    (0, 1),
];

/// What the independent checker ([`crate::verify::check`]) finds wrong with `triangles` as a plain
/// triangulation of `p` (no degenerate triangles claimed): nothing when it is one.
pub(crate) fn plain_problems(p: &Polygon, triangles: Vec<[usize; 3]>) -> Vec<String> {
    let t = crate::algo::Triangulation {
        algorithm: crate::algo::Algorithm::Ear,
        triangles,
        degenerate: Vec::new(),
        optimal: false,
        lower_bound: None,
        stopped: None,
    };
    crate::verify::check(p, &t).problems
}

/// An exact decimal from its text (panics, naming the text, if it does not parse).
pub(crate) fn d(s: &str) -> Decimal {
    Decimal::parse(s).expect(s)
}

/// A ring of exact points from decimal texts.
pub(crate) fn ring(points: &[(&str, &str)]) -> Vec<[Decimal; 2]> {
    points.iter().map(|(x, y)| [d(x), d(y)]).collect()
}

/// A raw polygon from integer rings (outer first), not validated.
pub(crate) fn raw(rings: &[&[(i64, i64)]]) -> RawPolygon {
    RawPolygon {
        rings: rings
            .iter()
            .map(|r| r.iter().map(|&(x, y)| [int(x), int(y)]).collect())
            .collect(),
        ordinates: None,
    }
}

/// A raw polygon from rings of decimal texts (outer first), not validated.
pub(crate) fn raw_decimal(rings: &[&[(&str, &str)]]) -> RawPolygon {
    RawPolygon {
        rings: rings.iter().map(|r| ring(r)).collect(),
        ordinates: None,
    }
}

/// A valid polygon from integer rings (outer first), through the real constructor (panics if
/// invalid: tests only).
pub(crate) fn polygon(rings: &[&[(i64, i64)]]) -> Polygon {
    Polygon::from_raw(&raw(rings))
        .expect("a valid test polygon")
        .0
}

/// Polygons as `f64` rings, for comparison with other crates' readers.
pub(crate) fn as_f64(polygons: &[RawPolygon]) -> Vec<Vec<Vec<[f64; 2]>>> {
    polygons
        .iter()
        .map(|p| {
            p.rings
                .iter()
                .map(|r| r.iter().map(|[x, y]| [x.to_f64(), y.to_f64()]).collect())
                .collect()
        })
        .collect()
}

fn int(v: i64) -> Decimal {
    d(&v.to_string())
}

/// A deterministic xorshift generator: `rnd(n)` is a number in `0..n`.
pub(crate) fn xorshift(seed: u64) -> impl FnMut(i64) -> i64 {
    let mut state = seed;
    move |n: i64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as i64
    }
}

/// The stored index of the vertex at input coordinates `q` (panics if there is none).
pub(crate) fn vertex_at(p: &Polygon, q: (i64, i64)) -> usize {
    let text = format!("({}, {})", q.0, q.1);
    (0..p.len())
        .find(|&i| p.format_vertex(i) == text)
        .expect("a vertex there")
}

/// A polygon with a triangular hole `(0, 10) (2, 2) (-2, 2)` and a hand-made plain
/// triangulation (11 triangles, stored indices) in which the chord from `S = (-20, 0)` to
/// `E = (20, 0)` crosses, in order, the triangles `(S p v) (v p q) (p r q) (q r s) (v s r)
/// (r E v)`, with `p = (-10, -10)` and `r = (10, -10)` below it and the hole's vertices `v =
/// (0, 10)`, `s = (2, 2)`, `q = (-2, 2)` above: on the upper side the crossed triangles go round
/// the hole and meet at `v` twice, so the polygon they leave above the chord, `S E v s q v`,
/// touches itself at `v`. `E` is a reflex vertex with `C = (40, 0)` beyond it: `(S, E, C)` is a
/// minimally degenerate triangle.
pub(crate) fn pinched_round_a_hole() -> (Polygon, Vec<[usize; 3]>) {
    let (s, p, r, e, f, c, u, t) = (
        (-20, 0),
        (-10, -10),
        (10, -10),
        (20, 0),
        (30, -10),
        (40, 0),
        (40, 20),
        (0, 20),
    );
    let (v, s2, q) = ((0, 10), (2, 2), (-2, 2));
    let poly = polygon(&[&[s, p, r, e, f, c, u, t], &[v, s2, q]]);
    let triangles = [
        [s, p, v],
        [v, p, q],
        [p, r, q],
        [q, r, s2],
        [v, s2, r],
        [r, e, v],
        [s, v, t],
        [e, f, c],
        [v, e, c],
        [v, c, u],
        [v, u, t],
    ]
    .iter()
    .map(|t| t.map(|x| vertex_at(&poly, x)))
    .collect();
    (poly, triangles)
}

/// A comb of `teeth` teeth `w` wide and `h` high over gaps `w` wide, every gap bottom on the line
/// y = 1 above a base from (0, 0) to (2 w teeth, 0), counter-clockwise.
pub(crate) fn comb(teeth: i64, w: i64, h: i64) -> Vec<(i64, i64)> {
    let mut ring = vec![(0, 0), (2 * w * teeth, 0)];
    for k in (0..teeth).rev() {
        let x = 2 * w * k;
        ring.extend([(x + 2 * w, 1), (x + w, 1), (x + w, 1 + h), (x, 1 + h)]);
    }
    ring
}

/// A sliver staircase: unit steps (scaled by `w` and `h`) from `(steps w, 1)` up to
/// `(w, steps h)` over the long edge from the origin, as `bench/polygon.py sliver` (with `w = h
/// = 1` every reflex corner lies on one line, each seeing along it).
pub(crate) fn sliver(steps: i64, w: i64, h: i64) -> Vec<(i64, i64)> {
    let mut ring = vec![(0, 0), (steps * w, 1)];
    for k in 1..steps {
        ring.extend([
            ((steps - k) * w, 1 + (k - 1) * h),
            ((steps - k) * w, 1 + k * h),
        ]);
    }
    ring
}

/// The region between the parabola `y = x^2` (its points at x = m, .., 0, all reflex) and the
/// chord below it from `(0, -m^2)` to `(m, 0)`, with about `bottom` vertices spread on the chord
/// (flat), counter-clockwise, as `bench/polygon.py parabola`: tangent rays cross the whole
/// polygon, and the hull chains of the shooter's paths are long (the parabola is convex).
pub(crate) fn parabola(m: i64, bottom: i64) -> Vec<(i64, i64)> {
    let bottom = bottom.clamp(1, m);
    let mut ring: Vec<(i64, i64)> = (0..bottom)
        .map(|i| i * m / bottom)
        .map(|x| (x, m * x - m * m))
        .collect();
    ring.push((m, 0));
    ring.extend((0..=m).rev().map(|k| (k, k * k)));
    ring
}

/// `count` random simple rings on the grid `0..side`, each grown from a triangle by inserting
/// up to `inserts` random grid points into random edges (a point kept only when the polygon
/// stays valid): collinear triples and flat vertices everywhere.
pub(crate) fn grown_rings(
    seed: u64,
    count: usize,
    side: i64,
    inserts: i64,
) -> Vec<Vec<(i64, i64)>> {
    let mut rnd = xorshift(seed);
    (0..count)
        .map(|_| {
            let mut ring: Vec<(i64, i64)> = vec![(0, 0), (side - 1, 0), (side / 2, side - 1)];
            for _ in 0..rnd(inserts) {
                let at = rnd(ring.len() as i64) as usize + 1;
                let mut next = ring.clone();
                next.insert(at, (rnd(side), rnd(side)));
                if Polygon::from_raw(&raw(&[&next])).is_ok() {
                    ring = next;
                }
            }
            ring
        })
        .collect()
}
