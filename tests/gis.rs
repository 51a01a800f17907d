//! Issue 36, GIS fidelity, through the binary: WKB and EWKB in (binary, hex as PostGIS prints
//! it), gzip-compressed inputs (files, directories, standard input, the caps on decompressed
//! bytes), formats minitri does not read named as such, GeoJSON Lines by `.jsonl` in a
//! directory; a FeatureCollection's `name` and `crs` kept in `--to geojson` (issue "GIS
//! fidelity", point 4).

use crate::util::{json, minitri, outcome, run};
use std::io::Write;

/// `--to wkt` of `args`, with exit status 0.
fn wkt(args: &[&str]) -> String {
    let (code, out, err) = run(&[&["--to", "wkt"], args].concat(), None);
    assert_eq!(code, 0, "{args:?}: {err}");
    out
}

/// Runs the binary with `args` and bytes on standard input: (exit code, stdout, stderr).
fn run_bytes(args: &[&str], stdin: Vec<u8>) -> (i32, String, String) {
    let mut cmd = minitri();
    cmd.args(args).write_stdin(stdin);
    outcome(&mut cmd)
}

/// `bytes` gzip-compressed.
fn gzip(bytes: &[u8]) -> Vec<u8> {
    let mut packed = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::default());
    packed.write_all(bytes).unwrap();
    packed.finish().unwrap()
}

#[test]
fn binary_wkb_and_postgis_hex_ewkb_give_the_triangles_of_the_wkt() {
    let from_wkt = wkt(&["fixtures/valid/u_shape.wkt"]);
    assert_eq!(from_wkt.lines().count(), 1);
    // Binary, by its name, by content on standard input, and with --from.
    assert_eq!(wkt(&["fixtures/gis/u_shape.wkb"]), from_wkt);
    let binary = std::fs::read(crate::util::fixtures().join("gis/u_shape.wkb")).unwrap();
    for args in [&["--to", "wkt"][..], &["--to", "wkt", "--from", "wkb"][..]] {
        let (code, out, err) = run_bytes(args, binary.clone());
        assert_eq!(
            (code, out.as_str()),
            (0, from_wkt.as_str()),
            "{args:?}: {err}"
        );
    }
    // Hex EWKB (SRID 4326), one geometry per line: the U-shape, then the decimal triangle
    // (0 0, 0.1 0.3, 0.2 0.6, 0 1), whose doubles are read as their shortest decimals: three
    // points on a line, so one triangle (as doubles they are not collinear).
    let (code, out, err) = run(&["fixtures/gis/postgis_ewkb.wkb"], None);
    assert_eq!(code, 0, "{err}");
    let doc = json(&out);
    let counts: Vec<_> = doc["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| (p["index"].clone(), p["triangle_count"].clone()))
        .collect();
    assert_eq!(counts, [(0.into(), 5.into()), (1.into(), 1.into())]);
    // Written back as EWKT, the SRID kept.
    let lines = wkt(&["fixtures/gis/postgis_ewkb.wkb"]);
    let lines: Vec<&str> = lines.lines().collect();
    assert_eq!(lines[0], format!("SRID=4326;{}", from_wkt.trim_end()));
    assert_eq!(
        lines[1],
        "SRID=4326;GEOMETRYCOLLECTION (POLYGON ((0 0, 0.2 0.6, 0 1, 0 0)))"
    );
    // The same hex on standard input, without a name: recognised by content.
    let hex = std::fs::read(crate::util::fixtures().join("gis/postgis_ewkb.wkb")).unwrap();
    let (code, out, _) = run_bytes(&["--to", "wkt"], hex);
    assert_eq!(code, 0);
    assert_eq!(out.lines().collect::<Vec<_>>(), lines);
}

#[test]
fn wkb_errors_name_the_line_or_byte_and_the_other_geometries_go_on() {
    let good =
        std::fs::read_to_string(crate::util::fixtures().join("gis/postgis_ewkb.wkb")).unwrap();
    let first = good.lines().next().unwrap();
    // A point (hex), a bad line, then the U-shape.
    let text = format!(
        "0101000000000000000000F03F000000000000F03F\n{}q\n{first}\n",
        &first[..6]
    );
    let (code, out, err) = run_bytes(&["--from", "wkb"], text.into_bytes());
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "minitri: -: line 1, column 1: expected a Polygon or MultiPolygon, found a Point\n\
         minitri: -: line 2, column 7: `q` is not a hexadecimal digit (one hex WKB geometry per line)\n"
    );
    assert_eq!(json(&out)["polygons"][0]["triangle_count"], 5);
    // Binary cut short: the error names the byte where the geometry starts.
    let binary = std::fs::read(crate::util::fixtures().join("gis/u_shape.wkb")).unwrap();
    let mut two = binary.clone();
    two.extend_from_slice(&binary[..binary.len() - 1]);
    let (code, out, err) = run_bytes(&["--from", "wkb"], two);
    assert_eq!(code, 1);
    assert!(
        err.starts_with(&format!(
            "minitri: -: byte {}: not a valid WKB geometry: ",
            binary.len() + 1
        )),
        "{err}"
    );
    assert_eq!(
        json(&out)["polygons"],
        serde_json::json!([]),
        "input not read to its end"
    );
}

#[test]
fn gzip_files_directories_and_standard_input_read_as_decompressed() {
    let plain = wkt(&["fixtures/valid/u_shape.wkt"]);
    assert_eq!(wkt(&["fixtures/gis/u_shape.wkt.gz"]), plain);
    // The extension before `.gz` decides: GeoJSON, its feature identity kept.
    let (code, out, err) = run(
        &["--to", "geojson", "fixtures/gis/u_shape.geojson.gz"],
        None,
    );
    assert_eq!(code, 0, "{err}");
    let doc = json(&out);
    assert_eq!(
        doc["features"][0]["properties"]["name"],
        "U-shape of the README"
    );
    assert_eq!(
        doc["features"][0]["properties"]["minitri"]["triangle_count"],
        5
    );
    // Standard input, by the magic bytes.
    let packed = gzip(b"POLYGON ((0 0, 0.1 0.3, 0.2 0.6, 0 1))");
    let (code, out, _) = run_bytes(&["--to", "wkt"], packed);
    assert_eq!(
        (code, out.as_str()),
        (
            0,
            "GEOMETRYCOLLECTION (POLYGON ((0 0, 0.2 0.6, 0 1, 0 0)))\n"
        )
    );
    // A directory: the .gz files are read, by their inner extension; `b.gz` has none and `c.csv.gz`
    // an unknown one: skipped.
    let dir = tempfile::tempdir().unwrap();
    let shapes = dir.path().join("shapes");
    std::fs::create_dir(&shapes).unwrap();
    for name in ["u_shape.wkt.gz", "u_shape.geojson.gz", "u_shape.wkb"] {
        std::fs::copy(
            crate::util::fixtures().join("gis").join(name),
            shapes.join(name),
        )
        .unwrap();
    }
    std::fs::write(shapes.join("b.gz"), gzip(b"x")).unwrap();
    std::fs::write(shapes.join("c.csv.gz"), gzip(b"x")).unwrap();
    let out_dir = dir.path().join("out");
    let (code, _, err) = run(
        &[shapes.to_str().unwrap(), "-o", out_dir.to_str().unwrap()],
        None,
    );
    assert_eq!(code, 0, "{err}");
    let mut written: Vec<String> = std::fs::read_dir(&out_dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    assert_eq!(
        written,
        ["u_shape.geojson.json", "u_shape.json", "u_shape.wkt.json"]
    );
    assert!(
        err.contains("3 files") && err.contains("2 skipped"),
        "{err}"
    );
}

#[test]
fn a_gzip_bomb_stops_at_the_cap_on_decompressed_bytes() {
    // 50 MB of blanks after a polygon's start compress to about 50 kB; with the cap lowered to
    // 1 MB, reading stops there, and the message says that decompressed bytes are counted.
    let mut text = b"POLYGON ((0 0, 1 0, 0 1".to_vec();
    text.resize(50_000_000, b' ');
    text.extend_from_slice(b"))");
    let packed = gzip(&text);
    assert!(packed.len() < 100_000, "{}", packed.len());
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bomb.wkt.gz");
    std::fs::write(&path, &packed).unwrap();
    let path = path.to_str().unwrap();
    let mut cmd = minitri();
    cmd.env("MINITRI_INPUT_LIMIT_FOR_TESTS", "1000000")
        .arg(path);
    let (code, _, err) = outcome(&mut cmd);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        format!(
            "minitri: {path}: input too large: more than 1000000 bytes decompressed (the most \
             read as WKT or a vertex list)\n"
        )
    );
    // The same as GeoJSON: the cap on one feature, streamed.
    let mut text = br#"{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1]]"#.to_vec();
    text.resize(50_000_000, b' ');
    text.extend_from_slice(b"]}");
    let mut cmd = minitri();
    cmd.env("MINITRI_INPUT_LIMIT_FOR_TESTS", "1000000")
        .write_stdin(gzip(&text));
    let (code, _, err) = outcome(&mut cmd);
    assert_eq!(code, 1);
    assert!(
        err.contains("too large: more than 1000000 bytes in one GeoJSON value"),
        "{err}"
    );
    // And as WKB (binary bytes are read whole, under the same cap).
    let mut bytes = std::fs::read(crate::util::fixtures().join("gis/u_shape.wkb")).unwrap();
    bytes.resize(50_000_000, 0);
    let mut cmd = minitri();
    cmd.env("MINITRI_INPUT_LIMIT_FOR_TESTS", "1000000")
        .write_stdin(gzip(&bytes));
    let (code, _, err) = outcome(&mut cmd);
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "minitri: -: input too large: more than 1000000 bytes decompressed (the most read as WKB)\n"
    );
}

#[test]
fn formats_minitri_does_not_read_are_named_whatever_the_name_or_from() {
    let convert = "; convert it first, e.g. to GeoJSON with `ogr2ogr -f GeoJSON out.geojson INPUT`";
    for (bytes, what) in [
        (
            &b"<?xml version=\"1.0\"?>\n<kml>"[..],
            "not a format minitri reads (KML)",
        ),
        (
            &b"\xef\xbb\xbf  <FeatureCollection/>"[..],
            "not a format minitri reads (XML)",
        ),
        (
            &b"PAR1\x15\x04"[..],
            "not a format minitri reads (Parquet or GeoParquet)",
        ),
        (
            &b"PK\x03\x04\x14\x00"[..],
            "not a format minitri reads (a ZIP archive, such as KMZ or a zipped shapefile)",
        ),
    ] {
        for args in [&[][..], &["--from", "wkt"][..], &["--from", "geojson"][..]] {
            let (code, _, err) = run_bytes(args, bytes.to_vec());
            assert_eq!(code, 1, "{what}");
            assert_eq!(err, format!("minitri: -: {what}{convert}\n"), "{args:?}");
        }
    }
    // A KML file compressed: decompressed, then named.
    let (code, _, err) = run_bytes(&[], gzip(b"<kml xmlns=\"http://www.opengis.net/kml/2.2\">"));
    assert_eq!(code, 1);
    assert_eq!(
        err,
        format!("minitri: -: not a format minitri reads (KML){convert}\n")
    );
    for (bytes, name) in [
        (&b"BZh91AY&SY"[..], "bzip2"),
        (&b"\xfd7zXZ\x00\x00"[..], "xz"),
        (&b"\x28\xb5\x2f\xfd\x00"[..], "zstd"),
    ] {
        let (code, _, err) = run_bytes(&[], bytes.to_vec());
        assert_eq!(code, 1);
        assert_eq!(
            err,
            format!(
                "minitri: -: compressed with {name}, which minitri does not read (only gzip); \
                 decompress it first\n"
            )
        );
    }
}

#[test]
fn a_directory_reads_geojson_lines_by_every_extension_the_writer_uses() {
    let dir = tempfile::tempdir().unwrap();
    let shapes = dir.path().join("shapes");
    std::fs::create_dir(&shapes).unwrap();
    let line = r#"{"type":"Feature","id":7,"properties":null,"geometry":{"type":"Polygon","coordinates":[[[0,0],[2,0],[1,0.5],[2,2],[0,2],[0,0]]]}}"#;
    // Two lines each, the first of them written the way `--to geojsonl -o a.jsonl` writes.
    for name in ["a.jsonl", "b.ndjson", "c.geojsonl", "d.geojsons"] {
        std::fs::write(shapes.join(name), format!("{line}\n{line}\n")).unwrap();
    }
    let (code, out, err) = run(&["--to", "geojsonl", shapes.to_str().unwrap()], None);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.lines().count(), 8, "one line out per line in");
    for (k, out_line) in out.lines().enumerate() {
        let feature = json(out_line);
        assert_eq!(feature["id"], 7);
        assert_eq!(feature["properties"]["minitri"]["line"], (k % 2 + 1) as u64);
    }
    // What the writer writes to `.jsonl` reads back (line by line, by name).
    let written = dir.path().join("out.jsonl");
    let (code, _, err) = run(
        &[
            "-o",
            written.to_str().unwrap(),
            shapes.join("a.jsonl").to_str().unwrap(),
        ],
        None,
    );
    assert_eq!(code, 0, "{err}");
    let (code, out, err) = run(&[written.to_str().unwrap()], None);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        json(&out)["polygons"].as_array().unwrap().len(),
        6,
        "3 triangles a line"
    );
}

#[test]
fn a_directory_output_gets_its_format_from_to_never_from_its_name_new_or_existing() {
    let dir = tempfile::tempdir().unwrap();
    let shapes = dir.path().join("shapes");
    std::fs::create_dir(&shapes).unwrap();
    std::fs::copy("fixtures/valid/u_shape.wkt", shapes.join("u.wkt")).unwrap();
    let listing = |d: &std::path::Path| -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    };
    for exists in [false, true] {
        let out = dir.path().join(format!("d{exists}.svg"));
        if exists {
            std::fs::create_dir(&out).unwrap();
        }
        let (code, _, err) = run(
            &[shapes.to_str().unwrap(), "-o", out.to_str().unwrap()],
            None,
        );
        assert_eq!(code, 0, "{err}");
        assert_eq!(listing(&out), ["u.json"], "exists: {exists}");
        let text = std::fs::read_to_string(out.join("u.json")).unwrap();
        assert_eq!(json(&text)["polygons"][0]["triangle_count"], 5);
        // --to decides, and a --to that differs from the directory's "extension" is no conflict.
        let (code, _, err) = run(
            &[
                shapes.to_str().unwrap(),
                "-o",
                out.to_str().unwrap(),
                "--to",
                "wkt",
            ],
            None,
        );
        assert_eq!(code, 0, "{err}");
        assert_eq!(listing(&out), ["u.json", "u.wkt"], "exists: {exists}");
    }
    // Several files into a new directory named like a format: the same.
    let out = dir.path().join("two.geojson");
    let (code, _, err) = run(
        &[
            "fixtures/valid/u_shape.wkt",
            "fixtures/valid/l_shape.wkt",
            "-o",
            out.to_str().unwrap(),
        ],
        None,
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(listing(&out), ["l_shape.json", "u_shape.json"]);
    // One input file: `-o` names a file, and its extension decides.
    let file = dir.path().join("one.svg");
    let (code, _, err) = run(
        &["fixtures/valid/u_shape.wkt", "-o", file.to_str().unwrap()],
        None,
    );
    assert_eq!(code, 0, "{err}");
    assert!(std::fs::read_to_string(&file).unwrap().contains("<svg"));
}

/// The triangles of `--to wkt` lines, each as its sorted corners (start and turn aside).
fn triangles_of(wkt_lines: &str) -> Vec<Vec<String>> {
    let mut all: Vec<Vec<String>> = wkt_lines
        .split("POLYGON ((")
        .skip(1)
        .map(|rest| {
            let ring = &rest[..rest.find("))").expect("a closed ring")];
            let mut corners: Vec<String> = ring.split(", ").map(str::to_string).collect();
            assert_eq!(corners.first(), corners.last(), "closed: {ring}");
            corners.pop();
            corners.sort();
            corners
        })
        .collect();
    all.sort();
    all
}

#[test]
fn every_output_that_holds_geometry_reads_back_into_minitri() {
    let dir = tempfile::tempdir().unwrap();
    // A polygon with flat vertices, one with a hole and decimals, a GeoJSON Lines layer with a
    // MultiPolygon feature and a failed one.
    let layer = dir.path().join("layer.geojsonl");
    std::fs::write(
        &layer,
        "{\"type\":\"Feature\",\"id\":1,\"properties\":{},\"geometry\":{\"type\":\"MultiPolygon\",\"coordinates\":[[[[0,0],[0.5,0],[1,0],[0,1],[0,0]]],[[[5,5],[6,5],[6,6],[5,6],[5,5]]]]}}\n\
         {\"type\":\"Feature\",\"id\":2,\"properties\":{},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]}}\n",
    )
    .unwrap();
    let inputs = [
        "fixtures/valid/u_shape.wkt".to_string(),
        "fixtures/holes/decimal_collinear_holes.wkt".to_string(),
        layer.to_str().unwrap().to_string(),
    ];
    for input in &inputs {
        let (_, first, err) = run(&["--to", "wkt", input], None);
        let want = triangles_of(&first);
        assert!(!want.is_empty(), "{input}: {err}");
        for (to, name) in [
            ("geojson", "out.geojson"),
            ("geojsonl", "out.geojsonl"),
            ("geojson-triangles", "out.geojson"),
            ("wkt", "out.wkt"),
            ("csv", "out.csv"),
        ] {
            let out = dir.path().join(name);
            let out = out.to_str().unwrap();
            let _ = std::fs::remove_file(out);
            let (code, _, err) = run(&["--to", to, "-o", out, input], None);
            assert!(code == 0 || input.ends_with(".geojsonl"), "{to}: {err}");
            // Read back by its name, and by content on standard input: every triangle is a
            // polygon of one triangle, the same corners exactly as written.
            let text = std::fs::read_to_string(out).unwrap();
            // The layer's failed feature (a bow tie) is a Feature with a null geometry in
            // GeoJSON, which reads back as that feature's error; WKT and CSV skip its EMPTY.
            let failed = input.ends_with(".geojsonl") && (to == "geojson" || to == "geojsonl");
            let status = i32::from(failed);
            for args in [vec!["--to", "wkt", out], vec!["--to", "wkt"]] {
                let stdin = (args.len() == 2).then_some(text.as_str());
                let (code, back, err) = run(&args, stdin);
                assert_eq!(
                    code, status,
                    "{input} --to {to}, read back ({args:?}): {err}"
                );
                assert_eq!(triangles_of(&back), want, "{input} --to {to} ({args:?})");
            }
            // Each triangle read back is a polygon of its own, triangulated as one triangle
            // (a GeoJSON feature's triangles stay one feature: its parts).
            let (code, doc, err) = run(&[out], None);
            assert_eq!(code, status, "{err}");
            let polygons = json(&doc)["polygons"].as_array().unwrap().clone();
            assert_eq!(polygons.len(), want.len(), "{input} --to {to}");
            assert!(
                polygons.iter().all(|p| p["triangle_count"] == 1),
                "{input} --to {to}"
            );
        }
    }
}

/// The members of a FeatureCollection other than `features`, as JSON values.
fn collection_members(document: &str) -> serde_json::Map<String, serde_json::Value> {
    let mut members = json(document).as_object().unwrap().clone();
    members.remove("features");
    members
}

#[test]
fn a_gdal_collections_name_and_crs_are_carried_to_the_geojson_output_and_read_back() {
    let input = "fixtures/gis/gdal_3857.geojson";
    let text = std::fs::read_to_string(input).unwrap();
    let crs = r#"{ "type": "name", "properties": { "name": "urn:ogc:def:crs:EPSG::3857" } }"#;
    assert!(text.contains(crs));
    let (code, out, err) = run(&["--to", "geojson", input], None);
    assert_eq!((code, err.as_str()), (0, ""));
    // The members in GDAL's order, before the features, the crs byte for byte.
    assert!(
        out.starts_with(&format!(
            r#"{{"type": "FeatureCollection", "name": "parcels", "crs": {crs}, "features": ["#
        )),
        "{out}"
    );
    let members = collection_members(&out);
    assert_eq!(members, collection_members(&text));
    assert_eq!(json(&out)["features"].as_array().unwrap().len(), 2);
    // Read back by minitri: the same members again, the same triangles.
    let (code, again, err) = run(&["--to", "geojson", "--from", "geojson", "-"], Some(&out));
    assert_eq!(code, 0, "{err}");
    assert_eq!(collection_members(&again), members);
    let triangles = |doc: &str| -> Vec<serde_json::Value> {
        json(doc)["features"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["properties"]["minitri"]["triangle_count"].clone())
            .collect()
    };
    assert_eq!(triangles(&again), triangles(&out));
    // A collection whose "features" come before its members (read whole): carried too.
    let late = r#"{"features": [{"type": "Feature", "properties": null, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 1]]]}}], "crs": {"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::2154"}}, "name": "late", "type": "FeatureCollection"}"#;
    let (code, out, err) = run(&["--to", "geojson", "--from", "geojson", "-"], Some(late));
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        collection_members(&out),
        collection_members(&late.replace("\"features\": [", "\"features\": [0, "))
    );
    // Without them, nothing added.
    let (_, out, _) = run(&["--to", "geojson", "fixtures/valid/u_shape.geojson"], None);
    assert!(out.starts_with(r#"{"type": "FeatureCollection", "features": ["#));
    // GeoJSON Lines has no place for them: Features only.
    let (code, out, _) = run(&["--to", "geojsonl", input], None);
    assert_eq!(code, 0);
    assert!(out
        .lines()
        .all(|l| !l.contains("crs") && l.starts_with(r#"{"type": "Feature""#)));
}

#[test]
fn inputs_of_different_crs_in_one_output_keep_the_first_and_warn() {
    let input = "fixtures/gis/gdal_3857.geojson";
    let other = "fixtures/valid/u_shape.geojson";
    let warning = |of: &str, crs: &str, output: &str, from: &str| {
        format!(
            "minitri: warning: {of}: its \"crs\" ({crs}) is not the output's ({output}, from {from}): its features are written under the output's; give each input its own output (-o DIR)\n"
        )
    };
    let epsg = "urn:ogc:def:crs:EPSG::3857";
    let (code, out, err) = run(&["--to", "geojson", input, other], None);
    assert_eq!(code, 0);
    assert_eq!(collection_members(&out)["name"], "parcels");
    assert!(
        err.starts_with(&warning(other, "none (WGS 84)", epsg, input)),
        "{err}"
    );
    let (_, out, err) = run(&["--to", "geojson", other, input], None);
    assert!(!collection_members(&out).contains_key("crs"));
    assert!(
        err.starts_with(&warning(input, epsg, "none (WGS 84)", other)),
        "{err}"
    );
    // The same crs twice: no warning; --quiet: none either.
    let (_, _, err) = run(&["--to", "geojson", input, input], None);
    assert!(!err.contains("warning"), "{err}");
    let (_, _, err) = run(&["--to", "geojson", "-q", input, other], None);
    assert_eq!(err, "");
    // The warning as docs/errors.md shows it.
    let dir = tempfile::tempdir().unwrap();
    std::fs::copy(other, dir.path().join("a.geojson")).unwrap();
    std::fs::copy(input, dir.path().join("b.geojson")).unwrap();
    let mut cmd = minitri();
    cmd.current_dir(dir.path())
        .args(["--to", "geojson", "a.geojson", "b.geojson"]);
    let (code, _, err) = outcome(&mut cmd);
    assert_eq!(code, 0);
    let line = err
        .lines()
        .next()
        .unwrap()
        .strip_prefix("minitri: ")
        .unwrap();
    let catalogue = std::fs::read_to_string(crate::util::fixtures().join("../docs/errors.md"));
    assert!(
        catalogue.unwrap().contains(&format!("| 0 | `{line}` |")),
        "docs/errors.md has no row for {line}"
    );
    // Each input into its own output: each keeps its own.
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().to_str().unwrap();
    let (code, _, err) = run(&["--to", "geojson", "-q", input, other, "-o", out], None);
    assert_eq!(code, 0, "{err}");
    let written = std::fs::read_to_string(dir.path().join("gdal_3857.geojson")).unwrap();
    assert_eq!(
        collection_members(&written)["crs"]["properties"]["name"],
        epsg
    );
}

#[test]
fn an_ewkt_or_ewkb_srid_is_written_back_as_ewkt_and_as_a_geojson_crs() {
    let ewkt = "SRID=3857;POLYGON ((0 0, 2 0, 2 2, 1 1, 0 2, 0 0))\nPOLYGON ((0 0, 1 0, 0 1))\nsrid=2154;MULTIPOLYGON (((0 0, 1 0, 0 1)), ((5 5, 6 5, 5 6)))\n";
    let (code, out, err) = run(&["--to", "wkt", "--from", "wkt", "-"], Some(ewkt));
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        out,
        "SRID=3857;GEOMETRYCOLLECTION (POLYGON ((2 0, 2 2, 1 1, 2 0)), POLYGON ((0 0, 2 0, 0 2, 0 0)))\n\
         GEOMETRYCOLLECTION (POLYGON ((0 1, 0 0, 1 0, 0 1)))\n\
         SRID=2154;GEOMETRYCOLLECTION (POLYGON ((0 1, 0 0, 1 0, 0 1)))\n\
         SRID=2154;GEOMETRYCOLLECTION (POLYGON ((5 6, 5 5, 6 5, 5 6)))\n"
    );
    // Read back by minitri: each triangle of a line (a polygon of its own when read) keeps
    // its line's SRID.
    let srid = |line: &str| line.split_once(';').map(|(s, _)| s.to_string());
    let (code, again, err) = run(&["--to", "wkt", "--from", "wkt", "-"], Some(&out));
    assert_eq!(code, 0, "{err}");
    let again: Vec<_> = again.lines().map(srid).collect();
    let srid3857 = Some("SRID=3857".to_string());
    let srid2154 = Some("SRID=2154".to_string());
    assert_eq!(
        again,
        [srid3857.clone(), srid3857, None, srid2154.clone(), srid2154]
    );
    // Hex EWKB (PostGIS's SRID 4326) in, EWKT out, read back the same.
    let out = wkt(&["fixtures/gis/postgis_ewkb.wkb"]);
    assert!(
        out.lines()
            .all(|l| l.starts_with("SRID=4326;GEOMETRYCOLLECTION (")),
        "{out}"
    );
    let (code, again, _) = run(&["--to", "wkt", "--from", "wkt", "-"], Some(&out));
    assert_eq!(code, 0);
    assert!(again
        .lines()
        .all(|l| l.starts_with("SRID=4326;GEOMETRYCOLLECTION (")));
    assert_eq!(again.lines().count(), 6, "5 + 1 triangles, one a line");
    // --to geojson: the SRID as a crs, as GDAL names it, read back by minitri.
    let (code, out, err) = run(&["--to", "geojson", "fixtures/gis/postgis_ewkb.wkb"], None);
    assert_eq!((code, err.as_str()), (0, ""));
    let crs =
        serde_json::json!({"type": "name", "properties": {"name": "urn:ogc:def:crs:EPSG::4326"}});
    assert_eq!(collection_members(&out)["crs"], crs);
    let (code, again, _) = run(&["--to", "geojson", "--from", "geojson", "-"], Some(&out));
    assert_eq!(code, 0);
    assert_eq!(collection_members(&again)["crs"], crs);
    // Without an SRID: plain WKT, no crs.
    let (_, out, _) = run(&["--to", "wkt", "fixtures/valid/u_shape.wkt"], None);
    assert!(out.starts_with("GEOMETRYCOLLECTION ("));
}

/// The U-shape with a Z value for each vertex (vertex k at height `k.5`, the closing one
/// repeating vertex 0's), as WKT.
const U_SHAPE_Z: &str = "POLYGON Z ((3 2 0.5, 4 2 1.5, 5 2 2.5, 6 2 3.5, 6 3 4.5, 6 4 5.5, 5 4 6.5, 5 3 7.5, 4 3 8.5, 4 4 9.5, 3 4 10.5, 3 3 11.5, 3 2 0.5))";

/// The Z (and M) of each `x y z ...` corner of `--to wkt` text, keyed by `x y`.
fn heights(wkt_text: &str) -> Vec<(String, String)> {
    let start = wkt_text.find("((").map_or(0, |i| i + 2);
    let mut corners: Vec<(String, String)> = wkt_text[start..]
        .split(['(', ')', ','])
        .map(str::trim)
        .filter(|p| p.starts_with(|c: char| c.is_ascii_digit() || c == '-'))
        .map(|p| {
            let numbers: Vec<&str> = p.split(' ').collect();
            (numbers[..2].join(" "), numbers[2..].join(" "))
        })
        .collect();
    corners.sort();
    corners.dedup();
    corners
}

#[test]
fn z_and_m_values_are_carried_to_every_output_that_holds_them_and_read_back() {
    // The input's height of each point.
    let expected: Vec<(String, String)> = heights(U_SHAPE_Z);
    assert_eq!(expected.len(), 12);
    let plain = run(&["--to", "wkt", "fixtures/valid/u_shape.wkt"], None).1;
    let out = run(&["--to", "wkt", "-"], Some(U_SHAPE_Z));
    assert_eq!(out.0, 0, "{}", out.2);
    let with_z = out.1;
    assert!(
        with_z.starts_with("GEOMETRYCOLLECTION Z (POLYGON Z (("),
        "{with_z}"
    );
    // The same triangles as without Z (triangulated in x, y), each corner its input height.
    assert_eq!(
        triangles_of(&plain).len(),
        with_z.matches("POLYGON Z").count()
    );
    assert!(
        heights(&with_z)
            .iter()
            .all(|corner| expected.contains(corner)),
        "{with_z}"
    );
    // JSON: each input vertex's Z by its number, beside the triangles' vertex numbers.
    let doc = json(&run(&["-"], Some(U_SHAPE_Z)).1);
    let z: Vec<String> = doc["polygons"][0]["vertices_z"]
        .as_array()
        .unwrap()
        .iter()
        .map(ToString::to_string)
        .collect();
    let want: Vec<String> = (0..12).map(|k| format!("{k}.5")).collect();
    assert_eq!(z, want);
    assert!(doc["polygons"][0].get("vertices_m").is_none());
    // Every geometry output read back gives the same triangles with the same heights.
    for to in ["wkt", "csv", "geojson", "geojsonl", "geojson-triangles"] {
        let (code, text, err) = run(&["--to", to, "-"], Some(U_SHAPE_Z));
        assert_eq!(code, 0, "{to}: {err}");
        let (code, back, err) = run(&["--to", "wkt", "-"], Some(&text));
        assert_eq!(code, 0, "{to}: {err}");
        assert!(back.contains("POLYGON Z (("), "{to}: {back}");
        assert!(
            heights(&back).iter().all(|c| expected.contains(c)),
            "{to}: {back}"
        );
    }
    // GeoJSON positions [x, y, z] in and out.
    let geojson = r#"{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0, 10.25], [4, 0, 11], [4, 4, 12], [2, 2, 13], [0, 4, 14], [0, 0, 10.25]]]}}"#;
    let (code, out, err) = run(&["--to", "geojson", "-"], Some(geojson));
    assert_eq!(code, 0, "{err}");
    assert!(
        out.contains("[0, 0, 10.25]") && out.contains("[2, 2, 13]"),
        "{out}"
    );
    // M and ZM: WKT keeps them (NaN, "no value", too), JSON lists them as vertices_m.
    let (_, out, _) = run(
        &["--to", "wkt", "-"],
        Some("POLYGON M ((0 0 1, 4 0 2, 4 4 NaN, 0 4 4))"),
    );
    assert!(
        out.starts_with("GEOMETRYCOLLECTION M (POLYGON M (("),
        "{out}"
    );
    assert!(out.contains("4 4 NaN"), "{out}");
    let doc = json(
        &run(
            &["-"],
            Some("POLYGON ZM ((0 0 1 5, 4 0 2 6, 4 4 3 7, 0 4 4 8))"),
        )
        .1,
    );
    assert_eq!(doc["polygons"][0]["vertices_z"].to_string(), "[1,2,3,4]");
    assert_eq!(doc["polygons"][0]["vertices_m"].to_string(), "[5,6,7,8]");
    // Hex WKB of a POLYGON Z (ISO code 1003), doubles read as their shortest decimals.
    let mut wkb = vec![1u8, 0xEB, 0x03, 0, 0, 1, 0, 0, 0, 5, 0, 0, 0];
    for [x, y, z] in [
        [0.0, 0.0, 0.1],
        [4.0, 0.0, 0.2],
        [4.0, 4.0, 0.3],
        [0.0, 4.0, 0.4],
        [0.0, 0.0, 0.1],
    ] {
        for c in [x, y, z] {
            wkb.extend(f64::to_le_bytes(c));
        }
    }
    let hex: String = wkb.iter().map(|b| format!("{b:02X}")).collect();
    let (code, out, err) = run(&["--to", "wkt", "-"], Some(&hex));
    assert_eq!(code, 0, "{err}");
    assert!(
        out.starts_with("GEOMETRYCOLLECTION Z (POLYGON Z (("),
        "{out}"
    );
    assert!(out.contains("4 4 0.3") && out.contains("0 0 0.1"), "{out}");
}

#[test]
fn positions_mixing_two_three_and_four_numbers_are_an_error_naming_where() {
    let wkt = "POLYGON ((0 0 1, 4 0 2, 4 4, 0 4 3))";
    let message =
        "line 1, column 25: this point has 2 coordinates but the polygon's first point has 3";
    crate::util::fails_with(&["--to", "wkt", "-"], wkt, message);
    let geojson = r#"{"type": "Polygon", "coordinates": [[[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1, 0], [2, 1, 0], [2, 2, 0]]]}"#;
    let message =
        "ring 1, position 0: this position has 3 numbers but the feature's first position has 2";
    crate::util::fails_with(&["--to", "wkt", "-"], geojson, message);
}

#[test]
fn the_per_feature_example_of_pipelines_md_is_what_the_binary_writes() {
    let doc = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/pipelines.md"),
    )
    .unwrap();
    let example = |start: &str| {
        doc.lines()
            .map(str::trim)
            .find(|l| l.starts_with(start))
            .unwrap_or_else(|| panic!("docs/pipelines.md has no line {start}"))
            .to_string()
    };
    let input = example(r#"{"type": "Feature", "id": "b-1", "properties""#);
    let expected = example(r#"{"type": "Feature", "id": "b-1", "geometry""#);
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("b.geojsonl"), format!("{input}\n")).unwrap();
    let mut cmd = minitri();
    cmd.current_dir(dir.path())
        .args(["--to", "geojsonl", "b.geojsonl"]);
    let (code, out, err) = outcome(&mut cmd);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out.trim_end(), expected);
}
