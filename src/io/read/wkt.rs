//! Reader for well-known text (WKT): a small tokenizer and a recursive-descent parser.
//!
//! # Grammar
//!
//! Keywords are case-insensitive; whitespace (and `#` comments, running to the end of the line)
//! may separate any two tokens.
//!
//! ```text
//! input      := [ "SRID" "=" integer ";" ] geometry [ ";" ]
//! geometry   := "POLYGON" dim ( "EMPTY" | polygon )
//!             | "MULTIPOLYGON" dim ( "EMPTY" | "(" part ( "," part )* ")" )
//!             | "GEOMETRYCOLLECTION" dim ( "EMPTY" | "(" geometry ( "," geometry )* ")" )
//! dim        := [ "Z" | "M" | "ZM" ]      (also glued to the keyword: "POLYGONZ")
//! part       := "EMPTY" | polygon
//! polygon    := "(" ring ( "," ring )* ")"
//! ring       := "(" point ( "," point )* ")"
//! point      := number number [ number [ number ] ]    (x y, then z and m, which are ignored)
//! ```
//!
//! Exactly one top-level geometry is read; anything after it is an error (wrap several in a
//! `GEOMETRYCOLLECTION` or `MULTIPOLYGON`). Collections may nest up to 64 levels.
//!
//! A member of a `GEOMETRYCOLLECTION` of another WKT type (`POINT`, `LINESTRING`, `TRIANGLE`,
//! ...) is read as far as its syntax goes (its dimension tag, then `EMPTY` or a body of balanced
//! parentheses holding words and commas; an unbalanced body is a syntax error, as anywhere) and
//! becomes one failed part: [`read_parts`] gives its error, at its keyword, in its place among
//! the polygons, and the collection's polygons stand. [`read`] fails on it.
//!
//! Output guarantee: one [`RawPolygon`] per `POLYGON` and per `MULTIPOLYGON` part, in input
//! order, `EMPTY` ones skipped; coordinates are exact [`Decimal`]s parsed from their literal text
//! (never through `f64`); each ring loses its repeated closing vertex. Errors carry the line and
//! column of the offending token.
//!
//! Vertices: one polygon (a `POLYGON`, or one polygon of a `MULTIPOLYGON`), all its rings
//! together, may hold at most a cap of vertices ([`MAX_VERTICES`] by default,
//! [`read_parts_within`] to choose). Past it the polygon becomes a failed part, located at the
//! first vertex too many; its vertices are dropped and the rest of it is read (its syntax still
//! checked) without being kept, and the other polygons stand.
//!
//! Complexity: linear in the input size.

use super::limits::{too_many_vertices, MAX_VERTICES};
use super::vertices::{parse_number, quote};
use super::{drop_closing_vertex, locate, ParseError, RawPolygon};
use crate::geom::decimal::{Decimal, NumberError};

/// Deepest nesting of `GEOMETRYCOLLECTION`s accepted (bounds the recursion).
const MAX_DEPTH: usize = 64;

/// What the top level and a collection accept.
const GEOMETRY_TYPES: &str = "POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION";

/// Other WKT geometry types, named in the error when one is found.
const OTHER_TYPES: [&str; 15] = [
    "POINT",
    "LINESTRING",
    "MULTIPOINT",
    "MULTILINESTRING",
    "TRIANGLE",
    "TIN",
    "POLYHEDRALSURFACE",
    "CIRCULARSTRING",
    "COMPOUNDCURVE",
    "CURVEPOLYGON",
    "MULTICURVE",
    "MULTISURFACE",
    "CURVE",
    "SURFACE",
    "GEOMETRY",
];

/// Reads the one WKT geometry of `text` and returns its polygons.
///
/// # Errors
/// [`ParseError`] with line and column for a syntax error, a number that is not a finite
/// decimal, a point with fewer than 2 or more than 4 coordinates (or not as many as the first
/// point of its polygon: a missing comma, most likely), an empty ring, a geometry type
/// other than `POLYGON`, `MULTIPOLYGON` and `GEOMETRYCOLLECTION`, collections nested deeper than
/// 64 levels, or text after the geometry; without location for an empty input or a geometry
/// holding no polygon (all `EMPTY`).
///
/// # Examples
/// ```
/// use minitri::io::read::wkt;
/// let polygons = wkt::read("MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 5 6)))")?;
/// assert_eq!(polygons.len(), 2);
/// assert_eq!(polygons[0].rings[0].len(), 3);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read(text: &str) -> Result<Vec<RawPolygon>, ParseError> {
    read_parts(text)?.into_iter().collect()
}

/// Reads the WKT geometry of `text` and returns its parts in input order: its polygons,
/// and for each member of a `GEOMETRYCOLLECTION` of another type (`POINT`, `LINESTRING`, ...)
/// the error that names it, at its line and column. Several geometries, each starting on a
/// new line (WKT lines, as `--to wkt` writes them), are read in turn, their polygons numbered
/// on; a second geometry on the line where the previous one ends is an error.
///
/// # Errors
/// As [`read`], but for the members of collections of other types; a geometry without any part
/// (all `EMPTY`) is an error.
///
/// # Examples
/// ```
/// use minitri::io::read::wkt;
/// let parts = wkt::read_parts("GEOMETRYCOLLECTION (POINT (1 2), POLYGON ((0 0, 1 0, 0 1)))")?;
/// assert_eq!(
///     parts[0].as_ref().unwrap_err().to_string(),
///     "line 1, column 21: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found POINT"
/// );
/// assert_eq!(parts[1].as_ref().unwrap().rings[0].len(), 3);
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts(text: &str) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    read_parts_within(text, MAX_VERTICES)
}

/// [`read_parts`] with a cap of `max_vertices` vertices a polygon: past it, the polygon is a
/// failed part (located at its first vertex too many) and the other polygons stand.
///
/// # Errors
/// As [`read_parts`].
///
/// # Examples
/// ```
/// use minitri::io::read::wkt;
/// let text = "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 2)), ((5 5, 6 5, 5 6)))";
/// let parts = wkt::read_parts_within(text, 3)?;
/// assert_eq!(
///     parts[0].as_ref().unwrap_err().to_string(),
///     "line 1, column 32: too many vertices: more than 3 in one polygon (the most held while \
///      reading; --max-vertices raises it); the rest of it was read but not kept"
/// );
/// assert!(parts[1].is_ok());
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts_within(
    text: &str,
    max_vertices: usize,
) -> Result<Vec<Result<RawPolygon, ParseError>>, ParseError> {
    read_parts_srid_within(text, max_vertices).map(|(parts, _)| parts)
}

/// [`read_parts_within`] with each part's EWKT SRID (`SRID=4326;` before its geometry; `None`
/// without one), in the order of the parts.
///
/// # Errors
/// As [`read_parts`].
///
/// # Examples
/// ```
/// use minitri::io::read::wkt;
/// let text = "SRID=3857;POLYGON ((0 0, 1 0, 0 1))\nPOLYGON ((0 0, 1 0, 0 1))";
/// let (parts, srids) = wkt::read_parts_srid_within(text, 10)?;
/// assert_eq!((parts.len(), srids), (2, vec![Some(3857), None]));
/// # Ok::<(), minitri::io::read::ParseError>(())
/// ```
pub fn read_parts_srid_within(
    text: &str,
    max_vertices: usize,
) -> Result<super::wkb::PartsAndSrids, ParseError> {
    let mut srids = Vec::new();
    let mut parser = Parser {
        text,
        pos: 0,
        parts: Vec::new(),
        dimensions: None,
        measured: false,
        ordinates: Vec::new(),
        no_room: None,
        vertices: 0,
        max_vertices,
    };
    if parser.peek().kind == Tok::End {
        return Err(ParseError::new("empty input: no polygon found"));
    }
    let srid = parser.srid_prefix()?;
    parser.geometry(0)?;
    srids.resize(parser.parts.len(), srid);
    // WKT lines: a further geometry on a later line (as `--to wkt` writes them).
    while parser.next_line_geometry() {
        let srid = parser.srid_prefix()?;
        parser.geometry(0)?;
        srids.resize(parser.parts.len(), srid);
    }
    parser.end()?;
    if parser.parts.is_empty() {
        return Err(ParseError::new("no polygon found: the geometry is EMPTY"));
    }
    Ok((parser.parts, srids))
}

/// A token kind; words are keywords or number literals.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Tok<'a> {
    Word(&'a str),
    Open,
    Close,
    Comma,
    Semicolon,
    Equals,
    End,
}

/// A token and the byte offset where it starts.
#[derive(Clone, Copy, Debug)]
struct Token<'a> {
    offset: usize,
    kind: Tok<'a>,
}

impl Tok<'_> {
    /// The token as named in an error message (`'('`, `"abc"`).
    fn describe(self) -> String {
        match self {
            Tok::Word(w) => quote(w),
            Tok::Open => "'('".into(),
            Tok::Close => "')'".into(),
            Tok::Comma => "','".into(),
            Tok::Semicolon => "';'".into(),
            Tok::Equals => "'='".into(),
            Tok::End => "the end of the input".into(),
        }
    }
}

/// The three accepted geometry types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Polygon,
    MultiPolygon,
    Collection,
}

/// Splits a keyword into its geometry type name (one of `names`, any case) and whether a
/// dimension tag (`Z`, `M`, `ZM`) is glued to it.
fn split_type<'n>(word: &str, names: &[&'n str]) -> Option<(&'n str, bool)> {
    names.iter().find_map(|&name| {
        let head = word.get(..name.len())?;
        let tail = word.get(name.len()..)?;
        if !head.eq_ignore_ascii_case(name) {
            return None;
        }
        if tail.is_empty() {
            Some((name, false))
        } else if ["Z", "M", "ZM"]
            .iter()
            .any(|tag| tail.eq_ignore_ascii_case(tag))
        {
            Some((name, true))
        } else {
            None
        }
    })
}

/// The accepted geometry type of a keyword, and whether a dimension tag is glued to it.
fn classify(word: &str) -> Option<(Kind, bool)> {
    let (name, glued) = split_type(word, &["POLYGON", "MULTIPOLYGON", "GEOMETRYCOLLECTION"])?;
    let kind = match name {
        "POLYGON" => Kind::Polygon,
        "MULTIPOLYGON" => Kind::MultiPolygon,
        _ => Kind::Collection,
    };
    Some((kind, glued))
}

/// Whether a word names a WKT geometry type, accepted or not.
fn is_geometry_keyword(word: &str) -> bool {
    classify(word).is_some() || split_type(word, &OTHER_TYPES).is_some()
}

/// Whether `c` ends a word.
fn is_delimiter(c: char) -> bool {
    c.is_whitespace() || matches!(c, '(' | ')' | ',' | ';' | '=' | '#' | '\u{feff}')
}

/// The parser state: the text, the position of the next token, and the parts read so far.
struct Parser<'a> {
    text: &'a str,
    pos: usize,
    parts: Vec<Result<RawPolygon, ParseError>>,
    /// How many coordinates the current polygon's first point has: every point of a polygon
    /// must have as many (a point with more is most likely a missing comma).
    dimensions: Option<usize>,
    /// Whether the geometry being read is tagged `M` (its 3-number points are `x y m`).
    measured: bool,
    /// The Z and M values of the current polygon's vertices read so far (input numbering).
    ordinates: Vec<super::Ordinate>,
    /// The current polygon could not be stored (memory refused): its error, at the point where
    /// it happened. The polygon is read to its end (its syntax still checked) and becomes a
    /// failed part. Also set when the polygon has more than `max_vertices` vertices.
    no_room: Option<ParseError>,
    /// Vertices of the current polygon read so far, all its rings together.
    vertices: usize,
    /// The most vertices one polygon may hold.
    max_vertices: usize,
}

impl<'a> Parser<'a> {
    /// Skips whitespace, byte-order marks and `#` comments.
    fn skip_space(&mut self) {
        let bytes = self.text.as_bytes();
        loop {
            let rest = self.text.get(self.pos..).unwrap_or_default();
            let trimmed = rest.trim_start_matches(|c: char| c.is_whitespace() || c == '\u{feff}');
            self.pos += rest.len() - trimmed.len();
            if bytes.get(self.pos) != Some(&b'#') {
                return;
            }
            self.pos += trimmed.find('\n').unwrap_or(trimmed.len());
        }
    }

    /// Reads the next token.
    fn next(&mut self) -> Token<'a> {
        self.skip_space();
        let offset = self.pos;
        let rest = self.text.get(offset..).unwrap_or_default();
        let (kind, len) = match rest.chars().next() {
            None => (Tok::End, 0),
            Some('(') => (Tok::Open, 1),
            Some(')') => (Tok::Close, 1),
            Some(',') => (Tok::Comma, 1),
            Some(';') => (Tok::Semicolon, 1),
            Some('=') => (Tok::Equals, 1),
            Some(_) => {
                let len = rest.find(is_delimiter).unwrap_or(rest.len());
                (Tok::Word(rest.get(..len).unwrap_or_default()), len)
            }
        };
        self.pos = offset + len;
        Token { offset, kind }
    }

    /// The next token, left unread.
    fn peek(&mut self) -> Token<'a> {
        let saved = self.pos;
        let token = self.next();
        self.pos = saved;
        token
    }

    /// Reads the next token if it is the given word (any case).
    fn eat_word(&mut self, word: &str) -> bool {
        let saved = self.pos;
        match self.next().kind {
            Tok::Word(w) if w.eq_ignore_ascii_case(word) => true,
            _ => {
                self.pos = saved;
                false
            }
        }
    }

    /// An error at a token.
    fn error(&self, token: Token<'_>, message: impl Into<String>) -> ParseError {
        ParseError::at(locate(self.text, token.offset), message)
    }

    /// The error for an unexpected token.
    fn expected(&self, what: &str, token: Token<'_>) -> ParseError {
        match token.kind {
            Tok::End => self.error(
                token,
                format!("expected {what} but reached the end of the input"),
            ),
            kind => self.error(token, format!("expected {what}, found {}", kind.describe())),
        }
    }

    /// Reads a token that must be `kind`.
    fn expect(&mut self, kind: Tok<'_>, what: &str) -> Result<(), ParseError> {
        let token = self.next();
        if token.kind == kind {
            Ok(())
        } else {
            Err(self.expected(what, token))
        }
    }

    /// After an item of a list: `true` after a `,`, `false` after the closing `)`.
    fn list_continues(&mut self) -> Result<bool, ParseError> {
        let token = self.next();
        match token.kind {
            Tok::Comma => Ok(true),
            Tok::Close => Ok(false),
            _ => Err(self.expected("')' or ','", token)),
        }
    }

    /// Reads an EWKT `SRID=<integer>;` prefix, if there is one: its SRID (`None` also for
    /// one beyond 32 bits, which no registry uses).
    fn srid_prefix(&mut self) -> Result<Option<u32>, ParseError> {
        let saved = self.pos;
        if !self.eat_word("SRID") {
            return Ok(None);
        }
        if self.peek().kind != Tok::Equals {
            self.pos = saved;
            return Ok(None);
        }
        self.next();
        let token = self.next();
        let srid = match token.kind {
            Tok::Word(w) if w.bytes().all(|b| b.is_ascii_digit()) => w.parse().ok(),
            _ => return Err(self.expected("an SRID number after 'SRID='", token)),
        };
        self.expect(Tok::Semicolon, "';' after the SRID")?;
        Ok(srid)
    }

    /// Reads one geometry, `depth` collections deep, appending its polygons.
    fn geometry(&mut self, depth: usize) -> Result<(), ParseError> {
        let token = self.next();
        if depth > MAX_DEPTH {
            return Err(self.error(
                token,
                format!("geometry collections nested deeper than {MAX_DEPTH} levels"),
            ));
        }
        let Tok::Word(word) = token.kind else {
            return Err(self.expected(GEOMETRY_TYPES, token));
        };
        let Some((kind, glued)) = classify(word) else {
            let other = split_type(word, &OTHER_TYPES);
            let found = match other {
                Some((name, _)) => name.to_string(),
                None => quote(word),
            };
            let error = self.error(token, format!("expected {GEOMETRY_TYPES}, found {found}"));
            return match other {
                // A member of a collection: skipped, one failed part.
                Some((name, glued)) if depth > 0 => {
                    self.skip_body(name, glued)?;
                    self.parts.push(Err(error));
                    Ok(())
                }
                _ => Err(error),
            };
        };
        let tag = self.dimension(glued);
        // The tag of a collection's member is its own (a collection's is not inherited).
        self.measured = match tag {
            Some(tag) => tag.eq_ignore_ascii_case("M"),
            // Glued (`POLYGONM`): an `M` not after a `Z`.
            None => {
                let upper = word.to_ascii_uppercase();
                glued && upper.ends_with('M') && !upper.ends_with("ZM")
            }
        };
        if self.eat_word("EMPTY") {
            return Ok(());
        }
        match kind {
            Kind::Polygon => {
                let polygon = self.polygon("'(' or EMPTY after POLYGON")?;
                let part = self.stored(polygon);
                self.parts.push(part);
            }
            Kind::MultiPolygon => {
                self.expect(Tok::Open, "'(' or EMPTY after MULTIPOLYGON")?;
                loop {
                    if !self.eat_word("EMPTY") {
                        let polygon = self.polygon("'(' opening a polygon, or EMPTY")?;
                        let part = self.stored(polygon);
                        self.parts.push(part);
                    }
                    if !self.list_continues()? {
                        break;
                    }
                }
            }
            Kind::Collection => {
                self.expect(Tok::Open, "'(' or EMPTY after GEOMETRYCOLLECTION")?;
                loop {
                    self.geometry(depth + 1)?;
                    if !self.list_continues()? {
                        break;
                    }
                }
            }
        }
        Ok(())
    }

    /// Skips a dimension tag (`Z`, `M`, `ZM`) after a geometry keyword, unless one is `glued`
    /// to it; returns the tag skipped.
    fn dimension(&mut self, glued: bool) -> Option<&'static str> {
        if glued {
            return None;
        }
        ["ZM", "Z", "M"].into_iter().find(|&tag| self.eat_word(tag))
    }

    /// Skips the rest of a geometry of another type `name` (after its keyword): its dimension
    /// tag, then `EMPTY` or a body of balanced parentheses holding words and commas.
    fn skip_body(&mut self, name: &str, glued: bool) -> Result<(), ParseError> {
        self.dimension(glued);
        if self.eat_word("EMPTY") {
            return Ok(());
        }
        self.expect(Tok::Open, &format!("'(' or EMPTY after {name}"))?;
        let mut open = 1usize;
        while open > 0 {
            let token = self.next();
            match token.kind {
                Tok::Open => open += 1,
                Tok::Close => open -= 1,
                Tok::Word(_) | Tok::Comma => {}
                Tok::Semicolon | Tok::Equals | Tok::End => {
                    return Err(self.expected("')' or ','", token))
                }
            }
        }
        Ok(())
    }

    /// Reads `( ring, ... )`; `what` names the opening parenthesis in an error.
    fn polygon(&mut self, what: &str) -> Result<RawPolygon, ParseError> {
        self.expect(Tok::Open, what)?;
        self.dimensions = None;
        self.vertices = 0;
        self.ordinates = Vec::new();
        let mut rings = Vec::new();
        loop {
            let ring = self.ring()?;
            if self.no_room.is_none() {
                rings.push(ring);
            } else {
                rings.clear(); // the polygon is dropped: its memory goes back at once
            }
            if !self.list_continues()? {
                break;
            }
        }
        let dims = self
            .dimensions
            .and_then(|count| super::Dims::of(count, self.measured));
        let values = std::mem::take(&mut self.ordinates);
        let ordinates = dims.map(|dims| super::Ordinates { dims, values });
        Ok(RawPolygon { rings, ordinates })
    }

    /// Reads `( point, ... )`, without its repeated closing point.
    fn ring(&mut self) -> Result<Vec<[Decimal; 2]>, ParseError> {
        let token = self.next();
        match token.kind {
            Tok::Open => {}
            Tok::Word(w) if w.eq_ignore_ascii_case("EMPTY") => {
                return Err(self.error(
                    token,
                    "empty ring: a ring cannot be EMPTY, expected '(' and its points",
                ));
            }
            _ => return Err(self.expected("'(' opening a ring", token)),
        }
        if self.peek().kind == Tok::Close {
            return Err(self.error(
                token,
                "empty ring '()': expected points `x y` separated by commas",
            ));
        }
        let mut ring = Vec::new();
        loop {
            let token = self.peek();
            let (point, extra) = self.point()?;
            self.count_vertex(token, &mut ring, &point);
            // Memory refused: the polygon is dropped and read on without storing its points.
            if self.no_room.is_none() && ring.try_reserve(1).is_err() {
                let message = format!(
                    "not enough memory to hold this polygon: {} vertices of the ring read, no room for more",
                    ring.len()
                );
                ring = Vec::new();
                self.no_room = Some(self.error(token, message));
            }
            if self.no_room.is_none() {
                ring.push(point);
                if self.ordinates.try_reserve(2).is_err() {
                    ring = Vec::new();
                    self.no_room =
                        Some(self.error(token, "not enough memory to hold this polygon"));
                } else {
                    self.ordinates.extend(extra.into_iter().flatten());
                }
            }
            if !self.list_continues()? {
                break;
            }
        }
        // The closing vertex is not a vertex of the polygon: not counted against the cap.
        if drop_closing_vertex(&mut ring) {
            self.vertices -= 1;
            // The closing point's z and m go with it.
            let extra = self.dimensions.unwrap_or(2).saturating_sub(2);
            self.ordinates
                .truncate(self.ordinates.len().saturating_sub(extra));
        }
        Ok(ring)
    }

    /// Counts one more vertex of the polygon; one too many drops it (`ring`, and the rings
    /// before, by [`Parser::polygon`]) and makes it a failed part, located at `token`. A point
    /// repeating the ring's first may be its closing one, which the polygon does not count: it
    /// may be one past the cap (if another point follows in the ring, that one is too many).
    fn count_vertex(
        &mut self,
        token: Token<'_>,
        ring: &mut Vec<[Decimal; 2]>,
        point: &[Decimal; 2],
    ) {
        self.vertices += 1;
        let closing = self.vertices == self.max_vertices + 1 && ring.first() == Some(point);
        if self.vertices > self.max_vertices && !closing && self.no_room.is_none() {
            *ring = Vec::new();
            let message = too_many_vertices(self.max_vertices, "one polygon");
            self.no_room = Some(self.error(token, message));
        }
    }

    /// The part a polygon read makes: the polygon, or the error of memory refused for it.
    fn stored(&mut self, polygon: RawPolygon) -> Result<RawPolygon, ParseError> {
        match self.no_room.take() {
            Some(error) => Err(error),
            None => Ok(polygon),
        }
    }

    /// Reads `x y [z [m]]`: `x` and `y`, and the values after them (`None` for NaN).
    fn point(&mut self) -> Result<([Decimal; 2], [Option<super::Ordinate>; 2]), ParseError> {
        let first_token = self.next();
        let Tok::Word(x) = first_token.kind else {
            return Err(self.expected("a number", first_token));
        };
        let x = parse_number(x).map_err(|m| self.error(first_token, m))?;
        let second = self.next();
        let Tok::Word(y) = second.kind else {
            return Err(self.error(
                first_token,
                "a point needs at least 2 coordinates `x y`, found 1",
            ));
        };
        let y = parse_number(y).map_err(|m| self.error(second, m))?;
        let mut count = 2;
        let mut extras = [None, None];
        for slot in &mut extras {
            let token = self.peek();
            let Tok::Word(extra) = token.kind else { break };
            self.next();
            count += 1;
            // z and m must be numbers; NaN is a common "no value" for them.
            *slot = Some(match Decimal::parse(extra) {
                Ok(d) => Some(d),
                Err(NumberError::NonFinite(_)) if extra.eq_ignore_ascii_case("nan") => None,
                Err(_) => {
                    let message = parse_number(extra).err().unwrap_or_default();
                    return Err(self.error(token, message));
                }
            });
        }
        let token = self.peek();
        if let Tok::Word(w) = token.kind {
            let message = format!(
                "a point has at most 4 coordinates `x y z m`, found a 5th: {}",
                quote(w)
            );
            return Err(self.error(token, message));
        }
        match self.dimensions {
            None => self.dimensions = Some(count),
            Some(first) if first != count => {
                let hint = if count > first {
                    " (a missing comma?)"
                } else {
                    ""
                };
                let message = format!(
                    "this point has {count} coordinates but the polygon's first point has {first}{hint}"
                );
                return Err(self.error(first_token, message));
            }
            Some(_) => {}
        }
        Ok(([x, y], extras))
    }

    /// Whether a further geometry (its type keyword, or `SRID=`) starts on a later line than the
    /// end of the one just read, after an optional `;`: WKT lines, one geometry per line, read
    /// one after the other. A second geometry on the same line stays an error ([`Self::end`]).
    fn next_line_geometry(&mut self) -> bool {
        let saved = self.pos;
        if self.peek().kind == Tok::Semicolon {
            self.next();
        }
        let token = self.peek();
        let starts = matches!(token.kind, Tok::Word(w) if is_geometry_keyword(w) || w.eq_ignore_ascii_case("SRID"));
        let between = self.text.get(saved..token.offset).unwrap_or_default();
        if starts && between.contains('\n') {
            return true;
        }
        self.pos = saved;
        false
    }

    /// Checks that nothing but an optional `;` follows the geometry.
    fn end(&mut self) -> Result<(), ParseError> {
        if self.peek().kind == Tok::Semicolon {
            self.next();
        }
        let token = self.peek();
        match token.kind {
            Tok::End => Ok(()),
            kind => {
                let rest = quote(self.text.get(token.offset..).unwrap_or_default());
                let hint = match kind {
                    Tok::Word(w) if is_geometry_keyword(w) => {
                        " (a second geometry is not allowed; wrap several in a GEOMETRYCOLLECTION or MULTIPOLYGON)"
                    }
                    _ => "",
                };
                Err(self.error(
                    token,
                    format!("unexpected text after the geometry: {rest}{hint}"),
                ))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::read::{Dims, Ordinates};
    use crate::test_support::{as_f64, d, ring};
    use std::str::FromStr;

    fn error(text: &str) -> String {
        read(text).expect_err(text).to_string()
    }

    #[test]
    fn wkt_lines_are_read_one_geometry_per_line_and_a_second_on_one_line_is_an_error() {
        // What `--to wkt` writes: one collection of triangles per line, EMPTY for a failure.
        let text =
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1, 0 0)), POLYGON ((1 0, 1 1, 0 1, 1 0)))\n\
                    GEOMETRYCOLLECTION EMPTY\n\
                    SRID=4326;POLYGON Z ((5 5 1, 6 5 1, 5 6 1));\n\
                    # a comment\n\
                    MULTIPOLYGON (((0 0, 2 0, 0 2)))\n";
        let parts = read_parts(text).unwrap();
        let sizes: Vec<usize> = parts
            .iter()
            .map(|p| p.as_ref().unwrap().rings[0].len())
            .collect();
        assert_eq!(sizes, [3, 3, 3, 3]);
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1)) POLYGON ((0 0, 1 0, 0 1))\nPOLYGON ((0 0, 1 0, 0 1))"),
            "line 1, column 27: unexpected text after the geometry: \"POLYGON ((0 0, 1 0, 0 1))\" \
             (a second geometry is not allowed; wrap several in a GEOMETRYCOLLECTION or MULTIPOLYGON)"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1))\ngarbage"),
            "line 2, column 1: unexpected text after the geometry: \"garbage\""
        );
    }

    #[test]
    fn a_polygon_past_the_cap_on_vertices_fails_alone() {
        // Rings counted together, as the output counts them (closing vertices left out); each
        // polygon counted alone.
        let text = "GEOMETRYCOLLECTION (POLYGON ((0 0, 9 0, 9 9, 0 0), (1 1, 2 1, 1 2, 1 1)), \
                    MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 5 6, 5 5))))";
        let ok = |parts: Vec<Result<RawPolygon, ParseError>>| -> Vec<bool> {
            parts.iter().map(Result::is_ok).collect()
        };
        assert_eq!(ok(read_parts_within(text, 6).unwrap()), [true, true, true]);
        let parts = read_parts_within(text, 5).unwrap();
        assert_eq!(ok(parts.clone()), [false, true, true]);
        let error = parts[0].as_ref().unwrap_err().to_string();
        assert!(
            error.starts_with("line 1, column 63: too many vertices: more than 5 in one polygon"),
            "{error}"
        );
        // Exactly the cap, closed or not; a point repeating the first that is not the last
        // counts.
        for text in [
            "POLYGON ((0 0, 1 0, 0 1, 0 0))",
            "POLYGON ((0 0, 1 0, 0 1))",
        ] {
            assert_eq!(ok(read_parts_within(text, 3).unwrap()), [true], "{text}");
        }
        let through = "POLYGON ((0 0, 1 0, 1 1, 0 0, 0 1, 0 0))";
        assert_eq!(ok(read_parts_within(through, 4).unwrap()), [false]);
        assert_eq!(ok(read_parts_within(through, 5).unwrap()), [true]);
        // The rest of a polygon past the cap is still read: a syntax error in it is reported.
        let bad = "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 2, x 3)), ((5 5, 6 5, 5 6)))";
        assert!(read_parts_within(bad, 3)
            .unwrap_err()
            .to_string()
            .contains("`x` is not a number"));
    }

    #[test]
    fn reads_a_polygon_with_and_without_closing_point() {
        let closed = read("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))").unwrap();
        let open = read("polygon((0 0,4 0,4 4,0 4))").unwrap();
        assert_eq!(closed, open);
        assert_eq!(
            closed[0].rings,
            vec![ring(&[("0", "0"), ("4", "0"), ("4", "4"), ("0", "4")])]
        );
    }

    #[test]
    fn reads_holes_in_order() {
        let text = "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (1 1, 2 1, 2 2, 1 1), (5 5, 6 5, 6 6))";
        let polygons = read(text).unwrap();
        assert_eq!(polygons.len(), 1);
        assert_eq!(polygons[0].rings.len(), 3);
        assert_eq!(
            polygons[0].rings[1],
            ring(&[("1", "1"), ("2", "1"), ("2", "2")])
        );
        assert_eq!(
            polygons[0].rings[2],
            ring(&[("5", "5"), ("6", "5"), ("6", "6")])
        );
    }

    #[test]
    fn keeps_decimals_exact() {
        let polygons = read("POLYGON ((0 0, 0.1 0.3, 0.2 0.6, -1.5E-3 +2e2))").unwrap();
        let r = &polygons[0].rings[0];
        assert_eq!(r[1], [d("0.1"), d("0.3")]);
        assert_eq!(r[2], [d("0.2"), d("0.6")]);
        assert_eq!(r[3], [d("-0.0015"), d("200")]);
    }

    #[test]
    fn keeps_z_and_m_values_beside_x_and_y() {
        let plain = read("POLYGON ((0 0, 1 0, 0 1))").unwrap();
        assert_eq!(plain[0].ordinates, None);
        let n = |v: &str| (v != "NaN").then(|| d(v));
        // The polygon, its dimensions, and its vertices' values (the closing point's go with it;
        // without a tag, 3 numbers are x y z, as GEOS and PostGIS read them).
        let cases: [(&str, Dims, &str); 8] = [
            ("POLYGON Z ((0 0 5, 1 0 6, 0 1 7))", Dims::Z, "5 6 7"),
            ("POLYGON M ((0 0 5, 1 0 6, 0 1 7, 0 0 8))", Dims::M, "5 6 7"),
            (
                "POLYGON ZM ((0 0 5 1, 1 0 6 2, 0 1 7 NaN))",
                Dims::Zm,
                "5 1 6 2 7 NaN",
            ),
            ("POLYGONZ ((0 0 5, 1 0 6, 0 1 7))", Dims::Z, "5 6 7"),
            ("POLYGONM ((0 0 5, 1 0 6, 0 1 7))", Dims::M, "5 6 7"),
            (
                "polygonzm((0 0 5 1,1 0 6 2,0 1 7 3))",
                Dims::Zm,
                "5 1 6 2 7 3",
            ),
            ("POLYGON ((0 0 1, 1 0 2.50, 0 1 -3))", Dims::Z, "1 2.5 -3"),
            (
                "GEOMETRYCOLLECTION M (POLYGON Z ((0 0 1, 1 0 2, 0 1 3)))",
                Dims::Z,
                "1 2 3",
            ),
        ];
        for (text, dims, values) in cases {
            let read = read(text).unwrap();
            assert_eq!(read[0].rings, plain[0].rings, "{text}");
            let expected = Ordinates {
                dims,
                values: values.split(' ').map(n).collect(),
            };
            assert_eq!(read[0].ordinates.as_ref(), Some(&expected), "{text}");
        }
        assert_eq!(
            read("POLYGON Z ((0 0 1, 1 0 inf, 0 1 3))")
                .unwrap_err()
                .to_string(),
            "line 1, column 24: `inf` is not a finite number"
        );
        // Points of one polygon with different numbers of coordinates: most likely a missing
        // comma, which would otherwise swallow a point silently. Each polygon decides alone.
        assert_eq!(
            read("POLYGON ((0 0, 4 0 4 4, 0 4))").unwrap_err().to_string(),
            "line 1, column 16: this point has 4 coordinates but the polygon's first point has 2 (a missing comma?)"
        );
        assert_eq!(
            read("POLYGON ((0 0 1, 1 0, 0 1 2 3))")
                .unwrap_err()
                .to_string(),
            "line 1, column 18: this point has 2 coordinates but the polygon's first point has 3"
        );
        let mixed = "MULTIPOLYGON (((0 0, 1 0, 0 1)), ((0 0 9, 1 0 9, 0 1 9)))";
        assert_eq!(read(mixed).unwrap().len(), 2);
    }

    #[test]
    fn reads_multipolygons_and_collections() {
        let text = "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1)), POLYGON EMPTY, \
                    MULTIPOLYGON (((2 2, 3 2, 2 3)), EMPTY, ((4 4, 5 4, 4 5), (4.1 4.1, 4.2 4.1, 4.1 4.2))), \
                    GEOMETRYCOLLECTION (GEOMETRYCOLLECTION (POLYGON ((6 6, 7 6, 6 7)))), GEOMETRYCOLLECTION EMPTY)";
        let polygons = read(text).unwrap();
        let firsts: Vec<_> = polygons.iter().map(|p| p.rings[0][0]).collect();
        assert_eq!(
            firsts,
            vec![
                [d("0"), d("0")],
                [d("2"), d("2")],
                [d("4"), d("4")],
                [d("6"), d("6")]
            ]
        );
        assert_eq!(polygons[2].rings.len(), 2);
        let multi =
            read("MULTIPOLYGON Z (((0 0 0, 1 0 0, 0 1 0)), ((5 5 1, 6 5 1, 5 6 1, 5 5 1)))")
                .unwrap();
        assert_eq!(multi.len(), 2);
        assert_eq!(multi[1].rings[0].len(), 3);
    }

    #[test]
    fn accepts_layout_variations() {
        let expected = read("POLYGON ((0 0, 1 0, 0 1))").unwrap();
        for text in [
            "  POLYGON\r\n(\r\n(0 0,\r\n 1 0,\t0 1)\r\n)\r\n",
            "POLYGON ((0 0, 1 0, 0 1));",
            "POLYGON ((0 0, 1 0, 0 1)) ;  \n",
            "SRID=4326;POLYGON ((0 0, 1 0, 0 1))",
            "srid = 4326 ; POLYGON ((0 0, 1 0, 0 1))",
            "# a comment\nPOLYGON ((0 0, 1 0, 0 1)) # trailing\n",
            "\u{feff}POLYGON ((0 0, 1 0, 0 1))",
            "POLYGON((0 0,1 0,0 1))",
        ] {
            assert_eq!(read(text).unwrap(), expected, "{text:?}");
        }
    }

    #[test]
    fn short_rings_are_left_to_validation() {
        let polygons = read("POLYGON ((0 0, 4 0, 4 4), (1 1), (2 2, 2 2))").unwrap();
        assert_eq!(polygons[0].rings[1].len(), 1);
        assert_eq!(polygons[0].rings[2].len(), 1);
    }

    #[test]
    fn rejects_empty_input_and_empty_geometries() {
        for text in ["", "   \n\t", "# just a comment\n"] {
            assert_eq!(error(text), "empty input: no polygon found");
        }
        for text in [
            "POLYGON EMPTY",
            "GEOMETRYCOLLECTION (POLYGON EMPTY, MULTIPOLYGON EMPTY)",
            "MULTIPOLYGON (EMPTY)",
        ] {
            assert_eq!(error(text), "no polygon found: the geometry is EMPTY");
        }
    }

    #[test]
    fn rejects_wrong_geometry_types() {
        assert_eq!(
            error("LINESTRING (0 0, 1 1)"),
            "line 1, column 1: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found LINESTRING"
        );
        assert_eq!(
            error("GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1)),\n  point z (1 2 3))"),
            "line 2, column 3: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found POINT"
        );
        assert_eq!(
            error("0 0\n1 0"),
            "line 1, column 1: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found \"0\""
        );
        assert_eq!(
            error("(0 0)"),
            "line 1, column 1: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found '('"
        );
    }

    /// The parts of `text`: `None` for a polygon, the message of a failed part.
    fn parts(text: &str) -> Vec<Option<String>> {
        read_parts(text)
            .unwrap()
            .into_iter()
            .map(|part| part.err().map(|e| e.to_string()))
            .collect()
    }

    #[test]
    fn a_collection_member_of_another_type_is_skipped_and_reported() {
        let found = |line: usize, column: usize, name: &str| {
            Some(format!(
                "line {line}, column {column}: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found {name}"
            ))
        };
        let text = "GEOMETRYCOLLECTION (POINT (1 2), POLYGON ((0 0, 1 0, 0 1)))";
        assert_eq!(parts(text), [found(1, 21, "POINT"), None]);
        let polygon = read_parts(text).unwrap().pop().unwrap().unwrap();
        assert_eq!(polygon, read("POLYGON ((0 0, 1 0, 0 1))").unwrap()[0]);
        // `read`, all or nothing, fails on it, as before.
        assert_eq!(error(text), found(1, 21, "POINT").unwrap());
        // Every other type, with dimension tags, EMPTY, nested parentheses, in nested
        // collections, between polygons and MultiPolygon parts.
        let text = "GEOMETRYCOLLECTION (\n\
            MULTIPOLYGON (((0 0, 1 0, 0 1)), ((5 5, 6 5, 5 6))),\n\
            linestring zm (0 0 1 2, 1 1 1 2), POINT EMPTY,\n\
            GEOMETRYCOLLECTION (MULTILINESTRINGZ ((0 0 0, 1 1 1), (2 2 2, 3 3 3)), POLYGON ((0 0, 2 0, 0 2))),\n\
            CURVEPOLYGON (CIRCULARSTRING (0 0, 1 1, 2 0, 1 -1, 0 0)), TIN EMPTY, GEOMETRYCOLLECTION EMPTY)";
        assert_eq!(
            parts(text),
            [
                None,
                None,
                found(3, 1, "LINESTRING"),
                found(3, 35, "POINT"),
                found(4, 21, "MULTILINESTRING"),
                None,
                found(5, 1, "CURVEPOLYGON"),
                found(5, 59, "TIN"),
            ]
        );
        // Only points: no polygon, one error each.
        assert_eq!(
            parts("GEOMETRYCOLLECTION (POINT (1 2), MULTIPOINT ((1 2), (3 4)))").len(),
            2
        );
        // At the top level it is still the input's error, and a syntax error in a skipped body
        // is still a syntax error of the input.
        assert_eq!(error("POINT (1 2)"), found(1, 1, "POINT").unwrap());
        for (bad, message) in [
            (
                "GEOMETRYCOLLECTION (POINT (1 2, POLYGON ((0 0, 1 0, 0 1)))",
                "line 1, column 59: expected ')' or ',' but reached the end of the input",
            ),
            (
                "GEOMETRYCOLLECTION (POINT (1 2); POLYGON ((0 0, 1 0, 0 1)))",
                "line 1, column 32: expected ')' or ',', found ';'",
            ),
            (
                "GEOMETRYCOLLECTION (POINT 1 2, POLYGON ((0 0, 1 0, 0 1)))",
                "line 1, column 27: expected '(' or EMPTY after POINT, found \"1\"",
            ),
            (
                "GEOMETRYCOLLECTION (POINT (1 2)) POLYGON ((0 0, 1 0, 0 1))",
                "line 1, column 34: unexpected text after the geometry: \"POLYGON ((0 0, 1 0, 0 1))\" \
                 (a second geometry is not allowed; wrap several in a GEOMETRYCOLLECTION or MULTIPOLYGON)",
            ),
            (
                "GEOMETRYCOLLECTION (POINTS (1 2), POLYGON ((0 0, 1 0, 0 1)))",
                "line 1, column 21: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found \"POINTS\"",
            ),
        ] {
            assert_eq!(read_parts(bad).unwrap_err().to_string(), message, "{bad}");
        }
    }

    #[test]
    fn rejects_syntax_errors_with_line_and_column() {
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1)"),
            "line 1, column 25: expected ')' or ',' but reached the end of the input"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1"),
            "line 1, column 24: expected ')' or ',' but reached the end of the input"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1))"),
            "line 1, column 16: a point needs at least 2 coordinates `x y`, found 1"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1 2 3 4))"),
            "line 1, column 29: a point has at most 4 coordinates `x y z m`, found a 5th: \"4\""
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0,\n  0 NaN))"),
            "line 2, column 5: `NaN` is not a finite number"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 abc))"),
            "line 1, column 23: `abc` is not a number"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1) (2 2, 3 3, 2 3))"),
            "line 1, column 26: expected ')' or ',', found '('"
        );
        assert_eq!(
            error("POLYGON (0 0, 1 0, 0 1)"),
            "line 1, column 10: expected '(' opening a ring, found \"0\""
        );
        assert_eq!(
            error("MULTIPOLYGON ((0 0, 1 0, 0 1))"),
            "line 1, column 16: expected '(' opening a ring, found \"0\""
        );
        assert_eq!(
            error("POLYGON (())"),
            "line 1, column 10: empty ring '()': expected points `x y` separated by commas"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1), EMPTY)"),
            "line 1, column 27: empty ring: a ring cannot be EMPTY, expected '(' and its points"
        );
        assert_eq!(
            error("POLYGON [[0 0, 1 0, 0 1]]"),
            "line 1, column 9: expected '(' or EMPTY after POLYGON, found \"[[0\""
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0; 0 1))"),
            "line 1, column 19: expected ')' or ',', found ';'"
        );
        assert_eq!(
            error("SRID=abc;POLYGON ((0 0, 1 0, 0 1))"),
            "line 1, column 6: expected an SRID number after 'SRID=', found \"abc\""
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1, ))"),
            "line 1, column 26: expected a number, found ')'"
        );
    }

    #[test]
    fn rejects_text_after_the_geometry() {
        // A second geometry on the same line (on a line of its own it is read: WKT lines).
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1)) POLYGON ((5 5, 6 5, 5 6, 5 5), (1 1, 2 2, 1 2))"),
            "line 1, column 27: unexpected text after the geometry: \"POLYGON ((5 5, 6 5, 5 6, 5 5), (1 1, 2 2...\" \
             (a second geometry is not allowed; wrap several in a GEOMETRYCOLLECTION or MULTIPOLYGON)"
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1)))"),
            "line 1, column 26: unexpected text after the geometry: \")\""
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1)); x"),
            "line 1, column 28: unexpected text after the geometry: \"x\""
        );
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 1));;"),
            "line 1, column 27: unexpected text after the geometry: \";\""
        );
    }

    #[test]
    fn never_panics_on_hostile_input() {
        let deep = format!(
            "{}POLYGON ((0 0, 1 0, 0 1)){}",
            "GEOMETRYCOLLECTION (".repeat(100),
            ")".repeat(100)
        );
        assert_eq!(
            error(&deep),
            "line 1, column 1301: geometry collections nested deeper than 64 levels"
        );
        let parens = format!("POLYGON {}", "(".repeat(100_000));
        assert_eq!(
            error(&parens),
            "line 1, column 11: expected a number, found '('"
        );
        let long = format!("POLYGON ((0 {}", "1".repeat(10_000_000));
        let message = error(&long);
        assert!(message.starts_with("line 1, column 13: `111"), "{message}");
        assert!(message.len() < 120, "{message}");
        let binary: String = (0u8..=255).map(char::from).collect();
        assert!(read(&binary).is_err());
        assert_eq!(
            error("POLYGON ((0 0, 1 0, 0 ∞))"),
            "line 1, column 23: `∞` is not a number"
        );
        assert_eq!(error("POLYGÖN ((0 0))"), "line 1, column 1: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found \"POLYGÖN\"");
        assert_eq!(
            error("é POLYGON"),
            "line 1, column 1: expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found \"é\""
        );
    }

    /// The polygons of a geometry parsed by the `wkt` crate, closing points dropped.
    fn wkt_crate_polygons(geometry: &wkt::Wkt<f64>, out: &mut Vec<Vec<Vec<[f64; 2]>>>) {
        let polygon = |p: &wkt::types::Polygon<f64>| -> Vec<Vec<[f64; 2]>> {
            p.rings()
                .iter()
                .map(|r| {
                    let mut ring: Vec<[f64; 2]> = r.coords().iter().map(|c| [c.x, c.y]).collect();
                    if ring.len() > 1 && ring.first() == ring.last() {
                        ring.pop();
                    }
                    ring
                })
                .collect()
        };
        match geometry {
            wkt::Wkt::Polygon(p) if !p.rings().is_empty() => out.push(polygon(p)),
            wkt::Wkt::MultiPolygon(m) => out.extend(
                m.polygons()
                    .iter()
                    .filter(|p| !p.rings().is_empty())
                    .map(polygon),
            ),
            wkt::Wkt::GeometryCollection(c) => c
                .geometries()
                .iter()
                .for_each(|g| wkt_crate_polygons(g, out)),
            _ => {}
        }
    }

    #[test]
    fn agrees_with_the_wkt_crate() {
        for text in [
            "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 2 1, 2 2, 1 1))",
            "POLYGON ((0.1 0.3, 0.2 0.6, -1e-3 7.25, 123456.789 -0.000001))",
            "POLYGON Z ((0 0 1, 1 0 2, 0 1 3, 0 0 1))",
            "MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((2 2, 3 2, 2 3), (2.1 2.1, 2.2 2.1, 2.1 2.2)))",
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 1 0, 0 1)), MULTIPOLYGON (((5 5, 6 5, 5 6))))",
        ] {
            let ours = as_f64(&read(text).unwrap());
            let theirs = wkt::Wkt::<f64>::from_str(text).unwrap();
            let mut expected = Vec::new();
            wkt_crate_polygons(&theirs, &mut expected);
            assert_eq!(ours, expected, "{text}");
        }
    }
}
