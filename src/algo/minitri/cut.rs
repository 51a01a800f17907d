//! Steps 4 and 5 of MINITRI for polygons that may have holes: the chosen degenerate triangles
//! are cut into a plain triangulation, then each saves one triangle at its middle vertex.
//!
//! Chen & Chang (1990, §3, Steps 4-5) cut P along the chosen triangles into pieces and
//! triangulate each piece. With holes a piece may have holes, and a cut touching a hole at one
//! vertex makes a piece whose boundary visits that vertex twice, which no plain triangulator of
//! simple rings accepts. So here the same result is reached inside one triangulation:
//!
//! 1. Start from any plain triangulation of P (n + 2w - 2 triangles, every side an edge or a
//!    proper diagonal).
//! 2. Insert the sides `a b` and `b c` of every chosen triangle as edges: remove the triangles the
//!    segment crosses and triangulate the two polygons on its sides (the classic insertion of a
//!    constraint; de Berg et al., *Computational Geometry*, §9.3 / Anglada 1997). The count does
//!    not change: `v` vertices around the removed region, `v - 2` triangles before and after.
//!    A side has no vertex inside it (minimality) and chosen triangles never cross (they are
//!    independent), so the segment crosses diagonals only, and never an inserted side.
//! 3. For every chosen `(a, b, c)`, the triangles at `b` in its closed 180-degree half-plane
//!    form a fan whose union is a polygon `l_0, l_1, .., l_k` (star-shaped from `b`, with `b`
//!    inside its side `l_k l_0` on the line `a c`); retriangulating it without `b` turns `k`
//!    triangles into `k - 1`. No other chosen side enters the fan (an independent triangle
//!    ending at `b` does not reach into its 180-degree side), so the fans can be done one after
//!    another; a 3b-partner merged before only moves the fan's end along the line.
//!
//! The result has `n + 2w - 2 - d` nondegenerate triangles; the independent checker
//! ([`crate::verify`]) proves each output. Every decision is an exact orientation test.
//!
//! Complexity: each insertion costs the triangles its segment crosses plus their plain
//! retriangulation, O(n log n) at worst per segment; each fan, its size. Near-linear when the
//! chosen triangles are short, O(d n log n) at worst.

use super::degenerate::Degenerate;
use crate::algo::plain;
use crate::geom::kernel::{cross, Point};
use crate::geom::polygon::Polygon;
use std::collections::HashMap;

/// A triangulation under edits: triangles by index, and the triangle of every directed edge.
struct Mesh<'a> {
    polygon: &'a Polygon,
    triangles: Vec<[usize; 3]>,
    alive: Vec<bool>,
    by_edge: HashMap<(usize, usize), usize>,
    /// The triangles ever added at each vertex (dead ones included).
    at_vertex: Vec<Vec<usize>>,
}

impl<'a> Mesh<'a> {
    fn new(polygon: &'a Polygon, triangles: Vec<[usize; 3]>) -> Mesh<'a> {
        let mut mesh = Mesh {
            polygon,
            triangles: Vec::with_capacity(triangles.len()),
            alive: Vec::new(),
            by_edge: HashMap::with_capacity(3 * triangles.len()),
            at_vertex: vec![Vec::new(); polygon.len()],
        };
        for t in triangles {
            mesh.add(t);
        }
        mesh
    }

    fn point(&self, v: usize) -> Point {
        self.polygon.point(v)
    }

    fn add(&mut self, t: [usize; 3]) {
        let id = self.triangles.len();
        for k in 0..3 {
            self.by_edge.insert((t[k], t[(k + 1) % 3]), id);
            self.at_vertex[t[k]].push(id);
        }
        self.triangles.push(t);
        self.alive.push(true);
    }

    fn remove(&mut self, id: usize) {
        let t = self.triangles[id];
        for k in 0..3 {
            self.by_edge.remove(&(t[k], t[(k + 1) % 3]));
        }
        self.alive[id] = false;
    }

    /// The triangle holding the directed edge `u -> v`, as `(id, third vertex)`.
    fn across(&self, u: usize, v: usize) -> Option<(usize, usize)> {
        let &id = self.by_edge.get(&(u, v))?;
        let t = self.triangles[id];
        let k = t.iter().position(|&x| x == u)?;
        Some((id, t[(k + 2) % 3]))
    }

    /// Triangulates the counter-clockwise polygon `ring` (vertex indices) and adds the triangles.
    fn fill(&mut self, ring: &[usize]) {
        let points: Vec<Point> = ring.iter().map(|&v| self.point(v)).collect();
        for t in plain(&points) {
            self.add(t.map(|i| ring[i]));
        }
    }

    /// Makes the segment `s e` an edge. Contract: it is a chord with no vertex inside, crossing
    /// no edge that must stay.
    fn insert(&mut self, s: usize, e: usize) {
        if self.by_edge.contains_key(&(s, e)) || self.by_edge.contains_key(&(e, s)) {
            return;
        }
        let (ps, pe) = (self.point(s), self.point(e));
        // The triangle (s, x, y) at s whose angle holds the direction to e: rotate
        // counter-clockwise around s from its boundary edge to next(s).
        let mut x = self.polygon.next(s);
        let (mut id, mut y) = self.across(s, x).expect("a boundary edge has a triangle");
        while !(cross(ps, self.point(x), pe) > 0 && cross(ps, pe, self.point(y)) > 0) {
            x = y;
            (id, y) = self
                .across(s, x)
                .expect("the segment leaves s inside the polygon");
        }
        // Walk along s -> e: x on its right, y on its left.
        let mut removed = vec![id];
        let (mut right, mut left) = (vec![x], vec![y]);
        loop {
            let (next, z) = self
                .across(y, x)
                .expect("the segment crosses diagonals only");
            removed.push(next);
            if z == e {
                break;
            }
            if cross(ps, pe, self.point(z)) < 0 {
                right.push(z);
                x = z;
            } else {
                left.push(z);
                y = z;
            }
        }
        for id in removed {
            self.remove(id);
        }
        let mut upper = vec![s, e];
        upper.extend(left.iter().rev());
        let mut lower = vec![e, s];
        lower.extend(right);
        self.fill(&upper);
        self.fill(&lower);
    }

    /// Retriangulates the fan at `m.b` on its 180-degree side without `b` as a corner.
    ///
    /// The fan is taken as the triangles around `b` lying in the closed 180-degree half-plane,
    /// not as the triangles between the edges `b a` and `b c`: when a 3b-partner sharing `a b`
    /// was merged first, `b a` is no longer an edge there (the side through `a` and `b` now
    /// ends beyond `a`), yet the half-plane's fan is still bounded by the line.
    fn merge_fan(&mut self, m: &Degenerate) {
        let (pa, pc) = (self.point(m.a), self.point(m.c));
        let other_side = m.non_straight_side(self.polygon);
        let in_half_plane =
            |mesh: &Self, v: usize| cross(pa, pc, mesh.point(v)).signum() as i32 != other_side;
        // The live triangles (b, u, w) at b in the half-plane, chained by u -> w (they cannot be
        // walked by shared edges: an earlier merge may have left a T-junction at b's partner).
        let b = m.b;
        let mut fan: HashMap<usize, (usize, usize)> = HashMap::new(); // u -> (triangle, w)
        for &id in &self.at_vertex[b] {
            if !self.alive[id] {
                continue;
            }
            let t = self.triangles[id];
            let k = t.iter().position(|&v| v == b).expect("listed at b");
            let (u, w) = (t[(k + 1) % 3], t[(k + 2) % 3]);
            if in_half_plane(self, u) && in_half_plane(self, w) {
                fan.insert(u, (id, w));
            }
        }
        let ends: std::collections::HashSet<usize> = fan.values().map(|&(_, w)| w).collect();
        let mut at = *fan
            .keys()
            .find(|u| !ends.contains(u))
            .expect("the fan has a first triangle");
        let mut link = vec![at];
        while let Some(&(id, w)) = fan.get(&at) {
            self.remove(id);
            link.push(w);
            at = w;
        }
        self.fill(&link);
    }
}

/// The triangles of P with the chosen (independent) triangles cut in, starting from the plain
/// triangulation `base`: `base.len() - chosen.len()` triangles, counter-clockwise.
pub fn triangulate_with_cuts(
    polygon: &Polygon,
    base: Vec<[usize; 3]>,
    chosen: &[Degenerate],
) -> Vec<[usize; 3]> {
    let mut mesh = Mesh::new(polygon, base);
    for m in chosen {
        mesh.insert(m.a, m.b);
        mesh.insert(m.b, m.c);
    }
    for m in chosen {
        mesh.merge_fan(m);
    }
    mesh.triangles
        .iter()
        .zip(&mesh.alive)
        .filter(|(_, &alive)| alive)
        .map(|(t, _)| *t)
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::polygon;

    /// The stored index of the vertex at input coordinates `q`.
    fn vertex(p: &Polygon, q: (i64, i64)) -> usize {
        let text = format!("({}, {})", q.0, q.1);
        (0..p.len())
            .find(|&i| p.format_vertex(i) == text)
            .expect("a vertex there")
    }

    #[test]
    fn pinch_repro() {
        let (s, p, r, e, t) = ((-20, 0), (-10, -10), (10, -10), (20, 0), (0, 20));
        let (v, sv, q) = ((0, 10), (2, 2), (-2, 2));
        let poly = polygon(&[&[s, p, r, e, t], &[v, sv, q]]);
        let at = |x| vertex(&poly, x);
        let tris: Vec<[usize; 3]> = [
            [v, p, q],
            [p, r, q],
            [q, r, sv],
            [v, sv, r],
            [s, p, v],
            [r, e, v],
            [s, v, t],
            [v, e, t],
        ]
        .iter()
        .map(|t| t.map(at))
        .collect();
        let mut mesh = Mesh::new(&poly, tris);
        mesh.insert(at(s), at(e));
    }
}
