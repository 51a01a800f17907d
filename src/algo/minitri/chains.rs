//! The 3b-chains of step 3 (Chen & Chang 1990, §3, relationship (iii)(b)): two minimally
//! degenerate triangles `(a, b, c)` and `(b, c, d)` on one line, sharing the side `b c`, with
//! their 180-degree sides on the same side of the line, cross on the circle yet are
//! independent; a 3b-chain is a path of such pairs, and any set of its members is independent
//! (see [`super::mis`]).

use super::degenerate::Degenerate;
use super::lists::Lists;
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cross, Dir};
use crate::geom::polygon::Polygon;

/// The 3b-chains: for each triangle, its chain (a path of 3b-partners) and its place in it.
#[derive(Clone, Debug)]
pub struct Chains {
    /// The chains, each a list of triangles in order along their line.
    pub paths: Lists,
    /// For each triangle: (its chain, its index in that chain).
    pub place: Vec<(usize, usize)>,
}

impl Chains {
    /// `k` triangles, each a chain of its own (no 3b pairs).
    pub fn lone(k: usize) -> Chains {
        let mut paths = Lists::with_capacity(k);
        for t in 0..k {
            paths.push(t);
            paths.close();
        }
        Chains {
            paths,
            place: (0..k).map(|t| (t, 0)).collect(),
        }
    }
}

/// Whether `s` and `t` form a 3b pair: they share a side on one line (the middle of each is an
/// end of the other) and their 180-degree sides lie on the same side of the line.
pub fn is_3b_pair<P: Coord>(polygon: &Polygon<P>, s: &Degenerate, t: &Degenerate) -> bool {
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
pub fn chains<P: Coord>(polygon: &Polygon<P>, mdts: &[Degenerate]) -> Chains {
    // The triangles by middle vertex (adjacency arrays): `by_middle[start[v]..start[v + 1]]`.
    let mut start = vec![0; polygon.len() + 1];
    for m in mdts {
        start[m.b + 1] += 1;
    }
    for v in 0..polygon.len() {
        start[v + 1] += start[v];
    }
    let mut by_middle = vec![0; mdts.len()];
    let mut fill = start.clone();
    for (t, m) in mdts.iter().enumerate() {
        by_middle[fill[m.b]] = t;
        fill[m.b] += 1;
    }
    // Each triangle's 3b-partners: at most one through each end (`NONE` for none).
    const NONE: usize = usize::MAX;
    let mut partners: Vec<[usize; 2]> = vec![[NONE; 2]; mdts.len()];
    for (s, m) in mdts.iter().enumerate() {
        for (k, end) in [m.a, m.c].into_iter().enumerate() {
            // The triangle with middle `end` and an end at `m.b`, if any (one at most: the
            // nearest vertex in a direction is unique).
            let found = by_middle[start[end]..start[end + 1]]
                .iter()
                .find(|&&t| mdts[t].a == m.b || mdts[t].c == m.b);
            if let Some(&t) = found {
                if is_3b_pair(polygon, m, &mdts[t]) {
                    partners[s][k] = t;
                }
            }
        }
    }
    let mut place = vec![(usize::MAX, 0); mdts.len()];
    let mut paths = Lists::with_capacity(mdts.len());
    for start in 0..mdts.len() {
        if place[start].0 != usize::MAX || !partners[start].contains(&NONE) {
            continue; // already placed, or inside a path (paths start at an end)
        }
        let chain = paths.len();
        let (mut prev, mut at) = (NONE, start);
        loop {
            place[at] = (chain, paths.open_len());
            paths.push(at);
            match partners[at].iter().find(|&&p| p != prev && p != NONE) {
                Some(&next) => (prev, at) = (at, next),
                None => break,
            }
        }
        paths.close();
    }
    Chains { paths, place }
}
