//! Visibility by triangular expansion: the vertices seen from a reflex vertex in its double cone.
//!
//! For Step 1 of MINITRI, a reflex vertex `b` matters only in the directions `d` such that both
//! `d` and `-d` lie in its closed interior angle: two closed cones `[next, -prev]` and
//! `[-next, prev]` (directions towards `b`'s neighbours and their opposites), each narrower than
//! a half-turn. In each, we need the vertices seen from `b` that are nearest in their direction.
//!
//! Method: triangular expansion over any triangulation of the polygon (F. Bungiu, M. Hemmer,
//! J. Hershberger, K. Huang, A. Kröller, "Efficient computation of visibility polygons",
//! EuroCG 2014). Around `b`, every triangle of its fan whose angle meets the cone hands the part
//! of the cone it covers through its far edge; a cone crossing an edge into the next triangle
//! either passes wholly to one side of that triangle's third vertex `x`, or `x` lies strictly
//! inside it: then `x` is seen from `b` along a segment crossing only diagonals (so along a chord
//! with no vertex inside it: `x` is the nearest vertex in its direction), and the cone splits at
//! `x`. Cones end at polygon edges. A vertex exactly on a cone's boundary ray lies behind the
//! vertex that defines that ray, so it is not the nearest one there and is skipped. The fan's own
//! vertices are seen along triangulation edges, so they are nearest in their directions too.
//!
//! Only opposite pairs of directions matter to Step 1, so the two cones are expanded together,
//! both sweeping from their upper bound down (a depth-first walk that always continues with the
//! highest part of a cone, turning the other cone by a half-turn to compare): directions above a
//! cone's highest pending part are settled, so a part of the other cone whose opposite directions
//! are all settled and hold no vertex found there is dropped, and a part reaching above the other
//! cone's highest pending part is cut down to it. In general position almost no direction has a
//! vertex on both sides, so most of the wide cone never needs walking. A part that walks far
//! while the other cone's top part shares its directions lets that part walk in turn (at 64
//! triangles from the vertex, then 128, ..): where the other side ends sooner, the far walk is
//! cut short (a TIGER state boundary of long, almost straight lines: -17% time in all).
//!
//! The walk runs over the plain triangulation as a half-edge [`Mesh`] (the one of `algo/mesh.rs`,
//! each vertex's boundary half-edge starting its fan), made fatter by edge flips towards the
//! constrained Delaunay triangulation ([`Mesh::flip_towards_delaunay`]): rays then cross far
//! fewer triangles than the long slivers of a monotone triangulation.
//!
//! Every decision is an exact sign of a cross product of two [`Dir`]s; the only floating point
//! (which diagonals to flip) affects the running time, never what is found.
//! Complexity: O(n) to build the mesh, at most `max_flips` O(1) flips, then per vertex work
//! proportional to the triangles met by the parts of its cones still alive (an O(1) pruning test
//! for each part taken from the stacks, none for the triangles a part crosses whole, see
//! [`double_cone`]): O(n) per vertex, so O(n^2) in the worst case, but far less
//! on typical polygons. Measured on random star polygons (the `bench/polygon.py star` family),
//! after the flips: about 37 states per vertex at 10^4 vertices, 42 at 10^5, 48 at 10^6 (before the
//! flips and the pairing of the cones: 210 at 10^4, 560 at 10^5); on the `bars` family (a corridor
//! the length of the polygon, Theta(n^2) visible pairs), about 10 states per vertex on the mesh
//! swept along the corridor (`crate::algo::plain::polygon`).

use super::ray_shooting::{Lazy, RAY_WALK};
pub use crate::algo::mesh::Mesh;
use crate::geom::kernel::Coord;
use crate::geom::kernel::Dir;
use crate::geom::polygon::Polygon;

/// A cone of directions from `lo` counter-clockwise to `hi` (narrower than a half-turn); a bound
/// marked `_in` is not defined by a vertex, so a vertex exactly on it is seen.
#[derive(Clone, Copy, Debug)]
struct Cone<P: Coord> {
    lo: Dir<P>,
    hi: Dir<P>,
    lo_in: bool,
    hi_in: bool,
}

impl<P: Coord> Cone<P> {
    /// The zero-width part at direction `d` (both ends included).
    fn at(d: Dir<P>) -> Cone<P> {
        Cone {
            lo: d,
            hi: d,
            lo_in: true,
            hi_in: true,
        }
    }

    /// The same directions turned by a half-turn (the other cone's view of them).
    fn reversed(self) -> Cone<P> {
        Cone {
            lo: self.lo.reversed(),
            hi: self.hi.reversed(),
            ..self
        }
    }

    /// Whether every direction of `self` lies below every direction of `other` (an end shared
    /// by both is common to them only if both include it). Both parts in one cone.
    fn wholly_below(self, other: Cone<P>) -> bool {
        let c = other.lo.cross(self.hi);
        c < 0 || (c == 0 && !(other.lo_in && self.hi_in))
    }

    /// Whether `self` and `other` (in the same cone) share a direction.
    fn meets(self, other: Cone<P>) -> bool {
        !self.wholly_below(other) && !other.wholly_below(self)
    }

    /// Whether direction `d` (in the same cone) lies in `self`, ends as flagged.
    fn holds(self, d: Dir<P>) -> bool {
        self.holds_given(d, self.lo.cross(d))
    }

    /// [`Cone::holds`] with `right = lo x d` computed already (the walk needs it again).
    fn holds_given(self, d: Dir<P>, right: i128) -> bool {
        let left = d.cross(self.hi);
        (right > 0 || (right == 0 && self.lo_in)) && (left > 0 || (left == 0 && self.hi_in))
    }
}

/// A vertex seen from the searching vertex `b`, with its direction from `b`.
pub type Sighting<P = crate::geom::kernel::Point> = (Dir<P>, usize);

/// What a part of a cone on the stack stands for.
#[derive(Clone, Copy, Debug)]
enum Step {
    /// Enter the triangle of this half-edge `w -> u` (`w` on the left seen from `b`).
    Enter(usize),
    /// Record this vertex, found in the direction of the (zero-width) part.
    Found(usize),
}

/// Reusable buffers for [`double_cone`], so that searching from many vertices allocates once.
pub struct Workspace<P: Coord> {
    /// The fan around `b`: its vertices `u_0 = next(b), .., u_m = prev(b)` counter-clockwise,
    /// with their directions from `b`.
    fan: Vec<Sighting<P>>,
    /// For each fan triangle `b u_i u_(i+1)`, its far side: the half-edge `u_i -> u_(i+1)`.
    far_sides: Vec<usize>,
    /// Per cone: the parts still to expand, disjoint and sorted by angle (the highest on top),
    /// each with what to do with it.
    stacks: [Vec<(Step, Cone<P>)>; 2],
    /// Per cone: the vertices found with their directions from `b`, by decreasing angle while
    /// searching, by increasing angle when handed out.
    found: [Vec<Sighting<P>>; 2],
    /// The rays a part is cut into ([`isolated`]), by decreasing angle.
    rays: Vec<Dir<P>>,
}

impl<P: Coord> Default for Workspace<P> {
    fn default() -> Self {
        Workspace {
            fan: Vec::new(),
            far_sides: Vec::new(),
            stacks: [Vec::new(), Vec::new()],
            found: [Vec::new(), Vec::new()],
            rays: Vec::new(),
        }
    }
}

/// The vertices found in the two cones of [`double_cone`], each sorted by angle.
pub type Cones<'w, P> = (&'w [Sighting<P>], &'w [Sighting<P>]);

/// The vertices seen from reflex vertex `b` that are nearest in their direction, in the two
/// cones of its double wedge: `(cone [next, -prev], cone [-next, prev])`, each sorted by angle,
/// with their directions from `b`; `None` if the walk went over the budget of `shooter`
/// ([`Lazy::budget`]: triangles crossed by parts of non-zero width).
///
/// Only directions `d` whose opposite `-d` is found in the other cone matter to the caller, so
/// the lists may omit other vertices: the two cones sweep down together (see the module doc),
/// and a part of one cone is dropped as soon as no direction in it (its ends counted only where
/// they belong to it) has its opposite in a pending part of the other cone or at a vertex found
/// there. On polygons where one side of `b` is a narrow pocket, this turns the expansion of the
/// wide side into a few ray walks. An end that belongs to a part is one not defined by a vertex:
/// a part bounded by the ray through a vertex `x` (beyond `x`) cannot find anything on that ray,
/// and counting that ray would keep alive, all along a corridor, a part hugging a wall whose
/// vertex opposite is `b`'s own neighbour (the `bars` benchmark; figures in docs/benchmarks.md).
///
/// The sweep: every part on either stack is a range of directions, the vertices of the fan
/// around `b` are zero-width parts among them, and each round pops the part reaching highest
/// over both cones (the other cone's directions turned by a half-turn). So parts are popped,
/// and vertices found, in decreasing angle in each cone, and a popped part lies above or at
/// everything pending in the other cone and below or at everything found there: whether the
/// other cone still has a pending part or a found vertex opposite it is read off the top of
/// its stack and the end of its list, in O(1) (the loops below step over at most a part or a
/// vertex sharing an end; `debug_assertions` builds check this against a search of the whole
/// stack and list). A part that crosses a triangle wholly on one side of its apex walks on into
/// the next one without going back to the stack: it is still the highest part, and nothing
/// changed in the other cone (most of the triangles walked on random stars: docs/benchmarks.md).
/// After a turn (a long walk stopped to let the other cone walk, see the body) that order holds
/// within each cone only: the lookups stay exact (they search sorted lists, stepping over more
/// entries), and the cutting of parts into rays then reads every vertex found opposite a part.
pub fn double_cone<'w, P: Coord>(
    polygon: &Polygon<P>,
    mesh: &Mesh,
    b: usize,
    work: &'w mut Workspace<P>,
    shooter: &Lazy,
    budget: usize,
) -> Option<Cones<'w, P>> {
    let c = polygon.point(b);
    let dir = |v: usize| Dir::between(c, polygon.point(v));
    let (to_next, to_prev) = (dir(polygon.next(b)), dir(polygon.prev(b)));
    // The bounds towards next(b) and prev(b) are defined by those vertices (anything behind them
    // is not nearest); the opposite bounds are not, so a vertex exactly on them counts.
    let cones = [
        Cone {
            lo: to_next,
            hi: to_prev.reversed(),
            lo_in: false,
            hi_in: true,
        },
        Cone {
            lo: to_next.reversed(),
            hi: to_prev,
            lo_in: true,
            hi_in: false,
        },
    ];
    let Workspace {
        fan,
        far_sides,
        stacks,
        found,
        rays,
    } = work;
    // The fan around b, counter-clockwise from the edge to next(b) to the edge from prev(b):
    // its vertices u_0 = next(b), .., u_m = prev(b) by increasing angle (from 0 to b's interior
    // angle, more than a half-turn), and the far side of each of its triangles.
    fan.clear();
    far_sides.clear();
    fan.push((to_next, polygon.next(b)));
    // From the boundary half-edge b -> next(b), across each side w -> b to b -> w.
    for h in mesh.out(b).into_iter().flat_map(|h| mesh.fan(h)) {
        let w = mesh.apex(h);
        fan.push((dir(w), w));
        far_sides.push(Mesh::next_in_triangle(h));
    }
    for (side, cone) in cones.iter().enumerate() {
        found[side].clear();
        let stack = &mut stacks[side];
        stack.clear();
        // Where each fan vertex lies against the closed cone: -1 below, 0 inside, 1 above. The
        // cone is [0, a - pi] (side 0) or [pi, a] (side 1) in angles from next(b), a the
        // interior angle; the fan's angles run from 0 to a.
        let start = cone.lo; // next(b) or its opposite
        let place = |d: Dir<P>| -> i8 {
            let s = start.cross(d);
            let from_start = s > 0 || (s == 0 && start.dot(d) > 0);
            if !from_start {
                // Angles in [pi, 2 pi) from `start`: side 0's fan vertices there are above its
                // cone (which ends before pi), side 1's are below pi.
                if side == 0 {
                    1
                } else {
                    -1
                }
            } else if d.cross(cone.hi) >= 0 {
                0
            } else {
                1
            }
        };
        let mut before = place(fan[0].0);
        if before == 0 {
            stack.push((Step::Found(fan[0].1), Cone::at(fan[0].0)));
        }
        for (i, &far) in far_sides.iter().enumerate() {
            let ((du, _), (dw, w)) = (fan[i], fan[i + 1]);
            let after = place(dw);
            if before <= 0 && after >= 0 {
                // The part of the cone inside this fan triangle's angle; a bound taken from u
                // or w is defined by a vertex.
                let (lo, lo_in) = if before < 0 {
                    (cone.lo, cone.lo_in)
                } else {
                    (du, false)
                };
                let (hi, hi_in) = if after > 0 {
                    (cone.hi, cone.hi_in)
                } else {
                    (dw, false)
                };
                let part = Cone {
                    lo,
                    hi,
                    lo_in,
                    hi_in,
                };
                enter(stack, mesh, far, part);
            }
            if after == 0 {
                stack.push((Step::Found(w), Cone::at(dw)));
            }
            before = after;
        }
    }
    // Triangles walked from b so far: parts are cut into rays only past `isolate_after`
    // (ISOLATE_AFTER in the default hybrid).
    let mut crossed: usize = 0;
    let isolate_after = shooter.isolate_after();
    // Past the budget the walk gives up (`None`). The budget counts the triangles crossed by
    // parts of non-zero width: `give_up_at` moves up by the triangles rays walk (their walking
    // is bounded by the shooter's policy instead). One test in the loop for both thresholds.
    let mut give_up_at = budget.saturating_add(1);
    // Turns: when the walk from b reaches `yield_at` triangles, the wide part walking on goes
    // back to its stack and the other cone walks next if its top part shares directions with
    // it (turned by a half-turn); the next such moment is twice as far. Without turns a part
    // reaching higher walks its whole length first, even where the other cone's opposite part
    // would end at a polygon edge within a few triangles and settle those directions empty (on
    // a state boundary of long, almost straight lines, parts crossing the whole polygon); with
    // them such a part is pruned or cut into rays once the other cone has walked. Each cone
    // still sweeps down in angle, so what the pruning reads stays exact; only the cones' order
    // changes.
    let mut yield_at = FIRST_QUOTA;
    let next_check = |crossed: usize, give_up_at: usize, yield_at: usize| {
        let at = if crossed < isolate_after {
            isolate_after.min(give_up_at)
        } else {
            give_up_at
        };
        at.min(yield_at).max(crossed + 1)
    };
    let mut check_at = next_check(0, give_up_at, yield_at);
    // The cone whose turn it is, if any.
    let mut turn: Option<usize> = None;
    loop {
        // Expand the cone whose top part reaches higher (comparing the other cone's directions
        // turned by a half-turn), so that both sweep down together; or the other cone, whose
        // turn it is.
        let side = match (stacks[0].last(), stacks[1].last()) {
            (None, None) => break,
            (Some(_), None) => 0,
            (None, Some(_)) => 1,
            (Some(s), Some(t)) => {
                let higher = usize::from(s.1.hi.cross(t.1.hi.reversed()) > 0);
                match turn.take() {
                    Some(side) if side != higher && s.1.meets(t.1.reversed()) => {
                        #[cfg(test)]
                        TURNS.with(|t| t.set(t.get() + 1));
                        side
                    }
                    _ => higher,
                }
            }
        };
        let Some((step, mut cone)) = stacks[side].pop() else {
            break; // not reached: the chosen cone has a part
        };
        // A direction matters only if its opposite may still be found in the other cone: in a
        // part on the other stack, or at a vertex found there.
        let other = 1 - side;
        let opposite = cone.reversed();
        let (parts, seen) = (&stacks[other], &found[other]);
        if !pending_in(parts, opposite) && !found_in(seen, opposite) {
            continue;
        }
        // Once the walk from b has crossed `isolate_after` triangles: where the other cone holds
        // only isolated directions opposite this part (vertices found there, zero-width parts
        // still pending), and no wide part, the part becomes a few rays.
        if let (Step::Enter(g), true) = (step, crossed >= isolate_after) {
            if isolated(parts, seen, cone, rays) {
                // The rays by increasing angle, the highest on top.
                for &d in rays.iter().rev() {
                    stacks[side].push((Step::Enter(g), Cone::at(d)));
                }
                continue;
            }
        }
        // Above the other cone's top part, only the directions of vertices found there matter:
        // if there are none, the part narrows down to that top part's upper bound (a bound not
        // defined by a vertex, strictly inside the part).
        if let Some(top) = parts.last() {
            let f = top.1.hi.reversed();
            if cone.lo.cross(f) > 0
                && f.cross(cone.hi) > 0
                && !found_in(
                    seen,
                    Cone {
                        lo: top.1.hi,
                        lo_in: true,
                        ..opposite
                    },
                )
            {
                cone.hi = f;
                cone.hi_in = true;
            }
        }
        let mut g = match step {
            Step::Found(x) => {
                found[side].push((cone.lo, x));
                continue;
            }
            Step::Enter(g) => g,
        };
        // Walk on while the whole part passes one side of the entered triangle's apex: the other
        // cone is unchanged, so the tests above would give the same answer again (no push and
        // pop for each triangle crossed).
        let stack = &mut stacks[side];
        // A ray (zero-width part) walks RAY_WALK triangles at a time; past that, once long
        // walks have cost enough in all, it is shot over heavy paths instead (`ray_shooting`).
        let ray = cone.lo.cross(cone.hi) == 0;
        let (mut walked, mut ask) = (0, shooter.first_ask());
        loop {
            if ray && walked >= ask {
                ask = walked.saturating_add(RAY_WALK);
                if let Some(shot) = shooter.get(polygon, mesh, RAY_WALK) {
                    if let Some(x) = shot.shoot(polygon, mesh, b, cone.lo, g) {
                        stack.push((Step::Found(x), Cone::at(dir(x))));
                    }
                    // A shot costs O(log^2 n): it counts against the budget as log2 n
                    // triangles, so a vertex shoots O(1) rays before it is given up.
                    give_up_at = give_up_at.saturating_sub(shooter.shot_cost());
                    break;
                }
            }
            walked += 1;
            crossed += 1;
            if crossed >= check_at {
                if !ray && crossed >= give_up_at {
                    return None;
                }
                let yielding = crossed >= yield_at;
                if yielding {
                    yield_at = crossed.saturating_mul(2);
                }
                check_at = next_check(crossed, give_up_at, yield_at);
                if !ray && (yielding || crossed == isolate_after) {
                    // Back to the stack: at a turn, the other cone walks next if its top part
                    // shares directions with this one; else it is taken again at once, to be
                    // cut into rays if it can.
                    if yielding {
                        turn = Some(other);
                    }
                    stack.push((Step::Enter(g), cone));
                    break;
                }
            }
            // The entered triangle has the half-edge g = w -> u; its apex x follows u.
            let (x, k_ux, k_xw) = mesh.apex_and_sides(g);
            let dx = dir(x);
            let right = cone.lo.cross(dx);
            let through = if cone.holds_given(dx, right) {
                enter(
                    stack,
                    mesh,
                    k_ux,
                    Cone {
                        hi: dx,
                        hi_in: false,
                        ..cone
                    },
                );
                // x is recorded once every direction above it is settled: by a zero-width part
                // between the two halves.
                stack.push((Step::Found(x), Cone::at(dx)));
                enter(
                    stack,
                    mesh,
                    k_xw,
                    Cone {
                        lo: dx,
                        lo_in: false,
                        ..cone
                    },
                );
                break;
            } else if right <= 0 {
                k_xw // the whole cone passes right of x: through x -> w
            } else {
                k_ux // through u -> x
            };
            match mesh.twin_of(through) {
                None => break, // the part ends at a polygon edge
                Some(next) => g = next,
            }
        }
        if ray {
            give_up_at = give_up_at.saturating_add(walked);
            if crossed >= give_up_at {
                return None;
            }
            check_at = next_check(crossed, give_up_at, yield_at);
        }
    }
    for list in found.iter_mut() {
        list.reverse();
        debug_assert!(list.windows(2).all(|w| w[0].0.cross(w[1].0) > 0));
    }
    let [first, second] = found;
    Some((first, second))
}

/// How many triangles the walk from one vertex crosses before its parts are cut into rays
/// (`isolated`) in the default hybrid (`super::ray_shooting::RayPolicy`): typical vertices never get there (random stars walk 40-50 triangles per
/// vertex), so they keep the plain walk, which is cheaper when cones are short; a vertex of a
/// comb's floor or a sliver's staircase does, and its remaining parts become a few rays.
pub const ISOLATE_AFTER: usize = 64;

/// The most rays a part is cut into by [`isolated`]; with more, it is walked whole.
const MAX_RAYS: usize = 16;

/// The triangles walked from a vertex before a wide part walking on first lets the other cone
/// take its turn (then at twice as many, and so on; see [`double_cone`]). Typical vertices
/// never get there (random stars walk 40-50 triangles per vertex); 64 measured best among
/// 8-1024 (docs/benchmarks.md).
const FIRST_QUOTA: usize = 64;

// How many times a cone took its turn out of the angular order, on this thread (for tests).
#[cfg(test)]
thread_local!(pub(super) static TURNS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) });

/// Cuts a wide part `cone` of one cone (just popped) into `rays`, by decreasing angle, when the
/// other cone has nothing but isolated directions opposite it: vertices found there (`seen`, by
/// decreasing angle), zero-width parts on top of its stack (`parts`, sorted by angle, the
/// highest last: vertices waiting to be recorded, or rays), and no wide part overlapping it.
/// False (walk the part) when a wide part overlaps it (then walking the part costs less than
/// walking a few rays besides), when more than [`MAX_RAYS`] rays would be needed or more
/// zero-width parts would have to be looked at.
///
/// When the cones sweep in step, the part lies above or at everything pending in the other
/// cone and below or at everything found there (so at most one vertex found, at its upper end);
/// after a turn ([`double_cone`]) vertices found inside it come first.
///
/// Exact: the directions are those of vertices, compared by cross product signs. A ray walked
/// from the part's entry side finds the nearest vertex exactly on it, as the part would have
/// (a zero-width part is a part like any other for the walk); the walk of the rest of the part
/// is skipped, and with it the triangles crossed only by directions whose opposite holds no
/// vertex (on a comb whose gap floors lie on one line, every reflex vertex walked half the
/// polygon's base before).
fn isolated<P: Coord>(
    parts: &[(Step, Cone<P>)],
    seen: &[Sighting<P>],
    cone: Cone<P>,
    rays: &mut Vec<Dir<P>>,
) -> bool {
    rays.clear();
    if cone.lo.cross(cone.hi) <= 0 {
        return false; // already a ray
    }
    // Adds `d`, at or below those already in (a repeat of the last is skipped); false if full.
    let add = |rays: &mut Vec<Dir<P>>, d: Dir<P>| {
        if rays.last().is_some_and(|r| r.cross(d) == 0) {
            return true;
        }
        rays.push(d);
        rays.len() <= MAX_RAYS
    };
    // The vertices found opposite the part: the last of the list that are not below it (when
    // the cones sweep in step, at most one, at the part's upper end).
    let opposite = cone.reversed();
    let below = seen
        .iter()
        .rev()
        .take_while(|&&(d, _)| Cone::at(d).wholly_below(opposite))
        .count();
    let rest = &seen[..seen.len() - below];
    let inside = rest
        .iter()
        .rev()
        .take(MAX_RAYS + 1)
        .take_while(|&&(d, _)| opposite.holds(d))
        .count();
    for &(d, _) in &rest[rest.len() - inside..] {
        if !add(rays, d.reversed()) {
            return false;
        }
    }
    // The zero-width parts on top of the other stack, from the top down: at most MAX_RAYS + 1
    // looked at, so that each part taken costs O(1) more (a stack topped by many vertices
    // waiting to be recorded is left to the walk).
    let mut k = parts.len();
    while k > 0 {
        let part = parts[k - 1].1;
        if part.lo.cross(part.hi) != 0 {
            break;
        }
        if parts.len() - k > MAX_RAYS {
            return false;
        }
        k -= 1;
        let d = part.lo.reversed();
        if cone.holds(d) {
            if !add(rays, d) {
                return false;
            }
        } else if cone.lo.cross(d) <= 0 {
            // At or below the part's lower end: so is everything further down.
            return true;
        }
    }
    // The highest wide part left, if any.
    let Some(wide) = k.checked_sub(1).map(|k| parts[k].1) else {
        return true;
    };
    let f = wide.hi.reversed();
    if f.cross(cone.hi) <= 0 {
        return false; // the wide part reaches the part's upper end: nothing to cut
    }
    let low = cone.lo.cross(f);
    if low < 0 {
        return true; // the wide part lies wholly below the part
    }
    if low == 0 {
        // The two meet at the part's lower end only: a ray there if both include it.
        return !(cone.lo_in && wide.hi_in) || add(rays, cone.lo);
    }
    // A wide part overlapping this one: the walk of the range would stay, and walking a few
    // rays besides costs more than it saves (measured on random stars and corridors).
    false
}

/// Whether a part of `parts` (disjoint, sorted by angle, the highest last) shares a direction
/// with `range`. Stepping down from the top: parts wholly above `range` are skipped (at most
/// one, sharing an end not included by both, since the part popped lies above or at all pending
/// ones), then the first one not wholly above decides.
fn pending_in<P: Coord>(parts: &[(Step, Cone<P>)], range: Cone<P>) -> bool {
    let answer = parts
        .iter()
        .rev()
        .find(|(_, part)| !range.wholly_below(*part))
        .is_some_and(|(_, part)| !part.wholly_below(range));
    debug_assert_eq!(
        answer,
        parts
            .iter()
            .any(|(_, p)| p.meets(range)),
    );
    answer
}

/// Whether a vertex of `seen` (by decreasing angle) lies in `range`: stepping back from the
/// lowest, past those below `range` (at most one sharing its end, see [`double_cone`]).
fn found_in<P: Coord>(seen: &[Sighting<P>], range: Cone<P>) -> bool {
    let below = |d: Dir<P>| Cone::at(d).wholly_below(range);
    let answer = seen
        .iter()
        .rev()
        .find(|&&(d, _)| !below(d))
        .is_some_and(|&(d, _)| range.holds(d));
    debug_assert_eq!(answer, seen.iter().any(|&(d, _)| range.holds(d)));
    answer
}

/// Pushes the part of a cone that leaves a triangle through its half-edge `k`, unless that is a
/// polygon edge or the part is empty.
fn enter<P: Coord>(stack: &mut Vec<(Step, Cone<P>)>, mesh: &Mesh, k: usize, part: Cone<P>) {
    if let Some(next) = mesh.twin_of(k) {
        if part.lo.cross(part.hi) > 0 {
            stack.push((Step::Enter(next), part));
        }
    }
}
