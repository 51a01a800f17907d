//! Pipelines (docs/pipelines.md): feature identity kept, one Feature per input feature, GeoJSON
//! Lines out as a filter, the output format from `-o`'s extension, bounded memory.

use crate::util::{json, run};
use serde_json::Value;
use std::io::{BufRead, BufReader, Write};
use std::process::{Command, Stdio};

/// Three features: a Polygon with an id and properties (a T-junction: 2 triangles), a
/// two-part MultiPolygon, a null geometry; then one that is not a polygon, one that is invalid.
const LAYER: [&str; 5] = [
    r#"{"type": "Feature", "id": "b-1", "properties": {"name": "Hôtel", "h": 12.50, "big": 1e400}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [2, 0], [2, 2], [0, 2], [0, 0]]]}}"#,
    r#"{"type": "Feature", "id": 7, "properties": null, "geometry": {"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]], [[[5, 5], [6, 5], [6, 6], [5, 6]]]]}}"#,
    r#"{"type": "Feature", "id": 8, "properties": {"k": 2}, "geometry": null}"#,
    r#"{"type": "Feature", "id": 9, "geometry": {"type": "Point", "coordinates": [0, 0]}}"#,
    r#"{"type": "Feature", "id": [10], "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 1], [1, 0], [0, 1]]]}}"#,
];

fn collection() -> String {
    format!(
        "{{\"type\": \"FeatureCollection\", \"features\": [\n{}\n]}}\n",
        LAYER.join(",\n")
    )
}

fn lines() -> String {
    LAYER.join("\n") + "\n"
}

/// The `minitri` member of a Feature's properties.
fn facts(feature: &Value) -> &Value {
    &feature["properties"]["minitri"]
}

#[test]
fn geojson_gives_one_feature_per_input_feature_with_its_id_and_properties() {
    for (input, from_lines) in [(collection(), false), (lines(), true)] {
        let (code, out, err) = run(&["--to", "geojson"], Some(&input));
        assert_eq!(code, 1, "the null, the Point and the bow tie fail: {err}");
        let doc = json(&out);
        let features = doc["features"].as_array().unwrap();
        assert_eq!(features.len(), 5, "one per input feature: {out}");
        let ids: Vec<String> = features.iter().map(|f| f["id"].to_string()).collect();
        assert_eq!(ids, ["\"b-1\"", "7", "8", "9", "[10]"]);
        for (k, f) in features.iter().enumerate() {
            assert_eq!(facts(f)["feature"], k, "{f}");
            assert_eq!(facts(f)["line"].as_u64().is_some(), from_lines, "{f}");
        }
        // The properties as written (1e400 and 12.50 are not even f64s), minitri's added.
        assert!(
            out.contains(
                r#""properties": {"name": "Hôtel", "h": 12.50, "big": 1e400, "minitri": {"#
            ),
            "{out}"
        );
        let first = &features[0];
        // A collection of Polygons (OGC: the triangles share edges, which the polygons of a
        // valid MultiPolygon may not).
        assert_eq!(first["geometry"]["type"], "GeometryCollection");
        let members = first["geometry"]["geometries"].as_array().unwrap();
        assert_eq!(members.len(), 2);
        assert!(members.iter().all(|m| m["type"] == "Polygon"));
        assert_eq!(facts(first)["triangle_count"], 2);
        assert_eq!(facts(first)["degenerate_count"], 1);
        assert_eq!(facts(first)["optimal"], true);
        assert_eq!(facts(first)["ok"], true);
        // The MultiPolygon stays one feature: its two parts' triangles in one geometry.
        let multi = &features[1];
        assert_eq!(facts(multi)["parts"], 2);
        assert_eq!(facts(multi)["triangle_count"], 3);
        assert_eq!(multi["geometry"]["geometries"].as_array().unwrap().len(), 3);
        assert_eq!(multi["properties"].as_object().unwrap().len(), 1);
        // A null geometry is reported, not skipped; so are the Point and the bow tie.
        for (k, needle) in [
            (2, "\"geometry\" is null: nothing to triangulate"),
            (
                3,
                "expected a Polygon or MultiPolygon geometry, found \"Point\"",
            ),
            (4, "self-intersection"),
        ] {
            let f = &features[k];
            assert_eq!(f["geometry"], Value::Null, "{f}");
            assert_eq!(facts(f)["ok"], false, "{f}");
            let errors: Vec<&str> = facts(f)["errors"]
                .as_array()
                .unwrap()
                .iter()
                .map(|e| e.as_str().unwrap())
                .collect();
            let errors = errors.join("; ");
            assert!(errors.contains(needle), "{k}: {errors}");
            assert!(err.contains(needle), "{err}");
        }
        assert_eq!(features[2]["properties"]["k"], 2);
    }
}

#[test]
fn errors_and_results_are_numbered_by_feature_and_part() {
    let (code, out, err) = run(&[], Some(&collection()));
    assert_eq!(code, 1);
    let doc = json(&out);
    let polygons = doc["polygons"].as_array().unwrap();
    let numbered: Vec<(Value, Value, Value)> = polygons
        .iter()
        .map(|p| (p["feature"].clone(), p["part"].clone(), p["id"].clone()))
        .collect();
    assert_eq!(
        numbered,
        [
            (0.into(), Value::Null, "b-1".into()),
            (1.into(), 0.into(), 7.into()),
            (1.into(), 1.into(), 7.into()),
        ]
    );
    assert_eq!(polygons[0]["properties"]["name"], "Hôtel");
    let errors: Vec<(Value, Value)> = doc["errors"]
        .as_array()
        .unwrap()
        .iter()
        .map(|e| (e["feature"].clone(), e["id"].clone()))
        .collect();
    assert_eq!(
        errors,
        [
            (2.into(), 8.into()),
            (3.into(), 9.into()),
            (4.into(), serde_json::json!([10]))
        ]
    );
    // Standard error names features the same way, whether reading or validating failed.
    for line in [
        "minitri: -: feature 2: \"geometry\" is null: nothing to triangulate",
        "minitri: -: feature 3: expected a Polygon or MultiPolygon geometry",
        "minitri: -: feature 4: self-intersection",
    ] {
        assert!(err.contains(line), "{line}\n{err}");
    }
}

/// A GeometryCollection feature with a Point among its polygons (issue 24 point 8), then a
/// Polygon feature.
const COLLECTION_LAYER: [&str; 2] = [
    r#"{"type": "Feature", "id": "gc", "geometry": {"type": "GeometryCollection", "geometries": [{"type": "Point", "coordinates": [1, 2]}, {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}, {"type": "MultiPolygon", "coordinates": [[[[5, 5], [6, 5], [5, 6]]], [[[8, 8], [9, 8], [8, 9]]]]}]}}"#,
    r#"{"type": "Feature", "id": "p", "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [2, 0], [2, 2], [0, 2]]]}}"#,
];

#[test]
fn a_collection_member_that_is_not_a_polygon_is_a_failed_part_of_its_feature() {
    let collection = format!(
        "{{\"type\": \"FeatureCollection\", \"features\": [\n{}\n]}}\n",
        COLLECTION_LAYER.join(",\n")
    );
    let lines = COLLECTION_LAYER.join("\n") + "\n";
    for (input, name) in [(collection, "feature 0"), (lines, "line 1, column 1")] {
        let message = format!(
            "{name}, geometry 0: expected a Polygon or MultiPolygon geometry, found \"Point\""
        )
        .replace("column 1, geometry", "column 1: geometry");
        // JSON: the collection's polygons are parts 1 to 3 of feature 0, the Point its part 0.
        let (code, out, err) = run(&[], Some(&input));
        assert_eq!(code, 1, "not wholly processed: {err}");
        assert_eq!(err, format!("minitri: -: {message}\n"));
        let doc = json(&out);
        let numbered: Vec<(Value, Value, Value)> = doc["polygons"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| (p["index"].clone(), p["feature"].clone(), p["part"].clone()))
            .collect();
        assert_eq!(
            numbered,
            [
                (0.into(), 0.into(), 1.into()),
                (1.into(), 0.into(), 2.into()),
                (2.into(), 0.into(), 3.into()),
                (3.into(), 1.into(), Value::Null),
            ]
        );
        let mut error = doc["errors"][0].clone();
        error.as_object_mut().unwrap().remove("line");
        assert_eq!(
            error,
            serde_json::json!({"source": "-", "feature": 0, "part": 0, "id": "gc", "message": message})
        );
        assert_eq!(doc["errors"].as_array().unwrap().len(), 1);
        // GeoJSON: feature 0's Feature carries its triangles and the Point's error.
        for to in ["geojson", "geojsonl"] {
            let (code, out, _) = run(&["--from", "geojson", "-", "--to", to], Some(&input));
            assert_eq!(code, 1);
            let features: Vec<Value> = match to {
                "geojson" => json(&out)["features"].as_array().unwrap().clone(),
                _ => out.lines().map(json).collect(),
            };
            assert_eq!(features.len(), 2, "one per input feature: {out}");
            let gc = &features[0];
            assert_eq!(gc["id"], "gc");
            assert_eq!(facts(gc)["ok"], false);
            assert_eq!(facts(gc)["parts"], 4);
            assert_eq!(facts(gc)["triangle_count"], 3);
            assert_eq!(gc["geometry"]["geometries"].as_array().unwrap().len(), 3);
            assert_eq!(
                facts(gc)["errors"],
                serde_json::json!([format!("part 0: {message}")])
            );
            assert_eq!(facts(&features[1])["ok"], true);
        }
    }
    // WKT: the polygons triangulated, the Point reported at its line and column.
    let wkt =
        "GEOMETRYCOLLECTION (POINT (1 2),\n  POLYGON ((0 0, 1 0, 0 1)), LINESTRING (0 0, 1 1))";
    let (code, out, err) = run(&["--from", "wkt"], Some(wkt));
    assert_eq!(code, 1);
    let expected = "expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION, found";
    assert_eq!(
        err,
        format!(
            "minitri: -: line 1, column 21: {expected} POINT\nminitri: -: line 2, column 30: {expected} LINESTRING\n"
        )
    );
    let doc = json(&out);
    assert_eq!(doc["polygons"].as_array().unwrap().len(), 1);
    assert_eq!(doc["polygons"][0]["index"], 0);
    assert_eq!(
        doc["errors"][0],
        serde_json::json!({"source": "-", "message": format!("line 1, column 21: {expected} POINT")})
    );
}

#[test]
fn geojsonl_is_a_filter_one_line_out_per_line_in() {
    let mut input = lines();
    input.push_str("not json\n\n"); // a line that is not JSON, then a blank line (no feature)
    let (code, out, err) = run(
        &["--from", "geojson", "-", "--to", "geojsonl"],
        Some(&input),
    );
    assert_eq!(code, 1, "{err}");
    let out: Vec<Value> = out.lines().map(json).collect();
    assert_eq!(out.len(), 6, "one line per non-blank line in");
    let lines: Vec<u64> = out
        .iter()
        .map(|f| facts(f)["line"].as_u64().unwrap())
        .collect();
    assert_eq!(lines, [1, 2, 3, 4, 5, 6]);
    assert_eq!(out[0]["id"], "b-1");
    assert_eq!(out[5]["id"], Value::Null);
    assert!(
        facts(&out[5])["errors"][0]
            .as_str()
            .unwrap()
            .starts_with("line 6, column 2: invalid JSON: expected ident"),
        "{}",
        facts(&out[5])
    );
    // The same Features as --to geojson, in the same order.
    let (_, whole, _) = run(&["--from", "geojson", "-", "--to", "geojson"], Some(&input));
    assert_eq!(json(&whole)["features"].as_array().unwrap(), &out);
}

/// [`LAYER`] and a MultiPolygon whose second part is a bow tie (a partly failed feature).
fn layer_with_a_partial_failure() -> Vec<&'static str> {
    let mut layer = LAYER.to_vec();
    layer.push(
        r#"{"type": "Feature", "id": "half", "properties": {"note": "a, \"b\"\nc"}, "geometry": {"type": "MultiPolygon", "coordinates": [[[[0, 0], [1, 0], [0, 1]]], [[[0, 0], [1, 1], [1, 0], [0, 1]]]]}}"#,
    );
    layer
}

/// The `--to wkt` line of each feature of [`layer_with_a_partial_failure`].
const LAYER_WKT: [&str; 6] = [
    "GEOMETRYCOLLECTION (POLYGON ((0 2, 0 0, 2 0, 0 2)), POLYGON ((2 2, 0 2, 2 0, 2 2)))",
    "GEOMETRYCOLLECTION (POLYGON ((0 1, 0 0, 1 0, 0 1)), POLYGON ((5 6, 5 5, 6 5, 5 6)), POLYGON ((6 6, 5 6, 6 5, 6 6)))",
    "GEOMETRYCOLLECTION EMPTY",
    "GEOMETRYCOLLECTION EMPTY",
    "GEOMETRYCOLLECTION EMPTY",
    "GEOMETRYCOLLECTION (POLYGON ((0 1, 0 0, 1 0, 0 1)))",
];

/// The layer as a FeatureCollection and as GeoJSON Lines (with a line that is not JSON and a
/// blank line, which is no feature).
fn layer_inputs() -> [(String, bool); 2] {
    let layer = layer_with_a_partial_failure();
    [
        (
            format!(
                "{{\"type\": \"FeatureCollection\", \"features\": [\n{}\n]}}\n",
                layer.join(",\n")
            ),
            false,
        ),
        (layer.join("\n") + "\n\nnot json\n", true),
    ]
}

#[test]
fn wkt_is_one_line_per_input_feature_in_order_empty_where_nothing_was_triangulated() {
    for (input, from_lines) in layer_inputs() {
        let (code, out, err) = run(&["--from", "geojson", "-", "--to", "wkt"], Some(&input));
        assert_eq!(code, 1, "{err}");
        let mut want = LAYER_WKT.to_vec();
        if from_lines {
            want.push("GEOMETRYCOLLECTION EMPTY"); // the line that is not JSON
        }
        assert_eq!(out.lines().collect::<Vec<_>>(), want, "{out}");
        // The failed part's error still goes to standard error.
        assert!(
            err.contains(if from_lines {
                "minitri: -: line 6, part 1: self-intersection"
            } else {
                "minitri: -: feature 5, part 1: self-intersection"
            }),
            "{err}"
        );
        // Each line is the geometry of the feature's --to geojson Feature.
        let (_, geo, _) = run(
            &["--from", "geojson", "-", "--to", "geojsonl"],
            Some(&input),
        );
        let features: Vec<Value> = geo.lines().map(json).collect();
        assert_eq!(features.len(), want.len());
        for (f, line) in features.iter().zip(&want) {
            let triangles = f["geometry"]["geometries"].as_array().map_or(0, Vec::len);
            assert_eq!(line.matches("((").count(), triangles, "{line} vs {f}");
        }
    }
}

/// Reads RFC 4180 CSV: records ending in CRLF, fields in double quotes when they hold a comma,
/// a quote or a line break, quotes doubled inside. Panics on anything else.
fn read_csv(text: &str) -> Vec<Vec<String>> {
    let mut records = Vec::new();
    let (mut record, mut field) = (Vec::new(), String::new());
    let mut chars = text.chars().peekable();
    let mut quoted = false;
    while let Some(c) = chars.next() {
        match (quoted, c) {
            (true, '"') if chars.peek() == Some(&'"') => {
                chars.next();
                field.push('"');
            }
            (true, '"') => {
                quoted = false;
                let next = chars.peek().copied();
                assert!(matches!(next, Some(',' | '\r')), "text after a quote");
            }
            (true, c) => field.push(c),
            (false, '"') => {
                assert!(field.is_empty(), "a quote inside an unquoted field");
                quoted = true;
            }
            (false, ',') => record.push(std::mem::take(&mut field)),
            (false, '\r') => {
                assert_eq!(chars.next(), Some('\n'), "records end in CRLF");
                record.push(std::mem::take(&mut field));
                records.push(std::mem::take(&mut record));
            }
            (false, '\n') => panic!("a bare LF outside quotes"),
            (false, c) => field.push(c),
        }
    }
    assert!(
        !quoted && record.is_empty() && field.is_empty(),
        "ends inside a record"
    );
    records
}

#[test]
fn csv_is_one_row_per_input_feature_with_its_id_and_properties_as_written() {
    for (input, from_lines) in layer_inputs() {
        let (code, out, err) = run(&["--from", "geojson", "-", "--to", "csv"], Some(&input));
        assert_eq!(code, 1, "{err}");
        let records = read_csv(&out);
        assert_eq!(
            records[0].join(","),
            "WKT,source,feature,line,id,properties,ok,algorithm,parts,triangle_count,\
             degenerate_count,pseudotriangle_count,optimal,errors"
        );
        let rows = &records[1..];
        assert_eq!(rows.len(), if from_lines { 7 } else { 6 }, "{out}");
        let column = |name: &str| -> Vec<&str> {
            let k = records[0].iter().position(|c| c == name).unwrap();
            rows.iter().map(|r| r[k].as_str()).collect()
        };
        // The WKT column is --to wkt's lines; the properties are the JSON as written.
        assert_eq!(column("WKT")[..6], LAYER_WKT);
        assert_eq!(column("feature")[..6], ["0", "1", "2", "3", "4", "5"]);
        // A string id as its text (what a join compares), anything else as written.
        assert_eq!(column("id")[..6], ["b-1", "7", "8", "9", "[10]", "half"]);
        assert_eq!(
            column("properties")[..6],
            [
                r#"{"name": "Hôtel", "h": 12.50, "big": 1e400}"#,
                "null",
                r#"{"k": 2}"#,
                "",
                "{}",
                r#"{"note": "a, \"b\"\nc"}"#,
            ]
        );
        assert_eq!(
            column("ok")[..6],
            ["true", "true", "false", "false", "false", "false"]
        );
        assert_eq!(column("parts")[..6], ["1", "2", "1", "1", "1", "2"]);
        assert_eq!(column("triangle_count")[..6], ["2", "3", "", "", "", "1"]);
        assert_eq!(column("degenerate_count")[..6], ["1", "0", "", "", "", "0"]);
        assert_eq!(column("optimal")[..6], ["true", "true", "", "", "", "true"]);
        assert_eq!(column("algorithm")[0], "minitri");
        assert!(column("pseudotriangle_count").iter().all(|c| c.is_empty()));
        let errors = column("errors");
        let name = |k: usize| match from_lines {
            true => format!("line {}", k + 1),
            false => format!("feature {k}"),
        };
        assert_eq!(
            errors[2],
            format!("{}: \"geometry\" is null: nothing to triangulate", name(2))
        );
        assert!(
            errors[4].starts_with("self-intersection: "),
            "{}",
            errors[4]
        );
        assert!(
            errors[5].starts_with("part 1: self-intersection: "),
            "{}",
            errors[5]
        );
        let lines = column("line");
        if from_lines {
            assert_eq!(lines, ["1", "2", "3", "4", "5", "6", "8"]);
            assert_eq!(column("id")[6], "", "a line that is not JSON has no id");
            assert_eq!(column("WKT")[6], "GEOMETRYCOLLECTION EMPTY");
        } else {
            assert!(lines.iter().all(|l| l.is_empty()));
        }
    }
}

#[test]
fn csv_rows_of_wkt_input_are_its_polygons_and_pseudotriangles_have_their_column() {
    let wkt = "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 2 1, 0 4)), POINT (1 2), \
               POLYGON ((0 0, 2 2, 2 0, 0 2)))";
    let (code, out, err) = run(&["--from", "wkt", "-a", "pseudo", "--to", "csv"], Some(wkt));
    assert_eq!(code, 1, "{err}");
    let records = read_csv(&out);
    let rows: Vec<String> = records[1..].iter().map(|r| r[..13].join("|")).collect();
    assert_eq!(
        rows,
        [
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 2 1, 0 4, 0 0)))|-|0||||true|pseudo|1|||1|false",
            // The Point is no polygon: a row about the input, without feature or geometry.
            "|-|||||false||1||||",
            "GEOMETRYCOLLECTION EMPTY|-|1||||false||1||||",
        ]
    );
    assert!(records[2][13].contains("found POINT"), "{out}");
    // --to wkt: a line per polygon, none for the Point.
    let (_, out, _) = run(&["--from", "wkt", "-a", "pseudo", "--to", "wkt"], Some(wkt));
    assert_eq!(
        out,
        "GEOMETRYCOLLECTION (POLYGON ((0 0, 4 0, 2 1, 0 4, 0 0)))\nGEOMETRYCOLLECTION EMPTY\n"
    );
}

#[test]
fn the_old_geojson_output_is_one_feature_per_triangle() {
    let (code, out, err) = run(&["--to", "geojson-triangles"], Some(LAYER[0]));
    assert_eq!(code, 0, "{err}");
    let features = json(&out)["features"].as_array().unwrap().clone();
    assert_eq!(features.len(), 2);
    assert_eq!(features[1]["properties"]["triangle"], 1);
}

#[test]
fn the_output_format_follows_the_file_name_unless_told_otherwise() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in.geojsonl");
    std::fs::write(&input, LAYER[..2].join("\n") + "\n").unwrap();
    let input = input.to_str().unwrap();
    let path = |name: &str| dir.path().join(name).to_str().unwrap().to_string();
    for (name, starts) in [
        ("a.geojson", "{\"type\": \"FeatureCollection\""),
        ("a.geojsonl", "{\"type\": \"Feature\""),
        ("a.ndjson", "{\"type\": \"Feature\""),
        ("a.wkt", "GEOMETRYCOLLECTION"),
        ("a.csv", "WKT,source,feature,"),
        ("a.CSV", "WKT,source,feature,"),
        ("a.svg", "<svg"),
        ("a.json", "{\n  \"polygons\""),
        ("a.out", "{\n  \"polygons\""),
    ] {
        let (code, _, err) = run(&[input, "-o", &path(name)], None);
        assert_eq!(code, 0, "{name}: {err}");
        let text = std::fs::read_to_string(path(name)).unwrap();
        assert!(
            text.trim_start_matches(r#"<?xml version="1.0" encoding="UTF-8"?>"#)
                .trim_start()
                .starts_with(starts),
            "{name}: {text}"
        );
    }
    let (code, _, _) = run(
        &[input, "-o", &path("b.geojson"), "--to", "geojson-triangles"],
        None,
    );
    assert_eq!(code, 0, "the per-triangle GeoJSON is GeoJSON too");
    let (code, out, err) = run(&[input, "-o", &path("c.svg"), "--to", "wkt"], None);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains("--to wkt conflicts with the output file's extension .svg"),
        "{err}"
    );
    assert!(!dir.path().join("c.svg").exists());
    // .csv stands for --to csv: --to wkt contradicts it, --to csv agrees.
    let (code, out, err) = run(&[input, "-o", &path("d.csv"), "--to", "wkt"], None);
    assert_eq!((code, out.as_str()), (2, ""));
    assert!(
        err.contains(
            "--to wkt conflicts with the output file's extension .csv (which stands for --to csv)"
        ),
        "{err}"
    );
    assert!(!dir.path().join("d.csv").exists());
    let (code, _, err) = run(&[input, "-o", &path("e.csv"), "--to", "csv"], None);
    assert_eq!(code, 0, "{err}");
    let rows = std::fs::read_to_string(path("e.csv")).unwrap();
    assert_eq!(
        read_csv(&rows).len(),
        3,
        "a header and a row per feature: {rows}"
    );
}

/// A building-like line: a rectangle with a notch (8 vertices), `k` as id.
fn building(k: u64) -> String {
    let (x, y) = ((k % 1000) * 20, (k / 1000) * 20);
    let p = |dx: u64, dy: u64| format!("[{}, {}]", x + dx, y + dy);
    format!(
        "{{\"type\": \"Feature\", \"id\": {k}, \"properties\": {{\"k\": {k}}}, \"geometry\": {{\"type\": \"Polygon\", \"coordinates\": [[{}, {}, {}, {}, {}, {}, {}, {}]]}}}}\n",
        p(0, 0), p(10, 0), p(10, 4), p(6, 4), p(6, 10), p(3, 10), p(0, 10), p(0, 0)
    )
}

/// Streams `n` generated lines through the filter; returns (lines out, peak resident KiB
/// polled from /proc while it runs).
fn stream_through(n: u64) -> (u64, u64) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_minitri"))
        .args(["--from", "geojson", "-", "--to", "geojsonl", "--jobs", "2"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .expect("run minitri");
    let pid = child.id();
    let mut stdin = child.stdin.take().unwrap();
    let writer = std::thread::spawn(move || {
        let mut out = std::io::BufWriter::new(&mut stdin);
        for k in 0..n {
            out.write_all(building(k).as_bytes()).unwrap();
        }
    });
    let peak = || {
        std::fs::read_to_string(format!("/proc/{pid}/status"))
            .ok()
            .and_then(|s| {
                let line = s.lines().find(|l| l.starts_with("VmHWM:"))?.to_string();
                line.split_whitespace().nth(1)?.parse::<u64>().ok()
            })
            .unwrap_or(0)
    };
    let (mut count, mut high) = (0, 0);
    for line in BufReader::new(child.stdout.take().unwrap()).lines() {
        let line = line.unwrap();
        assert!(line.contains(&format!("\"id\": {count},")), "{line}");
        count += 1;
        if count % 4096 == 0 {
            high = high.max(peak());
        }
    }
    writer.join().unwrap();
    assert!(child.wait().unwrap().success());
    (count, high)
}

/// The filter's memory does not grow with the input: 10^5 and 10^6 lines peak alike. Run by
/// .ci/run (`cargo test --test main -- --ignored pipelines::`); prints the figures.
#[test]
#[ignore = "streams 1.1 million lines (about a minute); run by .ci/run"]
fn the_filter_streams_in_bounded_memory() {
    let (small_lines, small) = stream_through(100_000);
    let (big_lines, big) = stream_through(1_000_000);
    assert_eq!((small_lines, big_lines), (100_000, 1_000_000));
    println!("peak resident memory: 10^5 lines {small} KiB, 10^6 lines {big} KiB");
    assert!(small > 0, "VmHWM not readable");
    assert!(
        big < small + small / 2 + 8 * 1024,
        "memory grows with the input: {small} KiB for 10^5 lines, {big} KiB for 10^6"
    );
}
