//! Exact decimal numbers, as written in the input.
//!
//! Input contract: a decimal literal `[+-]digits[.digits][(e|E)[+-]digits]` (also `.5` and `5.`).
//! Output guarantee: the value `±mantissa × 10^exponent` exactly, normalised (no trailing zeros
//! in the mantissa, zero has exponent 0 and no sign), so two literals denote the same number
//! exactly when their `Decimal`s are equal. `NaN`, `inf` and `infinity` are rejected by name.
//! Complexity: linear in the length of the literal, constant extra memory; a literal with too
//! many significant digits is rejected at the first digit too many.

use std::cmp::Ordering;
use std::fmt;

/// Most significant digits a coordinate may carry (what fits a `u128`).
pub const MAX_DIGITS: usize = 38;

/// Largest decimal exponent accepted; beyond it no coordinate could fit the exact grid anyway.
const MAX_EXPONENT: i64 = 1_000;

/// An exact decimal number `±mantissa × 10^exponent`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Default)]
pub struct Decimal {
    negative: bool,
    mantissa: u128,
    exponent: i32,
}

/// Why a number could not be read.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum NumberError {
    /// The text is not a decimal number at all.
    #[error("`{0}` is not a number")]
    Invalid(String),
    /// NaN or an infinity.
    #[error("`{0}` is not a finite number")]
    NonFinite(String),
    /// More significant digits than exact arithmetic can carry.
    #[error("`{0}` has more than {MAX_DIGITS} significant digits")]
    TooManyDigits(String),
    /// An exponent far outside any usable range.
    #[error("`{0}` has an exponent outside -{MAX_EXPONENT}..{MAX_EXPONENT}")]
    ExponentOutOfRange(String),
}

impl Decimal {
    /// Zero.
    pub const ZERO: Decimal = Decimal {
        negative: false,
        mantissa: 0,
        exponent: 0,
    };

    /// Parses a decimal literal exactly.
    ///
    /// # Errors
    /// [`NumberError`] names what is wrong with the text.
    ///
    /// # Examples
    /// ```
    /// use minitri::Decimal;
    /// let a: Decimal = Decimal::parse("0.10")?;
    /// assert_eq!(a, Decimal::parse("1e-1")?);
    /// # Ok::<(), minitri::NumberError>(())
    /// ```
    pub fn parse(text: &str) -> Result<Decimal, NumberError> {
        let invalid = || NumberError::Invalid(literal(text));
        // Only a short text can name a non-finite value (no copy of a long literal is made).
        if text.len() <= "-infinity".len() {
            let unsigned = text.trim_start_matches(['+', '-']);
            if ["nan", "inf", "infinity"]
                .iter()
                .any(|name| unsigned.eq_ignore_ascii_case(name))
            {
                return Err(NumberError::NonFinite(literal(text)));
            }
        }
        let bytes = text.as_bytes();
        let mut pos = 0;
        let negative = match bytes.first() {
            Some(b'-') => {
                pos += 1;
                true
            }
            Some(b'+') => {
                pos += 1;
                false
            }
            _ => false,
        };
        // The significant digits so far are `mantissa` followed by `zeros` zeros (held back:
        // trailing zeros are not significant); `significant` counts both.
        let mut mantissa: u128 = 0;
        let mut significant: usize = 0;
        let mut zeros: i64 = 0;
        let mut fraction_digits: i64 = 0;
        let mut seen_digit = false;
        let mut seen_point = false;
        while pos < bytes.len() {
            match bytes[pos] {
                c @ b'0'..=b'9' => {
                    seen_digit = true;
                    if c == b'0' {
                        if significant > 0 {
                            zeros += 1;
                            significant += 1;
                        }
                    } else {
                        significant += 1;
                        if significant > MAX_DIGITS {
                            // Rejected at once: a long literal is never read to its end.
                            return Err(NumberError::TooManyDigits(literal(text)));
                        }
                        for _ in 0..zeros {
                            mantissa *= 10;
                        }
                        zeros = 0;
                        mantissa = mantissa * 10 + u128::from(c - b'0');
                    }
                    if seen_point {
                        fraction_digits += 1;
                    }
                }
                b'.' if !seen_point => seen_point = true,
                _ => break,
            }
            pos += 1;
        }
        if !seen_digit {
            return Err(invalid());
        }
        let mut exponent: i64 = 0;
        if pos < bytes.len() {
            if bytes[pos] != b'e' && bytes[pos] != b'E' {
                return Err(invalid());
            }
            let rest = &text[pos + 1..];
            let body = rest.strip_prefix(['+', '-']).unwrap_or(rest);
            if body.is_empty() || !body.bytes().all(|c| c.is_ascii_digit()) {
                return Err(invalid());
            }
            let trimmed = body.trim_start_matches('0');
            if trimmed.len() > 6 {
                return Err(NumberError::ExponentOutOfRange(literal(text)));
            }
            let magnitude: i64 = if trimmed.is_empty() {
                0
            } else {
                trimmed.parse().map_err(|_| invalid())?
            };
            exponent = if rest.starts_with('-') {
                -magnitude
            } else {
                magnitude
            };
        }
        if mantissa == 0 {
            return Ok(Decimal::ZERO);
        }
        exponent = exponent - fraction_digits + zeros;
        if exponent.abs() > MAX_EXPONENT {
            return Err(NumberError::ExponentOutOfRange(literal(text)));
        }
        Ok(Decimal {
            negative,
            mantissa,
            exponent: exponent as i32,
        })
    }

    /// The power of ten of the last significant digit (`0.25` has exponent -2).
    pub fn exponent(&self) -> i32 {
        self.exponent
    }

    /// `self × 10^scale` as an exact integer, if it is one and fits an `i128`.
    pub(crate) fn scaled(&self, scale: i32) -> Option<i128> {
        if self.mantissa == 0 {
            return Some(0);
        }
        let shift = u32::try_from(self.exponent.checked_add(scale)?).ok()?;
        let magnitude = i128::try_from(self.mantissa)
            .ok()?
            .checked_mul(10i128.checked_pow(shift)?)?;
        Some(if self.negative { -magnitude } else { magnitude })
    }

    /// For messages: the plain notation when it is short (at most 16 characters), else the same
    /// exact value in scientific notation (`1e400`, `-1.25e-30`), so a message stays short.
    ///
    /// # Examples
    /// ```
    /// use minitri::Decimal;
    /// assert_eq!(Decimal::parse("0.125")?.brief(), "0.125");
    /// assert_eq!(Decimal::parse("-125e400")?.brief(), "-1.25e402");
    /// # Ok::<(), minitri::NumberError>(())
    /// ```
    pub fn brief(&self) -> String {
        let plain = self.to_string();
        if plain.len() <= 16 {
            return plain;
        }
        let digits = self.mantissa.to_string();
        let sign = if self.negative { "-" } else { "" };
        let power = i64::from(self.exponent) + digits.len() as i64 - 1;
        match digits.split_at(1) {
            (head, "") => format!("{sign}{head}e{power}"),
            (head, tail) => format!("{sign}{head}.{tail}e{power}"),
        }
    }

    /// The sign and the digits: the value is `±mantissa × 10^exponent` (`true`: negative).
    pub(crate) fn parts(&self) -> (bool, u128) {
        (self.negative, self.mantissa)
    }

    /// The opposite number, exactly.
    pub(crate) fn negated(self) -> Decimal {
        Decimal {
            negative: !self.negative && self.mantissa != 0,
            ..self
        }
    }

    /// `floor(log10(|self|))`, exactly; `i32::MIN` for zero.
    pub(crate) fn magnitude(&self) -> i32 {
        if self.mantissa == 0 {
            return i32::MIN;
        }
        self.exponent + self.mantissa.ilog10() as i32
    }

    /// The nearest `f64` to `self / 10^shift` (for drawing only): finite for any decimal when
    /// `shift` is near its [`Decimal::magnitude`].
    pub(crate) fn shifted_f64(&self, shift: i32) -> f64 {
        let sign = if self.negative { "-" } else { "" };
        let exponent = i64::from(self.exponent) - i64::from(shift);
        format!("{sign}{}e{exponent}", self.mantissa)
            .parse()
            .unwrap_or(0.0)
    }

    /// The nearest `f64` (for drawing only, never for decisions).
    pub fn to_f64(&self) -> f64 {
        // Formatting then parsing gives the correctly rounded value.
        self.to_string().parse().unwrap_or(0.0)
    }
}

/// Longest literal kept in a [`NumberError`], in characters (then `...`): a rejected 100 MB
/// literal is not copied.
const MAX_LITERAL_CHARS: usize = 80;

/// `text` for a [`NumberError`]: at most [`MAX_LITERAL_CHARS`] characters, then `...`.
fn literal(text: &str) -> String {
    match text.char_indices().nth(MAX_LITERAL_CHARS) {
        Some((end, _)) => format!("{}...", &text[..end]),
        None => text.to_string(),
    }
}

impl From<u64> for Decimal {
    /// The integer exactly (as [`Decimal::parse`] of its decimal notation).
    fn from(value: u64) -> Decimal {
        Decimal::integer(false, value)
    }
}

impl From<i64> for Decimal {
    /// The integer exactly (as [`Decimal::parse`] of its decimal notation).
    fn from(value: i64) -> Decimal {
        Decimal::integer(value < 0, value.unsigned_abs())
    }
}

impl Decimal {
    /// `-magnitude` or `magnitude`, normalised (trailing zeros into the exponent).
    fn integer(negative: bool, magnitude: u64) -> Decimal {
        if magnitude == 0 {
            return Decimal::ZERO;
        }
        let mut mantissa = u128::from(magnitude);
        let mut exponent = 0;
        while mantissa % 10 == 0 {
            mantissa /= 10;
            exponent += 1;
        }
        Decimal {
            negative,
            mantissa,
            exponent,
        }
    }
}

impl Ord for Decimal {
    /// The order of the values, exactly.
    fn cmp(&self, other: &Decimal) -> Ordering {
        let sign = |d: &Decimal| match (d.mantissa, d.negative) {
            (0, _) => 0,
            (_, true) => -1,
            (_, false) => 1,
        };
        let by_sign = sign(self).cmp(&sign(other));
        if by_sign != Ordering::Equal || sign(self) == 0 {
            return by_sign;
        }
        // Same sign, both non-zero: compare the magnitudes by their leading power of ten, then
        // digit by digit (aligned, both then have the same number of digits, at most 38).
        let power = |d: &Decimal| i64::from(d.exponent) + i64::from(d.mantissa.ilog10());
        let magnitude = power(self).cmp(&power(other)).then_with(|| {
            let (a, b) = (self.mantissa, other.mantissa);
            if self.exponent >= other.exponent {
                let shift = (self.exponent - other.exponent) as u32;
                (a * 10u128.pow(shift)).cmp(&b)
            } else {
                let shift = (other.exponent - self.exponent) as u32;
                a.cmp(&(b * 10u128.pow(shift)))
            }
        });
        if self.negative {
            magnitude.reverse()
        } else {
            magnitude
        }
    }
}

impl PartialOrd for Decimal {
    fn partial_cmp(&self, other: &Decimal) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl std::str::FromStr for Decimal {
    type Err = NumberError;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Decimal::parse(s)
    }
}

impl fmt::Display for Decimal {
    /// Plain decimal notation, exact, without exponent: `-0.125`, `1200`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let digits = self.mantissa.to_string();
        let sign = if self.negative { "-" } else { "" };
        if self.exponent >= 0 {
            write!(f, "{sign}{digits}{}", "0".repeat(self.exponent as usize))
        } else {
            let point = digits.len() as i64 + i64::from(self.exponent);
            if point > 0 {
                let (int, frac) = digits.split_at(point as usize);
                write!(f, "{sign}{int}.{frac}")
            } else {
                write!(f, "{sign}0.{}{digits}", "0".repeat((-point) as usize))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::d;

    #[test]
    fn equal_values_written_differently_are_equal() {
        assert_eq!(d("0.1"), d("0.10"));
        assert_eq!(d("1e-1"), d(".1"));
        assert_eq!(d("-0"), d("0.000"));
        assert_eq!(d("1200"), d("1.2e3"));
        assert_eq!(d("+5."), d("5"));
        assert_ne!(d("0.1"), d("0.1000000000000000001"));
    }

    #[test]
    fn integers_convert_as_their_decimal_notation_parses() {
        for value in [
            0,
            1,
            -1,
            7,
            10,
            -100,
            120,
            1_000_000,
            -305_000,
            i64::MAX,
            i64::MIN,
        ] {
            assert_eq!(
                Decimal::from(value),
                Decimal::parse(&value.to_string()).unwrap()
            );
        }
        for value in [0, 9, 90, 18_000_000_000_000_000_000, u64::MAX] {
            assert_eq!(
                Decimal::from(value),
                Decimal::parse(&value.to_string()).unwrap()
            );
        }
        assert_eq!(Decimal::from(-2500i64).to_string(), "-2500");
        assert_eq!(Decimal::from(-2500i64).exponent(), 2);
    }

    #[test]
    fn display_is_exact_plain_notation() {
        assert_eq!(d("-0.125").to_string(), "-0.125");
        assert_eq!(d("1.2e3").to_string(), "1200");
        assert_eq!(d("3e-5").to_string(), "0.00003");
        assert_eq!(d("0.30000000000000001").to_string(), "0.30000000000000001");
    }

    #[test]
    fn scaled_is_exact_and_checked() {
        assert_eq!(d("0.3").scaled(1), Some(3));
        assert_eq!(d("-2.5").scaled(3), Some(-2500));
        assert_eq!(d("0.25").scaled(1), None, "not an integer on that grid");
        assert_eq!(d("1e200").scaled(0), None, "overflow is detected");
        assert_eq!(d("0").scaled(400), Some(0), "zero fits any grid");
    }

    #[test]
    fn brief_is_plain_when_short_and_scientific_when_long() {
        assert_eq!(d("-0.125").brief(), "-0.125");
        assert_eq!(d("1e15").brief(), "1000000000000000");
        assert_eq!(d("1e16").brief(), "1e16");
        assert_eq!(d("-1.5e-30").brief(), "-1.5e-30");
        assert_eq!(
            d("123456789012345678901234567890").brief(),
            "1.2345678901234567890123456789e29"
        );
    }

    #[test]
    fn bad_numbers_are_named() {
        assert_eq!(
            Decimal::parse("NaN"),
            Err(NumberError::NonFinite("NaN".into()))
        );
        assert_eq!(
            Decimal::parse("-Infinity"),
            Err(NumberError::NonFinite("-Infinity".into()))
        );
        assert!(matches!(
            Decimal::parse("1.2.3"),
            Err(NumberError::Invalid(_))
        ));
        assert!(matches!(Decimal::parse("-"), Err(NumberError::Invalid(_))));
        assert!(matches!(Decimal::parse("1e"), Err(NumberError::Invalid(_))));
        assert!(matches!(
            Decimal::parse("0x10"),
            Err(NumberError::Invalid(_))
        ));
        assert!(matches!(
            Decimal::parse("1e999999999"),
            Err(NumberError::ExponentOutOfRange(_))
        ));
        assert!(matches!(
            Decimal::parse("123456789012345678901234567890123456789"),
            Err(NumberError::TooManyDigits(_))
        ));
        // A long literal is rejected at its 39th significant digit, and quoted short.
        let long = "7".repeat(1_000_000);
        let error = Decimal::parse(&long).unwrap_err().to_string();
        assert_eq!(
            error,
            format!(
                "`{}...` has more than 38 significant digits",
                "7".repeat(80)
            )
        );
        let zeros = format!("1{}", "0".repeat(1_000_000));
        assert_eq!(
            Decimal::parse(&zeros),
            Err(NumberError::ExponentOutOfRange(format!(
                "1{}...",
                "0".repeat(79)
            )))
        );
        // Trailing zeros do not count as significant digits.
        assert_eq!(
            d("1000000000000000000000000000000000000000000")
                .to_string()
                .len(),
            43
        );
    }
}
