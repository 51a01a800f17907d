//! Step 3 on corridors: the scans of [`super::mis`] jump over nested ranges ("ladders").
//!
//! In a long corridor the triangles across it (rungs) nest along its whole length, each rung's
//! gap is a range asked for, and Valiente's method scans each of them: Theta(n^2) positions
//! (the bars and the snake of `docs/benchmarks.md`). This module removes the repetition
//! without changing a single value.
//!
//! A scan (weighted interval scheduling over a range, left to right) is max-plus linear: what
//! it computes at a position is a maximum of sums of a constant and one value computed earlier.
//! Cut the line before position `a` and after `b`. Inside `a..=b` the scan reads, from before
//! `a`, only a few values: the best before `a` itself, the best before `lo` for each unit (or
//! staircase piece) ending inside and starting before `a`, and the running maximum of each
//! staircase whose consecutive ends straddle the cut. These are the level's *in-slots*. After
//! `b` the outer scan reads, from inside, the best before `b + 1` and the values of units and
//! staircases starting inside and ending after `b`: its *out-slots*. So the out-slots are a
//! max-plus matrix times the in-slots, the same for every scan that passes over `a..=b` (a scan
//! starting later than some in-slot's position reads it as minus infinity: that unit does not
//! lie within its range). The matrix is built once by one scan of `a..=b` per in-slot (that
//! slot 0, the others minus infinity), and each of those scans jumps over the levels nested
//! inside in turn. A range containing a level then costs its positions outside the level plus
//! one matrix product, instead of its whole length.
//!
//! The levels are chosen among the ranges asked for: only those with few slots (at most 24
//! each way, found with two reporting trees, not by walking the range), and only where the
//! positions a level owns (its length minus the levels it jumps itself) are at least 128 and
//! pay for a matrix product (at least ins x outs). Both numbers were measured best
//! (docs/benchmarks.md). Nothing depends on
//! the choice for exactness: every choice gives the values of plain scans, which the tests
//! check with a level at every range asked for (`LadderPolicy::Every`) against no levels.
//!
//! One thing breaks "built once": values are found in order of span, so when a level is first
//! needed, a unit reaching into it from outside (or a staircase gap across its start) may not
//! be valued yet. Its column of the matrix is then wrong, but only a scan starting at or before
//! that unit's start multiplies that column by a finite value; so a level records the furthest
//! such start (`valid_from`), and a scan from further out builds it again (by then everything
//! within the scan's range is valued). Values are `i64`: counts are below 2^32, minus infinity
//! is -2^50, and a sum never adds more than two of them before it is clamped.
//!
//! Costs: with at most `sigma` slots per level and levels every `sigma^2` positions or more,
//! building all matrices costs O(n sigma) and each range asked for at most O(sigma^2) beyond
//! its own positions before its first level. On the corridors the slots are the diagonal rungs
//! reaching into the level and the pieces of the two walls' 3b-chains across its cuts: 7 to 25
//! on the bars, whose scans then stay linear. On the snake (a vertex at every lattice point)
//! bundles of long diagonal triangles cross each other, cuts through a bundle have hundreds of
//! slots and are no levels, and the positions scanned grow about as the square root of the
//! length per position.
//! The reconstruction scans again and, where its walk back needs a value inside a level it
//! jumped, scans that level from the values saved at the jump (see `mis::Sub::best_in`).

use std::collections::BTreeSet;

/// Minus infinity in the max-plus products (far from overflow when a few are added).
pub(super) const NEG: i64 = -(1 << 50);

/// `v`, or [`NEG`] if it is a sum involving minus infinity.
pub(super) fn clamp(v: i64) -> i64 {
    if v < NEG / 2 {
        NEG
    } else {
        v
    }
}

/// A value a scan reads across a cut.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) enum Slot {
    /// The best value before a local position (within the scan's range).
    Before(u32),
    /// The running maximum `M(i)` of staircase `stair` (see `mis::Staircase`).
    Run { stair: u32, i: u32 },
}

/// Something read across positions: `slot`, whose value is settled at `lo`, read at `hi`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Reader {
    pub lo: u32,
    pub hi: u32,
    pub slot: Slot,
}

/// How levels are chosen (`Off` and `Every` are for the tests).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(not(test), allow(dead_code))]
pub(crate) enum LadderPolicy {
    /// No levels: every range is scanned whole.
    Off,
    /// Levels where they save work (the default).
    Auto,
    /// A level at every range asked for, whatever its slots (for the tests).
    Every,
}

/// A range `a..=b` whose scan is a matrix from its in-slots to its out-slots.
pub(super) struct Level {
    pub a: usize,
    pub b: usize,
    /// `ins[0]` is `Before(a)`.
    pub ins: Vec<Slot>,
    /// `outs[0]` is `Before(b + 1)`.
    pub outs: Vec<Slot>,
    /// The levels its own scans jump, in order.
    pub jumps: Vec<u32>,
    /// `outs.len()` rows of `ins.len()` entries; empty until built.
    pub matrix: Vec<i64>,
    /// The matrix holds for scans from `valid_from` or later: it was built before every unit
    /// or staircase gap reaching into the level from before `valid_from - 1` was valued (their
    /// columns are then wrong, and a scan from `valid_from` or later multiplies them by minus
    /// infinity, since they do not lie within its range).
    pub valid_from: usize,
}

/// The levels of one component, found by start.
pub(super) struct Ladders {
    pub levels: Vec<Level>,
    /// Positions where levels start.
    starts: BTreeSet<u32>,
    /// The longest level starting at a position (`u32::MAX`: none), and for each level the
    /// next shorter one with the same start.
    head: Vec<u32>,
    shorter: Vec<u32>,
}

const NONE: u32 = u32::MAX;

impl Ladders {
    /// No levels.
    pub fn none() -> Ladders {
        Ladders {
            levels: Vec::new(),
            starts: BTreeSet::new(),
            head: Vec::new(),
            shorter: Vec::new(),
        }
    }

    /// Chooses the levels among `ranges` (the ranges asked for, inclusive local positions) of a
    /// component with `p` positions, whose scans read across positions as `readers` say.
    pub fn choose(
        p: usize,
        policy: LadderPolicy,
        ranges: &[(u32, u32)],
        readers: impl FnOnce() -> Vec<Reader>,
    ) -> Ladders {
        let mut ladders = Ladders::none();
        let (min_len, max_slots) = match policy {
            LadderPolicy::Off => return ladders,
            LadderPolicy::Auto => (128, 24),
            LadderPolicy::Every => (1, usize::MAX),
        };
        let mut candidates: Vec<(u32, u32)> = ranges
            .iter()
            .copied()
            .filter(|&(a, b)| (b - a + 1) as usize >= min_len)
            .collect();
        if candidates.is_empty() {
            return ladders;
        }
        candidates.sort_unstable_by_key(|&(a, b)| (b - a, a));
        ladders.head = vec![NONE; p + 1];
        candidates.dedup();
        // Readers ending in `a..=b` that start before `a`, and those starting in `a..=b` that
        // end after `b`.
        let readers = readers();
        let readers = &readers[..];
        let limit = max_slots.saturating_mul(3); // readers, several per slot at most
        let mut by_hi = Reporter::new(readers, |r| r.hi, |r| r.lo);
        let mut by_lo = Reporter::new(readers, |r| r.lo, |r| u32::MAX - r.hi);
        let mut found = Vec::new();
        let mut jumps = Vec::new();
        for (a, b) in candidates {
            let (a, b) = (a as usize, b as usize);
            ladders.jumps_in(a, b, &mut jumps);
            let jumped: usize = jumps
                .iter()
                .map(|&k| ladders.levels[k as usize].b + 1 - ladders.levels[k as usize].a)
                .sum();
            // A level pays when a jump over it (a product) is cheaper than scanning the
            // positions it does not jump itself: at most `own` in-slots times out-slots (so
            // the reports stop early where that fails).
            let own = match policy {
                LadderPolicy::Auto => b + 1 - a - jumped,
                _ => usize::MAX,
            };
            if own < min_len {
                continue; // (without a report: most candidates, those just around a level)
            }
            let mut ins = vec![Slot::Before(a as u32)];
            if !by_hi.report(a as u32, b as u32, a as u32, limit.min(own), &mut found) {
                continue;
            }
            ins.extend(found.iter().map(|&r| readers[r as usize].slot));
            dedup_after_first(&mut ins);
            let mut outs = vec![Slot::Before(b as u32 + 1)];
            let most = limit.min(own / ins.len());
            if !by_lo.report(a as u32, b as u32, u32::MAX - b as u32, most, &mut found) {
                continue;
            }
            outs.extend(found.iter().map(|&r| readers[r as usize].slot));
            dedup_after_first(&mut outs);
            if ins.len() > max_slots || outs.len() > max_slots || ins.len() * outs.len() > own {
                continue;
            }
            let k = ladders.levels.len() as u32;
            ladders.levels.push(Level {
                a,
                b,
                ins,
                outs,
                jumps: jumps.clone(),
                matrix: Vec::new(),
                valid_from: 0,
            });
            // Candidates come by length, so the new level is the longest at its start.
            ladders.shorter.push(ladders.head[a]);
            ladders.head[a] = k;
            ladders.starts.insert(a as u32);
        }
        ladders
    }

    /// The level that is exactly `a..=b`, if any.
    pub fn level(&self, a: usize, b: usize) -> Option<usize> {
        let mut k = *self.head.get(a)?;
        while k != NONE {
            let level = &self.levels[k as usize];
            if level.b == b {
                return Some(k as usize);
            }
            k = self.shorter[k as usize];
        }
        None
    }

    /// The levels a scan of `a..=b` jumps, into `out` in order: from the left, the longest
    /// level starting at each position and lying within `a..=b`.
    pub fn jumps_in(&self, a: usize, b: usize, out: &mut Vec<u32>) {
        out.clear();
        let mut x = a as u32;
        while x as usize <= b {
            let Some(&s) = self.starts.range(x..=b as u32).next() else {
                break;
            };
            let mut k = self.head[s as usize];
            while k != NONE && self.levels[k as usize].b > b {
                k = self.shorter[k as usize];
            }
            if k == NONE {
                x = s + 1;
            } else {
                out.push(k);
                x = self.levels[k as usize].b as u32 + 1;
            }
        }
    }

    /// The out-slot values of level `k` from its in-slot values (its matrix must be built).
    pub fn apply(&self, k: usize, entry: &[i64], out: &mut Vec<i64>) {
        let level = &self.levels[k];
        let n = level.ins.len();
        out.clear();
        out.resize(level.outs.len(), NEG);
        for (c, &v) in entry.iter().enumerate() {
            if v == NEG {
                continue;
            }
            for (r, o) in out.iter_mut().enumerate() {
                *o = (*o).max(v + level.matrix[r * n + c]);
            }
        }
        out.iter_mut().for_each(|o| *o = clamp(*o));
    }
}

/// Removes repeated slots, keeping the first one in front.
fn dedup_after_first(slots: &mut Vec<Slot>) {
    let first = slots[0];
    slots[1..].sort_unstable();
    slots.dedup();
    let mut seen = false;
    slots.retain(|&s| s != first || !std::mem::replace(&mut seen, true));
}

/// Readers sorted by one position (`at`), with a minimum tree over a key, to report those with
/// `at` in a range whose key is below a bound: O((reported + 1) log n).
struct Reporter {
    /// The readers' indices in order of `at`, and their `at`.
    order: Vec<u32>,
    at: Vec<u32>,
    /// A complete binary tree of minimum keys over `order` (leaves from `size`).
    tree: Vec<u32>,
    size: usize,
    /// The nodes still to visit in [`Reporter::report`] (kept to save an allocation).
    stack: Vec<(usize, usize, usize)>,
}

impl Reporter {
    fn new(readers: &[Reader], at: impl Fn(&Reader) -> u32, key: impl Fn(&Reader) -> u32) -> Self {
        let mut order: Vec<u32> = (0..readers.len() as u32).collect();
        order.sort_unstable_by_key(|&r| at(&readers[r as usize]));
        let size = order.len().next_power_of_two().max(1);
        let mut tree = vec![u32::MAX; 2 * size];
        for (i, &r) in order.iter().enumerate() {
            tree[size + i] = key(&readers[r as usize]);
        }
        for i in (1..size).rev() {
            tree[i] = tree[2 * i].min(tree[2 * i + 1]);
        }
        let at = order.iter().map(|&r| at(&readers[r as usize])).collect();
        Reporter {
            order,
            at,
            tree,
            size,
            stack: Vec::new(),
        }
    }

    /// The readers with `at` in `lo..=hi` and key below `bound`, into `found`; false if there
    /// are more than `limit`.
    fn report(&mut self, lo: u32, hi: u32, bound: u32, limit: usize, found: &mut Vec<u32>) -> bool {
        found.clear();
        let first = self.at.partition_point(|&x| x < lo);
        let end = self.at.partition_point(|&x| x <= hi);
        if first >= end {
            return true;
        }
        // Nodes covering [first, end), visited from the root.
        let stack = &mut self.stack;
        stack.clear();
        stack.push((1, 0, self.size));
        while let Some((node, l, r)) = stack.pop() {
            if r <= first || end <= l || self.tree[node] >= bound {
                continue;
            }
            if node >= self.size {
                if found.len() == limit {
                    return false;
                }
                found.push(self.order[l]);
                continue;
            }
            let m = (l + r) / 2;
            stack.push((2 * node + 1, m, r));
            stack.push((2 * node, l, m));
        }
        true
    }
}
