//! Rings that touch: the contacts OGC allows, checked, and the rings re-linked into boundary walks.
//!
//! Input contract: a [`Polygon`] as built by `Polygon::build` (rings, not yet validated) and the
//! [`Contacts`] [`crate::geom::validate::touching`] found: every pair of rings meets at most at
//! single points that are vertices of one of them, no ring meets itself, nothing crosses away
//! from those points. Output guarantee: [`walks`] accepts exactly the OGC-valid polygons (the
//! OGC Simple Features rules for a polygon's rings: they may touch at single points, the
//! interior must stay connected) and returns the polygon as *boundary walks*: one closed walk per
//! group of rings joined by touches, interior on the left, each touch point stored once per
//! interior sector around it (those copies share coordinates and the touching vertex's input
//! number). Otherwise an [`InvalidPolygon`] naming rings, vertices and points.
//!
//! Method (see `docs/touching.md` for the proofs):
//! 1. A vertex of one ring strictly inside an edge of another is inserted into that edge (the
//!    same point and input number: no new points, no new numbers). Now rings touch only at
//!    common vertices; the vertices at one point come from different rings.
//! 2. At each touch point, each ring's two edge directions bound the wedge outside the region
//!    (counter-clockwise from the direction to its previous vertex to that to its next one).
//!    Sorted by angle, the directions must come in pairs (previous, next) of one ring each: a
//!    repeated direction is a shared stretch of edge; a direction inside another ring's wedge
//!    means the rings cross there or lie inside one another.
//! 3. The graph with a node per ring and per touch point, an edge per ring through a point, must
//!    be a forest: a cycle of touches encloses a piece of the interior, cut off from the rest.
//! 4. Rings joined by touches are where they belong when one free vertex (on no other ring) of
//!    the group lies inside the outer ring and outside every other hole (exact crossing count);
//!    the other rings were placed by the validation sweep.
//! 5. Around each touch point, the walk arriving along a ring's edge leaves along the edge that
//!    follows clockwise: the next ring's outgoing edge. Following these links gives the walks.
//!
//! Complexity: O(n log n) for steps 1, 2, 3 and 5; step 4 tests one point per group of touching
//! rings against the rings whose height range holds it and the outer ring's edges whose height
//! range holds it, found by stabbing queries ([`super::stabbing`]): O(n log n) plus the rings
//! and edges found (docs/benchmarks.md has what this saved on a raster layer's polygon).

use super::kernel::{cmp_angle, cross, Coord};
use super::polygon::{Polygon, Ring};
use super::stabbing::{ByY, Stabbing};
use super::validate::{self, Contacts, InvalidPolygon};
use std::cmp::Ordering;

/// The polygon of `rings` (validated but for touches, `contacts` found) as boundary walks.
///
/// # Errors
/// Every problem at a touch point, or the first cycle of touches, or misplaced rings.
pub(crate) fn walks<P: Coord>(
    rings: Polygon<P>,
    contacts: &Contacts,
) -> Result<Polygon<P>, Vec<InvalidPolygon>> {
    let (p, inserted) = if contacts.on_edge.is_empty() {
        (rings, Vec::new()) // only shared vertices: nothing to insert, no copy of the rings
    } else {
        insert_on_edges(&rings, &contacts.on_edge)
    };
    let groups = touch_groups(&p);
    let name = |i: usize| match inserted.iter().find(|&&(v, _)| v == i) {
        Some(&(_, (a, b))) => format!("{} edge {a}-{b}", p.ring(i)),
        None => format!("{} vertex {}", p.ring(i), p.id(i)),
    };
    let mut errors = Vec::new();
    // Around each touch point: the vertex whose outgoing edge the walk takes after arriving at
    // each vertex of the group (`leave[i]`), found from the angular order.
    let mut leave: Vec<usize> = (0..p.len()).collect();
    let mut dirs = Vec::new(); // reused by every group
    for group in &groups {
        if let Err(e) = around(&p, group, &name, &mut dirs, &mut leave) {
            errors.push(e);
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    let rings_n = p.holes() + 1;
    let joined = forest(&p, &groups).map_err(|e| vec![e])?;
    let errors = placement(&p, &groups, &joined, &contacts.below);
    if !errors.is_empty() {
        return Err(errors);
    }
    // Step 5: the walks. The walk goes prev(i) -> i -> next(leave[i]); stored vertex i becomes
    // the copy of its point for the sector after the edge prev(i) -> i.
    let succ: Vec<usize> = (0..p.len()).map(|i| p.next(leave[i])).collect();
    let mut seen = vec![false; p.len()];
    let mut order = Vec::with_capacity(p.len());
    let mut starts = Vec::new();
    // The outer walk first: it holds the outer ring's edges (vertex 0's incoming edge).
    for start in 0..p.len() {
        if seen[start] {
            continue;
        }
        starts.push(order.len());
        let mut i = start;
        while !seen[i] {
            seen[i] = true;
            order.push(i);
            i = succ[i];
        }
    }
    let touches = rings_n - starts.len();
    let mut copy = vec![false; p.len()];
    for &i in groups.iter().flatten() {
        copy[i] = true;
    }
    Ok(p.relinked(&order, &starts, touches, &copy))
}

/// A stored vertex inserted into an edge, with the input numbers of the edge's ends.
type Inserted = (usize, (usize, usize));

/// Step 1: `polygon` with each `(edge, vertex)` of `on_edge` inserted, and the inserted stored
/// vertices with the input numbers of the edge they split.
fn insert_on_edges<P: Coord>(
    polygon: &Polygon<P>,
    on_edge: &[(usize, usize)],
) -> (Polygon<P>, Vec<Inserted>) {
    let mut at_edge: Vec<Vec<usize>> = vec![Vec::new(); polygon.len()];
    for &(e, v) in on_edge {
        at_edge[e].push(v);
    }
    let mut rings: Vec<Vec<(P, usize)>> = Vec::with_capacity(polygon.holes() + 1);
    let mut inserted_at = Vec::new();
    for r in 0..=polygon.holes() {
        let mut ring = Vec::new();
        for e in polygon.ring_range(r) {
            ring.push((polygon.point(e), polygon.id(e)));
            let a = polygon.point(e);
            let mut on = at_edge[e].clone();
            // Along the edge from `a`: by distance from `a` (all on the segment).
            on.sort_by(|&u, &v| P::cmp_dist(a, polygon.point(u), polygon.point(v)));
            for v in on {
                inserted_at.push((r, ring.len(), (polygon.id(e), polygon.id(polygon.next(e)))));
                ring.push((polygon.point(v), polygon.id(v)));
            }
        }
        rings.push(ring);
    }
    let p = polygon.with_rings(&rings);
    let inserted = inserted_at
        .into_iter()
        .map(|(r, k, edge)| (p.ring_range(r).start + k, edge))
        .collect();
    (p, inserted)
}

/// The stored vertices sharing a point with another, one group per point.
fn touch_groups<P: Coord>(p: &Polygon<P>) -> Vec<Vec<usize>> {
    // Sorted as (point, vertex) values, not vertex numbers looked up at each comparison: the
    // sort is most of this function's work on a polygon with many touches.
    let mut order: Vec<(P, usize)> = (0..p.len()).map(|i| (p.point(i), i)).collect();
    order.sort_unstable();
    order
        .chunk_by(|a, b| a.0 == b.0)
        .filter(|g| g.len() > 1)
        .map(|g| g.iter().map(|&(_, i)| i).collect())
        .collect()
}

/// Step 2 at one touch point: sets `leave[arriving vertex]` to the vertex whose outgoing edge
/// follows, for each vertex of the group, or says why the rings may not meet like this (`leave`
/// is then partly set). `dirs` is scratch space.
fn around<P: Coord>(
    p: &Polygon<P>,
    group: &[usize],
    name: &impl Fn(usize) -> String,
    dirs: &mut Vec<(P, usize, bool)>,
    leave: &mut [usize],
) -> Result<(), InvalidPolygon> {
    let at = p.point(group[0]);
    // (direction's far point, vertex, is it the outgoing edge)
    dirs.clear();
    dirs.extend(group.iter().flat_map(|&v| {
        [
            (p.point(p.prev(v)), v, false),
            (p.point(p.next(v)), v, true),
        ]
    }));
    dirs.sort_by(|x, y| cmp_angle(at, x.0, y.0).then(x.2.cmp(&y.2)));
    let k = dirs.len();
    for i in 0..k {
        let (x, y) = (dirs[i], dirs[(i + 1) % k]);
        if x.1 != y.1 && cmp_angle(at, x.0, y.0) == Ordering::Equal {
            return Err(InvalidPolygon::SharedStretch {
                a: name(x.1),
                b: name(y.1),
                at: p.format_vertex(x.1),
                towards: p.grid().format_point(x.0),
            });
        }
    }
    // Each incoming direction must be followed counter-clockwise by its own ring's outgoing one.
    // Start the circle at an incoming direction.
    let first_in = dirs.iter().position(|d| !d.2).unwrap_or(0);
    for step in 0..k / 2 {
        let i = first_in + 2 * step;
        let (x, y) = (dirs[i % k], dirs[(i + 1) % k]);
        let before = dirs[(i + k - 1) % k];
        if x.2 || !y.2 || x.1 != y.1 || !before.2 {
            let other = if x.1 != y.1 { y.1 } else { before.1 };
            return Err(InvalidPolygon::TouchCrossing {
                a: name(x.1),
                b: name(other),
                at: p.format_vertex(x.1),
            });
        }
        // Arriving along x's ring (edge prev -> point), the region is the sector clockwise of
        // the incoming direction: it is left by `before`'s outgoing edge.
        leave[x.1] = before.1;
    }
    Ok(())
}

/// Step 3: the rings joined by touches (`joined[r]`: the representative of ring r's group), or
/// the first cycle of touches, named.
fn forest<P: Coord>(p: &Polygon<P>, groups: &[Vec<usize>]) -> Result<Vec<usize>, InvalidPolygon> {
    let rings = p.holes() + 1;
    let mut root: Vec<usize> = (0..rings).collect();
    fn find(root: &mut [usize], mut r: usize) -> usize {
        while root[r] != r {
            root[r] = root[root[r]];
            r = root[r];
        }
        r
    }
    // The touches kept so far, `(ring, ring, vertex of the second at the point, vertex of the
    // first)`: only read to name a cycle, so kept flat (no list per ring on the valid path).
    let mut kept: Vec<(usize, usize, usize, usize)> = Vec::new();
    for group in groups {
        let first = p.ring_index(group[0]);
        for &v in &group[1..] {
            let r = p.ring_index(v);
            let (a, b) = (find(&mut root, first), find(&mut root, r));
            if a == b {
                let path = cycle(rings, &kept, first, r);
                let rings: Vec<String> = path
                    .iter()
                    .map(|&(r, _)| Ring::from_index(r).to_string())
                    .collect();
                let mut points: Vec<String> = path
                    .iter()
                    .skip(1)
                    .map(|&(_, v)| p.format_vertex(v))
                    .chain(std::iter::once(p.format_vertex(v)))
                    .collect();
                points.dedup();
                return Err(InvalidPolygon::CutInterior {
                    rings: rings.join(", "),
                    points: points.join(", "),
                });
            }
            root[a] = b;
            kept.push((first, r, v, group[0]));
        }
    }
    Ok((0..rings).map(|r| find(&mut root, r)).collect())
}

/// The rings (with a vertex at each touch point passed) on the path of `kept` touches (see
/// [`forest`]) from `from` to `to`: `(ring, vertex at the point reached by)`; the first entry is
/// `(from, _)`.
fn cycle(
    rings: usize,
    kept: &[(usize, usize, usize, usize)],
    from: usize,
    to: usize,
) -> Vec<(usize, usize)> {
    let mut adjacent: Vec<Vec<(usize, usize)>> = vec![Vec::new(); rings];
    for &(a, b, at_b, at_a) in kept {
        adjacent[a].push((b, at_b));
        adjacent[b].push((a, at_a));
    }
    let mut back: Vec<Option<(usize, usize)>> = vec![None; rings];
    let mut queue = std::collections::VecDeque::from([from]);
    back[from] = Some((from, usize::MAX));
    while let Some(r) = queue.pop_front() {
        if r == to {
            break;
        }
        for &(s, v) in &adjacent[r] {
            if back[s].is_none() {
                back[s] = Some((r, v));
                queue.push_back(s);
            }
        }
    }
    let mut path = Vec::new();
    let mut r = to;
    while r != from {
        let Some((prev, v)) = back[r] else { break };
        path.push((r, v));
        r = prev;
    }
    path.push((from, usize::MAX));
    path.reverse();
    path
}

/// Step 4: misplaced rings (holes outside, nested), judged for groups of touching rings by one
/// free vertex each, for the other rings by the sweep's view below their first vertex.
fn placement<P: Coord>(
    p: &Polygon<P>,
    groups: &[Vec<usize>],
    joined: &[usize],
    below: &[Option<(usize, bool)>],
) -> Vec<InvalidPolygon> {
    let rings = joined.len();
    let mut touching = vec![false; rings];
    let mut at_touch = vec![false; p.len()];
    for group in groups {
        for &v in group {
            touching[p.ring_index(v)] = true;
            at_touch[v] = true;
        }
    }
    let mut errors = Vec::new();
    let parents = validate::parents(below, &touching);
    // Each ring's bounding box: its vertices of least and greatest x, of least and greatest y.
    let boxes: Vec<[P; 4]> = (0..rings)
        .map(|r| {
            let first = p.point(p.ring_range(r).start);
            p.ring_range(r).fold([first; 4], |b, i| {
                let q = p.point(i);
                [
                    std::cmp::min_by(b[0], q, |&u, &v| P::cmp_x(u, v)),
                    std::cmp::max_by(b[1], q, |&u, &v| P::cmp_x(u, v)),
                    std::cmp::min_by(b[2], q, |&u, &v| P::cmp_y(u, v)),
                    std::cmp::max_by(b[3], q, |&u, &v| P::cmp_y(u, v)),
                ]
            })
        })
        .collect();
    // Which rings' height ranges and which outer edges' height ranges hold a point: the only
    // rings a point can be inside, the only outer edges a horizontal ray from it can cross.
    let by_height = Stabbing::new(
        (0..rings)
            .map(|r| (ByY(boxes[r][2]), ByY(boxes[r][3]), r))
            .collect(),
    );
    let outer_edges = Stabbing::new(
        p.ring_range(0)
            .map(|i| {
                let (a, b) = (p.point(i), p.point(p.next(i)));
                (ByY(a).min(ByY(b)), ByY(a).max(ByY(b)), i)
            })
            .collect(),
    );
    let mut done = vec![false; rings];
    let mut candidates = Vec::new();
    for r in 0..rings {
        let group = joined[r];
        if !touching[r] || done[group] {
            continue;
        }
        let Some(v) = p.ring_range(r).find(|&i| !at_touch[i]) else {
            continue; // another ring of the group has one (a leaf of the forest)
        };
        done[group] = true;
        let q = p.point(v);
        // The outer ring always (outside it is an error), then every ring whose height range
        // holds `q`, in ring order: no other ring can hold `q`.
        candidates.clear();
        candidates.push(0);
        by_height.each(ByY(q), |s| candidates.push(s));
        candidates[1..].sort_unstable();
        candidates.dedup();
        for &s in candidates.iter().filter(|&&s| joined[s] != group) {
            let b = boxes[s];
            let inside = P::cmp_x(b[0], q).is_le()
                && P::cmp_x(q, b[1]).is_le()
                && P::cmp_y(b[2], q).is_le()
                && P::cmp_y(q, b[3]).is_le()
                && if s == 0 {
                    crosses_odd(p, q, |count| outer_edges.each(ByY(q), count))
                } else {
                    crosses_odd(p, q, |count| p.ring_range(s).for_each(count))
                };
            match (s == 0, inside, r == 0) {
                (true, false, _) => errors.push(InvalidPolygon::HoleOutside { hole: r }),
                (false, true, true) => errors.push(InvalidPolygon::OuterInsideHole { hole: s }),
                (false, true, false) => errors.push(InvalidPolygon::HoleInsideHole {
                    hole: r,
                    container: s,
                }),
                _ => {}
            }
        }
    }
    for (r, &parent) in parents.iter().enumerate() {
        if touching[r] {
            continue;
        }
        match (r, parent) {
            (0, None) | (1.., Some(0)) => {}
            (0, Some(hole)) => errors.push(InvalidPolygon::OuterInsideHole { hole }),
            (_, Some(container)) => {
                errors.push(InvalidPolygon::HoleInsideHole { hole: r, container })
            }
            (_, None) => errors.push(InvalidPolygon::HoleOutside { hole: r }),
        }
    }
    errors
}

/// Whether `q` (on no edge of the ring) lies inside a ring, given (by `edges`, which calls its
/// argument with edge starts) at least every edge of the ring whose height range holds `q`: exact
/// crossing count of the ray to the right.
fn crosses_odd<P: Coord>(p: &Polygon<P>, q: P, edges: impl FnOnce(&mut dyn FnMut(usize))) -> bool {
    let mut inside = false;
    edges(&mut |i| {
        let (a, b) = (p.point(i), p.point(p.next(i)));
        if P::cmp_y(a, q).is_gt() != P::cmp_y(b, q).is_gt()
            && (cross(a, b, q) > 0) == P::cmp_y(b, a).is_gt()
        {
            inside = !inside;
        }
    });
    inside
}
