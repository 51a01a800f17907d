use super::*;
use crate::geom::kernel::{cross, segment_contact, Point};
use crate::test_support::{raw, U_SHAPE};

fn error(rings: &[&[(i64, i64)]]) -> String {
    match Polygon::from_raw(&raw(rings)) {
        Ok(_) => "valid".to_string(),
        Err(e) => e.to_string(),
    }
}

const SQUARE: &[(i64, i64)] = &[(0, 0), (10, 0), (10, 10), (0, 10)];

#[test]
fn valid_polygons_pass() {
    assert_eq!(error(&[SQUARE]), "valid");
    assert_eq!(
        error(&[
            SQUARE,
            &[(2, 2), (4, 2), (4, 4)],
            &[(6, 6), (8, 6), (8, 8), (6, 8)]
        ]),
        "valid"
    );
    // Flat vertices and vertical edges.
    assert_eq!(
        error(&[&[
            (0, 0),
            (1, 0),
            (2, 0),
            (2, 1),
            (2, 2),
            (1, 2),
            (1, 1),
            (0, 1)
        ]]),
        "valid"
    );
    // The U-shape of the README.
    assert_eq!(error(&[&U_SHAPE]), "valid");
    let (p, _) = Polygon::from_raw(&raw(&[SQUARE, &[(2, 2), (2, 4), (4, 4)]])).unwrap();
    p.check_invariants();
}

#[test]
fn bowtie_is_a_self_intersection() {
    assert_eq!(
        error(&[&[(0, 0), (2, 2), (2, 0), (0, 2)]]),
        "self-intersection: outer ring edge 2-3 (2, 0)-(0, 2) crosses outer ring edge 0-1 (0, 0)-(2, 2) near (1, 1)"
    );
    let e = error(&[&[(0, 0), (4, 0), (0, 3), (4, 3)]]);
    assert!(
        e.starts_with("self-intersection: outer ring edge 1-2 (4, 0)-(0, 3) crosses"),
        "{e}"
    );
}

#[test]
fn a_vertex_on_an_edge_is_self_touching() {
    let e = error(&[&[(0, 0), (4, 0), (4, 4), (2, 0), (0, 4)]]);
    assert!(e.starts_with("self-touching: outer ring edge"), "{e}");
    assert!(
        e.ends_with("at vertex 3 (2, 0); --repair splits the ring there"),
        "{e}"
    );
}

#[test]
fn repeated_vertices_are_named() {
    // A figure eight through (2, 2), visited twice.
    let e = error(&[&[(0, 0), (2, 2), (4, 0), (4, 4), (2, 2), (0, 4)]]);
    assert_eq!(
        e,
        "outer ring vertex 1 and outer ring vertex 4 are both at (2, 2): the ring touches itself; --repair splits it there"
    );
    // Rings of different rings at one point touch, which OGC allows (`geom::touch`); twice
    // between the same two rings, they cut the interior in two.
    let e = error(&[SQUARE, &[(0, 0), (3, 1), (10, 10), (1, 3)]]);
    assert!(
        e.starts_with("touching rings cut the interior in two: outer ring, hole 1"),
        "{e}"
    );
}

#[test]
fn spikes_are_named() {
    let e = error(&[&[(0, 0), (4, 0), (4, 4), (4, 2), (0, 4)]]);
    assert_eq!(
        e,
        "spike at outer ring vertex 2 (4, 4): edges 1-2 and 2-3 fold back onto each other; --repair removes spikes"
    );
}

#[test]
fn collinear_overlap_is_found() {
    // Two separate parts of the ring run along y = 0 over the same stretch.
    let e = error(&[&[(0, 0), (6, 0), (6, 2), (4, 2), (4, -2), (2, -2), (2, 0)]]);
    assert_ne!(e, "valid");
    let e = error(&[&[
        (0, 0),
        (6, 0),
        (6, 3),
        (5, 3),
        (5, 0),
        (4, 0),
        (4, 3),
        (0, 3),
    ]]);
    assert!(e.contains("overlap") || e.contains("touch"), "{e}");
}

#[test]
fn holes_must_lie_strictly_inside() {
    assert_eq!(
        error(&[SQUARE, &[(12, 2), (14, 2), (14, 4)]]),
        "hole 1 lies outside the outer ring"
    );
    assert_eq!(
        error(&[
            SQUARE,
            &[(1, 1), (9, 1), (9, 9), (1, 9)],
            &[(3, 3), (5, 3), (5, 5)]
        ]),
        "hole 2 lies inside hole 1 (a hole cannot contain another hole)"
    );
    // A hole touching the outer ring inside an edge is valid (OGC); poking out there is not.
    let e = error(&[SQUARE, &[(0, 5), (3, 3), (-1, 7)]]);
    assert_ne!(e, "valid");
    let e = error(&[SQUARE, &[(-1, 5), (3, 3), (3, 7)]]);
    assert!(e.starts_with("rings cross: "), "{e}");
    let e = error(&[SQUARE, &[(2, 2), (6, 2), (6, 6)], &[(4, 1), (8, 1), (8, 5)]]);
    assert!(e.starts_with("rings cross: hole"), "{e}");
    let e = error(&[&[(2, 2), (4, 2), (4, 4)], SQUARE]);
    assert!(
        e.contains("outer ring lies inside hole 1") || e.contains("hole 1 lies outside"),
        "{e}"
    );
}

#[test]
fn too_few_and_zero_area() {
    assert_eq!(
        error(&[&[(0, 0), (1, 1)]]),
        "outer ring has 2 distinct vertices; a ring needs at least 3"
    );
    assert_eq!(
        error(&[&[(0, 0), (1, 1), (2, 2)]]),
        "outer ring has zero area (all its vertices lie on one line)"
    );
    assert_eq!(
        error(&[SQUARE, &[(1, 1), (2, 2), (3, 3), (2, 2)]]),
        "hole 1 has zero area (all its vertices lie on one line); --repair drops the hole"
    );
}

// ---- randomized comparison against an obviously correct quadratic check ----

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }
    fn below(&mut self, n: u64) -> i64 {
        (self.next() % n) as i64
    }
}

/// Winding-free even-odd point-in-ring test at a point not on the ring, exact.
fn inside(ring: &[Point], q: Point) -> bool {
    let mut c = false;
    for k in 0..ring.len() {
        let (a, b) = (ring[k], ring[(k + 1) % ring.len()]);
        if (a.y > q.y) != (b.y > q.y) {
            let s = cross(a, b, q);
            if (s > 0) == (b.y > a.y) {
                c = !c;
            }
        }
    }
    c
}

fn brute_force_valid(p: &Polygon) -> bool {
    let n = p.len();
    for e in 0..n {
        for f in e + 1..n {
            let adjacent = p.next(e) == f || p.next(f) == e;
            let c = segment_contact(
                p.point(e),
                p.point(p.next(e)),
                p.point(f),
                p.point(p.next(f)),
            );
            if adjacent {
                let shared = if p.next(e) == f { f } else { e };
                let (u, w) = (p.point(p.prev(shared)), p.point(p.next(shared)));
                let s = p.point(shared);
                if cross(u, s, w) == 0
                    && crate::geom::kernel::dot(s, u, w) > 0
                    && p.ring_range(p.ring_index(e)).len() >= 3
                {
                    return false;
                }
                if p.ring_range(p.ring_index(e)).len() == 3 && c == SegmentContact::Overlap {
                    return false;
                }
            } else if c != SegmentContact::Disjoint {
                return false;
            }
        }
    }
    let rings: Vec<Vec<Point>> = (0..=p.holes())
        .map(|r| p.ring_range(r).map(|i| p.point(i)).collect())
        .collect();
    for (h, ring) in rings.iter().enumerate().skip(1) {
        if !inside(&rings[0], ring[0]) {
            return false;
        }
        for (g, other) in rings.iter().enumerate().skip(1) {
            if g != h && inside(other, ring[0]) {
                return false;
            }
        }
    }
    true
}

#[test]
fn sweep_agrees_with_brute_force_on_random_rings() {
    let mut rng = Rng(0x9E37_79B9_7F4A_7C15);
    let (mut valid, mut invalid) = (0, 0);
    for case in 0..30_000 {
        let holes = rng.below(3) as usize;
        let size = 3 + rng.below(4);
        let mut rings: Vec<Vec<(i64, i64)>> = Vec::new();
        for r in 0..=holes {
            let len = if r == 0 {
                3 + rng.below(6)
            } else {
                3 + rng.below(2)
            } as usize;
            rings.push(
                (0..len)
                    .map(|_| (rng.below(size as u64 + 1), rng.below(size as u64 + 1)))
                    .collect(),
            );
        }
        let refs: Vec<&[(i64, i64)]> = rings.iter().map(|r| r.as_slice()).collect();
        let Ok((polygon, _)) = Polygon::build(&raw(&refs)) else {
            continue;
        };
        let fast = errors(&polygon).is_empty();
        let slow = brute_force_valid(&polygon);
        assert_eq!(fast, slow, "case {case}: {rings:?}: {:?}", errors(&polygon));
        // The sweep alone (small rings are otherwise checked pair by pair) agrees too, with the
        // same messages.
        assert_eq!(
            errors_with(&polygon, false),
            errors(&polygon),
            "case {case}: {rings:?}"
        );
        if fast {
            valid += 1;
        } else {
            invalid += 1;
        }
    }
    assert!(
        valid > 1_000 && invalid > 1_000,
        "valid {valid}, invalid {invalid}"
    );
}
