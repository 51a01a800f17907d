//! The command line, run as a user runs it: fixtures, formats, errors, exit codes, files.

use crate::util::{expected, fixtures, json, minitri, run};
use serde_json::Value;

#[test]
fn every_valid_fixture_gives_its_expected_minimum_verified() {
    let expected = expected("valid");
    assert!(expected.len() >= 9);
    for (name, minimum) in &expected {
        let path = format!("fixtures/valid/{name}");
        let (code, out, err) = run(&["--verify", &path], None);
        assert_eq!(code, 0, "{name}: {err}");
        let doc = json(&out);
        let p = &doc["polygons"][0];
        assert_eq!(p["algorithm"], "minitri");
        let (lower, upper) = (
            p["bounds"]["lower"].as_u64().unwrap(),
            p["bounds"]["upper"].as_u64().unwrap(),
        );
        let count = p["triangle_count"].as_u64().unwrap();
        assert!(
            lower <= count && count <= upper,
            "{name}: {lower} <= {count} <= {upper}"
        );
        let checks = p["verification"]["checks"].as_array().unwrap();
        assert_eq!(checks.len(), 2, "{name}: minitri and the asano DP");
        assert!(
            checks
                .iter()
                .all(|c| c["valid"] == true && c["triangle_count"] == p["triangle_count"]),
            "{name}"
        );
        assert_eq!(p["triangle_count"].to_string(), *minimum, "{name}");
        assert_eq!(
            p["verification"]["ok"], true,
            "{name}: {}",
            p["verification"]
        );
        let (n, d, t) = (
            p["vertices"].as_u64().unwrap(),
            p["degenerate_count"].as_u64().unwrap(),
            p["triangle_count"].as_u64().unwrap(),
        );
        assert_eq!(t, n - d - 2, "{name}: the formula of the spec");
        assert_eq!(
            p["degenerate_triangles"].as_array().unwrap().len() as u64,
            d
        );
    }
}

#[test]
fn ear_gives_n_minus_2_nondegenerate_triangles_and_verifies() {
    for name in [
        "u_shape.wkt",
        "collinear_bottom.wkt",
        "comb_clockwise.txt",
        "decimal_collinear.wkt",
    ] {
        let (code, out, err) = run(
            &["-a", "ear", "--verify", &format!("fixtures/valid/{name}")],
            None,
        );
        assert_eq!(code, 0, "{name}: {err}");
        let p = &json(&out)["polygons"][0];
        assert_eq!(
            p["triangle_count"].as_u64().unwrap(),
            p["vertices"].as_u64().unwrap() - 2,
            "{name}"
        );
        assert_eq!(p["degenerate_count"], 0);
        assert_eq!(p["optimal"], false);
        let checks = p["verification"]["checks"].as_array().unwrap();
        let names: Vec<&str> = checks
            .iter()
            .map(|c| c["algorithm"].as_str().unwrap())
            .collect();
        assert_eq!(
            names,
            ["ear", "minitri", "asano"],
            "ear and both exact algorithms are checked"
        );
        assert!(
            checks.iter().all(|c| c["valid"] == true),
            "{name}: {checks:?}"
        );
    }
}

#[test]
fn ear_triangulates_polygons_with_holes_into_n_plus_2w_minus_2_and_verifies() {
    let expected = expected("holes");
    assert!(expected.len() >= 5);
    for (name, count) in &expected {
        let (code, out, err) = run(
            &["-a", "ear", "--verify", &format!("fixtures/holes/{name}")],
            None,
        );
        assert_eq!(code, 0, "{name}: {err}");
        let p = &json(&out)["polygons"][0];
        let (n, w) = (
            p["vertices"].as_u64().unwrap(),
            p["holes"].as_u64().unwrap(),
        );
        assert!(w >= 1, "{name}: a fixture with holes");
        assert_eq!(p["triangle_count"].to_string(), *count, "{name}");
        assert_eq!(
            p["triangle_count"].as_u64().unwrap(),
            n + 2 * w - 2,
            "{name}"
        );
        assert_eq!(p["degenerate_count"], 0, "{name}");
        assert_eq!(p["optimal"], false, "{name}");
        let v = &p["verification"];
        assert_eq!(v["ok"], true, "{name}: {v}");
        let checks = v["checks"].as_array().unwrap();
        assert_eq!(checks[0]["algorithm"], "ear");
        assert_eq!(
            checks[1]["algorithm"], "minitri",
            "{name}: minitri handles holes"
        );
        assert!(checks.iter().all(|c| c["valid"] == true), "{name}: {v}");
    }
}

/// Regression: the default algorithm panicked on this polygon with 2 holes (MINITRI's cut step,
/// see `tests/holes_dp.rs`); now its minimum, checked and equal to the DP's.
#[test]
fn minitri_with_holes_cuts_a_side_pinched_round_a_hole() {
    let (code, out, err) = run(
        &["--verify", "fixtures/holes/cut_pinched_round_a_hole.wkt"],
        None,
    );
    assert_eq!(code, 0, "{err}");
    let p = &json(&out)["polygons"][0];
    assert_eq!(p["algorithm"], "minitri");
    assert_eq!(p["optimal"], true);
    assert_eq!(p["triangle_count"], 12);
    assert_eq!(p["degenerate_count"], 2);
    let checks = p["verification"]["checks"].as_array().unwrap();
    let names: Vec<&str> = checks
        .iter()
        .map(|c| c["algorithm"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["minitri", "asano"]);
    assert!(
        checks
            .iter()
            .all(|c| c["valid"] == true && c["triangle_count"] == 12),
        "{checks:?}"
    );
}

#[test]
fn decimal_input_is_exact_as_written() {
    let (code, out, _) = run(
        &["-a", "asano"],
        Some("POLYGON ((0 0, 0.1 0.3, 0.2 0.6, 0 1, 0 0))"),
    );
    assert_eq!(code, 0);
    let p = &json(&out)["polygons"][0];
    assert_eq!(p["triangle_count"], 1);
    assert_eq!(p["degenerate_triangles"], serde_json::json!([[0, 1, 2]]));
    // Not collinear once a digit changes: two triangles.
    let (_, out, _) = run(
        &["-a", "asano"],
        Some("POLYGON ((0 0, 0.1 0.3, 0.2 0.6000000000000001, 0 1, 0 0))"),
    );
    assert_eq!(json(&out)["polygons"][0]["triangle_count"], 2);
}

fn without_source(mut doc: Value) -> Value {
    for p in doc["polygons"].as_array_mut().unwrap() {
        // The GeoJSON input's feature identity too (WKT and vertex lists have none).
        for key in ["source", "feature", "id", "properties"] {
            p.as_object_mut().unwrap().remove(key);
        }
    }
    doc
}

#[test]
fn the_same_polygon_in_three_formats_gives_identical_json() {
    let docs: Vec<Value> = ["u_shape.wkt", "u_shape.geojson", "u_shape.txt"]
        .iter()
        .map(|f| {
            let (code, out, err) = run(&["-a", "asano", &format!("fixtures/valid/{f}")], None);
            assert_eq!(code, 0, "{f}: {err}");
            without_source(json(&out))
        })
        .collect();
    assert_eq!(docs[0], docs[1]);
    assert_eq!(docs[0], docs[2]);
    // And through standard input with detection by content.
    let text = std::fs::read_to_string(fixtures().join("valid/u_shape.geojson")).unwrap();
    let (_, out, _) = run(&["-a", "asano"], Some(&text));
    let doc = json(&out);
    assert_eq!(doc["polygons"][0]["source"], "-");
    assert_eq!(without_source(doc), docs[0]);
}

#[test]
fn one_bad_input_does_not_stop_the_others() {
    let (code, out, err) = run(
        &[
            "-a",
            "asano",
            "fixtures/invalid/bowtie.wkt",
            "fixtures/valid/l_shape.wkt",
        ],
        None,
    );
    assert_eq!(code, 1);
    assert!(
        err.contains("bowtie.wkt: polygon 0: self-intersection"),
        "{err}"
    );
    let doc = json(&out);
    assert_eq!(doc["polygons"][0]["source"], "fixtures/valid/l_shape.wkt");
    assert_eq!(doc["polygons"][0]["triangle_count"], 3);
    // Within one MULTIPOLYGON as well: polygon 1 fails, polygons 0 and 2 are solved.
    let multi = "MULTIPOLYGON (((0 0, 2 0, 2 1, 1 1, 1 2, 0 2)), ((0 0, 2 2, 2 0, 0 2)), ((0 0, 1 0, 0 1)))";
    let (code, out, err) = run(&["-a", "asano"], Some(multi));
    assert_eq!(code, 1);
    assert!(err.contains("-: polygon 1: self-intersection"), "{err}");
    let doc = json(&out);
    let indexes: Vec<_> = doc["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["index"].clone())
        .collect();
    assert_eq!(indexes, [0, 2]);
}

#[test]
fn duplicates_are_dropped_with_a_warning_and_keep_their_numbers() {
    let (code, out, err) = run(&["-a", "asano"], Some("0 0\n1 0\n1 0\n2 0\n2 2\n0 2\n"));
    assert_eq!(code, 0);
    assert!(
        err.contains(
            "warning: -: polygon 0: outer ring: vertex 2 (1, 0) repeats vertex 1 and was dropped"
        ),
        "{err}"
    );
    let p = &json(&out)["polygons"][0];
    assert_eq!(p["vertices"], 5);
    assert_eq!(p["input_vertices"], 6);
    let used: Vec<u64> = p["triangles"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|t| t.as_array().unwrap().iter().map(|v| v.as_u64().unwrap()))
        .collect();
    assert!(
        !used.contains(&2),
        "the dropped vertex appears in no triangle"
    );
    assert!(used.contains(&5));
    let (_, _, err) = run(
        &["-a", "asano", "--quiet"],
        Some("0 0\n1 0\n1 0\n2 0\n2 2\n0 2\n"),
    );
    assert_eq!(err, "");
}

#[test]
fn the_dp_triangulates_polygons_with_up_to_two_holes_and_refuses_more() {
    // A square with a square hole: n + 2w - 2 = 8; --verify checks it.
    let (code, out, err) = run(
        &["-a", "asano", "--verify"],
        Some("POLYGON ((0 0, 3 0, 3 3, 0 3), (1 1, 2 1, 2 2, 1 2))"),
    );
    assert_eq!(code, 0, "{err}");
    let doc = json(&out);
    let p = &doc["polygons"][0];
    assert_eq!(p["triangle_count"], 8);
    assert_eq!(p["holes"], 1);
    assert_eq!(p["verification"]["ok"], true);
    assert_eq!(p["verification"]["checks"][0]["algorithm"], "asano");
    let (code, _, err) = run(
        &["-a", "asano"],
        Some("POLYGON ((0 0, 9 0, 9 9, 0 9), (1 1, 2 1, 1 2), (4 4, 5 4, 4 5), (7 7, 8 7, 7 8))"),
    );
    assert_eq!(code, 1);
    assert!(
        err.contains("the asano dynamic program handles polygons with at most 2 holes (its time grows like n^(3+2k) with k holes), and this polygon has 3 holes"),
        "{err}"
    );
}

#[test]
fn the_dp_refuses_large_polygons_with_an_estimate() {
    let (code, _, err) = run(
        &[
            "-a",
            "asano",
            "--dp-limit",
            "10",
            "fixtures/valid/u_shape.wkt",
        ],
        None,
    );
    assert_eq!(code, 1);
    assert!(err.contains("needs about 2 kB and 1 µs for 12 vertices, above its limit of 10 vertices; use --algorithm minitri"), "{err}");
}

#[test]
fn exit_codes_and_help() {
    assert_eq!(run(&["--algorithm", "bogus"], None).0, 2);
    assert_eq!(run(&["--jobs", "0", "x.wkt"], None).0, 2);
    let (code, out, _) = run(&["--help"], None);
    assert_eq!(code, 0);
    assert!(out.contains("Examples:") && out.contains("--verify"));
    let (code, _, err) = run(&["no/such/file.wkt"], None);
    assert_eq!(code, 1);
    assert!(err.contains("no/such/file.wkt: cannot read"), "{err}");
}

#[test]
fn help_shows_an_example_of_every_use() {
    let (code, out, _) = run(&["--help"], None);
    assert_eq!(code, 0);
    for example in [
        "cat shape.wkt | minitri",
        "minitri --to svg -o u.svg",
        "--to geojson",
        "--to wkt",
        "--from vertices",
        "minitri --verify shapes/",
        "minitri shapes/ -o out/ --jobs 2",
        "minitri -q shapes/",
        "minitri --time-limit 60",
        "minitri -a ear",
        "minitri -a pseudo",
        "minitri --completions bash >",
        "minitri --man > minitri.1",
        "NO_COLOR",
        "Exit status:",
    ] {
        assert!(
            out.contains(example),
            "{example:?} missing from --help:\n{out}"
        );
    }
    // -h is the summary: the shell flags are left to --help.
    let (code, short, _) = run(&["-h"], None);
    assert_eq!(code, 0);
    assert!(
        short.contains("Examples:") && short.contains("--verify"),
        "{short}"
    );
    assert!(
        !short.contains("--completions") && !short.contains("--man"),
        "{short}"
    );
    let (code, version, _) = run(&["--version"], None);
    assert_eq!(code, 0);
    assert!(version.starts_with("minitri "), "{version}");
}

#[test]
fn completions_for_every_shell_and_a_man_page_without_reading_input() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        // Standard input is given, and must not be read (nor waited for).
        let (code, out, err) = run(&["--completions", shell], Some("not a polygon"));
        assert_eq!(code, 0, "{shell}: {err}");
        assert!(err.is_empty(), "{shell}: {err}");
        assert!(out.contains("minitri"), "{shell}");
        assert!(
            out.contains("algorithm") && out.contains("time-limit"),
            "{shell}"
        );
    }
    let (_, bash, _) = run(&["--completions", "bash"], None);
    assert!(bash.contains("complete -F _minitri"), "{bash}");
    assert!(
        bash.contains("--algorithm") && bash.contains("--quiet"),
        "{bash}"
    );
    let (_, zsh, _) = run(&["--completions", "zsh"], None);
    assert!(zsh.starts_with("#compdef minitri"), "{zsh}");

    let (code, man, err) = run(&["--man"], Some("not a polygon"));
    assert_eq!(code, 0, "{err}");
    assert!(err.is_empty(), "{err}");
    assert!(man.lines().any(|l| l.starts_with(".TH minitri 1")), "{man}");
    for section in [".SH NAME", ".SH SYNOPSIS", ".SH OPTIONS", ".SH EXAMPLES"] {
        assert!(man.contains(section), "{section} missing:\n{man}");
    }
    assert!(man.contains("\\-\\-algorithm") && man.contains("\\-\\-time\\-limit"));
    assert!(man.contains("minitri \\-\\-verify shapes/"), "{man}");

    // An unknown shell, or either flag with anything else, is a bad command line.
    let (code, _, err) = run(&["--completions", "tcsh"], None);
    assert_eq!(code, 2);
    assert!(err.contains("possible values: bash"), "{err}");
    for args in [
        &["--completions", "bash", "fixtures/valid/u_shape.wkt"][..],
        &["--man", "-q"],
        &["--man", "--completions", "zsh"],
        &["--man", "-o", "minitri.1"],
    ] {
        let (code, out, err) = run(args, None);
        assert_eq!(code, 2, "{args:?}");
        assert!(
            out.is_empty() && err.contains("cannot be used with"),
            "{args:?}: {err}"
        );
    }
}

#[test]
fn no_color_turns_colour_off_in_help_and_errors() {
    // Not a terminal here, so CLICOLOR_FORCE is what makes clap colour; it shows the check
    // below would see escapes if there were any.
    let colour = |no_color: Option<&str>, args: &[&str]| {
        let mut cmd = minitri();
        cmd.args(args)
            .env("CLICOLOR_FORCE", "1")
            .env_remove("NO_COLOR");
        if let Some(value) = no_color {
            cmd.env("NO_COLOR", value);
        }
        let out = cmd.output().unwrap();
        let text = [out.stdout, out.stderr].concat();
        String::from_utf8_lossy(&text).into_owned()
    };
    for args in [&["--help"][..], &["--bogus"]] {
        assert!(colour(None, args).contains("\x1b["), "{args:?}");
        // An empty NO_COLOR is no request (no-color.org).
        assert!(colour(Some(""), args).contains("\x1b["), "{args:?}");
        let plain = colour(Some("1"), args);
        assert!(!plain.contains('\x1b'), "{args:?}: {plain:?}");
    }
    let plain = colour(Some("1"), &["--help"]);
    assert!(plain.contains("Examples:") && plain.contains("cat shape.wkt | minitri"));
}

#[test]
fn output_files_are_written_whole_or_not_at_all() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("u.json");
    let (code, _, _) = run(
        &[
            "-a",
            "asano",
            "-o",
            good.to_str().unwrap(),
            "fixtures/valid/u_shape.wkt",
        ],
        None,
    );
    assert_eq!(code, 0);
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&good).unwrap()).unwrap();
    assert_eq!(doc["polygons"][0]["triangle_count"], 5);
    let bad = dir.path().join("bad.json");
    let (code, _, err) = run(
        &[
            "-a",
            "asano",
            "-o",
            bad.to_str().unwrap(),
            "fixtures/invalid/spike.wkt",
        ],
        None,
    );
    assert_eq!(code, 1);
    assert!(
        !bad.exists(),
        "no output file for an input that failed: {err}"
    );
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "no temporary file left behind"
    );
}

#[test]
fn svg_output_is_a_picture_with_the_legend() {
    let (code, out, err) = run(
        &["-a", "asano", "--to", "svg", "fixtures/valid/u_shape.wkt"],
        None,
    );
    assert_eq!(code, 0, "{err}");
    assert!(out.contains("<svg") && out.trim_end().ends_with("</svg>"));
    assert!(out.contains("n = 12") && out.contains("d = 5"), "legend");
}

#[test]
fn directories_are_read_recursively_in_sorted_order() {
    let (code, out, err) = run(&["-a", "asano", "fixtures/valid"], None);
    assert_eq!(code, 0, "{err}");
    let doc = json(&out);
    let sources: Vec<&str> = doc["polygons"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p["source"].as_str().unwrap())
        .collect();
    let mut sorted = sources.clone();
    sorted.sort();
    assert_eq!(sources, sorted);
    assert_eq!(
        sources.len(),
        expected("valid").len(),
        "every fixture, and nothing else"
    );
}

#[test]
fn verify_reports_a_wrong_output_and_exits_3() {
    // A fault injected on purpose: every output loses one triangle before it is checked.
    let (code, v) = crate::util::verify_with_fault(&["-a", "ear", "fixtures/valid/u_shape.wkt"]);
    assert_eq!(code, Some(3));
    assert_eq!(v["ok"], false);
    assert_eq!(v["checks"][0]["algorithm"], "ear");
    assert_eq!(v["checks"][0]["valid"], false);
    let problems = v["checks"][0]["problems"].to_string();
    assert!(
        problems.contains("area") && problems.contains("9 triangles"),
        "{problems}"
    );
    assert_eq!(
        v["checks"][1]["valid"], true,
        "minitri is computed independently"
    );
    assert_eq!(
        v["checks"][2]["valid"], true,
        "the asano reference is computed independently"
    );
    // Without the fault the same run is clean.
    assert_eq!(
        run(
            &["-a", "ear", "--verify", "fixtures/valid/u_shape.wkt"],
            None
        )
        .0,
        0
    );
}

#[test]
fn a_search_cut_short_reports_why_and_a_true_bound() {
    let holes = "POLYGON ((0 0, 20 0, 20 20, 0 20), (2 2, 2 6, 3 6, 4 4, 5 6, 6 6, 6 2), \
                 (10 2, 10 6, 11 6, 12 4, 13 6, 14 6, 14 2), (2 10, 2 14, 3 14, 4 12, 5 14, 6 14, 6 10), \
                 (10 10, 10 14, 11 14, 12 12, 13 14, 14 14, 14 10))";
    // Without the cut, the search finishes: proved optimal, no lower_bound or stopped_by field.
    let (_, out, _) = run(&[], Some(holes));
    let p = &json(&out)["polygons"][0];
    assert_eq!(p["optimal"], true);
    assert!(p.get("lower_bound").is_none() && p.get("stopped_by").is_none());
    let minimum = p["triangle_count"].as_u64().unwrap();
    // Cut short (the limit bounds every stage, step 1 included: issue 24), the answer is valid
    // and either meets the bound of the middle-vertex cliques (then it is proved all the same)
    // or says why it stopped and what is proved.
    let (code, out, err) = run(&["--time-limit", "0.000001", "--verify"], Some(holes));
    assert_eq!(code, 0, "{err}");
    let p = &json(&out)["polygons"][0];
    assert_eq!(p["verification"]["checks"][0]["valid"], true);
    let count = p["triangle_count"].as_u64().unwrap();
    assert!(count >= minimum);
    if p["optimal"] == true {
        assert_eq!(count, minimum);
        assert!(p.get("lower_bound").is_none() && p.get("stopped_by").is_none());
    } else {
        assert_eq!(p["stopped_by"], "time limit", "{p}");
        assert!(p["lower_bound"].as_u64().unwrap() <= minimum);
    }
}

/// The README's first example is what the binary prints: the JSON under "What it does" is the
/// output of its first command (`cargo run --release -- fixtures/valid/u_shape.wkt`) byte for
/// byte, run from the repository's root as the README says.
#[test]
fn the_readme_example_is_what_the_binary_prints() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = std::fs::read_to_string(root.join("README.md")).expect("README.md");
    let start = readme
        .find("```json\n{\n  \"polygons\"")
        .expect("the README's JSON example")
        + "```json\n".len();
    let end = start + readme[start..].find("```").expect("the end of the example");
    let (code, out, err) = run(&["fixtures/valid/u_shape.wkt"], None);
    assert_eq!(code, 0, "{err}");
    assert_eq!(out, readme[start..end], "README example out of date");
}

/// The user-facing documents: README.md, ARCHITECTURE.md and every `docs/*.md`, with their text.
fn documents() -> Vec<(std::path::PathBuf, String)> {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut paths = vec![root.join("README.md"), root.join("ARCHITECTURE.md")];
    let mut docs: Vec<_> = std::fs::read_dir(root.join("docs"))
        .expect("docs/")
        .map(|entry| entry.expect("docs/ entry").path())
        .filter(|p| p.extension().is_some_and(|e| e == "md"))
        .collect();
    docs.sort();
    paths.extend(docs);
    paths
        .into_iter()
        .map(|p| {
            let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{p:?}: {e}"));
            (p, text)
        })
        .collect()
}

/// Names of material that lives outside the repository (the project's development notes), which
/// no user-facing text may point to.
const OUTSIDE: [&str; 7] = [
    "../",
    "shared/",
    "DESIGN.md",
    "spec/CLI.md",
    "papers in",
    "papers/",
    "the spec",
];

/// The anchor GitHub gives a Markdown heading: lower case, punctuation dropped, spaces as `-`.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter(|c| c.is_alphanumeric() || *c == ' ' || *c == '-' || *c == '_')
        .map(|c| if c == ' ' { '-' } else { c })
        .collect()
}

/// The anchors of a Markdown text's headings.
fn anchors(text: &str) -> Vec<String> {
    text.lines()
        .filter(|l| l.starts_with('#'))
        .map(|l| anchor(l.trim_start_matches('#')))
        .collect()
}

/// Every relative link of README.md, ARCHITECTURE.md and docs/*.md names a file of the
/// repository (and a heading of it, after `#`), and no text names anything outside the
/// repository; a link may climb out of `docs/` (`../ARCHITECTURE.md`), never out of the root.
#[test]
fn the_documents_link_only_to_files_of_the_repository() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .canonicalize()
        .expect("root");
    for (path, text) in documents() {
        let dir = path.parent().expect("a directory");
        let mut rest = text.clone();
        for target in markdown_links(&text) {
            rest = rest.replace(&format!("]({target})"), "]()");
            if target.contains("://") || target.starts_with("mailto:") {
                continue;
            }
            let (file, fragment) = match target.split_once('#') {
                Some((file, fragment)) => (file, Some(fragment)),
                None => (target.as_str(), None),
            };
            let linked = if file.is_empty() {
                path.clone()
            } else {
                dir.join(file)
            };
            let resolved = linked
                .canonicalize()
                .unwrap_or_else(|_| panic!("{path:?}: link to a missing file: {target}"));
            assert!(
                resolved.starts_with(&root),
                "{path:?}: link outside the repository: {target}"
            );
            if let Some(fragment) = fragment {
                let linked_text = std::fs::read_to_string(&resolved).expect("linked file");
                assert!(
                    anchors(&linked_text).iter().any(|a| a == fragment),
                    "{path:?}: link to a missing heading: {target}"
                );
            }
        }
        for name in OUTSIDE {
            assert!(
                !rest.contains(name),
                "{path:?} refers outside the repository: {name:?}"
            );
        }
    }
}

/// No document keeps a merge's conflict markers (the README once carried both sides of a
/// conflicting `--time-limit` row for a day).
#[test]
fn documents_hold_no_conflict_markers() {
    for (path, text) in documents() {
        for (i, line) in text.lines().enumerate() {
            let marker =
                line.starts_with("<<<<<<< ") || line.starts_with(">>>>>>> ") || line == "=======";
            assert!(
                !marker,
                "{path:?} line {}: a conflict marker: {line}",
                i + 1
            );
        }
    }
}

/// The targets of the Markdown links `[text](target)` of a text.
fn markdown_links(text: &str) -> Vec<String> {
    text.match_indices("](")
        .filter_map(|(i, _)| {
            let target = &text[i + 2..];
            target.find(')').map(|end| target[..end].to_string())
        })
        .filter(|t| !t.contains(char::is_whitespace))
        .collect()
}

/// `--help` and `--man` name nothing outside the repository either.
#[test]
fn help_and_man_page_refer_to_nothing_outside_the_repository() {
    for flag in ["--help", "--man"] {
        let (code, out, err) = run(&[flag], None);
        assert_eq!(code, 0, "{err}");
        assert!(out.len() > 1000, "{flag}: {out}");
        for name in OUTSIDE {
            assert!(!out.contains(name), "{flag} refers to {name:?}");
        }
    }
}

/// A terminal on standard input is told how to end it, and no progress bar is drawn while one
/// types (`script`, of util-linux, runs the binary on a pseudo-terminal; Ctrl-D is byte 4).
/// Piped input gets no such line.
#[test]
fn typing_on_a_terminal_is_told_how_to_end_it() {
    use std::io::Write;
    let bin = assert_cmd::cargo::cargo_bin("minitri");
    let mut child = std::process::Command::new("script")
        .args(["-qec", &bin.display().to_string(), "/dev/null"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .expect("`script` (util-linux) runs the binary on a terminal");
    let mut stdin = child.stdin.take().expect("stdin");
    stdin
        .write_all(b"POLYGON ((0 0, 1 0, 0 1))\n\x04")
        .expect("typed");
    drop(stdin);
    let out = child.wait_with_output().expect("script ran");
    let screen = String::from_utf8_lossy(&out.stdout);
    assert!(
        screen.contains("minitri: reading standard input; Ctrl-D to end"),
        "{screen}"
    );
    assert!(screen.contains("\"triangle_count\": 1"), "{screen}");
    assert!(!screen.contains("files,"), "no progress bar: {screen}");
    let (code, _, err) = run(&[], Some("POLYGON ((0 0, 1 0, 0 1))"));
    assert_eq!((code, err.as_str()), (0, ""));
}

/// A directory without any input file is an error naming it (exit 1), and files of no input
/// format below a directory are counted in the summary.
#[test]
fn a_directory_without_input_files_is_named_and_skipped_files_are_counted() {
    let dir = tempfile::tempdir().expect("temporary directory");
    std::fs::write(dir.path().join("notes.md"), "not a polygon").expect("written");
    std::fs::write(dir.path().join("photo.png"), "not either").expect("written");
    let name = dir.path().display().to_string();
    let (code, out, err) = run(&[&name], None);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains(&format!(
            "minitri: {name}: no input file found in this directory (2 other files; \
             inputs end in .wkt, .geojson"
        )),
        "{err}"
    );
    assert_eq!(json(&out)["errors"][0]["source"], name.as_str());
    std::fs::copy(
        fixtures().join("valid/u_shape.wkt"),
        dir.path().join("u.wkt"),
    )
    .expect("copied");
    let (code, _, err) = run(&[&name], None);
    assert_eq!(code, 0, "{err}");
    assert!(
        err.contains("minitri: 1 file (2 skipped: no input format's extension), 1 polygon triangulated, 5 triangles"),
        "{err}"
    );
}

/// The summary counts the error lines printed (a polygon with two problems gives two) and only
/// the polygons triangulated.
#[test]
fn the_summary_counts_error_lines_and_triangulated_polygons() {
    let dir = tempfile::tempdir().expect("temporary directory");
    // Polygon 0 is fine; polygon 1 has two holes outside it: two lines, two errors.
    std::fs::write(
        dir.path().join("two.wkt"),
        "MULTIPOLYGON (((0 0, 1 0, 0 1)), ((0 0, 1 0, 0 1), (5 5, 6 5, 5 6), (7 7, 8 7, 7 8)))",
    )
    .expect("written");
    let name = dir.path().display().to_string();
    let (code, _, err) = run(&[&name], None);
    assert_eq!(code, 1, "{err}");
    assert!(
        err.contains("two.wkt: polygon 1: hole 1 lies outside the outer ring\n"),
        "{err}"
    );
    assert!(
        err.contains("two.wkt: polygon 1: hole 2 lies outside the outer ring\n"),
        "{err}"
    );
    assert!(
        err.contains("minitri: 1 file, 1 polygon triangulated, 1 triangle (0 saved against n + 2w - 2), 2 errors, "),
        "{err}"
    );
}

/// `--format` is answered with the flags that exist: `--to` for the output, `--from` for the
/// input (exit 2).
#[test]
fn format_points_to_to_and_from() {
    for args in [&["--format", "svg", "x.wkt"][..], &["--format=svg"][..]] {
        let (code, _, err) = run(args, None);
        assert_eq!(code, 2, "{err}");
        assert!(
            err.contains("there is no --format: the output format is --to (json, geojson, geojsonl, geojson-triangles, wkt, csv, svg), the input format --from"),
            "{err}"
        );
    }
}

/// Piped CSV with an `x,y` header is read as a vertex list, the header skipped.
#[test]
fn piped_csv_with_a_header_is_a_vertex_list() {
    let (code, out, err) = run(&[], Some("x,y\n0,0\n2,0\n1,0.5\n2,2\n0,2\n"));
    assert_eq!(code, 0, "{err}");
    let p = &json(&out)["polygons"][0];
    assert_eq!(
        (p["vertices"].as_u64(), p["input_vertices"].as_u64()),
        (Some(5), Some(5))
    );
    let (code, out, err) = run(
        &["--from", "vertices"],
        Some("lon, lat\r\n0,0\r\n1,0\r\n0,1\r\n"),
    );
    assert_eq!(code, 0, "{err}");
    assert_eq!(json(&out)["polygons"][0]["triangle_count"], 1);
    // Only the first line may be a header.
    let (code, _, err) = run(&["--from", "vertices"], Some("0,0\nx,y\n1,0\n0,1\n"));
    assert_eq!(code, 1);
    assert!(
        err.contains("line 2, column 1: `x` is not a number"),
        "{err}"
    );
}

#[test]
fn repair_splits_a_figure_eight_into_two_pieces_and_says_so() {
    let eight = "POLYGON ((0 0, 2 0, 2 2, 4 2, 4 4, 2 4, 2 2, 0 2, 0 0))";
    // Without --repair: rejected, and the message says what --repair would do.
    let (code, _, err) = run(&["--from", "wkt"], Some(eight));
    assert_eq!(code, 1);
    assert!(
        err.contains("the ring touches itself; --repair splits it there"),
        "{err}"
    );
    let (code, out, err) = run(&["--from", "wkt", "--repair", "--verify"], Some(eight));
    assert_eq!(code, 0, "{err}");
    let sentence = "outer ring touches itself at vertex 2 (2, 2): its loop of 4 vertices from there became a separate polygon";
    // Once for the polygon, not once per piece.
    assert_eq!(
        err.matches(&format!("warning: -: polygon 0: repaired: {sentence}"))
            .count(),
        1,
        "{err}"
    );
    let doc = json(&out);
    let pieces = doc["polygons"].as_array().expect("polygons");
    assert_eq!(pieces.len(), 2);
    for (k, p) in pieces.iter().enumerate() {
        assert_eq!(p["index"], 0);
        assert_eq!(p["piece"], k);
        assert_eq!(p["triangle_count"], 2);
        assert_eq!(p["verification"]["ok"], true);
        // Listed once, with piece 0; the other pieces point to it.
        if k == 0 {
            assert_eq!(
                p["repaired"],
                serde_json::json!([{"kind": "split_ring", "message": sentence}])
            );
        } else {
            assert_eq!(p.get("repaired"), None);
            assert_eq!(p["repaired_in_piece"], 0);
        }
    }
}

#[test]
fn repair_tells_an_input_warning_once_and_a_feature_stays_one_record() {
    // A figure eight with a repeated vertex (2 0): split in two pieces, the vertex dropped.
    let ring = "[0, 0], [2, 0], [2, 0], [2, 2], [4, 2], [4, 4], [2, 4], [2, 2], [0, 2], [0, 0]";
    let feature = format!(
        r#"{{"type": "Feature", "id": "eight", "geometry": {{"type": "Polygon", "coordinates": [[{ring}]]}}}}"#
    );
    let warning = "vertex 2 (2, 0) repeats vertex 1 and was dropped";
    for to in ["json", "geojsonl", "wkt", "csv"] {
        let (code, out, err) = run(&["--repair", "--to", to], Some(&feature));
        assert_eq!(code, 0, "{to}: {err}");
        assert_eq!(err.matches(warning).count(), 1, "{to}: {err}");
        assert!(
            err.contains(&format!(
                "warning: -: feature 0 piece 0: outer ring: {warning}"
            )),
            "{to}: {err}"
        );
        assert!(
            err.contains("warning: -: feature 0: repaired: outer ring touches itself"),
            "{to}: {err}"
        );
        match to {
            // The warning is the first piece's, in the JSON as on standard error.
            "json" => {
                let doc = json(&out);
                let warnings: Vec<usize> = doc["polygons"]
                    .as_array()
                    .expect("polygons")
                    .iter()
                    .map(|p| p["warnings"].as_array().map_or(0, Vec::len))
                    .collect();
                assert_eq!(warnings, [1, 0], "{out}");
            }
            // Both pieces in the feature's one Feature, line and row.
            "geojsonl" => {
                assert_eq!(out.lines().count(), 1, "{out}");
                assert_eq!(json(&out)["properties"]["minitri"]["triangle_count"], 4);
            }
            "wkt" => assert_eq!(
                out,
                "GEOMETRYCOLLECTION (POLYGON ((0 2, 0 0, 2 0, 0 2)), POLYGON ((2 2, 0 2, 2 0, 2 2)), \
                 POLYGON ((2 4, 2 2, 4 2, 2 4)), POLYGON ((4 4, 2 4, 4 2, 4 4)))\n"
            ),
            _ => assert_eq!(
                out.matches("\r\n").count(),
                2,
                "a header and one row: {out}"
            ),
        }
    }
}

#[test]
fn repair_removes_a_spike_and_merges_holes_sharing_an_edge() {
    let wkt = "POLYGON ((0 0, 9 0, 9 9, 4 9, 4 12, 4 9, 0 9), (1 1, 3 1, 3 3, 1 3), (3 1, 5 1, 5 3, 3 3))";
    let (code, _, err) = run(&["--from", "wkt"], Some(wkt));
    assert_eq!(code, 1);
    assert!(err.contains("--repair removes spikes"), "{err}");
    let (code, out, err) = run(&["--from", "wkt", "--repair", "--verify"], Some(wkt));
    assert_eq!(code, 0, "{err}");
    let p = &json(&out)["polygons"][0];
    assert!(p.get("piece").is_none(), "one piece: no piece field");
    assert_eq!(p["holes"], 1);
    assert_eq!(p["verification"]["ok"], true);
    let kinds: Vec<&str> = p["repaired"]
        .as_array()
        .expect("repaired")
        .iter()
        .map(|r| r["kind"].as_str().expect("kind"))
        .collect();
    assert_eq!(kinds, ["spike", "merged_rings"]);
    assert_eq!(
        p["repaired"][0]["message"],
        "outer ring: spike at vertex 4 (4, 12) removed (edges 3-4 and 4-5 folded back onto each other)"
    );
    // A valid polygon with --repair: an empty list.
    let (_, out, _) = run(
        &["--from", "wkt", "--repair"],
        Some("POLYGON ((0 0, 1 0, 0 1))"),
    );
    assert_eq!(json(&out)["polygons"][0]["repaired"], serde_json::json!([]));
}

#[test]
fn repair_leaves_crossing_rings_rejected() {
    let (code, out, _) = run(
        &["--from", "wkt", "--repair"],
        Some("POLYGON ((0 0, 2 2, 2 0, 0 2))"),
    );
    assert_eq!(code, 1);
    let message = json(&out)["errors"][0]["message"]
        .as_str()
        .expect("message")
        .to_string();
    assert!(message.starts_with("self-intersection"), "{message}");
}
