//! What reading yields, below both the readers (`io::read`, which make it) and the geometry
//! (`geom`, which validates it): a [`RawPolygon`] (rings of exact decimals, the Z and M values
//! of its vertices), or a [`ParseError`] naming where the input is wrong.
//!
//! Contract: each ring WITHOUT its repeated closing vertex, outer ring first, holes in input
//! order, so that the vertex numbering of `docs/cli.md` is the order of the vertices over the
//! rings; nothing else is cleaned (duplicates, winding and validity are `geom`'s business).

use crate::geom::decimal::Decimal;
use std::fmt;

/// A polygon as read: rings of exact coordinates, outer ring first.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct RawPolygon {
    /// `rings[0]` is the outer boundary, `rings[1..]` the holes; no repeated closing vertex.
    pub rings: Vec<Vec<[Decimal; 2]>>,
    /// The Z and M values of its vertices, when its positions have them (`POLYGON Z`,
    /// `[x, y, z]`, WKB Z/M/ZM); `None` for plain `x y` positions. Triangulation is in x, y
    /// only; the writers give each output vertex its input vertex's values.
    pub ordinates: Option<Ordinates>,
}

/// Which values besides x and y each position of a polygon has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dims {
    /// `x y z`.
    Z,
    /// `x y m` (WKT `POLYGON M`, WKB M).
    M,
    /// `x y z m`.
    Zm,
}

impl Dims {
    /// The dimensions of a position of `count` numbers (3 or 4), `measured` when its geometry
    /// is tagged `M` (then 3 numbers are `x y m`); `None` for 2 numbers.
    pub fn of(count: usize, measured: bool) -> Option<Dims> {
        match count {
            3 if measured => Some(Dims::M),
            3 => Some(Dims::Z),
            4 => Some(Dims::Zm),
            _ => None,
        }
    }

    /// How many values a vertex has besides x and y (1 or 2).
    pub fn count(self) -> usize {
        if self == Dims::Zm {
            2
        } else {
            1
        }
    }

    /// Whether the positions have a Z value.
    pub fn has_z(self) -> bool {
        self != Dims::M
    }

    /// Whether the positions have an M value.
    pub fn has_m(self) -> bool {
        self != Dims::Z
    }

    /// The WKT dimension tag: `Z`, `M` or `ZM`.
    pub fn tag(self) -> &'static str {
        match self {
            Dims::Z => "Z",
            Dims::M => "M",
            Dims::Zm => "ZM",
        }
    }
}

/// A Z or M value as read: its exact decimal, or `None` for NaN (which WKT and WKB use for
/// "no value").
pub type Ordinate = Option<Decimal>;

/// The Z and M values of a polygon's vertices, in input vertex numbering (the order of the
/// vertices over the rings, without the closing ones).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ordinates {
    /// Which values each vertex has.
    pub dims: Dims,
    /// `dims.count()` values per vertex (Z before M), vertex after vertex.
    pub values: Vec<Ordinate>,
}

impl Ordinates {
    /// No values yet, of `dims`.
    pub fn new(dims: Dims) -> Ordinates {
        Ordinates {
            dims,
            values: Vec::new(),
        }
    }

    /// The Z value of input vertex `vertex` (`None` without Z, or out of range).
    pub fn z(&self, vertex: usize) -> Option<&Ordinate> {
        self.dims
            .has_z()
            .then(|| self.values.get(vertex * self.dims.count()))
            .flatten()
    }

    /// The M value of input vertex `vertex` (`None` without M, or out of range).
    pub fn m(&self, vertex: usize) -> Option<&Ordinate> {
        let k = self.dims.count();
        self.dims
            .has_m()
            .then(|| self.values.get(vertex * k + k - 1))
            .flatten()
    }

    /// Vertex `vertex`'s values as WKT writes them after `x y`: ` 5` or ` 5 7` (NaN for a
    /// missing value); empty when out of range.
    pub fn wkt(&self, vertex: usize) -> String {
        let k = self.dims.count();
        let mut out = String::new();
        for value in self.values.iter().skip(vertex * k).take(k) {
            out.push(' ');
            match value {
                Some(d) => out.push_str(&d.to_string()),
                None => out.push_str("NaN"),
            }
        }
        out
    }

    /// Vertex `vertex`'s Z as a JSON number after `x, y` in a GeoJSON position: `, 5`
    /// (`, null` for NaN); empty without Z. GeoJSON positions have no M.
    pub fn geojson(&self, vertex: usize) -> String {
        match self.z(vertex) {
            Some(Some(z)) => format!(", {z}"),
            Some(None) => ", null".to_string(),
            None => String::new(),
        }
    }
}

/// A position in the input text, both 1-based.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Location {
    /// Line number, from 1.
    pub line: usize,
    /// Column in characters, from 1.
    pub column: usize,
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}, column {}", self.line, self.column)
    }
}

/// Why an input could not be read. `Display`: `line 3, column 14: expected ')' but found 'x'`.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}{message}", location.map(|l| format!("{l}: ")).unwrap_or_default())]
pub struct ParseError {
    /// Where the problem is, when the format allows saying so.
    pub location: Option<Location>,
    /// What is wrong, in words a user can act on (lowercase, no trailing period).
    pub message: String,
}

impl ParseError {
    /// An error at a known position.
    pub fn at(location: Location, message: impl Into<String>) -> ParseError {
        ParseError {
            location: Some(location),
            message: message.into(),
        }
    }

    /// An error without position.
    pub fn new(message: impl Into<String>) -> ParseError {
        ParseError {
            location: None,
            message: message.into(),
        }
    }
}
