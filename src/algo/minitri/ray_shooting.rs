//! Ray shooting from a vertex over a triangulation, in O(log^2 n) per ray after O(n log n)
//! preprocessing, or O(log n) amortized per ray for a batch shot in order of direction, with
//! orientation tests only: for the rays of step 1 of MINITRI (Chen & Chang 1990, §3, Step 1,
//! which shoots rays from reflex vertices along directions given by two vertices; the paper uses
//! Chazelle and Guibas' procedure, O(log n) per ray; this is a simpler one, as fast for the
//! batches of the bounded method, [`super::polygon_cutting`]).
//!
//! A ray from vertex `b` in direction `d` inside a triangulated polygon crosses a sequence of
//! triangles, a path in the dual tree (degree at most 3), until it meets a vertex exactly (the
//! nearest vertex in that direction: the answer) or leaves through a polygon edge (no vertex).
//! Walking it triangle by triangle costs the length of that path, which is linear on long thin
//! pieces (the base of a comb, the interior of a sliver staircase: every triangle there is a
//! long sliver). Instead, the dual tree is cut into heavy paths (each triangle continues the
//! path of its child with the largest subtree; any path in the tree meets O(log n) heavy paths).
//! Along one heavy path `T_0, T_1, ..`, the diagonal `h_i` between `T_i` and `T_(i+1)` is
//! crossed by the ray, going down, exactly when its tail lies strictly right of the ray's line
//! and its head strictly left; and a ray crossing `h_i, .., h_(j-1)` in turn runs inside those
//! triangles (a line crosses a triangle's boundary twice: once in, once out), so it reaches
//! `T_j`. The first `j` where this fails is found by a search tree over the tails (and one over
//! the heads) of the path whose nodes hold the convex hull of their range: whether some point
//! of a range lies on the closed wrong side of the line is read at the hull's extreme vertex,
//! found by binary search on the one chain that holds it, upper or lower by the ray's direction
//! (the edge directions of a chain turn monotonically within a half-turn, so the side changes
//! at most once along it). Going up is the mirror image. In `T_j` one step decides: the apex on
//! the line is the answer, else the ray leaves by one of two sides, to a polygon edge (no
//! vertex) or into a triangle of another heavy path.
//!
//! The search trees are biased: the link `h_j` weighs the triangles hanging off `T_j` and
//! `T_(j+1)` by light children (plus the path's mean), and a node splits its range where half
//! its weight is reached, so a link of weight `w` on a path of weight `W` lies O(log(W / w))
//! deep. A ray enters a heavy path at its top (a prefix is searched, from the root down to the
//! answer) or from a light subtree of some `T_i` (the search starts at `h_i` or `h_(i-1)`, whose
//! weight is at least that subtree's size), and leaves it into a light subtree of the answer's
//! triangle; so the depths telescope over the heavy paths one ray meets, O(log n) nodes in all,
//! each tested in O(log n): O(log^2 n) per ray.
//!
//! In order of direction: the extreme point of a chain in the direction normal to the ray moves
//! one way along the chain as the direction turns. So each chain of more than 16 points keeps a
//! finger where its last search ended ([`Shooter::shoot_with`]), and a search gallops from it
//! (steps of 1, 2, 4, .. towards the answer, then halving): O(1 + log(1 + k)) tests for an
//! answer `k` places away. A chain serves the rays pointing into one half-plane, and the
//! searches going up use the opposite directions; over a batch sorted by direction from any
//! start, the directions a chain sees form at most three arcs, along each of which its finger
//! moves one way: so the batch's hull tests cost O(1) per node visited plus three times the
//! chains' total length, O(n log n), and O(log n) per ray amortized over a batch of Omega(n)
//! rays. The fingers only decide where a search starts, never what it finds.
//!
//! Exact: every decision is the sign of a cross product of two differences of input points
//! ([`Dir::cross`]), in both kernels; no intersection point and no ray parameter is computed.
//!
//! ```text
//!      heavy path T_0 .. T_5, the ray from b crossing h_1 .. h_3 (tails x right, heads o left)
//!
//!        o-------o-------o-------o           o: heads of h_i, left of the ray
//!       / \ T_1 / \ T_3 / \ T_5 /
//!  b ==/===\===/===\===/===\===/====>        the ray, skipping T_2 .. T_4 by two hull tests
//!     / T_0 \ / T_2 \ / T_4 \ /
//!    x-------x-------x-------x               x: tails of h_i, right of the ray
//! ```

use super::expansion::{Mesh, ISOLATE_AFTER};
use crate::geom::kernel::{Coord, Dir};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
use std::sync::OnceLock;

/// When rays are walked and when they are shot ([`Lazy`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayPolicy {
    /// The default hybrid: the walk from a vertex cuts its parts into rays once it has crossed
    /// [`ISOLATE_AFTER`] triangles; every ray walks [`RAY_WALK`] triangles, and a longer one is
    /// shot once long walks have crossed [`BUILD_AFTER`] triangles per vertex in all.
    Hybrid,
    /// The walk alone (budget unlimited): parts never cut into rays, nothing shot.
    WalkOnly,
    /// The rays at once (budget 0): parts cut into rays from the start, every ray shot from its
    /// first triangle on (the shooter built at the first ray).
    ShootOnly,
}

/// How many triangles a ray walks before asking for the shooter (in [`RayPolicy::Hybrid`]).
pub const RAY_WALK: usize = 32;

/// Long-ray triangles walked per vertex before the shooter is built (its O(n log n)
/// preprocessing then costs about as much as the walking done so far).
pub const BUILD_AFTER: usize = 8;

/// A [`Shooter`] built on first need, shared by the threads searching one polygon, following a
/// [`RayPolicy`]: by default only once rays walked triangle by triangle have crossed, beyond
/// their first [`RAY_WALK`] triangles each, [`BUILD_AFTER`] triangles per vertex in all, so
/// that polygons whose rays are short never pay for it (the walk first, with a budget; the
/// bounded method for the rest).
pub struct Lazy {
    cell: OnceLock<Shooter>,
    walked: AtomicUsize,
    threshold: usize,
    first_ask: usize,
    isolate_after: usize,
    budget: usize,
    shot_cost: usize,
}

impl Lazy {
    /// Nothing built yet, for a polygon of `n` vertices.
    pub fn new(n: usize, policy: RayPolicy) -> Lazy {
        let (threshold, first_ask, isolate_after) = match policy {
            RayPolicy::Hybrid => (BUILD_AFTER.saturating_mul(n), RAY_WALK, ISOLATE_AFTER),
            RayPolicy::WalkOnly => (usize::MAX, usize::MAX, usize::MAX),
            RayPolicy::ShootOnly => (0, 0, 0),
        };
        Lazy {
            cell: OnceLock::new(),
            walked: AtomicUsize::new(0),
            threshold,
            first_ask,
            isolate_after,
            budget: usize::MAX,
            shot_cost: (usize::BITS - n.max(2).leading_zeros()) as usize,
        }
    }

    /// The same, walks from one vertex given up after `budget` triangles (`usize::MAX`: never;
    /// 0: no walk at all), the vertex then left to the bounded method
    /// ([`super::polygon_cutting`]).
    pub fn with_budget(self, budget: usize) -> Lazy {
        Lazy { budget, ..self }
    }

    /// After how many triangles walked from one vertex the walk gives up.
    pub fn budget(&self) -> usize {
        self.budget
    }

    /// What a shot ray counts against the budget, in triangles: `ceil(log2 n)` (a shot is
    /// O(log^2 n), a triangle walked O(1)); 0 without a budget.
    pub fn shot_cost(&self) -> usize {
        if self.budget == usize::MAX {
            0
        } else {
            self.shot_cost
        }
    }

    /// The shooter, built now if it was not.
    pub fn force<P: Coord>(&self, polygon: &Polygon<P>, mesh: &Mesh) -> &Shooter {
        self.cell.get_or_init(|| Shooter::new(polygon, mesh))
    }

    /// After how many triangles walked from one vertex its parts may be cut into rays
    /// (`usize::MAX`: never).
    pub fn isolate_after(&self) -> usize {
        self.isolate_after
    }

    /// After how many triangles a ray first asks for the shooter (`usize::MAX`: never).
    pub fn first_ask(&self) -> usize {
        self.first_ask
    }

    /// The shooter, if built, or if `steps` more triangles walked by long rays bring the total
    /// to the threshold (then built here, once).
    pub fn get<P: Coord>(
        &self,
        polygon: &Polygon<P>,
        mesh: &Mesh,
        steps: usize,
    ) -> Option<&Shooter> {
        if let Some(shooter) = self.cell.get() {
            return Some(shooter);
        }
        let total = self.walked.fetch_add(steps, Relaxed).saturating_add(steps);
        if total < self.threshold {
            return None;
        }
        Some(self.cell.get_or_init(|| Shooter::new(polygon, mesh)))
    }
}

/// A ray shooter over a fixed triangulation (the walk's [`Mesh`], after its flips).
pub struct Shooter {
    /// For each triangle, its heavy path and its position on it.
    place: Vec<(u32, u32)>,
    /// The heavy paths.
    paths: Vec<HeavyPath>,
    /// How many fingers [`Shooter::shoot_with`] may use: two per hull node with a chain of
    /// more than 16 points (its range holds more than 16 points: about one node in 16 of a
    /// balanced tree, so a finger buffer is a fraction of the shooter's own size).
    fingers: usize,
}

/// Where the last search on each long chain of the hull nodes ended ([`Shooter::shoot_with`]):
/// two per node with a chain of more than 16 points. Any values are valid starts (they only
/// decide how long a search takes, never what it finds), so one buffer serves every shooter in
/// turn.
pub type Fingers = [u32];

/// One heavy path `T_0, .., T_m` (from the top): the half-edges `h_i` of `T_i` whose twin lies
/// in `T_(i+1)`, with hull trees over their tails and their heads.
struct HeavyPath {
    links: Vec<u32>,
    tails: HullTree,
    heads: HullTree,
}

impl Shooter {
    /// Preprocesses the triangulation: heavy paths of the dual tree, hull trees along them.
    /// O(n log n) time and memory.
    pub fn new<P: Coord>(polygon: &Polygon<P>, mesh: &Mesh) -> Shooter {
        let triangles = mesh.triangle_count();
        // The dual tree (a spanning tree of the dual graph with holes): parents and a preorder,
        // iteratively.
        let mut parent = vec![u32::MAX; triangles];
        let mut order = Vec::with_capacity(triangles);
        let mut seen = vec![false; triangles];
        let mut stack = Vec::new();
        // From every triangle not reached yet (one root for a connected region; a forest
        // otherwise, so that every triangle is on some heavy path).
        for root in 0..triangles {
            if seen[root] {
                continue;
            }
            seen[root] = true;
            stack.push(root);
            while let Some(t) = stack.pop() {
                order.push(t);
                for k in 0..3 {
                    if let Some(g) = mesh.twin_of(3 * t + k) {
                        let s = g / 3;
                        if !seen[s] {
                            seen[s] = true;
                            parent[s] = t as u32;
                            stack.push(s);
                        }
                    }
                }
            }
        }
        let mut size = vec![1u32; triangles];
        for &t in order.iter().rev() {
            if let Some(&p) = parent.get(t) {
                if p != u32::MAX {
                    size[p as usize] += size[t];
                }
            }
        }
        // The heavy child of each triangle, as the half-edge leading to it.
        let mut heavy = vec![u32::MAX; triangles];
        for (t, heavy) in heavy.iter_mut().enumerate() {
            let mut best = 0;
            for k in 0..3 {
                if let Some(g) = mesh.twin_of(3 * t + k) {
                    let s = g / 3;
                    if parent[s] == t as u32 && size[s] > best {
                        best = size[s];
                        *heavy = (3 * t + k) as u32;
                    }
                }
            }
        }
        let mut place = vec![(u32::MAX, u32::MAX); triangles];
        let mut paths = Vec::new();
        // The finger slots handed out so far, through all paths (`HullTree::new`).
        let mut fingers = 0;
        for &top in &order {
            if place[top].0 != u32::MAX {
                continue; // on the path of an earlier triangle
            }
            let id = paths.len() as u32;
            let mut links = Vec::new();
            // Per triangle of the path, the triangles hanging off it by light children, itself
            // included (its subtree without its heavy child's).
            let mut light = Vec::new();
            let mut t = top;
            loop {
                place[t] = (id, links.len() as u32);
                let h = heavy[t];
                let below = match h {
                    u32::MAX => 0,
                    h => mesh.twin_of(h as usize).map_or(0, |g| size[g / 3]),
                };
                light.push(u64::from(size[t] - below));
                if h == u32::MAX {
                    break;
                }
                links.push(h);
                match mesh.twin_of(h as usize) {
                    Some(g) => t = g / 3,
                    None => break,
                }
            }
            // Link h_j weighs what hangs off its two triangles, plus the path's mean (which
            // keeps the tree about balanced where the weights are even, and at most doubles
            // the total): a ray entering T_i from a light subtree searches from h_i (down) or
            // h_(i-1) (up), and leaves T_j into one by h_j or h_(j-1), so each search costs
            // O(log) of the path's weight over the subtree it came from or goes to, and over
            // the heavy paths one ray meets these telescope to O(log n) nodes (biased search
            // trees). A ray entering the path at its top searches a prefix, with no start.
            let total: u64 = light.iter().sum();
            let mean = total / light.len().max(1) as u64;
            let weights: Vec<u64> = light.windows(2).map(|w| w[0] + w[1] + mean).collect();
            let ends = |tail: bool| -> Vec<usize> {
                links
                    .iter()
                    .map(|&h| {
                        let h = h as usize;
                        if tail {
                            mesh.tail(h)
                        } else {
                            mesh.head(h)
                        }
                    })
                    .collect()
            };
            let tails = HullTree::new(polygon, &ends(true), &weights, &mut fingers);
            let heads = HullTree::new(polygon, &ends(false), &weights, &mut fingers);
            paths.push(HeavyPath {
                links,
                tails,
                heads,
            });
        }
        Shooter {
            place,
            paths,
            fingers,
        }
    }

    /// How long a buffer of [`Fingers`] [`Shooter::shoot_with`] uses (a shorter one is used
    /// as far as it goes).
    pub fn finger_count(&self) -> usize {
        self.fingers
    }

    /// The first vertex met exactly by the ray from vertex `b` in direction `d`, the ray having
    /// entered the triangle of half-edge `g` through that half-edge (strictly between its ends,
    /// as in the walk of [`super::expansion`]); `None` if it leaves through a polygon edge first.
    /// O(log^2 n): each hull test a binary search.
    pub fn shoot<P: Coord>(
        &self,
        polygon: &Polygon<P>,
        mesh: &Mesh,
        b: usize,
        d: Dir<P>,
        g: usize,
    ) -> Option<usize> {
        self.shoot_with(polygon, mesh, b, d, g, &mut [])
    }

    /// [`Shooter::shoot`], each hull test searching its chain from where the last search on
    /// that chain ended (`fingers`), by doubling steps then halving: O(log(1 + k)) tests for an
    /// extreme point `k` places away. The extreme point of a chain in the direction normal to
    /// `d` moves one way along it as `d` turns, so rays shot in order of direction move each
    /// finger across its chain a bounded number of times (`super::polygon_cutting` shoots each
    /// level's rays so): O(log n) nodes per ray at O(1) amortized each, plus the chains' total
    /// length, instead of O(log^2 n) per ray.
    pub fn shoot_with<P: Coord>(
        &self,
        polygon: &Polygon<P>,
        mesh: &Mesh,
        b: usize,
        d: Dir<P>,
        mut g: usize,
        fingers: &mut Fingers,
    ) -> Option<usize> {
        let pb = polygon.point(b);
        let side = |v: usize| d.cross(Dir::between(pb, polygon.point(v)));
        // The side the ray leaves the triangle of `g` by, or the apex it meets.
        let exit = |g: usize| -> Result<usize, usize> {
            let x = mesh.apex(g);
            match side(x) {
                0 => Err(x),
                s if s < 0 => Ok(Mesh::next_in_triangle(Mesh::next_in_triangle(g))),
                _ => Ok(Mesh::next_in_triangle(g)),
            }
        };
        loop {
            let k = match exit(g) {
                Err(x) => return Some(x),
                Ok(k) => k,
            };
            // Along the heavy path of this triangle, if the ray follows it.
            let t = g / 3;
            let (id, i) = self.place[t];
            let path = &self.paths[id as usize];
            let i = i as usize;
            if path.links.get(i).is_some_and(|&h| h as usize == k) {
                // Down: the first link from i on not crossed with its tail right and head left (h_i,
                // which the ray leaves by, passes: searching from it keeps the search's start
                // at the weight of what hangs off T_i).
                let end = path.links.len();
                let fail = [
                    path.tails.at_or_left(polygon, pb, d, i..end, true, fingers),
                    path.heads
                        .at_or_left(polygon, pb, d.reversed(), i..end, true, fingers),
                ]
                .into_iter()
                .flatten()
                .min()
                .unwrap_or(end);
                // The ray reaches T_fail through the twin of h_(fail - 1).
                match mesh.twin_of(path.links[fail - 1] as usize) {
                    Some(next) => g = next,
                    None => return None, // not reached: links are diagonals
                }
                continue;
            }
            let up = i
                .checked_sub(1)
                .and_then(|m| mesh.twin_of(path.links[m] as usize).map(|h| (m, h)));
            if let Some((m, _)) = up.filter(|&(_, h)| h == k) {
                // Up across h_m: the last link up to m not crossed with its tail left and head
                // right (going up, the twin's tail is h's head; h_m itself passes).
                let fail = [
                    path.tails
                        .at_or_left(polygon, pb, d.reversed(), 0..m + 1, false, fingers),
                    path.heads
                        .at_or_left(polygon, pb, d, 0..m + 1, false, fingers),
                ]
                .into_iter()
                .flatten()
                .max();
                // The ray reaches T_(fail + 1) through h_(fail + 1) (T_0 through h_0).
                g = match fail {
                    Some(f) => path.links[f + 1] as usize,
                    None => path.links[0] as usize,
                };
                continue;
            }
            // Off the path: one step into the next triangle.
            match mesh.twin_of(k) {
                Some(next) => g = next,
                None => return None,
            }
        }
    }
}

/// A search tree over a sequence of points (vertex indices), each node holding the convex hull
/// of its range as a lower and an upper chain (Andrew's monotone chains), for the first or last
/// point of a range on the closed left of a line. Biased by weight: each node splits its range
/// where the weight is halved (a heavy point soon gets a leaf of its own), so a point of weight
/// `w` in a sequence of weight `W` lies O(log(W / w)) deep.
struct HullTree {
    len: usize,
    /// The nodes, the root first.
    nodes: Vec<HullNode>,
    verts: Vec<u32>,
    /// The points of the sequence, in order (the leaves).
    seq: Vec<u32>,
}

/// A node of a [`HullTree`]: the range of `verts` holding its lower chain, then its upper
/// chain, and where its range splits. Nodes are in preorder, so the node over `lo..hi` split
/// at `mid` has its left child next, and its right child `2 (mid - lo)` places on (the left
/// subtree has `mid - lo` leaves, so `2 (mid - lo) - 1` nodes).
#[derive(Clone, Copy)]
struct HullNode {
    hull: (u32, u32, u32),
    mid: u32,
    /// Where the fingers of its lower and upper chains are kept ([`Shooter::shoot_with`]):
    /// `finger` and `finger + 1`, for a node with a chain longer than [`FINGER_FROM`];
    /// `u32::MAX` for the others.
    finger: u32,
}

impl HullTree {
    fn new<P: Coord>(
        polygon: &Polygon<P>,
        seq: &[usize],
        weights: &[u64],
        fingers: &mut usize,
    ) -> HullTree {
        let len = seq.len();
        let mut tree = HullTree {
            len,
            nodes: Vec::with_capacity(2 * len),
            verts: Vec::new(),
            seq: seq.iter().map(|&v| v as u32).collect(),
        };
        let mut prefix = vec![0u64; len + 1];
        for (k, &w) in weights.iter().take(len).enumerate() {
            prefix[k + 1] = prefix[k] + w.max(1);
        }
        if len > 0 {
            tree.build(polygon, &prefix, 0, len);
        }
        for node in &mut tree.nodes {
            let (start, split, end) = node.hull;
            if (split - start).max(end - split) as usize > FINGER_FROM {
                node.finger = u32::try_from(*fingers).unwrap_or(u32::MAX);
                *fingers += 2;
            }
        }
        tree
    }

    /// Builds the node over `lo..hi` (appended to `nodes`: the root of the call is at the index
    /// `nodes` had on entry); returns its points sorted (x, then y), repeats removed.
    fn build<P: Coord>(
        &mut self,
        polygon: &Polygon<P>,
        prefix: &[u64],
        lo: usize,
        hi: usize,
    ) -> Vec<u32> {
        let p = |v: u32| polygon.point(v as usize);
        let node = self.nodes.len();
        self.nodes.push(HullNode {
            hull: (0, 0, 0),
            mid: hi as u32,
            finger: u32::MAX,
        });
        let sorted = if hi - lo == 1 {
            vec![self.seq[lo]]
        } else {
            // The point where half the weight is reached starts the right part (or ends the
            // left one, when it is the first).
            let half = prefix[lo] + (prefix[hi] - prefix[lo]) / 2;
            let k = lo + prefix[lo + 1..=hi].partition_point(|&x| x <= half);
            let mid = if k == lo { lo + 1 } else { k.min(hi - 1) };
            let left = self.build(polygon, prefix, lo, mid);
            debug_assert_eq!(self.nodes.len(), node + 2 * (mid - lo));
            let right = self.build(polygon, prefix, mid, hi);
            self.nodes[node].mid = mid as u32;
            let mut merged = Vec::with_capacity(left.len() + right.len());
            let (mut i, mut j) = (0, 0);
            while i < left.len() || j < right.len() {
                let take_left = j == right.len() || (i < left.len() && p(left[i]) <= p(right[j]));
                let v = if take_left {
                    i += 1;
                    left[i - 1]
                } else {
                    j += 1;
                    right[j - 1]
                };
                if merged.last().is_none_or(|&u| p(u) != p(v)) {
                    merged.push(v);
                }
            }
            merged
        };
        let start = self.verts.len();
        let chain = |verts: &mut Vec<u32>, iter: &mut dyn Iterator<Item = &u32>| {
            let base = verts.len();
            for &v in iter {
                while verts.len() >= base + 2
                    && crate::geom::kernel::cross(
                        p(verts[verts.len() - 2]),
                        p(verts[verts.len() - 1]),
                        p(v),
                    ) <= 0
                {
                    verts.pop();
                }
                verts.push(v);
            }
        };
        chain(&mut self.verts, &mut sorted.iter());
        let split = self.verts.len();
        chain(&mut self.verts, &mut sorted.iter().rev());
        self.nodes[node].hull = (start as u32, split as u32, self.verts.len() as u32);
        sorted
    }

    /// Whether some point of the node lies on the line through `b` with direction `d` or left
    /// of it: whether the largest `d x (p - b)` over the hull is at least 0. That function
    /// grows with y as fast as `d`'s x component, and the chains are x-monotone with the
    /// upper one above the lower at every x, so its largest value lies on the upper chain if
    /// `d` points rightwards, on the lower one if leftwards, and at the chains' common ends
    /// (the leftmost and rightmost points) if `d` is vertical. Along a chain it is at an end
    /// or where the edges stop turning towards the left of `d`: one binary search.
    /// With `fingers` ([`Shooter::shoot_with`]), the search on the chain starts where the last
    /// one on it ended, and records where this one ends.
    fn reaches<P: Coord>(
        &self,
        polygon: &Polygon<P>,
        node: usize,
        b: P,
        d: Dir<P>,
        fingers: &mut Fingers,
    ) -> bool {
        let p = |v: u32| polygon.point(v as usize);
        let left = |v: u32| d.cross(Dir::between(b, p(v))) >= 0;
        let (start, split, end) = self.nodes[node].hull;
        let lower = &self.verts[start as usize..split as usize];
        let (chain, upper) = match d.cmp_x() {
            Ordering::Less => (lower, false),
            Ordering::Greater => (&self.verts[split as usize..end as usize], true),
            Ordering::Equal => {
                let ends = [lower.first(), lower.last()];
                return ends.into_iter().flatten().any(|&v| left(v));
            }
        };
        let (Some(&first), Some(&last)) = (chain.first(), chain.last()) else {
            return false;
        };
        if left(first) || left(last) {
            return true;
        }
        // Edge k runs from chain[k] to chain[k + 1]; d x edge > 0: the side grows along it.
        let grows = |k: usize| d.cross(Dir::between(p(chain[k]), p(chain[k + 1]))) > 0;
        if chain.len() >= 3 && grows(0) {
            // Growing, then not: the maximum is where it stops, the first k >= 1 with
            // !grows(k) (k = last if none; the last point has no edge).
            let last = chain.len() - 1;
            let stops = |k: usize| k == last || !grows(k);
            // Bounds: grows(lo), stops(hi); from the finger for a long chain (a short one is
            // searched whole: its binary search is as short as a gallop).
            let finger = if chain.len() > FINGER_FROM {
                let slot = self.nodes[node].finger as usize + usize::from(upper);
                fingers.get_mut(slot)
            } else {
                None
            };
            let (mut lo, mut hi) = match finger.as_deref() {
                None => (0, last),
                Some(&f) => bracket(f as usize, last, stops),
            };
            while hi - lo > 1 {
                let mid = (lo + hi) / 2;
                if stops(mid) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            if let Some(f) = finger {
                *f = hi as u32;
            }
            return left(chain[hi]);
        }
        false
    }

    /// The first (`forward`) or the last index in `range` whose point lies on the line through
    /// `b` with direction `d` or left of it.
    fn at_or_left<P: Coord>(
        &self,
        polygon: &Polygon<P>,
        b: P,
        d: Dir<P>,
        range: std::ops::Range<usize>,
        forward: bool,
        fingers: &mut Fingers,
    ) -> Option<usize> {
        if range.is_empty() {
            return None;
        }
        let query = Query {
            polygon,
            b,
            d,
            lo: range.start,
            hi: range.end,
            forward,
        };
        self.find(&query, 0, 0, self.len, fingers)
    }

    /// The first (`forward`) or last index of `lo..hi` within node `node` (over `from..to`)
    /// whose point is on the closed left of the line: the nodes visited are those on the paths
    /// to `lo` (or `hi - 1`) and to the answer, each tested in O(log) by [`HullTree::reaches`].
    fn find<P: Coord>(
        &self,
        q: &Query<'_, P>,
        node: usize,
        from: usize,
        to: usize,
        fingers: &mut Fingers,
    ) -> Option<usize> {
        if q.hi <= from || to <= q.lo || !self.reaches(q.polygon, node, q.b, q.d, fingers) {
            return None;
        }
        if to - from == 1 {
            return Some(from);
        }
        let mid = self.nodes[node].mid as usize;
        let halves = [(node + 1, from, mid), (node + 2 * (mid - from), mid, to)];
        let order = if q.forward { [0, 1] } else { [1, 0] };
        order.into_iter().find_map(|k| {
            let (n, f, t) = halves[k];
            self.find(q, n, f, t, fingers)
        })
    }
}

/// The longest chain searched from end to end whether or not there is a finger.
const FINGER_FROM: usize = 16;

/// One search of [`HullTree::find`]: the first (`forward`) or last index of `lo..hi` whose
/// point lies on the closed left of the line through `b` with direction `d`.
struct Query<'a, P: Coord> {
    polygon: &'a Polygon<P>,
    b: P,
    d: Dir<P>,
    lo: usize,
    hi: usize,
    forward: bool,
}

/// Bounds `(lo, hi)` around the first `k` in `1..=last` with `stops(k)` (given that `stops` is
/// false, then true, over `0..=last`, `stops(0)` false and `stops(last)` true): `!stops(lo)`,
/// `stops(hi)`, found from `start` by steps of 1, 2, 4, .. towards it, so `hi - lo` is at most
/// twice the distance from `start` to the answer, with O(log) of it tests (galloping).
#[inline]
fn bracket(start: usize, last: usize, stops: impl Fn(usize) -> bool) -> (usize, usize) {
    let start = start.clamp(1, last);
    let mut step = 1;
    if stops(start) {
        // The answer is at or before `start`.
        let mut hi = start;
        loop {
            let k = hi.saturating_sub(step);
            if k == 0 {
                return (0, hi);
            }
            if !stops(k) {
                return (k, hi);
            }
            hi = k;
            step *= 2;
        }
    } else {
        let mut lo = start;
        loop {
            let k = lo.saturating_add(step);
            if k >= last {
                return (lo, last);
            }
            if stops(k) {
                return (lo, k);
            }
            lo = k;
            step *= 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::{bracket, Mesh, Shooter};
    use crate::geom::kernel::Dir;
    use crate::geom::polygon::Polygon;
    use crate::test_support::{comb, grown_rings, parabola, polygon, sliver};

    /// The ray walked triangle by triangle: the reference.
    fn walk(p: &Polygon, mesh: &Mesh, b: usize, d: Dir, mut g: usize) -> Option<usize> {
        let pb = p.point(b);
        loop {
            let x = mesh.apex(g);
            let s = d.cross(Dir::between(pb, p.point(x)));
            if s == 0 {
                return Some(x);
            }
            let k = if s < 0 {
                Mesh::next_in_triangle(Mesh::next_in_triangle(g))
            } else {
                Mesh::next_in_triangle(g)
            };
            g = mesh.twin_of(k)?;
        }
    }

    /// Every ray from a vertex towards another vertex, strictly inside the angle of one of its
    /// triangles, is shot where the walk ends, searching the hull chains from their ends or
    /// from fingers left by the rays before (in no particular order: the fingers change how
    /// long a search takes, never its answer): on combs, slivers, a parabola (long convex hull
    /// chains, searched from fingers) and random grid polygons, over the flipped mesh step 1
    /// walks.
    #[test]
    fn shoots_where_the_walk_ends() {
        let mut rings = vec![
            comb(40, 1, 9),
            comb(13, 2, 3),
            sliver(60, 1, 1),
            parabola(90, 9),
        ];
        rings.extend(grown_rings(0x35_0000_5407, 300, 13, 60));
        let (mut shot, mut with_fingers) = (0, 0);
        for ring in &rings {
            let p = polygon(&[ring]);
            let mut mesh = Mesh::new(&p, crate::algo::plain::polygon(&p, None));
            mesh.flip_towards_delaunay(&p, 4 * p.len());
            let shooter = Shooter::new(&p, &mesh);
            let mut fingers = vec![0; shooter.finger_count()];
            with_fingers += usize::from(!fingers.is_empty());
            for t in 0..mesh.triangle_count() {
                for k in 0..3 {
                    // From the corner b of triangle t across its far side g, into the
                    // neighbour through g's twin.
                    let g = 3 * t + k;
                    let b = mesh.apex(g);
                    let Some(entry) = mesh.twin_of(g) else {
                        continue;
                    };
                    let (u, w) = (mesh.tail(g), mesh.head(g));
                    let (du, dw) = (
                        Dir::between(p.point(b), p.point(u)),
                        Dir::between(p.point(b), p.point(w)),
                    );
                    for v in 0..p.len() {
                        let d = Dir::between(p.point(b), p.point(v));
                        if v == b || du.cross(d) <= 0 || d.cross(dw) <= 0 {
                            continue;
                        }
                        let walked = walk(&p, &mesh, b, d, entry);
                        assert_eq!(
                            shooter.shoot(&p, &mesh, b, d, entry),
                            walked,
                            "{ring:?} from {b} towards {v}"
                        );
                        assert_eq!(
                            shooter.shoot_with(&p, &mesh, b, d, entry, &mut fingers),
                            walked,
                            "{ring:?} from {b} towards {v}, from the fingers"
                        );
                        shot += 1;
                    }
                }
            }
        }
        assert!(shot > 10_000, "{shot} rays");
        assert!(with_fingers > 0, "no chain searched from a finger");
    }

    /// The galloping search's bounds hold the answer whatever the start, and are at most
    /// about twice the start's distance from it apart.
    #[test]
    fn brackets_the_answer_from_any_start() {
        for last in 1..40 {
            for answer in 1..=last {
                for start in 0..45 {
                    let (lo, hi) = bracket(start, last, |k| k >= answer);
                    assert!(lo < answer && answer <= hi, "{last} {answer} {start}");
                    let from = start.clamp(1, last);
                    assert!(hi - lo <= 2 * from.abs_diff(answer) + 2, "{last} {answer} {start}");
                }
            }
        }
    }
}
