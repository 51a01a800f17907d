//! Step 3 for small crossing components: a maximum independent set by branching over bit sets.
//!
//! Most connected components of the crossing graph are small (a footprint's few notches, a
//! maze's corridors), and for them the scans of [`super::mis`] cost far more to set up than to
//! run: on 8- to 40-vertex rectilinear polygons step 3 took about 80,000 instructions per
//! polygon. A component of at most [`SMALL`] chords is first searched here, directly on the
//! dependency relation of Theorem 1 without holes (Chen & Chang 1990, §2; see [`super::mis`]):
//! two triangles are dependent exactly when their chords cross on the circle and they are not in
//! one 3b-chain (any set of a chain's members is independent).
//!
//! The search keeps a set `chosen` and the chords still free (`left`, bit sets) and repeats:
//! - a chord with at most one dependent chord left is in some maximum set of what is left (if
//!   its neighbour is in one, swapping the neighbour for it keeps the set independent and as
//!   large), so it is chosen and its neighbour dropped;
//! - otherwise it branches on a chord with the most dependents left: chosen (its dependents
//!   are dropped), then dropped;
//!
//! and abandons a branch that cannot beat the largest set found (`chosen` plus all of `left`
//! is no larger). Exact, since the rules keep a maximum set reachable and the bound only drops
//! branches no better than one found. Time: O(k) per pass of the first rule, at most k passes
//! per node; branching happens only on a chord with two or more dependents left, so the tree is
//! small where the graph is dense or a forest of paths, and can grow as 1.38^k on sparse graphs
//! in between: after [`BUDGET`] nodes the search gives up and the component goes to the scans
//! (which are polynomial). On the batch benchmark's polygons (components of 2 to 38 chords) it
//! visits 1 to 37 nodes, 3 on average; step 3 went from about 80,000 to 22,000 instructions per
//! polygon there.

use super::chains::Chains;
use super::circle::Circle;

/// The largest component searched here (a bit set over the chords, `u64`).
pub const SMALL: usize = u64::BITS as usize;

/// The most search nodes spent on one component before giving it back to the scans.
pub const BUDGET: usize = 2_000;

/// A maximum independent set of the triangles of one crossing `component` (at most [`SMALL`]
/// of them), as triangle indices; `None` if the search needed more than [`BUDGET`] nodes.
///
/// # Panics
/// If the component has more than [`SMALL`] triangles.
pub fn maximum_independent_set(
    circle: &Circle,
    chains: &Chains,
    component: &[usize],
) -> Option<Vec<usize>> {
    assert!(
        component.len() <= SMALL,
        "a small component fits a u64 bit set"
    );
    if component.is_empty() {
        return Some(Vec::new());
    }
    let dependents = dependents(circle, chains, component);
    let mut search = Search {
        dependents: &dependents[..component.len()],
        best: 0,
        best_size: 0,
        nodes: 0,
    };
    search.run(0, u64::MAX >> (SMALL - component.len()))?;
    let best = search.best;
    Some(
        component
            .iter()
            .enumerate()
            .filter(|&(i, _)| best >> i & 1 == 1)
            .map(|(_, &t)| t)
            .collect(),
    )
}

/// For each chord of `component` (at most [`SMALL`]), the chords of the component it depends
/// on, as a bit set over positions in `component`: those it crosses on the circle, except the
/// members of its own 3b-chain.
///
/// One sweep along the circle instead of a test of every pair (docs/benchmarks.md): chord ends are distinct positions, and a chord `(a, b)` crosses exactly the
/// chords opened after `a` and still open at `b` (a chord opened before `a` and open at `b`
/// encloses it). O(k log k) for the ends' order, plus O(1) per crossing.
fn dependents(circle: &Circle, chains: &Chains, component: &[usize]) -> [u64; SMALL] {
    // The ends, by position: (position, index in the component, opening).
    let mut ends = [(0usize, 0u8, false); 2 * SMALL];
    let ends = &mut ends[..2 * component.len()];
    for (i, &t) in component.iter().enumerate() {
        let (l, r) = circle.chords[t];
        ends[2 * i] = (l, i as u8, true);
        ends[2 * i + 1] = (r, i as u8, false);
    }
    ends.sort_unstable_by_key(|e| e.0);
    let mut dependents = [0u64; SMALL];
    // The chords opened so far, those open now, and for each chord those opened before it.
    let (mut opened, mut open) = (0u64, 0u64);
    let mut before = [0u64; SMALL];
    for &(_, i, opening) in ends.iter() {
        let i = usize::from(i);
        if opening {
            before[i] = opened;
            opened |= 1 << i;
            open |= 1 << i;
            continue;
        }
        open &= !(1 << i);
        let mut crossing = open & !before[i];
        let chain = chains.place[component[i]].0;
        while crossing != 0 {
            let j = crossing.trailing_zeros() as usize;
            crossing &= crossing - 1;
            if chains.place[component[j]].0 != chain {
                dependents[i] |= 1 << j;
                dependents[j] |= 1 << i;
            }
        }
    }
    dependents
}

/// The search over bit sets of the component's chords.
struct Search<'a> {
    dependents: &'a [u64],
    /// The largest independent set found so far, and its size.
    best: u64,
    best_size: u32,
    /// Nodes visited.
    nodes: usize,
}

impl Search<'_> {
    /// Extends `chosen` (independent) by chords of `left` (none dependent on `chosen`), and
    /// keeps the result in `best` if larger; `None` once over the budget.
    fn run(&mut self, mut chosen: u64, mut left: u64) -> Option<()> {
        self.nodes += 1;
        if self.nodes > BUDGET {
            return None;
        }
        // Take every chord with at most one dependent left (`d & (d - 1) == 0`: at most one
        // bit), until none is left.
        loop {
            let before = left;
            let mut bits = left;
            while bits != 0 {
                let v = bits.trailing_zeros() as usize;
                bits &= bits - 1;
                let d = self.dependents[v] & left;
                if left >> v & 1 == 1 && d & d.wrapping_sub(1) == 0 {
                    chosen |= 1 << v;
                    left &= !(1 << v | d);
                }
            }
            if left == before {
                break;
            }
        }
        let size = chosen.count_ones();
        if size + left.count_ones() <= self.best_size {
            return Some(()); // cannot beat the best found
        }
        if left == 0 {
            (self.best, self.best_size) = (chosen, size);
            return Some(());
        }
        // Branch on the chord with the most dependents left (the lowest index among equals,
        // so the result is deterministic): chosen, then dropped.
        let mut most = (0, 0);
        let mut bits = left;
        while bits != 0 {
            let v = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            let degree = (self.dependents[v] & left).count_ones();
            if degree > most.0 {
                most = (degree, v);
            }
        }
        let v = most.1;
        self.run(chosen | 1 << v, left & !(1 << v | self.dependents[v]))?;
        self.run(chosen, left & !(1 << v))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::minitri::circle::chords_cross;
    use proptest::prelude::*;

    proptest! {
        /// The sweep finds exactly the pairs that cross and are not in one chain, on random
        /// chords with distinct ends (a component's, or any set of chords), random chains.
        #[test]
        fn dependents_are_the_crossing_pairs_of_other_chains(
            order in Just((0..2 * SMALL).collect::<Vec<usize>>()).prop_shuffle(),
            k in 1..=SMALL,
            chain_of in proptest::collection::vec(0..4usize, SMALL),
        ) {
            let chords: Vec<(usize, usize)> = (0..k)
                .map(|i| (order[2 * i].min(order[2 * i + 1]), order[2 * i].max(order[2 * i + 1])))
                .collect();
            let mut owner = vec![0; 2 * SMALL];
            for (t, &(l, r)) in chords.iter().enumerate() {
                owner[l] = t;
                owner[r] = t;
            }
            let circle = Circle { chords: chords.clone(), owner };
            let mut chains = Chains::lone(k);
            for (t, place) in chains.place.iter_mut().enumerate() {
                place.0 = chain_of[t];
            }
            // The component lists the chords in some order other than by triangle.
            let component: Vec<usize> = (0..k).rev().collect();
            let found = dependents(&circle, &chains, &component);
            for i in 0..k {
                let mut expected = 0u64;
                for j in 0..k {
                    let (s, t) = (component[i], component[j]);
                    if chords_cross(chords[s], chords[t]) && chain_of[s] != chain_of[t] {
                        expected |= 1 << j;
                    }
                }
                prop_assert_eq!(found[i], expected, "chord {}", i);
            }
        }
    }
}
