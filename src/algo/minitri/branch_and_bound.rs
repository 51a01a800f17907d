//! An exact maximum independent set of a general graph, by reductions and branch and bound,
//! with a time budget: Step 3 of MINITRI for polygons with holes.
//!
//! With holes the dependency graph of minimally degenerate triangles is no longer a circle graph,
//! and the problem is NP-hard (A. Lingas, "The power of non-rectilinear holes", ICALP 1982), so
//! Chen & Chang's Step 3 does not apply. This module solves it exactly where it can:
//!
//! - the graph splits into connected components, solved one by one, smallest first;
//! - reductions at every search node (Akiba & Iwata, "Branch-and-reduce exponential/FPT
//!   algorithms in practice", *Theor. Comput. Sci.* 609 (2016), Section 3): a vertex with at most
//!   one neighbour left is always in some maximum set (take it, drop its neighbour); a vertex
//!   dominated by a neighbour (whose closed neighbourhood lies inside its own) can be dropped;
//! - the graph left at a node splits again into connected components: all but the largest are
//!   solved exactly on their own (a maximum set of each) and the search goes on in the largest,
//!   keeping its bound;
//! - a start close to the maximum: a greedy set improved by iterated local search
//!   (`super::local_search`), so the bound prunes from the first node (a component of more
//!   than [`SEARCH_LIMIT`] vertices keeps that set, with a matching bound);
//! - branching on a vertex of highest degree (take it and drop its neighbours, or drop it), with
//!   the bound "chosen + a greedy clique cover of what is left" (an independent set has at most
//!   one vertex per clique), lowered by MaxSAT-style unit propagation and failed literals over
//!   the cover's cliques (`Search::bound`), over bit sets.
//!
//! When the search of every component finishes, the set is a maximum one (`optimal`). Past the
//! deadline the search stops where it is and keeps the best set found, with an upper bound on
//! the maximum: the finished components' sizes plus, for the others, their bound at the root.
//!
//! Complexity: exponential in the worst case (as it must be unless P = NP), O(V + E) for the
//! components and greedy sets, O(V + 4V x (degree^2)) for the local search; each search node
//! costs O(V^2 / 64) for the cover and reductions plus O(E) per propagation (one per clique set
//! aside, and up to three per small clique when the failed-literal test runs).

use super::local_search;
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

    fn or(&self, other: &Bits) -> Bits {
        Bits(self.0.iter().zip(&other.0).map(|(a, b)| a | b).collect())
    }

    fn contains(&self, v: usize) -> bool {
        self.0[v / 64] & (1 << (v % 64)) != 0
    }

    /// `self = a & b`, without allocating.
    fn assign_and(&mut self, a: &Bits, b: &Bits) {
        for ((w, x), y) in self.0.iter_mut().zip(&a.0).zip(&b.0) {
            *w = x & y;
        }
    }

    /// `self = self & other`, without allocating.
    fn intersect(&mut self, other: &Bits) {
        for (w, x) in self.0.iter_mut().zip(&other.0) {
            *w &= x;
        }
    }

    /// `self = self & !other`, without allocating.
    fn subtract(&mut self, other: &Bits) {
        for (w, x) in self.0.iter_mut().zip(&other.0) {
            *w &= !x;
        }
    }

    fn is_subset(&self, other: &Bits) -> bool {
        self.0.iter().zip(&other.0).all(|(a, b)| a & !b == 0)
    }

    /// The first member after `v`.
    fn after(&self, v: usize) -> Option<usize> {
        let (word, bit) = ((v + 1) / 64, (v + 1) % 64);
        let first = self.0.get(word)? & (!0u64).checked_shl(bit as u32).unwrap_or(0);
        if first != 0 {
            return Some(word * 64 + first.trailing_zeros() as usize);
        }
        self.0[word + 1..]
            .iter()
            .position(|&w| w != 0)
            .map(|k| (word + 1 + k) * 64 + self.0[word + 1 + k].trailing_zeros() as usize)
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
    // A large set first (greedy, then iterated local search): the search prunes with it from
    // the first node, and a component too large to search keeps it.
    let adjacent_local: Vec<Vec<usize>> = component
        .iter()
        .map(|&v| adjacent[v].iter().map(|&u| local(u)).collect())
        .collect();
    let greedy_set: Vec<usize> = greedy(adjacent, component).into_iter().map(local).collect();
    let start = local_search::improve(&adjacent_local, &greedy_set, 4 * n, deadline);
    if n > SEARCH_LIMIT {
        // Not searched: the local search's set, and the better of two bounds: a greedy
        // matching's (each matched edge a clique) and the propagated clique cover's, its work
        // bounded by a multiple of the graph's size (and the deadline).
        let set: Vec<usize> = start.iter().map(|&v| component[v]).collect();
        let mut scratch = Scratch::default();
        scratch.cover_by_lists(&adjacent_local);
        let edges: usize = adjacent_local.iter().map(Vec::len).sum();
        let budget = LARGE_BOUND_WORK * (n + edges);
        let all = Bits::full(n);
        let covered = scratch.lower(
            &adjacent_local,
            &all,
            0,
            Effort {
                thorough: true,
                deadline,
                budget,
            },
        );
        let bound = covered
            .min(n - greedy_matching(adjacent, component))
            .max(set.len());
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
        adjacent: adjacent_local,
        nodes: 0,
        deadline,
        stopped: false,
        scratch: Scratch::default(),
    };
    let all = Bits::full(n);
    let root_bound = search.bound(&all, 0, true);
    let best = search.solve(all, start);
    let set = best.iter().map(|&v| component[v]).collect();
    if search.stopped {
        (set, root_bound.max(best.len()), Some(Stopped::TimeLimit))
    } else {
        let size = best.len();
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
    /// The same graph as adjacency lists (for the propagation of [`Search::bound`]).
    adjacent: Vec<Vec<usize>>,
    nodes: u64,
    deadline: Option<Instant>,
    stopped: bool,
    scratch: Scratch,
}

/// Buffers of [`Search::bound`], kept between nodes (no allocation per node once grown).
#[derive(Default)]
struct Scratch {
    /// The cliques of the cover, one after another, and where each starts.
    members: Vec<usize>,
    starts: Vec<usize>,
    /// For each vertex of the cover, its clique.
    clique_of: Vec<usize>,
    /// The cliques of one member, and those of two or three (for failed literals).
    units: Vec<usize>,
    small: Vec<usize>,
    /// Per clique: whether it is spent (in an inconsistent set already counted); and, valid
    /// only when `mark` is the current pass (set up lazily, so that a propagation costs what it
    /// reaches, not the number of cliques): members still possible, whether it was
    /// propagated, and the cliques whose units removed some of its members.
    spent: Vec<bool>,
    mark: Vec<u32>,
    alive: Vec<usize>,
    done: Vec<bool>,
    because: Vec<Vec<usize>>,
    /// Per vertex: the pass that removed it (not the current pass = none).
    gone: Vec<u32>,
    pass: u32,
    queue: Vec<usize>,
    /// An inconsistent set being collected (cliques), and whether each is in it.
    set: Vec<usize>,
    in_set: Vec<bool>,
    /// Cliques met by one [`Scratch::collect`], and the list of them (to clear the marks).
    seen: Vec<bool>,
    trail: Vec<usize>,
    /// Adjacency entries and members looked at by the propagations of one [`Scratch::lower`].
    work: usize,
}

/// How hard [`Scratch::lower`] tries: failed literals at any bound (`thorough`) or only near
/// pruning; until `deadline`; within `budget` adjacency entries and members looked at.
#[derive(Clone, Copy)]
struct Effort {
    thorough: bool,
    deadline: Option<Instant>,
    budget: usize,
}

/// The work allowed to the bound of a component too large to search, as a multiple of its
/// vertices and adjacency entries (about that many propagations over the whole graph).
const LARGE_BOUND_WORK: usize = 32;

/// How close to pruning a node's bound must come for the failed-literal test
/// ([`Search::bound`]).
const FAILED_LITERAL_MARGIN: usize = 2;

impl Scratch {
    /// Closes the cover being built in the buffers: lists its cliques of one member and of two
    /// or three; the number of cliques.
    fn finish_cover(&mut self) -> usize {
        self.starts.push(self.members.len());
        let cliques = self.starts.len() - 1;
        self.units.clear();
        self.small.clear();
        for c in 0..cliques {
            match self.starts[c + 1] - self.starts[c] {
                1 => self.units.push(c),
                2 | 3 => self.small.push(c),
                _ => {}
            }
        }
        cliques
    }

    /// A greedy clique cover of the whole graph from its adjacency lists alone (for components
    /// too large for bit-set rows): each clique grows from the first vertex left, taking its
    /// neighbours left that are adjacent to every member so far. O(sum of degrees x clique
    /// size).
    fn cover_by_lists(&mut self, adjacent: &[Vec<usize>]) -> usize {
        let n = adjacent.len();
        const FREE: usize = usize::MAX;
        self.members.clear();
        self.starts.clear();
        self.clique_of.clear();
        self.clique_of.resize(n, FREE);
        self.gone.resize(n, 0);
        let mut near = vec![0u32; n]; // how many members of the growing clique each one touches
        let mut candidates = Vec::new();
        for v in 0..n {
            if self.clique_of[v] != FREE {
                continue;
            }
            let c = self.starts.len();
            self.starts.push(self.members.len());
            self.clique_of[v] = c;
            self.members.push(v);
            candidates.clear();
            candidates.extend(
                adjacent[v]
                    .iter()
                    .copied()
                    .filter(|&u| self.clique_of[u] == FREE),
            );
            let mut size = 1;
            for &u in &adjacent[v] {
                near[u] = 1;
            }
            for &u in &candidates {
                if near[u] as usize == size && self.clique_of[u] == FREE {
                    self.clique_of[u] = c;
                    self.members.push(u);
                    size += 1;
                    for &w in &adjacent[u] {
                        near[w] += 1;
                    }
                }
            }
            for &m in &self.members[self.starts[c]..] {
                near[m] = 0;
                for &w in &adjacent[m] {
                    near[w] = 0;
                }
            }
        }
        self.finish_cover()
    }

    /// [`Search::bound`] from the cover already made in the buffers.
    fn lower(
        &mut self,
        adjacent: &[Vec<usize>],
        cand: &Bits,
        enough: usize,
        effort: Effort,
    ) -> usize {
        let cliques = self.starts.len() - 1;
        let Effort {
            thorough,
            deadline,
            budget,
        } = effort;
        self.work = 0;
        self.spent.clear();
        self.spent.resize(cliques, false);
        let mut bound = cliques;
        // The failed-literal test goes round the small cliques once after the last set found
        // (so it tests each at most once per set found), and stops at the deadline.
        let mut at = 0;
        let mut tested = 0;
        'lower: while bound > enough {
            if self.work > budget || crate::algo::past(deadline) {
                break;
            }
            if let Some(d) = self.propagate(adjacent, cand, None) {
                self.set.clear();
                self.collect(d);
                self.spend();
                bound -= 1;
                continue;
            }
            if !thorough && bound > enough + FAILED_LITERAL_MARGIN {
                break;
            }
            while tested < self.small.len() {
                if self.work > budget || tested % 64 == 63 && crate::algo::past(deadline) {
                    break 'lower;
                }
                let c = self.small[at];
                at = (at + 1) % self.small.len();
                tested += 1;
                if self.spent[c] {
                    continue;
                }
                self.set.clear();
                self.set.push(c);
                let mut every = true;
                for k in self.starts[c]..self.starts[c + 1] {
                    let v = self.members[k];
                    match self.propagate(adjacent, cand, Some((c, v))) {
                        Some(d) => self.collect(d),
                        None => {
                            every = false;
                            break;
                        }
                    }
                }
                if every {
                    self.spend();
                    bound -= 1;
                    tested = 0;
                    continue 'lower;
                }
            }
            break;
        }
        bound
    }

    /// One unit propagation over the cover's cliques (those not spent), from its cliques of
    /// one member and, if `forced` (clique, member), from that member alone in its clique: the
    /// clique it empties, if any (`because` then records what emptied what).
    fn propagate(
        &mut self,
        adjacent: &[Vec<usize>],
        cand: &Bits,
        forced: Option<(usize, usize)>,
    ) -> Option<usize> {
        let cliques = self.starts.len() - 1;
        self.pass = self.pass.wrapping_add(1);
        if self.pass == 0 {
            self.gone.fill(0);
            self.mark.fill(0);
            self.pass = 1;
        }
        self.mark.resize(cliques, 0);
        self.alive.resize(cliques, 0);
        self.done.resize(cliques, false);
        self.because.resize_with(cliques, Vec::new);
        self.queue.clear();
        if let Some((c, v)) = forced {
            self.touch(c);
            for k in self.starts[c]..self.starts[c + 1] {
                if self.members[k] != v {
                    self.gone[self.members[k]] = self.pass;
                }
            }
            self.alive[c] = 1;
            self.queue.push(c);
        }
        self.queue.extend_from_slice(&self.units);
        while let Some(c) = self.queue.pop() {
            self.touch(c);
            if self.done[c] || self.spent[c] {
                continue;
            }
            self.done[c] = true;
            self.work += self.starts[c + 1] - self.starts[c];
            let Some(&v) = self.members[self.starts[c]..self.starts[c + 1]]
                .iter()
                .find(|&&v| self.gone[v] != self.pass)
            else {
                continue;
            };
            self.work += adjacent[v].len();
            for &u in &adjacent[v] {
                if !cand.contains(u) || self.gone[u] == self.pass {
                    continue;
                }
                let d = self.clique_of[u];
                if d == c || self.spent[d] {
                    continue;
                }
                self.touch(d);
                self.gone[u] = self.pass;
                self.alive[d] -= 1;
                self.because[d].push(c);
                if self.alive[d] == 0 {
                    return Some(d);
                }
                if self.alive[d] == 1 {
                    self.queue.push(d);
                }
            }
        }
        None
    }

    /// Sets up clique `c`'s state for the current pass, if not yet.
    fn touch(&mut self, c: usize) {
        if self.mark[c] != self.pass {
            self.mark[c] = self.pass;
            self.alive[c] = self.starts[c + 1] - self.starts[c];
            self.done[c] = false;
            self.because[c].clear();
        }
    }

    /// Adds to `set` the emptied clique `d` and, transitively, the cliques that emptied it in
    /// the last propagation. Costs what it visits: its marks are cleared afterwards, not
    /// allocated or filled per call.
    fn collect(&mut self, d: usize) {
        let cliques = self.starts.len() - 1;
        self.in_set.resize(cliques, false);
        self.seen.resize(cliques, false);
        for &c in &self.set {
            self.in_set[c] = true;
        }
        self.trail.clear();
        self.seen[d] = true;
        self.trail.push(d);
        let mut k = 0;
        while k < self.trail.len() {
            let c = self.trail[k];
            k += 1;
            if !self.in_set[c] {
                self.in_set[c] = true;
                self.set.push(c);
            }
            if self.mark[c] != self.pass {
                continue; // not reached by the last propagation: nothing emptied it
            }
            for i in 0..self.because[c].len() {
                let e = self.because[c][i];
                if !self.seen[e] {
                    self.seen[e] = true;
                    self.trail.push(e);
                }
            }
        }
        for &c in &self.trail {
            self.seen[c] = false;
        }
        for &c in &self.set {
            self.in_set[c] = false;
        }
    }

    /// Sets aside the cliques of `set` (an inconsistent set, counted once).
    fn spend(&mut self) {
        for &c in &self.set {
            self.spent[c] = true;
        }
    }
}

impl Search {
    /// An upper bound on the independent sets within `cand`: a greedy clique cover (an
    /// independent set has at most one vertex per clique), lowered by unit propagation as
    /// MaxSAT-based clique solvers do (C.-M. Li & Z. Quan, "An efficient branch-and-bound
    /// algorithm based on MaxSAT for the maximum clique problem", AAAI 2010; here on the
    /// complement: cliques for colour classes). A clique left with one possible member forces
    /// it, which removes its neighbours from the other cliques; a clique left with none shows
    /// that its set of cliques (itself and those whose forced members emptied it, transitively)
    /// cannot give one vertex each: an independent set takes at most one fewer than their
    /// number. Such sets are set aside (disjoint) and propagation starts again. Stops as soon
    /// as the bound is at most `enough` (the caller prunes there).
    ///
    /// Then, while no propagation empties a clique, *failed literals*: a clique of two or three
    /// each of whose members, forced, ends in an emptied clique is inconsistent together with
    /// all those sets. That costs more, so it runs at the root (`thorough`) and at nodes whose
    /// bound is within [`FAILED_LITERAL_MARGIN`] of pruning.
    fn bound(&mut self, cand: &Bits, enough: usize, thorough: bool) -> usize {
        self.cover(cand);
        let deadline = self.deadline;
        let adjacent = &self.adjacent;
        self.scratch.lower(
            adjacent,
            cand,
            enough,
            Effort {
                thorough,
                deadline,
                budget: usize::MAX,
            },
        )
    }

    /// A greedy clique cover of `cand` into the scratch buffers: the number of cliques.
    fn cover(&mut self, cand: &Bits) -> usize {
        let sc = &mut self.scratch;
        sc.members.clear();
        sc.starts.clear();
        sc.clique_of.resize(self.closed.len(), 0);
        sc.gone.resize(self.closed.len(), 0);
        let mut left = cand.clone();
        while let Some(v) = left.first() {
            sc.starts.push(sc.members.len());
            let mut common = left.and(&self.closed[v]);
            common.remove(v);
            left.remove(v);
            sc.clique_of[v] = sc.starts.len() - 1;
            sc.members.push(v);
            while let Some(u) = common.first() {
                left.remove(u);
                common.intersect(&self.closed[u]);
                common.remove(u);
                sc.clique_of[u] = sc.starts.len() - 1;
                sc.members.push(u);
            }
        }
        sc.finish_cover()
    }

    /// Shrinks `cand` by the reductions that keep some maximum independent set (Akiba & Iwata,
    /// "Branch-and-reduce exponential/FPT algorithms in practice", *Theor. Comput. Sci.* 609
    /// (2016), Section 3): a vertex with at most one neighbour left is in some maximum set
    /// (taken, into `chosen`, its neighbour dropped); a vertex `u` whose neighbour `v` has
    /// `N[v] ⊆ N[u]` within `cand` (`v` *dominates* `u`) can be left out (swap `u` for `v` in
    /// any set holding `u`).
    fn reduce(&self, cand: &mut Bits, chosen: &mut Vec<usize>) {
        let mut around = Bits::empty(self.closed.len());
        let mut dominate = true;
        loop {
            let mut changed = false;
            let mut next = cand.first();
            while let Some(v) = next {
                next = cand.after(v);
                around.assign_and(cand, &self.closed[v]);
                if around.len() <= 2 {
                    chosen.push(v);
                    cand.subtract(&self.closed[v]);
                    changed = true;
                    next = cand.after(v);
                    continue;
                }
                if !dominate {
                    continue;
                }
                for u in around.iter().filter(|&u| u != v) {
                    if around.is_subset(&self.closed[u]) {
                        cand.remove(u);
                        changed = true;
                    }
                }
                if changed {
                    next = cand.after(v);
                }
            }
            if !changed {
                return;
            }
            // Domination once per node: later passes take the cheap degree rule only.
            dominate = false;
        }
    }

    /// The connected components of the graph within `cand`, each as bits.
    fn split(&self, cand: &Bits) -> Vec<Bits> {
        let mut left = cand.clone();
        let mut parts = Vec::new();
        while let Some(v) = left.first() {
            let mut part = Bits::empty(self.closed.len());
            let mut frontier = Bits::empty(self.closed.len());
            frontier.insert(v);
            while let Some(u) = frontier.first() {
                frontier.remove(u);
                part.insert(u);
                left.remove(u);
                frontier = frontier.or(&left.and(&self.closed[u]));
            }
            parts.push(part);
        }
        parts
    }

    /// A maximum independent set within `cand` (vertices of the component), at least as large
    /// as `start` (an independent set within `cand`): reduced, split into connected
    /// components solved one by one, each by branch and bound. Past the deadline, the best
    /// set found.
    fn solve(&mut self, mut cand: Bits, start: Vec<usize>) -> Vec<usize> {
        let mut forced = Vec::new();
        self.reduce(&mut cand, &mut forced);
        let parts = self.split(&cand);
        let mut found = forced;
        for part in parts {
            let mut best: Vec<usize> = start
                .iter()
                .copied()
                .filter(|&v| part.contains(v))
                .collect();
            self.expand(part, &mut Vec::new(), &mut best);
            found.extend(best);
        }
        if found.len() >= start.len() {
            found
        } else {
            start // only when stopped early
        }
    }

    fn expand(&mut self, mut cand: Bits, chosen: &mut Vec<usize>, best: &mut Vec<usize>) {
        if self.stopped {
            return;
        }
        self.nodes += 1;
        if self.nodes % 256 == 1 && crate::algo::past(self.deadline) {
            self.stopped = true;
            return;
        }
        let mark = chosen.len();
        self.reduce(&mut cand, chosen);
        if cand.is_empty() {
            if chosen.len() > best.len() {
                best.clone_from(chosen);
            }
            chosen.truncate(mark);
            return;
        }
        let enough = best.len().saturating_sub(chosen.len());
        if self.bound(&cand, enough, false) <= enough {
            chosen.truncate(mark);
            return;
        }
        let mut parts = self.split(&cand);
        if parts.len() > 1 {
            // The components are independent of each other: a maximum set of each but the
            // largest, taken, and the search goes on in the largest (keeping its bound).
            parts.sort_by_key(Bits::len);
            let largest = parts.pop().expect("two parts");
            for part in parts {
                let found = self.solve(part, Vec::new());
                chosen.extend(found);
            }
            self.expand(largest, chosen, best);
            chosen.truncate(mark);
            return;
        }
        let v = cand
            .iter()
            .max_by_key(|&v| cand.and_count(&self.closed[v]))
            .expect("not empty");
        chosen.push(v);
        self.expand(cand.minus(&self.closed[v]), chosen, best);
        chosen.pop();
        let mut without = cand;
        without.remove(v);
        if without.len() + chosen.len() > best.len() {
            self.expand(without, chosen, best);
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

    /// A maximum independent set size by plain include/exclude branching, memoised (no
    /// reductions, no bound: an independent oracle for graphs of up to 64 vertices).
    fn naive(adjacent: &[Vec<usize>]) -> usize {
        fn go(
            mask: u64,
            closed: &[u64],
            memo: &mut std::collections::HashMap<u64, usize>,
        ) -> usize {
            if mask == 0 {
                return 0;
            }
            if let Some(&known) = memo.get(&mask) {
                return known;
            }
            let v = mask.trailing_zeros() as usize;
            let best =
                go(mask & !(1 << v), closed, memo).max(1 + go(mask & !closed[v], closed, memo));
            memo.insert(mask, best);
            best
        }
        let closed: Vec<u64> = (0..adjacent.len())
            .map(|v| adjacent[v].iter().fold(1u64 << v, |m, &u| m | 1 << u))
            .collect();
        let all = if adjacent.len() == 64 {
            !0
        } else {
            (1u64 << adjacent.len()) - 1
        };
        go(all, &closed, &mut std::collections::HashMap::new())
    }

    /// Larger sparse graphs, where the reductions (degree, domination) and the splitting into
    /// components at search nodes all act: the size equals the naive oracle's.
    #[test]
    fn equals_a_naive_search_on_larger_sparse_graphs() {
        let mut seed = 0xd0_u64;
        for case in 0..300 {
            let n = 20 + case % 29;
            let density = [2, 4, 6, 9][case % 4];
            let g = random_graph(n, density, &mut seed);
            let found = maximum_independent_set(&g, None);
            assert!(found.optimal);
            assert_eq!(found.set.len(), naive(&g), "case {case}: {g:?}");
            for &v in &found.set {
                assert!(g[v].iter().all(|u| found.set.binary_search(u).is_err()));
            }
        }
    }

    /// Graphs rich in cliques and odd cycles, as the dependency graphs of polygons with holes
    /// are (segments crossing near common points): points in a square joined when close. The
    /// cover's unit propagation lowers the bound there; the size equals the naive oracle's and
    /// the root bound never falls below it.
    #[test]
    fn equals_a_naive_search_on_geometric_graphs() {
        let mut seed = 0x6e0_u64;
        let mut next = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % 1000
        };
        for case in 0..200 {
            let n = 24 + case % 40;
            let radius = [90, 140, 200, 260][case % 4];
            let points: Vec<(i64, i64)> = (0..n).map(|_| (next() as i64, next() as i64)).collect();
            let mut g = vec![Vec::new(); n];
            for v in 0..n {
                for u in 0..v {
                    let (dx, dy) = (points[v].0 - points[u].0, points[v].1 - points[u].1);
                    if dx * dx + dy * dy < radius * radius {
                        g[v].push(u);
                        g[u].push(v);
                    }
                }
            }
            let exact = naive(&g);
            let found = maximum_independent_set(&g, None);
            assert!(found.optimal);
            assert_eq!(found.set.len(), exact, "case {case}: {g:?}");
            for &v in &found.set {
                assert!(g[v].iter().all(|u| found.set.binary_search(u).is_err()));
            }
            let all: Vec<usize> = (0..n).collect();
            let (_, bound, _) = solve_component(&g, &all, Some(Instant::now()));
            assert!(bound >= exact, "case {case}: bound {bound} below {exact}");
            // The bound of components too large to search, from adjacency lists alone.
            let mut scratch = Scratch::default();
            scratch.cover_by_lists(&g);
            let lists = scratch.lower(
                &g,
                &Bits::full(n),
                0,
                Effort {
                    thorough: true,
                    deadline: None,
                    budget: usize::MAX,
                },
            );
            assert!(
                lists >= exact,
                "case {case}: list bound {lists} below {exact}"
            );
        }
    }

    /// A component too large to search (a chain of triangles, each joined to the next by an
    /// edge) keeps the local search's set, and the propagated cover's bound (one per triangle)
    /// where a matching's would allow half as many again.
    #[test]
    fn a_component_too_large_to_search_gets_the_cover_bound() {
        let m = SEARCH_LIMIT / 3 + 10;
        let mut g = vec![Vec::new(); 3 * m];
        let join = |g: &mut Vec<Vec<usize>>, a: usize, b: usize| {
            g[a].push(b);
            g[b].push(a);
        };
        for i in 0..m {
            join(&mut g, 3 * i, 3 * i + 1);
            join(&mut g, 3 * i + 1, 3 * i + 2);
            join(&mut g, 3 * i, 3 * i + 2);
            if i + 1 < m {
                join(&mut g, 3 * i + 2, 3 * i + 3);
            }
        }
        let found = maximum_independent_set(&g, None);
        assert_eq!(found.stopped, Some(Stopped::SearchSize));
        assert_eq!(found.upper_bound, m);
        assert_eq!(found.set.len(), m);
        for &v in &found.set {
            assert!(g[v].iter().all(|u| found.set.binary_search(u).is_err()));
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
