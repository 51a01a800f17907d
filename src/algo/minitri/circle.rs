//! Step 2 of MINITRI: the circular representation C(P) (Chen & Chang 1990, §3, Step 2).
//!
//! The boundary of P is read as a circle (vertices in boundary order) and each minimally
//! degenerate triangle `(a, b, c)` becomes the chord `a c` of that circle. Several chords can end
//! at one vertex: their endpoints are spread over a small arc at that vertex, ordered by the
//! angle of the chord around the vertex, so that chords which do not cross in the plane do not
//! cross on the circle. Going round the circle in boundary order the boundary arrives from
//! `prev(v)` and leaves towards `next(v)`, so at `v` the chord turning furthest from the
//! direction of `next(v)` (nearest to `prev(v)`) comes first. Two triangles sharing an end
//! (Theorem 1 (ii)) thus never cross; the only independent triangles whose chords cross are the
//! pairs of a 3b-chain (relationship (iii)(b)), which [`super::mis`] treats separately.
//!
//! Complexity: O(K log K) for K triangles.

use super::degenerate::Degenerate;
use crate::geom::kernel::cmp_angle_from;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;

/// Chords on a circle with positions `0..2K`, one endpoint per position.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Circle {
    /// For each triangle, its chord `(left, right)` with `left < right`.
    pub chords: Vec<(usize, usize)>,
    /// For each position, the triangle whose chord ends there.
    pub owner: Vec<usize>,
}

impl Circle {
    /// Whether the chords of triangles `s` and `t` cross on the circle.
    pub fn cross(&self, s: usize, t: usize) -> bool {
        chords_cross(self.chords[s], self.chords[t])
    }
}

/// Whether two chords `(left, right)` (`left < right`, four distinct positions) cross: exactly
/// one end of each lies strictly between the ends of the other.
pub fn chords_cross((a, b): (usize, usize), (c, d): (usize, usize)) -> bool {
    (a < c && c < b && b < d) || (c < a && a < d && d < b)
}

/// Sorts the chord ends `(vertex, triangle, middle)` by vertex, the ends at one vertex by the
/// angle of their chord from the direction of `next(vertex)`, furthest first, equal angles in
/// triangle order: the order of a stable sort by (vertex, angle) of the ends listed by triangle.
/// Done as a counting sort by vertex (stable, so each vertex's ends stay in triangle order), then
/// a stable sort of each vertex's ends by angle (by insertion: they are few).
pub(super) fn sort_ends<P: Coord>(polygon: &Polygon<P>, ends: &mut Vec<(usize, usize, usize)>) {
    let mut start = vec![0usize; polygon.len() + 1];
    for &(v, _, _) in ends.iter() {
        start[v + 1] += 1;
    }
    for v in 0..polygon.len() {
        start[v + 1] += start[v];
    }
    let mut sorted = vec![(0, 0, 0); ends.len()];
    let mut fill = start.clone();
    for &end in ends.iter() {
        sorted[fill[end.0]] = end;
        fill[end.0] += 1;
    }
    for (v, bounds) in start.windows(2).enumerate() {
        let run = &mut sorted[bounds[0]..bounds[1]];
        if run.len() < 2 {
            continue;
        }
        let (c, r) = (polygon.point(v), polygon.point(polygon.next(v)));
        sort_stable(run, |&(_, _, x), &(_, _, y)| {
            cmp_angle_from(c, r, polygon.point(x), polygon.point(y)).reverse()
        });
    }
    *ends = sorted;
}

/// The runs up to this length are sorted by insertion ([`sort_stable`]).
const INSERTION_UP_TO: usize = 16;

/// A stable sort of `items` by `cmp`: by insertion (no allocation) for a short run, as the chord
/// ends at one vertex nearly always are, else the standard stable sort; both give the one order
/// of a stable sort.
fn sort_stable<T: Copy>(items: &mut [T], cmp: impl Fn(&T, &T) -> std::cmp::Ordering) {
    if items.len() > INSERTION_UP_TO {
        items.sort_by(cmp);
        return;
    }
    for k in 1..items.len() {
        let item = items[k];
        let mut at = k;
        while at > 0 && cmp(&items[at - 1], &item) == std::cmp::Ordering::Greater {
            items[at] = items[at - 1];
            at -= 1;
        }
        items[at] = item;
    }
}

/// Builds C(P) for the triangles `mdts` of `polygon`.
pub fn circle<P: Coord>(polygon: &Polygon<P>, mdts: &[Degenerate]) -> Circle {
    // (vertex at the endpoint, triangle, middle vertex the chord heads to)
    let mut ends: Vec<(usize, usize, usize)> = Vec::with_capacity(2 * mdts.len());
    for (t, m) in mdts.iter().enumerate() {
        ends.push((m.a, t, m.b));
        ends.push((m.c, t, m.b));
    }
    sort_ends(polygon, &mut ends);
    let mut chords = vec![(usize::MAX, usize::MAX); mdts.len()];
    let mut owner = Vec::with_capacity(ends.len());
    for (position, &(_, t, _)) in ends.iter().enumerate() {
        let chord = &mut chords[t];
        if chord.0 == usize::MAX {
            chord.0 = position;
        } else {
            chord.1 = position;
        }
        owner.push(t);
    }
    Circle { chords, owner }
}
