//! A large independent set by iterated local search: (1,2)-swaps and random forced insertions
//! (Andrade, Resende & Werneck, "Fast local search for the maximum independent set problem",
//! *J. Heuristics* 18 (2012), Sections 2-3), for [`super::branch_and_bound`].
//!
//! The exact search prunes with its best set found so far, and a component too large to search
//! keeps whatever set it starts from; both gain from a set close to the maximum early. The
//! search here only ever returns an independent set at least as large as the one it is given,
//! so it can change which triangles are chosen but never make an answer worse or wrong.
//!
//! A *(1,2)-swap* takes one vertex `x` out of the set and two non-adjacent vertices in, both
//! having `x` as their only neighbour in the set. A local optimum has none left (and no free
//! vertex, one without a neighbour in the set). The iterated search then forces a random vertex
//! in (its neighbours in the set out), goes to a local optimum again, keeps the result if it is
//! no smaller than the best, and otherwise returns to the best.
//!
//! Bound: each forced insertion costs O(sum of the degrees within distance 2 of the vertices that
//! changed), and there are at most `rounds` of them; the deadline is read every 64 rounds. The
//! random choices come from a fixed seed: the same graph gives the same set.

use std::time::Instant;

/// Independent-set state: membership and, for each vertex, its number of neighbours in the set.
struct State<'a> {
    adjacent: &'a [Vec<usize>],
    inside: Vec<bool>,
    tight: Vec<u32>,
    size: usize,
    /// Set vertices whose (1,2)-swaps may have changed, to look at.
    queue: Vec<usize>,
    /// Scratch marks for the swap test.
    mark: Vec<bool>,
    /// The changes since the best set (vertex, whether it went in), to return to it.
    log: Vec<(usize, bool)>,
}

impl<'a> State<'a> {
    fn new(adjacent: &'a [Vec<usize>], set: &[usize]) -> State<'a> {
        let n = adjacent.len();
        let mut state = State {
            adjacent,
            inside: vec![false; n],
            tight: vec![0; n],
            size: 0,
            queue: Vec::new(),
            mark: vec![false; n],
            log: Vec::new(),
        };
        for &v in set {
            state.put(v);
        }
        state.queue.extend_from_slice(set);
        state
    }

    fn put(&mut self, v: usize) {
        self.inside[v] = true;
        self.size += 1;
        for &u in &self.adjacent[v] {
            self.tight[u] += 1;
        }
    }

    fn take(&mut self, v: usize) {
        self.inside[v] = false;
        self.size -= 1;
        for &u in &self.adjacent[v] {
            self.tight[u] -= 1;
        }
    }

    fn insert(&mut self, v: usize) {
        self.put(v);
        self.log.push((v, true));
        self.queue.push(v);
    }

    /// Takes `v` out, queueing the set vertices that may have gained a swap.
    fn remove(&mut self, v: usize) {
        self.take(v);
        self.log.push((v, false));
        for &u in &self.adjacent[v] {
            if self.tight[u] == 1 && !self.inside[u] {
                // `u` now hangs on one set vertex: that one may have a swap.
                if let Some(&x) = self.adjacent[u].iter().find(|&&x| self.inside[x]) {
                    self.queue.push(x);
                }
            }
        }
    }

    /// Puts in every vertex with no neighbour in the set, in the order given.
    fn fill(&mut self, order: impl IntoIterator<Item = usize>) {
        for v in order {
            if !self.inside[v] && self.tight[v] == 0 {
                self.insert(v);
            }
        }
    }

    /// Forces `v` in: its neighbours in the set go out, then free vertices near them go in.
    fn force(&mut self, v: usize) {
        let out: Vec<usize> = self.adjacent[v]
            .iter()
            .copied()
            .filter(|&u| self.inside[u])
            .collect();
        for &u in &out {
            self.remove(u);
        }
        self.insert(v);
        let adjacent = self.adjacent;
        for &u in &out {
            self.fill(adjacent[u].iter().copied());
        }
    }

    /// Undoes the changes since the best set.
    fn back_to_best(&mut self) {
        while let Some((v, went_in)) = self.log.pop() {
            if went_in {
                self.take(v);
            } else {
                self.put(v);
            }
        }
        self.queue.clear();
    }

    /// A (1,2)-swap around set vertex `x`, if there is one: two non-adjacent vertices whose
    /// only neighbour in the set is `x`.
    fn swap_pair(&mut self, x: usize) -> Option<(usize, usize)> {
        let hanging: Vec<usize> = self.adjacent[x]
            .iter()
            .copied()
            .filter(|&u| self.tight[u] == 1)
            .collect();
        if hanging.len() < 2 {
            return None;
        }
        for (k, &u) in hanging.iter().enumerate() {
            for &w in &self.adjacent[u] {
                self.mark[w] = true;
            }
            let partner = hanging[k + 1..].iter().copied().find(|&w| !self.mark[w]);
            for &w in &self.adjacent[u] {
                self.mark[w] = false;
            }
            if let Some(w) = partner {
                return Some((u, w));
            }
        }
        None
    }

    /// (1,2)-swaps until none is left around the queued vertices: a local optimum.
    fn descend(&mut self) {
        while let Some(x) = self.queue.pop() {
            if !self.inside[x] {
                continue;
            }
            if let Some((u, w)) = self.swap_pair(x) {
                self.remove(x);
                self.insert(u);
                self.insert(w);
                let adjacent = self.adjacent;
                self.fill(adjacent[x].iter().copied());
            }
        }
    }

    fn set(&self) -> Vec<usize> {
        (0..self.inside.len()).filter(|&v| self.inside[v]).collect()
    }
}

/// An independent set at least as large as `start` (an independent set of the graph given by
/// its adjacency lists: symmetric, no loops), by at most `rounds` forced insertions, stopping
/// early at `deadline`.
pub fn improve(
    adjacent: &[Vec<usize>],
    start: &[usize],
    rounds: usize,
    deadline: Option<Instant>,
) -> Vec<usize> {
    let n = adjacent.len();
    if n == 0 {
        return Vec::new();
    }
    let mut state = State::new(adjacent, start);
    state.fill(0..n);
    state.descend();
    state.log.clear();
    let mut best = state.size;
    let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
    let mut random = move |below: usize| {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed % below as u64) as usize
    };
    for round in 0..rounds {
        if round % 64 == 63 && crate::algo::past(deadline) {
            break;
        }
        // A vertex outside the set, chosen at random (a few tries; the set may be almost all).
        let Some(v) = (0..8).map(|_| random(n)).find(|&v| !state.inside[v]) else {
            continue;
        };
        state.force(v);
        state.descend();
        if state.size >= best {
            // As large as the best: the new best (moving along plateaus diversifies).
            best = state.size;
            state.log.clear();
        } else {
            state.back_to_best();
        }
    }
    state.back_to_best();
    state.set()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn independent(adjacent: &[Vec<usize>], set: &[usize]) -> bool {
        let mut inside = vec![false; adjacent.len()];
        for &v in set {
            inside[v] = true;
        }
        set.iter().all(|&v| adjacent[v].iter().all(|&u| !inside[u]))
    }

    /// A star: from its centre, a (1,2)-swap puts two leaves in and the others follow as free
    /// vertices.
    #[test]
    fn a_swap_trades_a_centre_for_its_leaves() {
        let mut adjacent = vec![vec![1, 2, 3, 4]];
        adjacent.extend((1..5).map(|_| vec![0]));
        assert_eq!(improve(&adjacent, &[0], 0, None), vec![1, 2, 3, 4]);
    }

    /// On random graphs: always independent, never smaller than the start, and on graphs the
    /// exact search solves, never above its maximum (a sanity check on the bookkeeping).
    #[test]
    fn sets_are_independent_and_no_smaller() {
        let mut seed = 0xabc_u64;
        for case in 0..200 {
            let n = 5 + case % 60;
            let mut adjacent = vec![Vec::new(); n];
            for v in 0..n {
                for u in 0..v {
                    seed ^= seed << 13;
                    seed ^= seed >> 7;
                    seed ^= seed << 17;
                    if seed % 100 < 12 {
                        adjacent[v].push(u);
                        adjacent[u].push(v);
                    }
                }
            }
            let start = vec![0];
            let found = improve(&adjacent, &start, 200, None);
            assert!(independent(&adjacent, &found), "case {case}");
            let exact = super::super::branch_and_bound::maximum_independent_set(&adjacent, None);
            assert!(found.len() <= exact.set.len(), "case {case}");
            assert!(found.len() >= start.len(), "case {case}");
        }
    }
}
