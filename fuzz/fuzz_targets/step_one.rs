//! Step 1 of MINITRI (all minimally degenerate triangles) whatever the ray policy and the walk's
//! budget: the set of triangles, kinds included, found with every ray walked, every ray shot
//! over heavy paths (`minitri::algo::minitri::ray_shooting`), the default hybrid, and the
//! bounded method alone (budget 0: balanced cuts and shortest-path trees,
//! `minitri::algo::minitri::polygon_cutting`) must equal the angular sweep's
//! (`minimally_degenerate_by_sweep`).
//!
//! Inputs: a ring grown point by point on the grid 0..=16 (each point inserted after the vertex
//! its third byte names, kept only when the polygon stays valid, as in the `core` target), up to
//! `MAX` vertices; or, by the first byte, a comb of teeth of given widths, gaps and heights over
//! gap floors on one line, or a staircase of given steps over one long edge (a sliver): the
//! polygons whose long rays the shooter is for, of up to a few hundred vertices.
#![no_main]
use arbitrary::Arbitrary;
use libfuzzer_sys::fuzz_target;
use minitri::algo::minitri::degenerate::check_ray_policies;
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
    /// Per tooth: its width, the gap after it, its height (each taken modulo 4, plus 1).
    Comb(Vec<(u8, u8, u8)>),
    /// Per step: how far left and how far up (each taken modulo 3, plus 1).
    Staircase(Vec<(u8, u8)>),
}

fn valid(points: &[(i64, i64)]) -> Option<Polygon> {
    let raw = RawPolygon {
        rings: vec![ring(points)],
        ..Default::default()
    };
    Polygon::from_raw_all_errors(&raw).ok().map(|(p, _)| p)
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
        Input::Comb(teeth) => {
            // Teeth from right to left above the floor line y = 1, over a base down to y = 0.
            let size = |v: u8| 1 + i64::from(v % 4);
            let teeth = &teeth[..teeth.len().min(100)];
            let width: i64 = teeth.iter().map(|&(w, g, _)| size(w) + size(g)).sum();
            let mut ring = vec![(0, 0), (width, 0)];
            let mut x = width;
            for &(w, g, h) in teeth {
                ring.extend([
                    (x, 1 + size(h)),
                    (x - size(w), 1 + size(h)),
                    (x - size(w), 1),
                ]);
                x -= size(w) + size(g);
                ring.push((x, 1));
            }
            ring
        }
        Input::Staircase(steps) => {
            // From (width, 1) left and up, step by step, over the edge from the origin.
            let size = |v: u8| 1 + i64::from(v % 3);
            let steps = &steps[..steps.len().min(150)];
            let width: i64 = steps.iter().map(|&(l, _)| size(l)).sum();
            let (mut x, mut y) = (width, 1);
            let mut ring = vec![(0, 0), (x, y)];
            for &(left, up) in steps.iter().take(steps.len().saturating_sub(1)) {
                x -= size(left);
                ring.push((x, y));
                y += size(up);
                ring.push((x, y));
            }
            ring
        }
    };
    let Some(polygon) = valid(&points) else {
        return;
    };
    if let Err(e) = check_ray_policies(&polygon) {
        panic!("{e} on {points:?}");
    }
});
