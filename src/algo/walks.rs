//! Triangulations of polygons whose rings touch: boundary walks that visit a point once per
//! interior sector around it (see `crate::geom::touch` and `docs/touching.md`).
//!
//! Input contract: a valid [`Polygon`] with `touches() > 0`: walks, outer one counter-clockwise,
//! hole walks clockwise, interior on the left of every edge; stored vertices at one point
//! ("copies") have pairwise interior-disjoint angles (sectors) separated by wedges of positive
//! angle outside the region; no two consecutive stored vertices share a point.
//! Output guarantee: [`flattened`] gives `n + 2w - 2 - d` nondegenerate counter-clockwise
//! triangles (n stored vertices, copies counted, w hole walks) and `d` degenerate ones
//! (T-junctions) covering the region, as stored indices, each corner the copy whose sector holds
//! the triangle there, never more than the plain triangulation of the walks
//! (`crate::algo::plain::walks`, `n + 2w - 2`); [`minimum`] the exact minimum of a
//! polygon whose rings all join the outer ring (one walk), by the DP of [`super::asano`] over the
//! walk (`asano`'s method; `minitri` runs Chen & Chang's steps on the walks instead). Every decision is an exact orientation test.
//!
//! Method. A segment between two stored vertices is a *chord* of the walk when it leaves each end
//! inside that copy's closed angle, crosses no edge properly, and passes each point it contains
//! inside the closed angle of one copy there (so it stays in the closed region: away from
//! vertices nothing but a proper crossing can take it out, at a vertex it stays in that copy's
//! sector). The plain triangulation of the walks is the monotone sweep on the walks with every
//! copy moved symbolically into its sector (`crate::algo::plain::walks`); the ear clipper of
//! the bridged cycle below (`clipped_bridged`) remains only as its fallback, never taken in
//! the tests.
//!
//! [`flattened`] joins each hole walk to the outer walk by a bridge (a chord from the hole's
//! highest point, as earcut does; the walk then passes both ends twice) and clips ears: an ear
//! `p v q` is a strict left turn at `v` whose closed triangle holds no other vertex except copies
//! of its corners, leaving `p` and `q` strictly inside their angles (a copy of a corner has its
//! own sector, disjoint from the triangle's). Both theorems behind it (a bridge exists from a
//! hole's highest point, a weakly simple polygon of more than 3 vertices has an ear) are those
//! of simple polygons applied to the polygon with each copy moved an infinitesimal step into its
//! sector, which is simple and has the same triangulations.
//!
//! [`flattened`] (the minimum algorithms beyond the walk DP) first drops every position lying
//! strictly between its two cycle neighbours (an angle of exactly pi; the test is exact), and again whenever clipping an ear makes a neighbour so, as
//! earcut's `filterPoints` does. Dropping a position keeps every other angle and the region; the
//! dropped vertex then lies strictly inside a side of the one triangle later built on that stretch
//! of the cycle, a T-junction, which saves one triangle (`docs/touching.md`, the claim
//! `T = N + 2(w - t) - 2 - d`). Another position at the same point (a touch point, a bridge
//! end) has its sector on the far side of that straight stretch (sectors at a point are disjoint,
//! and the dropped one is a half-plane), so in the polygon with copies moved into their sectors
//! it lies outside every triangle on the stretch: the ear test lets a vertex strictly inside the
//! ear's sides `p v` or `v q` pass (any other vertex point strictly inside a cycle edge is
//! excluded: walk edges and bridges hold none, and a clipped diagonal held no live vertex). It
//! clips in two orders and keeps the better: the plain one, and a greedy one that first takes
//! an ear whose clipping makes a neighbour flat (a round of O(1) tests), any ear only when there
//! is none. The degenerate triangles are read off the triangles (a scan of the dropped vertices
//! per side); if they do not number exactly the dropped positions, or no ear is found, it returns
//! `Err` and the caller takes the plain triangulation: never a wrong answer.
//!
//! Complexity: O(n^2) for [`flattened`] in practice (each ear test scans the remaining vertices; the greedy
//! order adds an O(n) round of O(1) tests per ear, the reading off O(T d)), O(n^3) worst case,
//! cut short by its deadline; it runs the plain order too only up to [`BOTH_ORDERS_UP_TO`]
//! positions. O(n^3) time and O(n^2) memory for [`minimum`] (chord table by the angular sweep
//! of [`super::chords`], O(n^2 log n)), up to the DP's size limit (`--dp-limit`, 3,000 by
//! default). Chen & Chang's steps run on walks too ([`super::minitri::triangulate_walks`]).

use super::asano::solve_walk;
use super::chords::ChordTable;
use super::{t_junctions, Junctions, Stopped};
use crate::geom::kernel::{cross, dot, in_closed_wedge, properly_cross, strictly_between, Coord};
use crate::geom::polygon::Polygon;
#[cfg(test)]
use std::collections::HashMap;
use std::time::Instant;

/// Triangles as stored vertex indices.
pub type Triangles = Vec<[usize; 3]>;

/// The largest bridged cycle (positions) [`flattened`] clips in both orders, keeping the better;
/// beyond, the greedy order only (each clipping costs O(n^2) in practice).
pub const BOTH_ORDERS_UP_TO: usize = 2000;

/// Whether `t` lies strictly inside the angle at `w` from `next` counter-clockwise to `prev`
/// (closed angle minus the direction of `prev`: the ear's side `p q` may not run back along the
/// edge into `p`).
fn strictly_inside<P: Coord>(prev: P, w: P, next: P, t: P) -> bool {
    in_closed_wedge(prev, w, next, t)
        && !(cross(w, prev, t) == 0 && dot(w, prev, t) > 0)
        && !(cross(w, next, t) == 0 && dot(w, next, t) > 0)
}

/// The ear clipper over the bridged cycle (see the module documentation): the fallback of the
/// walks' plain triangulation (`crate::algo::plain::walks`) when its sweep fails its check
/// (not seen in the tests).
///
/// # Errors
/// [`WalksError`] if no ear or bridge is found, which the theory excludes (a broken invariant,
/// reported rather than a wrong answer).
pub(crate) fn clipped_bridged<P: Coord>(polygon: &Polygon<P>) -> Result<Triangles, WalksError> {
    let cycle = bridged(polygon, None)?;
    clip(polygon, &cycle, false, false, None).map(|(triangles, _)| triangles)
}

/// A triangulation of a polygon with touching rings with degenerate triangles where the
/// bridged cycle runs straight through a vertex (see the module documentation): the
/// nondegenerate triangles and the degenerate ones, at most as many triangles as the plain
/// triangulation (`crate::algo::plain::walks`).
///
/// # Errors
/// [`WalksError::TimeLimit`] past `deadline`; as `clipped_bridged`; or when the degenerate
/// triangles read off the result do not account for the triangles saved (a broken invariant;
/// the caller falls back to the plain triangulation).
pub fn flattened<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<Instant>,
) -> Result<(Triangles, Triangles), WalksError> {
    let cycle = bridged(polygon, deadline)?;
    let greedy = flattened_clip(polygon, &cycle, true, deadline);
    if cycle.len() > BOTH_ORDERS_UP_TO {
        return greedy;
    }
    match (greedy, flattened_clip(polygon, &cycle, false, deadline)) {
        (Ok(g), Ok(o)) => Ok(if o.0.len() < g.0.len() { o } else { g }),
        (Ok(found), Err(_)) | (Err(_), Ok(found)) => Ok(found),
        (Err(why), Err(_)) => Err(why),
    }
}

/// [`clip`] with flat positions dropped, in the greedy order or the plain one, and the
/// degenerate triangles read off its triangles (one per dropped position, else `Err`).
fn flattened_clip<P: Coord>(
    polygon: &Polygon<P>,
    cycle: &[usize],
    greedy: bool,
    deadline: Option<Instant>,
) -> Result<(Triangles, Triangles), WalksError> {
    let (triangles, dropped) = clip(polygon, cycle, true, greedy, deadline)?;
    let mut candidates: Vec<usize> = dropped.iter().map(|&k| cycle[k]).collect();
    candidates.sort_unstable();
    candidates.dedup();
    let degenerate = t_junctions(polygon, &triangles, Junctions::Walks(&candidates));
    if degenerate.len() != dropped.len() || triangles.len() + dropped.len() + 2 != cycle.len() {
        return Err(WalksError::Unaccounted {
            found: degenerate.len(),
            dropped: dropped.len(),
        });
    }
    Ok((triangles, degenerate))
}

/// The outer walk with every hole walk joined to it by a bridge (see the module documentation),
/// as a cycle of stored vertices (a bridge's ends appear twice).
fn bridged<P: Coord>(
    polygon: &Polygon<P>,
    deadline: Option<Instant>,
) -> Result<Vec<usize>, WalksError> {
    let pt = |i: usize| polygon.point(i);
    let walks: Vec<Vec<usize>> = (0..=polygon.holes())
        .map(|w| polygon.ring_range(w).collect())
        .collect();
    let mut outer = walks[0].clone();
    let mut holes: Vec<Vec<usize>> = walks[1..].to_vec();
    // Highest (lexicographically greatest (x, y)) point first, as earcut joins holes.
    holes.sort_by_key(|h| std::cmp::Reverse(h.iter().map(|&i| pt(i)).max()));
    for k in 0..holes.len() {
        if super::past(deadline) {
            return Err(WalksError::TimeLimit);
        }
        let hole = &holes[k];
        let top = hole
            .iter()
            .map(|&i| pt(i))
            .max()
            .unwrap_or_else(|| pt(outer[0]));
        let mut candidates: Vec<usize> = (0..outer.len()).collect();
        candidates.sort_by(|&o, &q| P::cmp_dist(top, pt(outer[o]), pt(outer[q])));
        let m = hole.len();
        let rest: Vec<&Vec<usize>> = holes[k + 1..].iter().collect();
        let mut bridge = None;
        'search: for &o in &candidates {
            if super::past(deadline) {
                return Err(WalksError::TimeLimit);
            }
            let v = outer[o];
            for h in (0..m).filter(|&h| pt(hole[h]) == top) {
                let hv = (
                    pt(hole[(h + m - 1) % m]),
                    pt(hole[h]),
                    pt(hole[(h + 1) % m]),
                );
                let n = outer.len();
                let ov = (pt(outer[(o + n - 1) % n]), pt(v), pt(outer[(o + 1) % n]));
                if pt(v) != top
                    && strictly_inside(hv.0, hv.1, hv.2, pt(v))
                    && strictly_inside(ov.0, ov.1, ov.2, top)
                    && clear(
                        polygon,
                        top,
                        pt(v),
                        std::iter::once(&outer)
                            .chain(std::iter::once(hole))
                            .chain(rest.iter().copied()),
                    )
                {
                    bridge = Some((o, h));
                    break 'search;
                }
            }
        }
        let Some((o, h)) = bridge else {
            return Err(WalksError::NoBridge(k + 1));
        };
        let mut joined = Vec::with_capacity(outer.len() + m + 2);
        joined.extend_from_slice(&outer[..=o]);
        joined.extend((0..=m).map(|s| hole[(h + s) % m]));
        joined.extend_from_slice(&outer[o..]);
        outer = joined;
    }
    Ok(outer)
}

/// Why a triangulation of the walks was not made. Only [`WalksError::TimeLimit`] is expected;
/// the others are broken invariants the theory excludes, reported rather than a wrong answer
/// (none seen in the tests).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum WalksError {
    /// The deadline passed first.
    #[error("the time limit passed")]
    TimeLimit,
    /// No bridge joins this hole walk (numbered from 1) to the walks before it.
    #[error("no bridge from hole walk {0} found")]
    NoBridge(usize),
    /// The ear clipper found no ear among this many vertices.
    #[error("no ear among {0} vertices")]
    NoEar(usize),
    /// The ear clipper's last three vertices were not a triangle.
    #[error("the last three vertices do not make a triangle")]
    LastNotATriangle,
    /// The degenerate triangles read off a flattened triangulation did not account for the
    /// vertices passed straight through.
    #[error(
        "{found} degenerate triangles read off for {dropped} vertices passed straight through"
    )]
    Unaccounted {
        /// Degenerate triangles found.
        found: usize,
        /// Vertices passed straight through.
        dropped: usize,
    },
}

/// Whether the open segment `a b` contains no vertex of `cycles` and crosses none of their
/// edges properly.
fn clear<'a, P: Coord>(
    polygon: &Polygon<P>,
    a: P,
    b: P,
    cycles: impl Iterator<Item = &'a Vec<usize>>,
) -> bool {
    cycles.into_iter().all(|c| {
        (0..c.len()).all(|s| {
            let (u, w) = (polygon.point(c[s]), polygon.point(c[(s + 1) % c.len()]));
            !strictly_between(a, u, b) && !properly_cross(a, b, u, w)
        })
    })
}

/// Ear clipping of one weakly simple cycle of stored vertices (see the module documentation):
/// the triangles and, with `flatten`, the number of positions passed straight through.
///
/// With `flatten`, every position strictly between its two cycle neighbours is dropped from the
/// cycle, first and whenever clipping an ear makes one so; a vertex of the cycle lying strictly
/// inside a side `p v` or `v q` of an ear then does not block it (see the module documentation).
fn clip<P: Coord>(
    polygon: &Polygon<P>,
    cycle: &[usize],
    flatten: bool,
    greedy: bool,
    deadline: Option<Instant>,
) -> Result<(Triangles, Vec<usize>), WalksError> {
    let n = cycle.len();
    let pt = |k: usize| polygon.point(cycle[k]);
    let mut next: Vec<usize> = (0..n).map(|k| (k + 1) % n).collect();
    let mut prev: Vec<usize> = (0..n).map(|k| (k + n - 1) % n).collect();
    let mut alive = vec![true; n];
    let mut triangles = Vec::with_capacity(n.saturating_sub(2));
    let mut remaining = n;
    let mut dropped = Vec::new();
    // Drops the flat positions of `stack` and, in turn, their neighbours that become flat.
    let mut flatten_from = |stack: &mut Vec<usize>,
                            next: &mut Vec<usize>,
                            prev: &mut Vec<usize>,
                            alive: &mut Vec<bool>,
                            remaining: &mut usize| {
        while let Some(k) = stack.pop() {
            if *remaining <= 3 || !alive[k] {
                continue;
            }
            let (p, q) = (prev[k], next[k]);
            if strictly_between(pt(p), pt(k), pt(q)) {
                next[p] = q;
                prev[q] = p;
                alive[k] = false;
                *remaining -= 1;
                dropped.push(k);
                stack.extend([p, q]);
            }
        }
    };
    if flatten {
        let mut stack: Vec<usize> = (0..n).rev().collect();
        flatten_from(&mut stack, &mut next, &mut prev, &mut alive, &mut remaining);
    }
    let mut v = (0..n).find(|&k| alive[k]).unwrap_or(0);
    let mut misses = 0;
    // With `greedy`: first look for an ear whose clipping makes a neighbour flat; after a round
    // without one, take the next ear of any kind.
    let mut only_flattening = greedy;
    let mut steps = 0u32;
    while remaining > 3 {
        steps = steps.wrapping_add(1);
        if steps.is_multiple_of(64) && super::past(deadline) {
            return Err(WalksError::TimeLimit);
        }
        let (p, q) = (prev[v], next[v]);
        let (a, b, c) = (pt(p), pt(v), pt(q));
        let ear = cross(a, b, c) > 0
            && (!only_flattening
                || strictly_between(pt(prev[p]), a, c)
                || strictly_between(a, c, pt(next[q])))
            && strictly_inside(pt(prev[p]), a, b, c)
            && strictly_inside(b, c, pt(next[q]), a)
            && (0..n).all(|r| {
                !alive[r] || r == p || r == v || r == q || {
                    let s = pt(r);
                    s == a
                        || s == b
                        || s == c
                        || !(cross(a, b, s) >= 0 && cross(b, c, s) >= 0 && cross(c, a, s) >= 0)
                        || (flatten && (strictly_between(a, s, b) || strictly_between(b, s, c)))
                }
            });
        if ear {
            triangles.push([cycle[p], cycle[v], cycle[q]]);
            next[p] = q;
            prev[q] = p;
            alive[v] = false;
            remaining -= 1;
            misses = 0;
            only_flattening = greedy;
            if flatten {
                let mut stack = vec![q, p];
                flatten_from(&mut stack, &mut next, &mut prev, &mut alive, &mut remaining);
            }
            v = if alive[p] { p } else { prev[p] };
            while !alive[v] {
                v = prev[v];
            }
        } else {
            misses += 1;
            if misses > remaining {
                if !only_flattening {
                    return Err(WalksError::NoEar(remaining));
                }
                only_flattening = false;
                misses = 0;
            }
            v = q;
        }
    }
    if remaining == 3 {
        let (p, q) = (prev[v], next[v]);
        if cross(pt(p), pt(v), pt(q)) > 0 {
            triangles.push([cycle[p], cycle[v], cycle[q]]);
        } else {
            return Err(WalksError::LastNotATriangle);
        }
    }
    Ok((triangles, dropped))
}

/// Whether the segment between stored vertices `i` and `j` is a chord of the walks (see the
/// module documentation; it may run along edges and pass vertices), straight from the
/// definition in O(n): the test oracle of the chord table's sweep on walks.
#[cfg(test)]
pub(crate) fn is_chord<P: Coord>(polygon: &Polygon<P>, i: usize, j: usize) -> bool {
    let (a, b) = (polygon.point(i), polygon.point(j));
    if a == b {
        return false;
    }
    let wedge = |v: usize, target: P| polygon.angle_holds(v, target);
    if !wedge(i, b) || !wedge(j, a) {
        return false;
    }
    let mut passed: HashMap<P, bool> = HashMap::new();
    for v in 0..polygon.len() {
        let (u, w) = (polygon.point(v), polygon.point(polygon.next(v)));
        if properly_cross(a, b, u, w) {
            return false;
        }
        if strictly_between(a, u, b) {
            let ok = wedge(v, a) && wedge(v, b);
            *passed.entry(u).or_insert(false) |= ok;
        }
    }
    passed.values().all(|&ok| ok)
}

/// The exact minimum triangulation of a polygon whose rings all join the outer ring (one walk)
/// of at most `limit` stored vertices: the nondegenerate triangles and the degenerate ones (as
/// [`super::Triangulation`] has them). `Err(Stopped::Touching)` with hole walks or beyond
/// `limit`, `Err(Stopped::TimeLimit)` when `deadline` passes first.
///
/// # Errors
/// As above; the caller then takes [`flattened`].
pub fn minimum<P: Coord>(
    polygon: &Polygon<P>,
    limit: usize,
    deadline: Option<Instant>,
) -> Result<(Triangles, Triangles), Stopped> {
    let n = polygon.len();
    if polygon.holes() > 0 || n > limit.min(65_000) {
        return Err(Stopped::Touching);
    }
    let chords = ChordTable::new(polygon);
    let walk = solve_walk(
        n,
        |i| polygon.point(i),
        |i, j| chords.is_chord(i, j),
        |i| chords.lines_through(i),
        deadline,
    );
    let Some(walk) = walk else {
        return Err(if super::past(deadline) {
            Stopped::TimeLimit
        } else {
            Stopped::Touching // not seen: a valid walk always has a triangulation
        });
    };
    let all: Vec<usize> = (0..n).collect();
    let degenerate = t_junctions(polygon, &walk.triangles, Junctions::Walks(&all));
    if degenerate.len() != walk.dummies {
        return Err(Stopped::Touching); // not seen; the caller falls back
    }
    Ok((walk.triangles, degenerate))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algo::plain::perturbed::{swept, tiles};
    use crate::test_support::{raw, xorshift};

    /// Random touching polygons on the grid 0..=8: a square with a few vertices added, and 1 to
    /// 4 small holes whose corners are often vertices of the rings so far (touches, several
    /// rings at one point, chains of holes, hole walks left). Only the valid ones with touches
    /// are kept.
    fn random_touching(rnd: &mut impl FnMut(i64) -> i64) -> Option<Polygon> {
        random_touching_sized(rnd, 8, 4)
    }

    fn valid(rings: &[Vec<(i64, i64)>]) -> Option<Polygon> {
        let rings: Vec<&[(i64, i64)]> = rings.iter().map(Vec::as_slice).collect();
        Polygon::from_raw(&raw(&rings)).ok().map(|(p, _)| p)
    }

    /// [`random_touching`] on the grid `0..=size` with up to `holes` holes.
    fn random_touching_sized(
        rnd: &mut impl FnMut(i64) -> i64,
        size: i64,
        holes: i64,
    ) -> Option<Polygon> {
        let mut outer = vec![(0, 0), (size, 0), (size, size), (0, size)];
        for _ in 0..rnd(size - 3) {
            let mut next = outer.clone();
            next.insert(
                rnd(outer.len() as i64) as usize + 1,
                (rnd(size + 1), rnd(size + 1)),
            );
            if Polygon::from_raw(&raw(&[&next])).is_ok() {
                outer = next;
            }
        }
        let mut rings = vec![outer];
        let tries = if holes > 4 { holes } else { 1 + rnd(holes) };
        for _ in 0..tries {
            let existing: Vec<(i64, i64)> = rings.iter().flatten().copied().collect();
            let anchor = if rnd(2) == 0 {
                (1 + rnd(size - 1), 1 + rnd(size - 1))
            } else {
                existing[rnd(existing.len() as i64) as usize]
            };
            let mut hole = vec![anchor];
            for _ in 0..2 + rnd(2) {
                let p = if rnd(5) == 0 {
                    existing[rnd(existing.len() as i64) as usize]
                } else {
                    (
                        (anchor.0 + rnd(5) - 2).clamp(0, size),
                        (anchor.1 + rnd(5) - 2).clamp(0, size),
                    )
                };
                if !hole.contains(&p) {
                    hole.push(p);
                }
            }
            rings.push(hole);
            // Large ones keep a hole only if the polygon stays valid (one bad hole of many
            // would make almost every try invalid).
            if holes > 4 && valid(&rings).is_none() {
                rings.pop();
            }
        }
        let p = valid(&rings)?;
        (p.touches() > 0).then_some(p)
    }

    /// The sweep over moved copies ([`swept`]) never falls back to the ear clipper: on random
    /// touching polygons, small and large (one walk and hole walks, many rings at a point), its
    /// triangles pass the independent checker and number `N + 2w - 2`.
    #[test]
    fn the_sweep_over_moved_copies_triangulates_every_touching_polygon() {
        let mut rnd = xorshift(0x5eed_7a11);
        let (mut checked, mut holes, mut large) = (0, 0, 0);
        while checked < 4000 {
            let p = if checked % 4 == 3 {
                random_touching_sized(&mut rnd, 30, 150)
            } else {
                random_touching(&mut rnd)
            };
            let Some(p) = p else {
                continue;
            };
            checked += 1;
            holes += usize::from(p.holes() > 0);
            large += usize::from(p.len() >= 48);
            let triangles = swept(&p).unwrap_or_else(|| panic!("{:?}", p.points()));
            let problems = crate::test_support::plain_problems(&p, triangles);
            assert!(problems.is_empty(), "{problems:?} {:?}", p.points());
        }
        assert!(holes > 500 && large > 500, "{holes} {large}");
    }

    /// [`tiles`] refuses what is not a triangulation of the walks: a triangle dropped, one
    /// doubled, one turned, and a walk edge used from outside.
    #[test]
    fn the_tiling_check_refuses_broken_triangulations() {
        let mut rnd = xorshift(0x7113_0001);
        let mut checked = 0;
        while checked < 300 {
            let Some(p) = random_touching(&mut rnd) else {
                continue;
            };
            checked += 1;
            let good = swept(&p).expect("sweep");
            assert!(tiles(&p, &good));
            let mut dropped = good.clone();
            dropped.pop();
            assert!(!tiles(&p, &dropped));
            let mut doubled = good.clone();
            doubled[0] = doubled[1];
            assert!(!tiles(&p, &doubled));
            let mut turned = good.clone();
            turned[0].swap(1, 2);
            assert!(!tiles(&p, &turned));
        }
    }

    #[test]
    fn the_chord_sweep_matches_the_definition_on_touching_walks() {
        let mut rnd = xorshift(0xc40d_5eed);
        let (mut checked, mut one_walk, mut pairs) = (0, 0, 0);
        while checked < 1500 {
            let Some(p) = random_touching(&mut rnd) else {
                continue;
            };
            checked += 1;
            one_walk += usize::from(p.holes() == 0);
            let table = ChordTable::new(&p);
            for i in 0..p.len() {
                for j in 0..p.len() {
                    if i == j {
                        continue;
                    }
                    pairs += 1;
                    assert_eq!(
                        table.is_chord(i, j),
                        is_chord(&p, i, j),
                        "{i}-{j} in {:?}",
                        p.points()
                    );
                    for k in (0..p.len()).filter(|&k| k != i && k != j) {
                        let (a, b, c) = (p.point(i), p.point(j), p.point(k));
                        let collinear = a != b && a != c && cross(a, b, c) == 0;
                        assert_eq!(
                            table.line(i, k) == table.line(i, j),
                            collinear,
                            "lines {i} {j} {k} in {:?}",
                            p.points()
                        );
                    }
                }
            }
        }
        assert!(
            one_walk > 500 && checked - one_walk > 100 && pairs > 100_000,
            "{checked} {one_walk} {pairs}"
        );
    }

    #[test]
    fn step_one_over_the_walks_mesh_matches_the_sweep() {
        use crate::algo::minitri::degenerate::{
            minimally_degenerate_by_sweep, minimally_degenerate_over_until,
        };
        let mut rnd = xorshift(0x57e9_0001);
        let (mut checked, mut found, mut flipped) = (0, 0, 0);
        while checked < 1800 {
            // Small ones, and larger ones whose mesh is flipped before walking (48 vertices on).
            let p = if checked < 1500 {
                random_touching(&mut rnd)
            } else {
                random_touching_sized(&mut rnd, 30, 150)
            };
            let Some(p) = p else {
                continue;
            };
            flipped += usize::from(p.len() >= 48);
            checked += 1;
            let key = |m: &crate::algo::minitri::degenerate::Degenerate| (m.a, m.b, m.c);
            let mut swept = minimally_degenerate_by_sweep(&p);
            let base = crate::algo::plain::walks(&p).expect("plain");
            let (mut walked, _, unexamined) = minimally_degenerate_over_until(&p, base, None);
            assert_eq!(unexamined, 0);
            swept.sort_by_key(key);
            walked.sort_by_key(key);
            assert_eq!(walked, swept, "{:?}", p.points());
            found += swept.len();
        }
        assert!(found > 1000 && flipped > 100, "{found} {flipped}");
    }

    #[test]
    fn on_one_walk_minitri_without_search_equals_the_walk_dp() {
        let mut rnd = xorshift(0x0e1a_3a1c);
        let (mut checked, mut large, mut saved) = (0, 0, 0);
        while checked < 200 {
            let p = if checked % 2 == 0 {
                random_touching(&mut rnd)
            } else {
                random_touching_sized(&mut rnd, 30, 150)
            };
            let Some(p) = p.filter(|p| p.holes() == 0) else {
                continue;
            };
            checked += 1;
            large += usize::from(p.len() >= 48);
            let t = crate::algo::minitri::triangulate_walks(&p, None).expect("minitri");
            assert!(t.optimal);
            assert!(crate::verify::check(&p, &t).valid, "{:?}", p.points());
            let (dp, _) = minimum(&p, super::super::asano::DEFAULT_LIMIT, None).expect("walk DP");
            assert_eq!(t.triangles.len(), dp.len(), "{:?}", p.points());
            saved += usize::from(!t.degenerate.is_empty());
        }
        assert!(large > 5 && saved > 100, "{large} {saved}");
    }
}
