//! `--to geojson-triangles` and `--to wkt` (issue 6, item 3), read back with the `geojson` and `wkt`
//! crates as a GIS tool would, and checked against the JSON output of the same run.
//!
//! The reading crates give `f64` coordinates, so the triangle areas summed from them are compared
//! with the polygon's area within a relative tolerance (for that comparison only). Exactness of
//! the coordinates is checked on the text: every number in the output is the input decimal, as
//! the polygon's exact grid formats it.

use crate::util::{json, run};
use minitri::{Algorithm, Options, Polygon};
use serde_json::Value;
use std::collections::{HashMap, HashSet};
use std::str::FromStr;

/// Inputs covering a flat-vertex polygon, holes, GeoJSON input and a multi-polygon source.
const INPUTS: [&str; 5] = [
    "fixtures/valid/u_shape.wkt",
    "fixtures/valid/comb_clockwise.txt",
    "fixtures/holes/square_with_hole.wkt",
    "fixtures/holes/decimal_collinear_holes.wkt",
    "fixtures/holes/hole_with_flat_vertices.geojson",
];

/// Two good polygons around a bowtie, in one source.
const MULTI: &str = "MULTIPOLYGON (((0 0, 2 0, 2 1, 0 1)), ((0 0, 2 2, 2 0, 0 2)), \
                     ((0 0, 0.1 0.3, 0.2 0.6, 0.2 1, -0.5 1)))";

/// The valid polygons of `path`, by index in the source (read by the library itself).
fn polygons(path: &str) -> HashMap<u64, Polygon> {
    let full = crate::util::fixtures().join("..").join(path);
    let text = std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{path}: {e}"));
    let extension = full.extension().and_then(|e| e.to_str());
    let format = minitri::io::read::detect(extension, &text);
    let options = Options {
        algorithm: Algorithm::Ear,
        ..Options::default()
    };
    minitri::process(path, &text, format, &options)
        .into_iter()
        .filter_map(|o| Some((o.index? as u64, o.polygon?.fast()?.clone())))
        .collect()
}

/// The polygon's area from its stored points (outer ring counter-clockwise, holes clockwise).
fn area(polygon: &Polygon) -> f64 {
    let starts = polygon.ring_starts();
    let mut twice = 0.0;
    for (r, &start) in starts.iter().enumerate() {
        let end = starts.get(r + 1).copied().unwrap_or(polygon.len());
        for i in start..end {
            let j = if i + 1 == end { start } else { i + 1 };
            let [x0, y0] = polygon.grid().to_f64(polygon.point(i));
            let [x1, y1] = polygon.grid().to_f64(polygon.point(j));
            twice += x0 * y1 - x1 * y0;
        }
    }
    twice / 2.0
}

/// Twice the signed area of a closed ring of `f64` points.
fn twice_signed_area(ring: &[[f64; 2]]) -> f64 {
    ring.windows(2)
        .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
        .sum()
}

/// Checks a triangle ring read back: closed, 4 points, counter-clockwise; returns its area.
fn triangle_area(ring: &[[f64; 2]], what: &str) -> f64 {
    assert_eq!(ring.len(), 4, "{what}: a triangle's closed ring");
    assert_eq!(ring[0], ring[3], "{what}: closed");
    let twice = twice_signed_area(ring);
    assert!(twice > 0.0, "{what}: counter-clockwise, got {ring:?}");
    twice / 2.0
}

fn assert_close(got: f64, want: f64, what: &str) {
    assert!(
        (got - want).abs() <= 1e-9 * want.abs().max(1.0),
        "{what}: area {got} != {want}"
    );
}

/// The exact text of stored vertex `i`'s coordinates.
fn exact(polygon: &Polygon, id: u64) -> [String; 2] {
    let i = (0..polygon.len())
        .find(|&i| polygon.id(i) as u64 == id)
        .unwrap_or_else(|| panic!("vertex {id} is not kept"));
    let p = polygon.point(i);
    [polygon.grid().format(0, p.x), polygon.grid().format(1, p.y)]
}

/// The middle vertices of the degenerate triangles in the JSON output of one polygon.
fn degenerate_middles(p: &Value) -> HashSet<u64> {
    p["degenerate_triangles"]
        .as_array()
        .expect("degenerate_triangles")
        .iter()
        .map(|d| d[1].as_u64().expect("vertex"))
        .collect()
}

/// A triangle feature as read back: its ring and its properties.
type ReadFeature = (Vec<[f64; 2]>, serde_json::Map<String, Value>);

/// The triangles' rings and properties as the `geojson` crate reads the document, or `None`
/// when it holds a non-integer number.
///
/// This package enables serde_json's `arbitrary_precision` (for exact decimal input), and
/// feature unification hands it to the `geojson` crate too, whose coordinate visitor (1.0) has
/// no `visit_map`, the form such numbers then take: in this build it cannot read `0.5`, although
/// the same text reads fine without that feature. So decimal documents are checked through
/// serde_json alone (`as_f64`, and the exact text), integer ones through both.
fn read_with_geojson_crate(text: &str) -> Option<Vec<ReadFeature>> {
    let decimals = json(text)["features"]
        .as_array()
        .expect("features")
        .iter()
        .flat_map(|f| {
            f["geometry"]["coordinates"][0]
                .as_array()
                .expect("ring")
                .clone()
        })
        .any(|c| c[0].is_f64() || c[1].is_f64());
    if decimals {
        return None;
    }
    let collection = match geojson::GeoJson::from_str(text) {
        Ok(geojson::GeoJson::FeatureCollection(c)) => c,
        other => panic!("not a FeatureCollection: {other:?}"),
    };
    let read = collection
        .features
        .into_iter()
        .map(|feature| {
            let ring = match feature.geometry.map(|g| g.value) {
                Some(geojson::GeometryValue::Polygon { coordinates }) => {
                    assert_eq!(coordinates.len(), 1, "no holes");
                    coordinates[0].iter().map(|c| [c[0], c[1]]).collect()
                }
                other => panic!("not a Polygon: {other:?}"),
            };
            (ring, feature.properties.expect("properties"))
        })
        .collect();
    Some(read)
}

/// Runs `minitri --to FORMAT path`, with exit status 0 unless `code` says otherwise.
fn output(format: &str, path: &str, code: i32) -> String {
    let format = if format == "geojson" {
        "geojson-triangles"
    } else {
        format
    };
    let (got, out, err) = run(&["--to", format, path], None);
    assert_eq!(got, code, "{format} {path}: {err}");
    out
}

/// Writes the multi-polygon source to a temporary file and returns (dir guard, path).
fn multi() -> (tempfile::TempDir, String) {
    let dir = tempfile::tempdir().expect("tempdir");
    let path = dir.path().join("multi.wkt");
    std::fs::write(&path, MULTI).expect("write");
    let path = path.to_str().expect("utf-8 path").to_string();
    (dir, path)
}

#[test]
fn geojson_output_reads_back_as_the_json_triangles() {
    let (_dir, multi) = multi();
    let paths: Vec<&str> = INPUTS.iter().copied().chain([multi.as_str()]).collect();
    for path in paths {
        let code = if path == multi { 1 } else { 0 };
        let doc = json(&output("json", path, code));
        let text = output("geojson", path, code);
        let raw: Value = json(&text);
        let features = read_with_geojson_crate(&text);
        let polygons = polygons(path);
        let solved = doc["polygons"].as_array().expect("polygons");
        let total: usize = solved
            .iter()
            .map(|p| p["triangle_count"].as_u64().expect("count") as usize)
            .sum();
        let raw_features = raw["features"].as_array().expect("features");
        assert_eq!(
            raw_features.len(),
            total,
            "{path}: one feature per triangle"
        );
        if let Some(features) = &features {
            assert_eq!(features.len(), total, "{path}: read by the geojson crate");
        }
        let mut raw_features = raw_features.iter().enumerate();
        for p in solved {
            let index = p["index"].as_u64().expect("index");
            let polygon = &polygons[&index];
            let middles = degenerate_middles(p);
            let mut sum = 0.0;
            let mut seen_middles = Vec::new();
            for (k, tri) in p["triangles"]
                .as_array()
                .expect("triangles")
                .iter()
                .enumerate()
            {
                let what = format!("{path}: polygon {index} triangle {k}");
                let (f, raw) = raw_features.next().expect("a feature");
                let props = raw["properties"].as_object().expect("properties");
                assert_eq!(props["source"], Value::from(path), "{what}");
                assert_eq!(props["polygon"].as_u64(), Some(index), "{what}");
                assert_eq!(props["triangle"].as_u64(), Some(k as u64), "{what}");
                assert_eq!(
                    &props["vertices"], tri,
                    "{what}: the JSON output's vertices"
                );
                let on_side: Vec<u64> = props["on_side"]
                    .as_array()
                    .expect("on_side")
                    .iter()
                    .map(|v| v.as_u64().expect("vertex"))
                    .collect();
                assert_eq!(
                    props["vertex_on_side"],
                    Value::from(!on_side.is_empty()),
                    "{what}"
                );
                seen_middles.extend(on_side);
                assert_eq!(raw["type"], "Feature", "{what}");
                assert_eq!(raw["geometry"]["type"], "Polygon", "{what}");
                let rings = raw["geometry"]["coordinates"].as_array().expect("rings");
                assert_eq!(rings.len(), 1, "{what}: no holes");
                let ring: Vec<[f64; 2]> = rings[0]
                    .as_array()
                    .expect("ring")
                    .iter()
                    .map(|c| [0, 1].map(|a| c[a].as_f64().expect("a number")))
                    .collect();
                if let Some(features) = &features {
                    let (crate_ring, crate_props) = &features[f];
                    assert_eq!(crate_ring, &ring, "{what}: as the geojson crate reads it");
                    assert_eq!(crate_props, props, "{what}: as the geojson crate reads it");
                }
                sum += triangle_area(&ring, &what);
                // The exact text of every coordinate: the corners in the order of `vertices`.
                let coordinates = &raw["geometry"]["coordinates"][0];
                for c in 0..4 {
                    let id = tri[c % 3].as_u64().expect("vertex");
                    let text = [0, 1].map(|a| coordinates[c][a].to_string());
                    assert_eq!(text, exact(polygon, id), "{what}: corner {c}");
                }
            }
            assert_close(sum, area(polygon), &format!("{path}: polygon {index}"));
            // Every T-junction is on exactly one triangle's side, and nothing else is.
            seen_middles.sort_unstable();
            let mut want: Vec<u64> = middles.into_iter().collect();
            want.sort_unstable();
            assert_eq!(
                seen_middles, want,
                "{path}: polygon {index}: on_side vs degenerate middles"
            );
        }
    }
}

#[test]
fn wkt_output_is_one_geometrycollection_line_per_input_polygon_as_the_json_triangles() {
    let (_dir, multi) = multi();
    let paths: Vec<&str> = INPUTS.iter().copied().chain([multi.as_str()]).collect();
    for path in paths {
        let code = if path == multi { 1 } else { 0 };
        let doc = json(&output("json", path, code));
        let text = output("wkt", path, code);
        let polygons = polygons(path);
        let solved = doc["polygons"].as_array().expect("polygons");
        let failed: Vec<u64> = doc["errors"]
            .as_array()
            .expect("errors")
            .iter()
            .map(|e| e["index"].as_u64().expect("a polygon's error"))
            .collect();
        // `wkt` ignores trailing text, so each line is parsed alone and the lines are counted.
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(
            lines.len(),
            solved.len() + failed.len(),
            "{path}: one line per input polygon (each a feature of its own)"
        );
        assert_eq!(failed, if path == multi { vec![1] } else { vec![] });
        for &k in &failed {
            assert_eq!(
                lines[k as usize], "GEOMETRYCOLLECTION EMPTY",
                "{path}: line {k}"
            );
        }
        for p in solved {
            let index = p["index"].as_u64().expect("index");
            let line = &lines[index as usize];
            let what = format!("{path}: polygon {index}");
            let polygon = &polygons[&index];
            // A collection of polygons (OGC: the triangles share edges, so they may not be the
            // polygons of one valid MULTIPOLYGON).
            let parts: Vec<wkt::types::Polygon<f64>> = match wkt::Wkt::<f64>::from_str(line) {
                Ok(wkt::Wkt::GeometryCollection(c)) => c
                    .geometries()
                    .iter()
                    .map(|g| match g {
                        wkt::Wkt::Polygon(p) => p.clone(),
                        other => panic!("{what}: not a POLYGON: {other:?}"),
                    })
                    .collect(),
                other => panic!("{what}: not a GEOMETRYCOLLECTION: {other:?}"),
            };
            let triangles = p["triangles"].as_array().expect("triangles");
            assert_eq!(parts.len(), triangles.len(), "{what}: triangle_count");
            let mut sum = 0.0;
            for (k, part) in parts.iter().enumerate() {
                assert_eq!(part.rings().len(), 1, "{what}: triangle {k} has no holes");
                let ring: Vec<[f64; 2]> = part.rings()[0]
                    .coords()
                    .iter()
                    .map(|c| [c.x, c.y])
                    .collect();
                sum += triangle_area(&ring, &format!("{what}: triangle {k}"));
            }
            assert_close(sum, area(polygon), &what);
            // The exact text: the corners of each triangle in the order of the JSON output.
            let want: Vec<String> = triangles
                .iter()
                .map(|t| {
                    let corners: Vec<String> = (0..4)
                        .map(|c| exact(polygon, t[c % 3].as_u64().expect("vertex")).join(" "))
                        .collect();
                    format!("POLYGON (({}))", corners.join(", "))
                })
                .collect();
            assert_eq!(
                *line,
                format!("GEOMETRYCOLLECTION ({})", want.join(", ")),
                "{what}"
            );
        }
    }
}

#[test]
fn decimal_coordinates_come_out_exactly_in_geojson_and_wkt() {
    // (0 0, 0.1 0.3, 0.2 0.6) are collinear: 2 triangles, and 0.1 0.3 lies on a side.
    let input = "GEOMETRYCOLLECTION (POLYGON ((0 0, 0.1 0.3, 0.2 0.6, 0.2 1, -0.5 1)), \
                 POLYGON ((0 0, 0.3 0, 0.1 0.3)))";
    let (code, wkt_out, err) = run(&["--to", "wkt"], Some(input));
    assert_eq!(code, 0, "{err}");
    for text in ["0.1 0.3", "0.2 0.6", "-0.5 1", "0 0"] {
        assert!(wkt_out.contains(text), "{text} in {wkt_out}");
    }
    let (code, geo_out, err) = run(&["--to", "geojson-triangles"], Some(input));
    assert_eq!(code, 0, "{err}");
    for text in ["[0.1, 0.3]", "[0.2, 0.6]", "[-0.5, 1]", "[0, 0]"] {
        assert!(geo_out.contains(text), "{text} in {geo_out}");
    }
    for out in [&wkt_out, &geo_out] {
        assert!(
            !out.contains("00000") && !out.contains("99999"),
            "no binary floating point: {out}"
        );
    }
    assert!(
        !geo_out.contains("\"0.1\""),
        "numbers, not strings: {geo_out}"
    );
    assert_eq!(wkt_out.matches("((").count(), 3, "{wkt_out}");
    assert!(geo_out.contains("\"on_side\": [1]"), "{geo_out}");
}

#[test]
fn failed_polygons_get_no_triangle_feature_and_an_empty_wkt_line() {
    let bowtie = "POLYGON ((0 0, 2 2, 2 0, 0 2))";
    let (code, out, err) = run(&["--to", "wkt"], Some(bowtie));
    assert_eq!(
        (code, out.as_str()),
        (1, "GEOMETRYCOLLECTION EMPTY\n"),
        "{err}"
    );
    assert!(err.contains("self-intersection"), "{err}");
    // An input that cannot be read at all has no polygon, so no line.
    let (code, out, err) = run(&["--to", "wkt"], Some("POLYGON ((0 0, 1 0"));
    assert_eq!((code, out.as_str()), (1, ""), "{err}");
    let (code, out, err) = run(&["--to", "geojson-triangles"], Some(bowtie));
    assert_eq!(code, 1, "{err}");
    assert!(err.contains("self-intersection"), "{err}");
    match geojson::GeoJson::from_str(&out) {
        Ok(geojson::GeoJson::FeatureCollection(c)) => assert!(c.features.is_empty()),
        other => panic!("not an empty FeatureCollection: {other:?}"),
    }
}

#[test]
fn a_batch_mirrors_into_geojson_and_wkt_files() {
    let out = tempfile::tempdir().expect("tempdir");
    for (format, extension) in [("geojson", "geojson"), ("wkt", "wkt")] {
        let target = out.path().join(format);
        let target_str = target.to_str().expect("utf-8 path");
        let (code, _, err) = run(&["fixtures/holes", "-o", target_str, "--to", format], None);
        assert_eq!(code, 0, "{err}");
        for name in ["square_with_hole", "holes_in_a_row"] {
            let file = target.join(format!("{name}.{extension}"));
            let text = std::fs::read_to_string(&file)
                .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
            assert!(!text.is_empty(), "{}", file.display());
        }
        let geojson_input = target.join(format!("hole_with_flat_vertices.{extension}"));
        assert!(geojson_input.exists(), "{}", geojson_input.display());
    }
}
