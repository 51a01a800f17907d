//! Shared oracles of the fuzz targets (`fuzz_targets/`).
//!
//! Every target ends in [`check_polygons`]: each polygon read goes through validation
//! (`Polygon::from_raw_all_errors`, which must not panic); a small valid one goes on through every
//! algorithm that applies, each output judged by the independent checker (`minitri::verify`), the
//! exact counts compared ([`check_polygon`]); and all the outcomes go through every writer, whose
//! JSON and GeoJSON output must parse as JSON. A panic or a failed assertion is a finding.

use minitri::algo::{asano, minitri as chen_chang, plain};
use minitri::io::read::RawPolygon;
use minitri::io::write::{svg::Style, OutputFormat};
use minitri::pipeline::{self, Options, Outcome};
use minitri::{verify, Algorithm, AnyPolygon, Coord, Decimal, Polygon, Triangulation};

/// The largest polygon (vertices over all rings) sent on to the algorithms: the exact
/// algorithms are exponential (holes) or cubic, and a fuzz execution must take milliseconds.
pub const SMALL: usize = 12;

/// The most holes of a polygon sent on to the algorithms (the holes DP takes at most 2).
pub const SMALL_HOLES: usize = 2;

/// Whether `raw` is small enough for [`check_polygon`] (counted before validation).
pub fn is_small(raw: &RawPolygon) -> bool {
    raw.rings.len() <= SMALL_HOLES + 1 && raw.rings.iter().map(Vec::len).sum::<usize>() <= SMALL
}

/// Checks one valid polygon with every algorithm that applies:
///
/// - `ear`: the checker accepts it, with exactly `n + 2w - 2` triangles and no degenerate ones;
/// - `minitri` (no deadline): the checker accepts it, and it is marked optimal (touching rings
///   too);
/// - without holes, `minitri`'s general method (the one it uses with holes): accepted, same count;
/// - `asano` (the DP, with holes up to its limits; the walk DP on touching rings of one walk):
///   accepted, same count as `minitri`;
/// - the minimum lies within `Polygon::minimum_bounds`.
///
/// # Panics
/// On any disagreement or rejected output: that is a finding.
pub fn check_polygon(polygon: &Polygon) {
    let w = polygon.holes();
    let checked = |t: &Triangulation| {
        let report = verify::check(polygon, t);
        assert!(
            report.valid,
            "{} output rejected by the checker on {:?}: {:?} (triangles {:?}, degenerate {:?})",
            t.algorithm,
            polygon.points(),
            report.problems,
            t.triangles,
            t.degenerate
        );
        t.triangles.len()
    };
    check_ear(polygon);
    let minitri = chen_chang::triangulate_within(polygon, None)
        .expect("minitri triangulates every valid polygon");
    // Touching rings included: Chen & Chang's steps on the walks (with the exact search when
    // hole walks are left) finish without a deadline.
    assert!(minitri.optimal, "minitri without deadline is not optimal");
    let minimum = checked(&minitri);
    // The general method (for holes) does not take touching rings' boundary walks.
    if w == 0 && polygon.touches() == 0 {
        let general = chen_chang::triangulate_general(polygon, None)
            .expect("the general method triangulates every valid polygon");
        assert!(
            general.optimal,
            "general method without deadline is not optimal"
        );
        assert_eq!(
            checked(&general),
            minimum,
            "minitri's general method disagrees on {:?}",
            polygon.points()
        );
    }
    match asano::triangulate(polygon, asano::DEFAULT_LIMIT) {
        Ok(dp) => assert_eq!(
            checked(&dp),
            minimum,
            "asano and minitri disagree on {:?} (ring starts {:?})",
            polygon.points(),
            polygon.ring_starts()
        ),
        Err(e) => assert!(w > 0, "asano refuses a polygon without holes: {e}"),
    }
    let (low, high) = polygon.minimum_bounds();
    assert!(
        low <= minimum && minimum <= high,
        "minimum {minimum} outside bounds {low}..={high} on {:?}",
        polygon.points()
    );
}

/// Checks `ear` alone: the checker accepts it, with exactly `n + 2w - 2` triangles and no
/// degenerate ones.
///
/// # Panics
/// When it does not: that is a finding.
pub fn check_ear<P: Coord>(polygon: &Polygon<P>) {
    let ear = plain::triangulate(polygon).expect("ear triangulates every valid polygon");
    let report = verify::check(polygon, &ear);
    assert!(
        report.valid,
        "ear output rejected by the checker on {:?}: {:?}",
        polygon.points(),
        report.problems
    );
    assert_eq!(
        ear.triangles.len(),
        polygon.len() + 2 * polygon.holes() - 2,
        "ear count on {:?}",
        polygon.points()
    );
    assert!(ear.degenerate.is_empty(), "ear lists degenerate triangles");
}

/// Validates each polygon; a small valid one goes through [`check_ear`] and the `--verify`
/// pipeline (minitri and asano, each output checked, counts compared; [`check_polygon`] does
/// more, but the `core` target covers the algorithms, and the readers' targets must stay fast);
/// then writes all outcomes in every output format.
pub fn check_polygons(raws: &[RawPolygon]) {
    let options = Options {
        algorithm: Algorithm::Minitri,
        dp_limit: asano::DEFAULT_LIMIT,
        verify: true,
        time_limit: None,
        repair: false,
    };
    let mut outcomes = Vec::new();
    for (index, raw) in raws.iter().enumerate() {
        // Either kernel: full-precision or huge coordinates take the wide one.
        match AnyPolygon::from_raw_all_errors(raw) {
            Err(errors) => {
                assert!(!errors.is_empty(), "invalid without a reason");
                for e in &errors {
                    assert!(!e.to_string().is_empty(), "empty message");
                }
                outcomes.extend(pipeline::process_raw("fuzz", index, raw.clone(), &options));
                if is_small(raw) {
                    // --repair: every piece it makes valid is solved and verified.
                    let repair = Options {
                        repair: true,
                        ..options.clone()
                    };
                    for outcome in pipeline::process_raw("fuzz", index, raw.clone(), &repair) {
                        if let Ok(solved) = &outcome.result {
                            let verification = solved.verification.as_ref().expect("verified");
                            assert!(
                                verification.ok,
                                "--repair, --verify fails: {verification:?}"
                            );
                        }
                        outcomes.push(outcome);
                    }
                }
            }
            Ok((polygon, _warnings)) if is_small(raw) => {
                minitri::with_polygon!(&polygon, p => check_ear(p));
                let outcome =
                    pipeline::process_raw("fuzz", index, raw.clone(), &options).swap_remove(0);
                let solved = outcome.result.as_ref().expect("a valid polygon is solved");
                let verification = solved.verification.as_ref().expect("verified");
                assert!(verification.ok, "--verify fails: {verification:?}");
                outcomes.push(outcome);
            }
            Ok(_) => {}
        }
    }
    write_all(outcomes);
}

/// Writes `outcomes` in every output format; JSON and GeoJSON must parse back.
pub fn write_all(outcomes: Vec<Outcome>) {
    for format in [
        OutputFormat::Json,
        OutputFormat::GeoJson,
        OutputFormat::GeoJsonTriangles,
        OutputFormat::GeoJsonLines,
        OutputFormat::Wkt,
        OutputFormat::Csv,
        OutputFormat::Svg(Style { labels: false }),
        OutputFormat::Svg(Style { labels: true }),
    ] {
        let mut bytes = Vec::new();
        {
            let mut sink = format.sink(&mut bytes).expect("writing to memory");
            for outcome in &outcomes {
                sink.push(outcome.clone()).expect("writing to memory");
            }
            sink.finish().expect("writing to memory");
        }
        let text = std::str::from_utf8(&bytes).expect("writers write UTF-8");
        if matches!(
            format,
            OutputFormat::Json | OutputFormat::GeoJson | OutputFormat::GeoJsonTriangles
        ) {
            if let Err(e) = serde_json::from_str::<serde_json::Value>(text) {
                panic!("{format:?} output is not JSON ({e}):\n{text}");
            }
        }
        if format == OutputFormat::GeoJsonLines {
            for line in text.lines() {
                if let Err(e) = serde_json::from_str::<serde_json::Value>(line) {
                    panic!("GeoJSON Lines output line is not JSON ({e}):\n{line}");
                }
            }
        }
    }
}

/// A ring of small integer points as exact decimals.
pub fn ring(points: &[(i64, i64)]) -> Vec<[Decimal; 2]> {
    let d = |v: i64| Decimal::parse(&v.to_string()).expect("an integer is a decimal");
    points.iter().map(|&(x, y)| [d(x), d(y)]).collect()
}
