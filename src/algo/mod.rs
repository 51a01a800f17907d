//! Triangulation algorithms. Each returns a plain [`Triangulation`]; writers consume it.
//!
//! - [`plain`]: the plain triangulation into n + 2w - 2 nondegenerate triangles (`--algorithm
//!   ear`): monotone pieces in O(n log n), ear clipping for small polygons, touching rings
//!   through copies moved into their sectors.
//! - [`minitri`]: the exact minimum by Chen & Chang's MINITRI.
//! - [`asano`]: the exact minimum by the dynamic program of Asano, Asano & Pinter.
//! - [`asano_holes`]: the same for polygons with 1 or 2 holes, by cutting each hole open.
//! - [`chords`]: which vertex pairs are chords (used by the DP).
//! - [`pseudo`]: a minimal pseudotriangulation inside a triangulation (`--algorithm pseudo`).
//! - [`pseudo_hull`]: a minimum pseudotriangulation of the convex hull containing the polygon's
//!   edges (`--algorithm pseudo-hull`).

pub mod asano;
pub mod asano_holes;
pub mod chords;
pub(crate) mod mesh;
pub mod minitri;
pub(crate) mod number_hash;
pub mod plain;
pub mod pseudo;
pub mod pseudo_hull;
pub mod walks;

use crate::geom::kernel::Coord;
use std::fmt;

/// Which algorithm made (or should make) a triangulation or a pseudotriangulation: what
/// [`crate::Options`] chooses (the command line's `--algorithm`) and what a [`Triangulation`]
/// records. The functions that run one algorithm take a [`Triangulator`] ([`crate::triangulate`])
/// or a [`Pseudotriangulator`] ([`crate::pseudotriangulate`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Algorithm {
    /// Chen & Chang's MINITRI (minimum; default).
    Minitri,
    /// The O(n^3) dynamic program of Asano, Asano & Pinter (minimum; reference).
    Asano,
    /// A plain triangulation into n + 2w - 2 triangles.
    Ear,
    /// A minimal pseudotriangulation of the polygon inside the plain triangulation.
    Pseudo,
    /// A minimum pseudotriangulation of the convex hull containing the polygon's edges.
    PseudoHull,
}

impl Algorithm {
    /// The name used on the command line and in JSON.
    pub fn name(self) -> &'static str {
        match self {
            Algorithm::Minitri => "minitri",
            Algorithm::Asano => "asano",
            Algorithm::Ear => "ear",
            Algorithm::Pseudo => "pseudo",
            Algorithm::PseudoHull => "pseudo-hull",
        }
    }

    /// Whether the algorithm computes a minimum triangulation.
    pub fn is_minimum(self) -> bool {
        matches!(self, Algorithm::Minitri | Algorithm::Asano)
    }

    /// Whether the algorithm computes a pseudotriangulation (not a triangulation).
    pub fn is_pseudo(self) -> bool {
        matches!(self, Algorithm::Pseudo | Algorithm::PseudoHull)
    }
}

/// An algorithm that makes a triangulation: what [`crate::triangulate`] takes. The
/// pseudotriangulation algorithms are [`Pseudotriangulator`]s, so that asking `triangulate` for
/// a pseudotriangulation does not compile.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Triangulator {
    /// Chen & Chang's MINITRI (minimum; default): [`Algorithm::Minitri`].
    Minitri,
    /// The O(n^3) dynamic program of Asano, Asano & Pinter (minimum; reference):
    /// [`Algorithm::Asano`].
    Asano,
    /// A plain triangulation into n + 2w - 2 triangles: [`Algorithm::Ear`].
    Ear,
}

/// An algorithm that makes a pseudotriangulation: what [`crate::pseudotriangulate`] takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Pseudotriangulator {
    /// A minimal pseudotriangulation of the polygon inside its plain triangulation:
    /// [`Algorithm::Pseudo`].
    Pseudo,
    /// A minimum pseudotriangulation of the convex hull containing the polygon's edges:
    /// [`Algorithm::PseudoHull`].
    PseudoHull,
}

impl From<Triangulator> for Algorithm {
    fn from(t: Triangulator) -> Algorithm {
        match t {
            Triangulator::Minitri => Algorithm::Minitri,
            Triangulator::Asano => Algorithm::Asano,
            Triangulator::Ear => Algorithm::Ear,
        }
    }
}

impl From<Pseudotriangulator> for Algorithm {
    fn from(p: Pseudotriangulator) -> Algorithm {
        match p {
            Pseudotriangulator::Pseudo => Algorithm::Pseudo,
            Pseudotriangulator::PseudoHull => Algorithm::PseudoHull,
        }
    }
}

impl Algorithm {
    /// The algorithm as a [`Triangulator`], when it makes a triangulation.
    ///
    /// # Examples
    /// ```
    /// use minitri::{Algorithm, Triangulator};
    /// assert_eq!(Algorithm::Asano.triangulator(), Some(Triangulator::Asano));
    /// assert_eq!(Algorithm::Pseudo.triangulator(), None);
    /// assert_eq!(Algorithm::from(Triangulator::Asano), Algorithm::Asano);
    /// ```
    pub fn triangulator(self) -> Option<Triangulator> {
        match self {
            Algorithm::Minitri => Some(Triangulator::Minitri),
            Algorithm::Asano => Some(Triangulator::Asano),
            Algorithm::Ear => Some(Triangulator::Ear),
            Algorithm::Pseudo | Algorithm::PseudoHull => None,
        }
    }

    /// The algorithm as a [`Pseudotriangulator`], when it makes a pseudotriangulation.
    pub fn pseudotriangulator(self) -> Option<Pseudotriangulator> {
        match self {
            Algorithm::Pseudo => Some(Pseudotriangulator::Pseudo),
            Algorithm::PseudoHull => Some(Pseudotriangulator::PseudoHull),
            Algorithm::Minitri | Algorithm::Asano | Algorithm::Ear => None,
        }
    }
}

impl fmt::Display for Triangulator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(Algorithm::from(*self).name())
    }
}

impl fmt::Display for Pseudotriangulator {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(Algorithm::from(*self).name())
    }
}

impl Triangulation {
    /// The triangles in INPUT vertex numbers, the numbering of the command line's output: 0-based
    /// over all rings in input order (outer ring first), each ring without its closing vertex,
    /// a dropped duplicate vertex keeping its number (it then appears in no triangle). The
    /// stored indices of [`Triangulation::triangles`] skip dropped duplicates, so they differ
    /// from these once a duplicate was dropped; [`crate::Polygon::id`] maps one vertex.
    ///
    /// # Examples
    /// ```
    /// use geo_types::polygon;
    /// // Vertex 1 repeats vertex 0: it is dropped, and the square keeps input numbers 0, 2, 3, 4.
    /// let square = polygon![(x: 0, y: 0), (x: 0, y: 0), (x: 1, y: 0), (x: 1, y: 1), (x: 0, y: 1)];
    /// let polygon = minitri::Polygon::try_from(&square)?;
    /// let t = minitri::triangulate(&polygon, minitri::Triangulator::Minitri)?;
    /// let used: std::collections::BTreeSet<usize> =
    ///     t.input_triangles(&polygon).into_iter().flatten().collect();
    /// assert_eq!(used.into_iter().collect::<Vec<_>>(), [0, 2, 3, 4]);
    /// assert!(t.triangles.iter().flatten().all(|&i| i < 4)); // stored: 0..4
    /// # Ok::<(), minitri::Error>(())
    /// ```
    pub fn input_triangles<P: Coord>(&self, polygon: &crate::Polygon<P>) -> Vec<[usize; 3]> {
        input_numbers(polygon, &self.triangles)
    }

    /// The degenerate triangles `[a, b, c]` in input vertex numbers, as
    /// [`Triangulation::input_triangles`].
    pub fn input_degenerate<P: Coord>(&self, polygon: &crate::Polygon<P>) -> Vec<[usize; 3]> {
        input_numbers(polygon, &self.degenerate)
    }
}

/// Triples of stored indices as input vertex numbers.
fn input_numbers<P: Coord>(polygon: &crate::Polygon<P>, triples: &[[usize; 3]]) -> Vec<[usize; 3]> {
    triples.iter().map(|t| t.map(|i| polygon.id(i))).collect()
}

impl Pseudotriangulation {
    /// The faces in INPUT vertex numbers (`cycle`, `corners`), as
    /// [`Triangulation::input_triangles`].
    pub fn input_faces<P: Coord>(&self, polygon: &crate::Polygon<P>) -> Vec<Pseudotriangle> {
        self.faces
            .iter()
            .map(|f| Pseudotriangle {
                cycle: f.cycle.iter().map(|&i| polygon.id(i)).collect(),
                corners: f.corners.iter().map(|&i| polygon.id(i)).collect(),
            })
            .collect()
    }

    /// Whether the count is proved minimum: `pseudo-hull` (it has [`Pseudotriangulation::hull`])
    /// when not stopped by the time limit; never `pseudo`, whose result is only minimal.
    pub fn optimal(&self) -> bool {
        self.hull.is_some() && self.stopped.is_none()
    }
}

impl fmt::Display for Algorithm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A triangulation of a [`crate::Polygon`], in STORED vertex indices (`0..polygon.len()`; map
/// them to input numbers with `polygon.id(i)`).
///
/// Contract of every algorithm: `triangles` are nondegenerate and counter-clockwise, their
/// interiors are disjoint, and they cover the polygon exactly; `degenerate` lists the zero-area
/// triangles `[a, b, c]` (`b` strictly between `a` and `c`) whose middle vertex `b` lies inside a
/// side of a triangle, so that `triangles.len() == n + 2w - 2 - degenerate.len()`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Triangulation {
    /// The algorithm that made it.
    pub algorithm: Algorithm,
    /// Nondegenerate triangles, counter-clockwise, as stored vertex indices.
    pub triangles: Vec<[usize; 3]>,
    /// Degenerate triangles used, `[a, b, c]` with `b` the middle vertex.
    pub degenerate: Vec<[usize; 3]>,
    /// Whether the count is proved minimum.
    pub optimal: bool,
    /// For a minimum algorithm whose search was cut short (`optimal` false): a proved lower
    /// bound on the minimum number of triangles.
    pub lower_bound: Option<usize>,
    /// For a minimum algorithm whose count is not proved minimum: why.
    pub stopped: Option<Stopped>,
}

/// Whether `deadline` (`None`: no limit) has passed: what every loop that can run long asks.
pub(crate) fn past(deadline: Option<std::time::Instant>) -> bool {
    deadline.is_some_and(|d| std::time::Instant::now() >= d)
}

/// Why a minimum algorithm's count is not proved minimum (`optimal` false). The triangulation
/// is valid all the same, and `lower_bound` says how far from the minimum it can be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Stopped {
    /// The exact method reached its time limit (`--time-limit`): for a polygon with holes while
    /// finding the minimally degenerate triangles, building their dependency graph, or
    /// searching it; for one without holes while finding them (step 1, O(n log^2 n)).
    TimeLimit,
    /// A connected component of the dependency graph had more triangles than the exact search
    /// takes (`SEARCH_LIMIT`, 4,096 triangles); it kept a greedy set.
    SearchSize,
    /// The dependency graph of all minimally degenerate triangles would have exceeded its size
    /// budget (`pair_budget`); the search used the shortest of them.
    GraphSize,
    /// Rings that touch, where the exact method on the walks failed a self-check (not seen in
    /// the tests) and the walk DP did not apply: the flattened walk was given.
    Touching,
}

impl Stopped {
    /// The name written in the JSON (`"stopped_by"`).
    pub fn name(self) -> &'static str {
        match self {
            Stopped::TimeLimit => "time limit",
            Stopped::SearchSize => "search size",
            Stopped::GraphSize => "graph size",
            Stopped::Touching => "touching rings",
        }
    }
}

/// A pseudotriangulation: faces that are simple polygons with exactly three corners (vertices
/// whose angle in the face is below pi; an angle of pi or more, flat included, is no corner).
/// Vertex numbers are STORED indices, as in [`Triangulation`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pseudotriangulation {
    /// The faces.
    pub faces: Vec<Pseudotriangle>,
    /// The number of edges (each counted once; polygon edges and, for `pseudo-hull`, hull edges
    /// included).
    pub edge_count: usize,
    /// For `pseudo-hull`: the counts of Corollary 1.
    pub hull: Option<HullCounts>,
    /// For `pseudo-hull`: why the result is not the construction's minimum one, if it is not.
    /// [`Stopped::TimeLimit`]: the construction passed its deadline (`--time-limit`), and the
    /// result is the greedy of `pseudo` on the hull's triangulation (minimal: no edge or
    /// triangle removable, every polygon edge kept; its count may exceed `2n - N - 2`).
    pub stopped: Option<Stopped>,
}

/// One face of a [`Pseudotriangulation`].
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pseudotriangle {
    /// The boundary, counter-clockwise (face on the left), starting at a corner.
    pub cycle: Vec<usize>,
    /// The vertices whose angle in the face is below pi, in cycle order (three in a
    /// pseudotriangle).
    pub corners: Vec<usize>,
}

impl Pseudotriangle {
    /// The face of a counter-clockwise cycle of `points` indices, its corners found by exact
    /// orientation, the cycle turned to start at its first corner.
    pub(crate) fn from_cycle<P: Coord>(points: &[P], mut cycle: Vec<usize>) -> Self {
        let k = cycle.len();
        let is_corner = |i: usize| {
            let [u, v, w] = [(i + k - 1) % k, i, (i + 1) % k].map(|j| points[cycle[j]]);
            crate::geom::kernel::cross(u, v, w) > 0
        };
        if let Some(first) = (0..k).find(|&i| is_corner(i)) {
            cycle.rotate_left(first);
        }
        let is_corner = |i: usize| {
            let [u, v, w] = [(i + k - 1) % k, i, (i + 1) % k].map(|j| points[cycle[j]]);
            crate::geom::kernel::cross(u, v, w) > 0
        };
        let corners = (0..k).filter(|&i| is_corner(i)).map(|i| cycle[i]).collect();
        Pseudotriangle { cycle, corners }
    }
}

/// The counts of Corollary 1 for `pseudo-hull` (vertex set S of n points, segments L = the
/// polygon's edges, plus the hull edges, which every pseudotriangulation of the hull contains).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct HullCounts {
    /// r: vertices with an angle of at least pi between neighbouring segments of L. Every vertex
    /// of a polygon has two edges, so r = n.
    pub reflex_vertices: usize,
    /// N: angles of at least pi between neighbouring segments of L and the hull edges, over all
    /// vertices (outer angles of hull vertices included). In general position N = r; a flat
    /// vertex (its two edges collinear) has two angles of exactly pi.
    pub big_angles: usize,
}

impl HullCounts {
    /// Corollary 1's number of pseudotriangles, 2n - r - 2.
    pub fn corollary(&self, n: usize) -> usize {
        (2 * n).saturating_sub(self.reflex_vertices + 2)
    }

    /// The least number of pseudotriangles containing L, 2n - N - 2 (Corollary 1 when N = r).
    pub fn minimum(&self, n: usize) -> usize {
        (2 * n).saturating_sub(self.big_angles + 2)
    }
}

/// Which vertices [`t_junctions`] looks at, and which copy it names at a touch point.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Junctions<'a> {
    /// Rings that do not touch: every vertex, each alone at its point.
    Rings,
    /// Boundary walks of touching rings ([`walks`]): only these stored vertices, and of the
    /// copies at one point the one whose closed angle holds the triangle (one per point).
    Walks(&'a [usize]),
}

/// The degenerate triangles a set of triangles uses: for every vertex lying strictly inside a
/// triangle side, the triple (its neighbour towards one end of the side, it, its neighbour
/// towards the other end), neighbours taken among the side's end points and the vertices on it.
/// On walks ([`Junctions::Walks`]) the vertex is the copy whose closed angle holds the triangle
/// (its two ends and its apex), one per point.
///
/// Every such vertex saves one triangle: the triangle corners cover its interior angle minus pi,
/// so summing angles gives `triangles = n + 2w - 2 - (number of these vertices)`. The triples are
/// minimally degenerate (nothing lies between their ends) and pairwise independent, since they
/// all occur in one triangulation.
///
/// Complexity: O(T c) for T triangles and c vertices looked at (a scan per side); for the
/// O(n^3) DP that is negligible.
pub(crate) fn t_junctions<P: Coord>(
    polygon: &crate::Polygon<P>,
    triangles: &[[usize; 3]],
    among: Junctions<'_>,
) -> Vec<[usize; 3]> {
    use crate::geom::kernel::strictly_between;
    let mut out = Vec::new();
    for t in triangles {
        for k in 0..3 {
            let (s, e, apex) = (t[k], t[(k + 1) % 3], t[(k + 2) % 3]);
            let (ps, pe) = (polygon.point(s), polygon.point(e));
            let on_side = |&v: &usize| strictly_between(ps, polygon.point(v), pe);
            let mut inside: Vec<usize> = match among {
                Junctions::Rings => (0..polygon.len()).filter(on_side).collect(),
                Junctions::Walks(candidates) => {
                    let pa = polygon.point(apex);
                    let holds = |v: usize, q: P| polygon.angle_holds(v, q);
                    candidates
                        .iter()
                        .copied()
                        .filter(|v| on_side(v) && holds(*v, ps) && holds(*v, pe) && holds(*v, pa))
                        .collect()
                }
            };
            if inside.is_empty() {
                continue;
            }
            inside.sort_by(|&u, &v| P::cmp_dist(ps, polygon.point(u), polygon.point(v)));
            if let Junctions::Walks(_) = among {
                inside.dedup_by_key(|v| polygon.point(*v)); // copies at one point
            }
            let chain: Vec<usize> = std::iter::once(s)
                .chain(inside)
                .chain(std::iter::once(e))
                .collect();
            out.extend(chain.windows(3).map(|w| [w[0], w[1], w[2]]));
        }
    }
    out
}

/// A triangulation of a polygon with touching rings ([`walks`]).
///
/// For `minitri`: Chen & Chang's steps on the walks ([`minitri::triangulate_walks`]): on one
/// walk (every ring joined to the outer ring) polynomial, as for a simple polygon; with hole
/// walks left, the exact search until `deadline`. For `asano` (the reference `--verify`
/// compares with): on one walk the walk DP ([`walks::minimum`], polynomial, up to `limit`
/// stored vertices), else the same as `minitri`. When no minimum is proved, the better of the
/// search's triangulation and the flattened walk ([`walks::flattened`]), with the better lower
/// bound and `stopped`. For `ear` (and on a failed self-check) the plain triangulation.
pub(crate) fn touching<P: Coord>(
    polygon: &crate::Polygon<P>,
    algorithm: Algorithm,
    limit: usize,
    deadline: Option<std::time::Instant>,
) -> Result<Triangulation, TriangulateError> {
    let mut why = Stopped::Touching;
    if algorithm == Algorithm::Asano && polygon.holes() == 0 {
        match walks::minimum(polygon, limit, deadline) {
            Ok((triangles, degenerate)) => {
                return Ok(Triangulation {
                    algorithm,
                    triangles,
                    degenerate,
                    optimal: true,
                    lower_bound: None,
                    stopped: None,
                })
            }
            Err(stopped) => why = stopped,
        }
    }
    let mut general = algorithm
        .is_minimum()
        .then(|| minitri::triangulate_walks(polygon, deadline).ok())
        .flatten()
        .map(|t| Triangulation { algorithm, ..t });
    if let Some(t) = general.take_if(|t| t.optimal) {
        return Ok(t);
    }
    let flattened = algorithm
        .is_minimum()
        .then(|| walks::flattened(polygon, deadline).ok())
        .flatten();
    let (triangles, degenerate) = match flattened {
        Some(found) => found,
        None => (
            plain::walks(polygon).map_err(|e| TriangulateError::Touching {
                algorithm,
                detail: e.to_string(),
            })?,
            Vec::new(),
        ),
    };
    let mut lower = polygon.minimum_bounds().0;
    let (triangles, degenerate) = match general {
        Some(t) => {
            lower = lower.max(t.lower_bound.unwrap_or(0));
            why = t.stopped.unwrap_or(why);
            if t.triangles.len() < triangles.len() {
                (t.triangles, t.degenerate)
            } else {
                (triangles, degenerate)
            }
        }
        None => (triangles, degenerate),
    };
    let optimal = algorithm.is_minimum() && triangles.len() <= lower;
    Ok(Triangulation {
        algorithm,
        triangles,
        degenerate,
        optimal,
        lower_bound: (algorithm.is_minimum() && !optimal).then_some(lower),
        stopped: (algorithm.is_minimum() && !optimal).then_some(why),
    })
}

/// Why an algorithm could not triangulate a (valid) polygon.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum TriangulateError {
    /// The algorithm handles polygons without holes only.
    #[error("the {algorithm} algorithm handles polygons without holes only, and this polygon has {holes} hole{} (holes are planned for a later version)", if *holes == 1 { "" } else { "s" })]
    HolesUnsupported {
        /// The algorithm.
        algorithm: Algorithm,
        /// The number of holes.
        holes: usize,
    },
    /// The dynamic program for polygons with holes handles at most 2 holes.
    #[error("the asano dynamic program handles polygons with at most {max} holes (its time grows like n^(3+2k) with k holes), and this polygon has {holes} holes")]
    TooManyHoles {
        /// The number of holes.
        holes: usize,
        /// The most holes it handles.
        max: usize,
    },
    /// The polygon with holes is too large for the dynamic program's time (n^(3+2k)).
    #[error("the asano dynamic program with {holes} hole{} needs about {time} for {n} vertices (its time grows like n^{}), above its limit of {limit} vertices with {holes} hole{}", if *holes == 1 { "" } else { "s" }, 3 + 2 * holes, if *holes == 1 { "" } else { "s" })]
    TooLargeWithHoles {
        /// Number of vertices (all rings).
        n: usize,
        /// Number of holes.
        holes: usize,
        /// The limit in force for this number of holes.
        limit: usize,
        /// Estimated time, in words.
        time: String,
    },
    /// An algorithm that cannot (yet) run on rings that touch, or a self-check of the walks'
    /// triangulation that failed (see `algo::walks`; not seen in the tests).
    #[error(
        "the {algorithm} algorithm cannot triangulate this polygon with touching rings: {detail}"
    )]
    Touching {
        /// The algorithm.
        algorithm: Algorithm,
        /// Why.
        detail: String,
    },
    /// A self-check of the `pseudo-hull` construction failed (see `algo::pseudo_hull`; not
    /// seen in the tests).
    #[error("the pseudo-hull construction (Theorem 6) failed a self-check after {edges} edges, short of the {target} a minimum pseudotriangulation has; no answer is given rather than a wrong one")]
    PseudoHullIncomplete {
        /// Edges found.
        edges: usize,
        /// Edges needed, 3n - N - 3.
        target: usize,
    },
    /// A self-check of MINITRI's cut step for polygons with holes failed (see
    /// `algo::minitri::cut`; not seen in the tests).
    #[error("the minitri cut step for polygons with holes failed a self-check while {step} of the degenerate triangle whose middle is vertex {vertex} {point}; no answer is given rather than a wrong one")]
    MinitriCutFailed {
        /// What the step was doing.
        step: &'static str,
        /// The input number of the chosen triangle's middle vertex.
        vertex: usize,
        /// Its coordinates, as written in the input.
        point: String,
    },
    /// The polygon is too large for an algorithm with polynomial memory.
    #[error("the asano dynamic program needs about {memory} and {time} for {n} vertices, above its limit of {limit} vertices; use --algorithm minitri, or raise the limit with --dp-limit")]
    TooLarge {
        /// Number of vertices.
        n: usize,
        /// The limit in force.
        limit: usize,
        /// Estimated memory, in words.
        memory: String,
        /// Estimated time, in words.
        time: String,
    },
    /// The memory for the algorithm's tables could not be had (a reservation failed): the
    /// polygon is reported instead of aborting the run.
    #[error("not enough memory: the {algorithm} algorithm's tables for {n} vertices take {memory}, and that memory could not be had")]
    OutOfMemory {
        /// The algorithm.
        algorithm: Algorithm,
        /// Number of vertices.
        n: usize,
        /// The memory asked for, in words.
        memory: String,
    },
}

/// A vector of `len` copies of `value`, or `None` when that memory cannot be had (a failed
/// reservation, instead of the abort of `vec!`). The reservation is of address space: on a
/// system that overcommits memory, a later shortage of physical memory is not seen here.
pub(crate) fn try_filled<T: Clone>(len: usize, value: T) -> Option<Vec<T>> {
    let mut v = Vec::new();
    v.try_reserve_exact(len).ok()?;
    v.resize(len, value);
    Some(v)
}
