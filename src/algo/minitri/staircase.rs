//! The staircase of a 3b-chain (step 3, [`super::mis`]): on the circle the chain's chords come
//! in order, so the value of any piece of three or more chords splits into a part for its first
//! chord, a sum along the chain and a part for its last, and the scans value all O(L^2) pieces
//! with a running maximum in O(L).

use super::mis::UNKNOWN;

/// A 3b-chain whose pieces of three or more chords are valued inside the scans, not as units.
///
/// Chain `c_0 .. c_{L-1}` on the line through `v_0 .. v_{L+1}`: `c_i = (v_i, v_{i+1}, v_{i+2})`
/// starts at `s_i` (its endpoint at `v_i`) and ends at `e_i` (at `v_{i+2}`). In a staircase the
/// endpoints at each `v_j` all come before those at `v_{j+1}`. Then the gaps of a piece `f..=l`
/// with `l >= f + 2` are: two at its left end (depending on `f` only), the gaps between
/// consecutive inner vertices `v_j, v_{j+1}` (`f + 2 <= j < l`), two at its right end (depending
/// on `l` only), and gaps between the two endpoints at one inner vertex, which hold no whole
/// chord. So `value(f, l) = (l - f + 1) + left[f] + sum(inner[f + 2 .. l]) + right[l]`.
pub(super) struct Staircase {
    /// The chain's triangles, oriented so that positions increase.
    pub(super) tris: Vec<usize>,
    /// `(s_i, e_i)`, local positions.
    pub(super) ends: Vec<(usize, usize)>,
    /// `left[f]`: the best inside the gaps `(s_f, s_{f+1})` and `(s_{f+1}, min(e_f, s_{f+2}))`.
    pub(super) left: Vec<u32>,
    /// `inner[j]`: the best inside the gap `(max(e_{j-2}, s_j), min(e_{j-1}, s_{j+1}))`.
    pub(super) inner: Vec<u32>,
    /// `right[l]`: the best inside `(max(e_{l-2}, s_l), e_{l-1})` and `(e_{l-1}, e_l)`.
    pub(super) right: Vec<u32>,
}

impl Staircase {
    /// A staircase of at least four chords in the 3b-chain `path`: the whole chain, or the
    /// chain without up to two chords at either end (the fewest dropped), with the range of
    /// `path` it covers.
    ///
    /// A chain's end chords may be irregular: where the chain's line leaves the walls whose
    /// pockets make the staircase, its last vertices can be anywhere on the boundary (a snake
    /// of corridors: `tests::snakes_keep_their_staircases`), so their endpoints there are
    /// anywhere on the circle. The pieces with such a chord are listed as units (O(L) of them),
    /// the rest stays a staircase.
    pub(super) fn find(
        path: &[usize],
        chord: impl Fn(usize) -> (usize, usize),
    ) -> Option<(std::ops::Range<usize>, Staircase)> {
        let l = path.len();
        (0..=4)
            .flat_map(|trim| (0..=trim).map(move |a| (a, trim - a)))
            .filter(|&(a, b)| a <= 2 && b <= 2 && l >= a + b + 4)
            .find_map(|(a, b)| Staircase::new(&path[a..l - b], &chord).map(|s| (a..l - b, s)))
    }

    /// The chords in the chain order, if the chain is a staircase of at least four chords.
    pub(super) fn new(
        tris: &[usize],
        chord: impl Fn(usize) -> (usize, usize),
    ) -> Option<Staircase> {
        if tris.len() < 4 {
            return None;
        }
        let mut tris = tris.to_vec();
        if chord(tris[0]).0 > chord(tris[1]).0 {
            tris.reverse();
        }
        let ends: Vec<(usize, usize)> = tris.iter().map(|&t| chord(t)).collect();
        let l = ends.len();
        // Vertex v_j holds s_j (j < L) and e_{j-2} (j >= 2): its lowest and highest position.
        let group = |j: usize| {
            let mut g = (usize::MAX, 0);
            if j < l {
                g = (g.0.min(ends[j].0), g.1.max(ends[j].0));
            }
            if (2..l + 2).contains(&j) {
                g = (g.0.min(ends[j - 2].1), g.1.max(ends[j - 2].1));
            }
            g
        };
        if !(0..l + 1).all(|j| group(j).1 < group(j + 1).0) {
            return None;
        }
        Some(Staircase {
            tris,
            ends,
            left: vec![UNKNOWN; l],
            inner: vec![UNKNOWN; l],
            right: vec![UNKNOWN; l],
        })
    }

    /// One past the furthest start of a gap read at the end of chord `i` (`left[i - 2]`,
    /// `inner[i - 1]`, `right[i]`) that is not valued yet, or 0.
    pub(super) fn unvalued_before(&self, i: usize) -> usize {
        let mut stale = 0;
        if self.left[i - 2] == UNKNOWN {
            stale = self.left_gaps(i - 2)[0].0 + 1;
        }
        if i >= 3 && self.inner[i - 1] == UNKNOWN {
            stale = stale.max(self.inner_gap(i - 1).0 + 1);
        }
        if self.right[i] == UNKNOWN {
            stale = stale.max(self.right_gaps(i)[0].0 + 1);
        }
        stale
    }

    /// The gaps (open ranges of local positions) that make up `left[f]`, `inner[j]`, `right[l]`.
    pub(super) fn left_gaps(&self, f: usize) -> [(usize, usize); 2] {
        let e = &self.ends;
        [(e[f].0, e[f + 1].0), (e[f + 1].0, e[f].1.min(e[f + 2].0))]
    }

    pub(super) fn inner_gap(&self, j: usize) -> (usize, usize) {
        let e = &self.ends;
        (e[j - 2].1.max(e[j].0), e[j - 1].1.min(e[j + 1].0))
    }

    pub(super) fn right_gaps(&self, l: usize) -> [(usize, usize); 2] {
        let e = &self.ends;
        [(e[l - 2].1.max(e[l].0), e[l - 1].1), (e[l - 1].1, e[l].1)]
    }
}
