//! The plain triangulation (`--algorithm ear`, monotone pieces) of polygons with many holes: a
//! square with a 64 x 64 grid of small square holes (all bottoms and tops level by row, so every
//! row is one long tie of split and merge vertices), and squares with grids of 10^3, 10^4 and
//! 10^5 small triangular holes, each randomly placed in its own cell. Time should grow like
//! n log n; hole-by-hole bridging (earcut) would grow like n times the number of holes.
//! Run: `cargo bench --bench holes`.

use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use minitri::algo::ear;
use minitri::{Decimal, Polygon, RawPolygon};
use std::hint::black_box;

fn ring(points: &[(i64, i64)]) -> Vec<[Decimal; 2]> {
    let d = |v: i64| Decimal::parse(&v.to_string()).expect("integer");
    points.iter().map(|&(x, y)| [d(x), d(y)]).collect()
}

fn polygon(rings: Vec<Vec<[Decimal; 2]>>) -> Polygon {
    Polygon::from_raw(&RawPolygon { rings })
        .expect("a valid polygon with holes")
        .0
}

/// A square with `k x k` square holes of side 2 on a pitch of 3.
fn square_holes(k: i64) -> Polygon {
    let side = 3 * k + 1;
    let mut rings = vec![ring(&[(0, 0), (side, 0), (side, side), (0, side)])];
    for i in 0..k {
        for j in 0..k {
            let (x, y) = (3 * i + 1, 3 * j + 1);
            rings.push(ring(&[(x, y), (x, y + 2), (x + 2, y + 2), (x + 2, y)]));
        }
    }
    polygon(rings)
}

/// A square with `holes` triangular holes, one per cell of a square grid of cells of side 1000
/// (the first `holes` cells, row by row), each with random corners inside its cell.
fn jittered_triangles(holes: usize, seed: u64) -> Polygon {
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
    let mut rings = vec![ring(&[(0, 0), (side, 0), (side, side), (0, side)])];
    for c in 0..holes as i64 {
        let (x, y) = ((c % k) * cell + 1, (c / k) * cell + 1);
        let triangle = loop {
            let t: Vec<(i64, i64)> = (0..3)
                .map(|_| (x + rnd(cell - 1), y + rnd(cell - 1)))
                .collect();
            let area =
                (t[1].0 - t[0].0) * (t[2].1 - t[0].1) - (t[1].1 - t[0].1) * (t[2].0 - t[0].0);
            if area != 0 {
                break t;
            }
        };
        rings.push(ring(&triangle));
    }
    polygon(rings)
}

fn holes(c: &mut Criterion) {
    let mut group = c.benchmark_group("holes");
    group.sample_size(10);
    let mut cases = vec![("squares", square_holes(64))];
    for count in [1_000, 10_000, 100_000] {
        cases.push(("triangles", jittered_triangles(count, 1)));
    }
    for (family, p) in &cases {
        group.throughput(Throughput::Elements(p.len() as u64));
        let id = BenchmarkId::new(*family, format!("{}_holes_n{}", p.holes(), p.len()));
        group.bench_with_input(id, p, |b, p| {
            b.iter(|| ear::triangulate(black_box(p)).expect("ear handles holes"))
        });
    }
    group.finish();
}

criterion_group!(benches, holes);
criterion_main!(benches);
