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
//! - [`maze`]: a random rectilinear polygon of about n vertices: a random spanning tree of a
//!   k x k grid, each node and tree edge a unit cell, the union's boundary walked (no flat
//!   vertices). Every vertex lies on a grid line shared with many others, so degenerate triangles
//!   abound (d is about 0.37 n), but corridors are one cell wide and turn often, so each vertex
//!   sees few others: the realistic rectilinear case (building footprints, floor plans).
//! - [`bars`]: the adversarial rectilinear case, a random "bar" of about 0.83 n vertices
//!   (`n / 4` columns, as in `bench/polygon.py`): the bottom follows random step heights 0..=4
//!   and the top 6..=12, so an open corridor 4 < y < 6 runs the whole length and Theta(n^2)
//!   vertex pairs see each other (issue 3). Consecutive equal points and flat vertices are removed.
//! - [`snake`]: a raster-like winding corridor (rows of a bar joined at alternate ends, every
//!   lattice point of the boundary a vertex): the realistic form of the bars' quadratic step 3.
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
    /// Random rectilinear maze (spanning tree of cells): many degenerate triangles, local
    /// visibility.
    Maze,
    /// Random rectilinear bar with an open corridor: many degenerate triangles, quadratic
    /// visibility.
    Bars,
    /// A raster-like winding corridor, every lattice point of the boundary a vertex.
    Snake,
}

impl Shape {
    /// The name used in tables and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Shape::Star => "star",
            Shape::Maze => "maze",
            Shape::Bars => "bars",
            Shape::Snake => "snake",
        }
    }

    /// The outer ring of this family's polygon for nominal size `n` and `seed`.
    pub fn points(self, n: usize, seed: u64) -> Vec<[i64; 2]> {
        match self {
            Shape::Star => star(n, seed),
            Shape::Maze => maze(n, seed),
            Shape::Bars => bars(n, seed),
            Shape::Snake => snake(n, seed),
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
pub fn bars(n: usize, seed: u64) -> Vec<[i64; 2]> {
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

/// A raster-like winding corridor of about `n` vertices (`bench/polygon.py snake` draws the same
/// family with Python's generator): `rows = max(2, round(sqrt(n) / 8))` corridors of
/// `columns = max(3, round(n / (3 rows)))` unit columns, bottoms at random heights 0 or 1 and tops
/// at 5 or 6 (row `r` is shifted up by `10 r`), joined at alternate ends by one-column connectors;
/// the boundary of the cells, counter-clockwise from its lowest-leftmost point, with every
/// lattice point a vertex (as an outline traced from a raster keeps them). Degenerate triangles
/// cross the corridor (nested inside each other along the whole snake: quadratic in step 3 of
/// MINITRI, as on the bars) and long 3b-chains run along its walls.
pub fn snake(n: usize, seed: u64) -> Vec<[i64; 2]> {
    let mut rng = Rng(seed);
    let rows = ((n as f64).sqrt() / 8.0).round().max(2.0) as i64;
    let columns = (n as f64 / (3 * rows) as f64).round().max(3.0) as i64;
    let mut cells = std::collections::HashSet::new();
    for r in 0..rows {
        let y0 = 10 * r;
        for x in 0..columns {
            let (bottom, top) = (rng.range(0, 1), rng.range(5, 6));
            cells.extend((bottom..top).map(|y| (x, y0 + y)));
        }
        if r + 1 < rows {
            let x = if r % 2 == 0 { columns - 1 } else { 0 };
            cells.extend((y0 + 1..y0 + 12).map(|y| (x, y)));
        }
    }
    // Column 0 is a corridor's first column: its lowest cell's lower-left corner starts the walk.
    let bottom = (0..).find(|&y| cells.contains(&(0, y))).expect("column 0");
    outline(|x, y| cells.contains(&(x, y)), [0, bottom], false)
}

/// A random rectilinear maze of about `n` vertices (`bench/polygon.py maze` draws the same
/// family): a random spanning tree (randomized Kruskal) of a k x k grid of nodes,
/// k = round(sqrt(n / 1.72)); node (i, j) is the unit cell (2i, 2j), the tree edge between two
/// nodes the cell between them; the outer boundary of these cells, counter-clockwise, corners
/// only. The union is simply connected (a tree) and never pinched: around every lattice point one
/// of the four cells is a node (always in) and the diagonally opposite one (odd, odd) never is.
pub fn maze(n: usize, seed: u64) -> Vec<[i64; 2]> {
    let mut rng = Rng(seed);
    let k = ((n as f64 / 1.72).sqrt().round() as usize).max(2);
    let side = 2 * k - 1; // cells per row
    let mut filled = vec![false; side * side];
    let cell = |x: usize, y: usize| y * side + x;
    for i in 0..k {
        for j in 0..k {
            filled[cell(2 * i, 2 * j)] = true;
        }
    }
    // Candidate tree edges (node, node, cell between), shuffled (Fisher-Yates).
    let mut edges: Vec<(usize, usize, usize)> = Vec::with_capacity(2 * k * k);
    for i in 0..k {
        for j in 0..k {
            if i + 1 < k {
                edges.push((i * k + j, (i + 1) * k + j, cell(2 * i + 1, 2 * j)));
            }
            if j + 1 < k {
                edges.push((i * k + j, i * k + j + 1, cell(2 * i, 2 * j + 1)));
            }
        }
    }
    for e in (1..edges.len()).rev() {
        edges.swap(e, (rng.next_u64() % (e as u64 + 1)) as usize);
    }
    let mut parent: Vec<usize> = (0..k * k).collect();
    fn root(parent: &mut [usize], mut a: usize) -> usize {
        while parent[a] != a {
            parent[a] = parent[parent[a]];
            a = parent[a];
        }
        a
    }
    for (a, b, between) in edges {
        let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
        if ra != rb {
            parent[ra] = rb;
            filled[between] = true;
        }
    }
    let inside = |x: i64, y: i64| {
        x >= 0
            && y >= 0
            && (x as usize) < side
            && (y as usize) < side
            && filled[cell(x as usize, y as usize)]
    };
    outline(inside, [0, 0], true) // from the lower-left corner of node (0, 0)
}

/// The boundary of a simply connected, never pinched union of unit cells (`inside(x, y)`: the
/// cell whose lower-left corner is `(x, y)`), counter-clockwise from `start`, the lower-left
/// corner of a cell whose neighbour below is outside: its corners only, or every lattice point
/// on it. At lattice point p heading in direction d (0 east, 1 north, 2 west, 3 south), the
/// cells ahead-left and ahead-right decide: turn right if ahead-right is in, go straight if only
/// ahead-left is in, else turn left.
fn outline(
    inside: impl Fn(i64, i64) -> bool,
    start: [i64; 2],
    corners_only: bool,
) -> Vec<[i64; 2]> {
    const STEP: [[i64; 2]; 4] = [[1, 0], [0, 1], [-1, 0], [0, -1]];
    // The cell ahead-left / ahead-right of lattice point p in direction d, as its lower-left corner.
    let ahead = |p: [i64; 2], d: usize| -> ([i64; 2], [i64; 2]) {
        match d {
            0 => ([p[0], p[1]], [p[0], p[1] - 1]),
            1 => ([p[0] - 1, p[1]], [p[0], p[1]]),
            2 => ([p[0] - 1, p[1] - 1], [p[0] - 1, p[1]]),
            _ => ([p[0], p[1] - 1], [p[0] - 1, p[1] - 1]),
        }
    };
    let (mut p, mut d) = (start, 0usize);
    let mut ring = Vec::new();
    loop {
        let (left, right) = ahead(p, d);
        let next = if inside(right[0], right[1]) {
            (d + 3) % 4
        } else if inside(left[0], left[1]) {
            d
        } else {
            (d + 1) % 4
        };
        if !corners_only || next != d || ring.is_empty() {
            ring.push(p);
        }
        d = next;
        p = [p[0] + STEP[d][0], p[1] + STEP[d][1]];
        if p == start {
            return ring;
        }
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
        ..Default::default()
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
