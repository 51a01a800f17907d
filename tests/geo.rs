//! The geo-types API: floats in are taken as their shortest decimals, so the triangles out carry
//! the input coordinates bit for bit; integers exactly; NaN refused; multipolygons polygon by
//! polygon.

use geo_types::polygon;
use minitri::{geo, verify, Error, Polygon, Triangulator};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

/// A ring around (0.5, 0.5): `radii.len()` evenly spaced directions; any f64 radii in
/// [0.1, 0.4), so every coordinate lies in [0.1, 0.9) with up to 17 significant digits.
fn star(radii: &[f64]) -> Vec<(f64, f64)> {
    let n = radii.len() as f64;
    radii
        .iter()
        .enumerate()
        .map(|(k, r)| {
            let angle = std::f64::consts::TAU * k as f64 / n;
            (0.5 + r * angle.cos(), 0.5 + r * angle.sin())
        })
        .collect()
}

fn geo_polygon(ring: &[(f64, f64)]) -> geo_types::Polygon<f64> {
    let coords: Vec<geo_types::Coord<f64>> = ring.iter().map(|&(x, y)| (x, y).into()).collect();
    geo_types::Polygon::new(coords.into(), vec![])
}

proptest! {
    #![proptest_config(Config {
        cases: 200,
        rng_seed: RngSeed::Fixed(0x9e0),
        failure_persistence: None,
        ..Config::default()
    })]

    #[test]
    fn float_coordinates_come_out_bit_for_bit(radii in prop::collection::vec(0.1f64..0.4, 3..14)) {
        let ring = star(&radii);
        let polygon = Polygon::try_from(&geo_polygon(&ring)).expect("a star around its centre");
        for algorithm in [Triangulator::Minitri, Triangulator::Ear] {
            let t = minitri::triangulate(&polygon, algorithm).expect("no holes, small");
            prop_assert!(verify::check(&polygon, &t).valid);
            let corners = geo::triangles(&polygon, &t);
            prop_assert_eq!(corners.len(), t.triangles.len());
            // Corner k of triangle j is input vertex id(t.triangles[j][k]), bit for bit.
            for (triangle, stored) in corners.iter().zip(&t.triangles) {
                for (corner, &i) in triangle.to_array().iter().zip(stored) {
                    let (x, y) = ring[polygon.id(i)];
                    prop_assert_eq!((corner.x.to_bits(), corner.y.to_bits()), (x.to_bits(), y.to_bits()));
                }
            }
            let multi = geo::multi_polygon(&polygon, &t);
            prop_assert_eq!(multi.0.len(), t.triangles.len());
            prop_assert!(multi.iter().all(|p| p.exterior().0.len() == 4 && p.interiors().is_empty()));
        }
    }
}

#[test]
fn floats_mean_their_shortest_decimals() {
    // 0.1 + 0.2 != 0.3 in binary, but (0.1, 0.1), (0.2, 0.2), (0.3, 0.3) are collinear as
    // decimals: the middle vertex is a T-junction and a pentagon needs 2 triangles, not 3.
    let p = polygon![
        (x: 0.1, y: 0.1), (x: 0.2, y: 0.2), (x: 0.3, y: 0.3), (x: 0.1, y: 0.5), (x: 0.0, y: 0.3)
    ];
    let polygon = Polygon::try_from(&p).unwrap();
    let t = minitri::triangulate(&polygon, Triangulator::Minitri).unwrap();
    assert_eq!((t.triangles.len(), t.degenerate.len()), (2, 1));
    let [a, b, c] = geo::degenerate(&polygon, &t)[0].to_array();
    assert_eq!((b.x, b.y), (0.2, 0.2));
    assert_eq!([a.x, c.x].iter().sum::<f64>(), 0.1 + 0.3);
    // f32 literals too: 0.1f32 is 0.1, not 0.100000001490116...
    let p32 = polygon![
        (x: 0.1f32, y: 0.1), (x: 0.2, y: 0.2), (x: 0.3, y: 0.3), (x: 0.1, y: 0.5), (x: 0.0, y: 0.3)
    ];
    let polygon32 = Polygon::try_from(&p32).unwrap();
    assert_eq!(
        minitri::triangulate(&polygon32, Triangulator::Asano)
            .unwrap()
            .triangles
            .len(),
        2
    );
    assert_eq!(polygon32.format_vertex(1), polygon.format_vertex(1));
}

#[test]
fn integers_are_exact_and_the_closing_coordinate_is_not_a_vertex() {
    let big = 1i64 << 55; // not representable in f64 plus 1
    let p = polygon![(x: 0i64, y: 0), (x: big + 1, y: 0), (x: 0, y: big + 1)];
    let raw = minitri::RawPolygon::try_from(&p).unwrap();
    assert_eq!(
        raw.rings[0].len(),
        3,
        "geo-types closes rings; the closing vertex is dropped"
    );
    assert_eq!(raw.rings[0][1][0].to_string(), (big + 1).to_string());
    let polygon = Polygon::try_from(&p).unwrap();
    assert_eq!(polygon.len(), 3);
    // -0.0 comes out as 0.0: the decimal zero has no sign.
    let q = polygon![(x: -0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 0.0, y: 1.0)];
    let polygon = Polygon::try_from(&q).unwrap();
    let t = minitri::triangulate(&polygon, Triangulator::Minitri).unwrap();
    let corners = geo::triangles(&polygon, &t)[0].to_array();
    assert!(corners.iter().all(|c| c.x.to_bits() != (-0.0f64).to_bits()));
}

#[test]
fn bad_coordinates_and_bad_polygons_are_named() {
    let inf = polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 0.0, y: f64::INFINITY)];
    let error = Polygon::try_from(&inf).unwrap_err();
    assert!(matches!(error, Error::Parse(_)));
    assert_eq!(
        error.to_string(),
        "polygon 0, outer ring, vertex 2: y coordinate `inf` is not a finite number"
    );
    let hole = geo_types::Polygon::new(
        vec![(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)].into(),
        vec![vec![(1.0, 1.0), (2.0, 1.0), (f64::NAN, 2.0)].into()],
    );
    assert_eq!(
        Polygon::try_from(&hole).unwrap_err().to_string(),
        "polygon 0, hole 1, vertex 2: x coordinate `NaN` is not a finite number"
    );
    // A bow tie crosses itself; in a multipolygon, the other polygons are still converted.
    let bow = polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 1.0), (x: 1.0, y: 0.0), (x: 0.0, y: 1.0)];
    let square = polygon![(x: 0.0, y: 0.0), (x: 1.0, y: 0.0), (x: 1.0, y: 1.0), (x: 0.0, y: 1.0)];
    let multi = geo_types::MultiPolygon(vec![square.clone(), bow, inf, square]);
    let results = geo::polygons(&multi);
    assert_eq!(results.len(), 4);
    assert!(results[0].is_ok() && results[3].is_ok());
    assert!(matches!(results[1], Err(Error::Invalid(_))));
    assert_eq!(
        results[2].as_ref().unwrap_err().to_string(),
        "polygon 2, outer ring, vertex 2: y coordinate `inf` is not a finite number"
    );
    let raw = geo::raw_polygons(&multi);
    assert!(raw.unwrap_err().to_string().starts_with("polygon 2, "));
}
