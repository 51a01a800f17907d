//! The wide exact kernel: points whose coordinates are the input decimals themselves, for the
//! polygons whose grid does not fit the fast kernel's `2^62` units (see [`crate::geom::kernel`]).
//!
//! Input contract: any [`Decimal`]s the readers accept (at most 38 significant digits, decimal
//! exponents within ±1000). Output guarantee: every predicate of [`Coord`] exact, as for
//! [`crate::geom::kernel::Point`]; `cross` and `dot` return only the sign (-1, 0 or 1).
//!
//! Each sign is first taken from a floating-point filter: the coordinates rounded to `f64` (a
//! relative error of at most u = 2^-53 each, for magnitudes within 10^±140) and the determinant
//! evaluated in `f64`, whose error is then below `6u (|a|+|b|)(|c|+|d|) + ...` (each difference
//! carries the rounding of its two inputs and its own, each product and the final difference one
//! more); the filter trusts the sign when the value exceeds `8u` times that sum, plus `1e-300` for
//! underflow. Otherwise (nearly or exactly degenerate inputs, or magnitudes outside 10^±140) the
//! sign is computed exactly: the decimals put on their finest common power of ten, in `i128` when
//! every one then fits `2^62`, else in big integers (`num-bigint`).
//! Complexity: O(1) for a filtered sign; the exact fallback is at worst quadratic in the number of
//! digits (about 2,000 decimal digits for the widest inputs).

use super::decimal::Decimal;
use super::kernel::{Coord, Point, MAX_COORD};
use super::polygon::Grid;
use num_bigint::BigInt;
use std::cmp::Ordering;
use std::fmt;
use std::hash::{Hash, Hasher};

/// A point with exact decimal coordinates and their `f64` roundings (for the filter).
#[derive(Clone, Copy, Debug)]
pub struct WidePoint {
    x: Decimal,
    y: Decimal,
    approx: [f64; 2],
    /// Whether both coordinates are zero or of magnitude within `10^±140`, where the rounding
    /// to `f64` has relative error at most `2^-53` and no product overflows.
    filtered: bool,
}

/// Magnitudes within `10^±FILTER_POWER` go through the filter.
const FILTER_POWER: i64 = 140;

/// `8u`, `u = 2^-53`: the filter's relative error bound (see the module documentation).
const FILTER_FACTOR: f64 = 4.0 * f64::EPSILON;

/// Absolute slack for products that underflow below the smallest normal `f64`.
const FILTER_FLOOR: f64 = 1e-300;

impl WidePoint {
    /// The point `(x, y)`, exactly.
    pub fn new(x: Decimal, y: Decimal) -> WidePoint {
        let in_range = |d: &Decimal| {
            let (_, mantissa) = d.parts();
            mantissa == 0 || {
                let power = i64::from(d.exponent()) + i64::from(mantissa.ilog10());
                (-FILTER_POWER..=FILTER_POWER).contains(&power)
            }
        };
        WidePoint {
            x,
            y,
            approx: [x.to_f64(), y.to_f64()],
            filtered: in_range(&x) && in_range(&y),
        }
    }

    /// The x coordinate.
    pub fn x(&self) -> Decimal {
        self.x
    }

    /// The y coordinate.
    pub fn y(&self) -> Decimal {
        self.y
    }
}

impl PartialEq for WidePoint {
    fn eq(&self, other: &WidePoint) -> bool {
        // Decimals are normalised: equal values have equal representations.
        self.x == other.x && self.y == other.y
    }
}

impl Eq for WidePoint {}

impl Hash for WidePoint {
    fn hash<H: Hasher>(&self, state: &mut H) {
        self.x.hash(state);
        self.y.hash(state);
    }
}

impl Ord for WidePoint {
    /// x first, then y, as [`crate::geom::kernel::Point`].
    fn cmp(&self, other: &WidePoint) -> Ordering {
        self.x.cmp(&other.x).then_with(|| self.y.cmp(&other.y))
    }
}

impl PartialOrd for WidePoint {
    fn partial_cmp(&self, other: &WidePoint) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// A wide direction: from one point to another.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct WideVector {
    from: WidePoint,
    to: WidePoint,
}

/// The sign of `u x v` (`dot`: of `u . v`), exactly: the filter, then the exact fallback.
fn sign(u: WideVector, v: WideVector, dot: bool) -> i128 {
    if let Some(s) = filtered_sign(u, v, dot) {
        return s;
    }
    let coords = [
        u.from.x, u.from.y, u.to.x, u.to.y, v.from.x, v.from.y, v.to.x, v.to.y,
    ];
    let value = |[ax, ay, bx, by, cx, cy, dx, dy]: [Num; 8]| {
        let (ux, uy, vx, vy) = (bx - ax, by - ay, dx - cx, dy - cy);
        if dot {
            ux * vx + uy * vy
        } else {
            ux * vy - uy * vx
        }
    };
    exact(&coords, value)
}

/// The filter's sign of `u x v` (or `u . v`), or `None` when it cannot be sure.
#[inline]
fn filtered_sign(u: WideVector, v: WideVector, dot: bool) -> Option<i128> {
    if !(u.from.filtered && u.to.filtered && v.from.filtered && v.to.filtered) {
        return None;
    }
    let ([ax, ay], [bx, by]) = (u.from.approx, u.to.approx);
    let ([cx, cy], [dx, dy]) = (v.from.approx, v.to.approx);
    let (ux, uy, vx, vy) = (bx - ax, by - ay, dx - cx, dy - cy);
    let (sux, suy) = (ax.abs() + bx.abs(), ay.abs() + by.abs());
    let (svx, svy) = (cx.abs() + dx.abs(), cy.abs() + dy.abs());
    let (value, size) = if dot {
        (ux * vx + uy * vy, sux * svx + suy * svy)
    } else {
        (ux * vy - uy * vx, sux * svy + suy * svx)
    };
    let bound = FILTER_FACTOR * size + FILTER_FLOOR;
    if value > bound {
        Some(1)
    } else if value < -bound {
        Some(-1)
    } else {
        None
    }
}

/// An exact integer for the fallback: `i128` when small enough, else a big integer.
///
/// The fallback evaluates one polynomial of degree 2 in the coordinates; written once over this
/// type, it runs in `i128` when every coordinate fits `2^62` on the common power of ten (then no
/// product of two differences overflows), else in `BigInt`.
#[derive(Clone, Debug)]
enum Num {
    Small(i128),
    Big(BigInt),
}

impl Num {
    fn big(self) -> BigInt {
        match self {
            Num::Small(v) => BigInt::from(v),
            Num::Big(v) => v,
        }
    }

    fn signum(&self) -> i128 {
        match self {
            Num::Small(v) => v.signum(),
            Num::Big(v) => match v.sign() {
                num_bigint::Sign::Minus => -1,
                num_bigint::Sign::NoSign => 0,
                num_bigint::Sign::Plus => 1,
            },
        }
    }
}

macro_rules! num_op {
    ($trait:ident, $method:ident, $checked:ident) => {
        impl std::ops::$trait for Num {
            type Output = Num;
            fn $method(self, other: Num) -> Num {
                match (self, other) {
                    (Num::Small(a), Num::Small(b)) => match a.$checked(b) {
                        Some(v) => Num::Small(v),
                        None => Num::Big(BigInt::from(a).$method(BigInt::from(b))),
                    },
                    (a, b) => Num::Big(a.big().$method(b.big())),
                }
            }
        }
    };
}
num_op!(Add, add, checked_add);
num_op!(Sub, sub, checked_sub);
num_op!(Mul, mul, checked_mul);

/// The decimals as exact integers on their finest common power of ten, and that power.
fn on_common_grid<const N: usize>(coords: &[Decimal; N]) -> ([Num; N], i32) {
    let exponent = coords
        .iter()
        .filter(|d| d.parts().1 != 0)
        .map(Decimal::exponent)
        .min()
        .unwrap_or(0);
    const LIMIT: i128 = 1 << 62;
    let mut small = [0i128; N];
    let fits = coords.iter().zip(&mut small).all(|(d, slot)| {
        d.scaled(-exponent)
            .filter(|v| v.abs() < LIMIT)
            .map(|v| *slot = v)
            .is_some()
    });
    let values = match fits {
        true => small.map(Num::Small),
        false => std::array::from_fn(|k| {
            let d = coords[k];
            let (negative, mantissa) = d.parts();
            let shift = (d.exponent() - exponent) as u32;
            let magnitude = if mantissa == 0 {
                BigInt::from(0)
            } else {
                BigInt::from(mantissa) * BigInt::from(10).pow(shift)
            };
            Num::Big(if negative { -magnitude } else { magnitude })
        }),
    };
    (values, exponent)
}

/// The sign of `value(coords)` computed exactly.
fn exact<const N: usize>(coords: &[Decimal; N], value: impl Fn([Num; N]) -> Num) -> i128 {
    value(on_common_grid(coords).0).signum()
}

/// The wide kernel's supporting line of a segment: two of its points, `p < q`.
///
/// Ordered by direction (counter-clockwise angle within the half-plane of directions that point
/// to larger points), then, for parallel lines, by side; equal exactly for the same line.
#[derive(Clone, Copy, Debug)]
pub struct WideLine {
    p: WidePoint,
    q: WidePoint,
}

impl Ord for WideLine {
    fn cmp(&self, other: &WideLine) -> Ordering {
        let (d, e) = (
            WidePoint::vector(self.p, self.q),
            WidePoint::vector(other.p, other.q),
        );
        // Both directions lie in one open half-plane plus one ray: the cross product orders them.
        0.cmp(&WidePoint::vector_cross(d, e))
            .then_with(|| 0.cmp(&WidePoint::cross(self.p, self.q, other.p)))
    }
}

impl PartialOrd for WideLine {
    fn partial_cmp(&self, other: &WideLine) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for WideLine {
    fn eq(&self, other: &WideLine) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for WideLine {}

/// An exact sum of twice-areas: `value × 10^exponent`.
#[derive(Clone, Debug, Default)]
pub struct WideArea {
    value: BigInt,
    exponent: i32,
}

impl WideArea {
    fn add(&mut self, value: BigInt, exponent: i32) {
        use num_bigint::Sign::NoSign;
        if self.value.sign() == NoSign {
            (self.value, self.exponent) = (value, exponent);
        } else if exponent >= self.exponent {
            self.value += value * BigInt::from(10).pow((exponent - self.exponent) as u32);
        } else {
            let shift = BigInt::from(10).pow((self.exponent - exponent) as u32);
            self.value = std::mem::take(&mut self.value) * shift + value;
            self.exponent = exponent;
        }
    }

    /// Both values on the finer power of ten.
    fn aligned(&self, other: &WideArea) -> (BigInt, BigInt) {
        let e = self.exponent.min(other.exponent);
        let scale = |a: &WideArea| &a.value * BigInt::from(10).pow((a.exponent - e) as u32);
        (scale(self), scale(other))
    }
}

impl PartialEq for WideArea {
    fn eq(&self, other: &WideArea) -> bool {
        let (a, b) = self.aligned(other);
        a == b
    }
}

impl fmt::Display for WideArea {
    /// The exact value, `digits` or `digits e exponent`, without trailing zeros.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let digits = self.value.to_string();
        let trimmed = digits.trim_end_matches('0');
        let (digits, exponent) = match trimmed {
            "" | "-" => ("0", 0),
            t => (t, self.exponent + (digits.len() - t.len()) as i32),
        };
        if exponent == 0 {
            write!(f, "{digits}")
        } else {
            write!(f, "{digits}e{exponent}")
        }
    }
}

impl Coord for WidePoint {
    type Vector = WideVector;
    type Line = WideLine;
    type AreaSum = WideArea;

    fn cross(a: WidePoint, b: WidePoint, c: WidePoint) -> i128 {
        sign(
            WideVector { from: a, to: b },
            WideVector { from: a, to: c },
            false,
        )
    }

    fn dot(a: WidePoint, b: WidePoint, c: WidePoint) -> i128 {
        sign(
            WideVector { from: a, to: b },
            WideVector { from: a, to: c },
            true,
        )
    }

    fn vector(from: WidePoint, to: WidePoint) -> WideVector {
        WideVector { from, to }
    }

    fn reversed(v: WideVector) -> WideVector {
        WideVector {
            from: v.to,
            to: v.from,
        }
    }

    fn vector_cross(u: WideVector, v: WideVector) -> i128 {
        sign(u, v, false)
    }

    fn vector_dot(u: WideVector, v: WideVector) -> i128 {
        sign(u, v, true)
    }

    fn vector_cmp_x(v: WideVector) -> Ordering {
        v.to.x.cmp(&v.from.x)
    }

    fn line_through(p: WidePoint, q: WidePoint) -> (WideLine, bool) {
        if p < q {
            (WideLine { p, q }, true)
        } else {
            (WideLine { p: q, q: p }, false)
        }
    }

    fn add_area(sum: &mut WideArea, a: WidePoint, b: WidePoint, c: WidePoint) {
        let (values, exponent) = on_common_grid(&[a.x, a.y, b.x, b.y, c.x, c.y]);
        let [ax, ay, bx, by, cx, cy] = values;
        let value = (bx - ax.clone()) * (cy - ay.clone()) - (by - ay) * (cx - ax);
        sum.add(value.big(), 2 * exponent);
    }

    fn area_signum(sum: &WideArea) -> i32 {
        match sum.value.sign() {
            num_bigint::Sign::Minus => -1,
            num_bigint::Sign::NoSign => 0,
            num_bigint::Sign::Plus => 1,
        }
    }

    fn cmp_x(a: WidePoint, b: WidePoint) -> Ordering {
        a.x.cmp(&b.x)
    }

    fn cmp_y(a: WidePoint, b: WidePoint) -> Ordering {
        a.y.cmp(&b.y)
    }

    fn cmp_dist(c: WidePoint, p: WidePoint, q: WidePoint) -> Ordering {
        let coords = [c.x, c.y, p.x, p.y, q.x, q.y];
        let s = exact(&coords, |[cx, cy, px, py, qx, qy]| {
            let (a, b) = (px - cx.clone(), py - cy.clone());
            let (d, e) = (qx - cx, qy - cy);
            a.clone() * a + b.clone() * b - (d.clone() * d + e.clone() * e)
        });
        s.cmp(&0)
    }

    fn corner(x_of: WidePoint, y_of: WidePoint) -> WidePoint {
        WidePoint::new(x_of.x, y_of.y)
    }

    fn quarter_turn(self) -> WidePoint {
        WidePoint::new(self.y.negated(), self.x)
    }

    fn offset_f64(self, origin: WidePoint) -> [f64; 2] {
        [
            self.approx[0] - origin.approx[0],
            self.approx[1] - origin.approx[1],
        ]
    }

    fn drawing_point(self, origin: WidePoint, scale: f64, shift: i32) -> Point {
        // Rounded and clamped into the fast grid's range (`as` saturates; NaN becomes 0).
        let offset = self.offset_f64_shifted(origin, shift);
        let [x, y] = offset.map(|v| (v * scale).round() as i64);
        Point::new(x.clamp(0, MAX_COORD), y.clamp(0, MAX_COORD))
    }

    fn incircle_approx(a: WidePoint, b: WidePoint, c: WidePoint, d: WidePoint) -> f64 {
        let rel = |p: WidePoint| (p.approx[0] - d.approx[0], p.approx[1] - d.approx[1]);
        let ((ax, ay), (bx, by), (cx, cy)) = (rel(a), rel(b), rel(c));
        (ax * ax + ay * ay) * (bx * cy - cx * by)
            + (bx * bx + by * by) * (cx * ay - ax * cy)
            + (cx * cx + cy * cy) * (ax * by - bx * ay)
    }

    fn magnitude(self) -> i32 {
        self.x.magnitude().max(self.y.magnitude())
    }

    fn offset_f64_shifted(self, origin: WidePoint, shift: i32) -> [f64; 2] {
        if shift == 0 {
            return self.offset_f64(origin);
        }
        [
            self.x.shifted_f64(shift) - origin.x.shifted_f64(shift),
            self.y.shifted_f64(shift) - origin.y.shifted_f64(shift),
        ]
    }

    fn format(self, _grid: &Grid, axis: usize) -> String {
        [self.x, self.y][axis].to_string()
    }

    fn to_f64(self, _grid: &Grid) -> [f64; 2] {
        self.approx
    }
}

#[cfg(test)]
mod tests;
