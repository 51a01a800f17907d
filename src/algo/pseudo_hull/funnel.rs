//! The shortest path through a sleeve of triangles, by the funnel algorithm (D. T. Lee and
//! F. P. Preparata, "Euclidean shortest paths in the presence of rectilinear barriers",
//! *Networks* 14 (1984); J. Hershberger and J. Snoeyink, "Computing minimum length paths of a
//! given homotopy class", *Comput. Geom.* 4 (1994), whose sleeves may meet a triangle more than
//! once: the funnel runs in the universal cover, where each passage is a new triangle).
//!
//! Input: a start vertex, the diagonals crossed in order (each as `(left, right)` seen in the
//! direction of travel; consecutive ones are two sides of one triangle, so they share one end),
//! and an end vertex lying in the last triangle. Output: the vertices of the shortest path,
//! start and end included. Every vertex the path passes through is listed, also where it goes
//! straight on (angle exactly pi): a chain keeps a vertex at a straight turn, and the apex moves
//! onto a vertex lying straight on the way. So no edge of the path contains a vertex.
//!
//! The two chains of the funnel are deques of sleeve vertices; a sleeve vertex is a copy of a
//! polygon vertex, told apart by the position where it entered the sleeve (the same vertex can
//! be met again further on, after the sleeve went round an obstacle). Every decision is an
//! exact orientation or dot-product sign. A configuration the algorithm cannot meet on a valid
//! sleeve (a point on the line of a chain segment but behind it) is reported as [`Broken`].
//! O(m) for m diagonals: each vertex enters and leaves a chain once.

use crate::algo::mesh::Broken;
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cross, dot};
use std::collections::VecDeque;

/// A sleeve vertex: the polygon vertex, and the position of its copy in the sleeve.
#[derive(Clone, Copy, Debug)]
struct Node {
    v: usize,
    copy: usize,
}

struct Funnel<'a, P: Coord> {
    pts: &'a [P],
    left: VecDeque<Node>,
    right: VecDeque<Node>,
    path: Vec<usize>,
}

impl<P: Coord> Funnel<'_, P> {
    fn p(&self, n: Node) -> P {
        self.pts[n.v]
    }

    /// Adds `x` at the far end of one chain (`left` true: the left chain). Mirror images: on the
    /// left chain every turn is to the left (or straight), on the right chain to the right.
    fn add(&mut self, x: Node, on_left: bool) -> Result<(), Broken> {
        let sign: i128 = if on_left { 1 } else { -1 };
        let px = self.p(x);
        loop {
            let chain = if on_left { &self.left } else { &self.right };
            let len = chain.len();
            if chain[len - 1].copy == x.copy {
                return Ok(());
            }
            if len >= 2 {
                let (a, b) = (self.p(chain[len - 2]), self.p(chain[len - 1]));
                let turn = sign * cross(a, b, px);
                if turn < 0 {
                    if on_left {
                        self.left.pop_back();
                    } else {
                        self.right.pop_back();
                    }
                    continue;
                }
                if turn == 0 && dot(b, a, px) >= 0 {
                    return Err(Broken);
                }
                break;
            }
            // The chain is the apex alone: does x lie beyond the other chain's first segment?
            loop {
                let other = if on_left { &self.right } else { &self.left };
                if other.len() < 2 {
                    break;
                }
                let (apex, r) = (other[0], other[1]);
                let (pa, pr) = (self.p(apex), self.p(r));
                let side = sign * cross(pa, pr, px);
                if side < 0 || (side == 0 && dot(pr, pa, px) < 0) {
                    // The apex moves on to r.
                    self.path.push(r.v);
                    if on_left {
                        self.right.pop_front();
                        self.left[0] = r;
                    } else {
                        self.left.pop_front();
                        self.right[0] = r;
                    }
                } else if side == 0 {
                    return Err(Broken);
                } else {
                    break;
                }
            }
            break;
        }
        if on_left {
            self.left.push_back(x);
        } else {
            self.right.push_back(x);
        }
        Ok(())
    }
}

/// The shortest path from `start` to `end` through the diagonals `portals` (`(left, right)`
/// each), as polygon vertices; see the module docs.
pub(super) fn shortest_path<P: Coord>(
    pts: &[P],
    start: usize,
    portals: &[(usize, usize)],
    end: usize,
) -> Result<Vec<usize>, Broken> {
    let apex = Node { v: start, copy: 0 };
    let mut f = Funnel {
        pts,
        left: VecDeque::from([apex]),
        right: VecDeque::from([apex]),
        path: vec![start],
    };
    let mut copies = 1;
    let mut fresh = |v: usize| {
        copies += 1;
        Node { v, copy: copies }
    };
    let (mut l, mut r) = (apex, apex);
    for (i, &(pl, pr)) in portals.iter().enumerate() {
        if i == 0 {
            // The first triangle holds the start: a diagonal end equal to it is that copy.
            l = if pl == start { apex } else { fresh(pl) };
            r = if pr == start { apex } else { fresh(pr) };
            f.add(l, true)?;
            f.add(r, false)?;
        } else if pl == l.v && pr != r.v {
            r = fresh(pr);
            f.add(r, false)?;
        } else if pr == r.v && pl != l.v {
            l = fresh(pl);
            f.add(l, true)?;
        } else {
            return Err(Broken); // not two sides of one triangle
        }
    }
    // The end lies in the last triangle: an end of the last diagonal equal to it is that copy.
    if !portals.is_empty() && end == r.v {
        f.add(r, false)?;
        f.path.extend(f.right.iter().skip(1).map(|n| n.v));
    } else {
        let t = if !portals.is_empty() && end == l.v {
            l
        } else {
            fresh(end)
        };
        f.add(t, true)?;
        f.path.extend(f.left.iter().skip(1).map(|n| n.v));
    }
    Ok(f.path)
}

#[cfg(test)]
mod tests {
    use super::shortest_path;
    use crate::geom::kernel::Point;

    #[test]
    fn a_straight_sleeve_gives_a_segment_and_a_bend_wraps_a_corner() {
        // Square 0 (0,0) 1 (4,0) 2 (4,4) 3 (0,4): from 0 to 2 across diagonal 1-3.
        let pts = [(0, 0), (4, 0), (4, 4), (0, 4)].map(|(x, y)| Point::new(x, y));
        assert_eq!(shortest_path(&pts, 0, &[(3, 1)], 2), Ok(vec![0, 2]));
        // An L: 0 (0,0) 1 (4,0) 2 (4,1) 3 (1,1) 4 (1,4) 5 (0,4); from 1 to 4 the path bends at 3.
        let pts = [(0, 0), (4, 0), (4, 1), (1, 1), (1, 4), (0, 4)].map(|(x, y)| Point::new(x, y));
        // Triangles (1, 2, 3), (1, 3, 0), (0, 3, 5), (5, 3, 4): diagonals 1-3, 3-0, 3-5.
        assert_eq!(
            shortest_path(&pts, 2, &[(1, 3), (0, 3), (5, 3)], 4),
            Ok(vec![2, 3, 4])
        );
    }

    #[test]
    fn a_vertex_straight_on_the_way_is_kept() {
        // 0 (0,0) 1 (2,0) 2 (4,0) 3 (4,2) 4 (2,1) 5 (0,2): 4 is not on 0..3; but from 0 to 2
        // through diagonals (4, 1), the straight path passes through 1: 0 -> 1 -> 2.
        let pts = [(0, 0), (2, 0), (4, 0), (4, 2), (2, 1), (0, 2)].map(|(x, y)| Point::new(x, y));
        assert_eq!(shortest_path(&pts, 0, &[(4, 1)], 2), Ok(vec![0, 1, 2]));
    }
}
