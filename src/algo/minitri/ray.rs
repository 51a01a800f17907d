//! Ray shooting from a vertex: the first boundary point a ray meets, exactly.
//!
//! Step 1's walk ([`super::expansion`]) sometimes carries a wide part of a cone a long way only
//! for a few directions (those whose opposite the other cone has found). For each such
//! direction it asks instead: going from vertex `b` along direction `d`, what is met first: a
//! vertex (then it is seen from `b` and nearest in that direction), or the relative interior
//! of an edge (then nothing is seen there)?
//!
//! Method: a bounding-volume hierarchy over the edges of all rings (boxes with integer corners;
//! edges sorted by the centre of their box along the longer side of the node's box, split at
//! the median, leaves of at most [`LEAF`] edges), searched depth first, nearer child first,
//! skipping every box that the ray does not meet before the best hit so far.
//!
//! Exactness: a hit is at `b + t d` with `t = num / den`, both `i128` below `2^126` in
//! magnitude (cross and dot products of grid differences, see `crate::geom::kernel`); two such
//! fractions are compared by products of 250 bits, computed by [`mul_wide`] (hand-written: a
//! 128 x 128 -> 256-bit product is four lines of limbs, no crate needed for it). A box is met
//! when the slabs' parameter intervals (fractions of grid differences) overlap within
//! `(0, best]`. No tolerance anywhere.
//!
//! Complexity: O(n log n) to build, O(n) memory; a query visits the boxes the ray meets before
//! its first hit (O(log n) on typical boundaries, O(n) in the worst case: boxes of a bounding
//! hierarchy are not disjoint, so this gives no worst-case bound, only the practical one).

use crate::geom::kernel::{Dir, Point};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;

/// The most edges in a leaf of the hierarchy.
const LEAF: usize = 4;

/// A node of the hierarchy: a box and either its two children or a range of `order`.
struct Node {
    min: Point,
    max: Point,
    /// Children `(left, right)` when `end == 0`; otherwise a leaf of `order[start..end]`.
    start: u32,
    end: u32,
}

/// The edges of a polygon (edge `v` runs from `v` to `next(v)`) in a box hierarchy.
pub struct Rays {
    nodes: Vec<Node>,
    order: Vec<u32>,
}

/// A ray parameter `num / den` with `den > 0`.
#[derive(Clone, Copy, Debug)]
struct Frac {
    num: i128,
    den: i128,
}

impl Frac {
    fn new(num: i128, den: i128) -> Frac {
        if den < 0 {
            Frac {
                num: -num,
                den: -den,
            }
        } else {
            Frac { num, den }
        }
    }

    /// Exact comparison of `a.num / a.den` with `b.num / b.den` (products of up to 252 bits).
    fn cmp(self, other: Frac) -> Ordering {
        let left = signed_wide(self.num, other.den);
        let right = signed_wide(other.num, self.den);
        left.cmp(&right)
    }
}

/// `x * y` as (sign, high, low) ordered like the product's value.
fn signed_wide(x: i128, y: i128) -> (i8, u128, u128) {
    let negative = (x < 0) != (y < 0);
    let (hi, lo) = mul_wide(x.unsigned_abs(), y.unsigned_abs());
    if hi == 0 && lo == 0 {
        (0, 0, 0)
    } else if negative {
        // Larger magnitudes are smaller values: complement the magnitude for ordering.
        (-1, !hi, !lo)
    } else {
        (1, hi, lo)
    }
}

/// The full 256-bit product of two `u128`s, as (high, low) halves.
fn mul_wide(x: u128, y: u128) -> (u128, u128) {
    let mask = u128::from(u64::MAX);
    let (x1, x0, y1, y0) = (x >> 64, x & mask, y >> 64, y & mask);
    let (p00, p01, p10, p11) = (x0 * y0, x0 * y1, x1 * y0, x1 * y1);
    let middle = (p00 >> 64) + (p01 & mask) + (p10 & mask);
    let lo = (p00 & mask) | (middle << 64);
    let hi = p11 + (p01 >> 64) + (p10 >> 64) + (middle >> 64);
    (hi, lo)
}

impl Rays {
    /// The hierarchy over every edge of `polygon`.
    pub fn new(polygon: &Polygon) -> Rays {
        let n = polygon.len();
        let mut rays = Rays {
            nodes: Vec::with_capacity(2 * n.div_ceil(LEAF) + 1),
            order: (0..n as u32).collect(),
        };
        let boxes: Vec<(Point, Point)> = (0..n)
            .map(|v| {
                let (p, q) = (polygon.point(v), polygon.point(polygon.next(v)));
                (
                    Point::new(p.x.min(q.x), p.y.min(q.y)),
                    Point::new(p.x.max(q.x), p.y.max(q.y)),
                )
            })
            .collect();
        rays.build(&boxes, 0, n);
        rays
    }

    /// Adds the node of `order[start..end]` (and its subtree); returns its index.
    fn build(&mut self, boxes: &[(Point, Point)], start: usize, end: usize) -> u32 {
        let edges = &mut self.order[start..end];
        let (mut min, mut max) = boxes[edges[0] as usize];
        for &e in edges.iter() {
            let (lo, hi) = boxes[e as usize];
            min = Point::new(min.x.min(lo.x), min.y.min(lo.y));
            max = Point::new(max.x.max(hi.x), max.y.max(hi.y));
        }
        let index = self.nodes.len() as u32;
        self.nodes.push(Node {
            min,
            max,
            start: start as u32,
            end: end as u32,
        });
        if end - start > LEAF {
            // Sum of both corners: twice the centre, no division.
            let along_x = max.x - min.x >= max.y - min.y;
            let key = |e: &u32| {
                let (lo, hi) = boxes[*e as usize];
                if along_x {
                    i128::from(lo.x) + i128::from(hi.x)
                } else {
                    i128::from(lo.y) + i128::from(hi.y)
                }
            };
            let middle = (end - start) / 2;
            edges.select_nth_unstable_by_key(middle, key);
            let left = self.build(boxes, start, start + middle);
            let right = self.build(boxes, start + middle, end);
            debug_assert_eq!(left, index + 1);
            self.nodes[index as usize].start = right;
            self.nodes[index as usize].end = 0;
        }
        index
    }

    /// Where the ray from vertex `b` along `d` (not zero) first meets the boundary, beyond `b`
    /// itself: `Some(v)` if at vertex `v`, `None` if inside an edge (or nowhere, which a ray
    /// from inside a bounded polygon cannot be).
    pub fn first_vertex(&self, polygon: &Polygon, b: usize, d: Dir) -> Option<usize> {
        let origin = polygon.point(b);
        let mut best: Option<(Frac, Option<usize>)> = None;
        let mut stack = vec![0u32];
        while let Some(i) = stack.pop() {
            let node = &self.nodes[i as usize];
            if node.end != 0 {
                for &e in &self.order[node.start as usize..node.end as usize] {
                    let e = e as usize;
                    if let Some(hit) = edge_hit(polygon, origin, b, d, e) {
                        let better = match best {
                            None => true,
                            Some((t, at)) => match hit.0.cmp(t) {
                                Ordering::Less => true,
                                // The same point: a vertex if any edge says so.
                                Ordering::Equal => at.is_none() && hit.1.is_some(),
                                Ordering::Greater => false,
                            },
                        };
                        if better {
                            best = Some(hit);
                        }
                    }
                }
                continue;
            }
            let limit = best.map(|(t, _)| t);
            let (left, right) = (i + 1, node.start);
            let entry = |k: u32| {
                let child = &self.nodes[k as usize];
                box_entry(origin, d, child.min, child.max, limit)
            };
            match (entry(left), entry(right)) {
                (Some(a), Some(c)) => {
                    // The nearer child last, so that it is searched first.
                    if a.cmp(c) == Ordering::Greater {
                        stack.extend([right, left]);
                    } else {
                        stack.extend([left, right]);
                    }
                }
                (Some(_), None) => stack.push(left),
                (None, Some(_)) => stack.push(right),
                (None, None) => {}
            }
        }
        best.and_then(|(_, at)| at)
    }
}

/// The first point (`t > 0`) where the ray from `origin` (vertex `b`) along `d` meets edge `e`:
/// its parameter and the vertex there, if it is one.
fn edge_hit(polygon: &Polygon, origin: Point, b: usize, d: Dir, e: usize) -> Option<(Frac, Option<usize>)> {
    let f = polygon.next(e);
    if e == b || f == b {
        return None; // b's own edges meet the ray only at b
    }
    let (p, q) = (polygon.point(e), polygon.point(f));
    let (bp, bq) = (Dir::between(origin, p), Dir::between(origin, q));
    let (u, v) = (d.cross(bp), d.cross(bq));
    if (u > 0 && v > 0) || (u < 0 && v < 0) {
        return None;
    }
    if u == 0 && v == 0 {
        // Along the ray's line: the nearer endpoint ahead is met first.
        let dd = d.dot(d);
        let (tp, tq) = (Frac::new(d.dot(bp), dd), Frac::new(d.dot(bq), dd));
        let ahead = |t: Frac| t.num > 0;
        return match (ahead(tp), ahead(tq)) {
            (true, true) if tp.cmp(tq) == Ordering::Greater => Some((tq, Some(f))),
            (true, _) => Some((tp, Some(e))),
            (false, true) => Some((tq, Some(f))),
            (false, false) => None,
        };
    }
    let pq = Dir::between(p, q);
    let t = Frac::new(bp.cross(pq), d.cross(pq));
    if t.num <= 0 {
        return None;
    }
    let at = if u == 0 {
        Some(e)
    } else if v == 0 {
        Some(f)
    } else {
        None
    };
    Some((t, at))
}

/// The smallest `t` in `(0, limit]` (no upper bound without `limit`) with `origin + t d` in the
/// closed box `[min, max]`, if there is one (0 when the ray starts in the box).
fn box_entry(origin: Point, d: Dir, min: Point, max: Point, limit: Option<Frac>) -> Option<Frac> {
    let zero = Frac { num: 0, den: 1 };
    let (mut lo, mut hi) = (zero, limit);
    let slabs = [(origin.x, d.x, min.x, max.x), (origin.y, d.y, min.y, max.y)];
    for (o, step, a, c) in slabs {
        if step == 0 {
            if o < a || o > c {
                return None;
            }
            continue;
        }
        let (s, e) = (
            Frac::new(i128::from(a - o), i128::from(step)),
            Frac::new(i128::from(c - o), i128::from(step)),
        );
        let (s, e) = if step > 0 { (s, e) } else { (e, s) };
        if s.cmp(lo) == Ordering::Greater {
            lo = s;
        }
        if hi.is_none_or(|h| e.cmp(h) == Ordering::Less) {
            hi = Some(e);
        }
    }
    match hi {
        Some(h) if lo.cmp(h) == Ordering::Greater => None,
        _ => Some(lo),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wide_products_order_like_the_values() {
        let big = (1i128 << 125) + 7;
        let cases = [
            (Frac::new(big, 3), Frac::new(big - 1, 3), Ordering::Greater),
            (Frac::new(-big, 3), Frac::new(1 - big, 3), Ordering::Less),
            (Frac::new(big, big - 1), Frac::new(1, 1), Ordering::Greater),
            (Frac::new(0, 5), Frac::new(0, big), Ordering::Equal),
            (Frac::new(-1, big), Frac::new(0, 1), Ordering::Less),
            (Frac::new(2 * 3, -4), Frac::new(-3, 2), Ordering::Equal),
        ];
        for (a, b, want) in cases {
            assert_eq!(a.cmp(b), want, "{a:?} vs {b:?}");
            assert_eq!(b.cmp(a), want.reverse(), "{b:?} vs {a:?}");
        }
        assert_eq!(mul_wide(u128::MAX, u128::MAX), (u128::MAX - 1, 1));
    }
}
