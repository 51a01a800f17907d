//! The public API never panics (issue 37): every public entry point, fed random and hostile
//! polygons (huge and tiny decimals, collinear runs, rings that touch or cross themselves, empty
//! rings, NaN and infinities from geo-types, deadlines already past), returns, and every `Ok`
//! it returns passes the independent checker. Only the crate's public surface is used here.

use geo_types::{Coord, LineString, MultiPolygon};
use minitri::{
    geo, verify, Algorithm, AnyPolygon, Format, Options, Polygon, Pseudotriangulator, RawPolygon,
    Triangulator,
};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};
use std::time::Duration;

/// A coordinate: mostly small integers (so that vertices repeat, runs are collinear and rings
/// touch or cross), some hostile floats, some ordinary ones.
fn coordinate() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => (-3i32..=3).prop_map(f64::from),
        1 => prop::sample::select(vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::MAX,
            -f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
            1e300,
            -1e-300,
            -0.0,
            0.1,
            0.3,
            1e15 + 0.5,
        ]),
        2 => -4.0f64..4.0,
    ]
}

/// A ring of 0 to 9 positions (empty, too short, or closed or not).
fn ring() -> impl Strategy<Value = Vec<(f64, f64)>> {
    prop::collection::vec((coordinate(), coordinate()), 0..10)
}

/// A ring as a geo-types line string.
fn line(r: Vec<(f64, f64)>) -> LineString<f64> {
    LineString(r.into_iter().map(|(x, y)| Coord { x, y }).collect())
}

/// A geo-types polygon: random rings (an outer ring and 0 to 2 holes; mostly not valid), or a
/// star around the origin on a half-unit grid (mostly valid: collinear runs, flat vertices,
/// T-junctions), sometimes with a small square hole that may touch it.
fn polygon() -> impl Strategy<Value = geo_types::Polygon<f64>> {
    let random = (ring(), prop::collection::vec(ring(), 0..3)).prop_map(|(outer, holes)| {
        geo_types::Polygon::new(line(outer), holes.into_iter().map(line).collect())
    });
    let star = (prop::collection::vec(2u8..=8, 3..14), 0u8..3).prop_map(|(radii, hole)| {
        let n = radii.len() as f64;
        let outer = radii
            .iter()
            .enumerate()
            .map(|(k, &r)| {
                let angle = std::f64::consts::TAU * k as f64 / n;
                let half = |v: f64| (v * 2.0).round() / 2.0;
                (
                    half(f64::from(r) * angle.cos()),
                    half(f64::from(r) * angle.sin()),
                )
            })
            .collect();
        let holes = match hole {
            0 => vec![],
            h => {
                let s = f64::from(h) / 2.0;
                vec![vec![(-s, -s), (-s, s), (s, s), (s, -s)]]
            }
        };
        geo_types::Polygon::new(line(outer), holes.into_iter().map(line).collect())
    });
    prop_oneof![random, star]
}

/// Options as a caller may set them: limits of 0 (a deadline already past, no DP at all) among
/// ordinary ones.
fn options() -> impl Strategy<Value = Options> {
    (
        prop::sample::select(vec![
            None,
            Some(Duration::ZERO),
            Some(Duration::from_millis(50)),
        ]),
        prop::sample::select(vec![0usize, 3, 64]),
        any::<bool>(),
    )
        .prop_map(|(time_limit, dp_limit, verify)| Options {
            time_limit,
            dp_limit,
            verify,
            ..Options::default()
        })
}

/// Every function of the public API on one valid polygon; each `Ok` checked.
fn exercise<P: minitri::Coord>(p: &Polygon<P>, options: &Options) -> Result<(), TestCaseError> {
    for algorithm in [
        Triangulator::Minitri,
        Triangulator::Asano,
        Triangulator::Ear,
    ] {
        let results = [
            minitri::triangulate(p, algorithm),
            minitri::triangulate_with(p, algorithm, options),
        ];
        for t in results.into_iter().flatten() {
            let check = verify::check(p, &t);
            prop_assert!(check.valid, "{algorithm}: {:?}", check.problems);
            prop_assert_eq!(geo::triangles(p, &t).len(), t.triangles.len());
            geo::degenerate(p, &t);
            geo::multi_polygon(p, &t);
            t.input_triangles(p);
            t.input_degenerate(p);
        }
    }
    for algorithm in [Pseudotriangulator::Pseudo, Pseudotriangulator::PseudoHull] {
        if let Ok(result) = minitri::pseudotriangulate(p, algorithm) {
            let check = verify::pseudo::check(p, algorithm.into(), &result);
            prop_assert!(check.valid, "{algorithm}: {:?}", check.problems);
            result.input_faces(p);
        }
    }
    for algorithm in [
        Algorithm::Minitri,
        Algorithm::Asano,
        Algorithm::Ear,
        Algorithm::Pseudo,
        Algorithm::PseudoHull,
    ] {
        let options = Options {
            algorithm,
            ..options.clone()
        };
        if let Ok(solved) = minitri::solve(p, &options) {
            solved_is_valid(p, &solved)?;
        }
    }
    // Any triangulation at all, nonsense included, is judged without a panic.
    let nonsense = minitri::Triangulation {
        algorithm: Algorithm::Ear,
        triangles: vec![[0, 0, 0], [usize::MAX, 1, 2], [2, 1, 0]],
        degenerate: vec![[0, usize::MAX, 1]],
        optimal: true,
        lower_bound: Some(usize::MAX),
        stopped: None,
    };
    prop_assert!(!verify::check(p, &nonsense).valid);
    Ok(())
}

/// A solved polygon's answer passes its checker (and its own verification, when it made one).
fn solved_is_valid<P: minitri::Coord>(
    p: &Polygon<P>,
    solved: &minitri::Solved,
) -> Result<(), TestCaseError> {
    match &solved.pseudo {
        Some(pseudo) => {
            let check = verify::pseudo::check(p, solved.triangulation.algorithm, pseudo);
            prop_assert!(check.valid, "{:?}", check.problems);
        }
        None => {
            let check = verify::check(p, &solved.triangulation);
            prop_assert!(check.valid, "{:?}", check.problems);
        }
    }
    if let Some(verification) = &solved.verification {
        prop_assert!(verification.ok, "{verification:?}");
    }
    Ok(())
}

/// The text path: each outcome of `process` that was solved is valid.
fn process_is_valid(text: &str, format: Format, options: &Options) -> Result<(), TestCaseError> {
    for outcome in minitri::process("api", text, format, options) {
        outcome.messages(false);
        if let (Ok(solved), Some(polygon)) = (&outcome.result, &outcome.polygon) {
            minitri::with_polygon!(polygon, p => solved_is_valid(p, solved))?;
        }
    }
    Ok(())
}

/// WKT of a polygon's rings, numbers as Rust prints them (NaN and inf included: the reader
/// refuses them).
fn wkt(polygon: &geo_types::Polygon<f64>) -> String {
    let ring = |r: &LineString<f64>| {
        let coords: Vec<String> = r.0.iter().map(|c| format!("{:?} {:?}", c.x, c.y)).collect();
        format!("({})", coords.join(", "))
    };
    let rings: Vec<String> = std::iter::once(polygon.exterior())
        .chain(polygon.interiors())
        .map(ring)
        .collect();
    format!("POLYGON ({})", rings.join(", "))
}

proptest! {
    #![proptest_config(Config {
        cases: 400,
        rng_seed: RngSeed::Fixed(0x37),
        failure_persistence: None,
        ..Config::default()
    })]

    #[test]
    fn no_public_function_panics_and_every_answer_checks(
        geo_polygon in polygon(),
        options in options(),
    ) {
        // From geo-types, every way in.
        let _ = RawPolygon::try_from(&geo_polygon);
        let _ = geo::polygon_with_warnings(&geo_polygon);
        if let Ok(p) = Polygon::try_from(&geo_polygon) {
            exercise(&p, &options)?;
        }
        let multi = MultiPolygon(vec![geo_polygon.clone(), geo_polygon.clone()]);
        let _ = geo::raw_polygons(&multi);
        for any in geo::polygons(&multi).into_iter().flatten() {
            minitri::with_polygon!(&any, p => exercise(p, &options))?;
            for algorithm in [Triangulator::Minitri, Triangulator::Ear] {
                if let Ok(t) = any.triangulate(algorithm) {
                    any.geo_triangles(&t);
                    any.geo_multi_polygon(&t);
                }
            }
            if let Ok(solved) = any.solve(&options) {
                minitri::with_polygon!(&any, p => solved_is_valid(p, &solved))?;
            }
        }
        if let Ok(raw) = RawPolygon::try_from(&geo_polygon) {
            let _ = AnyPolygon::from_raw_all_errors(&raw);
            for outcome in minitri::process_raw("api", 0, raw, &options) {
                if let (Ok(solved), Some(polygon)) = (&outcome.result, &outcome.polygon) {
                    minitri::with_polygon!(polygon, p => solved_is_valid(p, solved))?;
                }
            }
        }
        // From text: the polygon as WKT, read and processed, with and without repair.
        let text = wkt(&geo_polygon);
        let _ = minitri::read(Format::Wkt, &text);
        let _ = minitri::read_parts(Format::Wkt, &text);
        for repair in [false, true] {
            process_is_valid(&text, Format::Wkt, &Options { repair, ..options.clone() })?;
        }
    }

    #[test]
    fn no_reader_panics_on_any_text(text in ".{0,80}", bytes in prop::collection::vec(any::<u8>(), 0..40)) {
        let binary = String::from_utf8_lossy(&bytes).into_owned();
        for format in [Format::Wkt, Format::GeoJson, Format::Vertices, Format::Wkb, Format::Csv] {
            for input in [text.as_str(), binary.as_str()] {
                let _ = minitri::read(format, input);
                let _ = minitri::read_parts(format, input);
                process_is_valid(input, format, &Options::default())?;
            }
        }
        let _ = minitri::Decimal::parse(&text);
    }
}

#[test]
fn hostile_polygons_are_refused_or_solved_never_panic() {
    let hostile: Vec<Vec<(f64, f64)>> = vec![
        vec![],
        vec![(0.0, 0.0)],
        vec![(0.0, 0.0), (1.0, 0.0)],
        vec![(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)],
        vec![(0.0, 0.0), (2.0, 2.0), (2.0, 0.0), (0.0, 2.0)],
        vec![(0.0, 0.0), (f64::NAN, 0.0), (0.0, 1.0)],
        vec![(0.0, 0.0), (f64::INFINITY, 0.0), (0.0, 1.0)],
        vec![
            (0.0, 0.0),
            (f64::MAX, 0.0),
            (f64::MAX, f64::MAX),
            (0.0, f64::MAX),
        ],
        vec![(0.0, 0.0), (5e-324, 0.0), (5e-324, 5e-324), (0.0, 5e-324)],
        vec![
            (-1e300, -1e300),
            (1e300, -1e300),
            (1e-300, 1e-300),
            (-1e300, 1e300),
        ],
        vec![(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (2.0, 0.0), (0.0, 4.0)],
    ];
    for outer in &hostile {
        for holes in [
            vec![],
            vec![vec![]],
            vec![vec![(1.0, 1.0), (2.0, 1.0), (1.0, 2.0)]],
        ] {
            let p =
                geo_types::Polygon::new(line(outer.clone()), holes.into_iter().map(line).collect());
            for options in [
                Options::default(),
                Options {
                    time_limit: Some(Duration::ZERO),
                    dp_limit: 0,
                    verify: true,
                    repair: true,
                    ..Options::default()
                },
            ] {
                if let Ok(polygon) = Polygon::try_from(&p) {
                    exercise(&polygon, &options).unwrap();
                }
                process_is_valid(&wkt(&p), Format::Wkt, &options).unwrap();
            }
        }
    }
}
