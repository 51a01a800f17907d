//! `--algorithm pseudo-hull`: a MINIMUM pseudotriangulation of the convex hull of the polygon's
//! vertices that contains the polygon's edges (outer ring and holes) as the given segment set L,
//! by the construction in the proof of Theorem 6 of Rote, Wang, Wang & Xu, "On constrained
//! minimum pseudotriangulations", COCOON 2003, LNCS 2697, pp. 445-454,
//! doi:10.1007/3-540-45071-8_45, Section 6.
//!
//! The region is the whole convex hull: the polygon's interior, the interiors of its holes and
//! the pockets between the outer ring and the hull are all cut into pseudotriangles (Section 1: a
//! pseudotriangulation of a point set partitions the interior of its convex hull).
//!
//! # The construction (proof of Theorem 6)
//!
//! 1. Add the hull edges to L (the hull's boundary with every vertex on it, so a vertex inside a
//!    hull side splits it). The faces are the polygon's interior (its outer boundary B the outer
//!    ring, the holes its inner components), each hole's interior, and each pocket.
//! 2. Face by face: take three consecutive corners x1, x2, x3 of the face F on its outer boundary
//!    B (a corner: a visit of B at a vertex where F's angle is below pi; B may visit a vertex
//!    more than once). A1 is the walk along B from x1 through x2 to x3. Find the shortest path S
//!    from x1 to x3 in F homotopic to A1 (the string along A1 pulled taut, B and the inner
//!    components being obstacles), add its edges: the region R between A1 and S is a
//!    pseudotriangle with no vertex inside (pieces (a)-(e) of the proof), reported as a face.
//!    Repeat on what is left of F (one or more faces: S may touch B elsewhere, or swallow inner
//!    components into the new outer boundary), until S runs along edges only: F itself was the
//!    last pseudotriangle.
//!
//! How S is found: the hull is triangulated once (the polygon with its holes by
//! `algo::plain::polygon`, or the pipeline's, made beside the validation sweep or for
//! `pseudo`'s start; each hole and pocket by `algo::plain`; O(n log n)),
//! with the edges of L and of the hull marked fixed (`algo/mesh.rs`), and its triangles
//! fattened by Lawson flips (a heuristic for speed only: fat triangles make short sleeves). Walking along A1 just
//! inside F crosses, at each inner vertex of A1, the diagonals inside F's angle there,
//! clockwise; with immediate back-and-forth crossings of one diagonal cancelled, this is the
//! sleeve of Hershberger & Snoeyink, in which the funnel algorithm (`pseudo_hull/funnel.rs`)
//! gives S, a taut string in the universal cover of F (so a triangle met twice, after going round an obstacle,
//! is two triangles there). S's new edges are then made edges of the triangulation by flipping
//! the diagonals they cross (`algo/mesh.rs`; removing the crossed triangles and filling the
//! two sides would not do: with holes, a side can surround a hole and touch itself at a vertex)
//! and fixed, R's boundary is walked and marked finished, and each new edge of S, with the rest
//! of F on its left, becomes a place to continue from. A step starts at such an edge, walks
//! forward along B to the next corner (x2) and from there to x1 and x3.
//!
//! Why the count is minimum: with N the number of angles of at least pi between neighbouring
//! fixed edges (the outer angles at hull vertices included), Euler's formula and three corners
//! per face give `2n - N - 2` faces and `3n - N - 3` edges for every pseudotriangulation; adding
//! an edge never increases N, so none containing L has fewer faces than `2n - N0 - 2` (N0: N
//! after step 1). Each step keeps N: S passes only through vertices where it bends round an
//! obstacle or goes straight on, and there the angle of at least pi moves whole into R (on the
//! obstacle side S leaves angles below pi) or stays whole in the rest of F, at x1' where S leaves
//! A1; x1, x2, x3 are corners before and after. In general position (Section 2) every vertex has
//! one angle of at least pi, so N0 = r = n and the count is Corollary 1's `2n - r - 2 = n - 2`.
//!
//! # Collinear input
//!
//! The paper assumes general position. Here collinear points are allowed: a flat vertex keeps
//! both its angles of pi (N0 counts both), the hull keeps the points inside its sides, and no
//! edge passes through a vertex: where the taut string goes straight through a vertex (angle
//! exactly pi), the funnel lists that vertex and the edge is split there. Such a vertex gets an
//! angle of exactly pi in R (no corner) and keeps its one angle of at least pi, so the argument
//! above holds unchanged: the answer has `2n - N0 - 2` faces, the least possible. What is proved
//! and what is checked: the argument above (the paper's, with pi allowed) shows every step cuts
//! off one pseudotriangle and keeps N; the code does not trust it: each R is checked to be a
//! cycle of distinct vertices with exactly three corners, every inserted segment to cross only
//! diagonals and to contain no vertex, and the final counts of faces and edges against
//! `2n - N0 - 2` and `3n - N0 - 3`. Should any check fail (never seen in the tests, general
//! position or not), the polygon gets [`TriangulateError::PseudoHullIncomplete`], never a wrong
//! answer. The independent checker [`crate::verify::pseudo`] (`--verify`) checks the result
//! again from scratch.
//!
//! # Complexity
//!
//! O(n log n) for the hull and the first triangulation, O(n) expected flips to fatten it. A step
//! costs the triangles of F met at the vertices of A1 (walk and sleeve, O(n) at worst), O(1) per
//! diagonal in the funnel, and for each new edge of S the flips that insert it (O(k) for k
//! crossed diagonals when each flip can leave one crossing fewer, almost always; O(k^2) at
//! worst, Sloan's bound). There are at most 2n steps, so
//! the bounds multiply to O(n^3) in the worst case (flips) and O(n^2) without the flips; neither
//! is approached on typical polygons, where chains between corners are short and a step
//! touches a few dozen triangles: on random stars and mazes the time per vertex grows only
//! slowly from 10^3 to 10^5 vertices (`docs/benchmarks.md`).
//! Half-edges are found by their ends in a hash map (expected O(1)); only the start of an
//! inserted segment is searched by turning round its first vertex, O(degree). Inputs that do
//! more work: high degrees and long chains kept on B, as a square round a big convex hole
//! (figures in docs/benchmarks.md). O(n) memory; no size limit.

mod funnel;

use super::mesh::{Broken, Constrained};
use super::TriangulateError;
use super::{plain, HullCounts, Pseudotriangle, Pseudotriangulation};
use crate::geom::kernel::Coord;
use crate::geom::kernel::{cmp_angle, cross};
use crate::geom::polygon::Polygon;
use std::collections::HashSet;
use std::time::Instant;

/// A minimum pseudotriangulation of the convex hull of `polygon`'s vertices containing its
/// edges, by the construction of Theorem 6 (see the module docs).
///
/// # Errors
/// [`TriangulateError::PseudoHullIncomplete`] if one of the construction's self-checks fails
/// (see the module docs; not seen in the tests).
///
/// # Examples
/// ```
/// use minitri::{algo::pseudo_hull, Decimal, Polygon, RawPolygon};
/// let ring: Result<Vec<[Decimal; 2]>, minitri::NumberError> = [(0, 0), (4, 0), (2, 1), (2, 4)]
///     .iter()
///     .map(|&(x, y)| Ok([Decimal::parse(&x.to_string())?, Decimal::parse(&y.to_string())?]))
///     .collect();
/// let (polygon, _warnings) = Polygon::from_raw(&RawPolygon { rings: vec![ring?], ..Default::default() })?;
/// let p = pseudo_hull::pseudotriangulate(&polygon)?;
/// assert_eq!(p.faces.len(), 2); // n - 2: the polygon and the pocket under vertex (2, 1)
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
pub fn pseudotriangulate<P: Coord>(
    polygon: &Polygon<P>,
) -> Result<Pseudotriangulation, TriangulateError> {
    pseudotriangulate_within(polygon, None)
}

/// [`pseudotriangulate`] that ends soon after `deadline` (`None`: no limit). Should the
/// construction still be running then, the result is the greedy of [`super::pseudo`] (Rote et
/// al., Section 5, linear) on the same triangulation of the hull, its polygon edges kept: a
/// MINIMAL pseudotriangulation of the hull containing the polygon's edges, valid but not proved
/// minimum, marked `stopped: Some(Stopped::TimeLimit)` (so not optimal) unless it has the
/// `2n - N - 2` faces of every minimum one (then it is one, and `stopped` stays `None`). The clock is read
/// between steps and every `super::mesh` 1024 flips, so the run ends within one step's walk
/// (O(n)) and the greedy's O(n) after the deadline.
///
/// # Errors
/// As [`pseudotriangulate`].
pub fn pseudotriangulate_within<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<Instant>,
) -> Result<Pseudotriangulation, TriangulateError> {
    pseudotriangulate_premade(polygon, None, deadline)
}

/// [`pseudotriangulate_within`], the polygon's own part of the hull triangulated by `premade`'s
/// triangles when the caller made them already ([`plain::Premade`]).
///
/// # Errors
/// As [`pseudotriangulate`].
pub(crate) fn pseudotriangulate_premade<P: Coord>(
    polygon: &Polygon<P>,
    premade: plain::Premade,
    deadline: Option<Instant>,
) -> Result<Pseudotriangulation, TriangulateError> {
    if polygon.touches() > 0 {
        return Err(TriangulateError::Touching {
            algorithm: super::Algorithm::PseudoHull,
            detail: "its hull triangulation takes each point once, and touching rings share points"
                .to_string(),
        });
    }
    let n = polygon.len();
    let points = polygon.points();
    let hull = hull_cycle(points);
    let counts = hull_counts(polygon, &hull);
    let target_faces = (2 * n).saturating_sub(counts.big_angles + 2);
    let target_edges = (3 * n).saturating_sub(counts.big_angles + 3);
    let (triangles, fixed, work) = hull_triangles(polygon, &hull, premade);
    // Kept for the greedy should the deadline pass (a copy only when there is one).
    let fallback = deadline.map(|_| triangles.clone());
    let (mesh, faces, expired) = construct(polygon, &triangles, &fixed, work, deadline);
    if let (true, Some(triangles)) = (expired, fallback) {
        let mut p = super::pseudo::minimal(polygon, &triangles);
        // Polygon edges inside the hull have a face on both sides; the hull's edges one.
        let sides: usize = p.faces.iter().map(|f| f.cycle.len()).sum();
        p.edge_count = (sides + hull.len()) / 2;
        p.hull = Some(counts);
        // As many faces as every minimum one has (Theorem 6): minimum after all.
        p.stopped = (p.faces.len() != target_faces).then_some(super::Stopped::TimeLimit);
        return Ok(p);
    }
    let (edges, cycles) = match (mesh, faces) {
        (Some(edges), Ok(cycles)) => (edges, cycles),
        (edges, _) => (edges.unwrap_or(0), Vec::new()),
    };
    if cycles.len() != target_faces || edges != target_edges {
        return Err(TriangulateError::PseudoHullIncomplete {
            edges,
            target: target_edges,
        });
    }
    Ok(Pseudotriangulation {
        faces: cycles
            .into_iter()
            .map(|c| Pseudotriangle::from_cycle(points, c))
            .collect(),
        edge_count: edges,
        hull: Some(counts),
        stopped: None,
    })
}

/// Steps 1 and 2: the fixed edge count reached (none if the start failed), the faces, or
/// [`Broken`] if a self-check failed, and whether `deadline` passed first (the faces then
/// incomplete).
fn construct<P: Coord>(
    polygon: &Polygon<P>,
    triangles: &[[usize; 3]],
    fixed: &[(usize, usize)],
    mut work: Vec<(usize, usize)>,
    deadline: Option<Instant>,
) -> (Option<usize>, Result<Vec<Vec<usize>>, Broken>, bool) {
    let n = polygon.len();
    let (mut mesh, guard) = setup(polygon, triangles, fixed, deadline);
    let mut faces = Vec::new();
    let mut steps = 0;
    while let Some((u, v)) = work.pop() {
        if mesh.past_deadline(0) {
            break;
        }
        let result = mesh
            .half_from(u, v)
            .filter(|&h| mesh.is_fixed(h))
            .ok_or(Broken)
            .and_then(|h| {
                if mesh.is_done(h) {
                    return Ok(());
                }
                steps += 1;
                if steps > 2 * n + 2 {
                    return Err(Broken);
                }
                step(&mut mesh, h, guard, &mut faces, &mut work)
            });
        if let Err(e) = result {
            return (Some(mesh.fixed_edges), Err(e), mesh.expired);
        }
    }
    (Some(mesh.fixed_edges), Ok(faces), mesh.expired)
}

/// Step 1, the triangles: the hull triangulated (the polygon, each hole's interior, each
/// pocket), the edges to fix (L and the hull's), and a half-edge `(u, v)` of the outer boundary
/// of each face (the face on its left).
#[allow(clippy::type_complexity)]
fn hull_triangles<P: Coord>(
    polygon: &Polygon<P>,
    hull: &[usize],
    premade: plain::Premade,
) -> (Vec<[usize; 3]>, Vec<(usize, usize)>, Vec<(usize, usize)>) {
    let n = polygon.len();
    let points = polygon.points();
    let mut triangles = plain::polygon(polygon, premade);
    let mut fixed: Vec<(usize, usize)> = (0..n).map(|i| (i, polygon.next(i))).collect();
    // Where to start: a half-edge of each first face's outer boundary, the face on its left.
    let mut work: Vec<(usize, usize)> = vec![(0, polygon.next(0))];
    let add_cycle = |cycle: &[usize], triangles: &mut Vec<[usize; 3]>| {
        let pts: Vec<P> = cycle.iter().map(|&v| points[v]).collect();
        triangles.extend(
            plain::rings(&pts, &[0])
                .into_iter()
                .map(|t| t.map(|i| cycle[i])),
        );
    };
    for r in 1..polygon.ring_starts().len() {
        let mut hole: Vec<usize> = polygon.ring_range(r).collect();
        hole.reverse();
        add_cycle(&hole, &mut triangles);
        work.push((hole[0], hole[1]));
    }
    for (k, &a) in hull.iter().enumerate() {
        let b = hull[(k + 1) % hull.len()];
        fixed.push((a, b));
        if polygon.next(a) != b {
            // The pocket: the hull edge a -> b, then the ring back from b to a.
            let mut pocket = vec![a, b];
            let mut v = polygon.prev(b);
            while v != a {
                pocket.push(v);
                v = polygon.prev(v);
            }
            add_cycle(&pocket, &mut triangles);
            work.push((a, b));
        }
    }
    (triangles, fixed, work)
}

/// Step 1, the mesh: `triangles` with `fixed` fixed, fattened, and a bound on any walk.
fn setup<'a, P: Coord>(
    polygon: &'a Polygon<P>,
    triangles: &[[usize; 3]],
    fixed: &[(usize, usize)],
    deadline: Option<Instant>,
) -> (Constrained<'a, P>, usize) {
    let mut mesh = Constrained::new(polygon.points(), triangles, fixed);
    mesh.deadline = deadline;
    mesh.fatten(10 * triangles.len());
    #[cfg(test)]
    mesh.consistent().expect("initial mesh");
    let guard = 8 * triangles.len() + 16;
    (mesh, guard)
}

/// Whether the boundary turns at a corner (an angle below pi in the face on the left) between
/// `into` and `out`, two consecutive fixed half-edges of a face boundary.
fn corner<P: Coord>(mesh: &Constrained<P>, into: usize, out: usize) -> bool {
    let p = |v: usize| mesh.point(v);
    cross(p(mesh.tail(out)), p(mesh.head(out)), p(mesh.tail(into))) > 0
}

/// One step of Theorem 6's proof on the face on the left of the fixed half-edge `h` (an edge of
/// its outer boundary B): corners x1, x2, x3, the taut string S, R cut off and reported.
fn step<P: Coord>(
    mesh: &mut Constrained<P>,
    h: usize,
    guard: usize,
    faces: &mut Vec<Vec<usize>>,
    work: &mut Vec<(usize, usize)>,
) -> Result<(), Broken> {
    let next = |mesh: &Constrained<P>, g: usize| mesh.next_boundary(g, |_, _| {});
    // x2: the first corner from h on.
    let mut into = h;
    let mut out = next(mesh, into);
    let mut count = 0;
    while !corner(mesh, into, out) {
        (into, out) = (out, next(mesh, out));
        count += 1;
        if count > guard {
            return Err(Broken);
        }
    }
    // A1 runs from the origin of `first` (x1) to the head of `last` (x3).
    let mut first = into;
    loop {
        let before = mesh.prev_boundary(first);
        if corner(mesh, before, first) {
            break;
        }
        first = before;
        count += 1;
        if count > guard {
            return Err(Broken);
        }
    }
    let mut last = out;
    loop {
        let after = next(mesh, last);
        if corner(mesh, last, after) {
            break;
        }
        last = after;
        count += 1;
        if count > guard {
            return Err(Broken);
        }
    }
    // The sleeve: the diagonals crossed just inside F along A1, back-and-forth pairs cancelled.
    let mut portals: Vec<(usize, usize)> = Vec::new();
    let mut g = first;
    while g != last {
        g = mesh.next_boundary(g, |right, left| {
            if portals
                .last()
                .is_some_and(|&(l, r)| (l, r) == (right, left) || (l, r) == (left, right))
            {
                portals.pop();
            } else {
                portals.push((left, right));
            }
        });
        count += 1;
        if count > guard {
            return Err(Broken);
        }
    }
    let (x1, x3) = (mesh.tail(first), mesh.head(last));
    let path = funnel::shortest_path(mesh.points(), x1, &portals, x3)?;
    let new_edges: Vec<(usize, usize)> = path
        .windows(2)
        .map(|w| (w[0], w[1]))
        .filter(|&(a, b)| !mesh.is_fixed_edge(a, b))
        .collect();
    if new_edges.is_empty() {
        // S runs along B: F itself is the last pseudotriangle.
        faces.push(finish(mesh, first, guard)?);
        return Ok(());
    }
    for &(a, b) in &new_edges {
        mesh.insert(a, b)?;
        #[cfg(test)]
        mesh.consistent().expect("consistent");
    }
    for &(a, b) in &new_edges {
        let r = mesh.half_from(b, a).ok_or(Broken)?;
        if !mesh.is_done(r) {
            faces.push(finish(mesh, r, guard)?);
        }
        work.push((a, b));
    }
    Ok(())
}

/// Walks the face on the left of `h`, marks it finished and returns its cycle, checked to be a
/// pseudotriangle: distinct vertices, exactly three corners.
fn finish<P: Coord>(
    mesh: &mut Constrained<P>,
    h: usize,
    guard: usize,
) -> Result<Vec<usize>, Broken> {
    let mut cycle = Vec::new();
    let mut corners = 0;
    let mut g = h;
    loop {
        mesh.set_done(g);
        cycle.push(mesh.tail(g));
        let after = mesh.next_boundary(g, |_, _| {});
        corners += usize::from(corner(mesh, g, after));
        g = after;
        if g == h {
            break;
        }
        if cycle.len() > guard {
            return Err(Broken);
        }
    }
    let distinct: HashSet<usize> = cycle.iter().copied().collect();
    if corners != 3 || distinct.len() != cycle.len() {
        return Err(Broken);
    }
    Ok(cycle)
}

/// The counts of Corollary 1: r and N over the segments of L and the hull edges.
fn hull_counts<P: Coord>(polygon: &Polygon<P>, hull: &[usize]) -> HullCounts {
    let n = polygon.len();
    let points = polygon.points();
    let mut around: Vec<Vec<usize>> = (0..n)
        .map(|v| vec![polygon.prev(v), polygon.next(v)])
        .collect();
    for (k, &a) in hull.iter().enumerate() {
        let b = hull[(k + 1) % hull.len()];
        around[a].push(b);
        around[b].push(a);
    }
    let mut counts = HullCounts {
        reflex_vertices: 0,
        big_angles: 0,
    };
    for (v, list) in around.iter_mut().enumerate() {
        let c = points[v];
        list.sort_unstable();
        list.dedup();
        list.sort_by(|&a, &b| cmp_angle(c, points[a], points[b]));
        let d = list.len();
        let big = (0..d)
            .filter(|&k| cross(c, points[list[k]], points[list[(k + 1) % d]]) <= 0)
            .count();
        counts.big_angles += big;
        counts.reflex_vertices += usize::from(big > 0);
    }
    counts
}

/// The convex hull's boundary, counter-clockwise, with every point on it (collinear ones too):
/// Andrew's monotone chain, popping only strict right turns.
fn hull_cycle<P: Coord>(points: &[P]) -> Vec<usize> {
    let mut order: Vec<usize> = (0..points.len()).collect();
    order.sort_unstable_by_key(|&i| points[i]);
    let chain = |order: &mut dyn Iterator<Item = usize>| {
        let mut h: Vec<usize> = Vec::new();
        for i in order {
            while h.len() >= 2
                && cross(points[h[h.len() - 2]], points[h[h.len() - 1]], points[i]) < 0
            {
                h.pop();
            }
            h.push(i);
        }
        h.pop();
        h
    };
    let mut lower = chain(&mut order.iter().copied());
    let upper = chain(&mut order.iter().rev().copied());
    lower.extend(upper);
    lower
}

#[cfg(test)]
mod tests;
