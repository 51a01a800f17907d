//! Steps 4 and 5 of MINITRI: cut P along the chosen triangles, triangulate each piece
//! (Chen & Chang 1990, §3, Steps 4-5).
//!
//! The chosen triangles' sides `a b` and `b c` are added to the polygon's edges (duplicates and
//! sides that are edges merged), and the faces of this plane graph are the pieces. Independent
//! triangles never cross, and their sides have no vertex inside (minimality), so every piece is a
//! simple polygon. On its 180-degree side a chosen middle vertex `b` is straight (its neighbours in
//! the piece are `a` and `c`, collinear with it): it is dropped from that piece, which then has the
//! side `a c` with `b` inside it, the T-junction that saves a triangle. Input flat vertices that
//! are not chosen middles stay, and the plain triangulation (`crate::algo::plain`) never makes a zero-area
//! triangle at them. Each piece with `n_i` vertices gives `n_i - 2` triangles, `n - 2 - d` in all.
//!
//! Complexity: O((n + K) log n) to build the graph and walk its faces, plus O(n_i log n_i) for
//! each piece (`crate::algo::plain`).

use super::degenerate::Degenerate;
use crate::algo::plain;
use crate::geom::kernel::{cmp_angle, cross, Point};
use crate::geom::polygon::Polygon;

/// The triangles of all pieces, in stored vertex indices, counter-clockwise.
pub fn triangulate_pieces(polygon: &Polygon, chosen: &[Degenerate]) -> Vec<[usize; 3]> {
    let n = polygon.len();
    // Undirected edges, deduplicated.
    let mut edges: Vec<(usize, usize)> = (0..n).map(|i| ordered(i, polygon.next(i))).collect();
    for m in chosen {
        edges.push(ordered(m.a, m.b));
        edges.push(ordered(m.b, m.c));
    }
    edges.sort_unstable();
    edges.dedup();
    // Neighbours of each vertex in counter-clockwise order.
    let mut around: Vec<Vec<usize>> = vec![Vec::new(); n];
    for &(u, v) in &edges {
        around[u].push(v);
        around[v].push(u);
    }
    for (v, list) in around.iter_mut().enumerate() {
        let c = polygon.point(v);
        list.sort_by(|&x, &y| cmp_angle(c, polygon.point(x), polygon.point(y)));
    }
    let straight_middle = {
        let mut middle = vec![false; n];
        for m in chosen {
            middle[m.b] = true;
        }
        middle
    };
    // Walk every face with its interior on the left: arriving at v from u, leave along the edge
    // just clockwise of v -> u.
    let mut used: std::collections::HashSet<(usize, usize)> = std::collections::HashSet::new();
    let mut triangles = Vec::with_capacity(n);
    for &(x, y) in &edges {
        for (start_u, start_v) in [(x, y), (y, x)] {
            if used.contains(&(start_u, start_v)) {
                continue;
            }
            let mut face = Vec::new();
            let (mut u, mut v) = (start_u, start_v);
            loop {
                used.insert((u, v));
                face.push(u);
                let list = &around[v];
                let back = list
                    .iter()
                    .position(|&w| w == u)
                    .expect("edge listed at both ends");
                let w = list[(back + list.len() - 1) % list.len()];
                (u, v) = (v, w);
                if (u, v) == (start_u, start_v) {
                    break;
                }
            }
            let points: Vec<Point> = face.iter().map(|&i| polygon.point(i)).collect();
            if twice_area(&points) <= 0 {
                continue; // the outer face
            }
            // Drop chosen middles where they are straight (their 180-degree side).
            let k = face.len();
            let keep: Vec<usize> = (0..k)
                .filter(|&i| {
                    let (p, q) = (points[(i + k - 1) % k], points[(i + 1) % k]);
                    !(straight_middle[face[i]] && cross(p, points[i], q) == 0)
                })
                .map(|i| face[i])
                .collect();
            let piece: Vec<Point> = keep.iter().map(|&i| polygon.point(i)).collect();
            triangles.extend(plain(&piece).into_iter().map(|t| t.map(|i| keep[i])));
        }
    }
    triangles
}

fn ordered(u: usize, v: usize) -> (usize, usize) {
    (u.min(v), u.max(v))
}

fn twice_area(points: &[Point]) -> i128 {
    (0..points.len())
        .map(|i| cross(points[0], points[i], points[(i + 1) % points.len()]))
        .sum()
}
