//! A triangulation under edits, with some edges **fixed**: triangles with neighbour links, the
//! other edges plain diagonals that may be flipped. Shared by `--algorithm pseudo-hull`
//! ([`crate::algo::pseudo_hull`]: the convex hull triangulated; the polygon's edges, the hull
//! edges and each shortest path added so far fixed; faces walked across diagonals) and by
//! MINITRI with holes ([`crate::algo::minitri::cut`]: the sides of the chosen degenerate
//! triangles made edges of a plain triangulation of the polygon).
//!
//! Input contract: counter-clockwise nondegenerate triangles with disjoint interiors, meeting
//! edge to edge, whose union is a region in which every vertex has one fan of triangles (all
//! round it, or from one boundary edge to another: the region never touches itself at a
//! vertex). An edge with a triangle on one side only is on the region's boundary and is never
//! crossed.
//!
//! A half-edge is edge `k` of triangle `t`, from its vertex `k` to its vertex `k + 1`, with `t`
//! on its left. The faces of a pseudotriangulation are the unions of triangles joined across
//! diagonals; [`Mesh::next_boundary`] walks a face's boundary (face on the left), turning
//! clockwise around each vertex through the face's triangles, and reports the diagonals crossed.
//!
//! Segment insertion ([`Mesh::insert`]): the k diagonals the segment crosses are found by walking
//! along it, then flipped until the segment is an edge. First every flip that leaves one
//! crossing fewer is made, a diagonal being tested again only when a neighbour along the segment
//! was flipped: O(k) tests and at most k flips. That usually suffices (in MINITRI's cut step on
//! 2 * 10^5 random polygons with up to 12 holes, for all but 0.5% of the segments crossing a
//! diagonal), but not always: every flippable crossed diagonal can have its two apexes on
//! opposite sides of the segment (see the tests). Sloan's queue (1993) then finishes, flipping
//! any crossed diagonal whose quadrilateral is strictly convex: O(k^2) at worst. Removing the
//! crossed triangles and triangulating the two sides again would be about as fast but is wrong
//! in general: the triangles crossed on one side can go round a hole and touch at a vertex,
//! which no triangulator of simple polygons accepts (seen in pseudo-hull's property tests, and
//! in MINITRI's cut step before it used this mesh). Every decision is an exact orientation
//! test; a segment that would pass through a vertex or cross a fixed or boundary edge, or flips
//! that get stuck, are refused ([`Broken`]), never drawn.
//! [`Mesh::fatten`] flips diagonals towards the Delaunay triangulation with the kernel's
//! floating-point in-circle heuristic, which only steers speed (the allowed flips are decided
//! exactly).
//!
//! Complexity: O(m log m) to build for m triangles (half-edges sorted to link twins); a
//! half-edge found by its ends in expected O(1) (hash map); an insertion started in O(degree)
//! at its first vertex, O(k) to walk it, then the flips above.

use crate::algo::number_hash::NumberMap;
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cross, dot, incircle_approx, Point};
use std::collections::VecDeque;

const NONE: u32 = u32::MAX;

/// The neighbour links of a triangulation: for every half-edge `3 t + k` (side `k` of triangle
/// `t`, from its corner `k` to its corner `k + 1`; `corner(t, k)` gives the vertex, below
/// `vertices`), the half-edge of the other triangle on the same side, or `u32::MAX` where there
/// is none (the boundary). Shared with MINITRI's walking mesh (`minitri::expansion`).
///
/// The two half-edges of a side are found in the bucket of its lower end: half-edges bucketed
/// by that end (a counting sort), each bucket, a vertex's few sides, then sorted by the other
/// end. O(n) for bounded degrees, O(n log n) at worst.
pub(crate) fn twin_halves(
    vertices: usize,
    triangles: usize,
    corner: impl Fn(usize, usize) -> usize,
) -> Vec<u32> {
    let halves = 3 * triangles;
    let ends = |h: usize| {
        let (u, w) = (corner(h / 3, h % 3), corner(h / 3, (h + 1) % 3));
        (u.min(w), u.max(w) as u32)
    };
    let mut start = vec![0u32; vertices + 1];
    for h in 0..halves {
        start[ends(h).0 + 1] += 1;
    }
    for v in 0..vertices {
        start[v + 1] += start[v];
    }
    let mut bucket: Vec<(u32, u32)> = vec![(0, 0); halves];
    let mut fill = start.clone();
    for h in 0..halves {
        let (v, w) = ends(h);
        bucket[fill[v] as usize] = (w, h as u32);
        fill[v] += 1;
    }
    drop(fill);
    let mut twin = vec![NONE; halves];
    for v in 0..vertices {
        let group = &mut bucket[start[v] as usize..start[v + 1] as usize];
        group.sort_unstable();
        for pair in group.windows(2) {
            if pair[0].0 == pair[1].0 {
                twin[pair[0].1 as usize] = pair[1].1;
                twin[pair[1].1 as usize] = pair[0].1;
            }
        }
    }
    twin
}

/// An inconsistency a caller's construction must not meet: a segment through a vertex or across a
/// fixed or boundary edge, stuck flips, a missing edge (see the callers' module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Broken;

/// Edge `k` of triangle `t` (its vertex `k` to its vertex `k + 1`, the triangle on its left).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Half {
    t: u32,
    k: u8,
}

impl Half {
    fn next(self) -> Half {
        Half {
            t: self.t,
            k: (self.k + 1) % 3,
        }
    }

    fn prev(self) -> Half {
        Half {
            t: self.t,
            k: (self.k + 2) % 3,
        }
    }
}

fn key(from: usize, to: usize) -> u64 {
    ((from as u64) << 32) | to as u64
}

type Halves = NumberMap<u64, Half>;

/// Flag bits per triangle: bit `k` edge `k` fixed, bit `3 + k` the face on the left of edge `k`
/// finished (a pseudotriangle already reported).
const DONE: u8 = 8;

pub(crate) struct Mesh<'a, P: Coord = Point> {
    pts: &'a [P],
    tv: Vec<[u32; 3]>,
    tn: Vec<[u32; 3]>,
    flags: Vec<u8>,
    /// A live triangle at each vertex.
    vt: Vec<u32>,
    /// Every half-edge by its ends (`from << 32 | to`).
    halves: Halves,
    /// The number of fixed edges.
    pub(crate) fixed_edges: usize,
    /// When set: past this instant, [`Mesh::insert`] and [`Mesh::fatten`] give up ([`Broken`]
    /// from `insert`, with [`Mesh::expired`] set), checked every [`CHECK_EVERY`] flips.
    pub(crate) deadline: Option<std::time::Instant>,
    /// Whether a walk or flip sequence gave up at [`Mesh::deadline`].
    pub(crate) expired: bool,
}

/// Flips (or walk steps) between two readings of the clock against [`Mesh::deadline`].
const CHECK_EVERY: usize = 1024;

impl<'a, P: Coord> Mesh<'a, P> {
    /// The mesh of `triangles` (indices into `pts`, as the module's input contract says), with
    /// the undirected edges `fixed` fixed (each an edge of some triangle).
    pub(crate) fn new(pts: &'a [P], triangles: &[[usize; 3]], fixed: &[(usize, usize)]) -> Self {
        let m = triangles.len();
        let mut mesh = Mesh {
            pts,
            tv: triangles.iter().map(|t| t.map(|v| v as u32)).collect(),
            tn: vec![[NONE; 3]; m],
            flags: vec![0; m],
            vt: vec![NONE; pts.len()],
            halves: Halves::with_capacity_and_hasher(3 * m, Default::default()),
            fixed_edges: 0,
            deadline: None,
            expired: false,
        };
        for t in 0..m as u32 {
            mesh.index(t);
        }
        let twins = twin_halves(pts.len(), m, |t, k| mesh.tv[t][k] as usize);
        for (h, &g) in twins.iter().enumerate() {
            if g != NONE {
                mesh.tn[h / 3][h % 3] = g / 3;
            }
        }
        for (t, tri) in mesh.tv.iter().enumerate() {
            for &v in tri {
                mesh.vt[v as usize] = t as u32;
            }
        }
        for &(a, b) in fixed {
            if let Some(h) = mesh.half_from(a, b) {
                mesh.fix(h);
            }
        }
        mesh
    }

    pub(crate) fn origin(&self, h: Half) -> usize {
        self.tv[h.t as usize][h.k as usize] as usize
    }

    pub(crate) fn dest(&self, h: Half) -> usize {
        self.tv[h.t as usize][(h.k as usize + 1) % 3] as usize
    }

    pub(crate) fn point(&self, v: usize) -> P {
        self.pts[v]
    }

    pub(crate) fn points(&self) -> &'a [P] {
        self.pts
    }

    /// The triangles, counter-clockwise, as indices into the points.
    pub(crate) fn triangles(&self) -> impl Iterator<Item = [usize; 3]> + '_ {
        self.tv.iter().map(|t| t.map(|v| v as usize))
    }

    /// The same edge the other way, in the triangle on its right (none on the region's boundary).
    fn twin(&self, h: Half) -> Option<Half> {
        let t = self.tn[h.t as usize][h.k as usize];
        if t == NONE {
            return None;
        }
        let from = self.tv[h.t as usize][(h.k as usize + 1) % 3];
        let k = self.tv[t as usize].iter().position(|&v| v == from)?;
        Some(Half { t, k: k as u8 })
    }

    pub(crate) fn is_fixed(&self, h: Half) -> bool {
        self.flags[h.t as usize] & (1 << h.k) != 0
    }

    pub(crate) fn is_done(&self, h: Half) -> bool {
        self.flags[h.t as usize] & (DONE << h.k) != 0
    }

    pub(crate) fn set_done(&mut self, h: Half) {
        self.flags[h.t as usize] |= DONE << h.k;
    }

    /// Makes the edge of `h` fixed (both sides).
    fn fix(&mut self, h: Half) {
        if self.is_fixed(h) {
            return;
        }
        self.fixed_edges += 1;
        self.flags[h.t as usize] |= 1 << h.k;
        if let Some(g) = self.twin(h) {
            self.flags[g.t as usize] |= 1 << g.k;
        }
    }

    /// The half-edges leaving `u`, in rotation order (counter-clockwise, starting after a
    /// boundary edge if `u` is on the region's boundary).
    fn around(&self, u: usize) -> Vec<Half> {
        let t = self.vt[u];
        let Some(k) = self.tv[t as usize].iter().position(|&v| v as usize == u) else {
            return Vec::new();
        };
        let start = Half { t, k: k as u8 };
        // Clockwise to the first half-edge (or all the way round).
        let mut first = start;
        while let Some(g) = self.twin(first) {
            let cw = g.next();
            if cw == start {
                break;
            }
            first = cw;
        }
        let mut out = vec![first];
        let mut h = first;
        while let Some(g) = self.twin(h.prev()) {
            if g == first {
                break;
            }
            out.push(g);
            h = g;
        }
        out
    }

    /// The half-edge `u -> v`, if it is an edge with a triangle on its left.
    pub(crate) fn half_from(&self, u: usize, v: usize) -> Option<Half> {
        self.halves.get(&key(u, v)).copied()
    }

    /// Whether `u v` is a fixed edge.
    pub(crate) fn is_fixed_edge(&self, u: usize, v: usize) -> bool {
        self.half_from(u, v)
            .or_else(|| self.half_from(v, u))
            .is_some_and(|h| self.is_fixed(h))
    }

    /// Lists the half-edges of triangle `t` by their ends.
    fn index(&mut self, t: u32) {
        for k in 0..3u8 {
            let h = Half { t, k };
            self.halves.insert(key(self.origin(h), self.dest(h)), h);
        }
    }

    fn unindex(&mut self, t: u32) {
        for k in 0..3u8 {
            let h = Half { t, k };
            self.halves.remove(&key(self.origin(h), self.dest(h)));
        }
    }

    /// The next fixed half-edge along the boundary of the face on the left of the fixed
    /// half-edge `h` (turning clockwise round its head); the diagonals crossed on the way are
    /// passed to `crossed` as `(right, left)` = (the head of `h`, the diagonal's other end).
    pub(crate) fn next_boundary(&self, h: Half, mut crossed: impl FnMut(usize, usize)) -> Half {
        let mut g = h.next();
        while !self.is_fixed(g) {
            crossed(self.origin(g), self.dest(g));
            // A diagonal always has a triangle on both sides.
            g = match self.twin(g) {
                Some(t) => t.next(),
                None => return g,
            };
        }
        g
    }

    /// The fixed half-edge before `h` along the boundary of the face on its left.
    pub(crate) fn prev_boundary(&self, h: Half) -> Half {
        let mut g = h.prev();
        while !self.is_fixed(g) {
            g = match self.twin(g) {
                Some(t) => t.prev(),
                None => return g,
            };
        }
        g
    }

    /// Whether [`Mesh::deadline`] has passed (then [`Mesh::expired`] is set too); reads the clock
    /// only when `count` is a multiple of [`CHECK_EVERY`].
    pub(crate) fn past_deadline(&mut self, count: usize) -> bool {
        if !self.expired && count.is_multiple_of(CHECK_EVERY) {
            if let Some(deadline) = self.deadline {
                self.expired = std::time::Instant::now() >= deadline;
            }
        }
        self.expired
    }

    /// Makes segment `s e` a fixed edge: fixes it if it is an edge, inserts it otherwise.
    /// Refused if it passes through a vertex or crosses a fixed edge.
    /// Refused too once [`Mesh::deadline`] has passed during its flips ([`Mesh::expired`]).
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
            let (q, r) = (self.dest(h), self.dest(h.next()));
            if q == e {
                self.fix(h);
                return Ok(None);
            }
            if r == e {
                self.fix(h.prev());
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
        let mut crossing = h.next();
        loop {
            if self.is_fixed(crossing) {
                return Err(Broken);
            }
            crossed.push((self.origin(crossing), self.dest(crossing)));
            let g = self.twin(crossing).ok_or(Broken)?;
            let z = self.dest(g.next());
            if z == e {
                return Ok(Some(crossed));
            }
            let side = cross(ps, pe, self.point(z));
            if side > 0 {
                crossing = g.next(); // from the right end to z
            } else if side < 0 {
                crossing = g.prev(); // from z to the left end
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
    ) -> Result<(Half, Half, usize, usize, bool), Broken> {
        let h = self.half_from(a, b).ok_or(Broken)?;
        let g = self.twin(h).ok_or(Broken)?;
        let (c, d) = (self.dest(h.next()), self.dest(g.next()));
        let (pc, pd) = (self.point(c), self.point(d));
        let (sa, sb) = (cross(pc, pd, self.point(a)), cross(pc, pd, self.point(b)));
        Ok((h, g, c, d, sa != 0 && sb != 0 && (sa > 0) != (sb > 0)))
    }

    /// Flips the diagonals `crossed` (in order along `s -> e`, each from its right end to its
    /// left end) whose flip leaves the segment crossing one diagonal fewer: those whose
    /// quadrilateral is strictly convex and whose two apexes are `s` or `e` or on one side of
    /// the segment; returns those left, in order. Usually none is left; but a segment can cross
    /// diagonals none of which can go this way (each flippable one has its apexes on opposite
    /// sides of the segment; see the tests), and then [`Mesh::flip_across`] takes over.
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
    /// order, as [`Mesh::flip_out`] left them): flip any crossed diagonal whose quadrilateral
    /// is strictly convex (one always is), queueing the new one if it still crosses, until none
    /// is left. O(k^2) at worst.
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

    /// Fattens the triangles, which only makes walks shorter: Lawson's flips of diagonals
    /// towards the constrained Delaunay triangulation, at most `max_flips`. Whether a flip is ALLOWED is exact (the
    /// quadrilateral strictly convex, so the result is again a triangulation with the same
    /// fixed edges); whether it is DESIRABLE is [`incircle_approx`], a heuristic that never
    /// decides a fact of the answer (hence the bound on the flips, should rounding make them
    /// cycle). Stops at [`Mesh::deadline`] too.
    pub(crate) fn fatten(&mut self, max_flips: usize) {
        let mut stack: Vec<Half> = (0..self.tv.len() as u32)
            .flat_map(|t| (0..3u8).map(move |k| Half { t, k }))
            .collect();
        let mut flips = 0;
        let mut count = 0;
        while let Some(h) = stack.pop() {
            count += 1;
            if flips == max_flips || self.past_deadline(count) {
                break;
            }
            if self.is_fixed(h) {
                continue;
            }
            let Some(g) = self.twin(h) else { continue };
            let (a, b) = (self.origin(h), self.dest(h));
            let (c, d) = (self.dest(h.next()), self.dest(g.next()));
            let [pa, pb, pc, pd] = [a, b, c, d].map(|v| self.point(v));
            if cross(pc, pa, pd) <= 0 || cross(pd, pb, pc) <= 0 {
                continue;
            }
            if incircle_approx(pa, pb, pc, pd) <= 0.0 {
                continue;
            }
            self.flip(h, g);
            flips += 1;
            let (t1, t2) = (h.t, g.t);
            stack.extend([(t1, 0), (t1, 1), (t2, 0), (t2, 1)].map(|(t, k)| Half { t, k }));
        }
    }

    /// Flips the diagonal of `h` (`a -> b`, triangle `a b c`) and its twin `g` (`b a d`) to
    /// `c d`: the triangles become `c a d` and `d b c`.
    fn flip(&mut self, h: Half, g: Half) {
        let (t1, t2) = (h.t, g.t);
        let (a, b) = (self.origin(h), self.dest(h));
        let (c, d) = (self.dest(h.next()), self.dest(g.next()));
        // The outer edges: (neighbour, fixed) of c -> a, a -> d, d -> b, b -> c.
        let side = |mesh: &Self, x: Half| {
            (
                mesh.tn[x.t as usize][x.k as usize],
                mesh.is_fixed(x),
                mesh.is_done(x),
            )
        };
        let ca = side(self, h.prev());
        let ad = side(self, g.next());
        let db = side(self, g.prev());
        let bc = side(self, h.next());
        self.unindex(t1);
        self.unindex(t2);
        self.tv[t1 as usize] = [c as u32, a as u32, d as u32];
        self.tv[t2 as usize] = [d as u32, b as u32, c as u32];
        self.index(t1);
        self.index(t2);
        self.tn[t1 as usize] = [ca.0, ad.0, t2];
        self.tn[t2 as usize] = [db.0, bc.0, t1];
        let bits =
            |x: (u32, bool, bool), k: u8| (u8::from(x.1) << k) | ((u8::from(x.2) * DONE) << k);
        self.flags[t1 as usize] = bits(ca, 0) | bits(ad, 1);
        self.flags[t2 as usize] = bits(db, 0) | bits(bc, 1);
        // The neighbours across a -> d and b -> c changed triangle.
        for (n, (u, v), to) in [(ad.0, (d, a), t1), (bc.0, (c, b), t2)] {
            if n != NONE {
                let tri = self.tv[n as usize];
                for k in 0..3 {
                    if tri[k] as usize == u && tri[(k + 1) % 3] as usize == v {
                        self.tn[n as usize][k] = to;
                    }
                }
            }
        }
        for v in [a, c, d] {
            self.vt[v] = t1;
        }
        self.vt[b] = t2;
    }

    #[cfg(test)]
    pub(crate) fn consistent(&self) -> Result<(), String> {
        for t in 0..self.tv.len() as u32 {
            for k in 0..3u8 {
                let h = Half { t, k };
                let n = self.tn[t as usize][k as usize];
                if n == NONE {
                    continue;
                }
                let Some(g) = self.twin(h) else {
                    return Err(format!("{t}/{k} no twin"));
                };
                if self.dest(g) != self.origin(h) || self.tn[g.t as usize][g.k as usize] != t {
                    return Err(format!(
                        "{t}/{k} bad twin {:?} {:?}",
                        self.tv[t as usize], self.tv[n as usize]
                    ));
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
    fn pinched(poly: &Polygon) -> (Mesh<'_>, usize, usize, Vec<(usize, usize)>) {
        let (_, base) = pinched_round_a_hole();
        let mut mesh = Mesh::new(poly.points(), &base, &[]);
        let (s, e) = (vertex_at(poly, (-20, 0)), vertex_at(poly, (20, 0)));
        let crossed = mesh.crossed_by(s, e).unwrap().expect("not an edge yet");
        (mesh, s, e, crossed)
    }

    /// The segment `s e` is a fixed edge, the links are consistent, and the triangles are
    /// still a triangulation of the polygon (the independent checker).
    fn inserted(poly: &Polygon, mesh: &Mesh, s: usize, e: usize) {
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
        let mut mesh = Mesh::new(poly.points(), &base, &[]);
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
        let mut mesh = Mesh::new(poly.points(), &base, &[]);
        assert_eq!(mesh.insert(at((-20, 0)), at((40, 0))), Err(Broken));
        // Across the fixed diagonal (-10, -10)-(0, 10).
        let mut mesh = Mesh::new(poly.points(), &base, &[(at((-10, -10)), at((0, 10)))]);
        assert_eq!(mesh.insert(at((-20, 0)), at((20, 0))), Err(Broken));
    }
}
