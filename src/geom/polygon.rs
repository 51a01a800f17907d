//! The polygon type: exact grid coordinates, the spec's vertex numbering, normalised winding.
//!
//! Input contract: a [`RawPolygon`] (exact decimals, rings without closing vertex).
//! Output guarantee ([`AnyPolygon::from_raw`]): when every coordinate fits one integer grid per
//! polygon (multiplied by `10^scale`, `scale` the most decimal places used, then translated so the
//! minimum is 0) within [`MAX_COORD`], a fast [`Polygon`] of grid [`Point`]s; otherwise a
//! `Polygon<WidePoint>` on the input decimals themselves ([`crate::geom::wide`]); every kernel
//! predicate is exact either way. Exact consecutive duplicate vertices
//! are dropped with a [`Warning`]; kept vertices keep their input number (`id`). The outer ring is
//! stored counter-clockwise and every hole clockwise, so the interior is always on the left of
//! `i -> next(i)`. The polygon is then validated ([`crate::geom::validate`]).
//! Complexity: O(n log n) (the validation sweep dominates).

use super::decimal::Decimal;
use super::kernel::{cross, Area, Coord, Point, MAX_COORD};
use super::validate::{self, InvalidPolygon};
use super::wide::WidePoint;
use crate::raw::RawPolygon;
use std::borrow::Cow;
use std::fmt;
use std::ops::Range;

/// Which ring of a polygon: the outer boundary or a hole (numbered from 1 in input order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Ring {
    /// The outer boundary (ring 0).
    Outer,
    /// Hole `k` (ring `k`, from 1).
    Hole(usize),
}

impl Ring {
    /// The ring for a ring index (0 is the outer ring).
    pub fn from_index(index: usize) -> Ring {
        if index == 0 {
            Ring::Outer
        } else {
            Ring::Hole(index)
        }
    }
}

impl fmt::Display for Ring {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Ring::Outer => write!(f, "outer ring"),
            Ring::Hole(k) => write!(f, "hole {k}"),
        }
    }
}

/// Something the tool changed in the input, worth telling the user (on standard error).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Warning(pub String);

impl fmt::Display for Warning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// The map between input decimals and the exact integer grid.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Grid {
    /// Grid units per input unit are `10^scale`.
    scale: u32,
    /// The grid value (before translation) of grid point `(0, 0)`.
    origin: [i128; 2],
}

impl Grid {
    /// The input coordinate of grid value `value` on `axis` (0 = x, 1 = y), exactly, as text.
    pub fn format(&self, axis: usize, value: i64) -> String {
        let v = i128::from(value) + self.origin[axis];
        let digits = v.unsigned_abs().to_string();
        let sign = if v < 0 { "-" } else { "" };
        let scale = self.scale as usize;
        if scale == 0 {
            return format!("{sign}{digits}");
        }
        let padded = format!("{digits:0>width$}", width = scale + 1);
        let (int, frac) = padded.split_at(padded.len() - scale);
        let frac = frac.trim_end_matches('0');
        if frac.is_empty() {
            format!("{sign}{int}")
        } else {
            format!("{sign}{int}.{frac}")
        }
    }

    /// A point as `(x, y)` in input coordinates, exactly.
    pub fn format_point<P: Coord>(&self, p: P) -> String {
        format!("({}, {})", p.format(self, 0), p.format(self, 1))
    }

    /// The grid of a wide polygon: its points carry their input coordinates themselves.
    pub(crate) fn identity() -> Grid {
        Grid {
            scale: 0,
            origin: [0; 2],
        }
    }

    /// The input coordinates of a point, rounded to `f64` (for drawing only).
    pub fn to_f64<P: Coord>(&self, p: P) -> [f64; 2] {
        p.to_f64(self)
    }

    /// The input coordinates of a grid point, rounded to `f64`.
    pub(crate) fn grid_to_f64(&self, p: Point) -> [f64; 2] {
        let unit = 10f64.powi(self.scale as i32);
        [
            (i128::from(p.x) + self.origin[0]) as f64 / unit,
            (i128::from(p.y) + self.origin[1]) as f64 / unit,
        ]
    }
}

/// How a built polygon (`Polygon::build`, rings not yet known valid) becomes a valid one:
/// its validation sweep ([`Polygon::sweep`]), and beside it whatever the caller chooses to run
/// on the same rings (the pipeline: the plain triangulation for step 1, on a second core),
/// returned beside the valid polygon; then [`Polygon::settled`] on what the sweep learned.
/// [`SweepOnly`] runs the sweep alone.
pub(crate) trait Validation {
    /// What is made beside the sweep (the default: nothing made, e.g. for an invalid piece).
    type Beside: Default;

    /// `polygon` validated, as [`Polygon::validated`] returns it, with what was made beside.
    fn validated<P: Coord>(
        &self,
        polygon: Polygon<P>,
    ) -> Result<(Polygon<P>, Self::Beside), Vec<InvalidPolygon>>;
}

/// The validation sweep alone ([`Polygon::validated`]).
pub(crate) struct SweepOnly;

impl Validation for SweepOnly {
    type Beside = ();

    fn validated<P: Coord>(
        &self,
        polygon: Polygon<P>,
    ) -> Result<(Polygon<P>, ()), Vec<InvalidPolygon>> {
        Ok((polygon.validated()?, ()))
    }
}

/// A valid polygon with holes, its points of one exact kernel: the fast grid [`Point`]s (the
/// default) or [`WidePoint`]s.
///
/// Invariants (established by [`Polygon::from_raw`], checked by `check_invariants` in tests):
/// - vertices are stored ring after ring; ring 0 is the outer ring, counter-clockwise; rings
///   `1..` are the holes, clockwise; so the interior is on the left of every edge `i -> next(i)`;
/// - every ring has at least 3 vertices, non-zero area, no two vertices at the same point;
/// - the rings are simple, pairwise disjoint, and every hole lies inside the outer ring and
///   outside every other hole;
/// - `ids[i]` is the input vertex number of stored vertex `i` (spec numbering), strictly
///   increasing within the input order of each ring (reversed rings run backwards).
#[derive(Clone, Debug)]
pub struct Polygon<P = Point> {
    points: Vec<P>,
    ids: Vec<usize>,
    ring_starts: Vec<usize>,
    ring_of: Vec<u32>,
    input_vertices: usize,
    grid: Grid,
    /// With touching rings: the input ring of each stored vertex (`ring_of` then numbers the
    /// boundary walks); empty otherwise.
    source_ring: Vec<u32>,
    /// The number of touches joining rings into walks (input rings minus walks).
    touches: usize,
    /// With touching rings: whether each stored vertex is a copy of a touch point (its point
    /// is stored more than once); empty otherwise (all points distinct).
    copy: Vec<bool>,
}

/// A valid polygon of either kernel, as [`AnyPolygon::from_raw`] chose it.
#[derive(Clone, Debug)]
pub enum AnyPolygon {
    /// Its grid fits the fast kernel (`2^62` units).
    Fast(Polygon),
    /// Any other polygon: the wide kernel.
    Wide(Polygon<WidePoint>),
}

/// Runs `$body` with `$p` bound to the polygon of either kernel (one generic body, both kernels).
#[macro_export]
#[doc(hidden)]
macro_rules! with_polygon {
    ($any:expr, $p:ident => $body:expr) => {
        match $any {
            $crate::AnyPolygon::Fast($p) => $body,
            $crate::AnyPolygon::Wide($p) => $body,
        }
    };
}

impl AnyPolygon {
    /// Builds and validates a polygon from the reader's output, on the fast kernel when its grid
    /// fits, else on the wide one: any coordinates the readers accept.
    ///
    /// # Errors
    /// [`InvalidPolygon`]: the first problem found (see [`AnyPolygon::from_raw_all_errors`]).
    pub fn from_raw(raw: &RawPolygon) -> Result<(AnyPolygon, Vec<Warning>), InvalidPolygon> {
        AnyPolygon::from_raw_all_errors(raw).map_err(|mut errors| errors.swap_remove(0))
    }

    /// Like [`AnyPolygon::from_raw`], but returns every problem found (at least one on error).
    ///
    /// # Errors
    /// A non-empty list of [`InvalidPolygon`]s.
    pub fn from_raw_all_errors(
        raw: &RawPolygon,
    ) -> Result<(AnyPolygon, Vec<Warning>), Vec<InvalidPolygon>> {
        AnyPolygon::from_raw_validated(raw, &SweepOnly)
            .map(|(polygon, warnings, ())| (polygon, warnings))
    }

    /// [`AnyPolygon::from_raw_all_errors`], validated by `how`, with what it made beside.
    #[allow(clippy::type_complexity)]
    pub(crate) fn from_raw_validated<V: Validation>(
        raw: &RawPolygon,
        how: &V,
    ) -> Result<(AnyPolygon, Vec<Warning>, V::Beside), Vec<InvalidPolygon>> {
        match Polygon::from_raw_validated(raw, how) {
            Err(errors) if matches!(errors[..], [InvalidPolygon::CoordinatesTooLarge { .. }]) => {
                let (polygon, warnings) = Polygon::build_wide(raw).map_err(|e| vec![e])?;
                let (polygon, beside) = how.validated(polygon)?;
                Ok((AnyPolygon::Wide(polygon), warnings, beside))
            }
            other => other
                .map(|(polygon, warnings, beside)| (AnyPolygon::Fast(polygon), warnings, beside)),
        }
    }

    /// The fast polygon, if it is one.
    pub fn fast(&self) -> Option<&Polygon> {
        match self {
            AnyPolygon::Fast(p) => Some(p),
            AnyPolygon::Wide(_) => None,
        }
    }

    /// Whether the wide kernel holds it.
    pub fn is_wide(&self) -> bool {
        matches!(self, AnyPolygon::Wide(_))
    }

    /// Number of vertices kept (n, over all rings).
    pub fn len(&self) -> usize {
        with_polygon!(self, p => p.len())
    }

    /// Whether there are no vertices (never true for a valid polygon).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Number of holes (w).
    pub fn holes(&self) -> usize {
        with_polygon!(self, p => p.holes())
    }

    /// The number of touches between rings ([`Polygon::touches`]).
    pub fn touches(&self) -> usize {
        with_polygon!(self, p => p.touches())
    }

    /// The input vertex number of stored vertex `i`.
    pub fn id(&self, i: usize) -> usize {
        with_polygon!(self, p => p.id(i))
    }

    /// Vertex `i` as `(x, y)` in input coordinates, exactly.
    pub fn format_vertex(&self, i: usize) -> String {
        with_polygon!(self, p => p.format_vertex(i))
    }

    /// Vertex `i`'s coordinates `[x, y]` in input coordinates, exactly, as text.
    pub fn coordinates(&self, i: usize) -> [String; 2] {
        with_polygon!(self, p => {
            let q = p.point(i);
            [q.format(p.grid(), 0), q.format(p.grid(), 1)]
        })
    }

    /// Vertex `i`'s input coordinates rounded to `f64` (for drawing only).
    pub fn vertex_f64(&self, i: usize) -> [f64; 2] {
        with_polygon!(self, p => p.point(i).to_f64(p.grid()))
    }
}

impl AnyPolygon {
    /// The polygon for drawing only: a fast polygon itself; a wide one as a fast polygon of the
    /// same rings and numbers whose points are [`Polygon::drawing_point`]s (approximate, maybe
    /// not even valid: never for a decision).
    pub fn for_drawing(&self) -> Cow<'_, Polygon> {
        match self {
            AnyPolygon::Fast(p) => Cow::Borrowed(p),
            AnyPolygon::Wide(p) => {
                let (origin, scale, shift) = p.drawing_frame();
                let points = p
                    .points
                    .iter()
                    .map(|&q| q.drawing_point(origin, scale, shift))
                    .collect();
                Cow::Owned(Polygon {
                    points,
                    ids: p.ids.clone(),
                    ring_starts: p.ring_starts.clone(),
                    ring_of: p.ring_of.clone(),
                    input_vertices: p.input_vertices,
                    grid: p.grid,
                    source_ring: p.source_ring.clone(),
                    touches: p.touches,
                    copy: p.copy.clone(),
                })
            }
        }
    }
}

impl From<Polygon> for AnyPolygon {
    fn from(polygon: Polygon) -> AnyPolygon {
        AnyPolygon::Fast(polygon)
    }
}

impl From<Polygon<WidePoint>> for AnyPolygon {
    fn from(polygon: Polygon<WidePoint>) -> AnyPolygon {
        AnyPolygon::Wide(polygon)
    }
}

impl Polygon {
    /// Builds and validates a polygon on the fast kernel from the reader's output.
    ///
    /// # Errors
    /// [`InvalidPolygon`]: the first problem found (see [`Polygon::from_raw_all_errors`]);
    /// [`InvalidPolygon::CoordinatesTooLarge`] when the grid does not fit the fast kernel
    /// ([`AnyPolygon::from_raw`] then takes the wide one).
    pub fn from_raw(raw: &RawPolygon) -> Result<(Polygon, Vec<Warning>), InvalidPolygon> {
        Polygon::from_raw_all_errors(raw).map_err(|mut errors| errors.swap_remove(0))
    }

    /// Like [`Polygon::from_raw`], but returns every problem found (at least one on error).
    ///
    /// # Errors
    /// A non-empty list of [`InvalidPolygon`]s.
    pub fn from_raw_all_errors(
        raw: &RawPolygon,
    ) -> Result<(Polygon, Vec<Warning>), Vec<InvalidPolygon>> {
        Polygon::from_raw_validated(raw, &SweepOnly)
            .map(|(polygon, warnings, ())| (polygon, warnings))
    }

    /// [`Polygon::from_raw_all_errors`], validated by `how`, with what it made beside.
    #[allow(clippy::type_complexity)]
    pub(crate) fn from_raw_validated<V: Validation>(
        raw: &RawPolygon,
        how: &V,
    ) -> Result<(Polygon, Vec<Warning>, V::Beside), Vec<InvalidPolygon>> {
        let (polygon, warnings) = Polygon::build(raw).map_err(|e| vec![e])?;
        let (polygon, beside) = how.validated(polygon)?;
        Ok((polygon, warnings, beside))
    }

    /// Grid conversion, numbering, duplicate removal and winding, without the sweep.
    pub(crate) fn build(raw: &RawPolygon) -> Result<(Polygon, Vec<Warning>), InvalidPolygon> {
        if raw.rings.is_empty() {
            return Err(InvalidPolygon::TooFewVertices {
                ring: Ring::Outer,
                distinct: 0,
            });
        }
        let (points, grid) = to_grid(raw)?;
        Polygon::assemble(raw, points, grid)
    }
}

impl Polygon<WidePoint> {
    /// Builds and validates a polygon on the wide kernel (any coordinates the readers accept),
    /// every problem found.
    ///
    /// # Errors
    /// A non-empty list of [`InvalidPolygon`]s.
    pub fn from_raw_wide(
        raw: &RawPolygon,
    ) -> Result<(Polygon<WidePoint>, Vec<Warning>), Vec<InvalidPolygon>> {
        let (polygon, warnings) = Polygon::build_wide(raw).map_err(|e| vec![e])?;
        Ok((polygon.validated()?, warnings))
    }

    /// As [`Polygon::build`], on the wide kernel.
    pub(crate) fn build_wide(
        raw: &RawPolygon,
    ) -> Result<(Polygon<WidePoint>, Vec<Warning>), InvalidPolygon> {
        if raw.rings.is_empty() {
            return Err(InvalidPolygon::TooFewVertices {
                ring: Ring::Outer,
                distinct: 0,
            });
        }
        Polygon::assemble(raw, wide_points(raw), Grid::identity())
    }
}

/// The vertices of every ring of `raw`, in order, as wide-kernel points (any decimals).
pub(crate) fn wide_points(raw: &RawPolygon) -> Vec<WidePoint> {
    raw.rings
        .iter()
        .flatten()
        .map(|[x, y]| WidePoint::new(*x, *y))
        .collect()
}

impl<P: Coord> Polygon<P> {
    /// The polygon validated: as it is when no rings touch, else relinked into the boundary
    /// walks of its touching rings ([`crate::geom::touch`]).
    pub(crate) fn validated(self) -> Result<Polygon<P>, Vec<InvalidPolygon>> {
        let contacts = self.sweep()?;
        self.settled(contacts)
    }

    /// The validation sweep of a built polygon: what it learned (how the rings touch), or every
    /// problem found. O(n log n).
    pub(crate) fn sweep(&self) -> Result<validate::Contacts, Vec<InvalidPolygon>> {
        validate::touching(self)
    }

    /// The polygon validated, given what its sweep learned: as it is when no rings touch, else
    /// relinked into the boundary walks of its touching rings ([`crate::geom::touch`]).
    pub(crate) fn settled(
        self,
        contacts: validate::Contacts,
    ) -> Result<Polygon<P>, Vec<InvalidPolygon>> {
        if !contacts.any() {
            return Ok(self);
        }
        super::touch::walks(self, &contacts)
    }

    /// A polygon without rings yet, with room for `vertices` vertices in `rings` rings (rings are
    /// pushed by the caller, who closes `ring_starts`).
    fn empty(vertices: usize, rings: usize, input_vertices: usize, grid: Grid) -> Polygon<P> {
        Polygon {
            points: Vec::with_capacity(vertices),
            ids: Vec::with_capacity(vertices),
            ring_starts: Vec::with_capacity(rings + 1),
            ring_of: Vec::with_capacity(vertices),
            input_vertices,
            grid,
            source_ring: Vec::new(),
            touches: 0,
            copy: Vec::new(),
        }
    }

    /// The same polygon with other rings (points and input numbers, outer ring first); the
    /// rings' winding is kept as given.
    pub(super) fn with_rings(&self, rings: &[Vec<(P, usize)>]) -> Polygon<P> {
        Polygon::rings_as_they_are(rings, self.input_vertices, self.grid)
    }

    /// Rings (points and input numbers) stored as they are: no validation, no winding change,
    /// nothing dropped; for the sweep of [`crate::geom::repair`] over rings not yet valid.
    pub(crate) fn rings_as_they_are(
        rings: &[Vec<(P, usize)>],
        input_vertices: usize,
        grid: Grid,
    ) -> Polygon<P> {
        let total = rings.iter().map(Vec::len).sum();
        let mut p = Polygon::empty(total, rings.len(), input_vertices, grid);
        for (r, ring) in rings.iter().enumerate() {
            p.ring_starts.push(p.points.len());
            for &(q, id) in ring {
                p.points.push(q);
                p.ids.push(id);
                p.ring_of.push(r as u32);
            }
        }
        p.ring_starts.push(p.points.len());
        p
    }

    /// The boundary walks of touching rings: stored vertices `order` (walk after walk, each
    /// starting at `starts[w]`), each keeping its point, input number and input ring, and
    /// whether it is a copy of a touch point (`copy`, by stored vertex of `self`).
    pub(super) fn relinked(
        &self,
        order: &[usize],
        starts: &[usize],
        touches: usize,
        copy: &[bool],
    ) -> Polygon<P> {
        let mut ring_of = vec![0u32; order.len()];
        for (w, &start) in starts.iter().enumerate() {
            let end = starts.get(w + 1).copied().unwrap_or(order.len());
            ring_of[start..end].fill(w as u32);
        }
        let mut ring_starts = starts.to_vec();
        ring_starts.push(order.len());
        Polygon {
            points: order.iter().map(|&i| self.points[i]).collect(),
            ids: order.iter().map(|&i| self.ids[i]).collect(),
            ring_starts,
            ring_of,
            input_vertices: self.input_vertices,
            grid: self.grid,
            source_ring: order.iter().map(|&i| self.ring_of[i]).collect(),
            touches,
            copy: order.iter().map(|&i| copy[i]).collect(),
        }
    }

    /// Whether stored vertex `i` is a copy of a touch point: its point is stored more than once
    /// (only with touching rings).
    pub(crate) fn is_copy(&self, i: usize) -> bool {
        self.copy.get(i).copied().unwrap_or(false)
    }

    /// The number of holes of the input (hole walks plus touches).
    pub fn input_holes(&self) -> usize {
        self.holes() + self.touches
    }

    /// The number of touches: how many fewer boundary walks than input rings (0 without
    /// touching rings). Each joins two boundary components and lowers the plain count by 2.
    pub fn touches(&self) -> usize {
        self.touches
    }

    /// One ring of grid points as they are (no validation, no winding change; ids 0, 1, ..), for
    /// checking a cycle with [`crate::geom::validate::errors`] (`verify::pseudo`'s faces).
    pub(crate) fn ring_of_points(points: Vec<P>, grid: Grid) -> Polygon<P> {
        let k = points.len();
        Polygon {
            points,
            ids: (0..k).collect(),
            ring_starts: vec![0, k],
            ring_of: vec![0; k],
            input_vertices: k,
            grid,
            source_ring: Vec::new(),
            touches: 0,
            copy: Vec::new(),
        }
    }

    /// Numbering, duplicate removal and winding of `points` (every vertex of `raw`, in order),
    /// without the sweep.
    fn assemble(
        raw: &RawPolygon,
        points: Vec<P>,
        grid: Grid,
    ) -> Result<(Polygon<P>, Vec<Warning>), InvalidPolygon> {
        // Room for every vertex read (duplicates dropped below only leave a little unused), so
        // that the largest arrays never grow by doubling.
        let total: usize = raw.rings.iter().map(Vec::len).sum();
        let mut polygon = Polygon::empty(total, raw.rings.len(), 0, grid);
        let mut warnings = Vec::new();
        let mut values = points.into_iter();
        for (r, input_ring) in raw.rings.iter().enumerate() {
            let first_id = polygon.input_vertices;
            polygon.input_vertices += input_ring.len();
            let ring = values
                .by_ref()
                .take(input_ring.len())
                .enumerate()
                .map(|(k, point)| (point, first_id + k));
            polygon.push_ring(r, ring, &mut warnings)?;
        }
        polygon.ring_starts.push(polygon.points.len());
        Ok((polygon, warnings))
    }

    /// Builds a polygon, without the sweep, from rings already on `grid` (each point with its
    /// input vertex number; `input_vertices` numbers used by the input): what
    /// [`crate::geom::repair`] made of the input's rings.
    pub(crate) fn from_grid_rings(
        rings: Vec<Vec<(P, usize)>>,
        grid: Grid,
        input_vertices: usize,
    ) -> Result<(Polygon<P>, Vec<Warning>), InvalidPolygon> {
        let total = rings.iter().map(Vec::len).sum();
        let mut polygon = Polygon::empty(total, rings.len(), input_vertices, grid);
        let mut warnings = Vec::new();
        for (r, ring) in rings.into_iter().enumerate() {
            polygon.push_ring(r, ring.into_iter(), &mut warnings)?;
        }
        polygon.ring_starts.push(polygon.points.len());
        Ok((polygon, warnings))
    }

    /// Appends ring `r` (points with their input vertex numbers): consecutive duplicates dropped
    /// with a warning, at least 3 vertices and non-zero area required, winding normalised.
    fn push_ring(
        &mut self,
        r: usize,
        input_ring: impl Iterator<Item = (P, usize)>,
        warnings: &mut Vec<Warning>,
    ) -> Result<(), InvalidPolygon> {
        let ring = Ring::from_index(r);
        let grid = self.grid;
        let start = self.points.len();
        let mut kept: Vec<(P, usize)> = Vec::with_capacity(input_ring.size_hint().0);
        for (point, id) in input_ring {
            if let Some(&(last, last_id)) = kept.last() {
                if last == point {
                    warnings.push(dropped(ring, id, last_id, &grid, point));
                    continue;
                }
            }
            kept.push((point, id));
        }
        while kept.len() > 1 && kept.first().map(|f| f.0) == kept.last().map(|l| l.0) {
            if let (Some(&(point, id)), Some(&(_, first))) = (kept.last(), kept.first()) {
                warnings.push(dropped(ring, id, first, &grid, point));
            }
            kept.pop();
        }
        if kept.len() < 3 {
            return Err(InvalidPolygon::TooFewVertices {
                ring,
                distinct: kept.len(),
            });
        }
        let mut area = Area::default();
        for i in 0..kept.len() {
            area.add(kept[0].0, kept[i].0, kept[(i + 1) % kept.len()].0);
        }
        let want = if r == 0 { 1 } else { -1 };
        let collinear = kept
            .iter()
            .all(|&(q, _)| cross(kept[0].0, kept[1].0, q) == 0);
        if collinear {
            return Err(InvalidPolygon::ZeroArea { ring });
        }
        // A ring of zero signed area that is not collinear crosses itself: the sweep says where.
        if area.signum() == -want {
            kept[1..].reverse(); // keeps the first vertex first
        }
        self.ring_starts.push(start);
        for (point, id) in kept {
            self.points.push(point);
            self.ids.push(id);
            self.ring_of.push(r as u32);
        }
        Ok(())
    }

    /// Number of vertices kept (n, over all rings).
    pub fn len(&self) -> usize {
        self.points.len()
    }

    /// Whether there are no vertices (never true for a valid polygon).
    pub fn is_empty(&self) -> bool {
        self.points.is_empty()
    }

    /// Number of holes (w); with touching rings, of hole walks (boundary components but the
    /// outer one).
    pub fn holes(&self) -> usize {
        self.ring_starts.len() - 2
    }

    /// Number of vertex numbers used by the input (including dropped duplicates).
    pub fn input_vertices(&self) -> usize {
        self.input_vertices
    }

    /// The grid point of stored vertex `i`.
    #[inline]
    pub fn point(&self, i: usize) -> P {
        self.points[i]
    }

    /// All grid points, ring after ring.
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The input vertex number of stored vertex `i`.
    #[inline]
    pub fn id(&self, i: usize) -> usize {
        self.ids[i]
    }

    /// The index of the ring (with touching rings: the boundary walk) holding vertex `i` (0 =
    /// outer).
    #[inline]
    pub fn ring_index(&self, i: usize) -> usize {
        self.ring_of[i] as usize
    }

    /// The input ring holding vertex `i` (for messages; with touching rings not the walk).
    pub fn ring(&self, i: usize) -> Ring {
        match self.source_ring.get(i) {
            Some(&r) => Ring::from_index(r as usize),
            None => Ring::from_index(self.ring_index(i)),
        }
    }

    /// The stored index of the first vertex of each ring, outer ring first (so the first is 0);
    /// ring `r` runs up to the start of ring `r + 1`, the last one up to [`Polygon::len`].
    pub fn ring_starts(&self) -> &[usize] {
        &self.ring_starts[..self.ring_starts.len() - 1]
    }

    /// The stored vertex indices of ring `r` (0 = outer).
    pub fn ring_range(&self, r: usize) -> Range<usize> {
        self.ring_starts[r]..self.ring_starts[r + 1]
    }

    /// The next vertex along the boundary (interior on the left).
    #[inline]
    pub fn next(&self, i: usize) -> usize {
        let r = self.ring_index(i);
        if i + 1 == self.ring_starts[r + 1] {
            self.ring_starts[r]
        } else {
            i + 1
        }
    }

    /// Whether the direction from stored vertex `v` towards `target` lies in `v`'s closed
    /// interior angle (`in_closed_wedge`; for a copy of a touch point, its
    /// sector).
    #[inline]
    pub fn angle_holds(&self, v: usize, target: P) -> bool {
        let (prev, next) = (self.point(self.prev(v)), self.point(self.next(v)));
        super::kernel::in_closed_wedge(prev, self.point(v), next, target)
    }

    /// The previous vertex along the boundary.
    #[inline]
    pub fn prev(&self, i: usize) -> usize {
        let r = self.ring_index(i);
        if i == self.ring_starts[r] {
            self.ring_starts[r + 1] - 1
        } else {
            i - 1
        }
    }

    /// The grid map, to print exact input coordinates.
    pub fn grid(&self) -> &Grid {
        &self.grid
    }

    /// Vertex `i` as `(x, y)` in input coordinates, exactly.
    pub fn format_vertex(&self, i: usize) -> String {
        self.grid.format_point(self.points[i])
    }

    /// Point `p` (of this polygon) on a grid for drawing only: a fast polygon's grid point
    /// itself; for a wide polygon, its offset from the bounding box's lower left corner scaled so
    /// that the larger side spans `2^40` units (SVG panels and the checker's faults).
    pub fn drawing_point(&self, p: P) -> Point {
        let (origin, scale, shift) = self.drawing_frame();
        p.drawing_point(origin, scale, shift)
    }

    /// The lower left corner of the bounding box, the scale of [`Polygon::drawing_point`], and
    /// the power of ten of its unit: 0, unless the coordinates are beyond the range where `f64`
    /// holds them and their differences (magnitudes past 10^±300, such as `4e400`, which
    /// rounds to infinity: every point was drawn at one place), then the largest magnitude,
    /// found from the exact values.
    fn drawing_frame(&self) -> (P, f64, i32) {
        let magnitude = self.points.iter().map(|&q| q.magnitude()).max();
        let shift = match magnitude {
            Some(m) if m != i32::MIN && !(-300..=300).contains(&m) => m,
            _ => 0,
        };
        let first = self.points[0];
        let (mut lo, mut hi) = ([first; 2], [first; 2]);
        for &q in &self.points {
            for axis in 0..2 {
                let cmp = if axis == 0 { P::cmp_x } else { P::cmp_y };
                if cmp(q, lo[axis]).is_lt() {
                    lo[axis] = q;
                }
                if cmp(q, hi[axis]).is_gt() {
                    hi[axis] = q;
                }
            }
        }
        let (lo, hi) = (P::corner(lo[0], lo[1]), P::corner(hi[0], hi[1]));
        let [w, h] = hi.offset_f64_shifted(lo, shift);
        let span = w.max(h);
        (
            lo,
            if span > 0.0 {
                2f64.powi(40) / span
            } else {
                1.0
            },
            shift,
        )
    }

    /// Number of flat vertices (collinear with both neighbours, between them).
    pub fn flat_vertices(&self) -> usize {
        (0..self.len())
            .filter(|&i| {
                cross(
                    self.points[self.prev(i)],
                    self.points[i],
                    self.points[self.next(i)],
                ) == 0
            })
            .count()
    }

    /// Bounds on the minimum number of triangles: Chen & Chang's Theorem 3 gives
    /// `ceil(n/3) <= minimum <= n + 2w - 2` for polygons without flat vertices. A flat vertex
    /// need not be a corner of any triangle (`(0 0, 0.1 0.3, 0.2 0.6, 0 1)` has n = 4 and a
    /// minimum of 1), while every other vertex must be (each triangle has 3 corners), so in general
    /// the lower bound is `ceil((n - f)/3)` with `f` flat vertices; that is what this returns.
    pub fn minimum_bounds(&self) -> (usize, usize) {
        let n = self.len();
        (
            (n - self.flat_vertices()).div_ceil(3),
            n + 2 * self.holes() - 2,
        )
    }

    /// Twice the area, exactly.
    pub fn twice_area(&self) -> Area<P> {
        let mut sum = Area::default();
        for i in 0..self.len() {
            sum.add(self.points[0], self.points[i], self.points[self.next(i)]);
        }
        sum
    }

    /// Checks the documented invariants (tests only).
    #[cfg(test)]
    pub(crate) fn check_invariants(&self) {
        if self.touches == 0 {
            assert!(validate::errors(self).is_empty());
        }
        for r in 0..self.ring_starts.len() - 1 {
            let range = self.ring_range(r);
            assert!(range.len() >= 3);
            let mut area = Area::default();
            for i in range.clone() {
                assert_eq!(self.ring_index(i), r);
                assert_eq!(self.prev(self.next(i)), i);
                area.add(
                    self.points[range.start],
                    self.points[i],
                    self.points[self.next(i)],
                );
            }
            assert_eq!(area.signum(), if r == 0 { 1 } else { -1 });
        }
    }
}

pub(crate) fn dropped<P: Coord>(
    ring: Ring,
    id: usize,
    same_as: usize,
    grid: &Grid,
    p: P,
) -> Warning {
    Warning(format!(
        "{ring}: vertex {id} {} repeats vertex {same_as} and was dropped",
        grid.format_point(p)
    ))
}

/// Puts every coordinate of `raw` on one exact integer grid, translated to start at 0.
///
/// A coordinate beyond 128 bits on the grid, or a range above 2^62 units, is rejected naming
/// the vertices, the values and the unit (the finest decimal place used).
pub(crate) fn to_grid(raw: &RawPolygon) -> Result<(Vec<Point>, Grid), InvalidPolygon> {
    let all = || raw.rings.iter().flatten();
    let scale = all()
        .flatten()
        .map(|d| -d.exponent())
        .max()
        .unwrap_or(0)
        .max(0);
    let unit = if scale == 0 {
        "1".to_string()
    } else {
        format!("10^-{scale}")
    };
    // Each vertex number with its ring, for messages.
    let vertex = |id: usize| {
        let mut first = 0;
        for (r, ring) in raw.rings.iter().enumerate() {
            if id < first + ring.len() {
                return format!("{} vertex {id}", Ring::from_index(r));
            }
            first += ring.len();
        }
        format!("vertex {id}")
    };
    let too_large = |what: String| InvalidPolygon::CoordinatesTooLarge { detail: what };
    let mut scaled: Vec<[i128; 2]> = Vec::with_capacity(all().count());
    for (id, [x, y]) in all().enumerate() {
        let s = |name: &str, d: &Decimal| {
            d.scaled(scale).ok_or_else(|| {
                too_large(format!(
                    "{} has {name} = {}, more than 2^127 units of {unit} (the finest decimal place used)",
                    vertex(id),
                    d.brief()
                ))
            })
        };
        scaled.push([s("x", x)?, s("y", y)?]);
    }
    let mut origin = [i128::MAX; 2];
    let mut top = [i128::MIN; 2];
    let (mut lowest, mut highest) = ([0; 2], [0; 2]);
    for (id, p) in scaled.iter().enumerate() {
        for axis in 0..2 {
            if p[axis] < origin[axis] {
                (origin[axis], lowest[axis]) = (p[axis], id);
            }
            if p[axis] > top[axis] {
                (top[axis], highest[axis]) = (p[axis], id);
            }
        }
    }
    for axis in 0..2 {
        let span = top[axis].checked_sub(origin[axis]);
        if span.is_none_or(|s| s > i128::from(MAX_COORD)) {
            let value = |id: usize| all().nth(id).map(|p| p[axis].brief()).unwrap_or_default();
            return Err(too_large(format!(
                "the {name} coordinates range from {} ({}) to {} ({}), more than 2^62 units of {unit} (the finest decimal place used)",
                value(lowest[axis]),
                vertex(lowest[axis]),
                value(highest[axis]),
                vertex(highest[axis]),
                name = ["x", "y"][axis],
            )));
        }
    }
    let points = scaled
        .iter()
        .map(|p| Point::new((p[0] - origin[0]) as i64, (p[1] - origin[1]) as i64))
        .collect();
    Ok((
        points,
        Grid {
            scale: scale as u32,
            origin,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_support::raw_decimal;

    #[test]
    fn decimals_land_on_one_exact_grid() {
        let (p, w) = Polygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("0.1", "0.3"),
            ("0.2", "0.6"),
            ("0", "1"),
        ]]))
        .unwrap();
        p.check_invariants();
        assert!(w.is_empty());
        assert_eq!(
            p.points(),
            &[
                Point::new(0, 0),
                Point::new(1, 3),
                Point::new(2, 6),
                Point::new(0, 10)
            ]
        );
        assert_eq!(p.format_vertex(2), "(0.2, 0.6)");
        let (q, _) = Polygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("0", "1"),
            ("0.2", "0.6"),
            ("0.1", "0.3"),
        ]]))
        .unwrap();
        assert_eq!(q.points(), p.points(), "the clockwise input was reversed");
        assert_eq!(
            (q.id(0), q.id(1), q.id(3)),
            (0, 3, 1),
            "ids follow their points"
        );
    }

    #[test]
    fn negative_and_offset_coordinates_format_back_exactly() {
        let (p, _) = Polygon::from_raw(&raw_decimal(&[&[
            ("-1.5", "100"),
            ("2", "100"),
            ("2", "101.25"),
        ]]))
        .unwrap();
        assert_eq!(p.format_vertex(0), "(-1.5, 100)");
        assert_eq!(p.format_vertex(2), "(2, 101.25)");
        assert_eq!(p.grid().to_f64(p.point(2)), [2.0, 101.25]);
    }

    #[test]
    fn consecutive_duplicates_are_dropped_but_keep_their_numbers() {
        let (p, w) = Polygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("1", "0"),
            ("1", "0"),
            ("1", "1"),
            ("0", "0"),
        ]]))
        .unwrap();
        assert_eq!(p.len(), 3);
        assert_eq!(p.input_vertices(), 5);
        assert_eq!((0..3).map(|i| p.id(i)).collect::<Vec<_>>(), vec![0, 1, 3]);
        assert_eq!(w.len(), 2);
        assert_eq!(
            w[0].0,
            "outer ring: vertex 2 (1, 0) repeats vertex 1 and was dropped"
        );
        assert_eq!(
            w[1].0,
            "outer ring: vertex 4 (0, 0) repeats vertex 0 and was dropped"
        );
    }

    #[test]
    fn bounds_on_the_minimum_count_flat_vertices_out() {
        let (p, _) = Polygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("0.1", "0.3"),
            ("0.2", "0.6"),
            ("0", "1"),
        ]]))
        .unwrap();
        assert_eq!(p.flat_vertices(), 1);
        assert_eq!(
            p.minimum_bounds(),
            (1, 2),
            "ceil(3/3) = 1, not ceil(4/3) = 2"
        );
        let (q, _) = Polygon::from_raw(&raw_decimal(&[
            &[("0", "0"), ("4", "0"), ("4", "4"), ("0", "4")],
            &[("1", "1"), ("1", "2"), ("2", "1")],
        ]))
        .unwrap();
        assert_eq!(q.minimum_bounds(), (3, 7));
    }

    #[test]
    fn too_large_ranges_are_detected() {
        let e = Polygon::from_raw(&raw_decimal(&[&[("0", "0"), ("1e19", "0"), ("0", "0.1")]]))
            .unwrap_err();
        assert!(
            matches!(e, InvalidPolygon::CoordinatesTooLarge { .. }),
            "{e}"
        );
        let e = Polygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("1e-30", "0"),
            ("1e10", "1"),
        ]]))
        .unwrap_err();
        assert!(e.to_string().contains("too large"), "{e}");
        // The wide kernel takes them.
        for rings in [
            &[&[("0", "0"), ("1e19", "0"), ("0", "0.1")][..]][..],
            &[&[("0", "0"), ("1e-30", "0"), ("1e10", "1")][..]][..],
            &[&[("0", "0"), ("1", "0"), ("1", "1e400")][..]][..],
        ] {
            let (p, _) = AnyPolygon::from_raw(&raw_decimal(rings)).unwrap();
            assert!(p.is_wide());
            assert_eq!(p.len(), 3);
        }
        let (p, _) = AnyPolygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("1e-30", "0"),
            ("1e10", "1"),
        ]]))
        .unwrap();
        assert_eq!(p.format_vertex(1), "(0.000000000000000000000000000001, 0)");
        // The largest span that fits is accepted.
        assert!(Polygon::from_raw(&raw_decimal(&[&[
            ("0", "0"),
            ("4611686018427387904", "0"),
            ("0", "1")
        ]]))
        .is_ok());
    }
}
