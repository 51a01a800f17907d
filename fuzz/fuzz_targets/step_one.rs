//! Step 1 of MINITRI (all minimally degenerate triangles) whatever the ray policy: the set of
//! triangles, kinds included, found with every ray walked, every ray shot over heavy paths
//! (`minitri::algo::minitri::ray_shooting`) and the default hybrid must equal the angular
//! sweep's (`minimally_degenerate_by_sweep`).
//!
//! Inputs: a ring grown point by point on the grid 0..=16 (each point inserted after the vertex
//! its third byte names, kept only when the polygon stays valid, as in the `core` target), up to
//! `MAX` vertices; or, by the first byte, a comb (teeth `w` wide and `h` high over gap floors on
//! one line) or a sliver staircase over a long edge, the polygons whose long rays the shooter
//! is for, of up to a few hundred vertices.
#![no_main]
use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use minitri::algo::minitri::degenerate::{
    minimally_degenerate_by_sweep, minimally_degenerate_with, Degenerate,
};
use minitri::algo::minitri::ray_shooting::RayPolicy;
use minitri::io::read::RawPolygon;
use minitri::Polygon;
use minitri_fuzz::ring;

/// The most vertices of a grown ring.
const MAX: usize = 60;

/// A point `(x, y)` (each taken modulo 17) and where to insert it.
#[derive(Arbitrary, Debug, Clone, Copy)]
struct Vertex(u8, u8, u8);

#[derive(Arbitrary, Debug)]
enum Input {
    Grown(Vec<Vertex>),
    Comb { teeth: u8, w: u8, h: u8 },
    Sliver { steps: u8, w: u8, h: u8 },
}

fn valid(points: &[(i64, i64)]) -> Option<Polygon> {
    let raw = RawPolygon {
        rings: vec![ring(points)],
    };
    Polygon::from_raw_all_errors(&raw).ok().map(|(p, _)| p)
}

fn keys(found: &[Degenerate]) -> Vec<(usize, usize, usize, u8)> {
    let mut keys: Vec<_> = found
        .iter()
        .map(|m| (m.a, m.b, m.c, m.kind as u8))
        .collect();
    keys.sort_unstable();
    keys
}

fuzz_target!(|input: Input| {
    let points: Vec<(i64, i64)> = match input {
        Input::Grown(vertices) => {
            let point = |v: Vertex| (i64::from(v.0 % 17), i64::from(v.1 % 17));
            if vertices.len() < 3 {
                return;
            }
            let mut ring: Vec<(i64, i64)> = vertices[..3].iter().map(|&v| point(v)).collect();
            if valid(&ring).is_none() {
                return;
            }
            for &v in vertices[3..].iter().take(MAX - 3) {
                let at = usize::from(v.2) % ring.len() + 1;
                ring.insert(at, point(v));
                if valid(&ring).is_none() {
                    ring.remove(at);
                }
            }
            ring
        }
        Input::Comb { teeth, w, h } => {
            let (teeth, w, h) = (
                1 + i64::from(teeth % 80),
                1 + i64::from(w % 3),
                1 + i64::from(h % 9),
            );
            let mut ring = vec![(0, 0), (2 * w * teeth, 0)];
            for k in (0..teeth).rev() {
                let x = 2 * w * k;
                ring.extend([(x + 2 * w, 1), (x + w, 1), (x + w, 1 + h), (x, 1 + h)]);
            }
            ring
        }
        Input::Sliver { steps, w, h } => {
            let (steps, w, h) = (
                2 + i64::from(steps % 150),
                1 + i64::from(w % 3),
                1 + i64::from(h % 3),
            );
            let mut ring = vec![(0, 0), (steps * w, 1)];
            for k in 1..steps {
                ring.extend([
                    ((steps - k) * w, 1 + (k - 1) * h),
                    ((steps - k) * w, 1 + k * h),
                ]);
            }
            ring
        }
    };
    let Some(polygon) = valid(&points) else {
        return;
    };
    let swept = keys(&minimally_degenerate_by_sweep(&polygon));
    for policy in [RayPolicy::WalkOnly, RayPolicy::ShootOnly, RayPolicy::Hybrid] {
        let found = keys(&minimally_degenerate_with(&polygon, policy));
        assert_eq!(found, swept, "{policy:?} on {points:?}");
    }
});
