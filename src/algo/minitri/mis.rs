//! Step 3 of MINITRI: a maximum set of mutually independent minimally degenerate triangles
//! (Chen & Chang 1990, §3, Algorithm MISMDT, extending Supowit's circle-graph algorithm).
//!
//! Two triangles are dependent exactly when their chords cross on the circle of [`super::circle`],
//! except for the pairs of a 3b-chain: two triangles `(a, b, c)` and `(b, c, d)` on one line
//! sharing the side `b c`, with their 180-degree sides on the same side of the line. Those cross
//! on the circle yet are independent (relationship (iii)(b)); a 3b-chain is a path of such pairs,
//! and any set of its members is independent.
//!
//! `MIS(i, j)` is the largest independent set among the chords with both endpoints in positions
//! `i..=j`. Let `k j` be the chord ending at `j`. If `k` lies outside `i..j`, or the chord is not
//! used, `MIS(i, j) = MIS(i, j - 1)`. If it is used, every chosen chord crossing it is a 3b-partner
//! of it, and so on: the chosen chords connected to `k j` by crossings form a contiguous piece `S`
//! of its 3b-chain, lying in `i..=j`; every other chosen chord lies in one of the gaps between
//! consecutive endpoints of `S` (a chord spanning two gaps would cross a chord of `S`, since `S`
//! is connected by crossings), and chords in different gaps cannot cross. So
//! `MIS(i, j) = max(MIS(i, j - 1), max over S of |S| + sum of MIS(gap))`, which is exact
//! (Theorem 6), with 3b-chains of any length.
//!
//! Computation: the paper fills the table `MIS(i, j)` (O(K^2) memory). Here the circle is first
//! split into the connected components of its crossing graph (dependent chords cross, so the
//! components are independent problems; a lone chord is always taken), and each component is
//! solved by weighted interval scheduling over "units" (a chord, or a contiguous piece of a
//! 3b-chain) taken in order of span, in the manner of G. Valiente, "A new simple algorithm for
//! the maximum-weight independent set problem on circle graphs", ISAAC 2003: each unit's value
//! needs only the best sets in the gaps inside it, found by one scan each.
//!
//! Complexity: O(K alpha(K)) for the components; then the sum over units of their spans (in
//! endpoint positions of their component): O(K L) units for chains of length at most L, each span
//! at most the component's size, so O(K^2 L) in the worst case, near-linear when chords are
//! local; O(K L) memory.

use super::circle::Circle;
use super::degenerate::Degenerate;
use crate::geom::kernel::{cross, Dir};
use crate::geom::polygon::Polygon;
use std::collections::HashMap;

/// The 3b-chains: for each triangle, its chain (a path of 3b-partners) and its place in it.
#[derive(Clone, Debug)]
pub struct Chains {
    /// The chains, each a list of triangles in order along their line.
    pub paths: Vec<Vec<usize>>,
    /// For each triangle: (its chain, its index in that chain).
    pub place: Vec<(usize, usize)>,
}

/// Whether `s` and `t` form a 3b pair: they share a side on one line (the middle of each is an
/// end of the other) and their 180-degree sides lie on the same side of the line.
pub fn is_3b_pair(polygon: &Polygon, s: &Degenerate, t: &Degenerate) -> bool {
    let ends = |m: &Degenerate, v: usize| m.a == v || m.c == v;
    if !(ends(s, t.b) && ends(t, s.b)) {
        return false;
    }
    let (pa, pc) = (polygon.point(s.a), polygon.point(s.c));
    let (qa, qc) = (polygon.point(t.a), polygon.point(t.c));
    debug_assert!(cross(pa, pc, qa) == 0 && cross(pa, pc, qc) == 0);
    // Express t's side in s's orientation of the common line.
    let same_direction = Dir::between(pa, pc).dot(Dir::between(qa, qc)) > 0;
    let t_side = if same_direction {
        t.non_straight_side(polygon)
    } else {
        -t.non_straight_side(polygon)
    };
    s.non_straight_side(polygon) == t_side
}

/// Finds the 3b-chains among `mdts`.
pub fn chains(polygon: &Polygon, mdts: &[Degenerate]) -> Chains {
    let mut by_middle_end: HashMap<(usize, usize), usize> = HashMap::new();
    for (t, m) in mdts.iter().enumerate() {
        by_middle_end.insert((m.b, m.a), t);
        by_middle_end.insert((m.b, m.c), t);
    }
    let mut partners: Vec<Vec<usize>> = vec![Vec::new(); mdts.len()];
    for (s, m) in mdts.iter().enumerate() {
        for end in [m.a, m.c] {
            if let Some(&t) = by_middle_end.get(&(end, m.b)) {
                if is_3b_pair(polygon, m, &mdts[t]) {
                    partners[s].push(t);
                }
            }
        }
    }
    let mut place = vec![(usize::MAX, 0); mdts.len()];
    let mut paths = Vec::new();
    for start in 0..mdts.len() {
        if place[start].0 != usize::MAX || partners[start].len() == 2 {
            continue; // already placed, or inside a path (paths start at an end)
        }
        let mut path = vec![start];
        let (mut prev, mut at) = (usize::MAX, start);
        while let Some(&next) = partners[at].iter().find(|&&p| p != prev) {
            path.push(next);
            (prev, at) = (at, next);
        }
        for (i, &t) in path.iter().enumerate() {
            place[t] = (paths.len(), i);
        }
        paths.push(path);
    }
    Chains { paths, place }
}

/// A maximum independent set of the triangles, as indices into the triangle list.
///
/// The dependency graph has no edge between different connected components of the crossing
/// graph on the circle (dependent chords cross), so each component is solved on its own: a lone
/// chord is always taken, larger components go through the exact recurrence on their own
/// endpoints only.
pub fn maximum_independent_set(circle: &Circle, chains: &Chains) -> Vec<usize> {
    let mut chosen = Vec::new();
    let mut local = vec![u32::MAX; circle.owner.len()];
    for component in crossing_components(circle) {
        if component.len() == 1 {
            chosen.push(component[0]);
            continue;
        }
        let mut positions: Vec<usize> = component
            .iter()
            .flat_map(|&t| [circle.chords[t].0, circle.chords[t].1])
            .collect();
        positions.sort_unstable();
        for (i, &g) in positions.iter().enumerate() {
            local[g] = i as u32;
        }
        let sub = Sub {
            circle,
            chains,
            positions: &positions,
            local: &local,
        };
        chosen.extend(sub.solve());
    }
    chosen
}

/// The connected components of the crossing graph of the chords, each a list of triangles.
///
/// One pass over the circle with a stack of groups of chords already known to be connected, each
/// with its number of chords still open. When a chord closes, every group above its own group on
/// the stack holds open chords that opened after it, so each crosses it: they merge into its group.
/// A group with no open chord left is popped (anything later either encloses or avoids it).
/// O(K alpha(K)) with union-find.
pub fn crossing_components(circle: &Circle) -> Vec<Vec<usize>> {
    let k = circle.chords.len();
    let mut parent: Vec<usize> = (0..k).collect();
    fn find(parent: &mut [usize], mut x: usize) -> usize {
        while parent[x] != x {
            parent[x] = parent[parent[x]];
            x = parent[x];
        }
        x
    }
    let mut stack: Vec<(usize, usize)> = Vec::new(); // (a chord of the group, open chords)
    for (position, &t) in circle.owner.iter().enumerate() {
        if circle.chords[t].0 == position {
            stack.push((t, 1));
            continue;
        }
        let root = find(&mut parent, t);
        let mut open_above = 0;
        while let Some(&(member, open)) = stack.last() {
            let r = find(&mut parent, member);
            if r == root {
                break;
            }
            stack.pop();
            parent[r] = root;
            open_above += open;
        }
        if let Some(top) = stack.last_mut() {
            top.1 += open_above;
            top.1 -= 1;
            if top.1 == 0 {
                stack.pop();
            }
        }
    }
    let mut groups: std::collections::BTreeMap<usize, Vec<usize>> =
        std::collections::BTreeMap::new();
    for t in 0..k {
        let r = find(&mut parent, t);
        groups.entry(r).or_default().push(t);
    }
    groups.into_values().collect()
}

/// One component: its endpoints `positions` (global, sorted) and the map back (`local`).
struct Sub<'a> {
    circle: &'a Circle,
    chains: &'a Chains,
    positions: &'a [usize],
    local: &'a [u32],
}

/// A candidate for the top level of some range: one chord, or a contiguous piece of a 3b-chain
/// (whose chords cross one after the other), spanning local positions `lo..=hi`.
struct Unit {
    /// The piece `paths[chain][first..=last]` of a 3b-chain (a lone chord is a piece of one).
    chain: usize,
    first: usize,
    last: usize,
    lo: usize,
    hi: usize,
    /// Its chords plus the best inside each gap between their endpoints.
    value: u32,
}

impl Sub<'_> {
    fn piece(&self, unit: &Unit) -> &[usize] {
        &self.chains.paths[unit.chain][unit.first..=unit.last]
    }

    fn chord(&self, t: usize) -> (usize, usize) {
        let (l, r) = self.circle.chords[t];
        (self.local[l] as usize, self.local[r] as usize)
    }

    /// The gaps between consecutive endpoints of a unit's chords (inside its span).
    fn gaps(&self, chords: &[usize]) -> Vec<(usize, usize)> {
        let mut ends: Vec<usize> = chords
            .iter()
            .flat_map(|&t| <[usize; 2]>::from(self.chord(t)))
            .collect();
        ends.sort_unstable();
        ends.windows(2)
            .filter(|w| w[1] > w[0] + 1)
            .map(|w| (w[0] + 1, w[1] - 1))
            .collect()
    }

    /// A maximum independent set of this component.
    ///
    /// Any independent set splits into groups connected by crossings; each group is a unit (a
    /// lone chord, or a contiguous piece of a 3b-chain, the only independent chords that cross),
    /// the spans of two groups are nested or disjoint (a chord reaching from a gap of a group to
    /// outside that gap would cross the group), and a group nested in another lies in one of its
    /// gaps. So the best set in a range is a heaviest set of units with disjoint spans in it
    /// (weighted interval scheduling, one scan), where a unit weighs its chords plus the best in
    /// each of its gaps: ranges strictly inside it, already known when units are taken in order
    /// of span. Time: the sum of the units' spans; memory: linear in the units.
    fn solve(&self) -> Vec<usize> {
        let p = self.positions.len();
        let mut units: Vec<Unit> = Vec::new();
        let mut seen_chain = std::collections::HashSet::new();
        for &g in self.positions {
            let t = self.circle.owner[g];
            let (chain, _) = self.chains.place[t];
            if !seen_chain.insert(chain) {
                continue;
            }
            let path = &self.chains.paths[chain];
            for first in 0..path.len() {
                let (mut lo, mut hi) = (usize::MAX, 0);
                for (last, &c) in path.iter().enumerate().skip(first) {
                    let (l, r) = self.chord(c);
                    (lo, hi) = (lo.min(l), hi.max(r));
                    units.push(Unit {
                        chain,
                        first,
                        last,
                        lo,
                        hi,
                        value: 0,
                    });
                }
            }
        }
        units.sort_by_key(|u| u.hi - u.lo);
        let mut ending: Vec<Vec<usize>> = vec![Vec::new(); p];
        let mut scratch = Vec::new();
        // The best value inside a range, once known, stays known: every unit inside a gap of a
        // unit is narrower than that unit, so it was valued before the gap was first asked for.
        let mut memo: HashMap<(usize, usize), u32> = HashMap::new();
        for k in 0..units.len() {
            let mut inside = 0;
            for (a, b) in self.gaps(self.piece(&units[k])) {
                inside += *memo
                    .entry((a, b))
                    .or_insert_with(|| best_in(&units, &ending, a, b, &mut scratch).0);
            }
            units[k].value = (units[k].last - units[k].first + 1) as u32 + inside;
            ending[units[k].hi].push(k);
        }
        let mut chosen = Vec::new();
        let mut ranges = vec![(0, p - 1)];
        while let Some((a, b)) = ranges.pop() {
            let (_, picked) = best_in(&units, &ending, a, b, &mut scratch);
            for k in picked {
                let piece = self.piece(&units[k]);
                chosen.extend(piece);
                ranges.extend(self.gaps(piece));
            }
        }
        chosen
    }
}

/// Weighted interval scheduling over the units lying within `a..=b`: the best total value and
/// the units achieving it.
fn best_in(
    units: &[Unit],
    ending: &[Vec<usize>],
    a: usize,
    b: usize,
    best: &mut Vec<(u32, usize)>,
) -> (u32, Vec<usize>) {
    const NONE: usize = usize::MAX;
    best.clear();
    // best[x - a] = (value of the best set within a..=x, the unit ending at x in it, or NONE)
    for x in a..=b {
        let mut here = if x > a {
            (best[x - a - 1].0, NONE)
        } else {
            (0, NONE)
        };
        for &k in &ending[x] {
            let u = &units[k];
            if u.lo < a {
                continue;
            }
            let before = if u.lo > a { best[u.lo - a - 1].0 } else { 0 };
            if before + u.value > here.0 {
                here = (before + u.value, k);
            }
        }
        best.push(here);
    }
    let total = best.last().map_or(0, |b| b.0);
    let mut picked = Vec::new();
    let mut x = b as isize;
    while x >= a as isize {
        let (_, k) = best[x as usize - a];
        if k == NONE {
            x -= 1;
        } else {
            picked.push(k);
            x = units[k].lo as isize - 1;
        }
    }
    (total, picked)
}
