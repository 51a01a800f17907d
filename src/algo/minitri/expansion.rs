//! Visibility by triangular expansion: the vertices seen from a reflex vertex in its double cone.
//!
//! For Step 1 of MINITRI, a reflex vertex `b` matters only in the directions `d` such that both
//! `d` and `-d` lie in its closed interior angle: two closed cones `[next, -prev]` and
//! `[-next, prev]` (directions towards `b`'s neighbours and their opposites), each narrower than
//! a half-turn. In each, we need the vertices seen from `b` that are nearest in their direction.
//!
//! Method: triangular expansion over any triangulation of the polygon (F. Bungiu, M. Hemmer,
//! J. Hershberger, K. Huang, A. Kröller, "Efficient computation of visibility polygons",
//! EuroCG 2014). Around `b`, every triangle of its fan whose angle meets the cone hands the part
//! of the cone it covers through its far edge; a cone crossing an edge into the next triangle
//! either passes wholly to one side of that triangle's third vertex `x`, or `x` lies strictly
//! inside it: then `x` is seen from `b` along a segment crossing only diagonals (so along a chord
//! with no vertex inside it: `x` is the nearest vertex in its direction), and the cone splits at
//! `x`. Cones end at polygon edges. A vertex exactly on a cone's boundary ray lies behind the
//! vertex that defines that ray, so it is not the nearest one there and is skipped. The fan's own
//! vertices are seen along triangulation edges, so they are nearest in their directions too.
//!
//! Every decision is an exact sign of a cross product of two [`Dir`]s.
//! Complexity: proportional to the triangles met inside the cones: output-sensitive, O(n) per
//! vertex in the worst case, far less on typical polygons.

use crate::geom::kernel::{cmp_dir_from, Dir};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;
use std::collections::HashMap;

/// A cone of directions from `lo` counter-clockwise to `hi` (narrower than a half-turn); a bound
/// marked `_in` is not defined by a vertex, so a vertex exactly on it is seen.
#[derive(Clone, Copy, Debug)]
struct Cone {
    lo: Dir,
    hi: Dir,
    lo_in: bool,
    hi_in: bool,
}

/// A triangulation with neighbours, for walking.
pub struct Mesh {
    triangles: Vec<[usize; 3]>,
    /// `across[t][k]`: the triangle on the other side of edge `k` (`triangles[t][k] ->
    /// triangles[t][k+1]`), or `NONE` on the polygon boundary.
    across: Vec<[u32; 3]>,
    /// For each vertex, the triangle holding its edge to the next boundary vertex.
    first: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl Mesh {
    /// Builds the neighbour structure of counter-clockwise `triangles` of a polygon (holes allowed:
    /// the walks stop at every ring edge alike).
    pub fn new(polygon: &Polygon, triangles: Vec<[usize; 3]>) -> Mesh {
        let mut by_edge: HashMap<(usize, usize), u32> = HashMap::with_capacity(3 * triangles.len());
        for (t, tri) in triangles.iter().enumerate() {
            for k in 0..3 {
                by_edge.insert((tri[k], tri[(k + 1) % 3]), t as u32);
            }
        }
        let across = triangles
            .iter()
            .map(|tri| {
                let mut a = [NONE; 3];
                for (k, slot) in a.iter_mut().enumerate() {
                    *slot = by_edge
                        .get(&(tri[(k + 1) % 3], tri[k]))
                        .copied()
                        .unwrap_or(NONE);
                }
                a
            })
            .collect();
        let first = (0..polygon.len())
            .map(|v| by_edge.get(&(v, polygon.next(v))).copied().unwrap_or(NONE))
            .collect();
        Mesh {
            triangles,
            across,
            first,
        }
    }

    /// The vertex of triangle `t` opposite the directed edge `u -> w`, and the indices (within
    /// `t`) of its edges `u -> x` and `x -> w`.
    fn apex(&self, t: usize, u: usize) -> (usize, usize, usize) {
        let tri = self.triangles[t];
        let k = tri
            .iter()
            .position(|&v| v == u)
            .expect("edge vertex in its triangle");
        (tri[(k + 1) % 3], k, (k + 1) % 3)
    }
}

/// The vertices seen from reflex vertex `b` that are nearest in their direction, in the two
/// cones of its double wedge: `(cone [next, -prev], cone [-next, prev])`, each sorted by angle.
pub fn double_cone(polygon: &Polygon, mesh: &Mesh, b: usize) -> (Vec<usize>, Vec<usize>) {
    let c = polygon.point(b);
    let dir = |v: usize| Dir::between(c, polygon.point(v));
    let (to_next, to_prev) = (dir(polygon.next(b)), dir(polygon.prev(b)));
    // The bounds towards next(b) and prev(b) are defined by those vertices (anything behind them
    // is not nearest); the opposite bounds are not, so a vertex exactly on them counts.
    let cones = [
        Cone {
            lo: to_next,
            hi: to_prev.reversed(),
            lo_in: false,
            hi_in: true,
        },
        Cone {
            lo: to_next.reversed(),
            hi: to_prev,
            lo_in: true,
            hi_in: false,
        },
    ];
    let mut found: [Vec<usize>; 2] = [Vec::new(), Vec::new()];
    // The fan around b, counter-clockwise from the edge to next(b) to the edge from prev(b).
    let mut fan: Vec<(usize, usize, usize)> = Vec::new(); // (triangle, u, w): b, u, w CCW
    let mut t = mesh.first[b];
    while t != NONE {
        let tri = mesh.triangles[t as usize];
        let k = tri
            .iter()
            .position(|&v| v == b)
            .expect("fan triangle holds b");
        let (u, w) = (tri[(k + 1) % 3], tri[(k + 2) % 3]);
        fan.push((t as usize, u, w));
        t = mesh.across[t as usize][(k + 2) % 3]; // across the edge w -> b
    }
    // Directions around b compared by their angle from the direction of next(b).
    let cmp = |a: Dir, b: Dir| cmp_dir_from(to_next, a, b);
    for (side, cone) in cones.iter().enumerate() {
        // (triangle entered, w, u: the edge u -> w it was entered by, w on the left seen from
        // b, and the part of the cone passing through it)
        let mut stack: Vec<(usize, usize, usize, Cone)> = Vec::new();
        for &(t, u, w) in &fan {
            let (du, dw) = (dir(u), dir(w));
            for (v, d) in [(u, du), (w, dw)] {
                if cmp(cone.lo, d) != Ordering::Greater && cmp(d, cone.hi) != Ordering::Greater {
                    found[side].push(v);
                }
            }
            // The part of the cone inside this fan triangle's angle; a bound taken from u or w
            // is defined by a vertex.
            let (lo, lo_in) = if cmp(du, cone.lo) == Ordering::Less {
                (cone.lo, cone.lo_in)
            } else {
                (du, false)
            };
            let (hi, hi_in) = if cmp(dw, cone.hi) == Ordering::Greater {
                (cone.hi, cone.hi_in)
            } else {
                (dw, false)
            };
            if cmp(lo, hi) == Ordering::Less {
                let k = mesh.triangles[t]
                    .iter()
                    .position(|&v| v == u)
                    .expect("u in t");
                let next = mesh.across[t][k];
                if next != NONE {
                    stack.push((
                        next as usize,
                        w,
                        u,
                        Cone {
                            lo,
                            hi,
                            lo_in,
                            hi_in,
                        },
                    ));
                }
            }
        }
        while let Some((t, w, u, cone)) = stack.pop() {
            // The entered triangle has the directed edge w -> u; its apex x follows u.
            let (x, k_ux, k_xw) = mesh.apex(t, u);
            let dx = dir(x);
            let (right, left) = (cone.lo.cross(dx), dx.cross(cone.hi));
            let inside = (right > 0 || (right == 0 && cone.lo_in))
                && (left > 0 || (left == 0 && cone.hi_in));
            let mut go = |k: usize, new_w: usize, new_u: usize, part: Cone| {
                let next = mesh.across[t][k];
                if next != NONE && part.lo.cross(part.hi) > 0 {
                    stack.push((next as usize, new_w, new_u, part));
                }
            };
            if inside {
                found[side].push(x);
                go(
                    k_ux,
                    x,
                    u,
                    Cone {
                        hi: dx,
                        hi_in: false,
                        ..cone
                    },
                );
                go(
                    k_xw,
                    w,
                    x,
                    Cone {
                        lo: dx,
                        lo_in: false,
                        ..cone
                    },
                );
            } else if right <= 0 {
                go(k_xw, w, x, cone); // the whole cone passes right of x: through x -> w
            } else {
                go(k_ux, x, u, cone); // through u -> x
            }
        }
        let list = &mut found[side];
        list.sort_by(|&a, &b| cmp(dir(a), dir(b)).then(a.cmp(&b)));
        list.dedup();
    }
    let [first, second] = found;
    (first, second)
}
