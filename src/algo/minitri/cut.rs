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
//! 2. Insert the sides `a b` and `b c` of every chosen triangle as edges by flips
//!    (`algo/mesh.rs`; Sloan, "A fast algorithm for generating constrained Delaunay
//!    triangulations", *Computers & Structures* 47 (1993) 441-450): walk along the segment
//!    listing the diagonals it crosses, flip those whose quadrilateral is strictly convex until
//!    the segment is an edge; it is then fixed. A flip keeps the count of triangles. A side has
//!    no vertex inside it (minimality) and chosen triangles never cross (they are independent),
//!    so the segment crosses diagonals only, and never a side inserted before. (Removing the
//!    crossed triangles and triangulating the two sides again does not do: the triangles
//!    crossed on one side can go round a hole and touch at a vertex; see the tests.)
//! 3. For every chosen `(a, b, c)`, the triangles at `b` in its closed 180-degree half-plane
//!    form a fan whose union is a polygon `l_0, l_1, .., l_k` (star-shaped from `b`, with `b`
//!    inside its side `l_k l_0` on the line `a c`); retriangulating it without `b` turns `k`
//!    triangles into `k - 1`. No other chosen side enters the fan (an independent triangle
//!    ending at `b` does not reach into its 180-degree side), so the fans can be done one after
//!    another; a 3b-partner merged before only moves the fan's end along the line.
//!
//! The result has `n + 2w - 2 - d` nondegenerate triangles; the independent checker
//! ([`crate::verify`]) proves each output. Every decision is an exact orientation test. What
//! the argument above rules out is still checked (a side through a vertex or across a fixed
//! edge, stuck flips, a fan that is not a chain): should a check fail, the polygon gets
//! [`TriangulateError::MinitriCutFailed`], never a panic or a wrong answer.
//!
//! Complexity: O(m log m) to build the mesh of the m = n + 2w - 2 triangles; an insertion whose
//! segment crosses k diagonals, O(k) when each flip can leave one crossing fewer (almost always)
//! and O(k^2) at worst (`algo/mesh.rs`); each fan, its size (its polygon triangulated by
//! `crate::algo::plain::rings`). Near-linear when the chosen triangles are short, O(d n^2) at worst
//! (measured against the removal of crossed triangles it replaced: docs/benchmarks.md).

use super::degenerate::Degenerate;
use crate::algo::mesh::Constrained;
use crate::algo::{plain, TriangulateError};
use crate::geom::kernel::cross;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;
use std::collections::{HashMap, HashSet};

/// The triangulation of step 3 under edits: triangles by index, alive or removed, and the
/// triangles ever added at each vertex (removed ones included). No neighbour links: a merged
/// fan leaves a T-junction at its middle vertex, which edge-to-edge meshes cannot hold.
struct Fans<'a, P: Coord> {
    polygon: &'a Polygon<P>,
    triangles: Vec<[usize; 3]>,
    alive: Vec<bool>,
    at_vertex: Vec<Vec<usize>>,
}

impl<'a, P: Coord> Fans<'a, P> {
    fn new(polygon: &'a Polygon<P>, triangles: impl Iterator<Item = [usize; 3]>) -> Fans<'a, P> {
        let mut fans = Fans {
            polygon,
            triangles: Vec::new(),
            alive: Vec::new(),
            at_vertex: vec![Vec::new(); polygon.len()],
        };
        for t in triangles {
            fans.add(t);
        }
        fans
    }

    fn point(&self, v: usize) -> P {
        self.polygon.point(v)
    }

    fn add(&mut self, t: [usize; 3]) {
        let id = self.triangles.len();
        for v in t {
            self.at_vertex[v].push(id);
        }
        self.triangles.push(t);
        self.alive.push(true);
    }

    /// Retriangulates the fan at `m.b` on its 180-degree side without `b` as a corner; `None`
    /// if the triangles there do not chain into one fan (excluded by the module's argument).
    ///
    /// The fan is taken as the triangles around `b` lying in the closed 180-degree half-plane,
    /// not as the triangles between the edges `b a` and `b c`: when a 3b-partner sharing `a b`
    /// was merged first, `b a` is no longer an edge there (the side through `a` and `b` now
    /// ends beyond `a`), yet the half-plane's fan is still bounded by the line.
    fn merge(&mut self, m: &Degenerate) -> Option<()> {
        let (pa, pc) = (self.point(m.a), self.point(m.c));
        let other_side = m.non_straight_side(self.polygon);
        let in_half_plane =
            |fans: &Self, v: usize| cross(pa, pc, fans.point(v)).signum() as i32 != other_side;
        // The live triangles (b, u, w) at b in the half-plane, chained by u -> w (they cannot be
        // walked by shared edges: an earlier merge may have left a T-junction at b's partner).
        let b = m.b;
        let mut fan: HashMap<usize, (usize, usize)> = HashMap::new(); // u -> (triangle, w)
        for &id in &self.at_vertex[b] {
            if !self.alive[id] {
                continue;
            }
            let t = self.triangles[id];
            let k = t.iter().position(|&v| v == b)?;
            let (u, w) = (t[(k + 1) % 3], t[(k + 2) % 3]);
            if in_half_plane(self, u) && in_half_plane(self, w) && fan.insert(u, (id, w)).is_some()
            {
                return None; // two triangles from one edge
            }
        }
        let ends: HashSet<usize> = fan.values().map(|&(_, w)| w).collect();
        let mut at = *fan.keys().find(|u| !ends.contains(u))?;
        let mut link = vec![at];
        while let Some((id, w)) = fan.remove(&at) {
            self.alive[id] = false;
            link.push(w);
            at = w;
        }
        // One chain of at least two triangles from the line a c round to it again: the link is
        // then a simple polygon, star-shaped from b on its side `l_k l_0`.
        let on_line = |v: usize| cross(pa, pc, self.point(v)) == 0;
        if !fan.is_empty() || link.len() < 3 || !on_line(link[0]) || !on_line(at) {
            return None;
        }
        let points: Vec<P> = link.iter().map(|&v| self.point(v)).collect();
        for t in plain::rings(&points, &[0]) {
            self.add(t.map(|i| link[i]));
        }
        Some(())
    }
}

/// The triangles of P with the chosen (independent) triangles cut in, starting from the plain
/// triangulation `base`: `base.len() - chosen.len()` triangles, counter-clockwise.
///
/// # Errors
/// [`TriangulateError::MinitriCutFailed`] if a self-check fails (see the module docs; not seen
/// in the tests).
pub fn triangulate_with_cuts<P: Coord>(
    polygon: &Polygon<P>,
    base: Vec<[usize; 3]>,
    chosen: &[Degenerate],
) -> Result<Vec<[usize; 3]>, TriangulateError> {
    let failed = |step: &'static str, m: &Degenerate| TriangulateError::MinitriCutFailed {
        step,
        vertex: polygon.id(m.b),
        point: polygon.format_vertex(m.b),
    };
    let mut mesh = Constrained::new(polygon.points(), &base, &[]);
    drop(base);
    for m in chosen {
        mesh.insert(m.a, m.b)
            .and_then(|()| mesh.insert(m.b, m.c))
            .map_err(|_| failed("inserting the sides", m))?;
    }
    let mut fans = Fans::new(polygon, mesh.triangles());
    drop(mesh);
    for m in chosen {
        fans.merge(m).ok_or_else(|| failed("merging the fan", m))?;
    }
    Ok(fans
        .triangles
        .iter()
        .zip(&fans.alive)
        .filter(|(_, &alive)| alive)
        .map(|(t, _)| *t)
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::minitri::degenerate::Kind;
    use crate::algo::{Algorithm, Triangulation};
    use crate::test_support::{pinched_round_a_hole, vertex_at};

    fn checked(polygon: &Polygon, triangles: Vec<[usize; 3]>, degenerate: Vec<[usize; 3]>) {
        let t = Triangulation {
            algorithm: Algorithm::Minitri,
            triangles,
            degenerate,
            optimal: false,
            lower_bound: None,
            stopped: None,
        };
        let report = crate::verify::check(polygon, &t);
        assert!(report.valid, "{:?}: {:?}", t.triangles, report.problems);
    }

    /// The side `S E` of the chosen triangle `(S, E, C)` crosses triangles that go round the
    /// hole and meet at its vertex `v` twice (see [`pinched_round_a_hole`]). Removing them and
    /// triangulating the polygon left above the side, `S E v s q v`, which touches itself at
    /// `v` (the insertion used before), panicked in ear clipping ("no ear in a valid
    /// polygon"); flips insert it, and the fan at `E` then saves one triangle.
    #[test]
    fn a_side_whose_crossed_triangles_pinch_round_a_hole_is_cut_in() {
        let (poly, base) = pinched_round_a_hole();
        checked(&poly, base.clone(), Vec::new());
        let at = |x| vertex_at(&poly, x);
        let (s, e, c) = (at((-20, 0)), at((20, 0)), at((40, 0)));
        let chosen = Degenerate {
            a: s.min(c),
            b: e,
            c: s.max(c),
            kind: Kind::TypeI,
        };
        let cut = triangulate_with_cuts(&poly, base.clone(), &[chosen]).unwrap();
        assert_eq!(cut.len(), base.len() - 1);
        let has_edge = |u: usize, v: usize| {
            cut.iter()
                .any(|t| (0..3).any(|k| (t[k], t[(k + 1) % 3]) == (u, v)))
        };
        assert!(has_edge(s, e) || has_edge(e, s), "the side S E is an edge");
        checked(&poly, cut, vec![[chosen.a, chosen.b, chosen.c]]);
    }
}
