//! Step 3 of MINITRI: a maximum set of mutually independent minimally degenerate triangles
//! (Chen & Chang 1990, §3, Algorithm MISMDT, extending Supowit's circle-graph algorithm).
//!
//! Two triangles are dependent exactly when their chords cross on the circle of [`super::circle`],
//! except for the pairs of a 3b-chain: two triangles `(a, b, c)` and `(b, c, d)` on one line
//! sharing the side `b c`, with their 180-degree sides on the same side of the line. Those cross
//! on the circle yet are independent (relationship (iii)(b)); a 3b-chain is a path of such pairs,
//! and any set of its members is independent.
//!
//! Input contract: the chords of the circle of [`super::circle`] (one per minimally degenerate
//! triangle) and their 3b-chains ([`super::chains`]). Output guarantee: a maximum independent set,
//! exactly: with `MIS(i, j)` the best among the chords inside positions `i..=j`, `MIS(i, j) =
//! max(MIS(i, j - 1), max over S of |S| + sum of MIS(gap))`, `S` a contiguous piece of the 3b-chain
//! of the chord ending at `j` and the gaps those between its endpoints (Theorem 6, with 3b-chains
//! of any length).
//!
//! Method: the crossing graph's components are solved apart (a component of at most 64 chords by a
//! search over bit sets, [`super::small`]); each one left by weighted interval scheduling over units
//! (a chord, or a contiguous piece of a 3b-chain) in order of span, as G. Valiente's algorithm for
//! circle graphs (ISAAC 2003). The pieces of a 3b-chain that is a staircase on the circle are valued
//! in the scans (`Staircase`), the other pieces from the piece one chord shorter
//! (`Sub::list_units`); nested ranges are jumped by the levels of [`super::ladder`].
//!
//! Bound: O(K alpha(K)) for the components, then one scan per unit and staircase gap: O(sum of
//! spans), near-linear when chords are local, O(K^2) when many long chords nest in one crossing
//! component (the triangles across a long corridor), which the levels cut down. Memory O(K) plus
//! the ranges asked for with their values and the levels' matrices (at most 24 x 24 each).
//!
//! The reasoning in full, the staircase shape and where it breaks, the economies of the scans and
//! what was tried and dropped: docs/algorithms.md, "Step 3 in detail".

// The 3b-chains moved to their own module; their old paths stay (for the tests and examples).
pub use super::chains::Chains;
#[cfg(feature = "internals")]
pub use super::chains::{chains, is_3b_pair};
use super::circle::Circle;
use super::ladder::{clamp, LadderPolicy, Ladders, Level, Reader, Slot, NEG};
use super::lists::Lists;
use super::staircase::Staircase;

/// A maximum independent set of the triangles, as indices into the triangle list.
///
/// The dependency graph has no edge between different connected components of the crossing
/// graph on the circle (dependent chords cross), so each component is solved on its own: a lone
/// chord is always taken, small components are searched ([`super::small`]), the others go
/// through the exact recurrence on their own endpoints only.
pub fn maximum_independent_set(circle: &Circle, chains: &Chains) -> Vec<usize> {
    maximum_independent_set_with(circle, chains, Method::default()).0
}

/// How [`maximum_independent_set_with`] solves (the tests compare the ways).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Method {
    /// Whether long staircase pieces are valued in the scans (else every piece of every
    /// 3b-chain is an explicit unit, the slower and simpler method).
    pub staircases: bool,
    /// Which ranges the scans jump with a matrix ([`super::ladder`]).
    pub ladders: LadderPolicy,
    /// The largest crossing component solved by [`super::small`]'s search instead of the
    /// scans (lone chords are always just taken).
    pub small: usize,
}

impl Default for Method {
    fn default() -> Self {
        Method {
            staircases: true,
            ladders: LadderPolicy::Auto,
            small: super::small::SMALL,
        }
    }
}

/// [`maximum_independent_set`] by the given method; also returns what the solving took (for
/// the tests).
pub(crate) fn maximum_independent_set_with(
    circle: &Circle,
    chains: &Chains,
    method: Method,
) -> (Vec<usize>, Effort) {
    let mut effort = Effort::default();
    let mut chosen = Vec::new();
    let mut local = vec![u32::MAX; circle.owner.len()];
    let mut chain_seen = vec![u32::MAX; chains.paths.len()];
    for (number, component) in crossing_components(circle).iter().enumerate() {
        if component.len() == 1 {
            chosen.push(component[0]);
            continue;
        }
        if component.len() <= method.small {
            if let Some(set) = super::small::maximum_independent_set(circle, chains, component) {
                chosen.extend(set);
                effort.searched += 1;
                continue;
            }
        }
        let mut positions: Vec<usize> = component
            .iter()
            .flat_map(|&t| [circle.chords[t].0, circle.chords[t].1])
            .collect();
        positions.sort_unstable();
        for (i, &g) in positions.iter().enumerate() {
            local[g] = i as u32;
        }
        let cut = shortest_cut(component, |t| {
            let (l, r) = circle.chords[t];
            let (chain, i) = chains.place[t];
            let len = chains.paths.get(chain).len();
            let class = match () {
                _ if len < 4 => Protect::No,
                _ if (1..len - 1).contains(&i) => Protect::Inner,
                _ => Protect::End,
            };
            (local[l] as usize, local[r] as usize, class)
        });
        let p = positions.len();
        for &g in &positions {
            local[g] = ((local[g] as usize + p - cut) % p) as u32;
        }
        let sub = Sub {
            circle,
            chains,
            positions: &positions,
            local: &local,
            method,
        };
        chosen.extend(sub.solve(&mut chain_seen, number as u32, &mut effort));
    }
    (chosen, effort)
}

/// How much a chord's pocket must be kept whole when a component's circle is cut
/// ([`shortest_cut`]).
#[derive(Clone, Copy)]
enum Protect {
    /// Not a chord of a 3b-chain of four or more.
    No,
    /// The first or last chord of such a chain: cut through, it becomes an irregular end
    /// (`Staircase::find`), whose pieces are O(L) units.
    End,
    /// Any other chord of such a chain: cut through, the chain is no staircase at all.
    Inner,
}

/// Where to cut a component's circle into a line: the position (among `0..p`, `p` twice the
/// number of `chords`) that becomes the first. Cutting the circle anywhere gives the same
/// crossings, hence the same answer, but not the same work: a cut on the short side (the
/// pocket) of a chain's chord breaks the chain's staircase on the line (see [`Staircase`]; a
/// chain along a wall through the ring's first vertex took O(L^2) units), and the scans cost
/// about the total span (Valiente). So the cut falls on the short side of the fewest inner
/// chords of chains, then of the fewest end chords, then where the spans sum to the least
/// (`chord` gives each chord's ends and its [`Protect`] class). O(p).
fn shortest_cut(chords: &[usize], chord: impl Fn(usize) -> (usize, usize, Protect)) -> usize {
    let p = 2 * chords.len();
    // Cutting just before position r, chord (x, y) spans y - x if r is outside x + 1..=y,
    // p - (y - x) if inside: the change by r, as differences; and how many chords of long
    // 3b-chains r would cut, inner and end chords apart.
    let mut change = vec![0i64; p + 1];
    let mut cuts = vec![[0i32; 2]; p + 1];
    for &t in chords {
        let (x, y, class) = chord(t);
        let (x, y) = (x.min(y), x.max(y));
        let delta = p as i64 - 2 * (y - x) as i64;
        change[x + 1] += delta;
        change[y + 1] -= delta;
        // A chain's chord is cut when r falls on its short side (its pocket).
        let k = match class {
            Protect::No => continue,
            Protect::End => 1,
            Protect::Inner => 0,
        };
        if 2 * (y - x) <= p {
            cuts[x + 1][k] += 1;
            cuts[y + 1][k] -= 1;
        } else {
            cuts[0][k] += 1;
            cuts[x + 1][k] -= 1;
            cuts[y + 1][k] += 1;
        }
    }
    let (mut best, mut at) = ((i32::MAX, i32::MAX, i64::MAX), 0);
    let (mut total, mut inner, mut ends) = (0, 0, 0);
    for r in 0..p {
        total += change[r];
        inner += cuts[r][0];
        ends += cuts[r][1];
        if (inner, ends, total) < best {
            (best, at) = ((inner, ends, total), r);
        }
    }
    at
}

/// The connected components of the crossing graph of the chords, each a list of triangles.
///
/// One pass over the circle with a stack of groups of chords already known to be connected, each
/// with its number of chords still open. When a chord closes, every group above its own group on
/// the stack holds open chords that opened after it, so each crosses it: they merge into its group.
/// A group with no open chord left is popped (anything later either encloses or avoids it).
/// O(K alpha(K)) with union-find.
pub fn crossing_components(circle: &Circle) -> Lists {
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
    // Grouped by root, roots in increasing order.
    let root: Vec<usize> = (0..k).map(|t| find(&mut parent, t)).collect();
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_unstable_by_key(|&t| (root[t], t));
    let mut groups = Lists::with_capacity(k);
    for (i, &t) in order.iter().enumerate() {
        if i > 0 && root[t] != root[order[i - 1]] {
            groups.close();
        }
        groups.push(t);
    }
    if k > 0 {
        groups.close();
    }
    groups
}

/// One component: its endpoints `positions` (global, sorted) and the map back (`local`).
struct Sub<'a> {
    circle: &'a Circle,
    chains: &'a Chains,
    positions: &'a [usize],
    local: &'a [u32],
    method: Method,
}

/// What [`maximum_independent_set_with`] took, for the tests.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Effort {
    /// Staircases valued in the scans.
    pub staircases: usize,
    /// The longest 3b-chain all of whose pieces were listed as units (not a staircase).
    pub longest_listed: usize,
    /// The longest 3b-chain valued as a staircase without its first or last chords (irregular
    /// ends, whose pieces are units).
    pub longest_trimmed: usize,
    /// Positions the scans stepped through (not counting jumps).
    pub scanned: u64,
    /// Level matrices built ([`super::ladder`]).
    pub levels: usize,
    /// Ranges the jobs asked for (with repeats).
    pub asked: usize,
    /// Components solved by [`super::small`]'s search.
    pub searched: usize,
}

/// A candidate for the top level of some range: one chord, or a contiguous piece of a 3b-chain
/// (whose chords cross one after the other), spanning local positions `lo..=hi`.
/// (Indices and positions as `u32`: there are about two units per chord.)
struct Unit {
    /// The piece `paths.get(chain)[first..=last]` of a 3b-chain (a lone chord is a piece of one).
    chain: u32,
    first: u32,
    last: u32,
    lo: u32,
    hi: u32,
    /// The unit of the piece one chord shorter it is valued from (`NONE`: valued from all its
    /// gaps), and the gaps that change (`Table::deltas`).
    pred: u32,
    deltas: std::ops::Range<u32>,
}

impl Unit {
    /// Its triangles.
    fn piece<'c>(&self, chains: &'c Chains) -> &'c [usize] {
        &chains.paths.get(self.chain as usize)[self.first as usize..=self.last as usize]
    }

    /// Its chords, less one.
    fn length(&self) -> usize {
        (self.last - self.first) as usize
    }
}

/// The endpoints of a piece growing one chord at a time, for [`Sub::list_units`]: sorted by
/// `direction * position`, so that the endpoints of a piece growing rightwards (1) or leftwards
/// (-1) along a staircase mostly go at the end of the list.
struct Growing {
    direction: i64,
    keys: Vec<i64>,
}

impl Growing {
    fn new(direction: i64, chords: &[usize], chord: impl Fn(usize) -> (usize, usize)) -> Growing {
        let mut keys: Vec<i64> = chords
            .iter()
            .flat_map(|&t| <[usize; 2]>::from(chord(t)))
            .map(|x| direction * x as i64)
            .collect();
        keys.sort_unstable();
        Growing { direction, keys }
    }

    /// Adds a chord's endpoints; each splits the gap between its neighbours (if it falls
    /// between two) and makes new gaps with them: into `deltas` as `(x, y, added)`, the gap
    /// strictly between endpoints `x < y`.
    fn add(&mut self, chord: (usize, usize), deltas: &mut Vec<(u32, u32, bool)>) {
        let gap = |x: i64, y: i64, added: bool| (x.min(y) as u32, x.max(y) as u32, added);
        for x in <[usize; 2]>::from(chord) {
            let key = self.direction * x as i64;
            let at = self.keys.partition_point(|&k| k < key);
            let position = |k: i64| self.direction * k;
            let before = at.checked_sub(1).map(|i| position(self.keys[i]));
            let after = self.keys.get(at).map(|&k| position(k));
            if let (Some(b), Some(a)) = (before, after) {
                deltas.push(gap(b, a, false));
            }
            for neighbour in [before, after].into_iter().flatten() {
                deltas.push(gap(neighbour, x as i64, true));
            }
            self.keys.insert(at, key);
        }
    }
}

/// A best value not found yet (also a unit's or staircase gap's value before its job runs).
pub(super) const UNKNOWN: u32 = u32::MAX;

/// No unit starts (or ends) at a position.
const NONE: u32 = u32::MAX;

/// A unit or staircase piece chosen by the reconstruction.
#[derive(Clone, Copy, Debug)]
enum Pick {
    /// A unit of the list.
    Unit(u32),
    /// The piece `tris[first..=last]` of the staircase `stair`.
    Piece { stair: u32, first: u32, last: u32 },
}

/// Jobs in order of span: units to value, and staircase gap values to fill in (indices as
/// `u32`: there are about two per chord).
#[derive(Clone, Copy, Debug)]
enum Job {
    Unit(u32),
    Left(u32, u32),
    Inner(u32, u32),
    Right(u32, u32),
}

/// A job with what orders it: its span, 0 for a unit (units first), and a unit's number of
/// chords less one (a unit after the shorter piece it is valued from).
type Queued = (u32, u8, u32, Job);

/// What the scans read: the valued units, by end position, and the staircases.
struct Table {
    units: Vec<Unit>,
    /// The units by end position, as one flat array (compressed rows): those ending at local
    /// position `x` are `ending[ending_start[x]..ending_start[x + 1]]`, each as `(lo, value)`,
    /// in decreasing order of `lo` (a scan of `a..=b` stops at the first `lo < a`). A unit's
    /// value is filled in when its job runs, before any scan can reach it.
    ending_start: Vec<u32>,
    ending: Vec<(u32, u32)>,
    /// The unit of each entry of `ending` (read only by the reconstruction).
    ending_unit: Vec<u32>,
    /// Each unit's entry in `ending`.
    entry_of: Vec<u32>,
    /// Per local position: the nearest end of a unit starting there, and the furthest start of
    /// a unit ending there (`NONE` if there is none); see [`Table::tighten`].
    nearest_end: Vec<u32>,
    furthest_start: Vec<u32>,
    /// The ranges the jobs ask for, by start (compressed rows): those within `a..` end at
    /// `asked_end[asked_start[a]..asked_start[a + 1]]`, in increasing order.
    asked_start: Vec<u32>,
    asked_end: Vec<u32>,
    stairs: Vec<Staircase>,
    /// The gaps that change from a unit's shorter piece to it (see [`Unit::pred`]).
    deltas: Vec<(u32, u32, bool)>,
    /// Per local position, what the scans do there for a staircase (read in every step of
    /// every scan, so all it needs is in one record).
    events: Vec<StairEvent>,
}

/// At a local position, the end `e_i` of chord `i >= 2` of staircase `stair`, where the pieces
/// ending with `i` are valued; `first` is the position of `s_{i - 2}`, where the latest of them
/// begins (`stair == NONE`: nothing to do).
#[derive(Clone, Copy)]
struct StairEvent {
    stair: u32,
    i: u32,
    first: u32,
}

/// No staircase event at a position.
const NO_EVENT: StairEvent = StairEvent {
    stair: NONE,
    i: 0,
    first: 0,
};

/// Scratch for [`Sub::gaps`], reused so that valuing a unit allocates nothing.
#[derive(Default)]
struct GapBuffers {
    /// The sorted endpoints of the chords asked about.
    ends: Vec<usize>,
    /// The gaps found, as inclusive ranges of local positions.
    gaps: Vec<(usize, usize)>,
}

/// Scratch for the scans.
#[derive(Default)]
struct Scan {
    /// `before[x]`: the best value within `a..x` of the current scan of `a..` (local
    /// positions; written where the scan passes, and at the out-slots of the levels it jumps).
    before: Vec<i64>,
    /// Per staircase: (stamp of the scan, index of the last end it saw, the running maximum
    /// `M` there).
    run: Vec<(u32, u32, i64)>,
    stamp: u32,
    /// The best value within each range of [`Table::asked_end`], or `UNKNOWN`.
    asked_value: Vec<u32>,
    /// The levels the last scan jumped, by position, each with the start of its in-slot
    /// values in `entries`.
    holes: Vec<(u32, u32)>,
    entries: Vec<i64>,
    /// A jump's out-slot values.
    out: Vec<i64>,
    /// In a level's scan: one past the furthest start of a unit or staircase gap read before
    /// its job ran (see [`Level::valid_from`]).
    stale: usize,
    /// Positions scanned, and level matrices built (for [`Effort`]).
    scanned: u64,
    built: usize,
}

/// Where a scan starts (see [`Sub::scan`]).
#[derive(Clone, Copy)]
enum Entry<'e> {
    /// A range on its own: the best before `a` is 0, nothing before `a` lies within.
    Alone,
    /// A level's range, from these values of its in-slots.
    Level(&'e [Slot], &'e [i64]),
}

impl Scan {
    /// The value of a slot; a position before `floor` is minus infinity.
    fn read(&self, slot: Slot, floor: usize) -> i64 {
        match slot {
            Slot::Before(x) if (x as usize) < floor => NEG,
            Slot::Before(x) => self.before[x as usize],
            Slot::Run { stair, i } => match self.run[stair as usize] {
                (seen, last, m) if seen == self.stamp && last == i => m,
                _ => NEG,
            },
        }
    }

    fn write(&mut self, slot: Slot, v: i64) {
        match slot {
            Slot::Before(x) => self.before[x as usize] = v,
            Slot::Run { stair, i } => self.run[stair as usize] = (self.stamp, i, v),
        }
    }

    /// The levels the last scan jumped, each with its in-slot values.
    fn take_holes(&mut self, ladders: &Ladders) -> Vec<(u32, Vec<i64>)> {
        self.holes
            .iter()
            .map(|&(k, offset)| {
                let n = ladders.levels[k as usize].ins.len();
                let offset = offset as usize;
                (k, self.entries[offset..offset + n].to_vec())
            })
            .collect()
    }
}

impl Sub<'_> {
    fn chord(&self, t: usize) -> (usize, usize) {
        let (l, r) = self.circle.chords[t];
        let (l, r) = (self.local[l] as usize, self.local[r] as usize);
        (l.min(r), l.max(r))
    }

    /// The gaps between consecutive endpoints of some chords (inside their span), into
    /// `buffers.gaps`.
    fn gaps(&self, chords: &[usize], buffers: &mut GapBuffers) {
        let GapBuffers { ends, gaps } = buffers;
        ends.clear();
        ends.extend(
            chords
                .iter()
                .flat_map(|&t| <[usize; 2]>::from(self.chord(t))),
        );
        ends.sort_unstable();
        gaps.clear();
        gaps.extend(
            ends.windows(2)
                .filter(|w| w[1] > w[0] + 1)
                .map(|w| (w[0] + 1, w[1] - 1)),
        );
    }

    /// Lists the pieces of 3b-chain `chain` that are units: all of them but those of three or
    /// more chords in the staircase `core` (a range of the chain's indices), with their jobs.
    ///
    /// A piece of three or more chords is valued from a piece one chord shorter (its `pred`):
    /// the best in its gaps is the shorter piece's, minus the gaps the new chord's two
    /// endpoints split, plus the parts (`Growing`). So a family of O(L) such pieces (those with
    /// an irregular end chord) asks for O(L) ranges, not the O(L^2) of listing each piece's own
    /// gaps. The shorter piece is `first..last - 1` when `first` is outside the core (then
    /// it is a unit too), else `first + 1..=last` (then `last` is outside the core). Without
    /// the staircase method every piece is a unit valued from all its gaps.
    fn list_units(
        &self,
        chain: usize,
        core: std::ops::Range<usize>,
        table: &mut Table,
        jobs: &mut Vec<Queued>,
    ) {
        let n = self.chains.paths.get(chain).len();
        let first_unit = table.units.len();
        if !self.method.staircases {
            for first in 0..n {
                for last in first..n {
                    self.push_unit(chain, (first, last), NONE, &[], table, jobs);
                }
            }
            return;
        }
        // Pieces of one and two chords: `(first, first)` is unit `plain + 2 first`, and
        // `(first, first + 1)` the next one.
        let plain = table.units.len() as u32;
        for first in 0..n {
            for last in first..n.min(first + 2) {
                self.push_unit(chain, (first, last), NONE, &[], table, jobs);
            }
        }
        let families = self.grow_rightwards(chain, &core, plain, table, jobs);
        self.grow_leftwards(chain, &core, plain, &families, table, jobs);
        debug_assert!(table.units[first_unit..].iter().all(|u| u.pred == NONE
            || (
                table.units[u.pred as usize].first,
                table.units[u.pred as usize].last
            ) == if core.contains(&(u.first as usize)) {
                (u.first + 1, u.last)
            } else {
                (u.first, u.last - 1)
            }));
    }

    /// Lists the unit of piece `first..=last` of 3b-chain `chain` and its job: valued from all
    /// its gaps (`pred` is `NONE`), or from unit `pred`, one chord shorter, and the gaps
    /// `deltas` change. Returns its number.
    fn push_unit(
        &self,
        chain: usize,
        (first, last): (usize, usize),
        pred: u32,
        deltas: &[(u32, u32, bool)],
        table: &mut Table,
        jobs: &mut Vec<Queued>,
    ) -> u32 {
        let path = self.chains.paths.get(chain);
        let k = table.units.len();
        let (mut lo, mut hi) = (usize::MAX, 0);
        let chords: &[usize] = if pred == NONE {
            &path[first..=last]
        } else {
            let u = &table.units[pred as usize];
            (lo, hi) = (u.lo as usize, u.hi as usize);
            if last > u.last as usize {
                &path[last..=last]
            } else {
                &path[first..=first]
            }
        };
        for &t in chords {
            let (l, r) = self.chord(t);
            (lo, hi) = (lo.min(l), hi.max(r));
        }
        let start = table.deltas.len() as u32;
        table.deltas.extend_from_slice(deltas);
        jobs.push((
            (hi - lo) as u32,
            0,
            (last - first) as u32,
            Job::Unit(k as u32),
        ));
        table.units.push(Unit {
            chain: chain as u32,
            first: first as u32,
            last: last as u32,
            lo: lo as u32,
            hi: hi as u32,
            pred,
            deltas: start..table.deltas.len() as u32,
        });
        k as u32
    }

    /// Growing `first..=last` from the pair (unit `plain + 2 first + 1`), for each `first`
    /// outside the core: the unit of `(first, last)` is `grown + last - first - 2` for that
    /// family's `(first, grown)`, returned.
    fn grow_rightwards(
        &self,
        chain: usize,
        core: &std::ops::Range<usize>,
        plain: u32,
        table: &mut Table,
        jobs: &mut Vec<Queued>,
    ) -> Vec<(usize, u32)> {
        let path = self.chains.paths.get(chain);
        let n = path.len();
        let mut families: Vec<(usize, u32)> = Vec::new();
        let mut deltas = Vec::new();
        for first in (0..n).filter(|f| !core.contains(f)) {
            families.push((first, table.units.len() as u32));
            let mut growing = Growing::new(1, &path[first..(first + 2).min(n)], |t| self.chord(t));
            let mut pred = plain + 2 * first as u32 + 1;
            for (last, &t) in path.iter().enumerate().skip(first + 2) {
                deltas.clear();
                growing.add(self.chord(t), &mut deltas);
                pred = self.push_unit(chain, (first, last), pred, &deltas, table, jobs);
            }
        }
        families
    }

    /// Growing `first..=last` leftwards into the core, for each `last` after it (not when there
    /// is no core: every piece is listed by [`Self::grow_rightwards`] then).
    fn grow_leftwards(
        &self,
        chain: usize,
        core: &std::ops::Range<usize>,
        plain: u32,
        families: &[(usize, u32)],
        table: &mut Table,
        jobs: &mut Vec<Queued>,
    ) {
        let path = self.chains.paths.get(chain);
        let n = path.len();
        let mut deltas = Vec::new();
        for last in (core.end..n).filter(|&last| !core.is_empty() && last >= core.start + 2) {
            let top = (last - 2).min(core.end - 1);
            let mut pred = if top + 1 == last - 1 {
                plain + 2 * (top + 1) as u32 + 1
            } else {
                // `(core.end, last)`, grown from the pair of `core.end` (outside the core).
                let (_, grown) = families
                    .iter()
                    .find(|&&(first, _)| first == top + 1)
                    .expect("the first chord after the core starts a family");
                grown + (last - top - 3) as u32
            };
            let mut growing = Growing::new(-1, &path[top + 1..=last], |t| self.chord(t));
            for first in (core.start..=top).rev() {
                deltas.clear();
                growing.add(self.chord(path[first]), &mut deltas);
                pred = self.push_unit(chain, (first, last), pred, &deltas, table, jobs);
            }
        }
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
    /// of span.
    ///
    /// Pieces of one or two chords are explicit units. The longer pieces of a staircase chain
    /// (see [`Staircase`]; the shape is checked, pieces with an irregular end chord are explicit
    /// units, and so are all pieces of a chain that is no staircase) are valued in the scans: at
    /// the end `e_l` of chord `l`, the best start `f <= l - 2` is a running maximum,
    /// `M(l) = max(M(l - 1) + inner[l - 1], start(f = l - 2))`, with `start(f)` the best before
    /// `s_f` plus `left[f] - f`. So a staircase of length L costs O(L) units and gaps, not the
    /// O(L^2) of listing its pieces.
    ///
    /// The scans jump the levels chosen among the ranges asked for ([`super::ladder`]), and
    /// the reconstruction scans a level again only where its walk back needs a value inside.
    fn solve(&self, chain_seen: &mut [u32], component: u32, effort: &mut Effort) -> Vec<usize> {
        let p = self.positions.len();
        let mut table = Table {
            units: Vec::new(),
            ending_start: Vec::new(),
            ending: Vec::new(),
            ending_unit: Vec::new(),
            entry_of: Vec::new(),
            nearest_end: Vec::new(),
            furthest_start: Vec::new(),
            asked_start: Vec::new(),
            asked_end: Vec::new(),
            stairs: Vec::new(),
            deltas: Vec::new(),
            events: vec![NO_EVENT; p],
        };
        // (span, units first, pieces by length, job): a unit's shorter piece and all ranges
        // inside it come before it.
        let mut jobs: Vec<Queued> = Vec::new();
        for &g in self.positions {
            let (chain, _) = self.chains.place[self.circle.owner[g]];
            // Each chain once: `chain_seen` is shared by all components, marked with this one's
            // number (cheaper than a hash set per component).
            if chain_seen[chain] == component {
                continue;
            }
            chain_seen[chain] = component;
            self.list_chain(chain, &mut table, &mut jobs, effort);
        }
        table.index_ending(p);
        let mut scan = Scan {
            run: vec![(0, 0, NEG); table.stairs.len()],
            before: vec![0; p + 1],
            ..Scan::default()
        };
        jobs.sort_by_key(|&(span, kind, length, _)| (span, kind, length));
        let mut buffers = GapBuffers::default();
        let (from, ranges, minus) = self.ranges_of(&table, &jobs, &mut buffers);
        table.index_asked(p, &ranges);
        scan.asked_value = vec![UNKNOWN; ranges.len()];
        effort.asked += ranges.len();
        let mut ladders = Ladders::choose(p, self.method.ladders, &ranges, || table.readers());
        // Every job valued in order: the sum of the best values in the ranges it asks for.
        for (n, &(_, _, _, job)) in jobs.iter().enumerate() {
            let asked = from[n] as usize..from[n + 1] as usize;
            let mut inside: i64 = 0;
            for (&(a, b), &minus) in ranges[asked.clone()].iter().zip(&minus[asked]) {
                let v = self.best_value(&table, &mut ladders, &mut scan, a as usize, b as usize);
                inside += if minus { -(v as i64) } else { v as i64 };
            }
            set_value(&mut table, job, inside);
        }
        let chosen = self.reconstruct(&table, &mut ladders, &mut scan, &mut buffers);
        effort.staircases += table.stairs.len();
        effort.scanned += scan.scanned;
        effort.levels += scan.built;
        chosen
    }

    /// The units of 3b-chain `chain` and, when it is a staircase, its staircase's jobs (its
    /// `left`, `inner` and `right` values) and scan events.
    fn list_chain(
        &self,
        chain: usize,
        table: &mut Table,
        jobs: &mut Vec<Queued>,
        effort: &mut Effort,
    ) {
        let path = self.chains.paths.get(chain);
        let stair = if self.method.staircases {
            Staircase::find(path, |t| self.chord(t))
        } else {
            None
        };
        // Pieces of three or more chords of the staircase core are valued in the scans;
        // every other piece is a unit.
        match &stair {
            None => effort.longest_listed = effort.longest_listed.max(path.len()),
            Some((core, _)) if core.len() < path.len() => {
                effort.longest_trimmed = effort.longest_trimmed.max(path.len());
            }
            Some(_) => {}
        }
        let (core, stair) = match stair {
            Some((core, stair)) => (core, Some(stair)),
            None => (0..0, None),
        };
        self.list_units(chain, core, table, jobs);
        let Some(stair) = stair else {
            return;
        };
        let s = table.stairs.len();
        let l = stair.tris.len();
        let span = |(x, y): (usize, usize)| (y - x) as u32;
        let s32 = s as u32;
        for f in 0..l - 2 {
            let [g0, g1] = stair.left_gaps(f);
            jobs.push((span(g0).max(span(g1)), 1, 0, Job::Left(s32, f as u32)));
        }
        for j in 2..l - 1 {
            jobs.push((span(stair.inner_gap(j)), 1, 0, Job::Inner(s32, j as u32)));
        }
        for r in 2..l {
            let [g0, g1] = stair.right_gaps(r);
            jobs.push((span(g0).max(span(g1)), 1, 0, Job::Right(s32, r as u32)));
        }
        for (i, &(_, hi)) in stair.ends.iter().enumerate().skip(2) {
            table.events[hi] = StairEvent {
                stair: s as u32,
                i: i as u32,
                first: stair.ends[i - 2].0 as u32,
            };
        }
        table.stairs.push(stair);
    }

    /// The chosen chords, walking back from the whole range: the best units and staircase
    /// pieces in each range, then the same in each of their gaps.
    fn reconstruct(
        &self,
        table: &Table,
        ladders: &mut Ladders,
        scan: &mut Scan,
        buffers: &mut GapBuffers,
    ) -> Vec<usize> {
        let mut chosen = Vec::new();
        let mut ranges = vec![(0, self.positions.len() - 1)];
        while let Some((a, b)) = ranges.pop() {
            let picked = self.best_in(table, ladders, scan, a, b);
            for pick in picked {
                let piece = match pick {
                    Pick::Unit(k) => table.units[k as usize].piece(self.chains),
                    Pick::Piece { stair, first, last } => {
                        &table.stairs[stair as usize].tris[first as usize..=last as usize]
                    }
                };
                chosen.extend(piece);
                self.gaps(piece, buffers);
                ranges.extend(
                    buffers
                        .gaps
                        .iter()
                        .filter_map(|&(a, b)| table.tighten(a, b)),
                );
            }
        }
        chosen
    }

    /// The ranges (inclusive, local positions) whose best values each job sums: the gaps of a
    /// unit (or, for a unit valued from a shorter piece, the gaps that change, those split
    /// counted with `minus`), or those making up a staircase's `left`, `inner` or `right`
    /// value. Job `n` asks for `ranges[from[n]..from[n + 1]]`.
    fn ranges_of(
        &self,
        table: &Table,
        jobs: &[Queued],
        buffers: &mut GapBuffers,
    ) -> (Vec<u32>, Vec<(u32, u32)>, Vec<bool>) {
        let mut from = Vec::with_capacity(jobs.len() + 1);
        let (mut ranges, mut minus) = (Vec::new(), Vec::new());
        from.push(0);
        for &(_, _, _, job) in jobs {
            let mut gap = |(x, y): (usize, usize), subtract: bool| {
                if y > x + 1 {
                    if let Some((a, b)) = table.tighten(x + 1, y - 1) {
                        ranges.push((a as u32, b as u32));
                        minus.push(subtract);
                    }
                }
            };
            let mut open = |ends| gap(ends, false);
            match job {
                Job::Unit(k) if table.units[k as usize].pred != NONE => {
                    let deltas = table.units[k as usize].deltas.clone();
                    for &(x, y, add) in &table.deltas[deltas.start as usize..deltas.end as usize] {
                        gap((x as usize, y as usize), !add);
                    }
                }
                Job::Unit(k) => {
                    let u = &table.units[k as usize];
                    self.gaps(u.piece(self.chains), buffers);
                    for &(a, b) in &buffers.gaps {
                        open((a - 1, b + 1));
                    }
                }
                Job::Left(s, f) => {
                    let gaps = table.stairs[s as usize].left_gaps(f as usize);
                    gaps.into_iter().for_each(open);
                }
                Job::Inner(s, j) => open(table.stairs[s as usize].inner_gap(j as usize)),
                Job::Right(s, r) => {
                    let gaps = table.stairs[s as usize].right_gaps(r as usize);
                    gaps.into_iter().for_each(open);
                }
            }
            from.push(ranges.len() as u32);
        }
        (from, ranges, minus)
    }

    /// The best value within `a..=b`, one of the ranges asked for, found once: every unit and
    /// staircase gap inside a range is narrower than it, so it was valued before the range was
    /// first asked for. A level's value is an entry of its matrix (built now, if it was not
    /// yet). The scan's values also give every range asked for with the same start and an
    /// earlier end (every unit inside it is inside `a..=b`, so valued already), except those
    /// ending inside a level the scan jumped.
    fn best_value(
        &self,
        table: &Table,
        ladders: &mut Ladders,
        scan: &mut Scan,
        a: usize,
        b: usize,
    ) -> u32 {
        let group = table.asked_start[a] as usize..table.asked_start[a + 1] as usize;
        let ends = &table.asked_end[group.clone()];
        let i = ends
            .binary_search(&(b as u32))
            .expect("every range a job asks for is listed");
        let known = scan.asked_value[group.start + i];
        if known != UNKNOWN {
            return known;
        }
        let v = match ladders.level(a, b) {
            Some(k) => {
                let built_now = self.ensure(table, ladders, scan, k, a);
                let v = ladders.levels[k].matrix[0];
                if !built_now {
                    // No scan now: only this range's value is known.
                    scan.asked_value[group.start + i] = v as u32;
                    return v as u32;
                }
                // The last scan of the build was from `Before(a)` alone: a plain scan.
                v
            }
            None => {
                let jumps = self.prepare(table, ladders, scan, a, b);
                self.scan(table, ladders, scan, a, b, Entry::Alone, &jumps)
            }
        };
        let mut holes = scan
            .holes
            .iter()
            .map(|&(k, _)| &ladders.levels[k as usize])
            .peekable();
        for (j, &end) in group.zip(ends) {
            let end = end as usize;
            if end > b {
                break;
            }
            while holes.peek().is_some_and(|level| level.b < end + 1) {
                holes.next();
            }
            let inside_hole = holes.peek().is_some_and(|level| level.a < end + 1);
            if scan.asked_value[j] == UNKNOWN && !inside_hole {
                scan.asked_value[j] = scan.before[end + 1] as u32;
            }
        }
        v as u32
    }

    /// The levels a scan of `a..=b` (not a level itself) jumps, with their matrices built and
    /// valid for a scan from `a`.
    fn prepare(
        &self,
        table: &Table,
        ladders: &mut Ladders,
        scan: &mut Scan,
        a: usize,
        b: usize,
    ) -> Vec<u32> {
        let mut jumps = Vec::new();
        ladders.jumps_in(a, b, &mut jumps);
        for &k in &jumps {
            self.ensure(table, ladders, scan, k as usize, a);
        }
        jumps
    }

    /// Makes the matrix of level `k` valid for scans from `start` (everything within
    /// `start..` that a scan of the level reads must be valued by now): built, or built again,
    /// after the levels it jumps (innermost first). True if it was built now.
    fn ensure(
        &self,
        table: &Table,
        ladders: &mut Ladders,
        scan: &mut Scan,
        k: usize,
        start: usize,
    ) -> bool {
        let valid = |level: &Level| !level.matrix.is_empty() && level.valid_from <= start;
        if valid(&ladders.levels[k]) {
            return false;
        }
        let mut stack = vec![k];
        while let Some(&top) = stack.last() {
            let level = &ladders.levels[top];
            if valid(level) {
                stack.pop();
                continue;
            }
            let before = stack.len();
            stack.extend(
                level
                    .jumps
                    .iter()
                    .map(|&j| j as usize)
                    .filter(|&j| !valid(&ladders.levels[j])),
            );
            if stack.len() == before {
                self.build(table, ladders, scan, top);
                debug_assert!(valid(&ladders.levels[top]), "a level read an unvalued item");
                stack.pop();
            }
        }
        true
    }

    /// The matrix of level `k` (its jumps built): one scan of its range per in-slot, that slot
    /// 0 and the others minus infinity; `Before(a)` last, so that `scan.before` then holds the
    /// plain scan of the range. Units reaching in from outside and staircase gaps across its
    /// start may not be valued yet: the matrix is then valid only for scans starting after
    /// them ([`Level::valid_from`]), and built again for a scan from further out.
    fn build(&self, table: &Table, ladders: &mut Ladders, scan: &mut Scan, k: usize) {
        let level = &ladders.levels[k];
        let n = level.ins.len();
        let mut matrix = vec![NEG; n * level.outs.len()];
        let mut entry = vec![NEG; n];
        scan.stale = 0;
        for c in (0..n).rev() {
            entry.fill(NEG);
            entry[c] = 0;
            let slots = Entry::Level(&level.ins, &entry);
            self.scan(table, ladders, scan, level.a, level.b, slots, &level.jumps);
            for (r, &slot) in level.outs.iter().enumerate() {
                matrix[r * n + c] = clamp(scan.read(slot, 0));
            }
        }
        let level = &mut ladders.levels[k];
        level.matrix = matrix;
        level.valid_from = scan.stale;
        scan.built += 1;
    }

    /// Weighted interval scheduling over the units and staircase pieces lying within `a..=b`:
    /// the picks of a best set. One scan fills `scan.before`; then, walking back from `b`,
    /// where the best grows at a position some unit or staircase piece ending there achieves
    /// the new value, and the walk goes on before its start. Where the walk needs a value
    /// inside a level the scan jumped, that level is scanned again from the in-slot values
    /// saved at the jump (and so on inwards): the walk mostly steps over levels, by a chosen
    /// rung that spans one.
    fn best_in(
        &self,
        table: &Table,
        ladders: &mut Ladders,
        scan: &mut Scan,
        a: usize,
        b: usize,
    ) -> Vec<Pick> {
        let jumps = self.prepare(table, ladders, scan, a, b);
        let ladders = &*ladders;
        self.scan(table, ladders, scan, a, b, Entry::Alone, &jumps);
        let mut holes = scan.take_holes(ladders);
        let mut read = |y: usize| self.settled(table, ladders, scan, &mut holes, y);
        let mut picked = Vec::new();
        let mut x = b + 1; // the best within `a..x` is `before[x]`
        while x > a {
            let y = x - 1;
            let target = read(y + 1);
            if target == read(y) {
                x = y;
                continue;
            }
            let (pick, lo) = self
                .achieving(table, a, y, target, &mut read)
                .expect("the best grows at a position only by a unit or a piece ending there");
            picked.push(pick);
            x = lo;
        }
        picked
    }

    /// `before[y]` of the scan of [`Self::best_in`], scanning again the levels (in `holes`,
    /// by position, with their saved in-slot values) that hide it.
    fn settled(
        &self,
        table: &Table,
        ladders: &Ladders,
        scan: &mut Scan,
        holes: &mut Vec<(u32, Vec<i64>)>,
        y: usize,
    ) -> i64 {
        loop {
            let i = holes.partition_point(|&(k, _)| ladders.levels[k as usize].a < y);
            if i == 0 {
                break;
            }
            let level = &ladders.levels[holes[i - 1].0 as usize];
            if y > level.b || level.outs.contains(&Slot::Before(y as u32)) {
                break; // outside, or written by the jump
            }
            let (_, entry) = holes.remove(i - 1);
            let slots = Entry::Level(&level.ins, &entry);
            self.scan(table, ladders, scan, level.a, level.b, slots, &level.jumps);
            let inner = scan.take_holes(ladders);
            holes.splice(i - 1..i - 1, inner);
        }
        scan.before[y]
    }

    /// A unit or staircase piece within `a..` ending at `y` whose value plus the best before its
    /// start is `target`, the best within `a..=y` (`read` gives the best before a position),
    /// with its start.
    fn achieving(
        &self,
        table: &Table,
        a: usize,
        y: usize,
        target: i64,
        read: &mut impl FnMut(usize) -> i64,
    ) -> Option<(Pick, usize)> {
        let entries = table.ending_start[y] as usize..table.ending_start[y + 1] as usize;
        for e in entries {
            let (lo, value) = table.ending[e];
            let lo = lo as usize;
            if lo >= a && read(lo) + value as i64 == target {
                return Some((Pick::Unit(table.ending_unit[e]), lo));
            }
        }
        // A staircase piece `f..=i` ending at `y`, its start `s_f` in the range: the value
        // of the scan's running maximum, summed out for each `f` from `i - 2` down.
        let event = table.events[y];
        if event.stair == NONE {
            return None; // no piece ends at y
        }
        let (s, i) = (event.stair as usize, event.i as usize);
        let stair = &table.stairs[s];
        let mut inner = 0; // sum(inner[f + 2 .. i])
        for f in (0..=i - 2).rev() {
            if f + 2 < i {
                inner += stair.inner[f + 2] as i64;
            }
            let lo = stair.ends[f].0;
            if lo < a {
                break;
            }
            let count = (i - f + 1) as i64;
            let rest = stair.left[f] as i64 + inner + count + stair.right[i] as i64;
            if read(lo) + rest == target {
                let piece = Pick::Piece {
                    stair: s as u32,
                    first: f as u32,
                    last: i as u32,
                };
                return Some((piece, lo));
            }
        }
        None
    }

    /// The scan of `a..=b`: fills `scan.before` (at the positions it passes, and at the
    /// out-slots of the levels in `jumps`, which it jumps with their matrices) and returns the
    /// best total. `Entry::Alone`: nothing before `a` lies within the range; `Entry::Level`:
    /// the range is a level's, and what is read before `a` is its in-slots, given.
    #[allow(clippy::too_many_arguments)]
    fn scan(
        &self,
        table: &Table,
        ladders: &Ladders,
        scan: &mut Scan,
        a: usize,
        b: usize,
        entry: Entry,
        jumps: &[u32],
    ) -> i64 {
        scan.stamp += 1;
        let stamp = scan.stamp;
        // Reads before `floor` are minus infinity (`Alone`), or in-slots written here.
        let floor = match entry {
            Entry::Alone => {
                scan.before[a] = 0;
                a
            }
            Entry::Level(slots, values) => {
                for (&slot, &v) in slots.iter().zip(values) {
                    scan.write(slot, v);
                }
                0
            }
        };
        scan.holes.clear();
        scan.entries.clear();
        let level_at = |j: usize| jumps.get(j).map(|&k| &ladders.levels[k as usize]);
        let mut j = 0;
        let mut next = level_at(0).map_or(usize::MAX, |level| level.a);
        // `here`: the best within `a..x`, then within `a..=x`.
        let mut here = scan.before[a];
        let mut to = table.ending_start[a] as usize;
        let mut x = a;
        let mut stepped = 0;
        while x <= b {
            if x == next {
                // Jump over the level: out-slots from in-slots.
                let k = jumps[j] as usize;
                let level = &ladders.levels[k];
                scan.stale = scan.stale.max(level.valid_from);
                let offset = scan.entries.len();
                for &slot in &level.ins {
                    let v = clamp(scan.read(slot, floor));
                    scan.entries.push(v);
                }
                let mut out = std::mem::take(&mut scan.out);
                ladders.apply(k, &scan.entries[offset..], &mut out);
                for (&slot, &v) in level.outs.iter().zip(&out) {
                    scan.write(slot, v);
                }
                scan.out = out;
                scan.holes.push((k as u32, offset as u32));
                x = level.b + 1;
                here = scan.before[x];
                to = table.ending_start[x] as usize;
                j += 1;
                next = level_at(j).map_or(usize::MAX, |level| level.a);
                continue;
            }
            stepped += 1;
            let from = to;
            to = table.ending_start[x + 1] as usize;
            for e in from..to {
                let (lo, value) = table.ending[e];
                let lo = lo as usize;
                if lo < floor {
                    break;
                }
                if value == UNKNOWN {
                    // Only in a level's scan: a unit reaching in from outside, not valued yet.
                    scan.stale = scan.stale.max(lo + 1);
                }
                here = here.max(scan.before[lo] + value as i64);
            }
            let event = table.events[x];
            if event.stair != NONE {
                // The end of chord i: M(i) = max(M(i - 1) + inner[i - 1], start(i - 2)), with
                // start(f) = the best before s_f, plus left[f] - f.
                let (s, i) = (event.stair as usize, event.i as usize);
                let stair = &table.stairs[s];
                if floor == 0 {
                    scan.stale = scan.stale.max(stair.unvalued_before(i));
                }
                let (seen, last, previous) = scan.run[s];
                let mut m = NEG;
                if seen == stamp && last as usize + 1 == i {
                    m = previous + stair.inner[i - 1] as i64;
                }
                let first = event.first as usize;
                if first >= floor {
                    let start = scan.before[first] - (i - 2) as i64 + stair.left[i - 2] as i64;
                    m = m.max(start);
                }
                scan.run[s] = (stamp, i as u32, m);
                here = here.max(m + i as i64 + 1 + stair.right[i] as i64);
            }
            scan.before[x + 1] = here;
            x += 1;
        }
        scan.scanned += stepped;
        here
    }
}

impl Table {
    /// Builds `asked_start`, `asked_end` from the `ranges` the jobs ask for (a counting sort by
    /// start), for a component with `p` positions.
    fn index_asked(&mut self, p: usize, ranges: &[(u32, u32)]) {
        let mut start = vec![0u32; p + 1];
        for &(a, _) in ranges {
            start[a as usize] += 1;
        }
        for a in 0..p {
            start[a + 1] += start[a];
        }
        // Now `start[a]` is the end of the group of `a`: fill each group from its end.
        let mut end = vec![0; ranges.len()];
        for &(a, b) in ranges {
            start[a as usize] -= 1;
            end[start[a as usize] as usize] = b;
        }
        for a in 0..p {
            end[start[a] as usize..start[a + 1] as usize].sort_unstable();
        }
        (self.asked_start, self.asked_end) = (start, end);
    }

    /// What the scans read across positions ([`super::ladder`]): each unit reads the best
    /// before its start at its end; at the end `e_i` of a staircase chord (`i >= 2`), the best
    /// before `s_{i - 2}`, and the running maximum `M(i - 1)` settled at `e_{i - 1}`.
    fn readers(&self) -> Vec<Reader> {
        let mut readers: Vec<Reader> = self
            .units
            .iter()
            .map(|u| Reader {
                lo: u.lo,
                hi: u.hi,
                slot: Slot::Before(u.lo),
            })
            .collect();
        for (s, stair) in self.stairs.iter().enumerate() {
            let e = &stair.ends;
            for i in 2..e.len() {
                let first = e[i - 2].0 as u32;
                readers.push(Reader {
                    lo: first,
                    hi: e[i].1 as u32,
                    slot: Slot::Before(first),
                });
                if i >= 3 {
                    readers.push(Reader {
                        lo: e[i - 1].1 as u32,
                        hi: e[i].1 as u32,
                        slot: Slot::Run {
                            stair: s as u32,
                            i: i as u32 - 1,
                        },
                    });
                }
            }
        }
        readers
    }

    /// Builds the index of the units by end position (`ending_start`, `ending`, `ending_unit`,
    /// `entry_of`; values are filled in later) and `nearest_end`, `furthest_start`, for a
    /// component with `p` positions, once its units and staircases are listed.
    fn index_ending(&mut self, p: usize) {
        let mut order: Vec<u32> = (0..self.units.len() as u32).collect();
        order.sort_unstable_by_key(|&k| {
            let u = &self.units[k as usize];
            (u.hi, std::cmp::Reverse(u.lo))
        });
        self.ending_start = vec![0; p + 1];
        for u in &self.units {
            self.ending_start[u.hi as usize + 1] += 1;
        }
        for x in 0..p {
            self.ending_start[x + 1] += self.ending_start[x];
        }
        self.entry_of = vec![0; self.units.len()];
        for (e, &k) in order.iter().enumerate() {
            self.entry_of[k as usize] = e as u32;
        }
        self.ending = order
            .iter()
            .map(|&k| (self.units[k as usize].lo, UNKNOWN))
            .collect();
        self.ending_unit = order;
        // Units only: staircase pieces add nothing, since each chord is a unit and a piece's
        // first chord starts where the piece starts and ends within it, its last chord ends
        // where it ends and starts within it.
        let (mut nearest_end, mut furthest_start) = (vec![NONE; p], vec![NONE; p]);
        for u in &self.units {
            let (lo, hi) = (u.lo, u.hi);
            nearest_end[lo as usize] = nearest_end[lo as usize].min(hi);
            if furthest_start[hi as usize] == NONE || furthest_start[hi as usize] < lo {
                furthest_start[hi as usize] = lo;
            }
        }
        (self.nearest_end, self.furthest_start) = (nearest_end, furthest_start);
    }

    /// The range `a..=b` without first positions where nothing ending within it starts and last
    /// positions where nothing starting within it ends: the same units and pieces lie within
    /// it, so it has the same best value. `None` if nothing lies within `a..=b`.
    fn tighten(&self, mut a: usize, mut b: usize) -> Option<(usize, usize)> {
        while a <= b && (self.nearest_end[a] == NONE || self.nearest_end[a] as usize > b) {
            a += 1;
        }
        if a > b {
            return None;
        }
        // Something starts at `a` and ends within: the walk back stops there at the latest.
        while self.furthest_start[b] == NONE || (self.furthest_start[b] as usize) < a {
            b -= 1;
        }
        Some((a, b))
    }
}

/// Records the value of `job`: `inside`, the sum of the best values in the ranges it asked for
/// (for a unit valued from a shorter piece, that piece's gaps added back); a unit's value adds
/// its own chords.
fn set_value(table: &mut Table, job: Job, mut inside: i64) {
    let count = |u: &Unit| u.length() as i64 + 1;
    if let Job::Unit(k) = job {
        let u = &table.units[k as usize];
        if u.pred != NONE {
            // The shorter piece's gaps, with the changes listed for this one.
            let shorter = &table.units[u.pred as usize];
            let value = table.ending[table.entry_of[u.pred as usize] as usize].1;
            inside += value as i64 - count(shorter);
        }
    }
    let inside = inside as u32;
    match job {
        Job::Unit(k) => {
            let u = &table.units[k as usize];
            table.ending[table.entry_of[k as usize] as usize].1 = count(u) as u32 + inside;
        }
        Job::Left(s, f) => table.stairs[s as usize].left[f as usize] = inside,
        Job::Inner(s, j) => table.stairs[s as usize].inner[j as usize] = inside,
        Job::Right(s, r) => table.stairs[s as usize].right[r as usize] = inside,
    }
}
