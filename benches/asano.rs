//! The Asano DP on random star-shaped polygons and on convex polygons (its worst case: every
//! pair is a chord), n = 250 .. 2000; the same families as `bench/polygon.py`.
//! Run: `cargo bench --features bench --bench asano`. Peak memory: `bench/asano.sh` (`docs/benchmarks.md`).

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion};
use minitri::algo::{asano, chords::ChordTable};
use minitri::{Decimal, Polygon, RawPolygon};
use std::hint::black_box;

/// A random star-shaped polygon on an integer grid: sorted random angles, random radii.
fn star(n: usize, seed: u64) -> Polygon {
    let mut state = seed;
    let mut rnd = || {
        state = state
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (state >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut angles: Vec<f64> = (0..n).map(|_| rnd() * std::f64::consts::TAU).collect();
    angles.sort_by(f64::total_cmp);
    let mut ring: Vec<[Decimal; 2]> = Vec::new();
    for a in angles {
        let r = 1e6 * (0.3 + 0.7 * rnd());
        let d = |v: f64| Decimal::parse(&format!("{}", v.round() as i64)).expect("integer");
        let p = [d(r * a.cos()), d(r * a.sin())];
        if !ring.contains(&p) {
            ring.push(p);
        }
    }
    Polygon::from_raw(&RawPolygon {
        rings: vec![ring],
        ..Default::default()
    })
    .expect("a star-shaped polygon is simple")
    .0
}

/// A convex polygon: points on a parabola.
fn convex(n: usize) -> Polygon {
    let d = |v: usize| Decimal::parse(&v.to_string()).expect("integer");
    let mut ring: Vec<[Decimal; 2]> = (0..n - 1).map(|i| [d(i), d(i * i)]).collect();
    ring.push([d(0), d((n - 2) * (n - 2))]);
    Polygon::from_raw(&RawPolygon {
        rings: vec![ring],
        ..Default::default()
    })
    .expect("convex")
    .0
}

fn dp(c: &mut Criterion) {
    let mut group = c.benchmark_group("asano");
    group.sample_size(10);
    for n in [250, 500, 1000, 2000] {
        let polygon = star(n, 1);
        group.bench_with_input(BenchmarkId::new("dp", n), &polygon, |b, p| {
            b.iter(|| asano::triangulate(black_box(p), usize::MAX).expect("hole-free"))
        });
        group.bench_with_input(BenchmarkId::new("chord_table", n), &polygon, |b, p| {
            b.iter(|| ChordTable::new(black_box(p)))
        });
        let polygon = convex(n);
        group.bench_with_input(BenchmarkId::new("dp_convex", n), &polygon, |b, p| {
            b.iter(|| asano::triangulate(black_box(p), usize::MAX).expect("hole-free"))
        });
    }
    group.finish();
}

criterion_group!(benches, dp);
criterion_main!(benches);
