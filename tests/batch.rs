//! Batches (issue 5, items 2 and 3): a directory mirrored into an output directory, bad files
//! among good ones, atomic outputs, the same bytes for any number of threads, streamed
//! newline-delimited GeoJSON, the summary line.

use crate::util::json;
use serde_json::Value;
use std::fs;
use std::path::{Path, PathBuf};

/// Runs the binary in `dir` (so that sources are named relative to it): (code, stdout, stderr).
fn run_in(dir: &Path, args: &[&str], stdin: Option<&str>) -> (i32, String, String) {
    let mut cmd = crate::util::minitri();
    cmd.current_dir(dir).args(args);
    if let Some(s) = stdin {
        cmd.write_stdin(s);
    }
    crate::util::outcome(&mut cmd)
}

/// Writes `files` (relative path, content) below `root`, creating directories.
fn write_tree(root: &Path, files: &[(&str, &str)]) {
    for (path, content) in files {
        let path = root.join(path);
        fs::create_dir_all(path.parent().unwrap()).unwrap();
        fs::write(path, content).unwrap();
    }
}

/// Every file below `root`, relative to it, sorted.
fn files_below(root: &Path) -> Vec<PathBuf> {
    fn walk(dir: &Path, root: &Path, out: &mut Vec<PathBuf>) {
        for entry in fs::read_dir(dir).unwrap() {
            let path = entry.unwrap().path();
            if path.is_dir() {
                walk(&path, root, out);
            } else {
                out.push(path.strip_prefix(root).unwrap().to_path_buf());
            }
        }
    }
    let mut out = Vec::new();
    walk(root, root, &mut out);
    out.sort();
    out
}

fn read_json(path: &Path) -> Value {
    json(&fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display())))
}

/// `fixtures/valid/u_shape.wkt`: 12 vertices, 5 triangles at least.
const U_SHAPE: &str = "POLYGON ((3 2, 4 2, 5 2, 6 2, 6 3, 6 4, 5 4, 5 3, 4 3, 4 4, 3 4, 3 3, 3 2))";
const BOWTIE: &str = "POLYGON ((0 0, 2 2, 2 0, 0 2))";
const TRIANGLE_VERTICES: &str = "0 0\n4 0\n0 4\n";

/// A sawtooth comb with `teeth` teeth and a bottom side through every integer point (collinear
/// vertices, so degenerate triangles), as GeoJSON coordinates.
fn comb(teeth: usize) -> String {
    let width = 2 * teeth;
    let mut points: Vec<(usize, usize)> = (0..=width).map(|x| (x, 0)).collect();
    points.push((width, 2));
    for i in (0..teeth).rev() {
        points.push((2 * i + 1, 1));
        points.push((2 * i, 2));
    }
    let ring: Vec<String> = points.iter().map(|(x, y)| format!("[{x}, {y}]")).collect();
    format!("[[{}]]", ring.join(", "))
}

/// `count` features, each a comb (one in seven a MultiPolygon of two).
fn features(count: usize) -> Vec<String> {
    (0..count)
        .map(|k| {
            let geometry = if k % 7 == 3 {
                format!(
                    r#"{{"type": "MultiPolygon", "coordinates": [{}, {}]}}"#,
                    comb(1 + k % 5),
                    comb(2)
                )
            } else {
                format!(
                    r#"{{"type": "Polygon", "coordinates": {}}}"#,
                    comb(1 + k % 9)
                )
            };
            format!(r#"{{"type": "Feature", "properties": {{"k": {k}}}, "geometry": {geometry}}}"#)
        })
        .collect()
}

fn feature_collection(features: &[String]) -> String {
    format!(
        "{{\"type\": \"FeatureCollection\", \"features\": [\n{}\n]}}\n",
        features.join(",\n")
    )
}

/// The JSON document without the `source` fields (which name the input file).
fn without_sources(mut doc: Value) -> Value {
    for p in doc["polygons"].as_array_mut().unwrap() {
        p.as_object_mut().unwrap().remove("source");
    }
    for e in doc["errors"].as_array_mut().unwrap() {
        e.as_object_mut().unwrap().remove("source");
    }
    doc
}

#[test]
fn a_directory_is_mirrored_into_an_output_directory() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    write_tree(
        root,
        &[
            ("in/u.wkt", U_SHAPE),
            ("in/sub/t.txt", TRIANGLE_VERTICES),
            (
                "in/sub/deeper/many.geojson",
                &feature_collection(&features(5)),
            ),
            ("in/sub/notes.md", "not an input"),
        ],
    );
    let (code, out, err) = run_in(root, &["in", "-o", "out"], None);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, "", "nothing on standard output");
    assert_eq!(
        files_below(&root.join("out")),
        ["sub/deeper/many.json", "sub/t.json", "u.json"].map(PathBuf::from),
        "one output per input, the tree mirrored, nothing else (no temporary file)"
    );
    let u = read_json(&root.join("out/u.json"));
    assert_eq!(u["polygons"][0]["source"], "in/u.wkt");
    assert_eq!(u["polygons"][0]["triangle_count"], 5);
    let many = read_json(&root.join("out/sub/deeper/many.json"));
    assert_eq!(
        many["polygons"].as_array().unwrap().len(),
        6,
        "5 features, one with 2 parts"
    );
    assert!(
        err.contains("3 files (1 skipped: no input format's extension), 8 polygons triangulated, ")
            && err.contains(" saved against n + 2w - 2), 0 errors, "),
        "summary: {err}"
    );
    // SVG: one picture per input, same tree.
    let (code, _, err) = run_in(root, &["in", "-o", "svg", "--to", "svg"], None);
    assert_eq!(code, 0, "{err}");
    assert_eq!(
        files_below(&root.join("svg")),
        ["sub/deeper/many.svg", "sub/t.svg", "u.svg"].map(PathBuf::from)
    );
}

#[test]
fn inputs_with_the_same_stem_keep_their_full_names_and_nothing_is_overwritten() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    write_tree(
        root,
        &[
            ("in/a.wkt", U_SHAPE),
            ("in/a.txt", TRIANGLE_VERTICES),
            ("in/b.wkt", U_SHAPE),
            ("other/b.wkt", U_SHAPE),
        ],
    );
    let (code, _, err) = run_in(root, &["in", "other", "-o", "out"], None);
    assert_eq!(
        code, 1,
        "the input whose output is taken is an error: {err}"
    );
    assert_eq!(
        files_below(&root.join("out")),
        ["a.txt.json", "a.wkt.json", "b.wkt.json"].map(PathBuf::from)
    );
    assert!(
        err.contains("other/b.wkt: not processed: its output out/b.wkt.json would overwrite the output of in/b.wkt"),
        "{err}"
    );
    // Outputs inside the input directory are neither overwritten nor read back as inputs.
    let (code, _, err) = run_in(root, &["in", "-o", "in/out"], None);
    assert_eq!(code, 0, "{err}");
    let (code, _, err) = run_in(root, &["in", "-o", "in/out"], None);
    assert_eq!(code, 0, "{err}");
    assert!(err.contains("3 files, 3 polygons triangulated"), "{err}");
}

#[test]
fn a_bad_file_among_good_ones_is_reported_and_the_others_are_written() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    write_tree(
        root,
        &[
            ("in/1.wkt", U_SHAPE),
            ("in/2_bad.wkt", BOWTIE),
            ("in/3.txt", TRIANGLE_VERTICES),
            ("in/4_unreadable.wkt", "POLYGON ((0 0, 1 0"),
            (
                "in/5_mixed.wkt",
                "MULTIPOLYGON (((0 0, 1 0, 0 1)), ((0 0, 2 2, 2 0, 0 2)), ((0 0, 2 0, 1 0.5)))",
            ),
            // An earlier run's outputs: a failed input must leave them as they were.
            ("out/2_bad.json", "previous output"),
            ("out/4_unreadable.json", "previous output"),
        ],
    );
    let (code, _, err) = run_in(root, &["-j", "2", "in", "-o", "out"], None);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("minitri: in/2_bad.wkt: polygon 0: self-intersection: outer ring edge"),
        "file, polygon and reason: {err}"
    );
    assert!(
        err.contains("minitri: in/4_unreadable.wkt: line 1, column 19: "),
        "{err}"
    );
    assert!(
        err.contains("minitri: in/5_mixed.wkt: polygon 1: self-intersection"),
        "{err}"
    );
    assert!(
        err.contains("5 files, 4 polygons triangulated, ") && err.contains(", 3 errors, "),
        "{err}"
    );
    assert_eq!(
        files_below(&root.join("out")),
        [
            "1.json",
            "2_bad.json",
            "3.json",
            "4_unreadable.json",
            "5_mixed.json"
        ]
        .map(PathBuf::from),
        "no temporary file left behind"
    );
    for failed in ["2_bad.json", "4_unreadable.json"] {
        assert_eq!(
            fs::read_to_string(root.join("out").join(failed)).unwrap(),
            "previous output",
            "{failed}: not truncated, not replaced"
        );
    }
    assert_eq!(
        read_json(&root.join("out/3.json"))["polygons"][0]["triangle_count"],
        1
    );
    // Some polygons good, some bad: the good ones are written, the bad ones listed as errors.
    let mixed = read_json(&root.join("out/5_mixed.json"));
    let indexes: Vec<&Value> = mixed["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| &p["index"])
        .collect();
    assert_eq!(indexes, [0, 2]);
    assert_eq!(mixed["errors"][0]["index"], 1);
    assert_eq!(mixed["errors"][0]["source"], "in/5_mixed.wkt");
    // Messages come in input order whatever the threads did.
    let at = |s: &str| err.find(s).unwrap();
    assert!(
        at("in/2_bad.wkt") < at("in/4_unreadable.wkt")
            && at("in/4_unreadable.wkt") < at("in/5_mixed.wkt")
    );
}

#[test]
fn outputs_are_the_same_bytes_for_one_and_two_threads() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    let features = features(300);
    let mut files: Vec<(String, String)> = (0..12)
        .map(|k| {
            (
                format!("in/d{}/f{k}.geojson", k % 3),
                feature_collection(&features[k..k + 9]),
            )
        })
        .collect();
    files.push(("in/big.geojson".into(), feature_collection(&features)));
    files.push(("in/lines.ndjson".into(), features.join("\n")));
    files.push(("in/bad.wkt".into(), BOWTIE.into()));
    let refs: Vec<(&str, &str)> = files
        .iter()
        .map(|(a, b)| (a.as_str(), b.as_str()))
        .collect();
    write_tree(root, &refs);
    let mut documents = Vec::new();
    for jobs in ["1", "2"] {
        let out = format!("out{jobs}");
        let (code, _, err) = run_in(root, &["-j", jobs, "in", "-o", &out], None);
        assert_eq!(code, 1, "{err}");
        let (code, stdout, _) = run_in(root, &["-j", jobs, "in"], None);
        assert_eq!(code, 1);
        documents.push(stdout);
        let (code, stdout, _) = run_in(root, &["-j", jobs, "in/big.geojson"], None);
        assert_eq!(code, 0);
        documents.push(stdout);
    }
    let listing = files_below(&root.join("out1"));
    assert_eq!(listing.len(), 14, "every input but the bad one");
    assert_eq!(listing, files_below(&root.join("out2")));
    for file in &listing {
        assert_eq!(
            fs::read(root.join("out1").join(file)).unwrap(),
            fs::read(root.join("out2").join(file)).unwrap(),
            "{}",
            file.display()
        );
    }
    assert!(
        documents[0] == documents[2],
        "a directory to standard output"
    );
    assert!(
        documents[1] == documents[3],
        "a FeatureCollection to standard output"
    );
    let doc = json(&documents[1]);
    let indexes: Vec<u64> = doc["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["index"].as_u64().unwrap())
        .collect();
    assert_eq!(
        indexes,
        (0..indexes.len() as u64).collect::<Vec<_>>(),
        "input order"
    );
}

#[test]
fn newline_delimited_geojson_is_streamed_with_the_result_of_a_feature_collection() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    let features = features(40);
    let lines = features.join("\n") + "\n";
    write_tree(
        root,
        &[
            ("all.geojson", &feature_collection(&features)),
            ("all.ndjson", &lines),
            ("all.unknown", &lines),
        ],
    );
    let (code, collection, err) = run_in(root, &["all.geojson"], None);
    assert_eq!(code, 0, "{err}");
    let expected = without_sources(json(&collection));
    assert_eq!(expected["polygons"].as_array().unwrap().len(), 46);
    for (args, stdin) in [
        (vec!["all.ndjson"], None),
        (vec!["all.unknown"], None),
        (vec![], Some(lines.as_str())),
    ] {
        let (code, out, err) = run_in(root, &args, stdin);
        assert_eq!(code, 0, "{args:?}: {err}");
        assert_eq!(without_sources(json(&out)), expected, "{args:?}");
    }
    // A bad line is reported with its line number; the other lines go on.
    let mut bad = features.clone();
    bad[2] = r#"{"type": "Feature", "geometry": {"type": "Point", "coordinates": [0, 0]}}"#.into();
    let (code, out, err) = run_in(root, &[], Some(&bad.join("\n")));
    assert_eq!(code, 1);
    assert!(
        err.contains("minitri: -: line 3, column 1: expected a Polygon or MultiPolygon geometry, found \"Point\""),
        "{err}"
    );
    assert_eq!(json(&out)["polygons"].as_array().unwrap().len(), 45);
    // A feature of a FeatureCollection likewise.
    let (code, _, err) = run_in(root, &[], Some(&feature_collection(&bad)));
    assert_eq!(code, 1);
    assert!(
        err.contains("minitri: -: feature 2: expected a Polygon"),
        "{err}"
    );
}

#[test]
fn a_syntax_error_stops_a_streamed_collection_but_only_its_line_in_geojson_lines() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    let mut features = features(10);
    features.push(r#"{"type": "Feature",, }"#.into());
    features.push(features[0].clone());
    write_tree(
        root,
        &[
            ("in/broken.geojson", &feature_collection(&features)),
            ("in/lines.ndjson", &features.join("\n")),
            ("in/ok.wkt", U_SHAPE),
        ],
    );
    let (code, _, err) = run_in(root, &["in", "-o", "out"], None);
    assert_eq!(code, 1);
    assert!(
        err.contains("in/broken.geojson: line 12, column 20: invalid JSON"),
        "{err}"
    );
    assert!(
        err.contains("in/lines.ndjson: line 11, column 20: invalid JSON"),
        "{err}"
    );
    assert_eq!(
        files_below(&root.join("out")),
        ["lines.json", "ok.json"].map(PathBuf::from),
        "a collection cut short by a syntax error gets no output file"
    );
    let lines = read_json(&root.join("out/lines.json"));
    assert_eq!(
        lines["polygons"].as_array().unwrap().len(),
        12,
        "the lines after it too"
    );
    let (code, _, _) = run_in(root, &["in/broken.geojson", "-o", "one.json"], None);
    assert_eq!(code, 1);
    assert!(!root.join("one.json").exists());
    // On standard output, what came before the error stays, and the error is listed.
    let (code, out, _) = run_in(root, &["in/broken.geojson"], None);
    assert_eq!(code, 1);
    let doc = json(&out);
    assert_eq!(doc["polygons"].as_array().unwrap().len(), 11);
    assert!(doc["errors"][0]["message"]
        .as_str()
        .unwrap()
        .starts_with("line 12, column 20: invalid JSON"));
}

#[test]
fn quiet_silences_the_summary_and_bad_command_lines_exit_2() {
    let tmp = tempfile::tempdir().unwrap();
    let root = tmp.path();
    write_tree(
        root,
        &[
            ("in/u.wkt", U_SHAPE),
            ("in/t.txt", TRIANGLE_VERTICES),
            ("file", ""),
        ],
    );
    let (code, _, err) = run_in(root, &["--quiet", "in", "-o", "out"], None);
    assert_eq!((code, err.as_str()), (0, ""));
    let (code, _, err) = run_in(root, &["in"], None);
    assert_eq!(code, 0);
    assert!(
        err.starts_with(
            "minitri: 2 files, 2 polygons triangulated, 6 triangles (5 saved against n + 2w - 2), \
             0 errors, "
        ),
        "{err}"
    );
    let (_, _, err) = run_in(root, &["in/u.wkt"], None);
    assert_eq!(err, "", "no summary for a single file");
    let (code, _, err) = run_in(root, &["in", "-", "-o", "out"], Some(U_SHAPE));
    assert_eq!(code, 2, "{err}");
    let (code, _, err) = run_in(root, &["in", "-o", "file"], None);
    assert_eq!(code, 2, "{err}");
    assert!(err.contains("file is not a directory"), "{err}");
}

/// A rectilinear bar of `columns` unit columns (bottom heights 0..=4, top 6..=12, pseudo-random):
/// an open corridor runs its length, so MINITRI takes seconds on a few thousand columns.
fn slow_bar(columns: i64) -> String {
    let mut next = crate::util::xorshift(7);
    let bottom: Vec<i64> = (0..columns).map(|_| next(5)).collect();
    let top: Vec<i64> = (0..columns).map(|_| 6 + next(7)).collect();
    let mut ring: Vec<(i64, i64)> = Vec::new();
    for (x, &h) in (0..).zip(&bottom) {
        ring.extend([(x, h), (x + 1, h)]);
    }
    for (x, &h) in top.iter().enumerate().rev() {
        let x = x as i64;
        ring.extend([(x + 1, h), (x, h)]);
    }
    ring.dedup();
    let points: Vec<String> = ring.iter().map(|(x, y)| format!("{x} {y}")).collect();
    format!("POLYGON (({}, {}))\n", points.join(", "), points[0])
}

/// Ctrl-C (SIGINT) during a batch: exit status 130, the outputs finished before it stay complete,
/// the one being written is neither left truncated nor as a temporary file.
#[cfg(unix)]
#[test]
fn interrupt_leaves_complete_outputs_and_no_temporary_file() {
    let dir = tempfile::tempdir().unwrap();
    let input = dir.path().join("in");
    write_tree(
        &input,
        &[
            ("a.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))\n"),
            ("b/slow.wkt", &slow_bar(6000)),
        ],
    );
    let out = dir.path().join("out");
    let bin = assert_cmd::cargo::cargo_bin("minitri");
    let mut child = std::process::Command::new(bin)
        .current_dir(dir.path())
        .args(["--jobs", "1", "in", "-o", "out"])
        .stderr(std::process::Stdio::piped())
        .spawn()
        .expect("start minitri");
    let temporary = |root: &Path| {
        root.is_dir()
            && files_below(root)
                .iter()
                .any(|p| p.to_string_lossy().ends_with(".tmp"))
    };
    let start = std::time::Instant::now();
    while !temporary(&out.join("b")) {
        assert!(
            child.try_wait().unwrap().is_none(),
            "minitri finished before the slow output was begun"
        );
        assert!(start.elapsed().as_secs() < 120, "no temporary file seen");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let killed = std::process::Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("run kill");
    assert!(killed.success());
    let output = child.wait_with_output().expect("wait for minitri");
    assert_eq!(output.status.code(), Some(130));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(stderr.contains("minitri: interrupted"), "{stderr}");
    assert_eq!(files_below(&out), vec![PathBuf::from("a.json")]);
    let done = json(&fs::read_to_string(out.join("a.json")).unwrap());
    assert_eq!(done["polygons"][0]["triangle_count"], 2);
}
