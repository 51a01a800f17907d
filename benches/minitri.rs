//! MINITRI beside minitri's plain triangulation (`ear`), the `earcut` crate and, up to 2000
//! vertices, the Asano DP, on the same inputs: random star-shaped polygons in general position
//! and three random rectilinear families (many degenerate triangles): mazes (local visibility),
//! bars (an open corridor, quadratic visibility) and snakes (a winding corridor traced from a
//! raster), n = 10^3 .. 10^6 (`benches/common`).
//! Only the triangulation is timed: the polygon is built and validated beforehand; `earcut` gets
//! the same coordinates as `f64`.
//!
//! Run: `cargo bench --features bench --bench minitri`. Environment:
//! - `MINITRI_BENCH_MAX_N` (default 100000): the largest size (sizes are 10^3, 10^4, ...).
//!
//! The one-run table with peak memory and triangle counts is `benches/compare.rs`.

mod common;

use common::Shape;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode};
use minitri::{triangulate_with, Options, Triangulator};
use std::hint::black_box;
use std::time::Duration;

/// The largest polygon the DP is benchmarked on.
const DP_MAX_N: usize = 2000;

fn env_usize(name: &str, default: usize) -> usize {
    match std::env::var(name) {
        Ok(v) => v
            .trim()
            .replace('_', "")
            .parse()
            .unwrap_or_else(|_| panic!("{name}={v:?} is not a number")),
        Err(_) => default,
    }
}

fn family(c: &mut Criterion, shape: Shape) {
    let max_n = env_usize("MINITRI_BENCH_MAX_N", 100_000);
    let options = Options {
        dp_limit: usize::MAX,
        ..Options::default()
    };
    let mut group = c.benchmark_group(shape.name());
    group.sample_size(10);
    let sizes = [1_000, 10_000, 100_000, 1_000_000];
    for n in sizes.into_iter().filter(|&n| n <= max_n) {
        let points = shape.points(n, 1);
        let polygon = common::polygon(&points);
        let coords = common::earcut_input(&points);
        if n >= 100_000 {
            group.sampling_mode(SamplingMode::Flat);
            group.warm_up_time(Duration::from_secs(1));
            group.measurement_time(Duration::from_secs(if n >= 1_000_000 { 30 } else { 10 }));
        } else {
            group.sampling_mode(SamplingMode::Auto);
            group.warm_up_time(Duration::from_secs(1));
            group.measurement_time(Duration::from_secs(3));
        }
        group.bench_with_input(BenchmarkId::new("minitri", n), &polygon, |b, p| {
            b.iter(|| {
                triangulate_with(black_box(p), Triangulator::Minitri, &options).expect("hole-free")
            })
        });
        group.bench_with_input(BenchmarkId::new("ear", n), &polygon, |b, p| {
            b.iter(|| {
                triangulate_with(black_box(p), Triangulator::Ear, &options).expect("hole-free")
            })
        });
        group.bench_with_input(BenchmarkId::new("earcut", n), &coords, |b, xy| {
            b.iter(|| common::earcut(black_box(xy), &[]))
        });
        if polygon.len() <= DP_MAX_N {
            group.bench_with_input(BenchmarkId::new("asano", n), &polygon, |b, p| {
                b.iter(|| {
                    triangulate_with(black_box(p), Triangulator::Asano, &options).expect("fits")
                })
            });
        }
    }
    group.finish();
}

fn star(c: &mut Criterion) {
    family(c, Shape::Star);
}

fn maze(c: &mut Criterion) {
    family(c, Shape::Maze);
}

fn bars(c: &mut Criterion) {
    family(c, Shape::Bars);
}

fn snake(c: &mut Criterion) {
    family(c, Shape::Snake);
}

criterion_group!(benches, star, maze, bars, snake);
criterion_main!(benches);
