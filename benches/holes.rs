//! Polygons with many holes, on a polygon already read and validated (only the triangulation is
//! timed):
//!
//! - group `squares_64x64`: a square with a 64 x 64 grid of small square holes (all bottoms and
//!   tops level by row, so every row is one long tie of split and merge vertices; n = 16,388,
//!   4096 holes), triangulated three ways: `ear` (minitri's plain triangulation, monotone pieces,
//!   n + 2w - 2 triangles), `minitri` (the minimum: degenerate triangles, dependency graph, branch
//!   and bound with a 60 s deadline; every run must prove its result optimal, or the bench
//!   panics), and `earcut` (the `earcut` crate on the same coordinates as `f64`). Flat sampling,
//!   10 samples: `minitri` takes seconds per run.
//! - group `triangle_holes`: `ear` on squares with grids of 10^3, 10^4 and 10^5 small triangular
//!   holes, each randomly placed in its own cell. Time should grow like n log n; hole-by-hole
//!   bridging (earcut) would grow like n times the number of holes.
//!
//! Before timing, the triangle counts of the 64 x 64 square (plain, minimum, earcut) are printed.
//! Run: `cargo bench --features bench --bench holes` (2-3 minutes; `-- squares`
//! for the first group alone).

mod common;

use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use minitri::algo::minitri::triangulate_within;
use minitri::algo::plain;
use minitri::{Polygon, Triangulation};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// How long the exact search of `minitri` may run; far above what it needs (about 6 s).
const DEADLINE: Duration = Duration::from_secs(60);

/// A square with `k x k` square holes of side 2 on a pitch of 3: the outer ring, then the holes.
fn square_holes(k: i64) -> Vec<Vec<[i64; 2]>> {
    let side = 3 * k + 1;
    let mut rings = vec![vec![[0, 0], [side, 0], [side, side], [0, side]]];
    for i in 0..k {
        for j in 0..k {
            let (x, y) = (3 * i + 1, 3 * j + 1);
            rings.push(vec![[x, y], [x, y + 2], [x + 2, y + 2], [x + 2, y]]);
        }
    }
    rings
}

/// A square with `holes` triangular holes, one per cell of a square grid of cells of side 1000
/// (the first `holes` cells, row by row), each with random corners inside its cell.
fn jittered_triangles(holes: usize, seed: u64) -> Vec<Vec<[i64; 2]>> {
    let mut state = seed;
    let mut rnd = |n: i64| {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((state >> 33) % n as u64) as i64
    };
    let k = (holes as f64).sqrt().ceil() as i64;
    let cell = 1000;
    let side = k * cell + 2;
    let mut rings = vec![vec![[0, 0], [side, 0], [side, side], [0, side]]];
    for c in 0..holes as i64 {
        let (x, y) = ((c % k) * cell + 1, (c / k) * cell + 1);
        let triangle = loop {
            let t: Vec<[i64; 2]> = (0..3)
                .map(|_| [x + rnd(cell - 1), y + rnd(cell - 1)])
                .collect();
            let area = (t[1][0] - t[0][0]) * (t[2][1] - t[0][1])
                - (t[1][1] - t[0][1]) * (t[2][0] - t[0][0]);
            if area != 0 {
                break t;
            }
        };
        rings.push(triangle);
    }
    rings
}

/// The minimum triangulation within [`DEADLINE`].
///
/// # Panics
/// If the search did not prove its result optimal in time.
fn minimum(p: &Polygon) -> Triangulation {
    let t =
        triangulate_within(p, Instant::now().checked_add(DEADLINE)).expect("minitri handles holes");
    assert!(t.optimal, "not proved optimal within {DEADLINE:?}");
    t
}

fn squares(c: &mut Criterion) {
    let rings = square_holes(64);
    let p = common::polygon_with_holes(&rings);
    let (coords, hole_starts) = common::earcut_rings(&rings);
    let param = format!("{}_holes_n{}", p.holes(), p.len());

    let plain = plain::triangulate(&p)
        .expect("ear handles holes")
        .triangles
        .len();
    let start = Instant::now();
    let min = minimum(&p);
    let took = start.elapsed();
    let theirs = common::earcut(&coords, &hole_starts);
    let deviation = earcut::deviation(coords.iter().copied(), &hole_starts, &theirs);
    println!(
        "squares 64x64: n = {}, holes = {}; triangles: ear {plain}, minitri {} ({} degenerate, \
         proved optimal, one run {took:.2?}), earcut {} (area deviation {deviation:e})",
        p.len(),
        p.holes(),
        min.triangles.len(),
        min.degenerate.len(),
        theirs.len() / 3,
    );

    let mut group = c.benchmark_group("squares_64x64");
    group
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat)
        .measurement_time(Duration::from_secs(10))
        .throughput(Throughput::Elements(p.len() as u64));
    group.bench_with_input(BenchmarkId::new("ear", &param), &p, |b, p| {
        b.iter(|| plain::triangulate(black_box(p)).expect("ear handles holes"))
    });
    group.bench_with_input(BenchmarkId::new("earcut", &param), &coords, |b, coords| {
        b.iter(|| common::earcut(black_box(coords), &hole_starts))
    });
    // Ten runs of 4-7 s each (criterion says so when they need more than 50 s).
    group.measurement_time(Duration::from_secs(50));
    group.bench_with_input(BenchmarkId::new("minitri", &param), &p, |b, p| {
        b.iter(|| minimum(black_box(p)))
    });
    group.finish();
}

fn triangle_holes(c: &mut Criterion) {
    let mut group = c.benchmark_group("triangle_holes");
    group.sample_size(10);
    for count in [1_000, 10_000, 100_000] {
        let p = common::polygon_with_holes(&jittered_triangles(count, 1));
        group.throughput(Throughput::Elements(p.len() as u64));
        let id = BenchmarkId::new("ear", format!("{}_holes_n{}", p.holes(), p.len()));
        group.bench_with_input(id, &p, |b, p| {
            b.iter(|| plain::triangulate(black_box(p)).expect("ear handles holes"))
        });
    }
    group.finish();
}

criterion_group!(benches, squares, triangle_holes);
criterion_main!(benches);
