//! An O(n log n) plain triangulation of a polygon with holes into exactly n + 2w - 2
//! nondegenerate triangles (n vertices over all rings, w holes; n - 2 without holes), by
//! decomposition into monotone pieces (Lee & Preparata, "Location of a point in a planar
//! subdivision and its applications", *SIAM J. Comput.* 6 (1977); Garey, Johnson, Preparata &
//! Tarjan, "Triangulating a simple polygon", *Inform. Process. Lett.* 7 (1978); de Berg, Cheong,
//! van Kreveld & Overmars, *Computational Geometry*, ch. 3, whose Theorem 3.6 covers holes; the
//! lecture notes of Goldwasser (1991) and Toussaint (1993)).
//!
//! Input contract: the rings given one after another in one slice of points, ring 0 the outer
//! ring, counter-clockwise, rings 1.. the holes, clockwise (so the interior is on the left of every
//! edge); each ring at least 3 points, simple, no spike (an edge folding back onto its
//! neighbour); the rings pairwise disjoint (no common point at all), every hole inside the outer
//! ring and outside every other hole; no two points equal; flat vertices (three consecutive
//! collinear vertices) and any other collinearity, within a ring or across rings, allowed;
//! coordinates on the kernel's grid, so every cross product is exact in `i128`. This is what
//! [`crate::Polygon`] guarantees. A single counter-clockwise cycle is the case w = 0.
//! Output guarantee: exactly n + 2w - 2 counter-clockwise triangles of positive area, as indices
//! into the points, with disjoint interiors, covering the polygon (and no hole); every triangle
//! side is a polygon edge or a proper diagonal (it touches the boundary only at its two end
//! vertices). All decisions are exact orientation tests ([`cross`]) and coordinate comparisons;
//! nothing is constructed.
//!
//! # Height order
//!
//! "Above" and "below" mean the lexicographic order of `(y, x)`. This is the order of the
//! height `y + εx` for an infinitesimal `ε > 0`, a linear function, i.e. a sweep by a line turned
//! infinitesimally clockwise; so the textbook theory for a generic sweep direction applies
//! verbatim: no two vertices are at the same height, a horizontal edge simply rises to the east,
//! and the two neighbours of a flat vertex are one above and one below it (opposite vectors have
//! opposite lexicographic signs). "West" and "east" mean left and right of the upward direction:
//! for a segment `lo -> hi` (`lo` below `hi`) and a point `v` strictly between them in height and
//! not on the segment, `v` is west of it exactly when `cross(lo, hi, v) > 0` (if `q` is the
//! segment's point at `v`'s height, `v - q = t(-1, ε)` with `t > 0` for `v` west, and
//! `cross(hi - lo, v - q) = t ((hi - lo).y + ε (hi - lo).x) > 0` since `hi` is above `lo`; the
//! sign is never 0, because a point on the segment's line at a height strictly inside its span
//! lies on the segment).
//!
//! # Vertex classification
//!
//! For a vertex `v` with boundary neighbours `p` (previous) and `n` (next); the interior is on
//! the left of `p -> v -> n`, so `cross(p, v, n) > 0` means convex:
//!
//! | `p`   | `n`   | `cross(p, v, n)` | kind                                                |
//! |-------|-------|------------------|-----------------------------------------------------|
//! | above | above | `> 0`            | start                                               |
//! | above | above | `< 0`            | split (the exterior wedge is above `v`)             |
//! | below | below | `> 0`            | end                                                 |
//! | below | below | `< 0`            | merge (the exterior wedge is below `v`)             |
//! | above | below | any              | downward: regular, interior east (on a west chain)  |
//! | below | above | any              | upward: regular, interior west (on an east chain)   |
//!
//! `cross == 0` with both neighbours on one side is a spike, excluded by the contract; a flat
//! vertex is always regular. Since the interior is on the left of every edge (outer ring
//! counter-clockwise, holes clockwise), an edge running downward has the interior on its east, one
//! running upward on its west. On a hole the table reads the same: its lowest vertex is a split
//! vertex and its highest a merge vertex (both neighbours above, resp. below, and the clockwise
//! ring turns right there).
//!
//! # The sweep (monotone decomposition)
//!
//! Vertices are processed upward (the textbook sweeps downward; this is its mirror image). The
//! status holds the edges with the interior on their east that the sweep line cuts, i.e. the
//! downward edges `e = i -> next(i)` of any ring, with `lo = pts[next(i)]` already passed and
//! `hi = pts[i]` not yet,
//! ordered west to east; each has a helper, the highest vertex passed so far that sees `e`
//! horizontally to its west. Edge `e` is named by its first vertex `i`; `e_v` is the downward edge
//! `v -> next(v)` ending at `v`, `e_p` the downward edge `prev(v) -> v` starting at `v`;
//! "replace helper(e) by `v`" means: if `helper(e)` is a merge vertex, add the diagonal
//! `v helper(e)`; then helper(e) = `v`. "finish `e`" means: replace helper(e) by `v`, remove `e`.
//! "The edge west of `v`" is the status edge immediately west of `v`.
//!
//! | kind     | action                                                                   |
//! |----------|--------------------------------------------------------------------------|
//! | start    | insert `e_p` with helper `v`                                             |
//! | end      | finish `e_v`                                                             |
//! | split    | `e` = edge west of `v`; diagonal `v helper(e)`; helper(e) = `v`;         |
//! |          | insert `e_p` with helper `v`                                             |
//! | merge    | finish `e_v`; `e` = edge west of `v`; replace helper(e) by `v`           |
//! | downward | finish `e_v`; insert `e_p` with helper `v`                               |
//! | upward   | `e` = edge west of `v`; replace helper(e) by `v`                         |
//!
//! The status is a [`Status`] (a treap reached by handle: an edge is compared only when inserted
//! and when searched for west of a vertex, never to be removed) of `Cut`s compared by exact
//! orientation tests only (as `geom::validate`'s `Cut`, turned to the `(y, x)` order). Two facts
//! make that comparison exact
//! and consistent: (1) status edges are pairwise disjoint closed segments (two downward edges meet
//! only at a "downward" regular vertex, where one is removed before the other is inserted) and no
//! status edge touches the vertex being processed when the status is searched or changed (edges
//! ending at `v` are removed first; the searches happen when no status edge is incident to `v`);
//! (2) of two edges cut by the sweep line at once, the later-starting one's lower end lies at a
//! height strictly inside the other's span, so the sign of one [`cross`] against the other edge
//! says which is west, and is never 0. The edge west of `v` is the greatest cut below a probe at
//! `v`, compared the same way.
//!
//! Every diagonal is proper, by de Berg et al.'s Lemma 3.5: when `v` gets the diagonal to
//! `h = helper(e)`, the quadrilateral between `e`, the edge east of `v` and the sweep lines
//! through `h` and `v` has no vertex in its interior (such a vertex would have become the helper)
//! nor on its sides other than `h` and `v` (heights are distinct; polygon edges contain no
//! vertices), and `h`, `v` lie on its bottom and top sides; a merge helper is never an end of `e`
//! (it gets `e` as the edge west of it), so the open diagonal misses every vertex and edge. Each
//! split vertex gets a diagonal downward, each merge vertex one upward, so the pieces have no
//! split or merge vertex, hence are monotone in the height order (de Berg et al., Lemma 3.4 and
//! Theorem 3.6). No diagonal repeats or is an edge: each is added at the event of its upper end,
//! to a helper below; a split helper gets none; a merge vertex helps one edge at a time and both
//! its neighbours are below it, so they are processed before it and cannot be the upper end.
//!
//! # Holes
//!
//! Nothing above uses that the boundary is one cycle: every edge has the interior on its left,
//! whatever its ring; status edges of different rings are disjoint closed segments like those of
//! one ring (the rings are pairwise disjoint); and the quadrilateral argument of Lemma 3.5 is
//! local. So with holes the diagonals are again proper, pairwise non-crossing, none repeated, and
//! no piece has a split or merge vertex. Holes add one question: the shape of the pieces, since a
//! face of the plane graph (ring edges plus diagonals) could a priori surround a hole or touch
//! itself at a vertex. Neither happens, because that graph is 2-connected:
//!
//! Suppose it falls apart, after removing one vertex `v` or none, into two parts `A` and `B` that
//! share at most `v`, each with an edge. A ring minus `v` is still connected, so each ring lies
//! wholly in `A` or in `B`; let `A` be the part without the outer ring, and `H` the vertices of
//! the holes in `A` (`H` is not empty: an edge of `A` that is a diagonal at `v` has its other end
//! on a ring of `A`). The lowest vertex `l` of `H` is the lowest of its hole, a split vertex, so it
//! has a diagonal down to a vertex below all of `H`; the highest `h` is a merge vertex with a
//! diagonal up to a vertex above all of `H`. Every edge at a vertex of `A` other than `v` lies in
//! `A`, so if `l != v` the vertex below `l` is in `A` but not in `H`: it is `v`, and `v` is not in
//! `H`; likewise, if `h != v`, the vertex above `h` is `v`, not in `H`. Since `l != h`, at least
//! one case applies; if both apply, `v` is below `l` and above `h`, impossible; if one does, `v` is
//! the other of `l`, `h`, hence in `H`, a contradiction. So in the 2-connected plane graph every
//! face is bounded by a simple cycle (Diestel, *Graph Theory*, Proposition 4.2.6), and every
//! bounded face other than a hole is a simple polygon with no hole inside: a monotone piece.
//!
//! Count (Euler's formula on the connected graph: n vertices, n + D edges for D diagonals, D + 2
//! faces): the pieces are the D + 2 faces minus the unbounded one and the w holes, i.e. D + 1 - w,
//! and their vertex counts sum to n + 2D (a ring edge bounds one piece, a diagonal two).
//!
//! # Splitting into pieces
//!
//! The polygon edges and diagonals form a plane graph. Around each vertex the neighbours are
//! sorted counter-clockwise starting from the next boundary vertex (all lie in the closed interior
//! angle, which is then swept up to the previous boundary vertex; the sort is exact: half-plane,
//! then [`cross`]). Each piece is then the cycle of half-edges with the piece on their left: after
//! `u -> w` comes `w -> x`, `x` the neighbour of `w` just before `u` counter-clockwise. Each
//! piece comes out counter-clockwise. The half-edges `v -> prev(v)` have the outside of the polygon
//! (the unbounded face or a hole) on their left and start no walk.
//!
//! # Monotone pieces, with flat vertices
//!
//! Each piece (m vertices, `u_1 > ... > u_m` in height) is triangulated by the stack algorithm
//! (Garey et al.; de Berg et al., Section 3.3), emitting triangles instead of diagonals, with one
//! change: a candidate triangle at the top of the stack is cut off only if it is strictly convex
//! (`cross > 0`); when it is collinear (`cross == 0`) the new vertex waits on the stack exactly as
//! in the reflex case. Proof that it still ends with exactly m - 2 triangles, all positive:
//!
//! Invariant before `u_j` (3 <= j <= m): the untriangulated part is the polygon `Q` bounded by the
//! stack `s_0, ..., s_k` (k >= 1, `s_k = u_(j-1)`, `s_1..s_k` consecutive on one chain, `s_0`
//! the top or on the other chain, adjacent to `s_1` in `Q`) and `u_j, ..., u_m` along the chains;
//! every `s_i`, `0 < i < k`, is reflex or flat in `Q`. Being monotone and turning weakly one way
//! (the exterior way), the stack chain is convex: it lies in the closed exterior half-plane of the
//! line through any of its edges.
//!
//! Fan step (`u = u_j` on the other chain than `s_k`, or `u = u_m`): `u` lies strictly on the
//! interior side of every stack edge. Otherwise, for the edge `s_i s_(i+1)`, all of `s_0..s_k` and
//! `u` lie in the closed exterior half-plane; the part of `Q` at or above `u`'s height is a polygon
//! with those vertices plus at most one point `X` at `u`'s height on the edge leaving `s_k`
//! downward; so its part strictly on the interior side is bounded by the line and the two sides
//! at `X`, at heights below `s_k`, and `Q` would have no interior next to `s_i s_(i+1)`, which it
//! has. So each fan triangle `(u, s_i, s_(i+1))` is positive; the rays from `u` to `s_0..s_k` all
//! point upward and turn one way, so the triangles have disjoint interiors and form the polygon
//! `s_0..s_k u`, which contains no other vertex (all others are below `u`) and which no edge
//! enters; `u s_k` is a proper diagonal and the rest is `s_k, u` plus the unprocessed vertices,
//! i.e. the invariant with k = 1.
//!
//! Same-chain step: while `cross > 0` at `s_k` towards `u_j`, the triangle `s_(k-1) s_k u_j` is
//! positive, lies on the interior side of the line `s_(k-1) s_k` (where no other stack vertex is),
//! above `u_j`'s height (where no unprocessed vertex is), and the other chain's edge below `s_0`
//! cannot cross its third side without an end inside it; so it is cut off along a proper
//! diagonal and `s_k` popped. When `cross <= 0`, `u_j` is pushed and the old top is reflex or flat:
//! the invariant holds, and no zero-area triangle is emitted.
//!
//! Count: each emitted triangle removes exactly one vertex from `Q` (a same-chain triangle `s_k`;
//! a fan of k triangles `s_0..s_(k-1)`; the final fan of k triangles all k + 2 vertices left), so
//! there are exactly m - 2, all positive. Over all pieces (D diagonals, D + 1 - w pieces, vertex
//! counts summing to n + 2D, see "Holes") that is n + 2D - 2(D + 1 - w) = n + 2w - 2. In
//! particular a positive triangulation of a monotone polygon with flat vertices always exists.
//!
//! # Complexity and departures
//!
//! O(n log n) time (the sort by height, O(log n) per status operation, the angular sort of the
//! neighbours of each vertex), O(n) memory (status, helpers, at most one diagonal per split or
//! merge vertex, the adjacency of the plane graph, one stack), whatever the number of holes: holes
//! are swept like any other boundary, never bridged one by one to the outer ring (which costs
//! O(n) per hole in ear clippers such as earcut). Departures from the textbook: the
//! sweep runs upward in the `(y, x)` order instead of downward with ties broken by x, which removes
//! every special case for horizontal edges and equal heights; the status comparator is the
//! orientation test above instead of computed intersections; pieces are found by face walking over
//! sorted adjacency lists instead of a DCEL; the stack algorithm emits triangles and waits on
//! collinear triples as on reflex ones.

use crate::geom::kernel::{cross, dot, Coord};
use crate::geom::status::{Handle, Status};
use std::cmp::Ordering;
use std::fmt::Debug;

/// What the sweep asks of its points: the height order and orientation tests. Every
/// [`Coord`] is one (the `(y, x)` order and [`cross`]); so are the copies of touch points moved
/// symbolically into their sectors ([`super::perturbed`]), which is how boundary walks whose
/// rings touch are triangulated by the same sweep.
pub(crate) trait SweepPoint: Copy + Eq + Debug {
    /// The height order (module documentation, "Height order"): `Equal` only for equal points.
    fn cmp_height(self, other: Self) -> Ordering;
    /// The sign of the cross product of `b - a` and `c - a`: `Greater` for a left turn.
    fn orient(a: Self, b: Self, c: Self) -> Ordering;
    /// Whether `q`, collinear with `w` and `reference` ([`SweepPoint::orient`] `Equal`), lies
    /// on the side of `w` where `reference` is.
    fn same_side(w: Self, reference: Self, q: Self) -> bool;
}

impl<P: Coord> SweepPoint for P {
    #[inline]
    fn cmp_height(self, other: Self) -> Ordering {
        P::cmp_y(self, other).then_with(|| P::cmp_x(self, other))
    }
    #[inline]
    fn orient(a: Self, b: Self, c: Self) -> Ordering {
        cross(a, b, c).cmp(&0)
    }
    #[inline]
    fn same_side(w: Self, reference: Self, q: Self) -> bool {
        dot(w, reference, q) > 0
    }
}

/// Whether `a b c` turns strictly left.
#[inline]
fn left<P: SweepPoint>(a: P, b: P, c: P) -> bool {
    P::orient(a, b, c) == Ordering::Greater
}

/// Triangulates a polygon with holes given as its rings of points one after another:
/// `ring_starts[k]` is the index in `pts` of the first point of ring `k` (so `ring_starts[0] ==
/// 0`), ring `k` runs up to `ring_starts[k + 1]` (the last ring up to `pts.len()`); ring 0 is the
/// outer ring, counter-clockwise, the others are holes, clockwise. Returns exactly
/// `n + 2w - 2` counter-clockwise triangles of positive area (`n = pts.len()`, `w` holes), as
/// indices into `pts`. See the module documentation for the full contract and the method.
///
/// # Panics
/// If `ring_starts` does not describe rings of at least 3 points each (it must start at 0 and
/// increase by at least 3 from one ring start to the next and to `pts.len()`), and, as a broken
/// invariant, on input outside the module's contract (crossing or touching rings, equal points,
/// spikes, wrong orientations) when it is detected.
pub(crate) fn triangulate_rings<P: SweepPoint>(
    pts: &[P],
    ring_starts: &[usize],
) -> Vec<[usize; 3]> {
    try_triangulate_rings(pts, ring_starts)
        .expect("monotone triangulation: input outside the contract, invariant broken")
}

/// [`triangulate_rings`] on rings that may break its contract (crossing, touching, equal
/// points, spikes): the same triangles when they keep it, else `None` or some triangles. It never
/// panics (beyond `ring_starts` as in [`triangulate_rings`]) and always ends, within the same
/// bounds: every broken invariant that would be a panic there is a `None` here. So a polygon can
/// be triangulated while it is still being validated ([`crate::geom::polygon`]), the result
/// kept only if the polygon is valid.
pub(crate) fn try_triangulate_rings<P: SweepPoint>(
    pts: &[P],
    ring_starts: &[usize],
) -> Option<Vec<[usize; 3]>> {
    let n = pts.len();
    let links = Links::new(n, ring_starts);
    let holes = ring_starts.len() - 1;
    let expected = n + 2 * holes - 2;
    let mut triangles = Vec::with_capacity(expected);
    let mut work = Work::default();
    let diagonals = Sweep::run(pts, &links)?;
    if diagonals.is_empty() {
        // One monotone ring (a hole always gets diagonals at its lowest and highest vertices).
        let cycle: Vec<usize> = (0..n).collect();
        triangulate_monotone(pts, &cycle, &mut work, &mut triangles)?;
    } else {
        let (vertices, starts) = pieces(pts, &links, &diagonals)?;
        for w in starts.windows(2) {
            triangulate_monotone(pts, &vertices[w[0]..w[1]], &mut work, &mut triangles)?;
        }
    }
    // A wrong count is a broken invariant too.
    (triangles.len() == expected).then_some(triangles)
}

/// The boundary neighbours of every point of a set of rings stored one after another.
struct Links {
    next: Vec<usize>,
    prev: Vec<usize>,
}

impl Links {
    /// The links of rings starting at `ring_starts` (see [`triangulate_rings`]) in `0..n`.
    fn new(n: usize, ring_starts: &[usize]) -> Links {
        assert!(
            ring_starts.first() == Some(&0),
            "ring starts must begin with 0, got {ring_starts:?}"
        );
        let mut next = vec![0; n];
        let mut prev = vec![0; n];
        for (k, &first) in ring_starts.iter().enumerate() {
            let end = ring_starts.get(k + 1).copied().unwrap_or(n);
            assert!(
                end >= first + 3 && end <= n,
                "ring {k} of {ring_starts:?} has fewer than 3 of the {n} points"
            );
            for i in first..end {
                next[i] = if i + 1 == end { first } else { i + 1 };
                prev[i] = if i == first { end - 1 } else { i - 1 };
            }
        }
        Links { next, prev }
    }
}

/// The sweep key of a point: lexicographic `(y, x)`, the height order of the module
/// documentation.
#[inline]
fn height<P: SweepPoint>(p: P) -> Height<P> {
    Height(p)
}

/// A point in the height order: `(y, x)` lexicographic.
#[derive(Clone, Copy, PartialEq, Eq)]
struct Height<P>(P);

impl<P: SweepPoint> Ord for Height<P> {
    #[inline]
    fn cmp(&self, other: &Self) -> Ordering {
        self.0.cmp_height(other.0)
    }
}

impl<P: SweepPoint> PartialOrd for Height<P> {
    #[inline]
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// The kind of a vertex in the sweep (see the classification table of the module documentation).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    /// Both neighbours above, convex.
    Start,
    /// Both neighbours above, reflex.
    Split,
    /// Both neighbours below, convex.
    End,
    /// Both neighbours below, reflex.
    Merge,
    /// Regular; the boundary runs downward through it (interior east).
    Downward,
    /// Regular; the boundary runs upward through it (interior west).
    Upward,
}

impl Kind {
    /// The kind of vertex `v` with previous neighbour `p` and next neighbour `n`.
    fn of<P: SweepPoint>(p: P, v: P, n: P) -> Kind {
        let hv = height(v);
        let convex = left(p, v, n); // never 0 at a local extremum: that would be a spike
        match (height(p) > hv, height(n) > hv) {
            (true, true) if convex => Kind::Start,
            (true, true) => Kind::Split,
            (false, false) if convex => Kind::End,
            (false, false) => Kind::Merge,
            (true, false) => Kind::Downward,
            (false, true) => Kind::Upward,
        }
    }
}

/// An edge in the sweep status, or a probe for a point (`lo == hi`, `edge == PROBE`): `lo` below
/// `hi` in the height order; `edge` is the index of the edge's first vertex along the cycle.
#[derive(Clone, Copy, Debug)]
struct Cut<P> {
    lo: P,
    hi: P,
    edge: usize,
}

/// The `edge` of a probe.
const PROBE: usize = usize::MAX;

impl<P: SweepPoint> Cut<P> {
    /// The cut of edge `edge` from `a` to `b`.
    fn new(a: P, b: P, edge: usize) -> Cut<P> {
        if height(a) < height(b) {
            Cut { lo: a, hi: b, edge }
        } else {
            Cut { lo: b, hi: a, edge }
        }
    }

    /// A probe at `v`.
    fn probe(v: P) -> Cut<P> {
        Cut {
            lo: v,
            hi: v,
            edge: PROBE,
        }
    }
}

impl<P: SweepPoint> PartialEq for Cut<P> {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl<P: SweepPoint> Eq for Cut<P> {}

impl<P: SweepPoint> PartialOrd for Cut<P> {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl<P: SweepPoint> Ord for Cut<P> {
    /// West (`Less`) to east at the current sweep position, for disjoint edges both cut by the
    /// sweep line, or an edge and a probe at a point strictly inside its height span and not on it
    /// (the only pairs a set ever compares, see the module documentation): test the later-starting
    /// one's lower end against the earlier-starting edge.
    fn cmp(&self, other: &Self) -> Ordering {
        if self.edge == other.edge {
            return Ordering::Equal;
        }
        let (first, second, flipped) = if height(self.lo) <= height(other.lo) {
            (self, other, false)
        } else {
            (other, self, true)
        };
        // `second.lo` west of `first` (cross > 0) means `first` is Greater.
        let first_vs_second = match P::orient(first.lo, first.hi, second.lo) {
            Ordering::Greater => Ordering::Greater,
            Ordering::Less => Ordering::Less,
            Ordering::Equal => first.edge.cmp(&second.edge), // only for invalid input
        };
        if flipped {
            first_vs_second.reverse()
        } else {
            first_vs_second
        }
    }
}

/// The state of the monotone-decomposition sweep.
struct Sweep<'a, P: SweepPoint> {
    pts: &'a [P],
    links: &'a Links,
    kind: Vec<Kind>,
    status: Status<Cut<P>>,
    /// The status handle of every edge `e` in the status.
    handle: Vec<Option<Handle>>,
    /// `helper[e]` for every edge `e` in the status.
    helper: Vec<usize>,
    diagonals: Vec<[usize; 2]>,
}

impl<'a, P: SweepPoint> Sweep<'a, P> {
    /// The diagonals splitting the polygon into monotone pieces (proper, pairwise
    /// non-crossing, none repeated); `None` on input outside the contract where it shows.
    fn run(pts: &'a [P], links: &'a Links) -> Option<Vec<[usize; 2]>> {
        let n = pts.len();
        let kind = (0..n)
            .map(|v| Kind::of(pts[links.prev[v]], pts[v], pts[links.next[v]]))
            .collect();
        let mut sweep = Sweep {
            pts,
            links,
            kind,
            status: Status::new(),
            handle: vec![None; n],
            helper: vec![usize::MAX; n],
            diagonals: Vec::new(),
        };
        let mut order: Vec<usize> = (0..n).collect();
        order.sort_unstable_by_key(|&v| height(pts[v]));
        // Equal points would make the angular sort of `pieces` inconsistent.
        if order.windows(2).any(|w| pts[w[0]] == pts[w[1]]) {
            return None;
        }
        for v in order {
            sweep.event(v)?;
        }
        sweep.status.is_empty().then_some(sweep.diagonals)
    }

    fn cut(&self, e: usize) -> Cut<P> {
        Cut::new(self.pts[e], self.pts[self.links.next[e]], e)
    }

    /// Processes vertex `v` (see the action table of the module documentation); `None` when an
    /// invariant breaks (input outside the contract).
    fn event(&mut self, v: usize) -> Option<()> {
        let p = self.links.prev[v];
        match self.kind[v] {
            Kind::Start => self.insert(p, v),
            Kind::End => self.finish(v, v),
            Kind::Split => {
                let e = self.west_of(v)?;
                self.diagonals.push([v, self.helper[e]]);
                self.helper[e] = v;
                self.insert(p, v)
            }
            Kind::Merge => {
                self.finish(v, v)?;
                let e = self.west_of(v)?;
                self.replace_helper(e, v)
            }
            Kind::Downward => {
                self.finish(v, v)?;
                self.insert(p, v)
            }
            Kind::Upward => {
                let e = self.west_of(v)?;
                self.replace_helper(e, v)
            }
        }
    }

    /// Inserts edge `e` with helper `v` (`None` if it is in the status already).
    fn insert(&mut self, e: usize, v: usize) -> Option<()> {
        if self.handle[e].is_some() {
            return None;
        }
        self.helper[e] = v;
        self.handle[e] = Some(self.status.insert(self.cut(e)));
        Some(())
    }

    /// Removes edge `e`, which ends at `v`, adding the diagonal to its helper if that is a merge
    /// vertex (`None` if it is not in the status).
    fn finish(&mut self, e: usize, v: usize) -> Option<()> {
        let h = self.handle[e].take()?;
        self.replace_helper(e, v)?;
        self.status.remove(h);
        Some(())
    }

    /// Makes `v` the helper of `e`, adding the diagonal to the old helper if it is a merge vertex
    /// (`None` if `e` has no helper: it never entered the status).
    fn replace_helper(&mut self, e: usize, v: usize) -> Option<()> {
        let h = self.helper[e];
        if *self.kind.get(h)? == Kind::Merge {
            self.diagonals.push([v, h]);
        }
        self.helper[e] = v;
        Some(())
    }

    /// The status edge immediately west of vertex `v`, which exists whenever the interior lies
    /// west of `v` (split, merge and upward vertices).
    fn west_of(&self, v: usize) -> Option<usize> {
        let west = self.status.below(&Cut::probe(self.pts[v]))?;
        Some(self.status.key(west).edge)
    }
}

/// The pieces cut out of the polygon by `diagonals` (proper, pairwise non-crossing, connecting
/// the rings without cut vertex, see "Holes" in the module documentation): all their vertex
/// cycles, counter-clockwise, concatenated, and the start of each (plus the end). `None` when a
/// half-edge would lie on two pieces (input outside the contract). The walk cannot fail
/// otherwise: `twin` pairs first slots with last ones and diagonal slots with diagonal ones,
/// so from a slot that is not a vertex's last, `twin[h] - 1` is again one (and at least 0),
/// whatever the geometry.
fn pieces<P: SweepPoint>(
    pts: &[P],
    links: &Links,
    diagonals: &[[usize; 2]],
) -> Option<(Vec<usize>, Vec<usize>)> {
    let n = pts.len();
    let next = |i: usize| links.next[i];
    let prev = |i: usize| links.prev[i];
    // Adjacency lists: `start[v]..start[v + 1]` holds next(v), the diagonal ends sorted
    // counter-clockwise, prev(v). A slot is also the half-edge from `v` to the neighbour there.
    let mut start = vec![0usize; n + 1];
    for v in 0..n {
        start[v + 1] = 2;
    }
    for &[a, b] in diagonals {
        start[a + 1] += 1;
        start[b + 1] += 1;
    }
    for v in 0..n {
        start[v + 1] += start[v];
    }
    let slots = start[n];
    let mut to = vec![0usize; slots];
    // `label`: for a diagonal slot, 2 d + (0 from a, 1 from b); to find twins after sorting.
    let mut fill: Vec<usize> = start[..n].iter().map(|s| s + 1).collect();
    let mut middle: Vec<(usize, usize)> = vec![(0, 0); slots];
    for (d, &[a, b]) in diagonals.iter().enumerate() {
        middle[fill[a]] = (b, 2 * d);
        fill[a] += 1;
        middle[fill[b]] = (a, 2 * d + 1);
        fill[b] += 1;
    }
    let mut slot_of_label = vec![0usize; 2 * diagonals.len()];
    for v in 0..n {
        let (lo, hi) = (start[v], start[v + 1]);
        to[lo] = next(v);
        to[hi - 1] = prev(v);
        let w = pts[v];
        let reference = pts[next(v)];
        let part = &mut middle[lo + 1..hi - 1];
        if part.len() > 1 {
            part.sort_unstable_by(|&(a, _), &(b, _)| around(w, reference, pts[a], pts[b]));
        }
        for (k, &(x, label)) in part.iter().enumerate() {
            to[lo + 1 + k] = x;
            slot_of_label[label] = lo + 1 + k;
        }
    }
    drop(middle);
    let mut twin = vec![0usize; slots];
    for v in 0..n {
        twin[start[v]] = start[next(v) + 1] - 1; // v -> next(v) against next(v) -> v (its last)
        twin[start[v + 1] - 1] = start[prev(v)]; // v -> prev(v) against prev(v) -> v (its first)
    }
    for pair in slot_of_label.chunks_exact(2) {
        twin[pair[0]] = pair[1];
        twin[pair[1]] = pair[0];
    }
    // Walk every interior half-edge (all but the last slot of each vertex, v -> prev(v)).
    let mut used = vec![false; slots];
    let mut vertices = Vec::with_capacity(n + 2 * diagonals.len());
    let mut starts = vec![0];
    for v in 0..n {
        for first in start[v]..start[v + 1] - 1 {
            if used[first] {
                continue;
            }
            let (mut h, mut w) = (first, v);
            loop {
                if used[h] {
                    return None; // a half-edge on two pieces
                }
                used[h] = true;
                vertices.push(w);
                // At x = to[h], the twin is x -> w; the next half-edge is the slot before it.
                w = to[h];
                h = twin[h] - 1;
                if h == first {
                    break;
                }
            }
            starts.push(vertices.len());
        }
    }
    Some((vertices, starts))
}

/// Counter-clockwise order of the directions from `w` to `a` and to `b`, measured from the
/// direction of `reference` (exact: the half-plane first, then the turn). Directions must differ.
fn around<P: SweepPoint>(w: P, reference: P, a: P, b: P) -> Ordering {
    let half = |q: P| {
        let c = P::orient(w, reference, q);
        usize::from(
            !(c == Ordering::Greater || (c == Ordering::Equal && P::same_side(w, reference, q))),
        )
    };
    half(a)
        .cmp(&half(b))
        .then_with(|| P::orient(w, a, b).reverse())
}

/// The chain a vertex of a monotone piece lies on, seen from above.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Chain {
    /// The chain from the top down to the bottom along the cycle (interior east).
    West,
    /// The chain from the bottom up to the top along the cycle (interior west).
    East,
}

/// Scratch space reused across pieces.
#[derive(Default)]
struct Work {
    sorted: Vec<(usize, Chain)>,
    stack: Vec<(usize, Chain)>,
}

/// Triangulates a monotone piece (a counter-clockwise cycle of indices into `pts`, monotone in
/// the height order, flat vertices allowed) into `cycle.len() - 2` positive triangles, appended to
/// `out` (the stack algorithm; see the module documentation for the proof). `None` if the piece
/// has fewer than 3 vertices, is not monotone, or a triangle would not be positive (input
/// outside the contract).
fn triangulate_monotone<P: SweepPoint>(
    pts: &[P],
    cycle: &[usize],
    work: &mut Work,
    out: &mut Vec<[usize; 3]>,
) -> Option<()> {
    let m = cycle.len();
    if m < 3 {
        return None;
    }
    let h = |k: usize| height(pts[cycle[k]]);
    let (mut top, mut bottom) = (0, 0);
    for k in 1..m {
        if h(k) > h(top) {
            top = k;
        }
        if h(k) < h(bottom) {
            bottom = k;
        }
    }
    // Merge the two chains, both descending from the top, into one descending order.
    let sorted = &mut work.sorted;
    sorted.clear();
    sorted.push((cycle[top], Chain::West)); // the top's chain is never consulted
    let (mut west, mut east) = ((top + 1) % m, (top + m - 1) % m);
    while west != bottom || east != bottom {
        let take_west = east == bottom || (west != bottom && h(west) > h(east));
        if take_west {
            sorted.push((cycle[west], Chain::West));
            let step = (west + 1) % m;
            if h(step) >= h(west) {
                return None; // not monotone
            }
            west = step;
        } else {
            sorted.push((cycle[east], Chain::East));
            let step = (east + m - 1) % m;
            if h(step) >= h(east) {
                return None; // not monotone
            }
            east = step;
        }
    }
    sorted.push((cycle[bottom], Chain::West)); // the bottom's chain is never consulted
    let stack = &mut work.stack;
    stack.clear();
    stack.extend_from_slice(&sorted[..2]);
    for &(u, chain) in &sorted[2..m - 1] {
        let top_chain = stack[stack.len() - 1].1;
        if chain != top_chain {
            fan(pts, stack, u, top_chain, out)?;
            let last = stack[stack.len() - 1];
            stack.clear();
            stack.push(last);
        } else {
            while stack.len() >= 2 {
                let (s, r) = (stack[stack.len() - 1].0, stack[stack.len() - 2].0);
                let t = match chain {
                    Chain::West => [r, s, u],
                    Chain::East => [u, s, r],
                };
                // Strictly convex only: a collinear triple waits like a reflex one.
                if left(pts[t[0]], pts[t[1]], pts[t[2]]) {
                    out.push(t);
                    stack.pop();
                } else {
                    break;
                }
            }
        }
        stack.push((u, chain));
    }
    let top_chain = stack[stack.len() - 1].1;
    fan(pts, stack, sorted[m - 1].0, top_chain, out)
}

/// The fan from `u` (below the whole stack, on the other chain or the bottom) over the stack
/// chain, whose vertices `s_1..` lie on `chain`; `None` if a triangle would not be positive
/// (input outside the contract).
fn fan<P: SweepPoint>(
    pts: &[P],
    stack: &[(usize, Chain)],
    u: usize,
    chain: Chain,
    out: &mut Vec<[usize; 3]>,
) -> Option<()> {
    for w in stack.windows(2) {
        let (a, b) = (w[0].0, w[1].0);
        let t = match chain {
            Chain::West => [a, b, u],
            Chain::East => [u, b, a],
        };
        if !left(pts[t[0]], pts[t[1]], pts[t[2]]) {
            return None;
        }
        out.push(t);
    }
    Some(())
}

#[cfg(test)]
mod tests;
