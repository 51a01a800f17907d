//! Reader for the plain vertex list: one `x y` or `x,y` vertex per line.
//!
//! # Format
//!
//! ```text
//! # a square with a square hole      <- `#` starts a comment, here and after a vertex
//! 0 0
//! 10 0
//! 10 10
//! 0,10                               <- `x,y`, `x, y`, spaces and tabs all work
//! 0 0                                <- optional repeated closing vertex
//!                                    <- a blank line ends the ring; the next ring is a hole
//! 2.5 2.5
//! 2.5 7.5
//! 7.5 7.5
//! 7.5 2.5
//! ---                                <- a line holding only `---` starts the next polygon
//! 20 0
//! 30 0
//! 25 8.66
//! ```
//!
//! Grammar, line by line (`\n` or `\r\n` endings; a comment runs from `#` to the end of the line):
//!
//! - a vertex line holds exactly two decimal numbers `x` and `y`, separated by whitespace or by
//!   one comma with optional whitespace around it;
//! - a blank line (whitespace only) ends the current ring; several blank lines in a row count as
//!   one, and a line holding only a comment is ignored (it neither ends a ring nor adds a vertex);
//! - a first line of two column names and a comma (a CSV header such as `x,y`) is skipped;
//! - a line holding only `---` ends the current ring and polygon. A `---` before the first vertex
//!   or after the last one is allowed; two `---` with no vertex between them are an error.
//!
//! The first ring of each polygon is its outer boundary, the following rings are its holes.
//!
//! Output guarantee: the polygons in input order, each as rings of exact [`Decimal`]s (the
//! literal text of each number, never through `f64`), without the repeated closing vertex.
//! Rings are never empty; rings with fewer than 3 vertices are left to validation.
//! Errors name the line and column of the offending field, e.g.
//! ``line 7, column 3: `abc` is not a number``.
//!
//! A polygon may hold at most a cap of vertices ([`MAX_VERTICES`] by default,
//! [`read_parts_within`] to choose): past it, it is read to its end without being kept and is an
//! error in its place; the other polygons stand.
//!
//! Complexity: linear in the input size.
//!
//! This file also holds the small helpers the three readers share (`excerpt`, `quote`,
//! `parse_number`).

use super::limits::{too_many_vertices, MAX_VERTICES};
use super::{drop_closing_vertex, locate, ParseError, RawPolygon};
use crate::geom::decimal::{Decimal, NumberError};

/// Longest excerpt of the input quoted in an error message, in characters.
const EXCERPT_CHARS: usize = 40;

/// The start of `text` for an error message: its first line, at most 40 characters (then `...`),
/// control characters escaped.
pub(super) fn excerpt(text: &str) -> String {
    let line = text.split(['\n', '\r']).next().unwrap_or_default();
    let mut out = String::new();
    for (count, c) in line.chars().enumerate() {
        if count == EXCERPT_CHARS {
            out.push_str("...");
            break;
        }
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

/// [`excerpt`] in double quotes.
pub(super) fn quote(text: &str) -> String {
    format!("\"{}\"", excerpt(text))
}

/// Parses a number literal exactly; the error is the [`NumberError`] message, with the literal
/// shortened by [`excerpt`].
pub(super) fn parse_number(literal: &str) -> Result<Decimal, String> {
    Decimal::parse(literal).map_err(|error| {
        let short = match error {
            NumberError::Invalid(s) => NumberError::Invalid(excerpt(&s)),
            NumberError::NonFinite(s) => NumberError::NonFinite(excerpt(&s)),
            NumberError::TooManyDigits(s) => NumberError::TooManyDigits(excerpt(&s)),
            NumberError::ExponentOutOfRange(s) => NumberError::ExponentOutOfRange(excerpt(&s)),
        };
        short.to_string()
    })
}

/// Reads every polygon of a vertex list.
///
/// # Errors
/// [`ParseError`] with line and column for a line that is not exactly two numbers, a number that
/// is not a finite decimal, two `---` without a vertex between them, a polygon of more than
/// [`MAX_VERTICES`] vertices; without location for an input holding no vertex at all.
///
/// # Examples
/// ```
/// use minitri::io::read::vertices;
/// let polygons = vertices::read("0 0\n1 0\n0,1\n")?;
/// assert_eq!(polygons[0].rings[0].len(), 3);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read(text: &str) -> Result<Vec<RawPolygon>, ParseError> {
    read_parts_within(text, MAX_VERTICES)?.into_iter().collect()
}

/// Reads every polygon of a vertex list, at most `max_vertices` vertices a polygon (all its
/// rings together): a polygon with more is read to its end without being kept and is an
/// error in its place (at its first vertex too many); the other polygons stand.
///
/// # Errors
/// As [`read`], but for the polygons with too many vertices.
///
/// # Examples
/// ```
/// use minitri::io::read::vertices;
/// let parts = vertices::read_parts_within("0 0\n1 0\n0 1\n0 2\n---\n5 5\n6 5\n5 6\n", 3)?;
/// assert_eq!(
///     parts[0].as_ref().unwrap_err().to_string(),
///     "line 4, column 1: too many vertices: more than 3 in one polygon (the most held while \
///      reading; --max-vertices raises it); the rest of it was read but not kept"
/// );
/// assert_eq!(parts[1].as_ref().unwrap().rings[0].len(), 3);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts_within(
    text: &str,
    max_vertices: usize,
) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    let mut polygons = Vec::new();
    let mut current = Current::default();
    let mut seen_separator = false;
    // The first meaningful line may be a CSV header (`x,y`), skipped.
    let mut first = true;
    let mut line_start = 0;
    for raw_line in text.split('\n') {
        let start = line_start;
        line_start += raw_line.len() + 1;
        let line = raw_line.strip_suffix('\r').unwrap_or(raw_line);
        let content = line.split('#').next().unwrap_or_default();
        if line.trim_start_matches(is_space).is_empty() {
            current.end_ring();
        } else if content.trim_matches(is_space).is_empty() {
            // A comment-only line.
        } else if std::mem::take(&mut first) && is_header(content) {
            // A CSV header: the column names.
        } else if content.trim_matches(is_space) == "---" {
            current.end_ring();
            if current.is_empty() {
                if seen_separator {
                    let column = content.find('-').unwrap_or_default();
                    return Err(ParseError::at(
                        locate(text, start + column),
                        "empty polygon: no vertex between this `---` and the previous one",
                    ));
                }
            } else {
                polygons.push(current.finish());
            }
            seen_separator = true;
        } else {
            let vertex = parse_vertex(content).map_err(|(offset, message)| {
                ParseError::at(locate(text, start + offset), message)
            })?;
            let at = |message: String| ParseError::at(locate(text, start), message);
            current.add(vertex, max_vertices, at)?;
        }
    }
    current.end_ring();
    if !current.is_empty() {
        polygons.push(current.finish());
    }
    if polygons.is_empty() {
        return Err(ParseError::new("empty input: no polygon found"));
    }
    Ok(polygons)
}

/// The polygon being read: its finished rings, the current ring, how many vertices it has,
/// and, once it has too many, that error (its vertices are then no longer kept).
#[derive(Default)]
struct Current {
    rings: Vec<Vec<[Decimal; 2]>>,
    ring: Vec<[Decimal; 2]>,
    count: usize,
    over: Option<ParseError>,
}

impl Current {
    /// Adds a vertex, unless it is one too many (the polygon is then dropped, its error kept:
    /// `at` locates it).
    ///
    /// # Errors
    /// Memory refused: this input's error (the run goes on), not an abort.
    fn add(
        &mut self,
        vertex: [Decimal; 2],
        max_vertices: usize,
        at: impl FnOnce(String) -> ParseError,
    ) -> Result<(), ParseError> {
        self.count += 1;
        if self.over.is_some() {
            return Ok(());
        }
        // A vertex repeating the ring's first may be its closing one, not counted (see
        // `end_ring`): it may be one past the cap.
        let closing = self.count == max_vertices + 1 && self.ring.first() == Some(&vertex);
        if self.count > max_vertices && !closing {
            (self.rings, self.ring) = (Vec::new(), Vec::new());
            self.over = Some(at(too_many_vertices(max_vertices, "one polygon")));
            return Ok(());
        }
        if self.ring.try_reserve(1).is_err() {
            return Err(at(format!(
                "not enough memory to hold this polygon: {} vertices of the ring read, no room for more",
                self.ring.len()
            )));
        }
        self.ring.push(vertex);
        Ok(())
    }

    /// Ends the current ring.
    fn end_ring(&mut self) {
        if end_ring(&mut self.ring, &mut self.rings) {
            self.count -= 1; // the closing vertex, not a vertex of the polygon
        }
    }

    /// Whether the polygon has nothing yet (after [`Current::end_ring`]).
    fn is_empty(&self) -> bool {
        self.rings.is_empty() && self.over.is_none()
    }

    /// The polygon read, or its error; the next one starts empty.
    fn finish(&mut self) -> Result<RawPolygon, ParseError> {
        let current = std::mem::take(self);
        match current.over {
            Some(error) => Err(error),
            None => Ok(RawPolygon {
                rings: current.rings,
                ordinates: None,
            }),
        }
    }
}

/// Is `line` (its comment, if any, is ignored) a CSV header: two column names separated by one
/// comma, such as `x,y` or `lon, lat`? A name starts with a letter and holds letters, digits and
/// `_`; `inf`, `infinity` and `nan` are numbers, not names.
pub(crate) fn is_header(line: &str) -> bool {
    let content = line.split('#').next().unwrap_or_default();
    let mut fields = content.split(',').map(|f| f.trim_matches(is_space));
    let names = [fields.next(), fields.next()];
    fields.next().is_none() && names.iter().all(|f| f.is_some_and(is_name))
}

/// A column name of a CSV header (see [`is_header`]).
fn is_name(field: &str) -> bool {
    let number = ["inf", "infinity", "nan"]
        .iter()
        .any(|n| field.eq_ignore_ascii_case(n));
    !number
        && field.starts_with(|c: char| c.is_ascii_alphabetic())
        && field.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
}

/// Could `start`, the beginning of a first line cut off, still become a CSV header? (A letter
/// first, then only name characters, blanks (as [`is_header`] trims them: any whitespace) and
/// at most one comma, no comment yet.)
pub(crate) fn may_become_header(start: &str) -> bool {
    start.starts_with(|c: char| c.is_ascii_alphabetic())
        && start.matches(',').count() <= 1
        && start
            .chars()
            .all(|c| c.is_ascii_alphanumeric() || c == '_' || c == ',' || is_space(c))
}

/// Whitespace inside a line (a byte-order mark counts as whitespace).
fn is_space(c: char) -> bool {
    c.is_whitespace() || c == '\u{feff}'
}

/// Moves a finished, non-empty ring (without its closing vertex) to the polygon's rings;
/// returns whether a closing vertex was dropped.
fn end_ring(ring: &mut Vec<[Decimal; 2]>, rings: &mut Vec<Vec<[Decimal; 2]>>) -> bool {
    if ring.is_empty() {
        return false;
    }
    let closed = drop_closing_vertex(ring);
    rings.push(std::mem::take(ring));
    closed
}

/// Parses a vertex line without its comment; errors carry the byte offset in the line.
fn parse_vertex(line: &str) -> Result<[Decimal; 2], (usize, String)> {
    let fields = split_fields(line)?;
    // A field that is not a number is named before a wrong count (`POLYGON ((0 0, ...` read as
    // a vertex list is better told by its first word than by its number of fields).
    for (at, field) in fields.iter().take(2) {
        parse_number(field).map_err(|m| (*at, m))?;
    }
    match fields.as_slice() {
        [(x_at, x), (y_at, y)] => {
            let x = parse_number(x).map_err(|m| (*x_at, m))?;
            let y = parse_number(y).map_err(|m| (*y_at, m))?;
            Ok([x, y])
        }
        [(at, _)] => Err((
            *at,
            "expected 2 numbers `x y` or `x,y`, found 1 field".to_string(),
        )),
        _ => {
            let (at, third) = fields.get(2).copied().unwrap_or_default();
            let message = format!(
                "expected 2 numbers `x y` or `x,y`, found a third field {}",
                quote(third)
            );
            Err((at, message))
        }
    }
}

/// Splits a line into fields separated by whitespace or by one comma (with optional whitespace
/// around it), each with its byte offset; stops after a third field (the line is wrong then, and
/// a long line is not split to its end).
fn split_fields(line: &str) -> Result<Vec<(usize, &str)>, (usize, String)> {
    let mut fields = Vec::new();
    // Offset of a comma not yet followed by a field.
    let mut pending_comma: Option<usize> = None;
    let mut chars = line.char_indices().peekable();
    while let Some(&(at, c)) = chars.peek() {
        if is_space(c) {
            chars.next();
        } else if c == ',' {
            if fields.is_empty() || pending_comma.is_some() {
                return Err((at, "expected a number before ','".to_string()));
            }
            pending_comma = Some(at);
            chars.next();
        } else {
            let mut end = line.len();
            while let Some(&(i, c)) = chars.peek() {
                if is_space(c) || c == ',' {
                    end = i;
                    break;
                }
                chars.next();
            }
            fields.push((at, line.get(at..end).unwrap_or_default()));
            pending_comma = None;
            if fields.len() == 3 {
                return Ok(fields);
            }
        }
    }
    match pending_comma {
        Some(at) => Err((at, "expected a number after ','".to_string())),
        None => Ok(fields),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::{d, ring};

    fn error(text: &str) -> String {
        read(text).expect_err(text).to_string()
    }

    #[test]
    fn a_polygon_past_the_cap_on_vertices_fails_alone() {
        // Rings counted together; the next polygon counted from 0.
        let text = "0 0\n9 0\n9 9\n\n1 1\n2 1\n1 2\n---\n0 0\n1 0\n0 1\n";
        let parts = read_parts_within(text, 6).unwrap();
        assert!(parts[0].is_ok() && parts[1].is_ok());
        let parts = read_parts_within(text, 5).unwrap();
        let error = parts[0].as_ref().unwrap_err().to_string();
        assert!(
            error.starts_with("line 7, column 1: too many vertices: more than 5 in one polygon"),
            "{error}"
        );
        assert_eq!(parts[1].as_ref().unwrap().rings[0].len(), 3);
        // The last polygon too, and a syntax error after the cap still stops the input.
        assert!(read_parts_within("0 0\n1 0\n0 1\n0 2\n", 3).unwrap()[0].is_err());
        assert!(read_parts_within("0 0\n1 0\n0 1\n0 2\nx 3\n", 3).is_err());
    }

    #[test]
    fn reads_one_ring_in_every_separator_style() {
        let text = "0 0\n1,0\n1, 1\n0\t1\n  2   , 3  \n";
        let polygons = read(text).unwrap();
        assert_eq!(polygons.len(), 1);
        assert_eq!(
            polygons[0].rings,
            vec![ring(&[
                ("0", "0"),
                ("1", "0"),
                ("1", "1"),
                ("0", "1"),
                ("2", "3")
            ])]
        );
    }

    #[test]
    fn drops_the_optional_closing_vertex() {
        let open = read("0 0\n1 0\n0 1").unwrap();
        let closed = read("0 0\n1 0\n0 1\n0.0 0e5\n").unwrap();
        assert_eq!(open, closed);
        assert_eq!(open[0].rings[0].len(), 3);
    }

    #[test]
    fn keeps_decimals_exact() {
        let polygons = read("0 0\n0.1 0.3\n0.2 0.6\n-1.5e-3 +7\n").unwrap();
        let r = &polygons[0].rings[0];
        assert_eq!(r[1], [d("0.1"), d("0.3")]);
        assert_eq!(r[2], [d("0.2"), d("0.6")]);
        assert_eq!(r[3], [d("-0.0015"), d("7")]);
    }

    #[test]
    fn blank_lines_separate_rings_and_dashes_separate_polygons() {
        let text = "# outer\n0 0\n10 0 # corner\n10 10\n0 10\n\n\n  \n2 2\n2 3\n3 3\n\n4 4\n4 5\n5 5\n4 4\n---\n20 0\n30 0\n25 8\n";
        let polygons = read(text).unwrap();
        assert_eq!(polygons.len(), 2);
        assert_eq!(polygons[0].rings.len(), 3);
        assert_eq!(polygons[0].rings[0].len(), 4);
        assert_eq!(
            polygons[0].rings[2],
            ring(&[("4", "4"), ("4", "5"), ("5", "5")])
        );
        assert_eq!(
            polygons[1].rings,
            vec![ring(&[("20", "0"), ("30", "0"), ("25", "8")])]
        );
    }

    #[test]
    fn comment_only_lines_do_not_end_a_ring() {
        let polygons = read("0 0\n# between\n1 0\n   # indented\n0 1\n").unwrap();
        assert_eq!(polygons[0].rings.len(), 1);
        assert_eq!(polygons[0].rings[0].len(), 3);
    }

    #[test]
    fn windows_line_endings_work() {
        let text = "0 0\r\n1 0\r\n0 1\r\n\r\n0.1 0.1\r\n0.2 0.1\r\n0.1 0.2\r\n---\r\n5 5\r\n6 5\r\n5 6\r\n";
        let polygons = read(text).unwrap();
        assert_eq!(polygons.len(), 2);
        assert_eq!(polygons[0].rings.len(), 2);
        assert_eq!(polygons[0].rings[1][0], [d("0.1"), d("0.1")]);
        assert_eq!(
            error("0 0\r\n1 x\r\n"),
            "line 2, column 3: `x` is not a number"
        );
    }

    #[test]
    fn leading_and_trailing_separators_are_allowed() {
        let polygons = read("---\n0 0\n1 0\n0 1\n---\n\n").unwrap();
        assert_eq!(polygons.len(), 1);
        assert_eq!(
            read("\u{feff}0 0\n1 0\n0 1\n").unwrap(),
            read("0 0\n1 0\n0 1").unwrap()
        );
    }

    #[test]
    fn short_rings_are_left_to_validation() {
        let polygons = read("0 0\n1 0\n0 1\n\n0.5 0.5\n").unwrap();
        assert_eq!(polygons[0].rings[1].len(), 1);
    }

    #[test]
    fn rejects_malformed_lines_with_line_and_column() {
        assert_eq!(
            error("0 0\n1 0\n1 abc\n"),
            "line 3, column 3: `abc` is not a number"
        );
        assert_eq!(
            error("0 0\n  NaN 1\n"),
            "line 2, column 3: `NaN` is not a finite number"
        );
        assert_eq!(
            error("0 0\n1 0 5\n"),
            "line 2, column 5: expected 2 numbers `x y` or `x,y`, found a third field \"5\""
        );
        assert_eq!(
            error("0 0\n  7\n"),
            "line 2, column 3: expected 2 numbers `x y` or `x,y`, found 1 field"
        );
        assert_eq!(
            error("0 0\n1,,2\n"),
            "line 2, column 3: expected a number before ','"
        );
        assert_eq!(
            error(",1 2\n"),
            "line 1, column 1: expected a number before ','"
        );
        assert_eq!(
            error("1 2,\n"),
            "line 1, column 4: expected a number after ','"
        );
        assert_eq!(
            error("1 1e99999\n"),
            "line 1, column 3: `1e99999` has an exponent outside -1000..1000"
        );
        assert_eq!(
            error("0 0\n1 0\n---\n# c\n\n---\n1 1\n"),
            "line 6, column 1: empty polygon: no vertex between this `---` and the previous one"
        );
        assert_eq!(error("é 1\n"), "line 1, column 1: `é` is not a number");
        assert_eq!(error("1 é\n"), "line 1, column 3: `é` is not a number");
    }

    #[test]
    fn rejects_empty_input() {
        for text in [
            "",
            "\n\n",
            "  \r\n",
            "# only a comment\n# and another",
            "---\n",
        ] {
            assert_eq!(error(text), "empty input: no polygon found", "{text:?}");
        }
    }

    #[test]
    fn long_and_binary_input_give_short_errors() {
        let long = format!("0 {}\n", "9".repeat(1_000_000));
        let message = error(&long);
        assert!(message.starts_with("line 1, column 3: `9999"), "{message}");
        assert!(message.len() < 120, "{message}");
        // A line of a million vertices is split no further than its third field.
        let fields = "0 0, ".repeat(1_000_000);
        assert_eq!(
            error(&fields),
            "line 1, column 6: expected 2 numbers `x y` or `x,y`, found a third field \"0\""
        );
        let binary = "\u{0}\u{1}\u{7f} 1\n";
        assert_eq!(
            error(binary),
            "line 1, column 1: `\\u{0}\\u{1}\\u{7f}` is not a number"
        );
    }

    #[test]
    fn excerpt_truncates_and_escapes() {
        assert_eq!(excerpt("short"), "short");
        assert_eq!(excerpt(&"x".repeat(50)), format!("{}...", "x".repeat(40)));
        assert_eq!(excerpt("first\nsecond"), "first");
        assert_eq!(quote("a\tb"), "\"a\\tb\"");
    }
}
