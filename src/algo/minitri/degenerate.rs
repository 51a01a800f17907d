//! Step 1 of MINITRI: all minimally degenerate triangles (Chen & Chang 1990, §3, Step 1).
//!
//! A degenerate triangle `(a, b, c)` has `b` strictly between `a` and `c` on one line, with `a b`
//! and `b c` chords; it is minimally degenerate when no other vertex lies on segment `a c`. Then
//! both directions along the line lie in the closed interior angle at `b`, so `b` is reflex (or
//! flat: the paper excludes flat vertices, we do not), and `a`, `c` are the NEAREST vertices
//! from `b` in two opposite directions, both seen along chords.
//!
//! Kinds (§3): type (i) when neither side is an edge; type (ii) when one side is an edge and no
//! vertex of the triangle has another polygon edge on the triangle's line; type (iii) when one
//! side is an edge and some vertex has another edge on that line; `Flat` when both sides are
//! edges (`b` is a flat vertex; its only degenerate triangle is `(prev, b, next)`).
//!
//! Method: for a flat vertex, its one triangle. For a reflex vertex `b`, only the directions `d`
//! with both `d` and `-d` in its closed angle matter: a double cone. Triangular expansion over a
//! plain triangulation ([`super::expansion`]) lists the nearest vertices seen from `b` in each of
//! the two cones, sorted by angle; merging them pairs exactly opposite directions. This covers
//! all three types at once (types (ii)/(iii) are the directions along `b`'s own edges). The
//! paper instead finds types (ii)/(iii) by ray shooting and type (i) by divide and conquer with
//! polygon cutting; [`minimally_degenerate_by_sweep`] keeps a simpler O(r n log n) method (an
//! angular sweep around each reflex vertex) as the reference for the tests.
//!
//! Lemma 3 of the paper, K < 2n - 1 triangles, is proved there for polygons without flat
//! vertices, and checked by the property tests on those. With flat vertices we know no proof; on
//! the test population (thousands of random grid polygons, most with flat vertices) K < 2n - 1
//! still held, which `tests/property.rs` keeps watching.
//!
//! Complexity: a plain triangulation (O(n log n), swept along x when the bounding box is more
//! than twice as wide as tall: `crate::algo::plain::polygon`), at most `12 n` edge flips to
//! fatten it, then work proportional to the triangles met inside each reflex vertex's double
//! cone where both cones may still see a vertex (about 40-50 per vertex on random stars; see
//! [`super::expansion`] and `docs/benchmarks.md`). Parts of a cone left with only isolated
//! directions to match become rays, and a ray that walks far is shot instead
//! ([`super::ray_shooting`]: O(log^2 n) per ray after an O(n log n) build). The walk from one
//! vertex of a simple polygon is given up past [`walk_budget`] triangles (O(log n); a shot counts
//! as `log2 n` of them, so a vertex shoots O(1) rays: O(log^2 n) per vertex), or past 64 while
//! more than a quarter of the walks are given up (`Progress::budget`), and the vertices given
//! up are searched by balanced cuts, shortest-path trees and rays shot in order of direction
//! ([`super::polygon_cutting`], O(n log^2 n)), so step 1 is O(n log^2 n) in the worst case on
//! simple polygons, the paper's bound. With holes or touching rings the walk has no budget (the
//! cutting needs a dual tree): O(n^2) in the worst case, and `deadline` bounds the step.

use super::expansion::{double_cone, Mesh, Workspace};
use super::ray_shooting::{Lazy, RayPolicy};
use crate::algo::chords::visible_from;
use crate::geom::kernel::{Coord, Dir};
use crate::geom::kernel::{cmp_angle, cross};
use crate::geom::polygon::Polygon;
use rayon::prelude::*;
use std::any::Any;
use std::cell::RefCell;
use std::cmp::Ordering;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering::Relaxed};

/// The kind of a minimally degenerate triangle (Chen & Chang, §3).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Kind {
    /// Neither side is a polygon edge.
    TypeI,
    /// One side is an edge; no vertex has another edge on the line.
    TypeII,
    /// One side is an edge; some vertex has another edge on the line.
    TypeIII,
    /// Both sides are edges: the middle vertex is flat.
    Flat,
}

/// A minimally degenerate triangle, in stored vertex indices: `b` lies strictly between `a` and
/// `c`, with `a < c`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Degenerate {
    /// One end.
    pub a: usize,
    /// The middle vertex.
    pub b: usize,
    /// The other end (`a < c`).
    pub c: usize,
    /// Its kind.
    pub kind: Kind,
}

impl Degenerate {
    pub(super) fn new<P: Coord>(polygon: &Polygon<P>, a: usize, b: usize, c: usize) -> Degenerate {
        let (a, c) = (a.min(c), a.max(c));
        let edge = |u: usize, v: usize| polygon.next(u) == v || polygon.next(v) == u;
        let kind = match (edge(a, b), edge(b, c)) {
            (true, true) => Kind::Flat,
            (false, false) => Kind::TypeI,
            (side_ab, _) => {
                let side = if side_ab { (a, b) } else { (b, c) };
                let (p, q) = (polygon.point(a), polygon.point(c));
                let on_line = |u: usize, v: usize| {
                    cross(p, q, polygon.point(u)) == 0 && cross(p, q, polygon.point(v)) == 0
                };
                let other_edge_on_line = [a, b, c].iter().any(|&v| {
                    [polygon.prev(v), polygon.next(v)].iter().any(|&w| {
                        let same = (v == side.0 && w == side.1) || (v == side.1 && w == side.0);
                        !same && on_line(v, w)
                    })
                });
                if other_edge_on_line {
                    Kind::TypeIII
                } else {
                    Kind::TypeII
                }
            }
        };
        Degenerate { a, b, c, kind }
    }

    /// The middle vertex's side of the line that is NOT the 180-degree side, as the sign of
    /// `cross(a, c, x)` for points `x` there: where `b`'s polygon neighbours lie; for a flat `b`
    /// the exterior side (the interior is on the left of `prev -> b -> next`).
    pub fn non_straight_side<P: Coord>(&self, polygon: &Polygon<P>) -> i32 {
        let (pa, pc) = (polygon.point(self.a), polygon.point(self.c));
        let side = |v: usize| cross(pa, pc, polygon.point(v)).signum() as i32;
        match (side(polygon.prev(self.b)), side(polygon.next(self.b))) {
            // Flat: the interior is on the left of prev -> next, so the exterior is on the
            // right of a -> c when a is the previous vertex, on the left otherwise.
            (0, 0) if polygon.prev(self.b) == self.a => -1,
            (0, 0) => 1,
            (0, s) | (s, _) => s,
        }
    }
}

/// Whether `b` is reflex (to be searched); a flat `b` adds its one triangle to `out` instead, and
/// a convex `b` is the middle of nothing (no two opposite directions fit in its angle).
fn reflex_or_flat<P: Coord>(polygon: &Polygon<P>, b: usize, out: &mut Vec<Degenerate>) -> bool {
    let turn = turn_at(polygon, b);
    if turn == 0 {
        out.push(Degenerate::new(
            polygon,
            polygon.prev(b),
            b,
            polygon.next(b),
        ));
    }
    turn < 0
}

/// Whether `b` can be the middle of a minimally degenerate triangle: its angle is 180 degrees
/// or more (reflex or flat).
pub fn can_be_middle<P: Coord>(polygon: &Polygon<P>, b: usize) -> bool {
    turn_at(polygon, b) <= 0
}

/// The turn at `b` (positive: convex, interior on the left of every edge).
fn turn_at<P: Coord>(polygon: &Polygon<P>, b: usize) -> i128 {
    let (p, q) = (polygon.prev(b), polygon.next(b));
    cross(polygon.point(p), polygon.point(b), polygon.point(q))
}

/// The most edge flips made per vertex to fatten the triangulation walked: a bound (the flips
/// stay O(n)), since the flips are steered by inexact incircle tests
/// ([`Mesh::flip_towards_delaunay`]) and Lawson's flips can number O(n^2). Until they stop,
/// random star and rectilinear polygons need at most about 3.5 flips per vertex and Natural
/// Earth country outlines at most 2.3 (Iran); TIGER/Line state boundaries, whose long runs of
/// almost collinear vertices the sweep joins by fans across the state, 4.2 to 10.5 where rivers
/// make up some sides (Iowa to Kansas; their whole runs then take 13-50% fewer instructions
/// than with 4) and 25 to 82 where straight lines make up all four (Colorado, Utah, Wyoming, New
/// Mexico; flips past 4 cost them 8-16% and the walks gain nothing). 12 lets the first kind
/// finish and stops the second sooner than 16 would (docs/benchmarks.md).
const FLIPS_PER_VERTEX: usize = 12;

/// The smallest polygon whose triangulation is flipped before walking: in smaller ones the walks
/// are short whatever the triangles' shapes, and the flips cost more than they save (about even
/// at 50 vertices; docs/benchmarks.md).
const FLIPS_FROM: usize = 48;

/// All minimally degenerate triangles of a polygon (holes allowed), by triangular expansion from
/// each reflex vertex inside its double cone ([`super::expansion`]) over a plain triangulation.
pub fn minimally_degenerate<P: Coord>(polygon: &Polygon<P>) -> Vec<Degenerate> {
    minimally_degenerate_and_mesh(polygon).0
}

/// [`minimally_degenerate`], also handing back the plain triangulation it walked (`n + 2w - 2`
/// positive triangles, every side an edge or a proper diagonal), so that later steps need not
/// build another one.
pub fn minimally_degenerate_and_mesh<P: Coord>(
    polygon: &Polygon<P>,
) -> (Vec<Degenerate>, Vec<[usize; 3]>) {
    let (found, mesh, _) = minimally_degenerate_and_mesh_until(polygon, None);
    (found, mesh)
}

/// [`minimally_degenerate_and_mesh`], stopping at `deadline`: the triangles found by then (from
/// a subset of the middle vertices; each is minimally degenerate all the same), the mesh, and
/// how many vertices that could be a middle ([`can_be_middle`]) were not looked from (0: the
/// search finished). A vertex is looked from completely or not at all: every triangle whose
/// middle was looked from is found. The deadline is read before every 16th middle vertex.
pub fn minimally_degenerate_and_mesh_until<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<std::time::Instant>,
) -> (Vec<Degenerate>, Vec<[usize; 3]>, usize) {
    let plain = crate::algo::plain::polygon(polygon, None);
    minimally_degenerate_over_until(polygon, plain, deadline)
}

/// [`minimally_degenerate_and_mesh_until`] over a given plain triangulation `plain` of the
/// polygon (counter-clockwise triangles of stored vertices covering it). For touching rings,
/// the walks' plain triangulation (`crate::algo::plain::walks`): a copy of a touch point is a
/// vertex of its own with its own fan of triangles inside its sector, so the mesh is that of the
/// polygon with each copy moved into its sector, and the expansion never passes through a
/// vertex (it stops at the nearest one in each direction); the tests compare the result with
/// [`minimally_degenerate_by_sweep`] on random touching polygons.
pub fn minimally_degenerate_over_until<P: Coord>(
    polygon: &Polygon<P>,
    plain: Vec<[usize; 3]>,
    deadline: Option<std::time::Instant>,
) -> (Vec<Degenerate>, Vec<[usize; 3]>, usize) {
    minimally_degenerate_over_with(polygon, plain, deadline, RayPolicy::Hybrid)
}

/// All minimally degenerate triangles as [`minimally_degenerate`] finds them, with rays walked
/// or shot as `policy` says ([`super::ray_shooting`]) and the work shared between the walk and
/// the bounded method as `budget` says: the same set whatever the choices (the tests compare
/// them), only the time differs.
pub fn minimally_degenerate_with<P: Coord>(
    polygon: &Polygon<P>,
    policy: RayPolicy,
    budget: Budget,
) -> Vec<Degenerate> {
    let plain = crate::algo::plain::polygon(polygon, None);
    minimally_degenerate_over_budget(polygon, plain, None, policy, budget).0
}

/// The oracle of the tests and the `step_one` fuzz target: the set of minimally degenerate
/// triangles, kinds included, found with each [`RayPolicy`] and each [`Budget`] must equal the
/// angular sweep's ([`minimally_degenerate_by_sweep`]). Returns how many there are, or the
/// first choice that disagrees with both sets.
///
/// # Errors
/// A description of the disagreement (a bug).
pub fn check_ray_policies<P: Coord>(polygon: &Polygon<P>) -> Result<usize, String> {
    let sorted = |found: &[Degenerate]| {
        let mut keys: Vec<_> = found
            .iter()
            .map(|m| (m.a, m.b, m.c, m.kind as u8))
            .collect();
        keys.sort_unstable();
        keys
    };
    let swept = sorted(&minimally_degenerate_by_sweep(polygon));
    let choices = [
        (RayPolicy::WalkOnly, Budget::WalkOnly),
        (RayPolicy::ShootOnly, Budget::WalkOnly),
        (RayPolicy::Hybrid, Budget::Hybrid),
        (RayPolicy::Hybrid, Budget::CutsOnly),
        (RayPolicy::WalkOnly, Budget::CutsOnly),
    ];
    for (policy, budget) in choices {
        let found = sorted(&minimally_degenerate_with(polygon, policy, budget));
        if found != swept {
            return Err(format!(
                "{policy:?} {budget:?}: {found:?}, the sweep: {swept:?}"
            ));
        }
    }
    Ok(swept.len())
}

/// How step 1 shares its work between the walk and the bounded method
/// ([`super::polygon_cutting`]), which applies to simple polygons (one ring, no touching rings;
/// others are walked whatever this says). The same set of triangles either way (the tests
/// compare them); only the time differs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Budget {
    /// The default: the walk from each vertex, given up after [`walk_budget`] triangles, and
    /// the bounded method for the vertices given up.
    Hybrid,
    /// The walk alone (budget unlimited).
    WalkOnly,
    /// The bounded method alone (budget 0), for every reflex vertex.
    CutsOnly,
}

/// The triangles a walk from one vertex of a polygon of `n` vertices may cross with parts of
/// non-zero width before it is given up: `WALK_BUDGET_PER_LOG * ceil(log2 n)`, at least
/// [`WALK_BUDGET_MIN`]. So the walks cost O(n log n) in all whatever the polygon, and the
/// bounded method takes the vertices over it. The bounded method's constant factor is several
/// times the walk's, so the budget is set where no vertex of the random stars, combs, slivers
/// and Natural Earth boundaries of docs/benchmarks.md reaches it (China's would at 1024), while
/// a boundary with long straight lines of almost collinear vertices (a TIGER state line) hands
/// its longest walks over.
pub fn walk_budget(n: usize) -> usize {
    let log = usize::BITS - n.max(2).leading_zeros();
    (WALK_BUDGET_PER_LOG * log as usize).max(WALK_BUDGET_MIN)
}

/// See [`walk_budget`].
pub const WALK_BUDGET_PER_LOG: usize = 160;
/// See [`walk_budget`].
pub const WALK_BUDGET_MIN: usize = 2048;

/// [`minimally_degenerate_over_until`] with rays walked or shot as `policy` says.
pub fn minimally_degenerate_over_with<P: Coord>(
    polygon: &Polygon<P>,
    plain: Vec<[usize; 3]>,
    deadline: Option<std::time::Instant>,
    policy: RayPolicy,
) -> (Vec<Degenerate>, Vec<[usize; 3]>, usize) {
    minimally_degenerate_over_budget(polygon, plain, deadline, policy, Budget::Hybrid)
}

/// [`minimally_degenerate_over_with`], the work shared between the walk and the bounded method
/// as `budget` says.
pub fn minimally_degenerate_over_budget<P: Coord>(
    polygon: &Polygon<P>,
    plain: Vec<[usize; 3]>,
    deadline: Option<std::time::Instant>,
    policy: RayPolicy,
    budget: Budget,
) -> (Vec<Degenerate>, Vec<[usize; 3]>, usize) {
    let mut mesh = Mesh::new(polygon, plain);
    if polygon.len() >= FLIPS_FROM {
        mesh.flip_towards_delaunay(polygon, FLIPS_PER_VERTEX * polygon.len());
    }
    let progress = Progress::default();
    let n = polygon.len();
    let simple = polygon.holes() == 0 && polygon.touches() == 0;
    let limit = match budget {
        _ if !simple => usize::MAX,
        Budget::Hybrid => walk_budget(n),
        Budget::WalkOnly => usize::MAX,
        Budget::CutsOnly => 0,
    };
    // Long rays are shot over heavy paths once walking them has cost enough (built at most once).
    let shooter = Lazy::new(n, policy).with_budget(limit);
    // The vertices are independent searches over a shared mesh: in parallel (on the current
    // rayon pool) by blocks of vertices, concatenated in vertex order, so the result does not
    // depend on the number of threads. A polygon of one block skips the pool altogether.
    let search = |range| {
        search_range(
            polygon,
            &mesh,
            &shooter,
            range,
            deadline,
            &progress,
        )
    };
    let (found, given_up) = if n <= PARALLEL_BLOCK {
        search(0..n)
    } else {
        let blocks: Vec<(Vec<Degenerate>, Vec<usize>)> = (0..n.div_ceil(PARALLEL_BLOCK))
            .into_par_iter()
            .map(|block| search(block * PARALLEL_BLOCK..((block + 1) * PARALLEL_BLOCK).min(n)))
            .collect();
        let (found, given_up): (Vec<_>, Vec<_>) = blocks.into_iter().unzip();
        (found.concat(), given_up.concat())
    };
    let Progress {
        cut_short,
        unexamined,
        ..
    } = progress;
    let mut unexamined = unexamined.into_inner();
    if given_up.is_empty() {
        return (found, mesh.into_triangles(), unexamined);
    }
    // The vertices whose walk was given up: the bounded method, unless the deadline passed.
    let mut wanted = vec![false; n];
    for &b in &given_up {
        wanted[b] = true;
    }
    let more = if cut_short.into_inner() {
        None
    } else {
        let shooter = shooter.force(polygon, &mesh);
        super::polygon_cutting::middles(polygon, &mesh, shooter, &wanted, deadline)
    };
    let Some(mut more) = more else {
        unexamined += given_up.len();
        return (found, mesh.into_triangles(), unexamined);
    };
    // In the walk's order: by middle vertex, then as `search_from` pairs the two cones.
    in_walk_order(polygon, &mut more);
    let mut merged = Vec::with_capacity(found.len() + more.len());
    let mut rest = more.into_iter().peekable();
    for m in found {
        while let Some(x) = rest.next_if(|x| x.b < m.b) {
            merged.push(x);
        }
        merged.push(m);
    }
    merged.extend(rest);
    (merged, mesh.into_triangles(), unexamined)
}

/// Sorts triangles as [`search_from`] lists them: by middle vertex `b`, then by the angle from
/// `next(b)` of the end in `b`'s first cone (the end whose direction lies less than a half-turn
/// counter-clockwise from `next(b)`).
fn in_walk_order<P: Coord>(polygon: &Polygon<P>, list: &mut [Degenerate]) {
    // From `b`: the direction of next(b), and that of the end at the smaller angle from it
    // (the ends are a half-turn apart, so exactly one lies less than a half-turn on).
    let key = |m: &Degenerate| {
        let c = polygon.point(m.b);
        let dir = |v: usize| Dir::between(c, polygon.point(v));
        let (base, da, dc) = (dir(polygon.next(m.b)), dir(m.a), dir(m.c));
        (base, std::cmp::min_by(da, dc, |x, y| base.cmp_angle_from(*x, *y)))
    };
    list.sort_by(|x, y| {
        x.b.cmp(&y.b).then_with(|| {
            let ((base, dx), (_, dy)) = (key(x), key(y));
            base.cmp_angle_from(dx, dy)
        })
    });
}

/// The triangles found from the vertices of `range`, in vertex order, until `deadline` (then
/// `cut_short` is set, and the vertices of `range` that could be a middle and were not looked
/// from are added to `unexamined`), and the reflex vertices whose walk was given up (over the
/// budget of `shooter`).
fn search_range<P: Coord>(
    polygon: &Polygon<P>,
    mesh: &Mesh,
    shooter: &Lazy,
    range: std::ops::Range<usize>,
    deadline: Option<std::time::Instant>,
    progress: &Progress,
) -> (Vec<Degenerate>, Vec<usize>) {
    let Progress {
        cut_short,
        unexamined,
        ..
    } = progress;
    // One workspace per thread, kept from call to call (a batch of small polygons would
    // otherwise grow its buffers again for every polygon). Nothing in the search calls back
    // into the thread pool, so the borrow never nests.
    // (One slot per kernel: a thread-local cannot be generic.)
    thread_local!(static WORK: RefCell<Vec<Box<dyn Any>>> = RefCell::default());
    WORK.with_borrow_mut(|slots| {
        let k = match slots.iter().position(|s| s.is::<Workspace<P>>()) {
            Some(k) => k,
            None => {
                slots.push(Box::new(Workspace::<P>::default()));
                slots.len() - 1
            }
        };
        let Some(work) = slots[k].downcast_mut::<Workspace<P>>() else {
            unreachable!("slot {k} holds a workspace of this kernel")
        };
        let mut out = Vec::new();
        let mut given_up = Vec::new();
        let end = range.end;
        for b in range {
            if let Some(deadline) = deadline.filter(|_| b % 16 == 0) {
                if cut_short.load(Relaxed) || std::time::Instant::now() >= deadline {
                    cut_short.store(true, Relaxed);
                    let left = (b..end).filter(|&v| can_be_middle(polygon, v)).count();
                    unexamined.fetch_add(left, Relaxed);
                    break;
                }
            }
            let budget = progress.budget(shooter.budget());
            if let Some(finished) = search_from(polygon, mesh, shooter, b, budget, work, &mut out) {
                progress.count(finished);
                if !finished {
                    given_up.push(b);
                }
            }
        }
        (out, given_up)
    })
}

/// What the parallel searches from the vertices of one polygon share: whether the deadline cut
/// them short, how many vertices that could be a middle were not looked from, and how many
/// walks finished and were given up, which sets the next walk's budget ([`Progress::budget`]).
#[derive(Default)]
struct Progress {
    cut_short: AtomicBool,
    unexamined: AtomicUsize,
    walked: AtomicUsize,
    given_up: AtomicUsize,
}

impl Progress {
    /// The budget of the next walk, at most `full`: [`SHORT_BUDGET`] while more than one walk
    /// in [`GIVEN_UP_RATIO`], and more than [`GIVEN_UP_SLACK`] walks, have been given up. Where
    /// most walks are long, the bounded method will search most of the polygon anyway (its
    /// cuts and trees cost about the same whether a piece holds one vertex to search or all),
    /// and a walk given up at the full budget is work lost: on the `parabola` benchmark (every
    /// vertex reflex, every walk long) the full budget cost 5-6 times the bounded method alone,
    /// the short one 1.3-1.6 times (docs/benchmarks.md). Where few are, as on state boundaries,
    /// the walks keep their full budget. Which vertices are walked and which handed over
    /// depends on the threads' timing; the triangles found do not.
    fn budget(&self, full: usize) -> usize {
        let (walked, given_up) = (self.walked.load(Relaxed), self.given_up.load(Relaxed));
        if given_up > GIVEN_UP_SLACK && given_up.saturating_mul(GIVEN_UP_RATIO) > walked {
            full.min(SHORT_BUDGET)
        } else {
            full
        }
    }

    /// Counts a walk, finished or given up.
    fn count(&self, finished: bool) {
        self.walked.fetch_add(1, Relaxed);
        if !finished {
            self.given_up.fetch_add(1, Relaxed);
        }
    }
}

/// See [`Progress::budget`].
const GIVEN_UP_RATIO: usize = 4;
/// See [`Progress::budget`].
const GIVEN_UP_SLACK: usize = 16;
/// See [`Progress::budget`]: a walk not finished by the time its parts would be cut into rays.
const SHORT_BUDGET: usize = super::expansion::ISOLATE_AFTER;

/// How many vertices one parallel task searches from (small polygons stay on one thread). Small
/// enough that a 1000-vertex polygon keeps two cores busy (4 tasks; docs/benchmarks.md), large
/// enough that a task costs far more than handing it out.
const PARALLEL_BLOCK: usize = 256;

/// Adds the minimally degenerate triangles with middle vertex `b` to `out`, walking at most
/// `budget` triangles from it if it is reflex: `None` if it is not (nothing walked), else
/// whether the walk finished (`false`: given up over the budget, nothing added).
fn search_from<P: Coord>(
    polygon: &Polygon<P>,
    mesh: &Mesh,
    shooter: &Lazy,
    b: usize,
    budget: usize,
    work: &mut Workspace<P>,
    out: &mut Vec<Degenerate>,
) -> Option<bool> {
    if !reflex_or_flat(polygon, b, out) {
        return None;
    }
    if budget == 0 {
        return Some(false);
    }
    let Some((first, second)) = double_cone(polygon, mesh, b, work, shooter, budget) else {
        return Some(false);
    };
    // Opposite directions are at the same place of the two cones (both sorted by angle).
    let (mut i, mut j) = (0, 0);
    while i < first.len() && j < second.len() {
        let (d, e) = (first[i].0, second[j].0.reversed());
        match d.cross(e).cmp(&0) {
            Ordering::Greater => i += 1,
            Ordering::Less => j += 1,
            Ordering::Equal => {
                out.push(Degenerate::new(polygon, first[i].1, b, second[j].1));
                i += 1;
                j += 1;
            }
        }
    }
    Some(true)
}

/// The same triangles by an angular visibility sweep around every reflex vertex: O(r n log n).
/// The reference for tests of [`minimally_degenerate`].
pub fn minimally_degenerate_by_sweep<P: Coord>(polygon: &Polygon<P>) -> Vec<Degenerate> {
    minimally_degenerate_by_sweep_until(polygon, None).0
}

/// [`minimally_degenerate_by_sweep`], stopping at `deadline` (read before every 16th middle
/// vertex): the triangles found, and whether the search finished. It also takes the boundary
/// walks of touching rings (`crate::algo::walks`): the chord sweep (`visible_from`) handles
/// the copies of a touch point, and of the copies at the nearest point in a direction, the one
/// seen is the triangle's end (at most one is: the copies' closed angles are disjoint away from
/// the point). This is step 1 for touching rings, where the plain triangulation walked by
/// [`minimally_degenerate`] would have to go round touch points.
pub fn minimally_degenerate_by_sweep_until<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<std::time::Instant>,
) -> (Vec<Degenerate>, bool) {
    let mut out = Vec::new();
    let mut visible = Vec::new();
    let mut seen = vec![false; polygon.len()];
    for b in 0..polygon.len() {
        if b % 16 == 0 && crate::algo::past(deadline) {
            return (out, false);
        }
        if !reflex_or_flat(polygon, b, &mut out) {
            continue;
        }
        let order = visible_from(polygon, b, &mut visible);
        for &u in &visible {
            seen[u] = true;
        }
        // The nearest point of each direction around b, if a vertex there is seen along a
        // chord (one of its copies, for a touch point).
        let c = polygon.point(b);
        let mut nearest: Vec<usize> = Vec::new();
        let mut first: Option<usize> = None;
        for &u in &order {
            let same_direction = first.is_some_and(|l| {
                cmp_angle(c, polygon.point(l), polygon.point(u)) == Ordering::Equal
            });
            if same_direction {
                let at_first = first.is_some_and(|l| polygon.point(l) == polygon.point(u));
                if at_first && seen[u] && nearest.last() != first.as_ref() {
                    nearest.push(u);
                    first = Some(u);
                }
                continue;
            }
            first = Some(u);
            if seen[u] {
                nearest.push(u);
            }
        }
        for &u in &visible {
            seen[u] = false;
        }
        // Pair opposite directions: both halves are sorted by angle.
        let upper = |u: usize| crate::geom::kernel::above(c, polygon.point(u));
        let split = nearest.partition_point(|&u| upper(u));
        let (top, bottom) = nearest.split_at(split);
        let mut j = 0;
        for &w in bottom {
            while j < top.len() && cross(c, polygon.point(top[j]), polygon.point(w)) < 0 {
                j += 1;
            }
            if j < top.len() && cross(c, polygon.point(top[j]), polygon.point(w)) == 0 {
                out.push(Degenerate::new(polygon, top[j], b, w));
            }
        }
    }
    (out, true)
}

#[cfg(test)]
mod tests {
    use super::{Progress, GIVEN_UP_SLACK, SHORT_BUDGET};

    /// The walks keep their full budget while few are given up, and get the short one once
    /// more than one in four (past the slack) is; it comes back when enough finish again.
    #[test]
    fn walks_get_the_short_budget_once_many_are_given_up() {
        let progress = Progress::default();
        let full = 2048;
        for _ in 0..GIVEN_UP_SLACK {
            progress.count(false);
        }
        assert_eq!(progress.budget(full), full, "within the slack");
        progress.count(false);
        assert_eq!(progress.budget(full), SHORT_BUDGET);
        assert_eq!(progress.budget(10), 10, "never more than the full budget");
        for _ in 0..3 * (GIVEN_UP_SLACK + 1) {
            progress.count(true);
        }
        assert_eq!(progress.budget(full), full, "one in four given up");
    }
}
