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
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cmp_angle, cross, Area};
use crate::geom::polygon::Polygon;

/// The longest face list kept for the next faces once the outer face has been walked.
const GIVE_BACK: usize = 1 << 12;

/// The triangles of all pieces, in stored vertex indices, counter-clockwise.
pub fn triangulate_pieces<P: Coord>(
    polygon: &Polygon<P>,
    chosen: &[Degenerate],
) -> Vec<[usize; 3]> {
    let n = polygon.len();
    // Undirected edges, deduplicated.
    let mut edges: Vec<(usize, usize)> = Vec::with_capacity(n + 2 * chosen.len());
    edges.extend((0..n).map(|i| ordered(i, polygon.next(i))));
    for m in chosen {
        edges.push(ordered(m.a, m.b));
        edges.push(ordered(m.b, m.c));
    }
    edges.sort_unstable();
    edges.dedup();
    let graph = Graph::new(polygon, &edges);
    drop(edges);
    let straight_middle = {
        let mut middle = vec![false; n];
        for m in chosen {
            middle[m.b] = true;
        }
        middle
    };
    // Walk every face with its interior on the left: arriving at v from u, leave along the edge
    // just clockwise of v -> u. Each directed edge (a slot of `graph`) is walked once.
    let mut used = vec![false; graph.to.len()];
    let mut triangles = Vec::with_capacity(n);
    let (mut face, mut keep, mut piece) = (Vec::new(), Vec::new(), Vec::new());
    for start in 0..graph.to.len() {
        if used[start] {
            continue;
        }
        face.clear();
        let mut slot = start;
        while !used[slot] {
            used[slot] = true;
            face.push(graph.from[slot]);
            slot = graph.turn(slot);
        }
        let point = |i: usize| polygon.point(face[i]);
        let k = face.len();
        let mut area = Area::default();
        for i in 0..k {
            area.add(point(0), point(i), point((i + 1) % k));
        }
        if area.signum() <= 0 {
            // The outer face (clockwise; the area sum cannot overflow): it runs along the whole
            // boundary, the longest list of all, so on a large polygon its room is given back
            // right away (on a small one, it is kept for the pieces).
            if face.capacity() > GIVE_BACK {
                face = Vec::new();
            }
            continue;
        }
        // Drop chosen middles where they are straight (their 180-degree side).
        keep.clear();
        keep.extend((0..k).filter_map(|i| {
            let (p, q) = (point((i + k - 1) % k), point((i + 1) % k));
            let straight = straight_middle[face[i]] && cross(p, point(i), q) == 0;
            (!straight).then_some(face[i])
        }));
        if let [a, b, c] = keep[..] {
            triangles.push([a, b, c]); // already a triangle (of positive area: a piece)
            continue;
        }
        piece.clear();
        piece.extend(keep.iter().map(|&i| polygon.point(i)));
        triangles.extend(plain(&piece).into_iter().map(|t| t.map(|i| keep[i])));
    }
    triangles
}

/// The plane graph of the polygon's edges and the chosen sides, as adjacency arrays: the
/// directed edges leaving vertex `v` are the slots `start[v]..start[v + 1]`, sorted
/// counter-clockwise around `v`; slot `s` runs `from[s] -> to[s]`.
struct Graph {
    start: Vec<usize>,
    from: Vec<usize>,
    to: Vec<usize>,
}

impl Graph {
    fn new<P: Coord>(polygon: &Polygon<P>, edges: &[(usize, usize)]) -> Graph {
        let n = polygon.len();
        let mut start = vec![0; n + 1];
        for &(u, v) in edges {
            start[u + 1] += 1;
            start[v + 1] += 1;
        }
        for v in 0..n {
            start[v + 1] += start[v];
        }
        let mut fill = start.clone();
        let mut to = vec![0; 2 * edges.len()];
        let mut from = vec![0; 2 * edges.len()];
        for &(u, v) in edges {
            for (x, y) in [(u, v), (v, u)] {
                to[fill[x]] = y;
                from[fill[x]] = x;
                fill[x] += 1;
            }
        }
        for v in 0..n {
            let c = polygon.point(v);
            to[start[v]..start[v + 1]]
                .sort_by(|&x, &y| cmp_angle(c, polygon.point(x), polygon.point(y)));
        }
        Graph { start, from, to }
    }

    /// The slot after `slot` (`u -> v`) along its face: `v -> w` with `w` just clockwise of `u`
    /// around `v`.
    fn turn(&self, slot: usize) -> usize {
        let (u, v) = (self.from[slot], self.to[slot]);
        let (lo, hi) = (self.start[v], self.start[v + 1]);
        let back = (lo..hi)
            .find(|&s| self.to[s] == u)
            .expect("every edge is listed at both ends");
        if back == lo {
            hi - 1
        } else {
            back - 1
        }
    }
}

fn ordered(u: usize, v: usize) -> (usize, usize) {
    (u.min(v), u.max(v))
}
