//! Coordinates beyond the fast kernel's grid (`2^62` units): the wide kernel.
//!
//! - a 10,000-vertex polygon spanning ±180 by ±85 degrees written by a shortest-round-trip
//!   double printer (Rust's `{}` of `f64`), one vertex at `1.2345678901234567e-5`, triangulated
//!   by every algorithm and verified;
//! - every algorithm gives the same counts on random polygons (the generators of
//!   `property.rs`) and on the same polygons moved to grids that force the wide kernel: shifted
//!   by `1e-20` (signs from the floating-point filter), and scaled by `10^-200` and shifted by
//!   `10^-220` (beyond the filter's range: every sign exact in big integers).
//! - rings that touch (OGC touches, `src/geom/touch.rs`) and `--repair` (`src/geom/repair.rs`)
//!   on the wide kernel: a touching polygon and a repairable one written with full-precision
//!   doubles, accepted (repaired) and triangulated; and random touching or invalid polygons (the
//!   generator of `touching.rs`) giving the same validation, repairs and counts on the wide grids
//!   as on their integer grid.

use crate::property::{config, general, rectilinear, without_flat};
use minitri::algo::{asano, minitri as chen_chang, plain};
use minitri::geom::repair::RepairKind;
use minitri::{verify, Algorithm, AnyPolygon, Decimal, Format, Options, RawPolygon};
use proptest::prelude::*;

/// A star-shaped polygon around the origin, `n` vertices spanning ±180 by ±85, as WKT with
/// shortest round-trip doubles; the vertex nearest the positive y axis has x =
/// `1.2345678901234567e-5`.
fn world_star(n: usize) -> String {
    let mut state: u64 = 0x2545_F491_4F6C_DD1D;
    let mut coords = Vec::with_capacity(n);
    for k in 0..n {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        let extreme = k % (n / 4) == 0; // on the axes: the full ±180 by ±85
        let r = if extreme {
            1.0
        } else {
            0.55 + 0.45 * (state % 10_000) as f64 / 10_000.0
        };
        let theta = std::f64::consts::TAU * k as f64 / n as f64;
        let (mut x, y) = (180.0 * r * theta.cos(), 85.0 * r * theta.sin());
        if k == n / 4 {
            x = 1.2345678901234567e-5;
        } else if k == n / 2 {
            x = -179.99999999999997;
        }
        coords.push(format!("{x} {y}"));
    }
    coords.push(coords[0].clone());
    format!("POLYGON (({}))", coords.join(", "))
}

#[test]
fn a_world_sized_polygon_of_full_precision_doubles_is_triangulated_by_every_algorithm() {
    let text = world_star(10_000);
    // Rust's `{}` writes 1.2345678901234567e-5 in plain notation, its shortest digits.
    let tiny = format!("{}", 1.2345678901234567e-5_f64);
    assert!(tiny.starts_with("0.0000123456789012345"), "{tiny}");
    assert!(text.contains(&format!(", {tiny} ")));
    assert!(
        text.contains("-179.99999999999997 "),
        "full-precision coordinates near 180"
    );
    for algorithm in [
        Algorithm::Minitri,
        Algorithm::Ear,
        Algorithm::Pseudo,
        Algorithm::PseudoHull,
    ] {
        let options = Options {
            algorithm,
            verify: true,
            ..Options::default()
        };
        let outcomes = minitri::process("world", &text, Format::Wkt, &options);
        let o = &outcomes[0];
        let polygon = o.polygon.as_ref().expect("a valid polygon");
        assert!(polygon.is_wide(), "the grid does not fit 2^62 units");
        assert_eq!(polygon.len(), 10_000);
        let solved = o.result.as_ref().expect("triangulated");
        let v = solved.verification.as_ref().expect("verified");
        assert!(v.ok, "{algorithm}: {v:?}");
        if !algorithm.is_pseudo() {
            let t = &solved.triangulation;
            assert_eq!(t.triangles.len(), 10_000 - 2 - t.degenerate.len());
        }
    }
    // The DP, on a smaller one (O(n^3)).
    let text = world_star(120);
    let options = Options {
        algorithm: Algorithm::Asano,
        verify: true,
        ..Options::default()
    };
    let o = &minitri::process("world", &text, Format::Wkt, &options)[0];
    assert!(o.polygon.as_ref().is_some_and(AnyPolygon::is_wide));
    let solved = o.result.as_ref().expect("triangulated");
    assert!(solved.verification.as_ref().is_some_and(|v| v.ok));
}

/// The counts of every exact algorithm and `ear` on `polygon`, each output checked.
fn counts(polygon: &AnyPolygon) -> Result<[usize; 3], TestCaseError> {
    minitri::with_polygon!(polygon, p => {
        let m = chen_chang::triangulate(p).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let a = asano::triangulate(p, 40).map_err(|e| TestCaseError::fail(e.to_string()))?;
        let e = plain::triangulate(p).map_err(|e| TestCaseError::fail(e.to_string()))?;
        for t in [&m, &a, &e] {
            let check = verify::check(p, t);
            prop_assert!(check.valid, "{:?}: {:?}", t.algorithm, check.problems);
        }
        Ok([m.triangles.len(), a.triangles.len(), e.triangles.len()])
    })
}

/// The ring on three grids: as is (fast), shifted by `1e-20`, scaled by `10^-200` and shifted by
/// `10^-220` (both wide).
fn same_counts_on_wide_grids(ring: &[(i64, i64)]) -> Result<(), TestCaseError> {
    let build = |f: &dyn Fn(i64) -> String| -> Option<AnyPolygon> {
        let ring: Option<Vec<[Decimal; 2]>> = ring
            .iter()
            .map(|&(x, y)| Some([Decimal::parse(&f(x)).ok()?, Decimal::parse(&f(y)).ok()?]))
            .collect();
        AnyPolygon::from_raw(&RawPolygon {
            rings: vec![ring?],
            ..Default::default()
        })
        .ok()
        .map(|(p, _)| p)
    };
    let Some(fast) = build(&|v| v.to_string()) else {
        return Ok(());
    };
    prop_assert!(!fast.is_wide());
    let want = counts(&fast)?;
    // Generator coordinates are 0..=6, so these are exact decimal texts of v + 1e-20 and
    // v * 1e-200 + 1e-220.
    let shifted = build(&|v| format!("{v}.00000000000000000001")).expect("valid");
    let tiny = build(&|v| format!("{v}.00000000000000000001e-200")).expect("valid");
    for wide in [shifted, tiny] {
        prop_assert!(wide.is_wide());
        prop_assert_eq!(counts(&wide)?, want);
    }
    Ok(())
}

proptest! {
    #![proptest_config(config(300, 0x5eed_00a1))]
    #[test]
    fn general_polygons_give_the_same_counts_on_wide_grids(
        base in [(0i64..=6, 0i64..=6), (0i64..=6, 0i64..=6), (0i64..=6, 0i64..=6)],
        ops in prop::collection::vec((0usize..64, 0i64..=6, 0i64..=6), 2..30),
        drop_flat in any::<bool>(),
    ) {
        if let Some(ring) = general(base, &ops) {
            let ring = if drop_flat { without_flat(&ring) } else { ring };
            same_counts_on_wide_grids(&ring)?;
        }
    }
}

proptest! {
    #![proptest_config(config(200, 0x5eed_00a2))]
    #[test]
    fn rectilinear_polygons_give_the_same_counts_on_wide_grids(
        start in (0i64..6, 0i64..6),
        ops in prop::collection::vec((0i64..6, 0i64..6), 0..30),
    ) {
        same_counts_on_wide_grids(&rectilinear(start, &ops))?;
    }
}

/// One polygon's outcomes as text, one each piece, of `minitri::process` on WKT `text`.
fn outcomes(text: &str, algorithm: Algorithm, repair: bool) -> Vec<minitri::Outcome> {
    let options = Options {
        algorithm,
        verify: true,
        repair,
        ..Options::default()
    };
    minitri::process("wide", text, Format::Wkt, &options)
}

#[test]
fn touching_rings_of_full_precision_doubles_are_accepted_and_triangulated() {
    // Hole 1 touches the outer ring's left edge at (-179.99999999999997, 1.2345678901234567e-5)
    // (a vertex of the hole strictly inside the edge) and hole 2 at the vertex
    // (-90.12345678901234, 30.000000000000004) they share: two touches, one boundary walk.
    let text = "POLYGON ((-179.99999999999997 -85.05112877980659, \
        179.99999999999997 -85.05112877980659, 179.99999999999997 85.05112877980659, \
        -179.99999999999997 85.05112877980659, -179.99999999999997 -85.05112877980659), \
        (-179.99999999999997 0.000012345678901234567, -90.12345678901234 30.000000000000004, \
        -90.12345678901234 -29.999999999999996, -179.99999999999997 0.000012345678901234567), \
        (-90.12345678901234 30.000000000000004, 0.1 45.00000000000001, \
        0.30000000000000004 10.5, -90.12345678901234 30.000000000000004))";
    let mut minimum = None;
    for algorithm in [Algorithm::Minitri, Algorithm::Asano, Algorithm::Ear] {
        let o = &outcomes(text, algorithm, false)[0];
        let polygon = o
            .polygon
            .as_ref()
            .expect("valid: the rings touch as OGC allows");
        assert!(polygon.is_wide(), "the grid does not fit 2^62 units");
        assert_eq!((polygon.touches(), polygon.holes()), (2, 0));
        // 4 + 3 + 3 vertices, and hole 1's vertex on the outer edge also in that edge.
        assert_eq!(polygon.len(), 11);
        let solved = o.result.as_ref().expect("triangulated");
        let v = solved.verification.as_ref().expect("verified");
        assert!(v.ok, "{algorithm}: {v:?}");
        let t = &solved.triangulation;
        assert_eq!(t.triangles.len() + t.degenerate.len(), 11 - 2);
        if algorithm.is_minimum() {
            assert!(
                t.optimal,
                "{algorithm}: one walk of 11 is within the walk DP"
            );
            let count = t.triangles.len();
            assert_eq!(*minimum.get_or_insert(count), count, "{algorithm}");
        }
    }
    // The JSON carries the touches, as on the fast kernel.
    let json = minitri::io::write::json::render(&outcomes(text, Algorithm::Minitri, false)[0])
        .expect("a solved outcome");
    assert!(json.contains("\"touches\": 2"), "{json}");
}

#[test]
fn a_repairable_polygon_of_full_precision_doubles_is_repaired_and_triangulated() {
    // A figure eight through (1.2345678901234567e-5, 0.30000000000000004), with a spike at
    // (179.99999999999997, -85.05112877980659) (the boundary runs there and back along y =
    // -85.05112877980659): rejected as it is; --repair removes the spike and splits the ring
    // into two triangles.
    let centre = "0.000012345678901234567 0.30000000000000004";
    let text = format!(
        "POLYGON ((-179.99999999999997 -85.05112877980659, \
        179.99999999999997 -85.05112877980659, 90.00000000000001 -85.05112877980659, \
        {centre}, 179.99999999999997 85.05112877980659, -179.99999999999997 85.05112877980659, \
        {centre}, -179.99999999999997 -85.05112877980659))"
    );
    let as_is = &outcomes(&text, Algorithm::Minitri, false)[0];
    assert!(as_is.polygon.is_none());
    let message = match &as_is.result {
        Err(e) => e.messages().join("; "),
        Ok(_) => panic!("a spike and a self-touching ring are invalid"),
    };
    assert!(message.contains("spike"), "{message}");
    for algorithm in [Algorithm::Minitri, Algorithm::Asano, Algorithm::Ear] {
        let pieces = outcomes(&text, algorithm, true);
        assert_eq!(
            pieces.len(),
            2,
            "{algorithm}: a figure eight gives two polygons"
        );
        for (k, o) in pieces.iter().enumerate() {
            assert_eq!(o.piece, Some(k));
            let polygon = o.polygon.as_ref().expect("each piece valid");
            assert!(polygon.is_wide());
            assert_eq!(polygon.len(), 3);
            let solved = o.result.as_ref().expect("triangulated");
            assert!(solved.verification.as_ref().is_some_and(|v| v.ok));
            assert_eq!(solved.triangulation.triangles.len(), 1);
            let kinds: Vec<RepairKind> = o
                .repaired
                .as_ref()
                .expect("--repair")
                .iter()
                .map(|r| r.kind)
                .collect();
            // Listed once, with the first piece.
            let expected: &[RepairKind] = if k == 0 {
                &[RepairKind::Spike, RepairKind::SplitRing]
            } else {
                &[]
            };
            assert_eq!(kinds, expected, "{:?}", o.repaired);
        }
        let spike = &pieces[0].repaired.as_ref().expect("--repair")[0].message;
        assert!(
            spike.contains("spike at vertex 1 (179.99999999999997, -85.05112877980659) removed"),
            "{spike}"
        );
    }
}

/// What validation and `--repair` make of `raw`, in terms that do not depend on the grid: for
/// each outcome (piece), the repairs' kinds, the kinds of the problems or the polygon's
/// vertices, holes and touches and the counts of every algorithm given (each output verified).
fn summary(raw: &RawPolygon, repair: bool, algorithms: &[Algorithm], wide: bool) -> Vec<String> {
    let mut out = Vec::new();
    for algorithm in algorithms {
        let options = Options {
            algorithm: *algorithm,
            verify: true,
            repair,
            ..Options::default()
        };
        for o in minitri::pipeline::process_raw("wide", 0, raw.clone(), &options) {
            let repairs: Vec<RepairKind> = o.repaired.iter().flatten().map(|r| r.kind).collect();
            let line = match (&o.result, &o.polygon) {
                (Err(minitri::Error::Invalid(errors)), _) => format!(
                    "{repairs:?} invalid {:?}",
                    errors
                        .iter()
                        .map(std::mem::discriminant)
                        .collect::<Vec<_>>()
                ),
                (Err(e), _) => format!("{repairs:?} {algorithm} failed: {e}"),
                (Ok(solved), Some(p)) => {
                    assert_eq!(p.is_wide(), wide, "the kernel its coordinates need");
                    let v = solved.verification.as_ref().expect("verified");
                    assert!(v.ok, "{algorithm}: {v:?}");
                    let t = &solved.triangulation;
                    format!(
                        "{repairs:?} n {} holes {} touches {} {algorithm} {} + {} optimal {}",
                        p.len(),
                        p.holes(),
                        p.touches(),
                        t.triangles.len(),
                        t.degenerate.len(),
                        t.optimal
                    )
                }
                (Ok(_), None) => unreachable!("a solved outcome has its polygon"),
            };
            out.push(line);
        }
    }
    out
}

#[test]
fn touching_rings_and_repairs_give_the_same_outcomes_on_wide_grids() {
    // The touching-ring generator of touching.rs (coordinates 0..=6; touches common, invalid
    // polygons common): validation, every algorithm and --repair on the grid as is (fast) and
    // moved to grids that force the wide kernel must agree in everything but the coordinates.
    let mut rnd = crate::util::xorshift(0x71de_70c4);
    let (mut invalid, mut repaired, mut valid, mut touching) = (0, 0, 0, 0);
    let algorithms = [Algorithm::Minitri, Algorithm::Asano, Algorithm::Ear];
    let mut tries = 0;
    while (invalid < 600 || touching < 100) && tries < 200_000 {
        tries += 1;
        let Some(rings) = crate::touching::random_rings(&mut rnd) else {
            continue;
        };
        let fast = crate::touching::raw(&rings);
        let refs: Vec<&[(i64, i64)]> = rings.iter().map(|r| &r[..]).collect();
        let moved = |f: &dyn Fn(i64) -> String| written(&refs, f);
        let shifted = moved(&|v| format!("{v}.00000000000000000001"));
        let tiny = moved(&|v| format!("{v}.00000000000000000001e-200"));
        let Ok((p, _)) = AnyPolygon::from_raw(&fast) else {
            if invalid >= 600 {
                continue;
            }
            // Invalid: compare what --repair makes of it.
            let want = summary(&fast, true, &algorithms[..1], false);
            if want.iter().any(|l| !l.contains("invalid")) {
                repaired += 1;
            }
            for wide in [&shifted, &tiny] {
                assert!(AnyPolygon::from_raw(wide).is_err(), "{rings:?}");
                assert_eq!(
                    summary(wide, true, &algorithms[..1], true),
                    want,
                    "{rings:?}"
                );
            }
            invalid += 1;
            continue;
        };
        assert!(!p.is_wide());
        touching += usize::from(p.touches() > 0);
        let want = summary(&fast, false, &algorithms, false);
        for wide in [&shifted, &tiny] {
            let (w, _) = AnyPolygon::from_raw(wide).expect("valid on every grid");
            assert!(w.is_wide(), "{rings:?}");
            assert_eq!(summary(wide, false, &algorithms, true), want, "{rings:?}");
        }
        valid += 1;
    }
    assert!(
        invalid == 600 && repaired > 150 && touching >= 100,
        "{invalid} {repaired} {valid} {touching}"
    );
}

/// `rings` as read, each coordinate written by `f`.
fn written(rings: &[&[(i64, i64)]], f: &dyn Fn(i64) -> String) -> RawPolygon {
    RawPolygon {
        rings: rings
            .iter()
            .map(|r| {
                r.iter()
                    .map(|&(x, y)| {
                        [
                            Decimal::parse(&f(x)).unwrap(),
                            Decimal::parse(&f(y)).unwrap(),
                        ]
                    })
                    .collect()
            })
            .collect(),
        ..Default::default()
    }
}

#[test]
fn vertices_on_their_own_edges_and_cycles_of_touches_are_repaired_on_the_wide_kernel() {
    // A vertex inside its own ring's edge (outer ring, hole); a hole touching the outer ring
    // twice; two holes touching twice: repaired alike (repairs, pieces, counts, all verified) on
    // the integer grid and on grids that force the wide kernel.
    let square: &[(i64, i64)] = &[(-10, -10), (20, -10), (20, 20), (-10, 20)];
    type Rings<'a> = &'a [&'a [(i64, i64)]];
    let cases: [(Rings, RepairKind, usize); 4] = [
        (
            &[&[(0, 0), (10, 0), (10, 10), (6, 10), (5, 0), (4, 10), (0, 10)]],
            RepairKind::SplitRing,
            2,
        ),
        (
            &[
                square,
                &[(2, 2), (8, 2), (8, 8), (6, 8), (5, 2), (4, 8), (2, 8)],
            ],
            RepairKind::SplitRing,
            1,
        ),
        (
            &[
                &[(0, 0), (10, 0), (10, 10), (0, 10)],
                &[(3, 0), (5, 5), (10, 7)],
            ],
            RepairKind::CutInterior,
            2,
        ),
        (
            &[
                &[(0, 0), (20, 0), (20, 20), (0, 20)],
                &[(10, 4), (4, 10), (10, 16), (7, 10)],
                &[(10, 4), (13, 10), (10, 16), (16, 10)],
            ],
            RepairKind::CutInterior,
            2,
        ),
    ];
    let algorithms = [Algorithm::Minitri, Algorithm::Ear];
    for (rings, kind, pieces) in cases {
        let fast = written(rings, &|v| v.to_string());
        assert!(
            AnyPolygon::from_raw(&fast).is_err(),
            "{rings:?}: invalid as it is"
        );
        let want = summary(&fast, true, &algorithms, false);
        assert_eq!(want.len(), pieces * algorithms.len(), "{want:?}");
        // The repairs are listed with each polygon's first piece only (the others' list is
        // empty).
        assert!(want.iter().all(|l| !l.contains("invalid")), "{want:?}");
        assert!(
            want.iter().enumerate().all(|(i, l)| (i % pieces == 0)
                == l.starts_with(&format!("[{kind:?}]"))
                && (i % pieces == 0 || l.starts_with("[]"))),
            "{want:?}"
        );
        for suffix in ["", "e-200"] {
            let wide = written(rings, &|v| format!("{v}.00000000000000000001{suffix}"));
            assert_eq!(summary(&wide, true, &algorithms, true), want, "{rings:?}");
        }
    }
}
