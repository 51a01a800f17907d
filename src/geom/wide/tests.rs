use super::*;
use crate::geom::kernel::{cmp_angle, cross, dot, line_through, orient, Area};
use num_bigint::BigInt;

/// A small deterministic generator (xorshift64*).
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.next() % (hi - lo + 1) as u64) as i64
    }
}

fn dec(text: &str) -> Decimal {
    Decimal::parse(text).unwrap()
}

/// `value × 10^exponent` as a decimal.
fn scaled(value: i128, exponent: i32) -> Decimal {
    dec(&format!("{value}e{exponent}"))
}

/// Random small integer points, a third of the triples made collinear (the exact fallback).
fn triple(rng: &mut Rng) -> [(i64, i64); 3] {
    let mut p = || (rng.int(-1000, 1000), rng.int(-1000, 1000));
    let (a, b, mut c) = (p(), p(), p());
    if c.0 % 3 == 0 {
        let t = c.1 % 4;
        c = (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
    }
    [a, b, c]
}

/// The wide kernel agrees with the fast one on copies moved to grids the fast one cannot hold:
/// scaled by `10^k` and `10^e` (e from -400 to 400, beyond the filter's range) and shifted.
#[test]
fn predicates_match_the_fast_kernel_on_scaled_and_shifted_copies() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    for round in 0..20_000 {
        let pts = triple(&mut rng);
        let k = rng.int(0, 18) as u32;
        let e = rng.int(-400, 400) as i32;
        let shift = [rng.int(-1 << 40, 1 << 40), rng.int(-1 << 40, 1 << 40)]
            .map(|s| i128::from(s) * 10i128.pow(k.min(12)));
        let fast = pts.map(|(x, y)| Point::new(x, y));
        let wide = pts.map(|(x, y)| {
            let m = 10i128.pow(k);
            WidePoint::new(
                scaled(i128::from(x) * m + shift[0], e),
                scaled(i128::from(y) * m + shift[1], e),
            )
        });
        let [a, b, c] = wide;
        let [fa, fb, fc] = fast;
        let context = format!("round {round}: {pts:?} k {k} e {e}");
        assert_eq!(orient(a, b, c), orient(fa, fb, fc), "{context}");
        assert_eq!(dot(a, b, c).signum(), dot(fa, fb, fc).signum(), "{context}");
        assert_eq!(a.cmp(&b), fa.cmp(&fb), "{context}");
        assert_eq!(
            WidePoint::vector_cmp_x(WidePoint::vector(a, b)),
            Point::vector_cmp_x(Point::vector(fa, fb)),
            "{context}"
        );
        if a != b && a != c {
            assert_eq!(cmp_angle(a, b, c), cmp_angle(fa, fb, fc), "{context}");
            assert_eq!(
                WidePoint::cmp_dist(a, b, c),
                Point::cmp_dist(fa, fb, fc),
                "{context}"
            );
        }
        if a != b && b != c {
            let (l, m) = (line_through(a, b), line_through(b, c));
            let (fl, fm) = (line_through(fa, fb), line_through(fb, fc));
            assert_eq!(l.1, fl.1, "{context}");
            assert_eq!(l.0 == m.0, fl.0 == fm.0, "{context}");
        }
        let mut area = Area::default();
        area.add(a, b, c);
        assert_eq!(
            area.signum(),
            Point::cross(fa, fb, fc).signum() as i32,
            "{context}"
        );
    }
}

/// `value` exactly as `numerator / 10^places`, by reading the decimal's text (independent of
/// the kernel's common grid).
fn rational(d: Decimal, places: u32) -> BigInt {
    let text = d.to_string();
    let (int, frac) = text.split_once('.').unwrap_or((&text, ""));
    assert!(frac.len() as u32 <= places);
    let digits = format!("{int}{frac}{}", "0".repeat(places as usize - frac.len()));
    digits.parse().unwrap()
}

/// The orientation of points with unrelated exponents (shortest round-trip doubles of every
/// size, `1.2345678901234567e-5` beside `179.99999999999997`) against exact rational arithmetic.
#[test]
fn orientation_matches_exact_rationals_with_mixed_exponents() {
    let mut rng = Rng(42);
    let mut collinear = 0;
    for round in 0..5_000 {
        let coordinate = |rng: &mut Rng| -> Decimal {
            let magnitude = 10f64.powi(rng.int(-8, 2) as i32);
            let v = (rng.next() as f64 / u64::MAX as f64 - 0.5) * 2.0 * magnitude;
            dec(&format!("{v:e}"))
        };
        let mut pts: Vec<[Decimal; 2]> = (0..3)
            .map(|_| [coordinate(&mut rng), coordinate(&mut rng)])
            .collect();
        if round % 4 == 0 {
            // Exactly collinear: c = a + 2 (b - a) written out exactly.
            let third = |a: Decimal, b: Decimal| {
                let places = 40;
                let (ra, rb) = (rational(a, places), rational(b, places));
                let mut v: BigInt = ra.clone() + (rb - ra) * 2;
                let mut exponent = -(places as i32);
                while v != BigInt::from(0) && (&v % 10u32) == BigInt::from(0) {
                    v /= 10u32;
                    exponent += 1;
                }
                dec(&format!("{v}e{exponent}"))
            };
            pts[2] = [third(pts[0][0], pts[1][0]), third(pts[0][1], pts[1][1])];
            collinear += 1;
        }
        if round == 1 {
            pts[0] = [dec("1.2345678901234567e-5"), dec("179.99999999999997")];
        }
        let places = 40;
        let r: Vec<[BigInt; 2]> = pts
            .iter()
            .map(|p| [rational(p[0], places), rational(p[1], places)])
            .collect();
        let det = (r[1][0].clone() - &r[0][0]) * (r[2][1].clone() - &r[0][1])
            - (r[1][1].clone() - &r[0][1]) * (r[2][0].clone() - &r[0][0]);
        let want = match det.sign() {
            num_bigint::Sign::Minus => -1,
            num_bigint::Sign::NoSign => 0,
            num_bigint::Sign::Plus => 1,
        };
        let w: Vec<WidePoint> = pts.iter().map(|p| WidePoint::new(p[0], p[1])).collect();
        assert_eq!(cross(w[0], w[1], w[2]), want, "round {round}: {pts:?}");
        if round % 4 == 0 {
            assert_eq!(want, 0, "round {round}: constructed collinear");
        }
    }
    assert!(collinear > 1000);
}

#[test]
fn decimals_compare_by_value() {
    let order = [
        "-1e400",
        "-12.5",
        "-1.25",
        "-1e-30",
        "0",
        "1e-400",
        "0.000123",
        "0.0123",
        "0.1",
        "0.10000000000000001",
        "1",
        "9.99",
        "10",
        "1e30",
    ];
    for (i, a) in order.iter().enumerate() {
        for (j, b) in order.iter().enumerate() {
            assert_eq!(dec(a).cmp(&dec(b)), i.cmp(&j), "{a} vs {b}");
        }
    }
}

#[test]
fn areas_sum_exactly_across_exponents() {
    let p = |x: &str, y: &str| WidePoint::new(dec(x), dec(y));
    let (a, b, c, d) = (
        p("0", "0"),
        p("1e-30", "0"),
        p("1e-30", "1e20"),
        p("0", "1e20"),
    );
    let mut whole = Area::default();
    whole.add(a, b, c);
    whole.add(a, c, d);
    let mut square = Area::default();
    square.add(a, b, c);
    square.add(c, d, a);
    assert_eq!(whole, square);
    assert_eq!(whole.signum(), 1);
    assert_eq!(whole.to_string(), "2e-10");
}
