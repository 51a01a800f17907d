//! Steps 4 and 5 of MINITRI: cut P along the chosen triangles, triangulate each piece
//! (Chen & Chang 1990, §3, Steps 4-5).
//!
//! The chosen triangles' sides `a b` and `b c` are chords of the polygon (no vertex inside them,
//! by minimality; a side that is an edge adds nothing), and independent triangles never cross,
//! so the sides are non-crossing diagonals of a simple polygon, and the pieces are the faces
//! they cut it into. Non-crossing diagonals `(u, v)`, `u < v` in boundary order, nest like
//! parentheses (a diagonal splits the polygon into the two boundary chains between its ends,
//! and another one lies on one side, its ends on one chain), so one walk along the boundary with
//! a stack lists the pieces: each vertex is pushed, and at `v` each diagonal `(u, v)`, innermost
//! (largest `u`) first, closes the piece `u, .., v` of the vertices above `u`, which leave the
//! stack (`u` and `v` stay). What is left at the end is the piece with the edge `n-1 -> 0`. Each
//! piece lists its vertices in boundary order, so counter-clockwise. (This replaced a walk of the
//! faces of the plane graph, which sorted each vertex's edges by angle: 26.6K of 210K
//! instructions per polygon on the batch benchmark.)
//!
//! On its 180-degree side a chosen middle vertex `b` is straight (its neighbours in the piece
//! are `a` and `c`, collinear with it): it is dropped from that piece, which then has the side
//! `a c` with `b` inside it, the T-junction that saves a triangle. Input flat vertices that are
//! not chosen middles stay, and the plain triangulation (`crate::algo::plain::rings`) never makes a
//! zero-area triangle at them. Each piece with `n_i` vertices gives `n_i - 2` triangles,
//! `n - 2 - d` in all.
//!
//! Complexity: O(n + K log K) to sort the diagonals and walk the boundary, plus O(n_i log n_i)
//! for each piece (`crate::algo::plain::rings`).

use super::degenerate::Degenerate;
use crate::algo::plain;
use crate::geom::kernel::cross;
use crate::geom::kernel::Coord;
use crate::geom::polygon::Polygon;

/// The triangles of all pieces, in stored vertex indices, counter-clockwise.
///
/// Contract: `polygon` has one ring (no holes, no touching rings: those go through
/// [`super::cut`]), and `chosen` are mutually independent minimally degenerate triangles of it
/// (step 3's answer), so that their sides nest; debug builds check the nesting at every piece.
pub fn triangulate_pieces<P: Coord>(
    polygon: &Polygon<P>,
    chosen: &[Degenerate],
) -> Vec<[usize; 3]> {
    let n = polygon.len();
    // The diagonals (sides that are not edges) as (later end, earlier end), deduplicated
    // (3b-chains share sides), by later end and then innermost (latest earlier end) first.
    let is_edge = |u: usize, v: usize| polygon.next(u) == v || polygon.next(v) == u;
    let mut diagonals: Vec<(usize, usize)> = chosen
        .iter()
        .flat_map(|m| [(m.a, m.b), (m.b, m.c)])
        .filter(|&(u, v)| !is_edge(u, v))
        .map(|(u, v)| (u.max(v), u.min(v)))
        .collect();
    diagonals.sort_unstable_by_key(|&(v, u)| (v, std::cmp::Reverse(u)));
    diagonals.dedup();
    let mut straight_middle = vec![false; n];
    for m in chosen {
        straight_middle[m.b] = true;
    }
    let mut triangles = Vec::with_capacity(n);
    let (mut stack, mut face, mut keep, mut piece) =
        (Vec::with_capacity(n), Vec::new(), Vec::new(), Vec::new());
    let mut next_diagonal = diagonals.iter().peekable();
    for v in 0..n {
        stack.push(v);
        while let Some(&(_, u)) = next_diagonal.next_if(|d| d.0 == v) {
            stack.pop(); // v
            face.clear();
            while let Some(&w) = stack.last() {
                if w == u {
                    break;
                }
                face.push(w);
                stack.pop();
            }
            debug_assert_eq!(stack.last(), Some(&u), "non-crossing diagonals nest");
            face.push(u);
            face.reverse();
            face.push(v);
            stack.push(v);
            triangulate_piece(
                polygon,
                &face,
                &straight_middle,
                &mut keep,
                &mut piece,
                &mut triangles,
            );
        }
    }
    triangulate_piece(
        polygon,
        &stack,
        &straight_middle,
        &mut keep,
        &mut piece,
        &mut triangles,
    );
    triangles
}

/// Adds the triangles of one piece (its vertices counter-clockwise in `face`) to `triangles`,
/// chosen middles dropped where they are straight; `keep` and `piece` are buffers.
fn triangulate_piece<P: Coord>(
    polygon: &Polygon<P>,
    face: &[usize],
    straight_middle: &[bool],
    keep: &mut Vec<usize>,
    piece: &mut Vec<P>,
    triangles: &mut Vec<[usize; 3]>,
) {
    let point = |i: usize| polygon.point(face[i]);
    let k = face.len();
    // Drop chosen middles where they are straight (their 180-degree side).
    keep.clear();
    keep.extend((0..k).filter_map(|i| {
        let (p, q) = (point((i + k - 1) % k), point((i + 1) % k));
        let straight = straight_middle[face[i]] && cross(p, point(i), q) == 0;
        (!straight).then_some(face[i])
    }));
    if let [a, b, c] = keep[..] {
        triangles.push([a, b, c]); // already a triangle (of positive area: a piece)
        return;
    }
    piece.clear();
    piece.extend(keep.iter().map(|&i| polygon.point(i)));
    triangles.extend(
        plain::rings(piece, &[0])
            .into_iter()
            .map(|t| t.map(|i| keep[i])),
    );
}
