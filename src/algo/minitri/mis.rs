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
//! Complexity (this version): O(P^2) table entries for P = 2K endpoints, each trying the O(L^2)
//! contiguous pieces of a chain of length L: O(K^2 L^3) time and O(K^2) memory. It is the
//! reference implementation; an O(K)-memory method is still to come.

use super::circle::Circle;
use super::degenerate::Degenerate;
use crate::geom::kernel::cross;
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
    let along = |p: crate::geom::kernel::Point, q: crate::geom::kernel::Point| {
        (i128::from(q.x - p.x), i128::from(q.y - p.y))
    };
    let ((sx, sy), (tx, ty)) = (along(pa, pc), along(qa, qc));
    let same_direction = sx * tx + sy * ty > 0;
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

type Choice = (Vec<usize>, Vec<(usize, usize)>);

impl Sub<'_> {
    fn chord(&self, t: usize) -> (usize, usize) {
        let (l, r) = self.circle.chords[t];
        (self.local[l] as usize, self.local[r] as usize)
    }

    /// The recurrence over this component's endpoints `0..p`, then the recovered set.
    fn solve(&self) -> Vec<usize> {
        let p = self.positions.len();
        let mut table = vec![0u32; p * p];
        for j in 0..p {
            for i in (0..=j).rev() {
                let skip = if j > i { table[i * p + j - 1] } else { 0 };
                let best = self
                    .options(&table, i, j)
                    .into_iter()
                    .map(|(v, _)| v)
                    .fold(skip, u32::max);
                table[i * p + j] = best;
            }
        }
        let mut chosen = Vec::new();
        let mut stack = vec![(0usize, p - 1)];
        while let Some((i, j)) = stack.pop() {
            let value = table[i * p + j];
            if value == 0 {
                continue;
            }
            if j > i && value == table[i * p + j - 1] {
                stack.push((i, j - 1));
                continue;
            }
            let (_, (piece, gaps)) = self
                .options(&table, i, j)
                .into_iter()
                .find(|(v, _)| *v == value)
                .expect("the table value comes from some option");
            chosen.extend(piece);
            stack.extend(gaps);
        }
        chosen
    }

    /// Every way to use the chord ending at local position `j` within `i..=j`: its value and
    /// (piece of its 3b-chain, gaps left between the piece's endpoints).
    fn options(&self, table: &[u32], i: usize, j: usize) -> Vec<(u32, Choice)> {
        let p = self.positions.len();
        let t = self.circle.owner[self.positions[j]];
        let (k, _) = self.chord(t);
        if k < i || k == j {
            return Vec::new();
        }
        let (chain, at) = self.chains.place[t];
        let path = &self.chains.paths[chain];
        let inside = |s: usize| {
            let (l, r) = self.chord(s);
            l >= i && r <= j
        };
        let mut first = at;
        while first > 0 && inside(path[first - 1]) {
            first -= 1;
        }
        let mut last = at;
        while last + 1 < path.len() && inside(path[last + 1]) {
            last += 1;
        }
        let mut out = Vec::new();
        for s in first..=at {
            for e in at..=last {
                let piece: Vec<usize> = path[s..=e].to_vec();
                let mut ends: Vec<usize> = piece
                    .iter()
                    .flat_map(|&x| {
                        let (l, r) = self.chord(x);
                        [l, r]
                    })
                    .collect();
                ends.sort_unstable();
                let mut gaps = Vec::new();
                let mut from = i;
                for &x in &ends {
                    if x > from {
                        gaps.push((from, x - 1));
                    }
                    from = x + 1;
                }
                if from <= j {
                    gaps.push((from, j));
                }
                let value =
                    piece.len() as u32 + gaps.iter().map(|&(a, b)| table[a * p + b]).sum::<u32>();
                out.push((value, (piece, gaps)));
            }
        }
        out
    }
}
