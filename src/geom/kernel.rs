//! The exact kernel: the only place that computes signs from coordinates.
//!
//! Input contract: [`Point`]s on the polygon's integer grid with coordinates in
//! `0..=MAX_COORD` (`2^62`), which [`crate::geom::polygon`] guarantees. Every difference then fits
//! an `i64` with room to spare, every product of two differences is below `2^124`, and every 2x2
//! determinant below `2^125`, so all predicates below are exact in `i128` and cannot overflow.
//! Output guarantee: exact answers as named enums or booleans; no epsilon anywhere. The one
//! exception, [`incircle_approx`], is named as such and serves speed heuristics only.
//! Complexity: O(1) each.

use std::cmp::Ordering;

/// The largest grid coordinate; see the module documentation for why it keeps `i128` exact.
pub const MAX_COORD: i64 = 1 << 62;

/// A point on the exact integer grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord, Default)]
pub struct Point {
    /// Grid x.
    pub x: i64,
    /// Grid y.
    pub y: i64,
}

impl Point {
    /// A point from grid coordinates.
    pub const fn new(x: i64, y: i64) -> Point {
        Point { x, y }
    }
}

/// The turn made by going from `a` to `b` to `c`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Orientation {
    /// Left turn: `c` lies to the left of the directed line `a -> b`.
    CounterClockwise,
    /// Right turn.
    Clockwise,
    /// The three points lie on one line.
    Collinear,
}

/// Twice the signed area of triangle `a b c` (positive when counter-clockwise), exact.
#[inline]
pub fn cross(a: Point, b: Point, c: Point) -> i128 {
    let (ux, uy) = (i128::from(b.x - a.x), i128::from(b.y - a.y));
    let (vx, vy) = (i128::from(c.x - a.x), i128::from(c.y - a.y));
    ux * vy - uy * vx
}

/// The dot product of `b - a` and `c - a`, exact.
#[inline]
pub fn dot(a: Point, b: Point, c: Point) -> i128 {
    let (ux, uy) = (i128::from(b.x - a.x), i128::from(b.y - a.y));
    let (vx, vy) = (i128::from(c.x - a.x), i128::from(c.y - a.y));
    ux * vx + uy * vy
}

/// The orientation of `a b c`.
#[inline]
pub fn orient(a: Point, b: Point, c: Point) -> Orientation {
    match cross(a, b, c).cmp(&0) {
        Ordering::Greater => Orientation::CounterClockwise,
        Ordering::Less => Orientation::Clockwise,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// Whether `p` lies strictly between `a` and `c` on segment `a c` (`a != c`).
#[inline]
pub fn strictly_between(a: Point, p: Point, c: Point) -> bool {
    cross(a, c, p) == 0 && dot(p, a, c) < 0
}

/// Whether `p` lies on the closed segment `a b`.
#[inline]
pub fn on_segment(a: Point, b: Point, p: Point) -> bool {
    cross(a, b, p) == 0 && dot(p, a, b) <= 0
}

/// How two closed segments meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SegmentContact {
    /// No common point.
    Disjoint,
    /// One common point interior to both segments.
    Cross,
    /// Exactly one common point, an endpoint of at least one of them.
    Touch,
    /// Collinear with more than one common point.
    Overlap,
}

/// How closed segments `a b` and `c d` meet (each with distinct endpoints).
pub fn segment_contact(a: Point, b: Point, c: Point, d: Point) -> SegmentContact {
    let (o1, o2) = (cross(a, b, c), cross(a, b, d));
    let (o3, o4) = (cross(c, d, a), cross(c, d, b));
    if o1 == 0 && o2 == 0 {
        // Collinear: compare the spans along the line.
        let key = |p: Point| if a.x != b.x { p.x } else { p.y };
        let (lo1, hi1) = minmax(key(a), key(b));
        let (lo2, hi2) = minmax(key(c), key(d));
        let (lo, hi) = (lo1.max(lo2), hi1.min(hi2));
        return match lo.cmp(&hi) {
            Ordering::Greater => SegmentContact::Disjoint,
            Ordering::Equal => SegmentContact::Touch,
            Ordering::Less => SegmentContact::Overlap,
        };
    }
    if o1.signum() * o2.signum() > 0 || o3.signum() * o4.signum() > 0 {
        return SegmentContact::Disjoint;
    }
    if o1 != 0 && o2 != 0 && o3 != 0 && o4 != 0 {
        SegmentContact::Cross
    } else {
        SegmentContact::Touch
    }
}

/// Whether closed segments `a b` and `c d` cross at a single point interior to both.
#[inline]
pub fn properly_cross(a: Point, b: Point, c: Point, d: Point) -> bool {
    let (o1, o2) = (cross(a, b, c), cross(a, b, d));
    let (o3, o4) = (cross(c, d, a), cross(c, d, b));
    o1.signum() * o2.signum() < 0 && o3.signum() * o4.signum() < 0
}

fn minmax(a: i64, b: i64) -> (i64, i64) {
    if a <= b {
        (a, b)
    } else {
        (b, a)
    }
}

/// Whether the direction from `w` towards `target` lies in the CLOSED interior angle at vertex `w`,
/// whose boundary neighbours are `prev` and `next`, with the interior on the left of
/// `prev -> w -> next` (counter-clockwise outer ring, clockwise holes).
///
/// The interior angle sweeps counter-clockwise from the direction of `next` to that of `prev`.
/// A flat vertex (`prev`, `w`, `next` collinear, `prev` and `next` on opposite sides) has the
/// closed half-plane on the left as its angle. A spike (`prev` and `next` on the same side) has an
/// empty interior angle apart from its two edge directions; validation rejects spikes anyway.
pub fn in_closed_wedge(prev: Point, w: Point, next: Point, target: Point) -> bool {
    let turn = cross(prev, w, next); // > 0: convex at w
    let from_next = cross(w, next, target); // >= 0: target at or left of w->next
    let to_prev = cross(w, target, prev); // >= 0: prev at or left of w->target
    match turn.cmp(&0) {
        Ordering::Greater => from_next >= 0 && to_prev >= 0,
        Ordering::Less => from_next >= 0 || to_prev >= 0,
        Ordering::Equal => {
            if dot(w, prev, next) < 0 {
                from_next >= 0
            } else {
                // Spike: only the edge direction itself.
                from_next == 0 && dot(w, next, target) > 0
            }
        }
    }
}

/// Total order of directions around a centre, starting at the positive x axis and turning
/// counter-clockwise; equal for directions on the same ray. `a` and `b` must differ from `centre`.
pub fn cmp_angle(centre: Point, a: Point, b: Point) -> Ordering {
    let half = |p: Point| {
        let (dx, dy) = (p.x - centre.x, p.y - centre.y);
        if dy > 0 || (dy == 0 && dx > 0) {
            0
        } else {
            1
        }
    };
    half(a)
        .cmp(&half(b))
        .then_with(|| 0.cmp(&cross(centre, a, b)))
}

/// Total order of directions around a centre by counter-clockwise angle measured from the
/// direction towards `reference` (angle 0); equal for directions on the same ray. All points
/// must differ from `centre`.
pub fn cmp_angle_from(centre: Point, reference: Point, a: Point, b: Point) -> Ordering {
    let half = |p: Point| {
        let s = cross(centre, reference, p);
        if s > 0 || (s == 0 && dot(centre, reference, p) > 0) {
            0
        } else {
            1
        }
    };
    half(a)
        .cmp(&half(b))
        .then_with(|| 0.cmp(&cross(centre, a, b)))
}

/// A direction: the difference of two grid points, or its negation. Both components lie within
/// `±MAX_COORD`, so cross and dot products of two directions are exact in `i128`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Dir {
    /// x component.
    pub x: i64,
    /// y component.
    pub y: i64,
}

impl Dir {
    /// The direction from `from` to `to`.
    #[inline]
    pub fn between(from: Point, to: Point) -> Dir {
        Dir {
            x: to.x - from.x,
            y: to.y - from.y,
        }
    }

    /// The opposite direction.
    #[inline]
    pub fn reversed(self) -> Dir {
        Dir {
            x: -self.x,
            y: -self.y,
        }
    }

    /// The cross product `self x other` (positive when `other` turns counter-clockwise).
    #[inline]
    pub fn cross(self, other: Dir) -> i128 {
        i128::from(self.x) * i128::from(other.y) - i128::from(self.y) * i128::from(other.x)
    }

    /// The dot product.
    #[inline]
    pub fn dot(self, other: Dir) -> i128 {
        i128::from(self.x) * i128::from(other.x) + i128::from(self.y) * i128::from(other.y)
    }
}

/// Total order of directions by counter-clockwise angle measured from `reference` (angle 0).
pub fn cmp_dir_from(reference: Dir, a: Dir, b: Dir) -> Ordering {
    let half = |d: Dir| {
        let s = reference.cross(d);
        if s > 0 || (s == 0 && reference.dot(d) > 0) {
            0
        } else {
            1
        }
    };
    half(a).cmp(&half(b)).then_with(|| 0.cmp(&a.cross(b)))
}

/// APPROXIMATELY whether `d` lies inside the circle through the counter-clockwise triangle
/// `a b c`: positive inside, negative outside, computed in floating point and so possibly wrong
/// (even in sign) when `d` is near the circle.
///
/// The one inexact predicate of the kernel, for heuristics only: it may steer how fast an
/// algorithm runs (which diagonals to flip to fatten triangles), never a geometric fact of an
/// answer. The exact determinant would need about 250 bits.
pub fn incircle_approx(a: Point, b: Point, c: Point, d: Point) -> f64 {
    let rel = |p: Point| ((p.x - d.x) as f64, (p.y - d.y) as f64);
    let ((ax, ay), (bx, by), (cx, cy)) = (rel(a), rel(b), rel(c));
    (ax * ax + ay * ay) * (bx * cy - cx * by)
        + (bx * bx + by * by) * (cx * ay - ax * cy)
        + (cx * cx + cy * cy) * (ax * by - bx * ay)
}

/// An exact sum of many `i128` values (areas of large polygons), immune to overflow.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WideSum {
    /// Number of times the low part wrapped, signed: value = high * 2^128 + low.
    high: i64,
    low: i128,
}

impl WideSum {
    /// Adds `value` exactly.
    #[inline]
    pub fn add(&mut self, value: i128) {
        let (sum, wrapped) = self.low.overflowing_add(value);
        if wrapped {
            self.high += if value > 0 { 1 } else { -1 };
        }
        self.low = sum;
    }

    /// The sign of the sum.
    pub fn signum(&self) -> i32 {
        match self.high.cmp(&0) {
            Ordering::Greater => 1,
            Ordering::Less => -1,
            Ordering::Equal => self.low.signum() as i32,
        }
    }

    /// The sum, when it fits an `i128`.
    pub fn value(&self) -> Option<i128> {
        (self.high == 0).then_some(self.low)
    }

    /// The sum as `f64` (for display only).
    pub fn to_f64(&self) -> f64 {
        self.high as f64 * 2f64.powi(128) + self.low as f64
    }
}

/// The supporting line of a segment, as an exact key: the primitive direction `(dx, dy)`, with
/// `dx > 0` or `dx == 0 < dy`, and the offset `c = dy x - dx y` of any point on it.
///
/// Along that direction the points of the line increase in the derived order of [`Point`]
/// (x first, then y), which sweeps along a line use as the position on it (the checker of
/// `verify.rs`, the T-junction lookup of the GeoJSON writer).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub struct Line {
    dx: i64,
    dy: i64,
    c: i128,
}

/// The line through distinct grid points `p` and `q`, and whether `p -> q` runs in its direction.
/// Exact: differences are at most `2^62` and products below `2^124` (kernel contract).
pub fn line_through(p: Point, q: Point) -> (Line, bool) {
    let (dx, dy) = (q.x - p.x, q.y - p.y);
    // At least 1 for distinct points, at most 2^62: fits i64.
    let g = gcd(dx.unsigned_abs(), dy.unsigned_abs()).max(1) as i64;
    let (dx, dy) = (dx / g, dy / g);
    let forward = dx > 0 || (dx == 0 && dy > 0);
    let (dx, dy) = if forward { (dx, dy) } else { (-dx, -dy) };
    let c = i128::from(dy) * i128::from(p.x) - i128::from(dx) * i128::from(p.y);
    (Line { dx, dy, c }, forward)
}

/// Binary greatest common divisor (`gcd(0, 0) = 0`).
fn gcd(mut a: u64, mut b: u64) -> u64 {
    if a == 0 || b == 0 {
        return a | b;
    }
    let shift = (a | b).trailing_zeros();
    a >>= a.trailing_zeros();
    loop {
        b >>= b.trailing_zeros();
        if a > b {
            std::mem::swap(&mut a, &mut b);
        }
        b -= a;
        if b == 0 {
            return a << shift;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: i64, y: i64) -> Point {
        Point::new(x, y)
    }

    #[test]
    fn orientation_is_exact_at_the_range_limit() {
        let m = MAX_COORD;
        assert_eq!(
            orient(p(0, 0), p(m, m), p(m - 1, m - 1)),
            Orientation::Collinear
        );
        assert_eq!(
            orient(p(0, 0), p(m, m - 1), p(m - 1, m - 2)),
            Orientation::Clockwise
        );
        assert_eq!(
            orient(p(0, 0), p(m, 0), p(0, m)),
            Orientation::CounterClockwise
        );
        assert_eq!(cross(p(0, m), p(m, 0), p(m, m)), (m as i128) * (m as i128));
    }

    #[test]
    fn segment_contacts() {
        use SegmentContact::*;
        assert_eq!(segment_contact(p(0, 0), p(2, 2), p(0, 2), p(2, 0)), Cross);
        assert_eq!(segment_contact(p(0, 0), p(2, 2), p(1, 1), p(2, 0)), Touch);
        assert_eq!(segment_contact(p(0, 0), p(2, 0), p(2, 0), p(3, 1)), Touch);
        assert_eq!(segment_contact(p(0, 0), p(2, 0), p(1, 0), p(3, 0)), Overlap);
        assert_eq!(segment_contact(p(0, 0), p(2, 0), p(2, 0), p(3, 0)), Touch);
        assert_eq!(
            segment_contact(p(0, 0), p(2, 0), p(3, 0), p(4, 0)),
            Disjoint
        );
        assert_eq!(segment_contact(p(0, 0), p(0, 2), p(0, 1), p(0, 3)), Overlap);
        assert_eq!(
            segment_contact(p(0, 0), p(2, 2), p(3, 0), p(4, 1)),
            Disjoint
        );
        assert!(properly_cross(p(0, 0), p(2, 2), p(0, 2), p(2, 0)));
        assert!(!properly_cross(p(0, 0), p(2, 2), p(1, 1), p(2, 0)));
    }

    #[test]
    fn betweenness() {
        assert!(strictly_between(p(0, 0), p(1, 3), p(2, 6)));
        assert!(!strictly_between(p(0, 0), p(2, 6), p(2, 6)));
        assert!(!strictly_between(p(0, 0), p(3, 9), p(2, 6)));
        assert!(on_segment(p(0, 0), p(2, 6), p(2, 6)));
    }

    #[test]
    fn closed_wedges() {
        // Convex corner at the origin of a CCW square: interior is the first quadrant.
        let (prev, w, next) = (p(0, 1), p(0, 0), p(1, 0));
        assert!(in_closed_wedge(prev, w, next, p(1, 1)));
        assert!(
            in_closed_wedge(prev, w, next, p(5, 0)),
            "along an edge: closed"
        );
        assert!(in_closed_wedge(prev, w, next, p(0, 5)));
        assert!(!in_closed_wedge(prev, w, next, p(-1, 1)));
        assert!(!in_closed_wedge(prev, w, next, p(1, -1)));
        // Reflex corner (the same, traversed the other way): all but the open first quadrant.
        assert!(!in_closed_wedge(next, w, prev, p(1, 1)));
        assert!(in_closed_wedge(next, w, prev, p(5, 0)));
        assert!(in_closed_wedge(next, w, prev, p(-1, -1)));
        assert!(in_closed_wedge(next, w, prev, p(1, -1)));
        // Flat vertex going +x: the closed upper half-plane.
        let (prev, w, next) = (p(-1, 0), p(0, 0), p(1, 0));
        assert!(in_closed_wedge(prev, w, next, p(0, 1)));
        assert!(in_closed_wedge(prev, w, next, p(-3, 0)));
        assert!(!in_closed_wedge(prev, w, next, p(0, -1)));
    }

    #[test]
    fn angles_sort_counter_clockwise_from_the_x_axis() {
        let c = p(0, 0);
        let mut pts = [
            p(0, -1),
            p(1, 1),
            p(-1, 0),
            p(1, 0),
            p(0, 1),
            p(1, -1),
            p(2, 2),
        ];
        pts.sort_by(|&a, &b| cmp_angle(c, a, b));
        assert_eq!(pts[..4], [p(1, 0), p(1, 1), p(2, 2), p(0, 1)]);
        assert_eq!(pts[4..], [p(-1, 0), p(0, -1), p(1, -1)]);
        assert_eq!(cmp_angle(c, p(1, 1), p(2, 2)), Ordering::Equal);
    }

    #[test]
    fn angles_from_a_reference_direction() {
        let c = p(0, 0);
        let r = p(0, 1); // angle 0 points up
        let mut pts = [p(1, 0), p(-1, 0), p(0, 5), p(0, -1), p(-1, 1)];
        pts.sort_by(|&a, &b| cmp_angle_from(c, r, a, b));
        assert_eq!(pts, [p(0, 5), p(-1, 1), p(-1, 0), p(0, -1), p(1, 0)]);
        assert_eq!(cmp_angle_from(c, r, p(0, 1), p(0, 7)), Ordering::Equal);
    }

    #[test]
    fn wide_sums_do_not_overflow() {
        let mut s = WideSum::default();
        for _ in 0..4 {
            s.add(i128::MAX);
        }
        assert_eq!(s.signum(), 1);
        assert_eq!(s.value(), None);
        for _ in 0..4 {
            s.add(-i128::MAX);
        }
        assert_eq!(s.value(), Some(0));
        assert_eq!(s, WideSum::default());
    }
}
