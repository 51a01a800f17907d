//! The exact kernel: the only place that computes signs from coordinates.
//!
//! Two kernels implement [`Coord`], the predicates the algorithms use, and one is chosen per
//! polygon ([`crate::geom::polygon::AnyPolygon`]):
//! - [`Point`], the fast one: points on the polygon's integer grid with coordinates in
//!   `0..=MAX_COORD` (`2^62`), which [`crate::geom::polygon`] guarantees when it builds one. Every
//!   difference then fits an `i64` with room to spare, every product of two differences is below
//!   `2^124`, and every 2x2 determinant below `2^125`, so all predicates below are exact in
//!   `i128` and cannot overflow.
//! - [`crate::geom::wide::WidePoint`], for every other polygon the readers accept: the input
//!   decimals themselves, a floating-point filter and an exact big-integer fallback.
//!
//! Output guarantee: exact answers as named enums, booleans or signs; no epsilon anywhere. The one
//! exception, [`incircle_approx`], is named as such and serves speed heuristics only.
//! [`cross`] and [`dot`] return an `i128` whose SIGN is exact in both kernels; only the fast
//! kernel's value is the determinant itself (the wide kernel returns -1, 0 or 1), so magnitudes
//! are taken only through [`Area`] and [`Coord::cmp_dist`].
//! Complexity: O(1) each for the fast kernel; the wide kernel's exact fallback is linear in the
//! number of digits of its operands.

use std::cmp::Ordering;
use std::fmt;
use std::hash::Hash;

use super::polygon::Grid;

/// The largest grid coordinate; see the module documentation for why it keeps `i128` exact.
pub const MAX_COORD: i64 = 1 << 62;

/// A point type with exact predicates: the fast grid [`Point`] or the wide point.
///
/// Every method is exact except [`Coord::incircle_approx`] and the `f64` conversions, which
/// serve heuristics and drawing only.
pub trait Coord: Copy + Eq + Ord + Hash + fmt::Debug + Send + Sync + 'static {
    /// A direction, the difference of two points (`Dir` wraps it).
    type Vector: Copy + Eq + Hash + fmt::Debug + Send + Sync;
    /// The supporting line of a segment, as an exact, totally ordered key (`line_through`).
    type Line: Copy + Ord + fmt::Debug + Send + Sync;
    /// An exact sum of twice-areas (`Area` wraps it).
    type AreaSum: Clone + Default + PartialEq + fmt::Debug + fmt::Display + Send + Sync;

    /// A value with the sign of twice the signed area of `a b c` (positive when
    /// counter-clockwise); for [`Point`] that area itself.
    fn cross(a: Self, b: Self, c: Self) -> i128;
    /// A value with the sign of the dot product of `b - a` and `c - a`; for [`Point`] that
    /// product itself.
    fn dot(a: Self, b: Self, c: Self) -> i128;
    /// The vector from `from` to `to`.
    fn vector(from: Self, to: Self) -> Self::Vector;
    /// The opposite vector.
    fn reversed(v: Self::Vector) -> Self::Vector;
    /// A value with the sign of the cross product `u x v`.
    fn vector_cross(u: Self::Vector, v: Self::Vector) -> i128;
    /// A value with the sign of the dot product of `u` and `v`.
    fn vector_dot(u: Self::Vector, v: Self::Vector) -> i128;
    /// The sign of the x component of `v`: rightwards, vertical or leftwards.
    fn vector_cmp_x(v: Self::Vector) -> Ordering;
    /// The line through distinct points `p` and `q`, and whether `p -> q` runs in its direction
    /// (the direction along which points increase in the order of `Self`).
    fn line_through(p: Self, q: Self) -> (Self::Line, bool);
    /// Adds twice the signed area of `a b c` to `sum`, exactly.
    fn add_area(sum: &mut Self::AreaSum, a: Self, b: Self, c: Self);
    /// The sign of a sum of areas.
    fn area_signum(sum: &Self::AreaSum) -> i32;
    /// Compares the x coordinates.
    fn cmp_x(a: Self, b: Self) -> Ordering;
    /// Compares the y coordinates.
    fn cmp_y(a: Self, b: Self) -> Ordering;
    /// Compares the distances from `c` to `p` and to `q`.
    fn cmp_dist(c: Self, p: Self, q: Self) -> Ordering;
    /// The point with the x coordinate of `x_of` and the y coordinate of `y_of`.
    fn corner(x_of: Self, y_of: Self) -> Self;
    /// The point turned a quarter-turn counter-clockwise (`(x, y) -> (c - y, x)` for some
    /// constant `c`): exact, every orientation kept.
    fn quarter_turn(self) -> Self;
    /// `self - origin`, rounded to `f64`, in the units of the polygon's grid (drawing and
    /// heuristics only).
    fn offset_f64(self, origin: Self) -> [f64; 2];
    /// This point on a grid for drawing only: for [`Point`] itself; for the wide kernel
    /// `(self - origin) * scale` rounded, in units of `10^shift` input units (see
    /// [`crate::geom::polygon::Polygon::drawing_point`]).
    fn drawing_point(self, origin: Self, scale: f64, shift: i32) -> Point;
    /// The decimal order of magnitude of the larger coordinate, from the exact value
    /// (`floor(log10(max(|x|, |y|)))`; `i32::MIN` for the origin; 0 for the fast grid, whose
    /// offsets always fit `f64`).
    fn magnitude(self) -> i32 {
        0
    }
    /// [`Coord::offset_f64`] in units of `10^shift` input units, computed from the exact values:
    /// finite even where the coordinates themselves are beyond the range of `f64`.
    fn offset_f64_shifted(self, origin: Self, shift: i32) -> [f64; 2] {
        let _ = shift;
        self.offset_f64(origin)
    }
    /// APPROXIMATELY the in-circle determinant of `incircle_approx`.
    fn incircle_approx(a: Self, b: Self, c: Self, d: Self) -> f64;
    /// Coordinate `axis` (0 = x, 1 = y) in input coordinates, exactly, as text.
    fn format(self, grid: &Grid, axis: usize) -> String;
    /// The input coordinates, rounded to `f64` (for drawing only).
    fn to_f64(self, grid: &Grid) -> [f64; 2];
}

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

/// The fast kernel's vector: both components within `±MAX_COORD`, so cross and dot products of
/// two vectors are exact in `i128`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Vector {
    /// x component.
    pub x: i64,
    /// y component.
    pub y: i64,
}

impl Coord for Point {
    type Vector = Vector;
    type Line = Line;
    type AreaSum = WideSum;

    #[inline]
    fn cross(a: Point, b: Point, c: Point) -> i128 {
        let (ux, uy) = (i128::from(b.x - a.x), i128::from(b.y - a.y));
        let (vx, vy) = (i128::from(c.x - a.x), i128::from(c.y - a.y));
        ux * vy - uy * vx
    }

    #[inline]
    fn dot(a: Point, b: Point, c: Point) -> i128 {
        let (ux, uy) = (i128::from(b.x - a.x), i128::from(b.y - a.y));
        let (vx, vy) = (i128::from(c.x - a.x), i128::from(c.y - a.y));
        ux * vx + uy * vy
    }

    #[inline]
    fn vector(from: Point, to: Point) -> Vector {
        Vector {
            x: to.x - from.x,
            y: to.y - from.y,
        }
    }

    #[inline]
    fn reversed(v: Vector) -> Vector {
        Vector { x: -v.x, y: -v.y }
    }

    #[inline]
    fn vector_cross(u: Vector, v: Vector) -> i128 {
        i128::from(u.x) * i128::from(v.y) - i128::from(u.y) * i128::from(v.x)
    }

    #[inline]
    fn vector_dot(u: Vector, v: Vector) -> i128 {
        i128::from(u.x) * i128::from(v.x) + i128::from(u.y) * i128::from(v.y)
    }

    #[inline]
    fn vector_cmp_x(v: Vector) -> Ordering {
        v.x.cmp(&0)
    }

    /// Exact: differences are at most `2^62` and products below `2^124` (kernel contract).
    fn line_through(p: Point, q: Point) -> (Line, bool) {
        let (dx, dy) = (q.x - p.x, q.y - p.y);
        // At least 1 for distinct points, at most 2^62: fits i64.
        let g = gcd(dx.unsigned_abs(), dy.unsigned_abs()).max(1) as i64;
        let (dx, dy) = (dx / g, dy / g);
        let forward = dx > 0 || (dx == 0 && dy > 0);
        let (dx, dy) = if forward { (dx, dy) } else { (-dx, -dy) };
        let c = i128::from(dy) * i128::from(p.x) - i128::from(dx) * i128::from(p.y);
        (Line { dx, dy, c }, forward)
    }

    #[inline]
    fn add_area(sum: &mut WideSum, a: Point, b: Point, c: Point) {
        sum.add(Point::cross(a, b, c));
    }

    fn area_signum(sum: &WideSum) -> i32 {
        sum.signum()
    }

    #[inline]
    fn cmp_x(a: Point, b: Point) -> Ordering {
        a.x.cmp(&b.x)
    }

    #[inline]
    fn cmp_y(a: Point, b: Point) -> Ordering {
        a.y.cmp(&b.y)
    }

    #[inline]
    fn cmp_dist(c: Point, p: Point, q: Point) -> Ordering {
        Point::dot(c, p, p).cmp(&Point::dot(c, q, q))
    }

    fn corner(x_of: Point, y_of: Point) -> Point {
        Point::new(x_of.x, y_of.y)
    }

    fn quarter_turn(self) -> Point {
        Point::new(MAX_COORD - self.y, self.x)
    }

    fn offset_f64(self, origin: Point) -> [f64; 2] {
        // Grid coordinates lie in 0..=2^62, so these differences cannot overflow.
        [(self.x - origin.x) as f64, (self.y - origin.y) as f64]
    }

    fn drawing_point(self, _origin: Point, _scale: f64, _shift: i32) -> Point {
        self
    }

    fn incircle_approx(a: Point, b: Point, c: Point, d: Point) -> f64 {
        let rel = |p: Point| ((p.x - d.x) as f64, (p.y - d.y) as f64);
        let ((ax, ay), (bx, by), (cx, cy)) = (rel(a), rel(b), rel(c));
        (ax * ax + ay * ay) * (bx * cy - cx * by)
            + (bx * bx + by * by) * (cx * ay - ax * cy)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)
    }

    fn format(self, grid: &Grid, axis: usize) -> String {
        grid.format(axis, [self.x, self.y][axis])
    }

    fn to_f64(self, grid: &Grid) -> [f64; 2] {
        grid.grid_to_f64(self)
    }
}

/// Twice the signed area of triangle `a b c` (positive when counter-clockwise), exact for
/// [`Point`]; for the wide kernel only its sign (see the module documentation).
#[inline]
pub fn cross<P: Coord>(a: P, b: P, c: P) -> i128 {
    P::cross(a, b, c)
}

/// The dot product of `b - a` and `c - a`, exact for [`Point`]; for the wide kernel only its
/// sign.
#[inline]
pub fn dot<P: Coord>(a: P, b: P, c: P) -> i128 {
    P::dot(a, b, c)
}

/// The orientation of `a b c`.
#[inline]
pub fn orient<P: Coord>(a: P, b: P, c: P) -> Orientation {
    match cross(a, b, c).cmp(&0) {
        Ordering::Greater => Orientation::CounterClockwise,
        Ordering::Less => Orientation::Clockwise,
        Ordering::Equal => Orientation::Collinear,
    }
}

/// Whether `p` lies strictly between `a` and `c` on segment `a c` (`a != c`).
#[inline]
pub fn strictly_between<P: Coord>(a: P, p: P, c: P) -> bool {
    cross(a, c, p) == 0 && dot(p, a, c) < 0
}

/// Whether `p` lies on the closed segment `a b`.
#[inline]
pub fn on_segment<P: Coord>(a: P, b: P, p: P) -> bool {
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
pub fn segment_contact<P: Coord>(a: P, b: P, c: P, d: P) -> SegmentContact {
    let (o1, o2) = (cross(a, b, c), cross(a, b, d));
    let (o3, o4) = (cross(c, d, a), cross(c, d, b));
    if o1 == 0 && o2 == 0 {
        // Collinear: compare the spans along the line, where the order of points (x first, then
        // y) is the position along it.
        let (lo1, hi1) = (a.min(b), a.max(b));
        let (lo2, hi2) = (c.min(d), c.max(d));
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
pub fn properly_cross<P: Coord>(a: P, b: P, c: P, d: P) -> bool {
    let (o1, o2) = (cross(a, b, c), cross(a, b, d));
    let (o3, o4) = (cross(c, d, a), cross(c, d, b));
    o1.signum() * o2.signum() < 0 && o3.signum() * o4.signum() < 0
}

/// Whether the direction from `w` towards `target` lies in the CLOSED interior angle at vertex `w`,
/// whose boundary neighbours are `prev` and `next`, with the interior on the left of
/// `prev -> w -> next` (counter-clockwise outer ring, clockwise holes).
///
/// The interior angle sweeps counter-clockwise from the direction of `next` to that of `prev`.
/// A flat vertex (`prev`, `w`, `next` collinear, `prev` and `next` on opposite sides) has the
/// closed half-plane on the left as its angle. A spike (`prev` and `next` on the same side) has an
/// empty interior angle apart from its two edge directions; validation rejects spikes anyway.
pub fn in_closed_wedge<P: Coord>(prev: P, w: P, next: P, target: P) -> bool {
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

/// Whether `p` lies in the upper half-plane around `centre`, angles `[0, pi)`: above it, or at
/// its height and to its right.
#[inline]
pub fn above<P: Coord>(centre: P, p: P) -> bool {
    match P::cmp_y(p, centre) {
        Ordering::Greater => true,
        Ordering::Less => false,
        Ordering::Equal => P::cmp_x(p, centre) == Ordering::Greater,
    }
}

/// Total order of directions around a centre, starting at the positive x axis and turning
/// counter-clockwise; equal for directions on the same ray. `a` and `b` must differ from `centre`.
pub fn cmp_angle<P: Coord>(centre: P, a: P, b: P) -> Ordering {
    let half = |p: P| if above(centre, p) { 0 } else { 1 };
    half(a)
        .cmp(&half(b))
        .then_with(|| 0.cmp(&cross(centre, a, b)))
}

/// Total order of directions around a centre by counter-clockwise angle measured from the
/// direction towards `reference` (angle 0); equal for directions on the same ray. All points
/// must differ from `centre`.
pub fn cmp_angle_from<P: Coord>(centre: P, reference: P, a: P, b: P) -> Ordering {
    let half = |p: P| {
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

/// A direction: the difference of two points, or its negation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Dir<P: Coord = Point>(P::Vector);

impl<P: Coord> Dir<P> {
    /// The direction from `from` to `to`.
    #[inline]
    pub fn between(from: P, to: P) -> Dir<P> {
        Dir(P::vector(from, to))
    }

    /// The opposite direction.
    #[inline]
    pub fn reversed(self) -> Dir<P> {
        Dir(P::reversed(self.0))
    }

    /// The cross product `self x other` (positive when `other` turns counter-clockwise); exact
    /// for [`Point`], only its sign for the wide kernel.
    #[inline]
    pub fn cross(self, other: Dir<P>) -> i128 {
        P::vector_cross(self.0, other.0)
    }

    /// The dot product (exact for [`Point`], only its sign for the wide kernel).
    #[inline]
    pub fn dot(self, other: Dir<P>) -> i128 {
        P::vector_dot(self.0, other.0)
    }

    /// The sign of the x component: `Greater` rightwards, `Equal` vertical, `Less` leftwards.
    #[inline]
    pub fn cmp_x(self) -> Ordering {
        P::vector_cmp_x(self.0)
    }

    /// Total order of directions by counter-clockwise angle measured from `self` (angle 0, up
    /// to but excluding a full turn): [`cmp_angle_from`] for directions.
    pub fn cmp_angle_from(self, a: Dir<P>, b: Dir<P>) -> Ordering {
        let half = |d: Dir<P>| {
            let s = self.cross(d);
            u8::from(!(s > 0 || (s == 0 && self.dot(d) > 0)))
        };
        half(a).cmp(&half(b)).then_with(|| 0.cmp(&a.cross(b)))
    }
}

/// APPROXIMATELY whether `d` lies inside the circle through the counter-clockwise triangle
/// `a b c`: positive inside, negative outside, computed in floating point and so possibly wrong
/// (even in sign) when `d` is near the circle.
///
/// The one inexact predicate of the kernel, for heuristics only: it may steer how fast an
/// algorithm runs (which diagonals to flip to fatten triangles), never a geometric fact of an
/// answer. The exact determinant would need about 250 bits.
#[inline]
pub fn incircle_approx<P: Coord>(a: P, b: P, c: P, d: P) -> f64 {
    P::incircle_approx(a, b, c, d)
}

/// An exact sum of twice-areas of triangles, immune to overflow in both kernels.
#[derive(Clone, Debug, PartialEq)]
pub struct Area<P: Coord = Point>(P::AreaSum);

impl<P: Coord> Default for Area<P> {
    fn default() -> Self {
        Area(P::AreaSum::default())
    }
}

impl<P: Coord> Area<P> {
    /// Adds twice the signed area of `a b c`, exactly.
    #[inline]
    pub fn add(&mut self, a: P, b: P, c: P) {
        P::add_area(&mut self.0, a, b, c);
    }

    /// The sign of the sum.
    pub fn signum(&self) -> i32 {
        P::area_signum(&self.0)
    }
}

impl Area<Point> {
    /// The sum, when it fits an `i128`.
    pub fn value(&self) -> Option<i128> {
        self.0.value()
    }
}

impl<P: Coord> fmt::Display for Area<P> {
    /// The exact sum (in units of the grid), or about it when it is long.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
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
    pub fn to_f64(self) -> f64 {
        self.high as f64 * 2f64.powi(128) + self.low as f64
    }
}

impl fmt::Display for WideSum {
    /// The exact value when it fits an `i128`, else about it.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.value() {
            Some(v) => write!(f, "{v}"),
            None => write!(f, "about {:e}", self.to_f64()),
        }
    }
}

/// The fast kernel's supporting line of a segment, as an exact key: the primitive direction
/// `(dx, dy)`, with `dx > 0` or `dx == 0 < dy`, and the offset `c = dy x - dx y` of any point on
/// it.
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

/// The line through distinct points `p` and `q`, and whether `p -> q` runs in its direction.
#[inline]
pub fn line_through<P: Coord>(p: P, q: P) -> (P::Line, bool) {
    P::line_through(p, q)
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
