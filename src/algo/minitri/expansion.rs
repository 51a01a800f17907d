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
//! Only opposite pairs of directions matter to Step 1, so the two cones are expanded together,
//! both sweeping from their upper bound down (a depth-first walk that always continues with the
//! highest part of a cone, turning the other cone by a half-turn to compare): directions above a
//! cone's highest pending part are settled, so a part of the other cone whose opposite directions
//! are all settled and hold no vertex found there is dropped, and a part reaching above the other
//! cone's highest pending part is cut down to it. In general position almost no direction has a
//! vertex on both sides, so most of the wide cone never needs walking.
//!
//! The walk runs over the plain triangulation made fatter by edge flips towards the constrained
//! Delaunay triangulation ([`Mesh::flip_towards_delaunay`]): rays then cross far fewer triangles
//! than the long slivers of a monotone triangulation.
//!
//! Every decision is an exact sign of a cross product of two [`Dir`]s; the only floating point
//! (which diagonals to flip) affects the running time, never what is found.
//! Complexity: O(n log n) to build the mesh, at most `max_flips` O(1) flips, then per vertex work
//! proportional to the triangles met by the parts of its cones still alive (each with an
//! O(log n) pruning test): O(n) per vertex, so O(n^2) in the worst case, but far less on typical
//! polygons. Measured on random star polygons (the `bench/polygon.py star` family), after the
//! flips: about 37 states per vertex at 10^4 vertices, 42 at 10^5, 48 at 10^6 (before the flips
//! and the pairing of the cones: 210 at 10^4, 560 at 10^5); on the `bars` family (a corridor
//! the length of the polygon, Theta(n^2) visible pairs), about 10 states per vertex on the mesh
//! swept along the corridor (`crate::algo::plain_polygon_for_walking`).

use crate::algo::mesh::twin_halves;
use crate::geom::kernel::{cmp_dir_from, cross, incircle_approx, Dir};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;

/// A cone of directions from `lo` counter-clockwise to `hi` (narrower than a half-turn); a bound
/// marked `_in` is not defined by a vertex, so a vertex exactly on it is seen.
#[derive(Clone, Copy, Debug)]
struct Cone {
    lo: Dir,
    hi: Dir,
    lo_in: bool,
    hi_in: bool,
}

/// A triangulation of a polygon without holes with neighbours, for walking.
///
/// Invariants: `triangles` are counter-clockwise with positive area, disjoint interiors, covering
/// the polygon, every side a polygon edge or a proper diagonal. Half-edge `3 t + k` is the side
/// `triangles[t][k] -> triangles[t][(k + 1) % 3]`; `twin` maps it to the same side seen from the
/// neighbouring triangle (`NONE` exactly on the polygon boundary).
pub struct Mesh {
    triangles: Vec<[usize; 3]>,
    twin: Vec<u32>,
    /// For each vertex `v`, the half-edge `v -> next(v)` (a boundary side).
    first: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl Mesh {
    /// Builds the neighbour structure of counter-clockwise `triangles` of a polygon, holes allowed
    /// (a plain triangulation: n + 2w - 2 triangles, sides ring edges or proper diagonals; the
    /// walks stop at every ring edge alike).
    ///
    /// # Panics
    /// If the triangles do not share their sides as a triangulation of `polygon` does.
    pub fn new(polygon: &Polygon, triangles: Vec<[usize; 3]>) -> Mesh {
        let twin = twin_halves(polygon.len(), triangles.len(), |t, k| triangles[t][k]);
        let mut mesh = Mesh {
            triangles,
            twin,
            first: Vec::new(),
        };
        mesh.find_boundary(polygon);
        mesh
    }

    /// Sets `first` from the boundary half-edges.
    fn find_boundary(&mut self, polygon: &Polygon) {
        self.first = vec![NONE; polygon.len()];
        for (h, &g) in self.twin.iter().enumerate() {
            if g == NONE {
                let v = self.tail(h);
                assert_eq!(self.head(h), polygon.next(v), "a boundary side is an edge");
                self.first[v] = h as u32;
            }
        }
        assert!(
            !self.first.contains(&NONE),
            "every polygon edge is a triangle side"
        );
    }

    /// Panics unless the neighbour structure is consistent: twins are mutual and join the same
    /// two vertices in opposite directions, and `first` holds each vertex's boundary edge.
    #[cfg(test)]
    pub fn check_invariants(&self, polygon: &Polygon) {
        assert_eq!(self.twin.len(), 3 * self.triangles.len());
        for (h, &g) in self.twin.iter().enumerate() {
            if g != NONE {
                let g = g as usize;
                assert_eq!(self.twin[g] as usize, h, "twins are mutual");
                assert_eq!((self.tail(g), self.head(g)), (self.head(h), self.tail(h)));
            }
        }
        for (v, &h) in self.first.iter().enumerate() {
            let h = h as usize;
            assert_eq!((self.tail(h), self.head(h)), (v, polygon.next(v)));
            assert_eq!(self.twin[h], NONE);
        }
    }

    /// The triangles (counter-clockwise, as stored vertex indices).
    pub fn triangles(&self) -> &[[usize; 3]] {
        &self.triangles
    }

    /// The triangles, giving up the neighbour structure.
    pub fn into_triangles(self) -> Vec<[usize; 3]> {
        self.triangles
    }

    /// The vertex a half-edge starts from.
    #[inline]
    fn tail(&self, h: usize) -> usize {
        self.triangles[h / 3][h % 3]
    }

    /// The vertex a half-edge ends at.
    #[inline]
    fn head(&self, h: usize) -> usize {
        self.triangles[h / 3][(h + 1) % 3]
    }

    /// The vertex of a half-edge's triangle opposite it.
    #[inline]
    fn apex(&self, h: usize) -> usize {
        self.triangles[h / 3][(h + 2) % 3]
    }

    /// The next half-edge of the same triangle (counter-clockwise).
    #[inline]
    fn next_in_triangle(h: usize) -> usize {
        if h % 3 == 2 {
            h - 2
        } else {
            h + 1
        }
    }

    /// Fattens the triangles for walking, by Lawson's edge flips towards the constrained Delaunay
    /// triangulation (polygon edges are never flipped); returns the number of flips made.
    ///
    /// A flip replaces the diagonal `a b` of triangles `a b c` and `b a d` by `c d`. Whether it is
    /// ALLOWED is decided exactly: only when the quadrilateral `a d b c` is strictly convex
    /// (`c a d` and `d b c` counter-clockwise, exact [`cross`] signs), so the result is again a
    /// triangulation of the polygon with positive triangles whose sides are edges or proper
    /// diagonals (the new diagonal runs inside the open quadrilateral, which holds no vertex).
    /// Whether it is DESIRABLE (`d` inside the circle through `a b c`) is decided in floating
    /// point ([`incircle_approx`]): a wrong answer only makes the triangles a little less fat,
    /// hence walking a little slower, and never changes what the walk finds, which is correct
    /// over any triangulation. Since inexact answers could make flips cycle, at most `max_flips`
    /// are made.
    pub fn flip_towards_delaunay(&mut self, polygon: &Polygon, max_flips: usize) -> usize {
        let p = |v: usize| polygon.point(v);
        let mut stack: Vec<u32> = (0..self.twin.len() as u32)
            .filter(|&h| self.twin[h as usize] != NONE && h < self.twin[h as usize])
            .collect();
        let mut flips = 0;
        while let Some(h) = stack.pop() {
            if flips == max_flips {
                break;
            }
            let h = h as usize;
            let g = self.twin[h];
            if g == NONE {
                continue; // an entry made stale by earlier flips, now a boundary side
            }
            let g = g as usize;
            let (a, b, c, d) = (self.tail(h), self.head(h), self.apex(h), self.apex(g));
            if cross(p(c), p(a), p(d)) <= 0 || cross(p(d), p(b), p(c)) <= 0 {
                continue; // not strictly convex: the flip is not allowed
            }
            if incircle_approx(p(a), p(b), p(c), p(d)) <= 0.0 {
                continue; // not (as far as floating point tells) an improvement
            }
            let (t, s) = (h / 3, g / 3);
            let twin = |x: usize| self.twin[x];
            let (e_bc, e_ca) = (
                twin(Self::next_in_triangle(h)),
                twin(Self::next_in_triangle(Self::next_in_triangle(h))),
            );
            let (e_ad, e_db) = (
                twin(Self::next_in_triangle(g)),
                twin(Self::next_in_triangle(Self::next_in_triangle(g))),
            );
            self.triangles[t] = [c, a, d];
            self.triangles[s] = [d, b, c];
            let links = [
                (3 * t, e_ca),
                (3 * t + 1, e_ad),
                (3 * t + 2, (3 * s + 2) as u32),
                (3 * s, e_db),
                (3 * s + 1, e_bc),
                (3 * s + 2, (3 * t + 2) as u32),
            ];
            for (x, y) in links {
                self.twin[x] = y;
                if y != NONE {
                    self.twin[y as usize] = x as u32;
                }
            }
            stack.extend([3 * t, 3 * t + 1, 3 * s, 3 * s + 1].map(|x| x as u32));
            flips += 1;
        }
        self.find_boundary(polygon);
        flips
    }
}

/// A vertex seen from the searching vertex `b`, with its direction from `b`.
pub type Sighting = (Dir, usize);

/// What a part of a cone on the stack stands for.
#[derive(Clone, Copy, Debug)]
enum Step {
    /// Enter the triangle of this half-edge `w -> u` (`w` on the left seen from `b`).
    Enter(usize),
    /// Record this vertex, found in the direction of the (zero-width) part.
    Found(usize),
}

/// Reusable buffers for [`double_cone`], so that searching from many vertices allocates once.
#[derive(Default)]
pub struct Workspace {
    /// Half-edges `b -> u` of the fan around `b`.
    fan: Vec<usize>,
    /// Per cone: the parts still to expand, disjoint and sorted by angle (the highest on top),
    /// each with what to do with it.
    stacks: [Vec<(Step, Cone)>; 2],
    /// Per cone: the vertices found with their directions from `b`, first those of the fan (by
    /// increasing angle), then those found by walking (by decreasing angle); merged into one
    /// list by angle at the end.
    found: [Vec<Sighting>; 2],
    /// The merged list of one cone.
    merged: Vec<Sighting>,
}

/// The vertices seen from reflex vertex `b` that are nearest in their direction, in the two
/// cones of its double wedge: `(cone [next, -prev], cone [-next, prev])`, each sorted by angle,
/// with their directions from `b`.
///
/// Only directions `d` whose opposite `-d` is found in the other cone matter to the caller, so
/// the lists may omit other vertices: the two cones sweep down together (see the module doc),
/// and a part of one cone is dropped as soon as no direction in it (its ends counted only where
/// they belong to it) has its opposite in a pending part of the other cone or at a vertex found
/// there. On polygons where one side of `b` is a narrow pocket, this turns the expansion of the
/// wide side into a few ray walks. An end that belongs to a part is one not defined by a vertex:
/// a part bounded by the ray through a vertex `x` (beyond `x`) cannot find anything on that ray,
/// and counting that ray would keep alive, all along a corridor, a part hugging a wall whose
/// vertex opposite is `b`'s own neighbour (the `bars` benchmark: 9.5 million states for 13,000
/// vertices, 7 million once ends were exact, 136,000 on the mesh swept along the corridor).
pub fn double_cone<'w>(
    polygon: &Polygon,
    mesh: &Mesh,
    b: usize,
    work: &'w mut Workspace,
) -> (&'w [Sighting], &'w [Sighting]) {
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
    let Workspace {
        fan,
        stacks,
        found,
        merged,
    } = work;
    // The fan around b, counter-clockwise from the edge to next(b) to the edge from prev(b).
    fan.clear();
    let mut h = mesh.first[b] as usize;
    loop {
        fan.push(h);
        // Across the side w -> b; its twin is b -> w in the next triangle of the fan.
        match mesh.twin[Mesh::next_in_triangle(Mesh::next_in_triangle(h))] {
            NONE => break,
            g => h = g as usize,
        }
    }
    // Directions around b compared by their angle from the direction of next(b); inside either
    // cone this is the order by angle.
    let cmp = |a: Dir, b: Dir| cmp_dir_from(to_next, a, b);
    for (side, cone) in cones.iter().enumerate() {
        found[side].clear();
        stacks[side].clear();
        for &h in fan.iter() {
            let (u, w) = (mesh.head(h), mesh.apex(h));
            let (du, dw) = (dir(u), dir(w));
            for (v, d) in [(u, du), (w, dw)] {
                if cmp(cone.lo, d) != Ordering::Greater && cmp(d, cone.hi) != Ordering::Greater {
                    found[side].push((d, v));
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
                let next = mesh.twin[Mesh::next_in_triangle(h)];
                if next != NONE {
                    stacks[side].push((
                        Step::Enter(next as usize),
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
    }
    // Whether a vertex found so far in cone `side` lies in the range from `lo` to `hi` (inside
    // the cone; each end included when its flag says so). Inside one cone, narrower than a
    // half-turn, the sign of a cross product orders directions by angle; the fan's vertices come
    // first, by increasing angle, then the others, by decreasing angle (recorded by markers, see
    // below).
    let fan_found = [found[0].len(), found[1].len()];
    let any_found = |found: &[Vec<Sighting>; 2], side: usize, range: Cone| {
        let (fan_part, walk_part) = found[side].split_at(fan_found[side]);
        let above_lo = |d: Dir| range.lo.cross(d) > 0 || (range.lo_in && range.lo.cross(d) == 0);
        let below_hi = |d: Dir| d.cross(range.hi) > 0 || (range.hi_in && d.cross(range.hi) == 0);
        let i = fan_part.partition_point(|&(d, _)| !above_lo(d));
        let j = walk_part.partition_point(|&(d, _)| !below_hi(d));
        (i < fan_part.len() && below_hi(fan_part[i].0))
            || (j < walk_part.len() && above_lo(walk_part[j].0))
    };
    loop {
        // Both stacks hold disjoint parts sorted by angle, the highest on top, and only parts
        // on a stack can still find vertices: every direction of a cone above its top part is
        // settled. Expand the cone whose top part reaches higher (comparing the other cone's
        // directions turned by a half-turn), so that both sweep down together.
        let side = match (stacks[0].last(), stacks[1].last()) {
            (None, None) => break,
            (Some(_), None) => 0,
            (None, Some(_)) => 1,
            (Some(s), Some(t)) => usize::from(s.1.hi.cross(t.1.hi.reversed()) > 0),
        };
        let (step, mut cone) = stacks[side].pop().expect("the chosen cone has a part");
        // A direction matters only if its opposite may still be found in the other cone: in a
        // part on the other stack (sorted by angle, lowest first), or at a vertex found there.
        let other = 1 - side;
        let opposite = Cone {
            lo: cone.lo.reversed(),
            hi: cone.hi.reversed(),
            ..cone
        };
        let parts = &stacks[other];
        // The other cone's parts that reach into the opposite range: disjoint and sorted, so
        // the first not wholly below it is the only candidate (an end shared by two ranges is
        // common to them only if both include it).
        let i = parts.partition_point(|(_, part)| {
            let c = opposite.lo.cross(part.hi);
            c < 0 || (c == 0 && !(opposite.lo_in && part.hi_in))
        });
        let open = i < parts.len() && {
            let c = parts[i].1.lo.cross(opposite.hi);
            c > 0 || (c == 0 && opposite.hi_in && parts[i].1.lo_in)
        };
        if !open && !any_found(found, other, opposite) {
            continue;
        }
        // Above the other cone's top part, only the directions of vertices found there matter:
        // if there are none, the part narrows down to that top part's upper bound (a bound not
        // defined by a vertex, strictly inside the part).
        if let Some(top) = parts.last() {
            let f = top.1.hi.reversed();
            if cone.lo.cross(f) > 0
                && f.cross(cone.hi) > 0
                && !any_found(
                    found,
                    other,
                    Cone {
                        lo: top.1.hi,
                        lo_in: true,
                        ..opposite
                    },
                )
            {
                cone.hi = f;
                cone.hi_in = true;
            }
        }
        let g = match step {
            Step::Found(x) => {
                found[side].push((cone.lo, x));
                continue;
            }
            Step::Enter(g) => g,
        };
        // The entered triangle has the half-edge g = w -> u; its apex x follows u.
        let x = mesh.apex(g);
        let k_ux = Mesh::next_in_triangle(g);
        let k_xw = Mesh::next_in_triangle(k_ux);
        let dx = dir(x);
        let (right, left) = (cone.lo.cross(dx), dx.cross(cone.hi));
        let inside =
            (right > 0 || (right == 0 && cone.lo_in)) && (left > 0 || (left == 0 && cone.hi_in));
        let stack = &mut stacks[side];
        if inside {
            enter(
                stack,
                mesh,
                k_ux,
                Cone {
                    hi: dx,
                    hi_in: false,
                    ..cone
                },
            );
            // x is recorded once every direction above it is settled: by a zero-width part
            // between the two halves.
            stack.push((
                Step::Found(x),
                Cone {
                    lo: dx,
                    hi: dx,
                    lo_in: true,
                    hi_in: true,
                },
            ));
            enter(
                stack,
                mesh,
                k_xw,
                Cone {
                    lo: dx,
                    lo_in: false,
                    ..cone
                },
            );
        } else if right <= 0 {
            enter(stack, mesh, k_xw, cone); // the whole cone passes right of x: through x -> w
        } else {
            enter(stack, mesh, k_ux, cone); // through u -> x
        }
    }
    for (list, fan_count) in found.iter_mut().zip(fan_found) {
        merge_by_angle(list, fan_count, merged);
    }
    let [first, second] = found;
    (first, second)
}

/// Sorts one cone's `list` by angle, given that its first `fan_count` entries are sorted by
/// increasing angle and the rest by decreasing angle, in linear time (a merge); entries for the
/// same vertex met twice (the fan's triangles share their sides) are kept once. Inside a cone,
/// narrower than a half-turn, `d` comes before `e` exactly when `d x e > 0`.
fn merge_by_angle(list: &mut Vec<Sighting>, fan_count: usize, merged: &mut Vec<Sighting>) {
    list[fan_count..].reverse();
    let (fan, walk) = list.split_at(fan_count);
    merged.clear();
    let (mut i, mut j) = (0, 0);
    while i < fan.len() || j < walk.len() {
        let take_fan = j == walk.len() || (i < fan.len() && fan[i].0.cross(walk[j].0) >= 0);
        let next = if take_fan { fan[i] } else { walk[j] };
        if take_fan {
            i += 1;
        } else {
            j += 1;
        }
        if merged.last().map(|&(_, v)| v) != Some(next.1) {
            merged.push(next);
        }
    }
    std::mem::swap(list, merged);
}

/// Pushes the part of a cone that leaves a triangle through its half-edge `k`, unless that is a
/// polygon edge or the part is empty.
fn enter(stack: &mut Vec<(Step, Cone)>, mesh: &Mesh, k: usize, part: Cone) {
    let next = mesh.twin[k];
    if next != NONE && part.lo.cross(part.hi) > 0 {
        stack.push((Step::Enter(next as usize), part));
    }
}
