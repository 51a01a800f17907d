//! Independent checks of any triangulation, exact, sharing no code with the algorithms.
//!
//! Input contract: a valid [`Polygon`] (as built by [`Polygon::from_raw`]: distinct vertices on
//! the exact grid, interior on the left of every edge `i -> next(i)`) and ANY [`Triangulation`]:
//! indices may be out of range, repeated or nonsense; nothing here panics on them. Only the exact
//! kernel and the polygon's accessors are used; no floating point decides anything.
//!
//! Output guarantee: [`check`] returns `valid == true` (and no problems) exactly when
//! 1. every index is a vertex of the polygon and the three corners of a triangle are distinct;
//! 2. every triangle is nondegenerate and counter-clockwise;
//! 3. the triangles partition the polygon (the boundary chain below sums to zero);
//! 4. the triangles' total twice-area equals the polygon's;
//! 5. `triangles.len() == n + 2w - 2 - degenerate.len()`;
//! 6. each listed degenerate triangle `[a, b, c]` has `b` strictly between `a` and `c`, the whole
//!    segment `a c` lies on one side of some triangle (so `b` is a T-junction), and no two listed
//!    degenerate triangles share their middle vertex (in particular none is listed twice);
//! 7. the numbers reported beside the triangles hold: the flat vertices and the bounds
//!    recounted, `ceil((n - f)/3) <= lower_bound <= count <= n + 2w - 2`, no lower bound beside
//!    an optimal count ([`bounds`]).
//!
//! Otherwise `problems` holds human sentences (at most [`MAX_PROBLEMS`], then `... and N more`)
//! naming triangles by position in their list (from 0) and by INPUT vertex numbers, and
//! `faults` says WHERE, for drawing (all of them, not only the first [`MAX_PROBLEMS`]): the
//! triangles failing checks 1-2, the degenerate triangles failing check 6, and the stretches of
//! check 3 where the boundaries do not cancel (beside each lies a gap, an overlap or a triangle
//! outside the polygon). Checks 4 and 5 are global and have no place of their own.
//!
//! # Why the boundary chain proves a partition
//!
//! Give each side of each triangle, directed counter-clockwise, the weight +1, and each polygon
//! edge `i -> next(i)` the weight -1. For a point `x` on none of these segments, the winding
//! number of this 1-chain around `x` is `f(x) = cover(x) - inside(x)`, where `cover(x)` counts
//! the triangles whose interior holds `x` and `inside(x)` is 1 inside the polygon, 0 outside: a
//! counter-clockwise triangle winds once around its interior points, and the polygon's rings
//! (outer counter-clockwise, holes clockwise) wind once around exactly the polygon's interior
//! points. If the chain is zero (on every line, the weights of the segments on it cancel on every
//! stretch), every winding number is zero, so `f = 0` off a finite union of segments, a set of
//! measure zero. Since every triangle is positive:
//!
//! - interiors are disjoint: two overlapping open triangles would overlap in an open set, with
//!   points where `f >= 2 - 1 > 0`;
//! - nothing lies outside: an open triangle is a.e. inside the polygon, hence inside the closed
//!   polygon, and so is the closed triangle; its sides then lie in the closed polygon, and their
//!   ends are vertices, which is the definition of a chord;
//! - no hole is swallowed: points of a hole's interior have `f = 0` and are outside the polygon,
//!   so no triangle covers them (the trap with holes of `docs/algorithms.md`: chords alone do not show this);
//! - the union is the polygon: a.e. interior point is covered once, the union of the closed
//!   triangles is closed, so it contains the closure of the interior, the closed polygon.
//!
//! Conversely a partition gives `f = 0` a.e., so the chain (the boundary of `f`) is zero: the test
//! is exact in both directions. Sides shared by two triangles with the same two end vertices, and
//! polygon edges that are also triangle sides, cancel first (sorted by vertex pair); only the
//! remaining segments are grouped by their supporting line (an exact integer key: primitive
//! direction and offset) and swept along it in sorted order.
//!
//! # Why the degenerate list is exactly the set of T-junctions
//!
//! In a partition, `T = n + 2w - 2 - J`, where `J` counts the vertices lying inside a side of a
//! triangle: the triangles' angles sum to `T pi`, and they fill the polygon's interior angles,
//! which sum to `(n + 2w - 2) pi`, except for a straight angle at each such vertex. A vertex lies
//! inside at most one side (two would cover a whole neighbourhood of it, or overlap). Check 6 maps
//! each listed degenerate triangle to such a vertex, injectively (distinct middles), and check 5
//! says there are `J` of them; so the list is exactly the T-junctions. Its segments `a b` and `b c`
//! are chords, being parts of a triangle side.
//!
//! Complexity: O((T + n + d) log(T + n + d)) time, O(T + n + d) memory, for `T` triangles, `n`
//! vertices and `d` degenerate triangles: a few sorts, never pairs of triangles or triangles
//! times edges.

use crate::algo::{Algorithm, Triangulation};
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cross, line_through, strictly_between, Area, Point};
use crate::geom::polygon::Polygon;
use std::cmp::Ordering;

/// The largest number of problems listed; further ones are only counted.
pub const MAX_PROBLEMS: usize = 20;

/// The outcome of checking one triangulation.
#[derive(Clone, Debug, PartialEq, Eq, serde::Serialize)]
pub struct Check {
    /// Whether the triangulation is valid (exactly when `problems` is empty).
    pub valid: bool,
    /// What is wrong, as sentences; at most [`MAX_PROBLEMS`] and a final `... and N more`.
    pub problems: Vec<String>,
    /// Where it is wrong (not serialised: the sentences name the same places).
    #[serde(skip)]
    pub faults: Faults,
}

/// The places a check found wrong, for drawing them; empty when the triangulation is valid.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Faults {
    /// Positions in `triangles` of the triangles failing checks 1-2 (bad or repeated index, zero
    /// area, clockwise), in increasing order.
    pub triangles: Vec<usize>,
    /// Positions in `degenerate` of the degenerate triangles failing checks 1 or 6.
    pub degenerate: Vec<usize>,
    /// Check 3: each stretch `[from, to]` of grid points along which (triangles covering) minus
    /// (polygon) is higher on the left than on the right; so the left side, near the stretch, is
    /// covered too often (overlap, or a triangle outside) or the right side too rarely (a gap).
    pub stretches: Vec<[Point; 2]>,
}

impl Faults {
    /// Whether nothing was found at any place.
    pub fn is_empty(&self) -> bool {
        self.triangles.is_empty() && self.degenerate.is_empty() && self.stretches.is_empty()
    }
}

/// Checks, exactly, that `t` is a valid triangulation of `polygon` (see the module documentation
/// for what is checked and why it suffices).
pub fn check<P: Coord>(polygon: &Polygon<P>, t: &Triangulation) -> Check {
    let mut problems = Problems::default();
    check_count(polygon, t, &mut problems);
    check_area(polygon, t, &mut problems);
    check_triangles(polygon, t, &mut problems);
    check_chain(polygon, t, &mut problems);
    check_degenerate(polygon, t, &mut problems);
    for problem in bounds::problems(polygon, t) {
        problems.add(|| problem);
    }
    problems.finish()
}

/// Compares the results of exact minimum algorithms on one polygon, each given as (algorithm,
/// triangle count, lower bound): the bound is `None` when the algorithm proved its count
/// minimum (`optimal`), else the bound it proved. `None` when they are consistent, else a
/// sentence such as `asano gives 5 triangles but minitri gives 6`: two proved minimums differ,
/// or a count lies below what another result proved (an optimal count is its own bound; two
/// results cut short by a time limit may differ, as long as neither goes below the other's
/// bound). Entries of algorithms that do not compute a minimum ([`Algorithm::is_minimum`]) are
/// ignored.
pub fn agreement(results: &[(Algorithm, usize, Option<usize>)]) -> Option<String> {
    let exact: Vec<&(Algorithm, usize, Option<usize>)> =
        results.iter().filter(|(a, _, _)| a.is_minimum()).collect();
    let mut optimal = exact.iter().filter(|(_, _, lower)| lower.is_none());
    if let Some(&&(first, count, _)) = optimal.next() {
        let others: Vec<String> = optimal
            .filter(|&&&(_, c, _)| c != count)
            .map(|&&(a, c, _)| format!("{a} gives {c}"))
            .collect();
        if !others.is_empty() {
            return Some(format!(
                "{first} gives {} but {}",
                plural(count, "triangle"),
                others.join(" and ")
            ));
        }
    }
    for &&(a, count, _) in &exact {
        for &&(b, other, lower) in &exact {
            let bound = lower.unwrap_or(other);
            if count < bound {
                let claim = match lower {
                    None => format!("gives {other} as the minimum"),
                    Some(l) => format!("proves at least {l}"),
                };
                return Some(format!(
                    "{a} gives {} but {b} {claim}",
                    plural(count, "triangle")
                ));
            }
        }
    }
    None
}

/// Collects problems up to [`MAX_PROBLEMS`], counting the rest without formatting them, and
/// every fault's place.
#[derive(Default)]
struct Problems {
    list: Vec<String>,
    more: usize,
    faults: Faults,
}

impl Problems {
    fn add(&mut self, message: impl FnOnce() -> String) {
        if self.list.len() < MAX_PROBLEMS {
            self.list.push(message());
        } else {
            self.more += 1;
        }
    }

    fn finish(mut self) -> Check {
        if self.more > 0 {
            self.list.push(format!("... and {} more", self.more));
        }
        self.faults.triangles.sort_unstable();
        self.faults.triangles.dedup();
        self.faults.degenerate.sort_unstable();
        self.faults.degenerate.dedup();
        Check {
            valid: self.list.is_empty(),
            problems: self.list,
            faults: self.faults,
        }
    }
}

fn plural(count: usize, word: &str) -> String {
    if count == 1 {
        format!("1 {word}")
    } else {
        format!("{count} {word}s")
    }
}

/// The corners of `tri` when its indices are in range and distinct.
fn corners<P: Coord>(polygon: &Polygon<P>, tri: [usize; 3]) -> Option<[P; 3]> {
    let [a, b, c] = tri;
    let in_range = tri.iter().all(|&i| i < polygon.len());
    (in_range && a != b && b != c && a != c).then(|| tri.map(|i| polygon.point(i)))
}

/// `what k [ids]` with input vertex numbers, or the raw stored indices if any is out of range.
fn name<P: Coord>(polygon: &Polygon<P>, what: &str, k: usize, tri: [usize; 3]) -> String {
    if tri.iter().all(|&i| i < polygon.len()) {
        let [a, b, c] = tri.map(|i| polygon.id(i));
        format!("{what} {k} [{a}, {b}, {c}]")
    } else {
        let [a, b, c] = tri;
        format!("{what} {k} with stored indices [{a}, {b}, {c}]")
    }
}

/// Problems with the indices of `tri`, if any (check 1).
fn index_problem<P: Coord>(
    polygon: &Polygon<P>,
    what: &str,
    k: usize,
    tri: [usize; 3],
) -> Option<String> {
    let n = polygon.len();
    if let Some(&bad) = tri.iter().find(|&&i| i >= n) {
        let name = name(polygon, what, k, tri);
        return Some(format!(
            "{name} uses index {bad}, but the polygon has only {n} vertices"
        ));
    }
    let [a, b, c] = tri;
    let repeated = if a == b || a == c { a } else { b };
    (a == b || b == c || a == c).then(|| {
        let id = polygon.id(repeated);
        format!("{} repeats vertex {id}", name(polygon, what, k, tri))
    })
}

/// Check 5: the number of triangles.
fn check_count<P: Coord>(polygon: &Polygon<P>, t: &Triangulation, problems: &mut Problems) {
    let (n, w, d) = (polygon.len(), polygon.holes(), t.degenerate.len());
    let expected = n as i128 + 2 * w as i128 - d as i128 - 2;
    if t.triangles.len() as i128 != expected {
        problems.add(|| {
            format!(
                "{}, but n + 2w - d - 2 = {n} + {} - {d} - 2 = {expected}",
                plural(t.triangles.len(), "triangle"),
                2 * w
            )
        });
    }
}

/// Check 4: the total area (triangles with unusable indices count as zero).
fn check_area<P: Coord>(polygon: &Polygon<P>, t: &Triangulation, problems: &mut Problems) {
    let mut total = Area::default();
    for &tri in &t.triangles {
        if let Some([a, b, c]) = corners(polygon, tri) {
            total.add(a, b, c);
        }
    }
    let want = polygon.twice_area();
    if total != want {
        problems.add(|| {
            format!(
                "the triangles' total twice-area is {} but the polygon's is {} (in units of the exact grid)",
                total,
                want
            )
        });
    }
}

/// Checks 1 and 2 for every triangle.
fn check_triangles<P: Coord>(polygon: &Polygon<P>, t: &Triangulation, problems: &mut Problems) {
    for (k, &tri) in t.triangles.iter().enumerate() {
        if let Some(problem) = index_problem(polygon, "triangle", k, tri) {
            problems.add(|| problem);
            problems.faults.triangles.push(k);
            continue;
        }
        let [a, b, c] = tri.map(|i| polygon.point(i));
        let what = match cross(a, b, c).cmp(&0) {
            Ordering::Greater => continue,
            Ordering::Equal => "has zero area",
            Ordering::Less => "is clockwise",
        };
        problems.add(|| format!("{} {what}", name(polygon, "triangle", k, tri)));
        problems.faults.triangles.push(k);
    }
}

/// One end of a weighted segment on a line: the running weight changes by `delta` at `at`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Event<P: Coord> {
    line: P::Line,
    at: P,
    delta: i64,
}

/// Check 3: the boundary chain of the triangles minus that of the polygon is zero.
fn check_chain<P: Coord>(polygon: &Polygon<P>, t: &Triangulation, problems: &mut Problems) {
    // Every segment with weight +1: triangle sides as they run, polygon edges reversed (-1).
    let mut sides: Vec<[usize; 2]> = Vec::with_capacity(3 * t.triangles.len() + polygon.len());
    for &tri in &t.triangles {
        if corners(polygon, tri).is_some() {
            let [a, b, c] = tri;
            sides.extend([[a, b], [b, c], [c, a]]);
        }
    }
    sides.extend((0..polygon.len()).map(|i| [polygon.next(i), i]));
    check_sides_cancel(polygon, sides, problems);
}

/// The chain of `sides` (each `[from, to]` with weight +1) is zero: on every line, the weights of
/// the segments on it cancel on every stretch (the core of check 3, shared with [`pseudo`]).
fn check_sides_cancel<P: Coord>(
    polygon: &Polygon<P>,
    mut sides: Vec<[usize; 2]>,
    problems: &mut Problems,
) {
    // Cancel segments with the same two end vertices (most of them in a valid triangulation).
    let pair = |&[u, v]: &[usize; 2]| (u.min(v), u.max(v));
    sides.sort_unstable_by_key(pair);
    let mut events = Vec::new();
    for run in sides.chunk_by(|s, r| pair(s) == pair(r)) {
        let (lo, hi) = pair(&run[0]);
        let net: i64 = run.iter().map(|&[u, v]| if u < v { 1 } else { -1 }).sum();
        let (p, q) = (polygon.point(lo), polygon.point(hi));
        if net == 0 || p == q {
            continue;
        }
        // `net` times the segment p -> q; on its line, weight `w` from min to max.
        let (line, forward) = line_through(p, q);
        let w = if forward { net } else { -net };
        events.push(Event {
            line,
            at: p.min(q),
            delta: w,
        });
        events.push(Event {
            line,
            at: p.max(q),
            delta: -w,
        });
    }
    events.sort_unstable();
    // Sweep each line: the running weight must be zero between consecutive distinct points.
    for on_line in events.chunk_by(|e, f| e.line == f.line) {
        let mut sum = 0;
        let mut start = on_line[0].at;
        for at_point in on_line.chunk_by(|e, f| e.at == f.at) {
            let at = at_point[0].at;
            let new_sum = sum + at_point.iter().map(|e| e.delta).sum::<i64>();
            if new_sum != sum {
                if sum != 0 {
                    problems.add(|| uncancelled(polygon, start, at, sum));
                    let stretch = if sum > 0 { [start, at] } else { [at, start] };
                    problems
                        .faults
                        .stretches
                        .push(stretch.map(|p| polygon.drawing_point(p)));
                }
                sum = new_sum;
                start = at;
            }
        }
    }
}

/// Describes the stretch `from -> to` (in line order) whose chain weight is `w != 0`.
fn uncancelled<P: Coord>(polygon: &Polygon<P>, from: P, to: P, w: i64) -> String {
    let (from, to) = if w > 0 { (from, to) } else { (to, from) };
    let grid = polygon.grid();
    format!(
        "the boundaries do not cancel on the stretch {} -> {}: (triangles covering) - (polygon) \
         is {} higher on its left than on its right, so beside it there is a gap, an overlap, \
         or a triangle outside the polygon",
        grid.format_point(from),
        grid.format_point(to),
        w.unsigned_abs()
    )
}

/// A listed degenerate triangle to find on a triangle side: the segment `lo..=hi` on `line`.
struct Query<P: Coord> {
    line: P::Line,
    lo: P,
    hi: P,
    k: usize,
}

/// Check 6: the degenerate triangles.
fn check_degenerate<P: Coord>(polygon: &Polygon<P>, t: &Triangulation, problems: &mut Problems) {
    let mut queries = Vec::new();
    let mut middles = Vec::new();
    for (k, &deg) in t.degenerate.iter().enumerate() {
        if let Some(problem) = index_problem(polygon, "degenerate triangle", k, deg) {
            problems.add(|| problem);
            problems.faults.degenerate.push(k);
            continue;
        }
        let [a, b, c] = deg.map(|i| polygon.point(i));
        if !strictly_between(a, b, c) {
            problems.add(|| {
                let [ia, ib, ic] = deg.map(|i| polygon.id(i));
                format!(
                    "{}: vertex {ib} does not lie strictly between vertices {ia} and {ic}",
                    name(polygon, "degenerate triangle", k, deg)
                )
            });
            problems.faults.degenerate.push(k);
            continue;
        }
        let (line, _) = line_through(a, c);
        queries.push(Query {
            line,
            lo: a.min(c),
            hi: a.max(c),
            k,
        });
        let [ia, ib, ic] = deg;
        middles.push((ib, ia.min(ic), ia.max(ic), k));
    }
    // No two share a middle vertex (a vertex lies inside at most one triangle side).
    middles.sort_unstable();
    for pair in middles.windows(2) {
        let ((b, a, c, first), (b2, a2, c2, second)) = (pair[0], pair[1]);
        if b != b2 {
            continue;
        }
        problems.faults.degenerate.push(second);
        let this = name(polygon, "degenerate triangle", second, t.degenerate[second]);
        if (a, c) == (a2, c2) {
            problems.add(|| format!("{this} repeats degenerate triangle {first}"));
        } else {
            let id = polygon.id(b);
            problems.add(|| {
                format!(
                    "{this} has the same middle vertex {id} as degenerate triangle {first}, \
                     but a vertex lies inside at most one triangle side"
                )
            });
        }
    }
    if queries.is_empty() {
        return;
    }
    // The triangle sides on the lines of the queries, sorted by line and lower end.
    let mut lines: Vec<P::Line> = queries.iter().map(|q| q.line).collect();
    lines.sort_unstable();
    lines.dedup();
    let mut sides: Vec<(P::Line, P, P)> = Vec::new();
    for &tri in &t.triangles {
        if let Some([a, b, c]) = corners(polygon, tri) {
            for (p, q) in [(a, b), (b, c), (c, a)] {
                let (line, _) = line_through(p, q);
                if lines.binary_search(&line).is_ok() {
                    sides.push((line, p.min(q), p.max(q)));
                }
            }
        }
    }
    sides.sort_unstable();
    // reach[i]: the farthest upper end among sides[..=i] on the line of sides[i].
    let mut reach = Vec::with_capacity(sides.len());
    for (i, side) in sides.iter().enumerate() {
        let before = (i > 0 && sides[i - 1].0 == side.0).then(|| reach[i - 1]);
        reach.push(before.map_or(side.2, |r: P| r.max(side.2)));
    }
    for query in &queries {
        // The last side on the query's line whose lower end is at or before the query's.
        let end = sides.partition_point(|s| (s.0, s.1) <= (query.line, query.lo));
        let covered = end > 0 && sides[end - 1].0 == query.line && reach[end - 1] >= query.hi;
        if !covered {
            problems.faults.degenerate.push(query.k);
            let deg = t.degenerate[query.k];
            problems.add(|| {
                let [ia, ib, ic] = deg.map(|i| polygon.id(i));
                format!(
                    "{}: no triangle side contains the segment from vertex {ia} {} to vertex {ic} \
                     {}, so vertex {ib} is not a T-junction there",
                    name(polygon, "degenerate triangle", query.k, deg),
                    polygon.format_vertex(deg[0]),
                    polygon.format_vertex(deg[2]),
                )
            });
        }
    }
}

pub mod bounds;
pub mod pseudo;
#[cfg(test)]
mod tests;
