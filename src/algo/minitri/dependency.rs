//! The dependency graph of minimally degenerate triangles, for any polygon (holes allowed).
//!
//! Chen & Chang (1990, §2, Theorem 1) list when two minimally degenerate triangles can be used
//! together. Made concrete (`docs/algorithms.md`, "Theorem 1 made concrete"): triangles `T = (a, b, c)`
//! and `U = (x, y, z)` (middles `b`, `y`) are dependent exactly when
//! - the segments `a c` and `x z` cross properly, or
//! - they share their middle vertex (`b == y`), or
//! - an end of `U` is `b` and the other end of `U` lies strictly on `T`'s 180-degree side (or the
//!   same with `T` and `U` swapped).
//!
//! No other contact is possible: a vertex never lies inside a minimally degenerate segment except
//! its middle, so segments meet properly, at vertices that are ends or middles, or overlap along
//! one line sharing a side (relationship (iii): independent). Without holes this is the crossing
//! relation of the circle representation with the 3b-chain exception
//! ([`super::circle`], [`super::mis`]); the tests check that the two agree.
//!
//! Complexity: pairs sharing a vertex are found through per-vertex lists; proper crossings by a
//! sweep over x-extents, comparing segments whose x-ranges overlap: O(K log K + candidate
//! pairs), near-linear when segments are short, O(K^2) at worst.

use super::degenerate::Degenerate;
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cross, properly_cross};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;

/// Whether triangles `t` and `u` cannot both be used (Theorem 1, made concrete).
pub fn dependent<P: Coord>(polygon: &Polygon<P>, t: &Degenerate, u: &Degenerate) -> bool {
    if t.b == u.b {
        return true;
    }
    let p = |v: usize| polygon.point(v);
    if properly_cross(p(t.a), p(t.c), p(u.a), p(u.c)) {
        return true;
    }
    reaches_straight_side(polygon, t, u) || reaches_straight_side(polygon, u, t)
}

/// Whether `u` has an end at `t`'s middle and its other end strictly on `t`'s 180-degree side.
fn reaches_straight_side<P: Coord>(polygon: &Polygon<P>, t: &Degenerate, u: &Degenerate) -> bool {
    let other = if u.a == t.b {
        u.c
    } else if u.c == t.b {
        u.a
    } else {
        return false;
    };
    let side = cross(polygon.point(t.a), polygon.point(t.c), polygon.point(other)).signum() as i32;
    side != 0 && side != t.non_straight_side(polygon)
}

/// The dependency graph: for each triangle, the sorted list of triangles it depends on.
pub fn graph<P: Coord>(polygon: &Polygon<P>, mdts: &[Degenerate]) -> Vec<Vec<usize>> {
    graph_within(polygon, mdts, u64::MAX, None).unwrap_or_default()
}

/// How many pairs of triangles [`graph_within`] may compare for a polygon of `n` vertices
/// before it gives up: `2^24 + 64 n` (a few tenths of a second; at most 8 bytes a pair while
/// they are compared, 128 MiB for 2^24 dependent pairs, then 16 bytes a pair for a graph that
/// fits), far above what polygons whose triangles are short need (O(K)
/// pairs), below the Θ(K^2) pairs of polygons in which most triangles cross most others (in a
/// grid of small holes `K` itself is Θ(n^2)). The graph's memory is at most proportional to the
/// pairs compared.
pub fn pair_budget(n: usize) -> u64 {
    (1 << 24) + 64 * n as u64
}

/// [`graph`], or `None` as soon as it has compared more than `budget` pairs of triangles or
/// `deadline` has passed (checked every 4096 pairs), or memory for its pairs is refused, so
/// that neither its time nor its memory (proportional to the pairs compared) runs away on
/// polygons where most triangles depend on most others.
///
/// Memory: the dependent pairs are gathered first as 8 bytes each (`Pairs`, growth capped at
/// the budget), and only a graph that fits is turned into adjacency lists (16 bytes a pair,
/// each list allocated at its size while the pairs are given back), so that a try that runs
/// out of budget holds 8 bytes per pair found, not the 16 to 32 of growing lists.
pub fn graph_within<P: Coord>(
    polygon: &Polygon<P>,
    mdts: &[Degenerate],
    budget: u64,
    deadline: Option<std::time::Instant>,
) -> Option<Vec<Vec<usize>>> {
    let k = mdts.len();
    let mut pairs: u64 = 0;
    let mut spend = |count: usize| -> bool {
        let before = pairs;
        pairs = pairs.saturating_add(count as u64);
        pairs <= budget
            && (before >> 12 == pairs >> 12
                || deadline.is_none_or(|d| std::time::Instant::now() < d))
    };
    let mut found = Pairs::new(k, budget)?;
    // Pairs meeting at a vertex that is a middle of one of them.
    let mut at_vertex: Vec<Vec<usize>> = vec![Vec::new(); polygon.len()];
    for (t, m) in mdts.iter().enumerate() {
        for v in [m.a, m.b, m.c] {
            at_vertex[v].push(t);
        }
    }
    for (t, m) in mdts.iter().enumerate() {
        if !spend(at_vertex[m.b].len()) {
            return None;
        }
        for &u in &at_vertex[m.b] {
            if u != t && dependent(polygon, m, &mdts[u]) {
                found.push(t, u)?;
            }
        }
    }
    // Proper crossings: sweep over x, comparing segments whose x-ranges overlap.
    let range = |m: &Degenerate| {
        let (a, c) = (polygon.point(m.a), polygon.point(m.c));
        match P::cmp_x(a, c) {
            Ordering::Greater => (X(c), X(a)),
            _ => (X(a), X(c)),
        }
    };
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by_key(|&t| range(&mdts[t]).0);
    let mut active: Vec<usize> = Vec::new();
    for &t in &order {
        let (lo, _) = range(&mdts[t]);
        if !spend(active.len()) {
            return None;
        }
        active.retain(|&u| range(&mdts[u]).1 >= lo);
        for &u in &active {
            let (m, o) = (&mdts[t], &mdts[u]);
            let p = |v: usize| polygon.point(v);
            if properly_cross(p(m.a), p(m.c), p(o.a), p(o.c)) {
                found.push(t, u)?;
            }
        }
        active.push(t);
    }
    Some(found.adjacency(k))
}

/// Dependent pairs of triangles as they are found, two `u32` each.
struct Pairs {
    pairs: Vec<[u32; 2]>,
    /// The most pairs there can be (the pair budget): growth stops there.
    most: usize,
}

impl Pairs {
    /// Room for the pairs of `k` triangles, at most `budget` of them; `None` when the triangles
    /// cannot be numbered in 32 bits (billions of them: far beyond any budget).
    fn new(k: usize, budget: u64) -> Option<Pairs> {
        u32::try_from(k).ok()?;
        Some(Pairs {
            pairs: Vec::new(),
            most: usize::try_from(budget).unwrap_or(usize::MAX),
        })
    }

    /// Adds the pair `t`, `u`; `None` when memory for it is refused.
    fn push(&mut self, t: usize, u: usize) -> Option<()> {
        let pairs = &mut self.pairs;
        if pairs.len() == pairs.capacity() {
            let left = self.most.saturating_sub(pairs.capacity()).max(1);
            let room = pairs.capacity().max(1 << 10).min(left);
            pairs.try_reserve_exact(room).ok()?;
        }
        // Both below `k`, which fits in 32 bits (`Pairs::new`).
        pairs.push([t as u32, u as u32]);
        Some(())
    }

    /// For each of `k` triangles, the sorted list of those it depends on, each list allocated
    /// at its size; the pairs are given back as they are used.
    fn adjacency(self, k: usize) -> Vec<Vec<usize>> {
        let mut pairs = self.pairs;
        let mut degree = vec![0usize; k];
        for &[t, u] in &pairs {
            degree[t as usize] += 1;
            degree[u as usize] += 1;
        }
        let mut adjacent: Vec<Vec<usize>> = degree.into_iter().map(Vec::with_capacity).collect();
        while !pairs.is_empty() {
            let rest = pairs.len().saturating_sub(1 << 20);
            for [t, u] in pairs.drain(rest..) {
                adjacent[t as usize].push(u as usize);
                adjacent[u as usize].push(t as usize);
            }
            pairs.shrink_to_fit();
        }
        for list in &mut adjacent {
            list.sort_unstable();
            list.dedup();
        }
        adjacent
    }
}

/// A point ordered by its x coordinate alone (the sweep over x of [`graph`]).
#[derive(Clone, Copy, PartialEq, Eq)]
struct X<P>(P);

impl<P: Coord> Ord for X<P> {
    fn cmp(&self, other: &Self) -> Ordering {
        P::cmp_x(self.0, other.0)
    }
}

impl<P: Coord> PartialOrd for X<P> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
