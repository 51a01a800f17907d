//! Coordinates beyond the fast kernel's grid (`2^62` units): the wide kernel.
//!
//! - a 10,000-vertex polygon spanning ±180 by ±85 degrees written by a shortest-round-trip
//!   double printer (Rust's `{}` of `f64`), one vertex at `1.2345678901234567e-5`, triangulated
//!   by every algorithm and verified;
//! - every algorithm gives the same counts on random polygons (the generators of
//!   `property.rs`) and on the same polygons moved to grids that force the wide kernel: shifted
//!   by `1e-20` (signs from the floating-point filter), and scaled by `10^-200` and shifted by
//!   `10^-220` (beyond the filter's range: every sign exact in big integers).

use crate::property::{config, general, rectilinear, without_flat};
use minitri::algo::{asano, ear, minitri as chen_chang};
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
        let e = ear::triangulate(p).map_err(|e| TestCaseError::fail(e.to_string()))?;
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
        AnyPolygon::from_raw(&RawPolygon { rings: vec![ring?] })
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
