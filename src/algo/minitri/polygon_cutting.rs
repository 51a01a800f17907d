//! Step 1's bounded method: minimally degenerate triangles by balanced polygon cutting,
//! shortest-path trees and ray shooting (Chen & Chang 1990, §3, Step 1, whose divide and
//! conquer on balanced chords this follows; shortest-path trees by the funnel method of Guibas,
//! Hershberger, Leven, Sharir and Tarjan, *Algorithmica* 2 (1987) 209-233).
//!
//! For a simple polygon (one ring, no touching rings): the triangulation's dual is a tree.
//! Cutting a piece along the diagonal `p q` of a centroid edge of its dual tree leaves two halves
//! of at most about two thirds of its triangles each, so the pieces nest O(log n) deep. A
//! minimally degenerate triangle `(a, b, c)` (`b` strictly inside segment `a c`, both sides
//! chords or edges, no other vertex on `a c`) lies in every piece holding its three corners
//! (a segment between two vertices of a piece cannot leave it: it would cross one of its cut
//! diagonals twice), so some cut `p q` first separates them. Then either `b` is `p` or `q`, or
//! `a c` crosses `p q` at a point `x` with `b` and one end, say `a`, in the same half. In the
//! second case the shortest path from `a` to whichever of `p`, `q` lies across the chord `b x`
//! crosses it, and `a` sees all of `b x` along the line itself, so the path leaves `a` along
//! `a b`: `b` is `a`'s parent in the shortest-path tree from `p` or from `q` inside the half
//! (paths go straight through collinear vertices, so the parent is the nearest vertex on the
//! path). In the first case `b` is `a`'s parent from `b` itself. So, per cut, per half and per
//! vertex `a` of the half, with `u` its parent from `p` and from `q`: shoot a ray from `u` in
//! the direction `u - a`; if it first meets a vertex `c`, `(a, u, c)` is a minimally degenerate
//! triangle (the path edge `a u` and the ray `u c` hold no vertex). Every triangle is found
//! this way, and nothing else is.
//!
//! ```text
//!        q                     the cut p q splits the piece; the shortest path from a to q
//!       /|\                    inside a's half leaves a along a b, so b is a's parent and
//!   a--b-|-x--c                the ray from b in direction b - a meets c: (a, b, c) found.
//!       \|/
//!        p
//! ```
//!
//! Exact: every decision is the sign of an orientation test on input points (the funnel's
//! tangents, the direction's place in a vertex's fan, the ray shooting of
//! [`super::ray_shooting`]); no intersection point is computed.
//!
//! Cost: a piece of `m` triangles costs O(m) to collect and cut and O(m log m) for its four
//! shortest-path trees (a funnel split by binary search, undone on backtracking); O(n log^2 n)
//! over the O(log n) levels. Each vertex asks at most four rays per level: each walks up to
//! [`RAY_WALK`] triangles, and those still going are sorted by direction (O(n log n) per level)
//! and shot in that order, a few long runs per thread, so that the shooter's fingers follow the
//! directions round ([`super::ray_shooting::Shooter::shoot_with`]): O(n log n) per level for
//! the rays too, O(n log^2 n) in all, the paper's bound, against O(n^2) for the walk on inputs
//! where every reflex vertex sees most of the polygon. Pieces holding no vertex still to
//! be searched are skipped, so the method costs little when the walk left few vertices to it.

use super::degenerate::Degenerate;
use super::expansion::Mesh;
use super::ray_shooting::{Shooter, RAY_WALK};
use crate::geom::kernel::{cross, Coord, Dir};
use crate::geom::polygon::Polygon;
use rayon::iter::Either;
use rayon::prelude::*;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::collections::HashSet;
use std::hash::{BuildHasherDefault, Hasher};

/// A hasher for the pairs `(a << 32) | u` of [`middles`]' set of rays asked: one multiplication
/// (Fibonacci hashing), where the standard SipHash cost a fifth of the method's time on a
/// 13,565-vertex state boundary. The keys are vertex numbers, not input an attacker chooses
/// to collide (a collision costs time, never a wrong answer).
#[derive(Default)]
struct PairHasher(u64);

impl Hasher for PairHasher {
    fn finish(&self) -> u64 {
        self.0
    }

    fn write(&mut self, bytes: &[u8]) {
        for &b in bytes {
            self.0 = (self.0.rotate_left(8) ^ u64::from(b)).wrapping_mul(0x9E37_79B9_7F4A_7C15);
        }
    }

    fn write_u64(&mut self, key: u64) {
        self.0 = (self.0 ^ key).wrapping_mul(0x9E37_79B9_7F4A_7C15);
    }
}

/// No half-edge, triangle or index.
const NONE: usize = usize::MAX;

/// The minimally degenerate triangles whose middle vertex `b` has `wanted[b]` (`b` reflex), in
/// a simple polygon (one ring, no touches) triangulated by `mesh`, rays shot by `shooter` (built
/// on the same mesh). `None` if `deadline` passed first (read before each level's
/// shortest-path trees and again before its rays; a level is O(n log n) work, the deadline's
/// granularity). The triangles come in no particular order, without repetition.
pub(super) fn middles<P: Coord>(
    polygon: &Polygon<P>,
    mesh: &Mesh,
    shooter: &Shooter,
    wanted: &[bool],
    deadline: Option<std::time::Instant>,
) -> Option<Vec<Degenerate>> {
    let triangles = mesh.triangle_count();
    let fans = Fans::new(polygon, mesh, wanted);
    let mut pieces = Pieces::new(triangles);
    let mut asked: HashSet<u64, BuildHasherDefault<PairHasher>> = HashSet::default();
    let mut found = Vec::new();
    // Level by level: the pieces of a level are cut one after another (the cuts are marked in
    // one array), then the halves' shortest-path trees are built in parallel (on the current
    // rayon pool, each thread with its own buffers), the rays not asked before are kept, and
    // those are shot in parallel. The result is sorted, so it does not depend on the threads.
    let mut level = vec![0];
    while !level.is_empty() {
        if crate::algo::past(deadline) {
            return None;
        }
        let mut halves = Vec::new();
        for &root in &level {
            if let Some(cut) = pieces.cut(mesh, root, |v| wanted[v]) {
                halves.push(cut);
                halves.push(mesh.twin_of(cut)?);
            }
        }
        let blocked = &pieces.blocked;
        let rays: Vec<Vec<u64>> = halves
            .par_iter()
            .map(|&h| rays_of_half(polygon, mesh, blocked, wanted, h))
            .collect();
        let new: Vec<u64> = rays.into_iter().flatten().filter(|&k| asked.insert(k)).collect();
        if crate::algo::past(deadline) {
            return None;
        }
        // Each ray walked a few triangles (most end there), the others shot by direction in a
        // few long runs (one per task), each thread's fingers following the directions round
        // (`Shooter::shoot_with`): O(log n) amortized per ray.
        let walked: Vec<Either<Degenerate, FarRay<P>>> = new
            .par_iter()
            .filter_map(|&key| {
                let (a, u) = ((key >> 32) as usize, (key & 0xFFFF_FFFF) as usize);
                let d = Dir::between(polygon.point(a), polygon.point(u));
                match fans.walk(polygon, mesh, u, d) {
                    Walked::Hit(c) => Some(Either::Left(Degenerate::new(polygon, a, u, c))),
                    Walked::Miss => None,
                    Walked::Far(g) => Some(Either::Right(FarRay { d, a, u, g })),
                }
            })
            .collect();
        let mut far = Vec::new();
        for ray in walked {
            match ray {
                Either::Left(hit) => found.push(hit),
                Either::Right(ray) => far.push(ray),
            }
        }
        if let Some(base) = far.first().map(|ray| ray.d) {
            far.sort_unstable_by(|x, y| base.cmp_angle_from(x.d, y.d));
        }
        let run = far
            .len()
            .div_ceil(RUNS_PER_THREAD * rayon::current_num_threads())
            .max(MIN_RUN);
        let shot: Vec<Degenerate> = far
            .par_chunks(run)
            .flat_map_iter(|run| {
                FINGERS.with_borrow_mut(|fingers| {
                    fingers.resize(shooter.finger_count(), 0);
                    let hits = run.iter().filter_map(|ray| {
                        let c = shooter.shoot_with(polygon, mesh, ray.u, ray.d, ray.g, fingers)?;
                        Some(Degenerate::new(polygon, ray.a, ray.u, c))
                    });
                    hits.collect::<Vec<_>>()
                })
            })
            .collect();
        found.extend(shot);
        level = halves.iter().map(|&h| h / 3).collect();
    }
    // A triangle is found from either end (and again at other levels).
    found.sort_unstable_by_key(|m| (m.b, m.a, m.c));
    found.dedup();
    Some(found)
}

/// A ray of [`middles`], from `u` in direction `d = u - a`, still going after [`RAY_WALK`]
/// triangles: it enters the next triangle by half-edge `g`.
struct FarRay<P: Coord> {
    d: Dir<P>,
    a: usize,
    u: usize,
    g: usize,
}

/// How a ray of [`middles`] ended its first [`RAY_WALK`] triangles.
enum Walked {
    /// At this vertex.
    Hit(usize),
    /// At a polygon edge, or not in the vertex's angle.
    Miss,
    /// Still going, entering the triangle of this half-edge.
    Far(usize),
}

/// Runs of rays per thread at each level (a few, so that a thread left idle can take one).
const RUNS_PER_THREAD: usize = 4;

/// The fewest rays in one run (fewer are not worth a task).
const MIN_RUN: usize = 256;

thread_local! {
    /// Each thread's fingers for [`Shooter::shoot_with`], kept from run to run (any values are
    /// valid starts).
    static FINGERS: RefCell<Vec<u32>> = const { RefCell::new(Vec::new()) };
}

/// The rays to shoot for the half of the cut half-edge `h` (the half holding `h`'s triangle),
/// as keys `(a << 32) | u`: for every vertex `a` of the half and `u` its parent in the
/// shortest-path tree from either end of the cut, when `u` is wanted and the direction `u - a`
/// lies in `u`'s closed angle (the ray goes on from `u` away from `a`).
fn rays_of_half<P: Coord>(
    polygon: &Polygon<P>,
    mesh: &Mesh,
    blocked: &[bool],
    wanted: &[bool],
    h: usize,
) -> Vec<u64> {
    // One set of buffers per thread, kept from call to call (grown to the largest mesh seen).
    thread_local!(static FUNNELS: RefCell<Funnels> = RefCell::default());
    FUNNELS.with_borrow_mut(|funnels| {
        funnels.fit(polygon.len(), mesh.triangle_count());
        let mut rays = Vec::new();
        for root in [mesh.tail(h), mesh.head(h)] {
            funnels.tree(polygon, mesh, blocked, h, root);
            for &a in &funnels.reached {
                let u = funnels.parent[a as usize] as usize;
                if !wanted[u] {
                    continue;
                }
                // u is reflex: its exterior wedge is convex, and the direction must avoid it.
                let pu = polygon.point(u);
                let d = Dir::between(polygon.point(a as usize), pu);
                let to_next = Dir::between(pu, polygon.point(polygon.next(u)));
                let to_prev = Dir::between(pu, polygon.point(polygon.prev(u)));
                if to_prev.cross(d) > 0 && d.cross(to_next) > 0 {
                    continue;
                }
                rays.push((u64::from(a) << 32) | u as u64);
            }
        }
        // The two trees often give a vertex the same parent.
        rays.sort_unstable();
        rays.dedup();
        rays
    })
}

/// The pieces of the dual tree: the cut diagonals so far, and buffers to collect a piece.
struct Pieces {
    /// Half-edges of the cut diagonals (both halves of each).
    blocked: Vec<bool>,
    /// The piece being cut: its triangles in preorder.
    members: Vec<usize>,
    /// Per triangle: the half-edge leading to its parent in the piece ([`NONE`] at the root).
    up: Vec<usize>,
    /// Per triangle: its subtree's size in the piece.
    size: Vec<usize>,
    stack: Vec<usize>,
}

impl Pieces {
    fn new(triangles: usize) -> Pieces {
        Pieces {
            blocked: vec![false; 3 * triangles],
            members: Vec::new(),
            up: vec![NONE; triangles],
            size: vec![0; triangles],
            stack: Vec::new(),
        }
    }

    /// Cuts the piece holding triangle `root` along the diagonal of a centroid edge of its dual
    /// tree, and returns that diagonal's half-edge in the triangle below the edge; `None` if the
    /// piece is one triangle or none of its corners is `wanted`.
    fn cut(&mut self, mesh: &Mesh, root: usize, wanted: impl Fn(usize) -> bool) -> Option<usize> {
        self.members.clear();
        self.up[root] = NONE;
        self.stack.push(root);
        let mut any = false;
        while let Some(t) = self.stack.pop() {
            self.members.push(t);
            self.size[t] = 1;
            for h in 3 * t..3 * t + 3 {
                any |= wanted(mesh.tail(h));
                if self.blocked[h] || h == self.up[t] {
                    continue;
                }
                if let Some(g) = mesh.twin_of(h) {
                    self.up[g / 3] = g;
                    self.stack.push(g / 3);
                }
            }
        }
        if !any || self.members.len() < 2 {
            return None;
        }
        let total = self.members.len();
        let (mut best, mut best_larger) = (NONE, usize::MAX);
        for &t in self.members.iter().rev() {
            let g = self.up[t];
            if g == NONE {
                continue;
            }
            if let Some(h) = mesh.twin_of(g) {
                self.size[h / 3] += self.size[t];
            }
            let larger = self.size[t].max(total - self.size[t]);
            if larger < best_larger {
                (best, best_larger) = (g, larger);
            }
        }
        let twin = mesh.twin_of(best)?;
        self.blocked[best] = true;
        self.blocked[twin] = true;
        Some(best)
    }
}

/// Shortest-path trees in a half by the funnel method, the funnel kept in one array
/// (`buf[lo..=hi]`, its apex at `apex`): entering a triangle across `buf[lo] buf[hi]`, its third
/// vertex `w` finds its parent `buf[t]` by binary search, and the two funnels beyond are
/// `buf[lo..=t], w` and `w, buf[t..=hi]`: `w` is written next to `t`, the overwritten entry
/// restored once that side is done.
#[derive(Default)]
struct Funnels {
    /// The funnel (see [`Funnels::fit`] for its size).
    buf: Vec<u32>,
    /// Per vertex, its parent in the last tree (valid for the vertices of `reached`).
    parent: Vec<u32>,
    /// The vertices of the last tree but its root.
    reached: Vec<u32>,
    tasks: Vec<Task>,
}

/// A step of the depth-first walk of [`Funnels::tree`].
enum Task {
    /// Write `w` at `at` (unless `at` is [`NONE`]), then cross half-edge `g` with the funnel
    /// `buf[lo..=hi]`, apex at `apex`.
    Enter {
        g: usize,
        lo: usize,
        hi: usize,
        apex: usize,
        at: usize,
        w: u32,
    },
    /// Put `old` back at `at`.
    Undo { at: usize, old: u32 },
}

impl Funnels {
    /// Makes the buffers fit a mesh of `triangles` triangles over `vertices` vertices (the
    /// funnel starts in the middle of `buf`, and its range moves by at most one place per
    /// triangle crossed).
    fn fit(&mut self, vertices: usize, triangles: usize) {
        if self.parent.len() < vertices {
            self.parent.resize(vertices, 0);
        }
        if self.buf.len() < 2 * triangles + 8 {
            self.buf.resize(2 * triangles + 8, 0);
        }
    }

    /// The shortest-path tree from `root`, an end of the cut half-edge `h`, inside the half of
    /// `h`'s triangle (not crossing `blocked` half-edges): fills `parent` and `reached`.
    fn tree<P: Coord>(
        &mut self,
        polygon: &Polygon<P>,
        mesh: &Mesh,
        blocked: &[bool],
        h: usize,
        root: usize,
    ) {
        self.reached.clear();
        // The triangle (tail, head, apex) of h, counter-clockwise: its corners see the root.
        for v in [mesh.tail(h), mesh.head(h), mesh.apex(h)] {
            if v != root {
                self.parent[v] = root as u32;
                self.reached.push(v as u32);
            }
        }
        let mid = self.buf.len() / 2;
        for g in [Mesh::next_in_triangle(h), Mesh::prev_in_triangle(h)] {
            // Seen from the root, the side's left end is g's head (the triangle beyond g has its
            // third vertex on the left of head -> tail).
            let (u, v) = (mesh.head(g), mesh.tail(g));
            let (lo, hi, apex) = if root == u || root == v {
                self.buf[mid] = u as u32;
                self.buf[mid + 1] = v as u32;
                (mid, mid + 1, if root == u { mid } else { mid + 1 })
            } else {
                self.buf[mid - 1] = u as u32;
                self.buf[mid] = root as u32;
                self.buf[mid + 1] = v as u32;
                (mid - 1, mid + 1, mid)
            };
            self.walk(polygon, mesh, blocked, g, lo, hi, apex);
        }
    }

    /// The depth-first walk from crossing `g` with the funnel `buf[lo..=hi]`.
    #[allow(clippy::too_many_arguments)]
    fn walk<P: Coord>(
        &mut self,
        polygon: &Polygon<P>,
        mesh: &Mesh,
        blocked: &[bool],
        g: usize,
        lo: usize,
        hi: usize,
        apex: usize,
    ) {
        self.tasks.push(Task::Enter {
            g,
            lo,
            hi,
            apex,
            at: NONE,
            w: 0,
        });
        while let Some(task) = self.tasks.pop() {
            let (g, lo, hi, apex) = match task {
                Task::Undo { at, old } => {
                    self.buf[at] = old;
                    continue;
                }
                Task::Enter {
                    g,
                    lo,
                    hi,
                    apex,
                    at,
                    w,
                } => {
                    if at != NONE {
                        self.tasks.push(Task::Undo {
                            at,
                            old: self.buf[at],
                        });
                        self.buf[at] = w;
                    }
                    (g, lo, hi, apex)
                }
            };
            if blocked[g] {
                continue;
            }
            let Some(entry) = mesh.twin_of(g) else {
                continue; // a polygon edge
            };
            let w = mesh.apex(entry);
            let t = self.tangent(polygon, lo, hi, apex, w);
            self.parent[w] = self.buf[t];
            self.reached.push(w as u32);
            // The side (w, v) after the side (u, w): pushed first, taken last.
            self.tasks.push(Task::Enter {
                g: Mesh::next_in_triangle(entry),
                lo: t - 1,
                hi,
                apex: apex.max(t),
                at: t - 1,
                w: w as u32,
            });
            self.tasks.push(Task::Enter {
                g: Mesh::prev_in_triangle(entry),
                lo,
                hi: t + 1,
                apex: apex.min(t),
                at: t + 1,
                w: w as u32,
            });
        }
    }

    /// Where the shortest path from the apex to `w` (beyond the funnel's far side) leaves the
    /// funnel: the index of `w`'s parent. Along the left chain (`apex` down to `lo`) the path
    /// follows an edge `buf[j + 1] -> buf[j]` while `w` is on its left or on its line, along the
    /// right chain (`apex` up to `hi`) while `w` is on the right of `buf[j] -> buf[j + 1]` or on
    /// its line (a path through a collinear vertex goes on straight, and that vertex is the
    /// nearer parent). The chains are convex, so this holds on a prefix: binary search.
    fn tangent<P: Coord>(
        &self,
        polygon: &Polygon<P>,
        lo: usize,
        hi: usize,
        apex: usize,
        w: usize,
    ) -> usize {
        let at = |i: usize| polygon.point(self.buf[i] as usize);
        let pw = polygon.point(w);
        let left = |j: usize| cross(at(j + 1), at(j), pw) >= 0;
        let right = |j: usize| cross(at(j), at(j + 1), pw) <= 0;
        if apex > lo && left(apex - 1) {
            // The smallest j with `left` on j..apex.
            let (mut l, mut r) = (lo, apex - 1);
            while l < r {
                let m = (l + r) / 2;
                if left(m) {
                    r = m;
                } else {
                    l = m + 1;
                }
            }
            return l;
        }
        if apex < hi && right(apex) {
            // The largest j with `right` on apex..=j; the path reaches j + 1.
            let (mut l, mut r) = (apex, hi - 1);
            while l < r {
                let m = (l + r).div_ceil(2);
                if right(m) {
                    l = m;
                } else {
                    r = m - 1;
                }
            }
            return l + 1;
        }
        apex
    }
}

/// The fans of the wanted vertices: for each, the vertices of its triangles counter-clockwise
/// from `next(v)` to `prev(v)` with their directions, and the far side of each fan triangle.
struct Fans<P: Coord> {
    start: Vec<usize>,
    dirs: Vec<Dir<P>>,
    verts: Vec<usize>,
    /// `far[start[v] + i]`: the far side of the triangle between fan entries `i` and `i + 1`.
    far: Vec<usize>,
}

impl<P: Coord> Fans<P> {
    fn new(polygon: &Polygon<P>, mesh: &Mesh, wanted: &[bool]) -> Fans<P> {
        let mut fans = Fans {
            start: Vec::with_capacity(polygon.len() + 1),
            dirs: Vec::new(),
            verts: Vec::new(),
            far: Vec::new(),
        };
        for (v, &wanted) in wanted.iter().enumerate() {
            fans.start.push(fans.dirs.len());
            if !wanted {
                continue;
            }
            let c = polygon.point(v);
            fans.dirs.push(Dir::between(c, polygon.point(polygon.next(v))));
            fans.verts.push(polygon.next(v));
            fans.far.push(NONE);
            for h in mesh.out(v).into_iter().flat_map(|h| mesh.fan(h)) {
                // The fan triangle (v, previous entry, apex of h) has the far side h + 1.
                let last = fans.far.len() - 1;
                fans.far[last] = Mesh::next_in_triangle(h);
                let w = mesh.apex(h);
                fans.dirs.push(Dir::between(c, polygon.point(w)));
                fans.verts.push(w);
                fans.far.push(NONE);
            }
        }
        fans.start.push(fans.dirs.len());
        fans
    }

    /// The ray from `u` in direction `d` walked [`RAY_WALK`] triangles: the first vertex it
    /// meets, or none (`d` outside `u`'s closed interior angle, or a polygon edge met first),
    /// or the half-edge it enters the next triangle by, to be shot from there.
    fn walk(&self, polygon: &Polygon<P>, mesh: &Mesh, u: usize, d: Dir<P>) -> Walked {
        self.try_walk(polygon, mesh, u, d).unwrap_or(Walked::Miss)
    }

    /// [`Fans::walk`], `None` for a miss.
    fn try_walk(&self, polygon: &Polygon<P>, mesh: &Mesh, u: usize, d: Dir<P>) -> Option<Walked> {
        let range = self.start[u]..self.start[u + 1];
        let dirs = &self.dirs[range.clone()];
        // The fan's directions by counter-clockwise angle from its first one, next(u).
        let base = *dirs.first()?;
        let cmp = |x: Dir<P>, y: Dir<P>| base.cmp_angle_from(x, y);
        let i = dirs.partition_point(|&x| cmp(x, d) == Ordering::Less);
        let i_abs = range.start + i;
        if i == dirs.len() {
            return Some(Walked::Miss); // beyond prev(u): outside the angle
        }
        if cmp(dirs[i], d) == Ordering::Equal {
            return Some(Walked::Hit(self.verts[i_abs])); // along a side: its far end
        }
        let mut g = mesh.twin_of(*self.far.get(i_abs.checked_sub(1)?)?)?;
        // Most rays end within a few triangles: walked first, shot past RAY_WALK triangles.
        let pu = polygon.point(u);
        for _ in 0..RAY_WALK {
            let (x, k_ux, k_xw) = mesh.apex_and_sides(g);
            let side = d.cross(Dir::between(pu, polygon.point(x)));
            if side == 0 {
                return Some(Walked::Hit(x));
            }
            // The ray passes right of x (through x -> w) or left of it (through u -> x).
            g = mesh.twin_of(if side < 0 { k_xw } else { k_ux })?;
        }
        Some(Walked::Far(g))
    }
}

#[cfg(test)]
mod tests {
    use super::{middles, Mesh, Shooter};
    use crate::algo::minitri::degenerate::minimally_degenerate_by_sweep;
    use crate::geom::kernel::cross;
    use crate::test_support::{comb, grown_rings, polygon, sliver};

    /// On its own (every reflex vertex wanted), the bounded method finds exactly the triangles
    /// the angular sweep finds with a reflex middle, kinds included: on combs, a sliver
    /// staircase and random grid polygons, over the flipped mesh step 1 uses.
    #[test]
    fn finds_every_triangle_with_a_reflex_middle() {
        let mut rings = vec![comb(40, 1, 9), comb(7, 2, 3), comb(1, 1, 1), sliver(40, 1, 1)];
        rings.extend(grown_rings(0x35_c075_0001, 300, 11, 50));
        let mut total = 0;
        for ring in &rings {
            let p = polygon(&[ring]);
            let mut mesh = Mesh::new(&p, crate::algo::plain::polygon(&p, None));
            mesh.flip_towards_delaunay(&p, 4 * p.len());
            let shooter = Shooter::new(&p, &mesh);
            let wanted: Vec<bool> = (0..p.len())
                .map(|v| cross(p.point(p.prev(v)), p.point(v), p.point(p.next(v))) < 0)
                .collect();
            let Some(found) = middles(&p, &mesh, &shooter, &wanted, None) else {
                panic!("no deadline")
            };
            let key = |m: &super::Degenerate| (m.a, m.b, m.c, m.kind as u8);
            let mut found: Vec<_> = found.iter().map(key).collect();
            found.sort_unstable();
            let mut swept: Vec<_> = minimally_degenerate_by_sweep(&p)
                .iter()
                .filter(|m| wanted[m.b])
                .map(key)
                .collect();
            swept.sort_unstable();
            assert_eq!(found, swept, "{ring:?}");
            total += found.len();
        }
        assert!(total > 400, "{total} triangles");
    }
}
