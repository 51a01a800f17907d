//! The half-edge mesh of a triangulation, one type for every algorithm that walks or edits
//! triangles: step 1 of MINITRI walks it ([`crate::algo::minitri::expansion`],
//! [`crate::algo::minitri::ray_shooting`]), steps 4-5 cut sides into it
//! ([`crate::algo::minitri::cut`]), and the pseudotriangulations merge its faces
//! ([`crate::algo::pseudo`]) or insert shortest paths into it ([`crate::algo::pseudo_hull`]).
//!
//! Input contract: counter-clockwise nondegenerate triangles with disjoint interiors, meeting
//! edge to edge, whose union is a region in which every vertex has one fan of triangles (all
//! round it, or from one boundary edge to another: the region never touches itself at a
//! vertex). An edge with a triangle on one side only is on the region's boundary and is never
//! crossed.
//!
//! # Numbering
//!
//! Triangle `t` is stored as its three corners `[a, b, c]`, counter-clockwise. Its half-edges
//! are `3 t`, `3 t + 1`, `3 t + 2`: half-edge `3 t + k` runs from corner `k` (its tail) to
//! corner `k + 1` (its head) with `t` on its left, and corner `k + 2` is its apex.
//!
//! ```text
//!                 c                 next(3t) = 3t + 1, next(3t + 2) = 3t
//!                / \                prev(3t) = 3t + 2
//!       3t + 2  /   \  3t + 1       twin(h): the same side from head to tail in the
//!              /  t  \                       triangle on its right (none on the boundary)
//!             a ----- b
//!               3t + 0
//! ```
//!
//! # Operations
//!
//! [`Mesh`] holds the triangles, the twin of every half-edge, a half-edge leaving each vertex
//! and two flags per half-edge (fixed, and done: a face already reported):
//! - building: twins matched by their two ends in O(n + m) (one counting sort by the lower end,
//!   then one pass per bucket); [`Mesh::separate`] unlinks the twins of given edges;
//! - reading: [`Mesh::tail`], [`Mesh::head`], [`Mesh::apex`], [`Mesh::twin_of`] (and, with one
//!   division by 3 for all, [`Mesh::ends_and_apex`] and [`Mesh::apex_and_sides`]: the steps of
//!   the flips and of step 1's walks), the rotation
//!   round a vertex ([`Mesh::fan`]), the walk along a face of triangles joined across
//!   unfixed edges ([`Mesh::next_boundary`], [`Mesh::prev_boundary`]); all O(1) per step;
//! - [`Mesh::flip`], O(1), keeping the numbering: the triangles `t = (a b c)` and
//!   `s = (b a d)` on the diagonal `h = a -> b` (twin `g = b -> a`) become `t = (c a d)` and
//!   `s = (d b c)`, joined by `d -> c` (half-edge `3 t + 2`) and `c -> d` (`3 s + 2`); the four
//!   outer sides keep their twins and flags;
//!
//! ```text
//!            c                          c
//!           / \                        /|\
//!          /   \                      / | \
//!         /  t  \                    /  |  \
//!        a --h-> b        flip      a t | s b
//!        a <-g-- b         =>        \  |  /
//!         \  s  /                     \ | /
//!          \   /                       \|/
//!           \ /                         d
//!            d
//!   (the diagonal drawn as its two half-edges; t and s keep their numbers)
//! ```
//!
//! - Lawson's flips towards the constrained Delaunay triangulation ([`Mesh::lawson`]): whether a
//!   flip is ALLOWED is exact (an unfixed diagonal whose quadrilateral is strictly convex, so the
//!   result is again a triangulation of the region with the same fixed edges); whether it is
//!   DESIRABLE is the kernel's floating-point [`incircle_approx`], a heuristic that never
//!   decides a fact of the answer (hence a bound on the flips, should rounding make them
//!   cycle). Fatter triangles only make walks shorter.
//!
//! [`Constrained`] adds what editing by segments needs: the points, every half-edge found by
//! its two ends (a hash map, expected O(1)), and segment insertion ([`Constrained::insert`]):
//! the k diagonals the segment crosses are found by walking along it, then flipped until the
//! segment is an edge, which is then fixed. First every flip that leaves one crossing fewer is
//! made, a diagonal being tested again only when a neighbour along the segment was flipped: O(k)
//! tests and at most k flips. That almost always suffices (docs/benchmarks.md, "Figures behind
//! the code's constants and choices"), but not always: every flippable crossed diagonal can have its two apexes on opposite sides of the
//! segment (see the tests). Sloan's queue (1993) then finishes, flipping any crossed diagonal
//! whose quadrilateral is strictly convex: O(k^2) at worst. Removing the crossed triangles and
//! triangulating the two sides again would be about as fast but is wrong in general: the
//! triangles crossed on one side can go round a hole and touch at a vertex, which no
//! triangulator of simple polygons accepts (seen in pseudo-hull's property tests, and in
//! MINITRI's cut step before it used this mesh). Every decision is an exact orientation test; a
//! segment that would pass through a vertex or cross a fixed or boundary edge, or flips that get
//! stuck, are refused ([`Broken`]), never drawn.
//!
//! Complexity: O(n + m) to build for n vertices and m triangles (and O(m) expected to index the
//! half-edges of a [`Constrained`] mesh); an insertion started in O(degree) at its first
//! vertex, O(k) to walk it, then the flips above.

use crate::algo::number_hash::NumberMap;
use crate::geom::kernel::{cross, dot, incircle_approx, Coord, Point};
use crate::geom::polygon::Polygon;
use std::collections::VecDeque;
use std::time::Instant;

/// No half-edge: the twin of a boundary half-edge, the half-edge leaving a vertex of no triangle.
const NONE: u32 = u32::MAX;

/// Flag bits per triangle: bit `k` edge `k` fixed, bit `3 + k` the face on the left of edge `k`
/// finished (a pseudotriangle already reported).
const FIXED: u8 = 1;
const DONE: u8 = 8;

/// A triangulation with twin links (see the module docs for the numbering and the operations).
pub struct Mesh {
    /// The corners of each triangle, counter-clockwise.
    tri: Vec<[u32; 3]>,
    /// The twin of each half-edge, [`NONE`] on the region's boundary.
    twin: Vec<u32>,
    /// A half-edge leaving each vertex ([`NONE`] if it is in no triangle).
    out: Vec<u32>,
    /// [`FIXED`] and [`DONE`] bits of the half-edges, per triangle.
    flags: Vec<u8>,
}

/// The twin of every half-edge of `tri` (vertices below `vertices`), or [`NONE`]: half-edges
/// bucketed by their lower end (a counting sort), then in each bucket the first half-edge to
/// the other end waits for the second. O(n + m); a third half-edge on one side (outside the
/// contract) stays alone.
fn twin_halves(vertices: usize, tri: &[[u32; 3]]) -> Vec<u32> {
    let halves = 3 * tri.len();
    // The sides of each triangle as (lower end, higher end), by half-edge number.
    let sides = || {
        tri.iter().flat_map(|&[a, b, c]| {
            [(a, b), (b, c), (c, a)].map(|(u, w)| (u.min(w) as usize, u.max(w)))
        })
    };
    let mut start = vec![0u32; vertices + 1];
    for (v, _) in sides() {
        start[v + 1] += 1;
    }
    for v in 0..vertices {
        start[v + 1] += start[v];
    }
    let mut bucket: Vec<(u32, u32)> = vec![(0, 0); halves];
    let mut fill = start.clone();
    for (h, (v, w)) in sides().enumerate() {
        bucket[fill[v] as usize] = (w, h as u32);
        fill[v] += 1;
    }
    drop(fill);
    let mut twin = vec![NONE; halves];
    let mut waiting = vec![NONE; vertices];
    for v in 0..vertices {
        let group = &bucket[start[v] as usize..start[v + 1] as usize];
        for &(w, h) in group {
            let slot = &mut waiting[w as usize];
            if *slot == NONE {
                *slot = h;
            } else {
                twin[h as usize] = *slot;
                twin[*slot as usize] = h;
                *slot = NONE;
            }
        }
        for &(w, _) in group {
            waiting[w as usize] = NONE;
        }
    }
    twin
}

/// The corners after and before corner `k` (0, 1 or 2) of a triangle, counter-clockwise: corner
/// `k` starts half-edge `k`, so these are also the next and previous half-edges' corners.
#[inline]
fn around(k: usize) -> (usize, usize) {
    match k {
        0 => (1, 2),
        1 => (2, 0),
        _ => (0, 1),
    }
}

impl Mesh {
    /// The mesh of `triangles` (corners below `vertices`, as the module's input contract says).
    pub(crate) fn from_triangles(vertices: usize, triangles: &[[usize; 3]]) -> Mesh {
        let tri: Vec<[u32; 3]> = triangles.iter().map(|t| t.map(|v| v as u32)).collect();
        let twin = twin_halves(vertices, &tri);
        let mut out = vec![NONE; vertices];
        for (h, &v) in tri.iter().flatten().enumerate() {
            out[v as usize] = h as u32;
        }
        let flags = vec![0; tri.len()];
        Mesh {
            tri,
            twin,
            out,
            flags,
        }
    }

    /// The mesh of a triangulation of `polygon` (holes allowed; a plain triangulation: n + 2w - 2
    /// triangles, sides ring edges or proper diagonals), for walking: `Mesh::out` gives each
    /// vertex's boundary half-edge `v -> next(v)`.
    pub fn new<P: Coord>(polygon: &Polygon<P>, triangles: Vec<[usize; 3]>) -> Mesh {
        let mut mesh = Mesh::from_triangles(polygon.len(), &triangles);
        mesh.out_on_boundary(polygon);
        mesh
    }

    /// Sets [`Mesh::out`] of each vertex to its boundary half-edge.
    fn out_on_boundary<P: Coord>(&mut self, polygon: &Polygon<P>) {
        for h in 0..self.twin.len() {
            if self.twin[h] == NONE {
                let v = self.tail(h);
                debug_assert_eq!(self.head(h), polygon.next(v), "a boundary side is an edge");
                self.out[v] = h as u32;
            }
        }
        debug_assert!(
            !self.out.contains(&NONE),
            "every polygon edge is a triangle side"
        );
    }

    /// The number of triangles.
    pub fn triangle_count(&self) -> usize {
        self.tri.len()
    }

    /// The triangles, counter-clockwise, as indices into the points.
    pub fn triangles(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        self.tri.iter().map(|t| t.map(|v| v as usize))
    }

    /// The triangles, giving up the links.
    pub fn into_triangles(self) -> Vec<[usize; 3]> {
        self.triangles().collect()
    }

    /// The vertex a half-edge starts from.
    #[inline]
    pub(crate) fn tail(&self, h: usize) -> usize {
        self.tri[h / 3][h % 3] as usize
    }

    /// The vertex a half-edge ends at.
    #[inline]
    pub(crate) fn head(&self, h: usize) -> usize {
        self.tri[h / 3][(h + 1) % 3] as usize
    }

    /// The vertex of a half-edge's triangle opposite it.
    #[inline]
    pub(crate) fn apex(&self, h: usize) -> usize {
        self.tri[h / 3][(h + 2) % 3] as usize
    }

    /// The same side from the triangle on its right (`None` on the region's boundary).
    #[inline]
    pub(crate) fn twin_of(&self, h: usize) -> Option<usize> {
        match self.twin[h] {
            NONE => None,
            g => Some(g as usize),
        }
    }

    /// The tail, head and apex of a half-edge (`(tail(h), head(h), apex(h))`), with one division
    /// by 3.
    #[inline]
    pub(crate) fn ends_and_apex(&self, h: usize) -> (usize, usize, usize) {
        let (t, k) = (h / 3, h % 3);
        let (next, prev) = around(k);
        let corner = |k: usize| self.tri[t][k] as usize;
        (corner(k), corner(next), corner(prev))
    }

    /// The apex of a half-edge's triangle and that triangle's next and previous half-edges
    /// (`(apex(h), next_in_triangle(h), prev_in_triangle(h))`), with one division by 3: the step
    /// of the walks across triangles.
    #[inline]
    pub(crate) fn apex_and_sides(&self, h: usize) -> (usize, usize, usize) {
        let t = h / 3;
        let first = 3 * t;
        let (next, prev) = around(h - first);
        (self.tri[t][prev] as usize, first + next, first + prev)
    }

    /// The next half-edge of the same triangle (counter-clockwise).
    #[inline]
    pub(crate) fn next_in_triangle(h: usize) -> usize {
        if h % 3 == 2 {
            h - 2
        } else {
            h + 1
        }
    }

    /// The previous half-edge of the same triangle.
    #[inline]
    pub(crate) fn prev_in_triangle(h: usize) -> usize {
        if h.is_multiple_of(3) {
            h + 2
        } else {
            h - 1
        }
    }

    /// A half-edge leaving `v` ([`Mesh::new`]: its boundary half-edge), if `v` is in a triangle.
    #[inline]
    pub(crate) fn out(&self, v: usize) -> Option<usize> {
        match self.out[v] {
            NONE => None,
            h => Some(h as usize),
        }
    }

    /// The half-edges leaving the tail of `h`, counter-clockwise from `h` (each the twin of the
    /// previous one's triangle's incoming side), until the boundary or back at `h`.
    pub(crate) fn fan(&self, h: usize) -> impl Iterator<Item = usize> + '_ {
        std::iter::successors(Some(h), move |&g| {
            self.twin_of(Self::prev_in_triangle(g))
                .filter(|&next| next != h)
        })
    }

    /// Unlinks the twins of the sides `u v` for which `wall(u, v)` holds (in either direction).
    pub(crate) fn separate(&mut self, wall: impl Fn(usize, usize) -> bool) {
        for h in 0..self.twin.len() {
            let g = self.twin[h];
            if g != NONE && (h as u32) < g && wall(self.tail(h), self.head(h)) {
                self.twin[h] = NONE;
                self.twin[g as usize] = NONE;
            }
        }
    }

    /// Whether the side of `h` is fixed.
    pub(crate) fn is_fixed(&self, h: usize) -> bool {
        self.flags[h / 3] & (FIXED << (h % 3)) != 0
    }

    /// Whether the face on the left of `h` is marked finished.
    pub(crate) fn is_done(&self, h: usize) -> bool {
        self.flags[h / 3] & (DONE << (h % 3)) != 0
    }

    fn set_done(&mut self, h: usize) {
        self.flags[h / 3] |= DONE << (h % 3);
    }

    /// Makes the side of `h` fixed (both half-edges); false if it was already.
    fn fix(&mut self, h: usize) -> bool {
        if self.is_fixed(h) {
            return false;
        }
        self.flags[h / 3] |= FIXED << (h % 3);
        if let Some(g) = self.twin_of(h) {
            self.flags[g / 3] |= FIXED << (g % 3);
        }
        true
    }

    /// The next fixed half-edge along the boundary of the face on the left of the fixed
    /// half-edge `h` (turning clockwise round its head); the diagonals crossed on the way are
    /// passed to `crossed` as `(right, left)` = (the head of `h`, the diagonal's other end).
    pub(crate) fn next_boundary(&self, h: usize, mut crossed: impl FnMut(usize, usize)) -> usize {
        let mut g = Self::next_in_triangle(h);
        while !self.is_fixed(g) {
            crossed(self.tail(g), self.head(g));
            // A diagonal always has a triangle on both sides.
            g = match self.twin_of(g) {
                Some(t) => Self::next_in_triangle(t),
                None => return g,
            };
        }
        g
    }

    /// The fixed half-edge before `h` along the boundary of the face on its left.
    pub(crate) fn prev_boundary(&self, h: usize) -> usize {
        let mut g = Self::prev_in_triangle(h);
        while !self.is_fixed(g) {
            g = match self.twin_of(g) {
                Some(t) => Self::prev_in_triangle(t),
                None => return g,
            };
        }
        g
    }

    /// Flips the diagonal of `h` (see the module docs' drawing); `h` must have a twin.
    pub(crate) fn flip(&mut self, h: usize) {
        let Some(g) = self.twin_of(h) else {
            debug_assert!(false, "a boundary side is never flipped");
            return;
        };
        let (t, s) = (h / 3, g / 3);
        // Corner k of a triangle starts its half-edge k: h = a -> b (apex c), g = b -> a (apex d).
        let (kh, kg) = (h - 3 * t, g - 3 * s);
        let ((next_h, prev_h), (next_g, prev_g)) = (around(kh), around(kg));
        let (a, b, c) = (
            self.tri[t][kh] as usize,
            self.tri[t][next_h] as usize,
            self.tri[t][prev_h] as usize,
        );
        let d = self.tri[s][prev_g] as usize;
        // The outer sides c -> a, a -> d, d -> b, b -> c: twins and flags.
        let side = |tri: usize, k: usize| {
            let bits = (self.flags[tri] >> k) & (FIXED | DONE);
            (self.twin[3 * tri + k], bits)
        };
        let ca = side(t, prev_h);
        let ad = side(s, next_g);
        let db = side(s, prev_g);
        let bc = side(t, next_h);
        self.tri[t] = [c, a, d].map(|v| v as u32);
        self.tri[s] = [d, b, c].map(|v| v as u32);
        let links = [
            (3 * t, ca.0),
            (3 * t + 1, ad.0),
            (3 * t + 2, (3 * s + 2) as u32),
            (3 * s, db.0),
            (3 * s + 1, bc.0),
            (3 * s + 2, (3 * t + 2) as u32),
        ];
        for (x, y) in links {
            self.twin[x] = y;
            if y != NONE {
                self.twin[y as usize] = x as u32;
            }
        }
        self.flags[t] = ca.1 | (ad.1 << 1);
        self.flags[s] = db.1 | (bc.1 << 1);
        self.out[c] = (3 * t) as u32;
        self.out[a] = (3 * t + 1) as u32;
        self.out[d] = (3 * t + 2) as u32;
        self.out[b] = (3 * s + 1) as u32;
    }

    /// Lawson's flips of the diagonals on `stack` (the top first) towards the constrained
    /// Delaunay triangulation, re-queueing the four outer sides of each flip (see the module
    /// docs), at most `max_flips` of them; `stop(count)`, asked before each of the `count`
    /// half-edges taken, ends them early. Returns the number of flips.
    pub(crate) fn lawson<P: Coord>(
        &mut self,
        pts: &[P],
        mut stack: Vec<u32>,
        max_flips: usize,
        mut stop: impl FnMut(usize) -> bool,
    ) -> usize {
        let mut flips = 0;
        let mut count = 0;
        while let Some(h) = stack.pop() {
            count += 1;
            if flips == max_flips || stop(count) {
                break;
            }
            let h = h as usize;
            if self.is_fixed(h) {
                continue;
            }
            let Some(g) = self.twin_of(h) else {
                continue; // a boundary side (or an entry made stale by earlier flips)
            };
            let (a, b, c) = self.ends_and_apex(h);
            let d = self.apex_and_sides(g).0;
            let [pa, pb, pc, pd] = [a, b, c, d].map(|v| pts[v]);
            if cross(pc, pa, pd) <= 0 || cross(pd, pb, pc) <= 0 {
                continue; // not strictly convex: the flip is not allowed
            }
            if incircle_approx(pa, pb, pc, pd) <= 0.0 {
                continue; // not (as far as floating point tells) an improvement
            }
            self.flip(h);
            flips += 1;
            let (t, s) = (h / 3, g / 3);
            stack.extend([3 * t, 3 * t + 1, 3 * s, 3 * s + 1].map(|x| x as u32));
        }
        flips
    }

    /// Fattens a walking mesh ([`Mesh::new`]) by Lawson's flips (`Mesh::lawson`; polygon edges
    /// are never flipped), at most `max_flips`; returns the number of flips made. The result is
    /// again a triangulation of the polygon with positive triangles whose sides are edges or
    /// proper diagonals, and `Mesh::out` again each vertex's boundary half-edge.
    pub fn flip_towards_delaunay<P: Coord>(
        &mut self,
        polygon: &Polygon<P>,
        max_flips: usize,
    ) -> usize {
        let stack: Vec<u32> = (0..self.twin.len() as u32)
            .filter(|&h| self.twin[h as usize] != NONE && h < self.twin[h as usize])
            .collect();
        let flips = self.lawson(polygon.points(), stack, max_flips, |_| false);
        self.out_on_boundary(polygon);
        flips
    }

    /// Whether the twins are mutual and join the same two vertices in opposite directions.
    #[cfg(test)]
    pub(crate) fn consistent(&self) -> Result<(), String> {
        for h in 0..self.twin.len() {
            let Some(g) = self.twin_of(h) else { continue };
            if self.twin[g] as usize != h
                || (self.tail(g), self.head(g)) != (self.head(h), self.tail(h))
            {
                return Err(format!("{h}: bad twin {g}"));
            }
        }
        Ok(())
    }

    /// Panics unless the links are consistent and [`Mesh::out`] holds each vertex's boundary
    /// edge `v -> next(v)` (a walking mesh of `polygon`).
    #[cfg(test)]
    pub fn check_invariants<P: Coord>(&self, polygon: &Polygon<P>) {
        assert_eq!(self.twin.len(), 3 * self.tri.len());
        self.consistent().unwrap();
        for v in 0..polygon.len() {
            let h = self.out(v).expect("a boundary half-edge");
            assert_eq!((self.tail(h), self.head(h)), (v, polygon.next(v)));
            assert_eq!(self.twin_of(h), None);
        }
    }
}

/// An inconsistency a caller's construction must not meet: a segment through a vertex or across a
/// fixed or boundary edge, stuck flips, a missing edge (see the callers' module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Broken;

fn key(from: usize, to: usize) -> u64 {
    ((from as u64) << 32) | to as u64
}

/// Flips (or walk steps) between two readings of the clock against [`Constrained::deadline`].
const CHECK_EVERY: usize = 1024;

/// A [`Mesh`] edited by segments: with its points and every half-edge found by its ends (see
/// the module docs). Reads go to the mesh (`Deref`); edits through here keep the index.
pub(crate) struct Constrained<'a, P: Coord = Point> {
    pts: &'a [P],
    mesh: Mesh,
    /// Every half-edge by its ends (`from << 32 | to`).
    halves: NumberMap<u64, u32>,
    /// The number of fixed edges.
    pub(crate) fixed_edges: usize,
    /// When set: past this instant, [`Constrained::insert`] and [`Constrained::fatten`] give up
    /// ([`Broken`] from `insert`, with [`Constrained::expired`] set), checked every
    /// [`CHECK_EVERY`] flips.
    pub(crate) deadline: Option<Instant>,
    /// Whether a walk or flip sequence gave up at [`Constrained::deadline`].
    pub(crate) expired: bool,
}

impl<P: Coord> std::ops::Deref for Constrained<'_, P> {
    type Target = Mesh;

    fn deref(&self) -> &Mesh {
        &self.mesh
    }
}

/// Whether `deadline` has passed (then `expired` is set too); reads the clock only when `count`
/// is a multiple of [`CHECK_EVERY`].
fn past(deadline: Option<Instant>, expired: &mut bool, count: usize) -> bool {
    if !*expired && count.is_multiple_of(CHECK_EVERY) {
        if let Some(deadline) = deadline {
            *expired = Instant::now() >= deadline;
        }
    }
    *expired
}

impl<'a, P: Coord> Constrained<'a, P> {
    /// The mesh of `triangles` (indices into `pts`, as the module's input contract says), with
    /// the undirected edges `fixed` fixed (each an edge of some triangle).
    pub(crate) fn new(pts: &'a [P], triangles: &[[usize; 3]], fixed: &[(usize, usize)]) -> Self {
        let mesh = Mesh::from_triangles(pts.len(), triangles);
        let mut edited = Constrained {
            pts,
            halves: NumberMap::with_capacity_and_hasher(3 * mesh.tri.len(), Default::default()),
            mesh,
            fixed_edges: 0,
            deadline: None,
            expired: false,
        };
        for t in 0..edited.mesh.tri.len() {
            edited.index(t);
        }
        for &(a, b) in fixed {
            if let Some(h) = edited.half_from(a, b) {
                edited.fix(h);
            }
        }
        edited
    }

    pub(crate) fn point(&self, v: usize) -> P {
        self.pts[v]
    }

    pub(crate) fn points(&self) -> &'a [P] {
        self.pts
    }

    /// The half-edge `u -> v`, if it is an edge with a triangle on its left.
    pub(crate) fn half_from(&self, u: usize, v: usize) -> Option<usize> {
        self.halves.get(&key(u, v)).map(|&h| h as usize)
    }

    /// Whether `u v` is a fixed edge.
    pub(crate) fn is_fixed_edge(&self, u: usize, v: usize) -> bool {
        self.half_from(u, v)
            .or_else(|| self.half_from(v, u))
            .is_some_and(|h| self.is_fixed(h))
    }

    /// Marks the face on the left of `h` finished.
    pub(crate) fn set_done(&mut self, h: usize) {
        self.mesh.set_done(h);
    }

    /// Makes the edge of `h` fixed (both sides).
    fn fix(&mut self, h: usize) {
        if self.mesh.fix(h) {
            self.fixed_edges += 1;
        }
    }

    /// Lists the half-edges of triangle `t` by their ends.
    fn index(&mut self, t: usize) {
        for h in 3 * t..3 * t + 3 {
            let k = key(self.tail(h), self.head(h));
            self.halves.insert(k, h as u32);
        }
    }

    fn unindex(&mut self, t: usize) {
        for h in 3 * t..3 * t + 3 {
            let k = key(self.tail(h), self.head(h));
            self.halves.remove(&k);
        }
    }

    /// [`Mesh::flip`], keeping the index.
    fn flip(&mut self, h: usize, g: usize) {
        let (t, s) = (h / 3, g / 3);
        self.unindex(t);
        self.unindex(s);
        self.mesh.flip(h);
        self.index(t);
        self.index(s);
    }

    /// The half-edges leaving `u`, in rotation order (counter-clockwise, starting after a
    /// boundary edge if `u` is on the region's boundary).
    fn around(&self, u: usize) -> Vec<usize> {
        let Some(start) = self.out(u) else {
            return Vec::new();
        };
        // Clockwise to the first half-edge (or all the way round).
        let mut first = start;
        while let Some(g) = self.twin_of(first) {
            let cw = Mesh::next_in_triangle(g);
            if cw == start {
                break;
            }
            first = cw;
        }
        self.fan(first).collect()
    }

    /// Whether [`Constrained::deadline`] has passed (then [`Constrained::expired`] is set too);
    /// reads the clock only when `count` is a multiple of [`CHECK_EVERY`].
    pub(crate) fn past_deadline(&mut self, count: usize) -> bool {
        past(self.deadline, &mut self.expired, count)
    }

    /// Fattens the triangles by [`Mesh::lawson`]'s flips, at most `max_flips`, which only makes
    /// walks shorter. Stops at [`Constrained::deadline`] too.
    pub(crate) fn fatten(&mut self, max_flips: usize) {
        let stack: Vec<u32> = (0..self.mesh.twin.len() as u32).collect();
        let (deadline, expired) = (self.deadline, &mut self.expired);
        self.mesh.lawson(self.pts, stack, max_flips, |count| {
            past(deadline, expired, count)
        });
        self.halves.clear();
        for t in 0..self.mesh.tri.len() {
            self.index(t);
        }
    }

    /// Makes segment `s e` a fixed edge: fixes it if it is an edge, inserts it otherwise.
    /// Refused if it passes through a vertex or crosses a fixed edge.
    /// Refused too once [`Constrained::deadline`] has passed during its flips
    /// ([`Constrained::expired`]).
    pub(crate) fn insert(&mut self, s: usize, e: usize) -> Result<(), Broken> {
        let Some(crossed) = self.crossed_by(s, e)? else {
            return Ok(());
        };
        let left = self.flip_out(s, e, crossed)?;
        self.flip_across(s, e, left)?;
        let h = self.half_from(s, e).ok_or(Broken)?;
        self.fix(h);
        Ok(())
    }

    /// The diagonals the segment `s e` crosses, in order from `s`, each from its right end to
    /// its left end; `None` if `s e` is an edge already (then fixed). Refused if the segment
    /// passes through a vertex or crosses a fixed or boundary edge.
    fn crossed_by(&mut self, s: usize, e: usize) -> Result<Option<Vec<(usize, usize)>>, Broken> {
        let (ps, pe) = (self.point(s), self.point(e));
        if let Some(h) = self.half_from(s, e).or_else(|| self.half_from(e, s)) {
            self.fix(h);
            return Ok(None);
        }
        let mut start = None;
        for h in self.around(s) {
            let (q, r) = (self.head(h), self.apex(h));
            if q == e {
                self.fix(h);
                return Ok(None);
            }
            if r == e {
                self.fix(Mesh::prev_in_triangle(h));
                return Ok(None);
            }
            let (pq, pr) = (self.point(q), self.point(r));
            if cross(ps, pq, pe) == 0 && dot(ps, pq, pe) > 0 {
                return Err(Broken); // along an edge to another vertex: a vertex on the segment
            }
            if cross(ps, pq, pe) > 0 && cross(ps, pe, pr) > 0 {
                start = Some(h);
            }
        }
        let h = start.ok_or(Broken)?;
        // Walk along s -> e.
        let mut crossed: Vec<(usize, usize)> = Vec::new();
        let mut crossing = Mesh::next_in_triangle(h);
        loop {
            if self.is_fixed(crossing) {
                return Err(Broken);
            }
            crossed.push((self.tail(crossing), self.head(crossing)));
            let g = self.twin_of(crossing).ok_or(Broken)?;
            let z = self.apex(g);
            if z == e {
                return Ok(Some(crossed));
            }
            let side = cross(ps, pe, self.point(z));
            if side > 0 {
                crossing = Mesh::next_in_triangle(g); // from the right end to z
            } else if side < 0 {
                crossing = Mesh::prev_in_triangle(g); // from z to the left end
            } else {
                return Err(Broken);
            }
        }
    }

    /// The two triangles on the diagonal `a -> b`: its half-edges and their apexes `c` (on its
    /// left) and `d`, and whether the quadrilateral `a d b c` is strictly convex (flippable).
    fn quadrilateral(
        &self,
        a: usize,
        b: usize,
    ) -> Result<(usize, usize, usize, usize, bool), Broken> {
        let h = self.half_from(a, b).ok_or(Broken)?;
        let g = self.twin_of(h).ok_or(Broken)?;
        let (c, d) = (self.apex(h), self.apex(g));
        let (pc, pd) = (self.point(c), self.point(d));
        let (sa, sb) = (cross(pc, pd, self.point(a)), cross(pc, pd, self.point(b)));
        Ok((h, g, c, d, sa != 0 && sb != 0 && (sa > 0) != (sb > 0)))
    }

    /// Flips the diagonals `crossed` (in order along `s -> e`, each from its right end to its
    /// left end) whose flip leaves the segment crossing one diagonal fewer: those whose
    /// quadrilateral is strictly convex and whose two apexes are `s` or `e` or on one side of
    /// the segment; returns those left, in order. Usually none is left; but a segment can cross
    /// diagonals none of which can go this way (each flippable one has its apexes on opposite
    /// sides of the segment; see the tests), and then [`Constrained::flip_across`] takes over.
    ///
    /// A flip changes the quadrilaterals of the diagonal's two neighbours in the list only, so
    /// only those are tested again: O(k) tests and at most k flips in all.
    fn flip_out(
        &mut self,
        s: usize,
        e: usize,
        crossed: Vec<(usize, usize)>,
    ) -> Result<VecDeque<(usize, usize)>, Broken> {
        const END: usize = usize::MAX;
        let (ps, pe) = (self.point(s), self.point(e));
        let k = crossed.len();
        let mut prev: Vec<usize> = (0..k).map(|i| i.checked_sub(1).unwrap_or(END)).collect();
        let mut next: Vec<usize> = (1..=k).map(|i| if i == k { END } else { i }).collect();
        let mut alive = vec![true; k];
        let mut waiting = vec![true; k];
        let mut work: Vec<usize> = (0..k).rev().collect();
        while let Some(i) = work.pop() {
            waiting[i] = false;
            let (a, b) = crossed[i];
            let (h, g, c, d, convex) = self.quadrilateral(a, b)?;
            let side = |v: usize| cross(ps, pe, self.point(v)) > 0;
            let one_side = [c, d].iter().any(|v| *v == s || *v == e) || side(c) == side(d);
            if !(convex && one_side) {
                continue;
            }
            self.flip(h, g);
            alive[i] = false;
            let (p, n) = (prev[i], next[i]);
            if p != END {
                next[p] = n;
            }
            if n != END {
                prev[n] = p;
            }
            for j in [p, n] {
                if j != END && !waiting[j] {
                    waiting[j] = true;
                    work.push(j);
                }
            }
        }
        Ok(crossed
            .into_iter()
            .zip(alive)
            .filter_map(|(edge, alive)| alive.then_some(edge))
            .collect())
    }

    /// Sloan's insertion ("A fast algorithm for generating constrained Delaunay
    /// triangulations", Comput. Struct. 47 (1993) 441-450) on the diagonals `crossed` (in
    /// order, as [`Constrained::flip_out`] left them): flip any crossed diagonal whose
    /// quadrilateral is strictly convex (one always is), queueing the new one if it still
    /// crosses, until none is left. O(k^2) at worst.
    fn flip_across(
        &mut self,
        s: usize,
        e: usize,
        mut crossed: VecDeque<(usize, usize)>,
    ) -> Result<(), Broken> {
        let (ps, pe) = (self.point(s), self.point(e));
        let mut stuck = 0;
        let mut count = 0;
        while let Some((a, b)) = crossed.pop_front() {
            count += 1;
            if self.past_deadline(count) {
                return Err(Broken);
            }
            let (h, g, c, d, convex) = self.quadrilateral(a, b)?;
            if !convex {
                crossed.push_back((a, b));
                stuck += 1;
                if stuck > crossed.len() {
                    return Err(Broken);
                }
                continue;
            }
            stuck = 0;
            self.flip(h, g);
            if c != s && c != e && d != s && d != e {
                let (pc, pd) = (self.point(c), self.point(d));
                let (sc, sd) = (cross(ps, pe, pc), cross(ps, pe, pd));
                let (ts, te) = (cross(pc, pd, ps), cross(pc, pd, pe));
                if sc.signum() * sd.signum() < 0 && ts.signum() * te.signum() < 0 {
                    crossed.push_back((c, d));
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geom::polygon::Polygon;
    use crate::test_support::{pinched_round_a_hole, vertex_at};

    /// The mesh of [`pinched_round_a_hole`], the ends of its pinched chord and the diagonals
    /// the chord crosses.
    fn pinched(poly: &Polygon) -> (Constrained<'_>, usize, usize, Vec<(usize, usize)>) {
        let (_, base) = pinched_round_a_hole();
        let mut mesh = Constrained::new(poly.points(), &base, &[]);
        let (s, e) = (vertex_at(poly, (-20, 0)), vertex_at(poly, (20, 0)));
        let crossed = mesh.crossed_by(s, e).unwrap().expect("not an edge yet");
        (mesh, s, e, crossed)
    }

    /// The segment `s e` is a fixed edge, the links are consistent, and the triangles are
    /// still a triangulation of the polygon (the independent checker).
    fn inserted(poly: &Polygon, mesh: &Constrained, s: usize, e: usize) {
        assert!(mesh.is_fixed_edge(s, e));
        mesh.consistent().unwrap();
        let triangles: Vec<[usize; 3]> = mesh.triangles().collect();
        assert_eq!(triangles.len(), poly.len() + 2 * poly.holes() - 2);
        let problems = crate::test_support::plain_problems(poly, triangles);
        assert!(problems.is_empty(), "{problems:?}");
    }

    #[test]
    fn the_walk_lists_the_diagonals_crossed_round_the_hole() {
        let (poly, _) = pinched_round_a_hole();
        let (_, _, _, crossed) = pinched(&poly);
        let at = |x| vertex_at(&poly, x);
        let (p, r, v, q, s2) = (
            at((-10, -10)),
            at((10, -10)),
            at((0, 10)),
            at((-2, 2)),
            at((2, 2)),
        );
        assert_eq!(crossed, [(p, v), (p, q), (r, q), (r, s2), (r, v)]);
    }

    #[test]
    fn flips_that_each_remove_a_crossing_insert_the_pinched_chord() {
        let (poly, _) = pinched_round_a_hole();
        let (mut mesh, s, e, crossed) = pinched(&poly);
        let left = mesh.flip_out(s, e, crossed).unwrap();
        assert!(left.is_empty(), "{left:?}");
        mesh.fix(mesh.half_from(s, e).expect("an edge after the flips"));
        inserted(&poly, &mesh, s, e);
    }

    #[test]
    fn sloans_queue_alone_inserts_the_pinched_chord() {
        let (poly, _) = pinched_round_a_hole();
        let (mut mesh, s, e, crossed) = pinched(&poly);
        mesh.flip_across(s, e, crossed.into()).unwrap();
        mesh.fix(mesh.half_from(s, e).expect("an edge after the flips"));
        inserted(&poly, &mesh, s, e);
    }

    /// The hexagon `s R1 R2 e L2 L1`, dented at `L1` and `R2`, triangulated `(s R1 L1)
    /// (R1 L2 L1) (R1 R2 L2) (R2 e L2)`: the chord `s e` crosses `R1 L1`, `R1 L2` and `R2 L2`. The
    /// first and last cannot be flipped (their quadrilaterals are not convex, at the dents), and
    /// flipping the middle one gives `R2 L1`, still crossing: no flip leaves one crossing
    /// fewer, so Sloan's queue must take over.
    #[test]
    fn a_chord_where_no_flip_removes_a_crossing_is_inserted_by_sloans_queue() {
        let (s, r1, r2, e, l2, l1) = ((0, 0), (2, -4), (6, -1), (8, 0), (4, 4), (2, 1));
        let poly = crate::test_support::polygon(&[&[s, r1, r2, e, l2, l1]]);
        let at = |x| vertex_at(&poly, x);
        let base: Vec<[usize; 3]> = [[s, r1, l1], [r1, l2, l1], [r1, r2, l2], [r2, e, l2]]
            .iter()
            .map(|t| t.map(at))
            .collect();
        let mut mesh = Constrained::new(poly.points(), &base, &[]);
        let crossed = mesh.crossed_by(at(s), at(e)).unwrap().unwrap();
        let expected = [(at(r1), at(l1)), (at(r1), at(l2)), (at(r2), at(l2))];
        assert_eq!(crossed, expected);
        let left = mesh.flip_out(at(s), at(e), crossed).unwrap();
        assert_eq!(left, expected, "nothing flipped");
        assert_eq!(mesh.triangles().collect::<Vec<_>>(), base);
        assert_eq!(mesh.insert(at(s), at(e)), Ok(()));
        inserted(&poly, &mesh, at(s), at(e));
    }

    #[test]
    fn a_chord_through_a_vertex_or_across_a_fixed_edge_is_refused() {
        let (poly, base) = pinched_round_a_hole();
        let at = |x| vertex_at(&poly, x);
        // From (-20, 0) to (40, 0): through the vertex (20, 0).
        let mut mesh = Constrained::new(poly.points(), &base, &[]);
        assert_eq!(mesh.insert(at((-20, 0)), at((40, 0))), Err(Broken));
        // Across the fixed diagonal (-10, -10)-(0, 10).
        let mut mesh = Constrained::new(poly.points(), &base, &[(at((-10, -10)), at((0, 10)))]);
        assert_eq!(mesh.insert(at((-20, 0)), at((20, 0))), Err(Broken));
    }
}
