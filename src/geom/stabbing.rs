//! Closed intervals found by a value they hold (a *stabbing query*): the intervals sorted by
//! their low ends, over which a segment tree keeps the greatest high end of each node. A query
//! descends only into nodes whose intervals start at or below the value and reach up to it, so
//! it costs O((k + 1) log m) for k intervals found among m; building costs O(m log m).
//!
//! Used by the placement check of touching rings ([`super::touch`]), which asks for every ring
//! whose height range holds a point and every edge of the outer ring whose height range holds it
//! (the only edges a horizontal ray from the point can cross).

use super::kernel::Coord;
use std::cmp::Ordering;

/// A point ordered by its y coordinate alone.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ByY<P>(pub P);

impl<P: Coord> PartialEq for ByY<P> {
    fn eq(&self, other: &Self) -> bool {
        P::cmp_y(self.0, other.0) == Ordering::Equal
    }
}

impl<P: Coord> Eq for ByY<P> {}

impl<P: Coord> PartialOrd for ByY<P> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<P: Coord> Ord for ByY<P> {
    fn cmp(&self, other: &Self) -> Ordering {
        P::cmp_y(self.0, other.0)
    }
}

/// Closed intervals `[lo, hi]` with an item each, for stabbing queries.
pub(crate) struct Stabbing<K> {
    /// The intervals sorted by `lo`: `(lo, hi, item)`.
    sorted: Vec<(K, K, usize)>,
    /// `max[node]`: the greatest `hi` below the node (1-based heap order over `size` leaves).
    max: Vec<Option<K>>,
    size: usize,
}

impl<K: Copy + Ord> Stabbing<K> {
    /// The structure over `intervals` (`lo <= hi` each; an interval with `lo > hi` is never
    /// found).
    pub(crate) fn new(mut intervals: Vec<(K, K, usize)>) -> Stabbing<K> {
        intervals.sort_unstable_by_key(|a| a.0);
        let size = intervals.len().next_power_of_two().max(1);
        let mut max = vec![None; 2 * size];
        for (k, &(_, hi, _)) in intervals.iter().enumerate() {
            max[size + k] = Some(hi);
        }
        for node in (1..size).rev() {
            max[node] = max[2 * node].max(max[2 * node + 1]);
        }
        Stabbing {
            sorted: intervals,
            max,
            size,
        }
    }

    /// Calls `found` with the item of every interval holding `q`, in the order of their low
    /// ends.
    pub(crate) fn each(&self, q: K, mut found: impl FnMut(usize)) {
        let starts = self.sorted.partition_point(|&(lo, _, _)| lo <= q);
        self.descend(1, 0, self.size, starts, q, &mut found);
    }

    fn descend(
        &self,
        node: usize,
        from: usize,
        to: usize,
        starts: usize,
        q: K,
        found: &mut impl FnMut(usize),
    ) {
        if from >= starts || self.max[node].is_none_or(|hi| hi < q) {
            return;
        }
        if to - from == 1 {
            found(self.sorted[from].2);
            return;
        }
        let middle = (from + to) / 2;
        self.descend(2 * node, from, middle, starts, q, found);
        self.descend(2 * node + 1, middle, to, starts, q, found);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every query finds exactly the intervals a direct scan finds, in the order of their lows.
    #[test]
    fn stabbing_finds_what_a_scan_finds() {
        let mut seed = 0x57ab_u64;
        let mut next = |m: u64| {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            seed % m
        };
        for case in 0..200 {
            let m = (case % 40) as usize;
            let intervals: Vec<(u64, u64, usize)> = (0..m)
                .map(|k| {
                    let (a, b) = (next(50), next(50));
                    (a.min(b), a.max(b), k)
                })
                .collect();
            let tree = Stabbing::new(intervals.clone());
            for q in 0..52 {
                let mut found = Vec::new();
                tree.each(q, |k| found.push(k));
                found.sort_unstable();
                let expected: Vec<usize> = intervals
                    .iter()
                    .filter(|&&(lo, hi, _)| lo <= q && q <= hi)
                    .map(|&(_, _, k)| k)
                    .collect();
                assert_eq!(found, expected, "{intervals:?} at {q}");
            }
        }
    }
}
