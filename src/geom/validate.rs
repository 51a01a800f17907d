//! Validation: is the polygon simple, are its holes where holes belong?
//!
//! Input contract: a [`Polygon`] as built by `Polygon::from_raw` before validation (rings of at
//! least 3 distinct consecutive vertices, non-zero area, outer ring counter-clockwise, holes
//! clockwise). Output guarantee: [`errors`] is empty exactly when no two vertices share a point,
//! no edge folds back onto its neighbour (spike), no two non-adjacent edges share a point (no
//! crossing, no touching, no overlap, within a ring or between rings), every hole lies inside the
//! outer ring and no hole lies inside another hole.
//!
//! Method: one plane sweep over all edges of all rings (Shamos & Hoey, "Geometric intersection
//! problems", FOCS 1976), with exact predicates. Events are vertices in lexicographic `(x, y)`
//! order, which is a sweep by a line turned infinitesimally, so vertical edges need no special
//! case; the status orders the edges cut by the sweep line from below to above, compared by
//! orientation tests only. Every pair of edges that becomes adjacent in the status is tested; the
//! leftmost forbidden contact is always found this way. While sweeping, the edge just below the
//! lowest-leftmost vertex of each ring tells which ring encloses it, giving the nesting of rings.
//! The status is a [`Status`] (a treap with neighbour links): an edge is compared with others
//! only when inserted; its neighbours, and its removal, take no comparison.
//! Complexity: O(n log n) time (expected; about log2 n orientation tests per edge), O(n) memory.
//! Small polygons without holes (at most `SMALL_RING` vertices, the bulk of a batch of building
//! footprints) are first checked pair by pair, which costs less than the sweep's set there; the
//! sweep runs only if some pair meets, so the reported contact is the same either way.

use super::kernel::{segment_contact, Coord, SegmentContact};
use super::polygon::{Polygon, Ring};
use super::status::{Handle, Status};
use std::cmp::Ordering;

/// Why a polygon is not valid. `Display` names the ring, vertex numbers and coordinates.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum InvalidPolygon {
    /// A ring with fewer than 3 distinct vertices.
    #[error("{ring} has {distinct} distinct {}; a ring needs at least 3{}{}", if *distinct == 1 { "vertex" } else { "vertices" }, if *distinct == 1 && !matches!(ring, Ring::Outer) { " (a single point is not a hole; minitri takes no interior points)" } else { "" }, drop_hint(*ring))]
    TooFewVertices {
        /// The ring.
        ring: Ring,
        /// Its number of distinct vertices after dropping consecutive duplicates.
        distinct: usize,
    },
    /// A ring whose vertices are all collinear.
    #[error("{ring} has zero area (all its vertices lie on one line){}", drop_hint(*ring))]
    ZeroArea {
        /// The ring.
        ring: Ring,
    },
    /// Coordinates whose common decimal grid is too large for the fast kernel's exact 128-bit
    /// predicates: only from the fast kernel's own constructors (`Polygon::from_raw`);
    /// `AnyPolygon::from_raw` takes the wide kernel instead.
    #[error("coordinates too large for exact arithmetic: {detail}")]
    CoordinatesTooLarge {
        /// What exceeds the range.
        detail: String,
    },
    /// An edge folds back onto the previous one.
    #[error("spike at {ring} vertex {vertex} {at}: edges {prev}-{vertex} and {vertex}-{next} fold back onto each other; --repair removes spikes")]
    Spike {
        /// The ring.
        ring: Ring,
        /// The vertex where the boundary turns back.
        vertex: usize,
        /// Its previous vertex.
        prev: usize,
        /// Its next vertex.
        next: usize,
        /// Its coordinates.
        at: String,
    },
    /// Two vertices at the same point (the boundary touches itself there).
    #[error("{ring_a} vertex {vertex_a} and {ring_b} vertex {vertex_b} are both at {at}: {}", touch_kind(*ring_a, *ring_b))]
    RepeatedVertex {
        /// The first vertex's ring.
        ring_a: Ring,
        /// The first vertex.
        vertex_a: usize,
        /// The second vertex's ring.
        ring_b: Ring,
        /// The second vertex.
        vertex_b: usize,
        /// The common point.
        at: String,
    },
    /// Two non-adjacent edges share a point.
    #[error("{contact}{hint}", contact = .0, hint = overlap_hint(.0))]
    EdgesMeet(Box<EdgeContact>),
    /// A hole that is not inside the outer ring.
    #[error("hole {hole} lies outside the outer ring")]
    HoleOutside {
        /// The hole, numbered from 1.
        hole: usize,
    },
    /// A hole inside another hole.
    #[error("hole {hole} lies inside hole {container} (a hole cannot contain another hole)")]
    HoleInsideHole {
        /// The inner hole.
        hole: usize,
        /// The hole around it.
        container: usize,
    },
    /// Two rings leave a common point along the same direction (they share a stretch of edge).
    #[error("rings overlap: {a} and {b} at {at} both run towards {towards} (rings may touch at single points only)")]
    SharedStretch {
        /// The first ring's vertex (or edge) at the point.
        a: String,
        /// The second one.
        b: String,
        /// The common point.
        at: String,
        /// Where both run from there.
        towards: String,
    },
    /// Two rings meet at a point where they cross, or where one enters the other.
    #[error("rings cross at a touch point: {a} and {b} meet at {at}, and one passes into the other there")]
    TouchCrossing {
        /// The first ring's vertex (or edge) at the point.
        a: String,
        /// The second one.
        b: String,
        /// The common point.
        at: String,
    },
    /// Touches close a cycle of rings, which encloses a piece of the interior.
    #[error("touching rings cut the interior in two: {rings} touch in a cycle at {points}, enclosing a piece of the interior; --repair makes each piece a separate polygon")]
    CutInterior {
        /// The rings of the cycle.
        rings: String,
        /// Its touch points.
        points: String,
    },
    /// The outer ring inside one of the holes.
    #[error(
        "the outer ring lies inside hole {hole} (is the first ring really the outer boundary?)"
    )]
    OuterInsideHole {
        /// The hole around the outer ring.
        hole: usize,
    },
}

/// Two edges that meet where they must not, named for the user.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error("{}: {ring_a} edge {}-{} {} {} {ring_b} edge {}-{} {} {}", contact_title(*contact, *ring_a, *ring_b), edge_a.0, edge_a.1, segment_a, contact_verb(*contact), edge_b.0, edge_b.1, segment_b, at)]
pub struct EdgeContact {
    /// How they meet.
    pub contact: SegmentContact,
    /// The first edge's ring.
    pub ring_a: Ring,
    /// The first edge's vertex numbers.
    pub edge_a: (usize, usize),
    /// The first edge's coordinates.
    pub segment_a: String,
    /// The second edge's ring.
    pub ring_b: Ring,
    /// The second edge's vertex numbers.
    pub edge_b: (usize, usize),
    /// The second edge's coordinates.
    pub segment_b: String,
    /// Where they meet, in words.
    pub at: String,
}

/// What `--repair` would do about a degenerate ring: drop it, if it is a hole.
fn drop_hint(ring: Ring) -> &'static str {
    match ring {
        Ring::Outer => "",
        Ring::Hole(_) => "; --repair drops the hole",
    }
}

/// What `--repair` would do about edges running along each other.
fn overlap_hint(contact: &EdgeContact) -> &'static str {
    match (contact.contact, contact.ring_a == contact.ring_b) {
        (SegmentContact::Overlap, false) => "; --repair merges rings sharing a stretch of edge",
        (SegmentContact::Overlap, true) => "; --repair removes a stretch the ring runs along twice",
        (SegmentContact::Touch, true) => "; --repair splits the ring there",
        _ => "",
    }
}

fn touch_kind(a: Ring, b: Ring) -> &'static str {
    if a == b {
        "the ring touches itself; --repair splits it there"
    } else {
        "the rings touch"
    }
}

fn contact_title(contact: SegmentContact, a: Ring, b: Ring) -> &'static str {
    match (contact, a == b) {
        (SegmentContact::Cross, true) => "self-intersection",
        (SegmentContact::Cross, false) => "rings cross",
        (SegmentContact::Overlap, true) => "self-overlap",
        (SegmentContact::Overlap, false) => "rings overlap",
        (_, true) => "self-touching",
        (_, false) => "rings touch",
    }
}

fn contact_verb(contact: SegmentContact) -> &'static str {
    match contact {
        SegmentContact::Cross => "crosses",
        SegmentContact::Overlap => "overlaps",
        _ => "touches",
    }
}

/// The first problem of `polygon`, if any.
pub fn check<P: Coord>(polygon: &Polygon<P>) -> Result<(), InvalidPolygon> {
    errors(polygon).into_iter().next().map_or(Ok(()), Err)
}

/// Every problem of `polygon` that can be reported reliably: all spikes and repeated vertices;
/// then, only if there are none, the leftmost contact between edges; then, only if there is none,
/// every misplaced hole.
pub fn errors<P: Coord>(polygon: &Polygon<P>) -> Vec<InvalidPolygon> {
    errors_with(polygon, true)
}

/// Polygons without holes up to this many vertices are first checked pair by pair: cheaper than
/// the sweep's set for the small polygons of batches (building footprints).
const SMALL_RING: usize = 32;

/// [`errors`], with the pair-by-pair check of small rings on or off (the tests compare both).
pub(crate) fn errors_with<P: Coord>(
    polygon: &Polygon<P>,
    small_rings_by_pairs: bool,
) -> Vec<InvalidPolygon> {
    match scan(polygon, small_rings_by_pairs, false) {
        Ok(_) => Vec::new(),
        Err(errors) => errors,
    }
}

/// The contacts between rings that OGC allows, found by [`touching`]: each to be checked at its
/// point by [`crate::geom::touch`].
#[derive(Clone, Debug, Default)]
pub(crate) struct Contacts {
    /// `(edge, vertex)`: `vertex` (of another ring) lies strictly inside `edge` (`edge ->
    /// next(edge)`).
    pub on_edge: Vec<(usize, usize)>,
    /// Whether two vertices of different rings share a point.
    pub shared_vertices: bool,
    /// For each ring, what the sweep saw just below its lowest-leftmost vertex (see `sweep`).
    pub below: Vec<Option<(usize, bool)>>,
}

impl Contacts {
    /// Whether the rings touch at all.
    pub fn any(&self) -> bool {
        self.shared_vertices || !self.on_edge.is_empty()
    }
}

/// Like [`errors`], but rings may touch each other at single points: a vertex of both, or a
/// vertex of one strictly inside an edge of the other. Those contacts are returned (not judged:
/// [`crate::geom::touch`] checks them at their points and as a whole); every other problem is an
/// error as in [`errors`]. Misplaced rings are judged here only when nothing touches.
pub(crate) fn touching<P: Coord>(polygon: &Polygon<P>) -> Result<Contacts, Vec<InvalidPolygon>> {
    scan(polygon, true, true)
}

fn scan<P: Coord>(
    polygon: &Polygon<P>,
    small_rings_by_pairs: bool,
    allow_touches: bool,
) -> Result<Contacts, Vec<InvalidPolygon>> {
    let mut errors = spikes(polygon);
    let mut contacts = Contacts::default();
    // One small ring: valid exactly when no two non-adjacent edges meet (two vertices at one
    // point make two such edges meet there, so none is repeated either). Only if some do is the
    // full scan below run, which then reports what is wrong (its sorting is worth saving on a
    // batch of small polygons: docs/benchmarks.md).
    if errors.is_empty()
        && small_rings_by_pairs
        && polygon.holes() == 0
        && polygon.len() <= SMALL_RING
        && no_two_edges_meet(polygon)
    {
        return Ok(contacts);
    }
    let mut order: Vec<usize> = (0..polygon.len()).collect();
    order.sort_unstable_by_key(|&i| (polygon.point(i), i));
    for pair in order.windows(2) {
        let (i, j) = (pair[0], pair[1]);
        if polygon.point(i) == polygon.point(j) {
            if allow_touches && polygon.ring_index(i) != polygon.ring_index(j) {
                contacts.shared_vertices = true;
                continue;
            }
            errors.push(InvalidPolygon::RepeatedVertex {
                ring_a: polygon.ring(i),
                vertex_a: polygon.id(i),
                ring_b: polygon.ring(j),
                vertex_b: polygon.id(j),
                at: polygon.format_vertex(i),
            });
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    // (A small ring whose edges meet goes on to the sweep, which finds and reports the leftmost
    // contact, as for any polygon.)
    let mut found = allow_touches.then(Vec::new);
    let below = sweep(polygon, &order, &mut found, false).map_err(|e| vec![e])?;
    contacts.on_edge = found.unwrap_or_default();
    contacts.on_edge.sort_unstable();
    contacts.on_edge.dedup();
    if contacts.any() {
        contacts.below = below;
        return Ok(contacts);
    }
    let errors = nesting_errors(&parents(&below, &[]));
    if errors.is_empty() {
        Ok(contacts)
    } else {
        Err(errors)
    }
}

/// For `--repair`: every vertex lying strictly inside an edge, of another ring or of its own, as
/// `(edge, vertex)` pairs (sorted), found by the sweep. `None` when edges meet otherwise than at
/// such points or at common vertices (rings cross or overlap: validation reports it).
/// Within a ring no two vertices may share a point. O(n log n).
pub(crate) fn vertices_on_edges<P: Coord>(polygon: &Polygon<P>) -> Option<Vec<(usize, usize)>> {
    let mut order: Vec<usize> = (0..polygon.len()).collect();
    order.sort_unstable_by_key(|&i| (polygon.point(i), i));
    let mut found = Some(Vec::new());
    sweep(polygon, &order, &mut found, true).ok()?;
    let mut found = found.unwrap_or_default();
    found.sort_unstable();
    found.dedup();
    Some(found)
}

/// Each ring's enclosing ring (`None`: none) from what the sweep saw below each ring's first
/// vertex (`below[r]`: the ring of the edge below and whether that ring encloses the region above
/// the edge). Rings in `fixed` (touching others, their place judged elsewhere) are taken to be
/// where they belong: the outer ring in nothing, a hole in the outer ring.
pub(crate) fn parents(below: &[Option<(usize, bool)>], fixed: &[bool]) -> Vec<Option<usize>> {
    let mut parent: Vec<Option<usize>> = vec![None; below.len()];
    // A ring's `below` names a ring whose first vertex the sweep met earlier: resolve in that
    // order (the order of first vertices).
    let mut order: Vec<usize> = (0..below.len()).collect();
    let mut depth = vec![usize::MAX; below.len()];
    fn resolve(r: usize, below: &[Option<(usize, bool)>], depth: &mut [usize]) -> usize {
        if depth[r] == usize::MAX {
            depth[r] = 0; // guards against a cycle, which the sweep cannot make
            depth[r] = match below[r] {
                Some((owner, _)) if owner != r => resolve(owner, below, depth) + 1,
                _ => 0,
            };
        }
        depth[r]
    }
    for r in 0..below.len() {
        resolve(r, below, &mut depth);
    }
    order.sort_by_key(|&r| depth[r]);
    for r in order {
        parent[r] = if fixed.get(r).copied().unwrap_or(false) {
            (r != 0).then_some(0)
        } else {
            match below[r] {
                None => None,
                Some((owner, true)) => Some(owner),
                Some((owner, false)) => parent[owner],
            }
        };
    }
    parent
}

/// Whether no two non-adjacent edges of `polygon` share a point, testing every pair: O(n^2).
fn no_two_edges_meet<P: Coord>(polygon: &Polygon<P>) -> bool {
    let n = polygon.len();
    // Each edge with its bounding box (the ends of least and greatest x, then y), so that most
    // pairs are told apart by comparisons alone.
    let edges: Vec<(P, P, [P; 4])> = (0..n)
        .map(|e| {
            let (a, b) = (polygon.point(e), polygon.point(polygon.next(e)));
            let (x, y) = (P::cmp_x(a, b).is_le(), P::cmp_y(a, b).is_le());
            let pick = |first: bool| if first { a } else { b };
            (a, b, [pick(x), pick(!x), pick(y), pick(!y)])
        })
        .collect();
    let lt = |axis: usize, u: P, v: P| {
        let order = if axis == 0 {
            P::cmp_x(u, v)
        } else {
            P::cmp_y(u, v)
        };
        order == Ordering::Less
    };
    (0..n).all(|e| {
        let (a, b, r) = edges[e];
        (e + 1..n)
            .filter(|&f| polygon.next(e) != f && polygon.next(f) != e)
            .all(|f| {
                let (c, d, s) = edges[f];
                lt(0, r[1], s[0])
                    || lt(0, s[1], r[0])
                    || lt(1, r[3], s[2])
                    || lt(1, s[3], r[2])
                    || segment_contact(a, b, c, d) == SegmentContact::Disjoint
            })
    })
}

/// Whether the boundary `a -> b -> c` folds back at `b`: `a` and `c` on one line through `b`, on
/// the same side of it (a spike; `--repair` removes them with the same test).
pub(crate) fn folds_back<P: Coord>(a: P, b: P, c: P) -> bool {
    use super::kernel::{cross, dot};
    cross(a, b, c) == 0 && dot(b, a, c) > 0
}

fn spikes<P: Coord>(polygon: &Polygon<P>) -> Vec<InvalidPolygon> {
    (0..polygon.len())
        .filter_map(|i| {
            let (p, w, n) = (polygon.prev(i), i, polygon.next(i));
            let (a, b, c) = (polygon.point(p), polygon.point(w), polygon.point(n));
            folds_back(a, b, c).then(|| InvalidPolygon::Spike {
                ring: polygon.ring(i),
                vertex: polygon.id(w),
                prev: polygon.id(p),
                next: polygon.id(n),
                at: polygon.format_vertex(w),
            })
        })
        .collect()
}

/// An edge in the sweep status: `a < b` lexicographically; `edge` is the index of its first
/// vertex along the ring (the edge runs `edge -> next(edge)`). A probe for a point has `a == b`.
#[derive(Clone, Copy, Debug)]
struct Cut<P> {
    a: P,
    b: P,
    edge: usize,
}

const PROBE: usize = usize::MAX;

impl<P: Coord> Cut<P> {
    fn of(polygon: &Polygon<P>, edge: usize) -> Cut<P> {
        let (u, w) = (polygon.point(edge), polygon.point(polygon.next(edge)));
        Cut {
            a: u.min(w),
            b: u.max(w),
            edge,
        }
    }
}

order_from_cmp!(Cut<P>);

impl<P: Coord> Ord for Cut<P> {
    /// Below/above at the current sweep position, for edges cut by the sweep line at the same
    /// time (the only ones a set ever compares): test the later-starting edge's start (or, if it
    /// lies on the other edge's line, its end) against the earlier-starting edge.
    fn cmp(&self, other: &Self) -> Ordering {
        use super::kernel::cross;
        if self.edge == other.edge {
            return Ordering::Equal;
        }
        let (first, second, flipped) = if self.a <= other.a {
            (self, other, false)
        } else {
            (other, self, true)
        };
        let mut side = cross(first.a, first.b, second.a);
        if side == 0 {
            side = cross(first.a, first.b, second.b);
        }
        // `second` above `first` means `first` is Less.
        let first_vs_second = match side.cmp(&0) {
            Ordering::Greater => Ordering::Less,
            Ordering::Less => Ordering::Greater,
            Ordering::Equal => first.edge.cmp(&second.edge), // only with a contact, reported anyway
        };
        if flipped {
            first_vs_second.reverse()
        } else {
            first_vs_second
        }
    }
}

/// The sweep: the leftmost forbidden contact, or for each ring what lies just below its first
/// vertex (`None`: nothing; else the ring of the edge below and whether that ring encloses the
/// region above the edge). With `touches`, contacts OGC allows between rings are collected there
/// instead of being errors; with `touches` and `same_ring`, also a vertex strictly inside an edge
/// of its own ring.
fn sweep<P: Coord>(
    polygon: &Polygon<P>,
    order: &[usize],
    touches: &mut Option<Vec<(usize, usize)>>,
    same_ring: bool,
) -> Result<Vec<Option<(usize, bool)>>, InvalidPolygon> {
    let rings = polygon.holes() + 1;
    let mut below_of: Vec<Option<(usize, bool)>> = vec![None; rings];
    let mut seen = vec![false; rings];
    let mut status: Status<Cut<P>> = Status::new();
    // The status handle of each edge present (edges are numbered by their first vertex).
    let mut handle: Vec<Option<Handle>> = vec![None; polygon.len()];
    for &i in order {
        let p = polygon.point(i);
        let r = polygon.ring_index(i);
        if !seen[r] {
            seen[r] = true;
            let probe = Cut {
                a: p,
                b: p,
                edge: PROBE,
            };
            if let Some(below) = status.below(&probe) {
                let below = status.key(below).edge;
                let owner = polygon.ring_index(below);
                let forward = polygon.point(below) < polygon.point(polygon.next(below));
                // A ring encloses the region on the left of its edges if it is the outer ring
                // (counter-clockwise), on the right if it is a hole (clockwise).
                let enclosed_above = forward == (owner == 0);
                below_of[r] = Some((owner, enclosed_above));
            }
        }
        let edges = [polygon.prev(i), i];
        for &e in &edges {
            if Cut::of(polygon, e).b == p {
                let h = handle[e]
                    .take()
                    .expect("an edge ending here was inserted at its start");
                let above = status.next(h).map(|a| status.key(a).edge);
                let below = status.prev(h).map(|b| status.key(b).edge);
                status.remove(h);
                if let (Some(a), Some(b)) = (above, below) {
                    test(polygon, a, b, touches, same_ring)?;
                }
            }
        }
        for &e in &edges {
            let cut = Cut::of(polygon, e);
            if cut.a == p {
                let h = status.insert(cut);
                handle[e] = Some(h);
                if let Some(above) = status.next(h) {
                    test(polygon, e, status.key(above).edge, touches, same_ring)?;
                }
                if let Some(below) = status.prev(h) {
                    test(polygon, e, status.key(below).edge, touches, same_ring)?;
                }
            }
        }
    }
    Ok(below_of)
}

/// Whether edges `e` and `f` meet where they must not. With `touches`, a single common point of
/// edges of different rings that is a vertex of one of them is allowed: recorded there when it
/// lies strictly inside the other edge (a shared vertex is found by sorting); with `same_ring`,
/// also between edges of one ring.
fn test<P: Coord>(
    polygon: &Polygon<P>,
    e: usize,
    f: usize,
    touches: &mut Option<Vec<(usize, usize)>>,
    same_ring: bool,
) -> Result<(), InvalidPolygon> {
    if polygon.next(e) == f || polygon.next(f) == e {
        return Ok(()); // neighbours share their common vertex; spikes are reported separately
    }
    let (a, b) = (polygon.point(e), polygon.point(polygon.next(e)));
    let (c, d) = (polygon.point(f), polygon.point(polygon.next(f)));
    let contact = segment_contact(a, b, c, d);
    if contact == SegmentContact::Disjoint {
        return Ok(());
    }
    let (e1, f1) = (polygon.next(e), polygon.next(f));
    if let Some(found) = touches.as_mut() {
        if contact == SegmentContact::Touch
            && (same_ring || polygon.ring_index(e) != polygon.ring_index(f))
        {
            use super::kernel::strictly_between;
            for (edge, (s, t), v) in [
                (e, (a, b), f),
                (e, (a, b), f1),
                (f, (c, d), e),
                (f, (c, d), e1),
            ] {
                if strictly_between(s, polygon.point(v), t) {
                    found.push((edge, v));
                }
            }
            return Ok(());
        }
    }
    let at = match contact {
        SegmentContact::Cross => {
            // A constructed point, for the message only; no decision depends on it.
            let [ax, ay] = polygon.grid().to_f64(a);
            let [bx, by] = polygon.grid().to_f64(b);
            let [cx, cy] = polygon.grid().to_f64(c);
            let [dx, dy] = polygon.grid().to_f64(d);
            let t = ((cx - ax) * (dy - cy) - (cy - ay) * (dx - cx))
                / ((bx - ax) * (dy - cy) - (by - ay) * (dx - cx));
            format!("near ({}, {})", ax + t * (bx - ax), ay + t * (by - ay))
        }
        _ => {
            let on = |v: usize, s: P, t: P| super::kernel::on_segment(s, t, polygon.point(v));
            let v = [c, d]
                .iter()
                .zip([f, f1])
                .find(|(_, v)| on(*v, a, b))
                .map(|(_, v)| v);
            let v = v.or_else(|| [e, e1].into_iter().find(|&v| on(v, c, d)));
            match v {
                Some(v) => format!("at vertex {} {}", polygon.id(v), polygon.format_vertex(v)),
                None => String::new(),
            }
        }
    };
    let seg =
        |u: usize, w: usize| format!("{}-{}", polygon.format_vertex(u), polygon.format_vertex(w));
    Err(InvalidPolygon::EdgesMeet(Box::new(EdgeContact {
        contact,
        ring_a: polygon.ring(e),
        edge_a: (polygon.id(e), polygon.id(e1)),
        segment_a: seg(e, e1),
        ring_b: polygon.ring(f),
        edge_b: (polygon.id(f), polygon.id(f1)),
        segment_b: seg(f, f1),
        at,
    })))
}

fn nesting_errors(parent: &[Option<usize>]) -> Vec<InvalidPolygon> {
    let mut errors = Vec::new();
    if let Some(hole) = parent[0] {
        errors.push(InvalidPolygon::OuterInsideHole { hole });
    }
    for (hole, &p) in parent.iter().enumerate().skip(1) {
        match p {
            Some(0) => {}
            Some(container) => errors.push(InvalidPolygon::HoleInsideHole { hole, container }),
            None => errors.push(InvalidPolygon::HoleOutside { hole }),
        }
    }
    errors
}

#[cfg(test)]
mod tests;
