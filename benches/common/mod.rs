//! Benchmark inputs shared by the benches (each uses part of them): the two families of
//! `bench/polygon.py`, deterministic by seed, for `benches/minitri.rs` (criterion) and
//! `benches/compare.rs` (the table beside the `earcut` crate); polygons with holes given as
//! integer rings, for `benches/holes.rs`; and the mapbox/earcut fixtures in both forms, for
//! `benches/compare.rs` and `benches/earcut_fixtures.rs`; small rectilinear polygons for
//! `benches/batch.rs`.
//!
//! - [`star`]: a random star-shaped polygon in general position: random angles and radii around
//!   the origin on an integer grid, sorted exactly by angle (then by distance), so the polygon is
//!   simple; no flat vertices, and (on a grid this fine) collinear triples are rare.
//! - [`rectilinear`]: a random rectilinear "bar" of about 0.83 n vertices (`n / 4` columns, as in
//!   `bench/polygon.py`): the bottom follows random step heights 0..=4 and the top 6..=12, so long
//!   runs of horizontal edges at equal heights see each other (many degenerate triangles).
//!   Consecutive equal points and flat vertices are removed, as in `bench/polygon.py`.
//!
//! Both give the outer ring counter-clockwise as integer points, which [`polygon`] turns into a
//! validated [`minitri::Polygon`] through the public API (exact decimals, `Polygon::from_raw`)
//! and [`earcut_input`] into the `f64` pairs the `earcut` crate takes (exact: |coordinates| < 2^53).
//! [`raw_rings`] and [`earcut_rings`] do the same for an outer ring and holes; [`earcut_fixture`]
//! reads one mapbox/earcut fixture into both forms.
#![allow(dead_code)] // each bench uses part of this module

use minitri::{Decimal, Polygon, RawPolygon};
use std::cmp::Ordering;

/// A benchmark family.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Shape {
    /// Random star-shaped polygon in general position.
    Star,
    /// Random rectilinear bar with many degenerate triangles.
    Rectilinear,
}

impl Shape {
    /// The name used in tables and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Shape::Star => "star",
            Shape::Rectilinear => "rectilinear",
        }
    }

    /// The outer ring of this family's polygon for nominal size `n` and `seed`.
    pub fn points(self, n: usize, seed: u64) -> Vec<[i64; 2]> {
        match self {
            Shape::Star => star(n, seed),
            Shape::Rectilinear => rectilinear(n, seed),
        }
    }
}

/// SplitMix64: a small, fast, deterministic generator (no dependency needed).
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in `lo..=hi`.
    fn range(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as i64
    }
}

/// Exact counter-clockwise order of directions from the origin, starting at the positive x axis;
/// points on one ray by distance.
fn by_angle(p: &[i64; 2], q: &[i64; 2]) -> Ordering {
    let half = |a: &[i64; 2]| !(a[1] > 0 || (a[1] == 0 && a[0] > 0));
    let cross = i128::from(p[0]) * i128::from(q[1]) - i128::from(p[1]) * i128::from(q[0]);
    let norm = |a: &[i64; 2]| i128::from(a[0]).pow(2) + i128::from(a[1]).pow(2);
    half(p)
        .cmp(&half(q))
        .then(0.cmp(&cross))
        .then(norm(p).cmp(&norm(q)))
}

/// A random star-shaped polygon with (at most) `n` vertices: `n` random angles and radii in
/// `[0.3, 1] * (10 n + 1000)`, rounded to the integer grid, duplicates and the origin dropped,
/// sorted exactly by angle around the origin. Simple as long as no angular gap reaches pi
/// (checked; it never happens for n >= 20 with any seed tried).
///
/// # Panics
/// If the angular gap condition fails (pick another seed).
pub fn star(n: usize, seed: u64) -> Vec<[i64; 2]> {
    let mut rng = Rng(seed);
    let scale = 10.0 * n as f64 + 1000.0;
    let mut pts: Vec<[i64; 2]> = (0..n)
        .map(|_| {
            let a = rng.unit() * std::f64::consts::TAU;
            let r = scale * (0.3 + 0.7 * rng.unit());
            [(r * a.cos()).round() as i64, (r * a.sin()).round() as i64]
        })
        .filter(|&p| p != [0, 0])
        .collect();
    pts.sort_unstable();
    pts.dedup();
    pts.sort_unstable_by(by_angle);
    // Every turn around the origin between consecutive vertices must be less than pi.
    for (i, p) in pts.iter().enumerate() {
        let q = pts[(i + 1) % pts.len()];
        let cross = i128::from(p[0]) * i128::from(q[1]) - i128::from(p[1]) * i128::from(q[0]);
        assert!(cross >= 0, "star({n}, {seed}): angular gap of pi or more");
    }
    pts
}

/// A random rectilinear bar: `max(2, n / 4)` unit-wide columns, bottom heights in `0..=4`,
/// top heights in `6..=12`, walked counter-clockwise; then consecutive equal points and flat
/// vertices removed (about 0.83 n vertices remain).
pub fn rectilinear(n: usize, seed: u64) -> Vec<[i64; 2]> {
    let mut rng = Rng(seed);
    let columns = (n / 4).max(2) as i64;
    let top: Vec<i64> = (0..columns).map(|_| rng.range(6, 12)).collect();
    let bottom: Vec<i64> = (0..columns).map(|_| rng.range(0, 4)).collect();
    let mut ring = bar(&bottom, &top);
    let flat = |a: [i64; 2], b: [i64; 2], c: [i64; 2]| {
        (b[0] - a[0]) * (c[1] - a[1]) == (b[1] - a[1]) * (c[0] - a[0])
    };
    loop {
        let len = ring.len();
        let kept: Vec<[i64; 2]> = (0..len)
            .filter(|&i| !flat(ring[(i + len - 1) % len], ring[i], ring[(i + 1) % len]))
            .map(|i| ring[i])
            .collect();
        if kept.len() == len {
            return ring;
        }
        ring = kept;
    }
}

/// The reader's form of a ring of integer points.
pub fn raw(points: &[[i64; 2]]) -> RawPolygon {
    raw_rings(&[points])
}

/// The reader's form of integer rings: the outer ring, then the holes.
pub fn raw_rings<R: AsRef<[[i64; 2]]>>(rings: &[R]) -> RawPolygon {
    let d = |v: i64| Decimal::parse(&v.to_string()).expect("an integer is a decimal");
    RawPolygon {
        rings: rings
            .iter()
            .map(|ring| ring.as_ref().iter().map(|p| [d(p[0]), d(p[1])]).collect())
            .collect(),
    }
}

/// The validated polygon of a ring of integer points.
///
/// # Panics
/// If the generator made an invalid polygon (a bug in this file).
pub fn polygon(points: &[[i64; 2]]) -> Polygon {
    polygon_with_holes(&[points])
}

/// The validated polygon of integer rings: the outer ring, then the holes.
///
/// # Panics
/// If the generator made an invalid polygon (a bug in the bench).
pub fn polygon_with_holes<R: AsRef<[[i64; 2]]>>(rings: &[R]) -> Polygon {
    match Polygon::from_raw(&raw_rings(rings)) {
        Ok((polygon, _warnings)) => polygon,
        Err(e) => panic!("generated polygon is invalid: {e}"),
    }
}

/// The same points as the `f64` pairs the `earcut` crate takes (exact for these magnitudes).
pub fn earcut_input(points: &[[i64; 2]]) -> Vec<[f64; 2]> {
    points.iter().map(|p| [p[0] as f64, p[1] as f64]).collect()
}

/// Integer rings (the outer ring, then the holes) as the `earcut` crate takes them: all points
/// as `f64` pairs in one list, and the index where each hole starts.
pub fn earcut_rings<R: AsRef<[[i64; 2]]>>(rings: &[R]) -> (Vec<[f64; 2]>, Vec<u32>) {
    let mut coords = Vec::new();
    let mut hole_starts = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        if r > 0 {
            hole_starts.push(coords.len() as u32);
        }
        coords.extend(earcut_input(ring.as_ref()));
    }
    (coords, hole_starts)
}

/// A plain triangulation by the `earcut` crate (a fresh instance, so that its buffers count in
/// a memory measurement): triangle corner indices, three per triangle.
pub fn earcut(coords: &[[f64; 2]], hole_starts: &[u32]) -> Vec<u32> {
    let mut out = Vec::new();
    earcut::Earcut::new().earcut_slice(coords, hole_starts, &mut out);
    out
}

/// One mapbox/earcut fixture in both forms.
pub struct Fixture {
    /// The rings as minitri's GeoJSON reader reads them (exact decimals), or why it cannot.
    pub raw: Result<RawPolygon, String>,
    /// The same rings as `f64` pairs for the `earcut` crate, cleaned as minitri's reader and
    /// `Polygon` clean them (closing vertex and consecutive duplicates dropped), so that both
    /// see the same n.
    pub coords: Vec<[f64; 2]>,
    /// Where each hole starts in `coords`.
    pub hole_starts: Vec<u32>,
}

/// The fixtures of mapbox/earcut kept in this repository (`fixtures/earcut/`, ISC).
pub fn earcut_fixtures_dir() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/earcut")
}

/// Reads a fixture's text (a JSON array of rings, earcut's format); with `outer_only`, its outer
/// ring alone. A reader error of minitri's goes into [`Fixture::raw`]; an error here means the
/// text is not a fixture at all.
///
/// # Errors
/// When the text is not a JSON array of rings of `[x, y]` number pairs.
pub fn earcut_fixture(text: &str, outer_only: bool) -> Result<Fixture, String> {
    let mut rings: Vec<serde_json::Value> =
        serde_json::from_str(text).map_err(|e| e.to_string())?;
    if outer_only {
        rings.truncate(1);
    }
    // minitri reads the rings through its own GeoJSON reader (exact decimals).
    let geojson = serde_json::json!({ "type": "Polygon", "coordinates": rings });
    let raw = minitri::io::read::read(minitri::Format::GeoJson, &geojson.to_string())
        .map(|mut polygons| polygons.swap_remove(0))
        .map_err(|e| e.to_string());
    let mut coords = Vec::new();
    let mut hole_starts = Vec::new();
    for (r, ring) in rings.iter().enumerate() {
        let mut pts: Vec<[f64; 2]> = ring
            .as_array()
            .ok_or("ring is not an array")?
            .iter()
            .map(|p| {
                let x = |k: usize| p.get(k).and_then(serde_json::Value::as_f64);
                Ok([x(0).ok_or("bad point")?, x(1).ok_or("bad point")?])
            })
            .collect::<Result<_, String>>()?;
        pts.dedup();
        while pts.len() > 1 && pts.first() == pts.last() {
            pts.pop();
        }
        if r > 0 {
            hole_starts.push(coords.len() as u32);
        }
        coords.extend(pts);
    }
    Ok(Fixture {
        raw,
        coords,
        hole_starts,
    })
}

/// A small random rectilinear polygon for batch benchmarks: 2 to 10 unit columns, bottom heights
/// in `0..=2` and top heights in `4..=6`, walked counter-clockwise with only exact repeats removed,
/// so that equal neighbouring heights leave flat (collinear) vertices: 8 to 40 vertices, and
/// degenerate triangles to save.
pub fn small_rectilinear(seed: u64) -> Vec<[i64; 2]> {
    let mut rng = Rng(seed);
    let columns = rng.range(2, 10);
    let bottom: Vec<i64> = (0..columns).map(|_| rng.range(0, 2)).collect();
    let top: Vec<i64> = (0..columns).map(|_| rng.range(4, 6)).collect();
    bar(&bottom, &top)
}

/// The ring of unit-wide columns with these bottom and top heights, counter-clockwise (left to
/// right along the bottom, back along the top), with consecutive repeated points removed; flat
/// vertices stay.
fn bar(bottom: &[i64], top: &[i64]) -> Vec<[i64; 2]> {
    let mut ring: Vec<[i64; 2]> = Vec::with_capacity(4 * bottom.len());
    for (x, &h) in (0..).zip(bottom) {
        ring.extend([[x, h], [x + 1, h]]);
    }
    for (x, &h) in top.iter().enumerate().rev() {
        let x = x as i64;
        ring.extend([[x + 1, h], [x, h]]);
    }
    ring.dedup();
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    ring
}
