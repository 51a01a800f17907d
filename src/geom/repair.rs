//! `--repair`: the usual defects of real polygons mended without new points, before validation
//! (docs/repair.md describes each repair, its message and its cost).
//!
//! Input contract: the rings of one input polygon as points of either exact kernel (on its grid,
//! `to_grid` of [`crate::geom::polygon`], when it fits the fast kernel, else the input decimals,
//! [`crate::geom::wide`]), each vertex with its input number; ring 0 the outer ring.
//! Output guarantee (`repair`): one or more pieces, each an outer ring (counter-clockwise) and its
//! holes (clockwise) made only of input vertices at their input coordinates, whose union is the
//! region the input describes (the points covered an odd number of times by the rings' loops, as
//! OGC `make_valid` reads a ring); every change a [`Repair`] naming rings, vertices and
//! coordinates. The pieces are then validated as any polygon: rings that properly cross (which
//! would need a new point) are still rejected there. Every decision is an exact kernel test.
//!
//! The steps, in order: 1. repeated points dropped and spikes removed, per ring, repeatedly;
//! 2. degenerate holes dropped; 3. a ring through one point twice split into its loops; 4. edges
//! shared in opposite directions removed and the rings traced again; 5. a vertex inside an edge
//! of its own ring cut into it and split as in 3, and loops touching in a cycle traced again as
//! in 4 (5a, 5b), each piece of the interior its own polygon.
//!
//! Bound: O(n log n) for steps 1, 2, 4 and 5 (a sort of the edges by their supporting line, hash
//! maps of edges and points, one sweep); O(k n) for step 3 on a ring split into k loops, and
//! O(h n) to place h holes into several outer rings.

use super::kernel::{cmp_angle_from, cross, line_through, on_segment, Area, Coord, Point};
use super::polygon::{
    dropped, to_grid, wide_points, AnyPolygon, Grid, Polygon, Ring, SweepOnly, Validation, Warning,
};
use super::validate::{folds_back, vertices_on_edges, InvalidPolygon};
use crate::raw::RawPolygon;
use serde::Serialize;
use std::collections::HashMap;
use std::fmt;

/// A vertex: its point (of either kernel) and its input number.
pub(crate) type Vertex<P = Point> = (P, usize);

/// What a repair did.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RepairKind {
    /// A spike removed.
    Spike,
    /// A ring of fewer than 3 distinct points, or of zero area, dropped.
    DroppedRing,
    /// A ring touching itself at a vertex split into its loops.
    SplitRing,
    /// Rings sharing edges merged (the shared edges removed).
    MergedRings,
    /// Rings touching in a cycle, which cuts the interior into pieces: each piece made a
    /// separate polygon.
    CutInterior,
}

/// One change made by `--repair`, in words (`message`) and by kind.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct Repair {
    /// What was done.
    pub kind: RepairKind,
    /// The sentence naming what was changed.
    pub message: String,
}

impl fmt::Display for Repair {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

/// The repaired input: its pieces (rings of vertices, outer ring first), what was repaired,
/// and the repeated points dropped.
#[derive(Clone, Debug)]
pub(crate) struct Repaired<P = Point> {
    pub pieces: Vec<Vec<Vec<Vertex<P>>>>,
    pub repairs: Vec<Repair>,
    pub warnings: Vec<Warning>,
}

impl<P> Default for Repaired<P> {
    fn default() -> Self {
        Repaired {
            pieces: Vec::new(),
            repairs: Vec::new(),
            warnings: Vec::new(),
        }
    }
}

/// A piece of a repaired polygon: valid (with the warnings of building it; on the kernel the
/// input's coordinates needed), or every problem validation found.
pub type Piece = Result<(AnyPolygon, Vec<Warning>), Vec<InvalidPolygon>>;

/// One input polygon after `--repair`: each piece, valid or with its problems; what was
/// repaired; the repeated points dropped.
#[derive(Clone, Debug)]
pub struct Pieces {
    /// Each piece (in order: by the smallest input vertex number of its outer ring), as a valid
    /// polygon or with every problem validation found.
    pub pieces: Vec<Piece>,
    /// What was repaired (empty when the input needed nothing).
    pub repairs: Vec<Repair>,
    /// The repeated points dropped (as without `--repair`).
    pub warnings: Vec<Warning>,
}

/// Repairs one polygon as read, then builds and validates each piece; on the fast kernel when
/// the polygon's grid fits it, else on the wide one (any coordinates the readers accept).
///
/// # Errors
/// What cannot be repaired into anything: an outer ring of fewer than 3 distinct points or of
/// zero area.
pub fn repair_raw(raw: &RawPolygon) -> Result<Pieces, InvalidPolygon> {
    repair_raw_validated(raw, &SweepOnly).map(|(pieces, _)| pieces)
}

/// [`repair_raw`], each piece validated by `how`; with what was made beside each piece's
/// validation, in the order of the pieces (the default for an invalid piece).
pub(crate) fn repair_raw_validated<V: Validation>(
    raw: &RawPolygon,
    how: &V,
) -> Result<(Pieces, Vec<V::Beside>), InvalidPolygon> {
    if raw.rings.is_empty() {
        return Err(InvalidPolygon::TooFewVertices {
            ring: Ring::Outer,
            distinct: 0,
        });
    }
    match to_grid(raw) {
        Ok((points, grid)) => repair_points(raw, points, grid, how),
        Err(InvalidPolygon::CoordinatesTooLarge { .. }) => {
            repair_points(raw, wide_points(raw), Grid::identity(), how)
        }
        Err(e) => Err(e),
    }
}

/// [`repair_raw`] on `points` (every vertex of `raw`, in order) of one kernel.
fn repair_points<P: Coord, V: Validation>(
    raw: &RawPolygon,
    points: Vec<P>,
    grid: Grid,
    how: &V,
) -> Result<(Pieces, Vec<V::Beside>), InvalidPolygon>
where
    AnyPolygon: From<Polygon<P>>,
{
    let mut points = points.into_iter().enumerate();
    let rings: Vec<Vec<Vertex<P>>> = raw
        .rings
        .iter()
        .map(|r| {
            points
                .by_ref()
                .take(r.len())
                .map(|(id, p)| (p, id))
                .collect()
        })
        .collect();
    let input_vertices = rings.iter().map(Vec::len).sum();
    let repaired = repair(rings, &grid)?;
    let (pieces, besides) = repaired
        .pieces
        .into_iter()
        .map(|rings| {
            let (polygon, warnings) = match Polygon::from_grid_rings(rings, grid, input_vertices) {
                Ok(built) => built,
                Err(e) => return (Err(vec![e]), V::Beside::default()),
            };
            match how.validated(polygon) {
                Ok((polygon, beside)) => (Ok((AnyPolygon::from(polygon), warnings)), beside),
                Err(errors) => (Err(errors), V::Beside::default()),
            }
        })
        .unzip();
    let pieces = Pieces {
        pieces,
        repairs: repaired.repairs,
        warnings: repaired.warnings,
    };
    Ok((pieces, besides))
}

/// A loop with its role: an outer boundary (counter-clockwise) or a hole (clockwise).
#[derive(Clone, Debug)]
struct Loop<P> {
    /// The input ring it comes from.
    ring: usize,
    shell: bool,
    vertices: Vec<Vertex<P>>,
}

/// Repairs the rings of one polygon (see the module documentation).
///
/// # Errors
/// The outer ring's [`InvalidPolygon::TooFewVertices`] or [`InvalidPolygon::ZeroArea`] when it
/// has fewer than 3 distinct points or no area left once its spikes are gone (nothing to repair
/// into), or when nothing at all is left.
pub(crate) fn repair<P: Coord>(
    rings: Vec<Vec<Vertex<P>>>,
    grid: &Grid,
) -> Result<Repaired<P>, InvalidPolygon> {
    let mut out = Repaired::default();
    let mut loops = Vec::new();
    for (r, ring) in rings.into_iter().enumerate() {
        let name = Ring::from_index(r);
        // Judged as written first (a ring on one line is all spikes), then once despiked.
        let degenerate = |ring: &[Vertex<P>]| {
            let mut points: Vec<P> = ring.iter().map(|v| v.0).collect();
            points.dedup();
            while points.len() > 1 && points.first() == points.last() {
                points.pop();
            }
            let distinct = points.len();
            let flat = points
                .iter()
                .all(|&q| cross(points[0], points[1.min(distinct - 1)], q) == 0);
            (distinct < 3 || flat).then_some((distinct, flat && distinct >= 3))
        };
        let as_written = if ring.is_empty() {
            Some((0, false))
        } else {
            degenerate(&ring)
        };
        let (cleaned, problem) = match as_written {
            Some(problem) => (Vec::new(), Some((problem, false))),
            None => {
                let cleaned = despike(r, ring, grid, &mut out);
                let problem = if cleaned.is_empty() {
                    Some((0, false))
                } else {
                    degenerate(&cleaned)
                };
                (cleaned, problem.map(|p| (p, true)))
            }
        };
        if let Some(((distinct, flat), despiked)) = problem {
            if r == 0 {
                return Err(if flat {
                    InvalidPolygon::ZeroArea { ring: name }
                } else {
                    InvalidPolygon::TooFewVertices {
                        ring: name,
                        distinct,
                    }
                });
            }
            let why = if despiked {
                "nothing of it is left once its spikes are removed".to_string()
            } else if flat {
                "it has zero area (all its points on one line)".to_string()
            } else {
                format!(
                    "it has {distinct} distinct {}",
                    if distinct == 1 { "point" } else { "points" }
                )
            };
            out.repairs.push(Repair {
                kind: RepairKind::DroppedRing,
                message: format!("{name} dropped: {why}"),
            });
            continue;
        }
        loops.extend(split(r, r == 0, cleaned, grid, &mut out, &HashMap::new()));
    }
    let loops = merge(loops, grid, &mut out);
    let (mut shells, mut holes): (Vec<_>, Vec<_>) = separate(loops, grid, &mut out)
        .into_iter()
        .partition(|l| l.shell);
    if shells.is_empty() {
        return Err(InvalidPolygon::ZeroArea { ring: Ring::Outer });
    }
    let first_id = |l: &Loop<P>| l.vertices.iter().map(|v| v.1).min();
    shells.sort_by_key(first_id);
    holes.sort_by_key(|l| (l.ring, first_id(l)));
    let mut pieces: Vec<Vec<Vec<Vertex<P>>>> =
        shells.iter().map(|s| vec![s.vertices.clone()]).collect();
    for hole in holes {
        let at = if shells.len() == 1 {
            0
        } else {
            innermost(&shells, &hole.vertices).unwrap_or(0)
        };
        pieces[at].push(hole.vertices);
    }
    out.pieces = pieces;
    Ok(out)
}

/// Ring `r` without repeated consecutive points and without spikes.
fn despike<P: Coord>(
    r: usize,
    ring: Vec<Vertex<P>>,
    grid: &Grid,
    out: &mut Repaired<P>,
) -> Vec<Vertex<P>> {
    let name = Ring::from_index(r);
    let spike = |out: &mut Repaired<P>, a: Vertex<P>, b: Vertex<P>, c: Vertex<P>| {
        out.repairs.push(Repair {
            kind: RepairKind::Spike,
            message: format!(
                "{name}: spike at vertex {} {} removed (edges {}-{} and {}-{} folded back onto each other)",
                b.1,
                grid.format_point(b.0),
                a.1,
                b.1,
                b.1,
                c.1
            ),
        });
    };
    let mut kept: Vec<Vertex<P>> = Vec::with_capacity(ring.len());
    for v in ring {
        if let Some(&last) = kept.last() {
            if last.0 == v.0 {
                out.warnings.push(dropped(name, v.1, last.1, grid, v.0));
                continue;
            }
        }
        kept.push(v);
        while kept.len() >= 3 {
            let k = kept.len();
            let (a, b, c) = (kept[k - 3], kept[k - 2], kept[k - 1]);
            if !folds_back(a.0, b.0, c.0) {
                break;
            }
            spike(out, a, b, c);
            kept.remove(k - 2);
            if a.0 == c.0 {
                out.warnings.push(dropped(name, c.1, a.1, grid, c.0));
                kept.pop();
            }
        }
    }
    // Where the ring closes: the last vertex against the first, spikes at either end.
    loop {
        let k = kept.len();
        if k < 3 {
            if k == 2 && kept[0].0 == kept[1].0 {
                out.warnings
                    .push(dropped(name, kept[1].1, kept[0].1, grid, kept[1].0));
                kept.pop();
            }
            break;
        }
        let (first, second, last, before) = (kept[0], kept[1], kept[k - 1], kept[k - 2]);
        if first.0 == last.0 {
            out.warnings
                .push(dropped(name, last.1, first.1, grid, last.0));
            kept.pop();
        } else if folds_back(before.0, last.0, first.0) {
            spike(out, before, last, first);
            kept.pop();
        } else if folds_back(last.0, first.0, second.0) {
            spike(out, last, first, second);
            kept.remove(0);
        } else {
            break;
        }
    }
    kept
}

/// Ring `r` (an outer boundary if `outer`, else a hole) split into its loops where it passes a
/// point twice, each loop with its role and orientation; the loop through the ring's first
/// vertex first. `on_edge`: the points where the ring passes twice because a vertex of it lay
/// inside its edge (step 5), with that edge's input numbers, for the message.
fn split<P: Coord>(
    r: usize,
    outer: bool,
    ring: Vec<Vertex<P>>,
    grid: &Grid,
    out: &mut Repaired<P>,
    on_edge: &HashMap<P, (usize, usize)>,
) -> Vec<Loop<P>> {
    let mut stack: Vec<Vertex<P>> = Vec::with_capacity(ring.len());
    let mut at: HashMap<P, usize> = HashMap::new();
    let mut loops: Vec<Vec<Vertex<P>>> = Vec::new();
    for v in ring {
        if let Some(&k) = at.get(&v.0) {
            let found: Vec<Vertex<P>> = stack.drain(k..).collect();
            for u in &found[1..] {
                at.remove(&u.0);
            }
            loops.push(found);
        }
        at.insert(v.0, stack.len());
        stack.push(v);
    }
    loops.insert(0, stack);
    let name = Ring::from_index(r);
    let count = loops.len();
    let depths: Vec<usize> = (0..count)
        .map(|i| {
            (0..count)
                .filter(|&j| j != i && inside(&loops[i], &loops[j]))
                .count()
        })
        .collect();
    let mut result = Vec::with_capacity(count);
    for (i, mut vertices) in loops.into_iter().enumerate() {
        // The outer ring's loops: outer boundaries at even depth; a hole's: holes at even depth.
        let shell = depths[i].is_multiple_of(2) == outer;
        if i > 0 {
            let what = match (outer, shell) {
                (true, true) => "a separate polygon",
                (true, false) => "a hole",
                (false, false) => "a separate hole",
                (false, true) => "a separate polygon inside the hole",
            };
            let inside = on_edge
                .get(&vertices[0].0)
                .map(|(a, b)| format!(", inside its edge {a}-{b}"))
                .unwrap_or_default();
            out.repairs.push(Repair {
                kind: RepairKind::SplitRing,
                message: format!(
                    "{name} touches itself at vertex {} {}{inside}: its loop of {} vertices from there became {what}",
                    vertices[0].1,
                    grid.format_point(vertices[0].0),
                    vertices.len()
                ),
            });
        }
        orient(&mut vertices, shell);
        result.push(Loop {
            ring: r,
            shell,
            vertices,
        });
    }
    result
}

/// Twice the signed area of a loop.
fn area<P: Coord>(vertices: &[Vertex<P>]) -> Area<P> {
    let mut sum = Area::default();
    for (i, v) in vertices.iter().enumerate() {
        let w = vertices[(i + 1) % vertices.len()];
        sum.add(vertices[0].0, v.0, w.0);
    }
    sum
}

/// Turns a loop counter-clockwise (`shell`) or clockwise, keeping its first vertex first.
fn orient<P: Coord>(vertices: &mut [Vertex<P>], shell: bool) {
    let want = if shell { 1 } else { -1 };
    if area(vertices).signum() == -want {
        vertices[1..].reverse();
    }
}

/// The winding number of loop `ring` around `p`, or `None` when `p` lies on it.
fn winding<P: Coord>(ring: &[Vertex<P>], p: P) -> Option<i64> {
    let mut w = 0;
    for (i, a) in ring.iter().enumerate() {
        let (a, b) = (a.0, ring[(i + 1) % ring.len()].0);
        if on_segment(a, b, p) {
            return None;
        }
        if P::cmp_y(a, p).is_le() {
            if P::cmp_y(b, p).is_gt() && cross(a, b, p) > 0 {
                w += 1;
            }
        } else if P::cmp_y(b, p).is_le() && cross(a, b, p) < 0 {
            w -= 1;
        }
    }
    Some(w)
}

/// Whether loop `inner` lies inside loop `outer`, judged by its first vertex not on `outer`
/// (loops that do not cross; if every vertex is on `outer`, by none: false).
fn inside<P: Coord>(inner: &[Vertex<P>], outer: &[Vertex<P>]) -> bool {
    inner
        .iter()
        .find_map(|v| winding(outer, v.0))
        .is_some_and(|w| w != 0)
}

/// The innermost of `shells` around `hole`, if any.
fn innermost<P: Coord>(shells: &[Loop<P>], hole: &[Vertex<P>]) -> Option<usize> {
    let around: Vec<usize> = (0..shells.len())
        .filter(|&s| inside(hole, &shells[s].vertices))
        .collect();
    around.iter().copied().find(|&s| {
        around
            .iter()
            .all(|&t| t == s || inside(&shells[s].vertices, &shells[t].vertices))
    })
}

/// Two loops sharing edges: the pair (smaller first), how many edges, and the first one (its
/// loop and the position of its start).
type Shared = ((usize, usize), usize, (usize, usize));

/// Step 4: edges shared in opposite directions removed and the loops concerned traced again.
fn merge<P: Coord>(loops: Vec<Loop<P>>, grid: &Grid, out: &mut Repaired<P>) -> Vec<Loop<P>> {
    let cut = cut_overlaps(&loops);
    // Each directed edge (from, to) of the cut loops: (loop, position of its start).
    let mut edges: HashMap<(P, P), (usize, usize)> = HashMap::new();
    for (l, lp) in cut.iter().enumerate() {
        for i in 0..lp.vertices.len() {
            let (a, b) = (lp.vertices[i].0, lp.vertices[(i + 1) % lp.vertices.len()].0);
            edges.entry((a, b)).or_insert((l, i));
        }
    }
    let mut cancelled: Vec<Vec<bool>> = cut.iter().map(|l| vec![false; l.vertices.len()]).collect();
    // For each pair of loops, how many edges they share and the first one.
    let mut shared: Vec<Shared> = Vec::new();
    for (l, lp) in cut.iter().enumerate() {
        for i in 0..lp.vertices.len() {
            let (a, b) = (lp.vertices[i].0, lp.vertices[(i + 1) % lp.vertices.len()].0);
            let Some(&(m, j)) = edges.get(&(b, a)) else {
                continue;
            };
            if edges.get(&(a, b)) != Some(&(l, i)) || cancelled[l][i] || cancelled[m][j] {
                continue; // a repeated edge, or one already matched
            }
            cancelled[l][i] = true;
            cancelled[m][j] = true;
            let key = (l.min(m), l.max(m));
            match shared.iter_mut().find(|s| s.0 == key) {
                Some(s) => s.1 += 1,
                None => shared.push((key, 1, (l, i))),
            }
        }
    }
    if shared.is_empty() {
        return loops;
    }
    for &((l, m), count, (e, i)) in &shared {
        let v = &cut[e].vertices;
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        let edge = format!(
            "{} edge {}-{} {}-{}",
            Ring::from_index(cut[e].ring),
            a.1,
            b.1,
            grid.format_point(a.0),
            grid.format_point(b.0)
        );
        let (rl, rm) = (cut[l].ring, cut[m].ring);
        let edges = if count == 1 {
            "an edge".to_string()
        } else {
            format!("{count} edges")
        };
        let message = if rl == rm {
            format!(
                "{} runs along {edges} twice in opposite directions (first {edge}): removed, the ring traced again",
                Ring::from_index(rl)
            )
        } else if rl == 0 || rm == 0 {
            format!(
                "{} shares {edges} with the outer ring (first {edge}): removed, the hole became a notch of the outer ring",
                Ring::from_index(rl.max(rm))
            )
        } else {
            format!(
                "{} and {} share {edges} (first {edge}): removed, the holes merged",
                Ring::from_index(rl),
                Ring::from_index(rm)
            )
        };
        out.repairs.push(Repair {
            kind: RepairKind::MergedRings,
            message,
        });
    }
    let touched: Vec<bool> = cancelled.iter().map(|c| c.iter().any(|&x| x)).collect();
    let mut result = Vec::new();
    for (l, lp) in loops.into_iter().enumerate() {
        if !touched[l] {
            result.push(lp);
        }
    }
    // The remaining edges of the touched loops: start vertex, end point, and the ring numbers.
    let mut rest: Vec<(Vertex<P>, P, usize)> = Vec::new();
    for (l, lp) in cut.iter().enumerate().filter(|(l, _)| touched[*l]) {
        let k = lp.vertices.len();
        for i in (0..k).filter(|&i| !cancelled[l][i]) {
            rest.push((lp.vertices[i], lp.vertices[(i + 1) % k].0, lp.ring));
        }
    }
    for (ring, vertices) in trace(&rest) {
        let twice = area(&vertices).signum();
        if twice == 0 || vertices.len() < 3 {
            continue;
        }
        // Traced where rings touched, it may pass a point twice: its loops, as for an input ring.
        result.extend(split(ring, twice > 0, vertices, grid, out, &HashMap::new()));
    }
    result
}

/// The closed walks along `edges` (start vertex, end point, input ring), each edge taken once:
/// at a point with several ways on, the first edge clockwise from the way back, which keeps the
/// region on the left and parts the walks where rings only touch. Each walk with the ring of its
/// first edge.
fn trace<P: Coord>(edges: &[(Vertex<P>, P, usize)]) -> Vec<(usize, Vec<Vertex<P>>)> {
    let mut leaving: HashMap<P, Vec<usize>> = HashMap::new();
    for (e, edge) in edges.iter().enumerate() {
        leaving.entry(edge.0 .0).or_default().push(e);
    }
    let mut used = vec![false; edges.len()];
    let mut walks = Vec::new();
    for first in 0..edges.len() {
        if used[first] {
            continue;
        }
        let mut vertices = Vec::new();
        let mut e = first;
        loop {
            used[e] = true;
            vertices.push(edges[e].0);
            let (from, to) = (edges[e].0 .0, edges[e].1);
            let next = leaving.get(&to).and_then(|out| {
                // The first edge clockwise from the way back (the largest counter-clockwise angle).
                out.iter()
                    .copied()
                    .max_by(|&f, &g| cmp_angle_from(to, from, edges[f].1, edges[g].1))
            });
            match next {
                Some(f) if !used[f] => e = f,
                _ => break,
            }
        }
        walks.push((edges[first].2, vertices));
    }
    walks
}

/// Step 5: a vertex lying inside an edge of its own loop, and loops touching in a cycle.
///
/// The sweep of validation finds every vertex lying strictly inside an edge (of any loop); a
/// copy of the vertex (same point, same input number) is inserted into the edge. A loop that
/// now passes its own point twice is split there as in step 3. Then the loops meeting at common
/// points form a graph (a node per loop, an edge per loop through a shared point); where it has a
/// cycle, the loops of that connected part are traced again as in step 4 (without the shared
/// edges, nothing cancels): the walks are the boundaries of the region's pieces there, so an
/// interior cut in two becomes two polygons. Loops not concerned are returned as they came (the
/// contacts OGC allows are left to validation), as is everything when the sweep finds rings
/// crossing or overlapping, or a loop of fewer than 3 vertices (rejected by validation).
fn separate<P: Coord>(loops: Vec<Loop<P>>, grid: &Grid, out: &mut Repaired<P>) -> Vec<Loop<P>> {
    let result = match cut_at_own_touches(loops, grid, out) {
        Ok(result) => result,
        Err(loops) => return loops,
    };
    // Step 5b: the loops through each point shared by several; a touch joining loops already
    // joined closes a cycle.
    let n = result.len();
    let mut touches = shared_points(&result);
    let mut root: Vec<usize> = (0..n).collect();
    let mut closing = Vec::new();
    for (_, ls) in &mut touches {
        ls.dedup();
        for k in 1..ls.len() {
            let (a, b) = (find(&mut root, ls[0]), find(&mut root, ls[k]));
            if a == b {
                closing.push(ls[0]);
            } else {
                root[a] = b;
            }
        }
    }
    if closing.is_empty() {
        return result.into_iter().map(|(l, _)| l).collect();
    }
    let part: Vec<usize> = (0..n).map(|l| find(&mut root, l)).collect();
    let mut cyclic: Vec<usize> = closing.iter().map(|&l| part[l]).collect();
    cyclic.sort_unstable();
    cyclic.dedup();
    let mut members: HashMap<usize, Vec<usize>> = cyclic.iter().map(|&c| (c, Vec::new())).collect();
    for (l, c) in part.iter().enumerate() {
        if let Some(m) = members.get_mut(c) {
            m.push(l);
        }
    }
    let mut replaced: Vec<(usize, Vec<Loop<P>>)> = Vec::new();
    for c in cyclic {
        let points = touches.iter().filter(|(_, t)| part[t[0]] == c);
        let points: Vec<P> = points.map(|(p, _)| *p).collect();
        if let Some(traced) = cut_cycle(&result, &members[&c], &points, grid, out) {
            replaced.push((c, traced));
        }
    }
    let mut gone = vec![false; n];
    for &(c, _) in &replaced {
        gone[c] = true;
    }
    let mut loops = Vec::with_capacity(n);
    for (l, (lp, _)) in result.into_iter().enumerate() {
        if !gone[part[l]] {
            loops.push(lp);
        }
    }
    loops.extend(replaced.into_iter().flat_map(|(_, traced)| traced));
    loops
}

/// A loop with its edges cut at the vertices inside them (the vertices traced in step 5b).
type Cut<P> = (Loop<P>, Vec<Vertex<P>>);

/// The root of `r`'s set in the union-find forest `root` (paths halved on the way).
fn find(root: &mut [usize], mut r: usize) -> usize {
    while root[r] != r {
        root[r] = root[root[r]];
        r = root[r];
    }
    r
}

/// Step 5a of [`separate`]: each loop with its edges cut at the vertices the sweep finds inside
/// them (the cut vertices kept for tracing), split where it touches itself; `Err` with the
/// loops as they came when the sweep cannot run (a loop of fewer than 3 vertices, consecutive
/// repeats) or finds rings crossing or overlapping.
fn cut_at_own_touches<P: Coord>(
    loops: Vec<Loop<P>>,
    grid: &Grid,
    out: &mut Repaired<P>,
) -> Result<Vec<Cut<P>>, Vec<Loop<P>>> {
    // The sweep needs rings of at least 3 vertices without consecutive repeats; what is left
    // otherwise is rejected by validation.
    let sane = |l: &Loop<P>| {
        let v = &l.vertices;
        v.len() >= 3 && (0..v.len()).all(|i| v[i].0 != v[(i + 1) % v.len()].0)
    };
    if loops.is_empty() || !loops.iter().all(sane) {
        return Err(loops);
    }
    let rings: Vec<Vec<Vertex<P>>> = loops.iter().map(|l| l.vertices.clone()).collect();
    let polygon = Polygon::rings_as_they_are(&rings, 0, *grid);
    drop(rings);
    let Some(on_edge) = vertices_on_edges(&polygon) else {
        return Err(loops);
    };
    let starts = polygon.ring_starts();
    let locate = |i: usize| {
        let l = polygon.ring_index(i);
        (l, i - starts[l])
    };
    // The vertices to insert into each edge (loop, position of its start), and for each loop
    // the points of its own vertices inside its edges, with the edge's input numbers.
    let mut cuts: HashMap<(usize, usize), Vec<Vertex<P>>> = HashMap::new();
    let mut own: Vec<HashMap<P, (usize, usize)>> = vec![HashMap::new(); loops.len()];
    for &(e, v) in &on_edge {
        let ((l, i), (m, j)) = (locate(e), locate(v));
        let ring = &loops[l].vertices;
        cuts.entry((l, i)).or_default().push(loops[m].vertices[j]);
        if l == m {
            own[l]
                .entry(ring[j].0)
                .or_insert((ring[i].1, ring[(i + 1) % ring.len()].1));
        }
    }
    let mut result: Vec<Cut<P>> = Vec::with_capacity(loops.len());
    for (l, lp) in loops.into_iter().enumerate() {
        let mut vertices = Vec::with_capacity(lp.vertices.len());
        for (i, &v) in lp.vertices.iter().enumerate() {
            vertices.push(v);
            if let Some(inner) = cuts.get_mut(&(l, i)) {
                inner.sort_by(|x, y| P::cmp_dist(v.0, x.0, y.0));
                inner.dedup_by_key(|x| x.0);
                vertices.extend_from_slice(inner);
            }
        }
        if own[l].is_empty() {
            result.push((lp, vertices));
        } else {
            for piece in split(lp.ring, lp.shell, vertices, grid, out, &own[l]) {
                let cut = piece.vertices.clone();
                result.push((piece, cut));
            }
        }
    }
    Ok(result)
}

/// The points shared by several of the (cut) loops, in point order, each with the loops
/// through it (in loop order, a loop once for each time it passes there).
fn shared_points<P: Coord>(result: &[Cut<P>]) -> Vec<(P, Vec<usize>)> {
    let mut through: HashMap<P, Vec<usize>> = HashMap::new();
    for (l, (_, vertices)) in result.iter().enumerate() {
        for v in vertices {
            through.entry(v.0).or_default().push(l);
        }
    }
    let mut touches: Vec<(P, Vec<usize>)> =
        through.into_iter().filter(|(_, ls)| ls.len() > 1).collect();
    touches.sort_unstable_by_key(|t| t.0);
    touches
}

/// Step 5b of [`separate`] for one part of loops `ls` joined in a cycle at `points`: the part
/// traced again, with the repair told, when that cuts its interior into more pieces; `None`
/// when the cycle encloses no interior (pieces touching twice: left as it is).
fn cut_cycle<P: Coord>(
    result: &[Cut<P>],
    ls: &[usize],
    points: &[P],
    grid: &Grid,
    out: &mut Repaired<P>,
) -> Option<Vec<Loop<P>>> {
    let mut edges = Vec::new();
    for &l in ls {
        let (lp, vertices) = &result[l];
        let k = vertices.len();
        for i in 0..k {
            edges.push((vertices[i], vertices[(i + 1) % k].0, lp.ring));
        }
    }
    // Traced again, its walks split silently where they pass a point twice (a touch that is no
    // cycle: OGC allows it, as the input had it).
    let mut quiet = Repaired::default();
    let mut traced = Vec::new();
    for (ring, vertices) in trace(&edges) {
        let twice = area(&vertices).signum();
        if twice != 0 && vertices.len() >= 3 {
            traced.extend(split(
                ring,
                twice > 0,
                vertices,
                grid,
                &mut quiet,
                &HashMap::new(),
            ));
        }
    }
    let before = ls.iter().filter(|&&l| result[l].0.shell).count();
    let after = traced.iter().filter(|l| l.shell).count();
    if after <= before {
        return None;
    }
    let mut rings: Vec<usize> = ls.iter().map(|&l| result[l].0.ring).collect();
    rings.sort_unstable();
    rings.dedup();
    let mut names: Vec<String> = rings
        .iter()
        .map(|&r| Ring::from_index(r).to_string())
        .collect();
    let last = names.pop().unwrap_or_default();
    let (names, verb) = if names.is_empty() {
        (last, "touches itself")
    } else {
        (format!("{} and {last}", names.join(", ")), "touch")
    };
    const SHOWN: usize = 6;
    let shown: Vec<String> = points
        .iter()
        .take(SHOWN)
        .map(|&p| grid.format_point(p))
        .collect();
    let mut at = shown.join(", ");
    if points.len() > SHOWN {
        at.push_str(&format!(" and {} more points", points.len() - SHOWN));
    }
    out.repairs.push(Repair {
        kind: RepairKind::CutInterior,
        message: format!(
            "{names} {verb} at {at}, cutting the interior into {} pieces: each became a separate polygon",
            1 + after - before
        ),
    });
    Some(traced)
}

/// The loops with every edge cut at the vertices of collinear edges lying strictly inside it (a
/// vertex of the same point, with that vertex's number), so that a stretch shared by two rings
/// has the same vertices in both.
fn cut_overlaps<P: Coord>(loops: &[Loop<P>]) -> Vec<Loop<P>> {
    // Every edge by its supporting line: (line, loop, position of its start).
    let mut by_line = Vec::new();
    for (l, lp) in loops.iter().enumerate() {
        let k = lp.vertices.len();
        for i in 0..k {
            let (a, b) = (lp.vertices[i].0, lp.vertices[(i + 1) % k].0);
            by_line.push((line_through(a, b).0, l, i));
        }
    }
    by_line.sort_unstable_by_key(|x| x.0);
    // Cuts of each edge: (loop, position) -> vertices to insert.
    let mut cuts: HashMap<(usize, usize), Vec<Vertex<P>>> = HashMap::new();
    for group in by_line.chunk_by(|x, y| x.0 == y.0).filter(|g| g.len() > 1) {
        let mut points: Vec<Vertex<P>> = group
            .iter()
            .map(|&(_, l, i)| loops[l].vertices[i])
            .chain(group.iter().map(|&(_, l, i)| {
                let v = &loops[l].vertices;
                v[(i + 1) % v.len()]
            }))
            .collect();
        points.sort_unstable();
        points.dedup_by_key(|v| v.0);
        for &(_, l, i) in group {
            let v = &loops[l].vertices;
            let (a, b) = (v[i].0, v[(i + 1) % v.len()].0);
            let (lo, hi) = (a.min(b), a.max(b));
            let start = points.partition_point(|p| p.0 <= lo);
            let end = points.partition_point(|p| p.0 < hi);
            if start < end {
                let mut inner = points[start..end].to_vec();
                if a > b {
                    inner.reverse();
                }
                cuts.insert((l, i), inner);
            }
        }
    }
    loops
        .iter()
        .enumerate()
        .map(|(l, lp)| {
            let mut vertices = Vec::with_capacity(lp.vertices.len());
            for (i, &v) in lp.vertices.iter().enumerate() {
                vertices.push(v);
                if let Some(inner) = cuts.get(&(l, i)) {
                    vertices.extend_from_slice(inner);
                }
            }
            Loop {
                vertices,
                ..lp.clone()
            }
        })
        .collect()
}

#[cfg(test)]
mod tests;
