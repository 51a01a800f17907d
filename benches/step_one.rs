//! Step 1 of MINITRI (every minimally degenerate triangle) by its three ways of sharing the
//! work: the walk alone, the bounded method alone (balanced cuts, shortest-path trees and ray
//! shooting: `algo::minitri::polygon_cutting`) and the default hybrid (the walk with a budget per
//! vertex, the bounded method for the vertices over it). The same set of triangles each way
//! (the tests compare them); this times them. Inputs: random stars, mazes, bars and snakes
//! (`benches/common`), combs, sliver staircases and parabolas, n = 10^4 and 10^5 (about).
//!
//! Run: `cargo bench --features bench --bench step_one`.

mod common;

use common::Shape;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use minitri::algo::minitri::degenerate::{minimally_degenerate_with, Budget};
use minitri::algo::minitri::ray_shooting::RayPolicy;
use std::hint::black_box;
use std::time::Duration;

/// A comb of `teeth` teeth 1 wide and 9 high over gap floors on one line (`bench/polygon.py
/// comb`).
fn comb(teeth: i64) -> Vec<[i64; 2]> {
    let mut pts = vec![[0, 0], [2 * teeth - 1, 0]];
    for i in (0..teeth).rev() {
        pts.extend([[2 * i + 1, 10], [2 * i, 10]]);
        if i > 0 {
            pts.extend([[2 * i, 1], [2 * i - 1, 1]]);
        }
    }
    pts
}

/// The region under the parabola `y = x^2` (x = m, .., 0) above the chord from `(0, -m^2)` to
/// `(m, 0)` (`bench/polygon.py parabola`): every walk long, long convex hull chains.
fn parabola(m: i64) -> Vec<[i64; 2]> {
    let mut pts = vec![[0, -m * m], [m, 0]];
    pts.extend((0..=m).rev().map(|k| [k, k * k]));
    pts
}

/// A staircase of unit steps over the long edge (0 0)-(steps 1) (`bench/polygon.py sliver`).
fn sliver(steps: i64) -> Vec<[i64; 2]> {
    let mut pts = vec![[0, 0], [steps, 1]];
    for k in 1..steps {
        pts.extend([[steps - k, k], [steps - k, k + 1]]);
    }
    pts
}

fn step_one(c: &mut Criterion) {
    let mut inputs: Vec<(String, Vec<[i64; 2]>)> = Vec::new();
    for n in [10_000usize, 100_000] {
        for shape in [Shape::Star, Shape::Maze, Shape::Bars, Shape::Snake] {
            inputs.push((format!("{} {n}", shape.name()), shape.points(n, 1)));
        }
        inputs.push((format!("comb {n}"), comb(n as i64 / 4)));
        inputs.push((format!("sliver {n}"), sliver(n as i64 / 2)));
        inputs.push((format!("parabola {n}"), parabola(n as i64)));
    }
    let mut group = c.benchmark_group("step_one");
    group.sample_size(10);
    group.warm_up_time(Duration::from_secs(1));
    group.measurement_time(Duration::from_secs(3));
    for (name, points) in &inputs {
        let polygon = common::polygon(points);
        for (label, budget) in [
            ("hybrid", Budget::Hybrid),
            ("walk", Budget::WalkOnly),
            ("cuts", Budget::CutsOnly),
        ] {
            // The walk alone is quadratic on the parabola (every vertex sees across it all):
            // seconds per run at 10^4 vertices.
            if budget == Budget::WalkOnly && name.starts_with("parabola") {
                continue;
            }
            group.bench_with_input(BenchmarkId::new(label, name), &polygon, |b, p| {
                b.iter(|| minimally_degenerate_with(black_box(p), RayPolicy::Hybrid, budget).len())
            });
        }
    }
    group.finish();
}

criterion_group!(benches, step_one);
criterion_main!(benches);
