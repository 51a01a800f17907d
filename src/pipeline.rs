//! The library's main path: text in, read, validate, triangulate, verify; results out.
//!
//! Input contract: text in one of the [`Format`]s. Output guarantee: one [`Outcome`] per polygon
//! (or a single one for an input that cannot be read at all), in input order, each either solved
//! or carrying an [`Error`] that names what is wrong. One bad polygon never stops the others.
//! Complexity: that of reading and validating (O(n log n)) plus the chosen algorithm's.

use crate::algo::plain::{self, Premade};
use crate::algo::{
    asano, minitri, pseudo, pseudo_hull, Algorithm, Pseudotriangulation, Pseudotriangulator,
    TriangulateError, Triangulation, Triangulator,
};
use crate::geom::kernel::Coord;
use crate::geom::polygon::{AnyPolygon, Polygon, Validation};
use crate::geom::repair;
use crate::geom::validate::InvalidPolygon;
use crate::io::read::{self, Format};
use crate::raw::RawPolygon;
use crate::verify;

/// What to compute.
#[derive(Clone, Debug)]
pub struct Options {
    /// The algorithm whose triangulation is reported.
    pub algorithm: Algorithm,
    /// The largest polygon (in vertices) the O(n^3) dynamic program accepts.
    pub dp_limit: usize,
    /// Also run every other exact algorithm that applies and check every output independently.
    pub verify: bool,
    /// How long the exact method may run on one polygon (`None`: no limit): every stage of the
    /// search with holes or touching rings, step 1 without holes, `pseudo-hull`'s construction;
    /// past it the best found is reported, not optimal, with `stopped`.
    pub time_limit: Option<std::time::Duration>,
    /// Repair spikes, degenerate rings, self-touching rings, rings sharing edges and rings
    /// touching in a cycle before validating (docs/repair.md); a polygon may then give several pieces.
    pub repair: bool,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            algorithm: Algorithm::Minitri,
            dp_limit: asano::DEFAULT_LIMIT,
            verify: false,
            time_limit: Some(minitri::DEFAULT_TIME_LIMIT),
            repair: false,
        }
    }
}

pub use crate::outcome::{AlgorithmCheck, Error, Outcome, Solved, Verification};

/// Bytes a vertex reserved by [`reserve_for`]: less than any polygon was measured to need
/// beyond its reading (docs/benchmarks.md; the reading itself is freed once the polygon is
/// validated).
pub const RESERVED_PER_VERTEX: usize = 64;

/// Polygons below this many vertices are not checked by [`reserve_for`] (the reservation would
/// cost more than it tells).
const RESERVE_FROM: usize = 1 << 16;

/// Reserves, and frees at once, [`RESERVED_PER_VERTEX`] bytes a vertex for a polygon of `n`
/// vertices: when even that is refused (an address-space limit, `ulimit -v`), the polygon is
/// reported instead of aborting the run at its first allocation. A reservation granted promises
/// nothing: an allocation inside validation or an algorithm can still fail, and abort.
///
/// # Errors
/// [`Error::OutOfMemory`] when the reservation fails.
///
/// # Examples
/// ```
/// use minitri::pipeline::reserve_for;
/// assert!(reserve_for(1_000_000).is_ok());
/// let error = reserve_for(1 << 58).unwrap_err();
/// assert!(error.to_string().starts_with("not enough memory: 288230376151711744 vertices need at least"));
/// ```
pub fn reserve_for(n: usize) -> Result<(), Error> {
    if n < RESERVE_FROM {
        return Ok(());
    }
    let bytes = n.saturating_mul(RESERVED_PER_VERTEX);
    let mut reserved: Vec<u8> = Vec::new();
    reserved
        .try_reserve_exact(bytes)
        .map_err(|_| Error::OutOfMemory {
            n,
            memory: in_words(bytes as f64),
        })
}

/// A number of bytes in words: `120 MB`, `3.2 GB`.
fn in_words(bytes: f64) -> String {
    if bytes >= 1e9 {
        format!("{:.1} GB", bytes / 1e9)
    } else {
        format!("{:.0} MB", bytes / 1e6)
    }
}

/// Triangulates a valid polygon with one algorithm and the default [`Options`] (for the exact
/// algorithms: at most `Options::default().time_limit` a polygon (10 s), then the best found with
/// `optimal: false`; for `asano`: at most `Options::default().dp_limit` vertices).
///
/// # Errors
/// [`TriangulateError`] when the algorithm does not apply (holes, size).
///
/// # Examples
/// ```
/// use geo_types::polygon;
/// use minitri::{Polygon, Triangulator};
/// // A square with a vertex in the middle of its bottom side: with the diagonals from the top
/// // left corner, that vertex lies inside a side, so 2 triangles (n - 2 - d = 5 - 2 - 1) do;
/// // and 1 cannot, the square not being a triangle.
/// let square = polygon![(x: 0, y: 0), (x: 1, y: 0), (x: 2, y: 0), (x: 2, y: 2), (x: 0, y: 2)];
/// let polygon = Polygon::try_from(&square)?;
/// let t = minitri::triangulate(&polygon, Triangulator::Minitri)?;
/// assert_eq!((t.triangles.len(), t.degenerate.len()), (2, 1));
/// # Ok::<(), minitri::Error>(())
/// ```
pub fn triangulate<P: Coord>(
    polygon: &Polygon<P>,
    algorithm: Triangulator,
) -> Result<Triangulation, TriangulateError> {
    triangulate_with(polygon, algorithm, &Options::default())
}

/// Triangulates a valid polygon with one algorithm and the limits of `options` (its
/// `algorithm` and `verify` are not used here).
///
/// # Errors
/// [`TriangulateError`] when the algorithm does not apply (holes, size). The
/// pseudotriangulation algorithms are no [`Triangulator`]s: [`pseudotriangulate`] runs them.
///
/// # Examples
/// ```
/// use geo_types::polygon;
/// use minitri::{Algorithm, Options, Polygon, Triangulator};
/// let square = polygon![(x: 0, y: 0), (x: 2, y: 0), (x: 2, y: 2), (x: 0, y: 2)];
/// let polygon = Polygon::try_from(&square)?;
/// let options = Options::default();
/// for algorithm in [Triangulator::Minitri, Triangulator::Asano, Triangulator::Ear] {
///     let t = minitri::triangulate_with(&polygon, algorithm, &options)?;
///     assert_eq!((t.algorithm, t.triangles.len()), (Algorithm::from(algorithm), 2));
/// }
/// # Ok::<(), minitri::Error>(())
/// ```
pub fn triangulate_with<P: Coord>(
    polygon: &Polygon<P>,
    algorithm: Triangulator,
    options: &Options,
) -> Result<Triangulation, TriangulateError> {
    triangulate_premade(polygon, algorithm, options, None)
}

/// [`triangulate_with`], MINITRI's step 1 and `ear` taking `premade`'s triangles when the
/// pipeline made them already (beside the validation sweep, [`PlainBeside`]).
fn triangulate_premade<P: Coord>(
    polygon: &Polygon<P>,
    algorithm: Triangulator,
    options: &Options,
    premade: Premade,
) -> Result<Triangulation, TriangulateError> {
    let deadline = || {
        options
            .time_limit
            .and_then(|limit| std::time::Instant::now().checked_add(limit))
    };
    match algorithm {
        Triangulator::Asano if polygon.touches() > 0 => {
            crate::algo::touching(polygon, Algorithm::Asano, options.dp_limit, deadline())
        }
        Triangulator::Asano => asano::triangulate(polygon, options.dp_limit),
        Triangulator::Ear => plain::triangulate_premade(polygon, premade),
        Triangulator::Minitri => minitri::triangulate_premade(polygon, premade, deadline()),
    }
}

impl AnyPolygon {
    /// Triangulates the polygon, on whichever kernel holds it, as [`triangulate`] does.
    ///
    /// # Errors
    /// [`TriangulateError`] when the algorithm does not apply (holes, size).
    pub fn triangulate(&self, algorithm: Triangulator) -> Result<Triangulation, TriangulateError> {
        crate::with_polygon!(self, p => triangulate(p, algorithm))
    }

    /// Triangulates as `options` say, verifying if asked, as [`solve`] does.
    ///
    /// # Errors
    /// [`Error::Triangulate`] when the chosen algorithm does not apply.
    pub fn solve(&self, options: &Options) -> Result<Solved, Error> {
        self.solve_premade(options, None)
    }

    /// [`AnyPolygon::solve`], with the plain triangulation the pipeline made beside the
    /// validation sweep, if any.
    fn solve_premade(&self, options: &Options, premade: Premade) -> Result<Solved, Error> {
        crate::with_polygon!(self, p => solve_premade(p, options, premade))
    }
}

/// Pseudotriangulates a valid polygon: [`Pseudotriangulator::Pseudo`], a minimal
/// pseudotriangulation of the polygon inside its plain (`ear`) triangulation (Rote, Wang, Wang &
/// Xu, Section 5), or [`Pseudotriangulator::PseudoHull`], a minimum pseudotriangulation of the
/// convex hull containing every polygon edge (their Theorem 6). Vertex numbers are stored
/// indices, as in [`Triangulation`]; [`Pseudotriangulation::input_faces`] gives them in input
/// numbering.
///
/// # Errors
/// [`TriangulateError::PseudoHullIncomplete`] should a self-check of the construction fail.
///
/// # Examples
/// ```
/// use geo_types::polygon;
/// use minitri::{Polygon, Pseudotriangulator};
/// // A quadrilateral with one reflex vertex is itself a pseudotriangle: one face.
/// let dart = polygon![(x: 0, y: 0), (x: 4, y: 0), (x: 2, y: 1), (x: 0, y: 4)];
/// let polygon = Polygon::try_from(&dart)?;
/// let p = minitri::pseudotriangulate(&polygon, Pseudotriangulator::Pseudo)?;
/// assert_eq!((p.faces.len(), p.faces[0].corners.len()), (1, 3));
/// // The hull's version also cuts the pocket outside the reflex vertex: n - 2 = 2 faces.
/// let hull = minitri::pseudotriangulate(&polygon, Pseudotriangulator::PseudoHull)?;
/// assert_eq!(hull.faces.len(), 2);
/// # Ok::<(), minitri::Error>(())
/// ```
pub fn pseudotriangulate<P: Coord>(
    polygon: &Polygon<P>,
    algorithm: Pseudotriangulator,
) -> Result<Pseudotriangulation, TriangulateError> {
    match algorithm {
        Pseudotriangulator::PseudoHull => pseudo_hull::pseudotriangulate(polygon),
        Pseudotriangulator::Pseudo => Ok(pseudo::minimal(
            polygon,
            &plain::triangulate(polygon)?.triangles,
        )),
    }
}

/// Environment variable that makes [`solve`], when verifying, corrupt the chosen algorithm's
/// output before checking it: a fault injected on purpose, for the tests of `--verify` only.
/// With the value [`CORRUPT_WITH_EAR`], the output is replaced by `ear`'s valid but not minimal
/// triangulation, still labelled as the chosen algorithm (the exact algorithms then disagree
/// although every check passes, when the polygon has a T-junction to use); with any other value,
/// its last triangle is dropped (the checks fail).
pub const CORRUPT_FOR_TESTS: &str = "MINITRI_CORRUPT_FOR_TESTS";

/// The value of [`CORRUPT_FOR_TESTS`] that swaps in `ear`'s triangulation.
pub const CORRUPT_WITH_EAR: &str = "ear";

/// Triangulates a valid polygon as `options` say, verifying if asked.
///
/// # Errors
/// [`Error::Triangulate`] when the chosen algorithm does not apply.
pub fn solve<P: Coord>(polygon: &Polygon<P>, options: &Options) -> Result<Solved, Error> {
    solve_premade(polygon, options, None)
}

/// [`solve`], the chosen algorithm taking `premade`'s triangles when the pipeline made them
/// already (the other algorithms of `--verify` make their own).
fn solve_premade<P: Coord>(
    polygon: &Polygon<P>,
    options: &Options,
    premade: Premade,
) -> Result<Solved, Error> {
    let Some(algorithm) = options.algorithm.triangulator() else {
        return solve_pseudo(polygon, options, premade);
    };
    let mut triangulation = triangulate_premade(polygon, algorithm, options, premade)?;
    // The environment is read only with `--verify` (a lookup per polygon costs as much as
    // writing its output's numbers).
    let corrupt = options
        .verify
        .then(|| std::env::var_os(CORRUPT_FOR_TESTS))
        .flatten();
    if let Some(mode) = corrupt {
        // Fault injection, so that tests can see --verify catch a wrong output and exit 3.
        if mode == CORRUPT_WITH_EAR {
            let Triangulation {
                triangles,
                degenerate,
                ..
            } = plain::triangulate(polygon)?;
            triangulation = Triangulation {
                triangles,
                degenerate,
                ..triangulation
            };
        } else {
            triangulation.triangles.pop();
        }
    }
    let verification = options
        .verify
        .then(|| verify_all(polygon, &triangulation, options));
    Ok(Solved {
        triangulation,
        pseudo: None,
        verification,
    })
}

/// `pseudo` (minimal, inside the plain triangulation) or `pseudo-hull` (minimum, of the hull;
/// past `--time-limit`, minimal, `pseudo`'s greedy on the hull, with `stopped`).
fn solve_pseudo<P: Coord>(
    polygon: &Polygon<P>,
    options: &Options,
    premade: Premade,
) -> Result<Solved, Error> {
    let triangulation = plain::triangulate_premade(polygon, premade)?;
    let mut result = if options.algorithm == Algorithm::PseudoHull {
        let deadline = options
            .time_limit
            .and_then(|limit| std::time::Instant::now().checked_add(limit));
        // The hull's triangulation starts from the polygon's plain one: this one, not made again.
        let plain = (polygon.touches() == 0).then(|| triangulation.triangles.clone());
        pseudo_hull::pseudotriangulate_premade(polygon, plain, deadline)?
    } else {
        pseudo::minimal(polygon, &triangulation.triangles)
    };
    if options.verify && std::env::var_os(CORRUPT_FOR_TESTS).is_some() {
        result.faces.pop();
    }
    let verification = options.verify.then(|| {
        let check = verify::pseudo::check(polygon, options.algorithm, &result);
        Verification {
            ok: check.valid,
            checks: Vec::new(),
            pseudotriangulation: Some(check),
            disagreement: None,
            skipped: Vec::new(),
        }
    });
    Ok(Solved {
        triangulation: Triangulation {
            algorithm: options.algorithm,
            ..triangulation
        },
        pseudo: Some(result),
        verification,
    })
}

/// Checks `main` and every other exact algorithm's output independently, and their agreement.
fn verify_all<P: Coord>(
    polygon: &Polygon<P>,
    main: &Triangulation,
    options: &Options,
) -> Verification {
    let mut outputs = vec![main.clone()];
    let mut skipped = Vec::new();
    for other in [Triangulator::Minitri, Triangulator::Asano] {
        if Algorithm::from(other) == main.algorithm {
            continue;
        }
        match triangulate_with(polygon, other, options) {
            Ok(t) => outputs.push(t),
            Err(e) => skipped.push(format!("{other}: {e}")),
        }
    }
    let exact: Vec<(Algorithm, usize, Option<usize>)> = outputs
        .iter()
        .filter(|t| t.algorithm.is_minimum())
        .map(|t| {
            let lower = (!t.optimal).then(|| t.lower_bound.unwrap_or(0));
            (t.algorithm, t.triangles.len(), lower)
        })
        .collect();
    let checks: Vec<AlgorithmCheck> = outputs
        .into_iter()
        .map(|t| AlgorithmCheck {
            algorithm: t.algorithm.name(),
            triangle_count: t.triangles.len(),
            degenerate_count: t.degenerate.len(),
            check: verify::check(polygon, &t),
            triangulation: t,
        })
        .collect();
    let disagreement = verify::agreement(&exact);
    let ok = disagreement.is_none() && checks.iter().all(|c| c.check.valid);
    Verification {
        ok,
        checks,
        pseudotriangulation: None,
        disagreement,
        skipped,
    }
}

/// An outcome for a source that could not be read at all.
pub fn unreadable(source: &str, error: Error) -> Outcome {
    Outcome {
        source: source.to_string(),
        index: None,
        piece: None,
        pieces: 1,
        polygon: None,
        result: Err(error),
        warnings: Vec::new(),
        repaired: None,
        feature: None,
        srid: None,
        ordinates: None,
    }
}

/// Reads, validates and triangulates every polygon of one source text. A member of a geometry
/// collection that is not a polygon (a `POINT`) is one failed outcome in its place, without
/// index ([`read::read_parts`]); the polygons are numbered without it.
pub fn process(source: &str, text: &str, format: Format, options: &Options) -> Vec<Outcome> {
    let parts = match read::read_parts(format, text) {
        Ok(parts) => parts,
        Err(e) => return vec![unreadable(source, Error::Parse(e))],
    };
    let mut index = 0;
    let mut outcomes = Vec::new();
    for part in parts {
        match part {
            Ok(raw) => {
                outcomes.extend(process_raw(source, index, raw, options));
                index += 1;
            }
            Err(e) => outcomes.push(unreadable(source, Error::Parse(e))),
        }
    }
    outcomes
}

/// Validates and triangulates polygon `index` of `source`, as read: one outcome, or with
/// `--repair` one for each piece the repaired polygon falls into.
///
/// Takes the polygon as read by value and frees it once validated: the decimals as read take
/// 64 bytes a vertex (more with the reader's spare capacity), the validated [`Polygon`] holds
/// the same coordinates on its integer grid, and a huge polygon should not carry both through
/// the triangulation.
pub fn process_raw(
    source: &str,
    index: usize,
    mut raw: RawPolygon,
    options: &Options,
) -> Vec<Outcome> {
    let outcome = Outcome {
        source: source.to_string(),
        index: Some(index),
        piece: None,
        pieces: 1,
        polygon: None,
        result: Err(Error::Invalid(Vec::new())),
        warnings: Vec::new(),
        repaired: None,
        feature: None,
        srid: None,
        ordinates: raw.ordinates.take().map(std::sync::Arc::new),
    };
    if let Err(e) = reserve_for(raw.rings.iter().map(Vec::len).sum()) {
        return vec![Outcome {
            result: Err(e),
            ..outcome
        }];
    }
    if options.repair {
        let repaired = repair::repair_raw_validated(&raw, &PlainBeside);
        drop(raw);
        let (pieces, premades) = match repaired {
            Err(e) => {
                return vec![Outcome {
                    result: Err(Error::Invalid(vec![e])),
                    repaired: Some(Vec::new()),
                    ..outcome
                }]
            }
            Ok(pieces) => pieces,
        };
        let count = pieces.pieces.len();
        // The input polygon's warnings are told once, with its first piece.
        let mut input_warnings = Some(pieces.warnings);
        let mut repairs = pieces.repairs;
        return pieces
            .pieces
            .into_iter()
            .zip(premades)
            .enumerate()
            .map(|(k, (piece, premade))| {
                let mut warnings = input_warnings.take().unwrap_or_default();
                // The repairs once, with the first piece: a ring touching itself k times gives
                // k pieces and k repairs, and a copy for every piece grew as k^2.
                let repaired = if k == 0 {
                    std::mem::take(&mut repairs)
                } else {
                    Vec::new()
                };
                let mut one = Outcome {
                    piece: (count > 1).then_some(k),
                    pieces: count.max(1),
                    repaired: Some(repaired),
                    ..outcome.clone()
                };
                match piece {
                    Err(errors) => one.result = Err(Error::Invalid(errors)),
                    Ok((polygon, more)) => {
                        warnings.extend(more);
                        one.result = polygon.solve_premade(options, premade);
                        one.polygon = Some(polygon);
                    }
                }
                one.warnings = warnings;
                one
            })
            .collect();
    }
    let mut outcome = outcome;
    let validated = AnyPolygon::from_raw_validated(&raw, &PlainBeside);
    drop(raw);
    match validated {
        Err(errors) => outcome.result = Err(Error::Invalid(errors)),
        Ok((polygon, warnings, premade)) => {
            outcome.warnings = warnings;
            outcome.result = polygon.solve_premade(options, premade);
            outcome.polygon = Some(polygon);
        }
    }
    vec![outcome]
}

/// From this many vertices on, a polygon is triangulated for step 1 beside its validation
/// ([`PlainBeside`]); below, the second thread would not pay for itself.
const TRIANGULATE_WHILE_VALIDATING: usize = 8192;

/// Validation with the plain triangulation for step 1's walks run beside the sweep, on another
/// rayon thread, for a large polygon: the two sweeps take about as long each. The triangulation
/// of rings not yet known valid never panics and always ends
/// ([`crate::algo::plain::try_polygon`]), and it is kept only if the polygon is valid
/// and its rings do not touch (touching rings are relinked into walks, another polygon): then
/// returned beside the polygon, for [`solve_premade`] to hand to the chosen algorithm. On one
/// thread (`--jobs 1`) nothing would overlap: an invalid polygon would only be triangulated for
/// nothing, so the sweep runs alone.
pub(crate) struct PlainBeside;

impl Validation for PlainBeside {
    type Beside = Premade;

    fn validated<P: Coord>(
        &self,
        polygon: Polygon<P>,
    ) -> Result<(Polygon<P>, Premade), Vec<InvalidPolygon>> {
        if polygon.len() < TRIANGULATE_WHILE_VALIDATING || rayon::current_num_threads() <= 1 {
            return Ok((polygon.validated()?, None));
        }
        let (contacts, plain) = rayon::join(|| polygon.sweep(), || plain::try_polygon(&polygon));
        let contacts = contacts?;
        if contacts.any() {
            return Ok((polygon.settled(contacts)?, None));
        }
        Ok((polygon, plain))
    }
}
