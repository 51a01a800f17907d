//! An exact maximum independent set of a general graph, by reductions and branch and bound,
//! with a time budget: Step 3 of MINITRI for polygons with holes.
//!
//! With holes the dependency graph of minimally degenerate triangles is no longer a circle graph,
//! and the problem is NP-hard (A. Lingas, "The power of non-rectilinear holes", ICALP 1982), so
//! Chen & Chang's Step 3 does not apply. This module solves it exactly where it can:
//!
//! - the graph splits into connected components, solved one by one, smallest first;
//! - reductions: a vertex with at most one neighbour left is always in some maximum set
//!   (take it, drop its neighbour);
//! - branching on a vertex of highest degree (take it and drop its neighbours, or drop it), with
//!   the bound "chosen + a greedy clique cover of what is left" (an independent set has at most
//!   one vertex per clique), over bit sets (a component is searched only up to
//!   [`SEARCH_LIMIT`] vertices; a larger one keeps a greedy set and its clique-cover bound).
//!
//! When the search of every component finishes, the set is a maximum one (`optimal`). Past the
//! deadline the search stops where it is and keeps the best set found, with an upper bound on
//! the maximum: the finished components' sizes plus, for the others, their bound at the root.
//!
//! Complexity: exponential in the worst case (as it must be unless P = NP), O(V + E) for the
//! components and greedy sets; each search node costs O(V^2 / 64).

use crate::algo::Stopped;
use std::time::Instant;

/// The largest component searched exactly (bit-set rows cost V^2 / 8 bytes).
pub const SEARCH_LIMIT: usize = 4096;

/// A set found, with what is known about the maximum.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Found {
    /// An independent set (vertex numbers, sorted).
    pub set: Vec<usize>,
    /// An upper bound on the size of a maximum independent set (`set.len()` when optimal).
    pub upper_bound: usize,
    /// Whether `set` is proved maximum.
    pub optimal: bool,
    /// When not: why ([`Stopped::TimeLimit`] if the deadline stopped any component, else
    /// [`Stopped::SearchSize`]).
    pub stopped: Option<Stopped>,
}

/// A maximum independent set of the graph given by its adjacency lists (symmetric, no loops),
/// searched until `deadline` (none: until done).
pub fn maximum_independent_set(adjacent: &[Vec<usize>], deadline: Option<Instant>) -> Found {
    let labels: Vec<usize> = (0..adjacent.len()).collect();
    maximum_independent_set_labelled(adjacent, &labels, deadline)
}

/// [`maximum_independent_set`] with a known clique cover: vertices with the same `labels[v]`
/// are pairwise adjacent (for minimally degenerate triangles, those sharing their middle
/// vertex), so a component holding `m` distinct labels has no independent set above `m`. The
/// upper bound of a component not solved exactly is capped by it (it was not, and a search cut
/// short on a large component could report more than the component's number of middles).
pub fn maximum_independent_set_labelled(
    adjacent: &[Vec<usize>],
    labels: &[usize],
    deadline: Option<Instant>,
) -> Found {
    let mut components = components(adjacent);
    components.sort_by_key(Vec::len);
    let mut found = Found {
        set: Vec::new(),
        upper_bound: 0,
        optimal: true,
        stopped: None,
    };
    for component in components {
        if component.len() == 1 {
            found.set.push(component[0]);
            found.upper_bound += 1;
            continue;
        }
        let (set, bound, stopped) = solve_component(adjacent, &component, deadline);
        let mut distinct: Vec<usize> = component.iter().map(|&v| labels[v]).collect();
        distinct.sort_unstable();
        distinct.dedup();
        found.upper_bound += bound.min(distinct.len()).max(set.len());
        found.set.extend(set);
        found.optimal &= stopped.is_none();
        if found.stopped != Some(Stopped::TimeLimit) && stopped.is_some() {
            found.stopped = stopped;
        }
    }
    found.set.sort_unstable();
    found
}

/// The connected components, each a sorted list of vertices.
fn components(adjacent: &[Vec<usize>]) -> Vec<Vec<usize>> {
    let mut seen = vec![false; adjacent.len()];
    let mut out = Vec::new();
    for start in 0..adjacent.len() {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        let mut component = vec![start];
        let mut i = 0;
        while i < component.len() {
            for &u in &adjacent[component[i]] {
                if !seen[u] {
                    seen[u] = true;
                    component.push(u);
                }
            }
            i += 1;
        }
        component.sort_unstable();
        out.push(component);
    }
    out
}

/// A set of vertices `0..n` as bits.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Bits(Vec<u64>);

impl Bits {
    fn empty(n: usize) -> Bits {
        Bits(vec![0; n.div_ceil(64)])
    }

    fn full(n: usize) -> Bits {
        let mut b = Bits::empty(n);
        for v in 0..n {
            b.insert(v);
        }
        b
    }

    fn insert(&mut self, v: usize) {
        self.0[v / 64] |= 1 << (v % 64);
    }

    fn remove(&mut self, v: usize) {
        self.0[v / 64] &= !(1 << (v % 64));
    }

    fn is_empty(&self) -> bool {
        self.0.iter().all(|&w| w == 0)
    }

    fn len(&self) -> usize {
        self.0.iter().map(|w| w.count_ones() as usize).sum()
    }

    fn and_count(&self, other: &Bits) -> usize {
        self.0
            .iter()
            .zip(&other.0)
            .map(|(a, b)| (a & b).count_ones() as usize)
            .sum()
    }

    fn and(&self, other: &Bits) -> Bits {
        Bits(self.0.iter().zip(&other.0).map(|(a, b)| a & b).collect())
    }

    fn minus(&self, other: &Bits) -> Bits {
        Bits(self.0.iter().zip(&other.0).map(|(a, b)| a & !b).collect())
    }

    fn iter(&self) -> impl Iterator<Item = usize> + '_ {
        self.0.iter().enumerate().flat_map(|(i, &w)| {
            let mut w = w;
            std::iter::from_fn(move || {
                (w != 0).then(|| {
                    let bit = w.trailing_zeros() as usize;
                    w &= w - 1;
                    i * 64 + bit
                })
            })
        })
    }

    fn first(&self) -> Option<usize> {
        self.iter().next()
    }
}

/// Solves one component: (its set in global numbers, an upper bound, why it is not proved
/// maximum if it is not).
fn solve_component(
    adjacent: &[Vec<usize>],
    component: &[usize],
    deadline: Option<Instant>,
) -> (Vec<usize>, usize, Option<Stopped>) {
    let n = component.len();
    let local = |v: usize| {
        component
            .binary_search(&v)
            .expect("a neighbour in the component")
    };
    if n > SEARCH_LIMIT {
        let set = greedy(adjacent, component);
        let bound = n - greedy_matching(adjacent, component);
        return (set, bound, Some(Stopped::SearchSize));
    }
    let mut closed = Vec::with_capacity(n); // closed neighbourhoods N[v]
    for &v in component {
        let mut row = Bits::empty(n);
        row.insert(local(v));
        for &u in &adjacent[v] {
            row.insert(local(u));
        }
        closed.push(row);
    }
    let mut search = Search {
        closed,
        best: Vec::new(),
        nodes: 0,
        deadline,
        stopped: false,
    };
    // A greedy start, so that the bound prunes from the first node.
    search.best = greedy(adjacent, component).into_iter().map(local).collect();
    let all = Bits::full(n);
    let root_bound = search.clique_cover(&all);
    search.expand(all, &mut Vec::new());
    let set = search.best.iter().map(|&v| component[v]).collect();
    if search.stopped {
        (
            set,
            root_bound.max(search.best.len()),
            Some(Stopped::TimeLimit),
        )
    } else {
        let size = search.best.len();
        (set, size, None)
    }
}

/// A greedy independent set: repeatedly the vertex with fewest remaining neighbours.
fn greedy(adjacent: &[Vec<usize>], component: &[usize]) -> Vec<usize> {
    let mut order: Vec<usize> = component.to_vec();
    order.sort_by_key(|&v| adjacent[v].len());
    let mut blocked = std::collections::HashSet::new();
    let mut set = Vec::new();
    for v in order {
        if blocked.insert(v) {
            set.push(v);
            blocked.extend(adjacent[v].iter().copied());
        }
    }
    set
}

/// The size of a greedy matching: each matched edge is a clique, so `n - matching` bounds the
/// independent sets from above.
fn greedy_matching(adjacent: &[Vec<usize>], component: &[usize]) -> usize {
    let mut matched = std::collections::HashSet::new();
    let mut count = 0;
    for &v in component {
        if matched.contains(&v) {
            continue;
        }
        if let Some(&u) = adjacent[v].iter().find(|u| !matched.contains(*u)) {
            matched.insert(v);
            matched.insert(u);
            count += 1;
        }
    }
    count
}

struct Search {
    closed: Vec<Bits>,
    best: Vec<usize>,
    nodes: u64,
    deadline: Option<Instant>,
    stopped: bool,
}

impl Search {
    /// An upper bound on the independent sets within `cand`: the number of cliques in a greedy
    /// clique cover of it.
    fn clique_cover(&self, cand: &Bits) -> usize {
        let mut left = cand.clone();
        let mut cliques = 0;
        while let Some(v) = left.first() {
            let mut common = left.and(&self.closed[v]);
            common.remove(v);
            left.remove(v);
            while let Some(u) = common.first() {
                left.remove(u);
                common = common.and(&self.closed[u]);
                common.remove(u);
            }
            cliques += 1;
        }
        cliques
    }

    fn expand(&mut self, mut cand: Bits, chosen: &mut Vec<usize>) {
        if self.stopped {
            return;
        }
        self.nodes += 1;
        if self.nodes % 256 == 1 && self.deadline.is_some_and(|d| Instant::now() >= d) {
            self.stopped = true;
            return;
        }
        let mark = chosen.len();
        // Reductions: a vertex with at most one neighbour left is in some maximum set.
        loop {
            let low = cand.iter().find(|&v| cand.and_count(&self.closed[v]) <= 2);
            let Some(v) = low else { break };
            chosen.push(v);
            cand = cand.minus(&self.closed[v]);
        }
        if cand.is_empty() {
            if chosen.len() > self.best.len() {
                self.best = chosen.clone();
            }
            chosen.truncate(mark);
            return;
        }
        if chosen.len() + self.clique_cover(&cand) <= self.best.len() {
            chosen.truncate(mark);
            return;
        }
        let v = cand
            .iter()
            .max_by_key(|&v| cand.and_count(&self.closed[v]))
            .expect("not empty");
        chosen.push(v);
        self.expand(cand.minus(&self.closed[v]), chosen);
        chosen.pop();
        let mut without = cand;
        without.remove(v);
        if without.len() + chosen.len() > self.best.len() {
            self.expand(without, chosen);
        }
        chosen.truncate(mark);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn brute_force(adjacent: &[Vec<usize>]) -> usize {
        let n = adjacent.len();
        (0u32..1 << n)
            .filter(|&mask| {
                (0..n).all(|v| {
                    mask & (1 << v) == 0 || adjacent[v].iter().all(|&u| mask & (1 << u) == 0)
                })
            })
            .map(|mask| mask.count_ones() as usize)
            .max()
            .unwrap_or(0)
    }

    fn random_graph(n: usize, density: u64, seed: &mut u64) -> Vec<Vec<usize>> {
        let mut adjacent = vec![Vec::new(); n];
        for v in 0..n {
            for u in 0..v {
                *seed ^= *seed << 13;
                *seed ^= *seed >> 7;
                *seed ^= *seed << 17;
                if *seed % 100 < density {
                    adjacent[v].push(u);
                    adjacent[u].push(v);
                }
            }
        }
        adjacent
    }

    #[test]
    fn equals_brute_force_on_random_graphs() {
        let mut seed = 0x5eed_u64;
        for case in 0..600 {
            let n = 1 + case % 16;
            let density = [5, 15, 30, 50, 80][case % 5];
            let g = random_graph(n, density, &mut seed);
            let found = maximum_independent_set(&g, None);
            assert!(found.optimal);
            assert_eq!(found.set.len(), brute_force(&g), "case {case}: {g:?}");
            assert_eq!(found.upper_bound, found.set.len());
            for &v in &found.set {
                assert!(g[v].iter().all(|u| found.set.binary_search(u).is_err()));
            }
        }
    }

    #[test]
    fn a_past_deadline_gives_a_valid_set_and_a_true_bound() {
        let mut seed = 77;
        let g = random_graph(120, 4, &mut seed);
        let found = maximum_independent_set(&g, Some(Instant::now()));
        assert!(!found.optimal, "the search stops at its first node");
        for &v in &found.set {
            assert!(g[v].iter().all(|u| found.set.binary_search(u).is_err()));
        }
        let exact = maximum_independent_set(&g, None);
        assert!(exact.optimal);
        assert!(found.set.len() <= exact.set.len() && exact.set.len() <= found.upper_bound);
    }
}
