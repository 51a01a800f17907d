//! Pseudotriangulations (issue 7), on polygons already read, validated and (for `pseudo`)
//! triangulated:
//!
//! - group `pseudo_greedy`: the linear-time greedy of Section 5 (`pseudo::minimal`) alone, on
//!   the plain triangulation, for random star-shaped polygons (general position) and rectilinear
//!   mazes (many collinear vertices) of 10^3 to 10^6 vertices. Time per vertex should stay flat
//!   (Theorem 5); throughput is reported in vertices.
//! - group `pseudo_end_to_end`: the same with the O(n log n) plain triangulation included, as
//!   `--algorithm pseudo` runs it.
//! - group `pseudo_hull`: Theorem 6's construction (`pseudo_hull::pseudotriangulate`, hull,
//!   first triangulation and all steps) on random stars and mazes of 10^3 to 3 * 10^5 vertices
//!   (about 1 s at 10^5, 3 s at 3 * 10^5; see the module docs of `pseudo_hull`).
//!
//! Run: `cargo bench --features bench --bench pseudo` (about 6 minutes; `-- pseudo_hull` for the last group).

mod common;

use common::Shape;
use criterion::{
    criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode, Throughput,
};
use minitri::algo::{plain, pseudo, pseudo_hull};
use std::hint::black_box;
use std::time::Duration;

fn greedy(c: &mut Criterion) {
    for (name, end_to_end) in [("pseudo_greedy", false), ("pseudo_end_to_end", true)] {
        let mut group = c.benchmark_group(name);
        group.sampling_mode(SamplingMode::Flat);
        for shape in [Shape::Star, Shape::Maze] {
            for n in [1_000, 10_000, 100_000, 1_000_000] {
                let polygon = common::polygon(&shape.points(n, 7));
                let start = plain::triangulate(&polygon).expect("plain");
                group.throughput(Throughput::Elements(polygon.len() as u64));
                group.sample_size(if n >= 1_000_000 { 10 } else { 20 });
                group.measurement_time(Duration::from_secs(if n >= 100_000 { 8 } else { 3 }));
                let id = BenchmarkId::new(shape.name(), n);
                if end_to_end {
                    group.bench_with_input(id, &polygon, |b, p| {
                        b.iter(|| {
                            let t = plain::triangulate(black_box(p)).expect("plain");
                            pseudo::minimal(p, &t.triangles)
                        })
                    });
                } else {
                    group.bench_with_input(id, &polygon, |b, p| {
                        b.iter(|| pseudo::minimal(black_box(p), &start.triangles))
                    });
                }
            }
        }
        group.finish();
    }
}

fn hull(c: &mut Criterion) {
    let mut group = c.benchmark_group("pseudo_hull");
    group.sampling_mode(SamplingMode::Flat);
    group.sample_size(10);
    for shape in [Shape::Star, Shape::Maze] {
        for n in [1_000, 10_000, 100_000, 300_000] {
            let polygon = common::polygon(&shape.points(n, 7));
            group.throughput(Throughput::Elements(polygon.len() as u64));
            group.measurement_time(Duration::from_secs(match n {
                300_000 => 40,
                100_000 => 12,
                _ => 3,
            }));
            group.bench_with_input(BenchmarkId::new(shape.name(), n), &polygon, |b, p| {
                b.iter(|| pseudo_hull::pseudotriangulate(black_box(p)).expect("pseudo-hull"))
            });
        }
    }
    group.finish();
}

criterion_group!(benches, greedy, hull);
criterion_main!(benches);
