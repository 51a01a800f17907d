//! The error catalogue of `docs/errors.md`, run against the real binary: every fixture of
//! `fixtures/invalid/` gives exactly the message of its table row (from a file and from standard
//! input), and the generated 100 MB inputs give the messages of the second table. That file is
//! the single source of the expected messages, so it cannot drift from the tool.

use crate::util::{fixtures, json, minitri, outcome};
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::Path;

/// One row of a table of `docs/errors.md`: its cells, code spans unquoted.
type Row = Vec<String>;

/// The rows of the first table after the heading `heading` in `docs/errors.md` (header and
/// separator left out).
fn catalogue_table(heading: &str) -> Vec<Row> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/errors.md");
    let catalogue = std::fs::read_to_string(&path).expect("docs/errors.md");
    let section = catalogue
        .split_once(&format!("\n{heading}\n"))
        .unwrap_or_else(|| panic!("docs/errors.md has no heading {heading:?}"))
        .1;
    section
        .lines()
        .skip_while(|l| !l.starts_with('|'))
        .take_while(|l| l.starts_with('|'))
        .skip(2)
        .map(|line| {
            let inner = line
                .strip_prefix("| ")
                .and_then(|l| l.strip_suffix(" |"))
                .unwrap_or_else(|| panic!("not a table row: {line}"));
            inner.split(" | ").map(unquote).collect()
        })
        .collect()
}

/// A table cell without its code-span quotes: `` `x` `` or ``` `` x `` ```.
fn unquote(cell: &str) -> String {
    if let Some(inner) = cell.strip_prefix("`` ").and_then(|c| c.strip_suffix(" ``")) {
        inner.to_string()
    } else if let Some(inner) = cell.strip_prefix('`').and_then(|c| c.strip_suffix('`')) {
        assert!(
            !inner.contains('`'),
            "a backtick needs a double fence: {cell}"
        );
        inner.to_string()
    } else {
        cell.to_string()
    }
}

/// The `--from` value for a fixture's extension (the one before `.gz`). Formats minitri does
/// not read are recognised by content whatever `--from` says: `geojson` for them.
fn format_of(fixture: &str) -> &'static str {
    match minitri::io::read::extension_of(Path::new(fixture)) {
        Some("wkt") => "wkt",
        Some("geojson" | "ndjson") => "geojson",
        Some("txt") => "vertices",
        Some("wkb") => "wkb",
        Some("kml" | "gml" | "shp" | "fgb" | "gpkg") => "geojson",
        other => panic!("{fixture}: no format for extension {other:?}"),
    }
}

/// Runs the binary with `args` and `stdin`: (exit code, stdout, stderr).
fn run_bytes(args: &[&str], stdin: Option<Vec<u8>>) -> (i32, String, String) {
    let mut cmd = minitri();
    cmd.args(args);
    if let Some(bytes) = stdin {
        cmd.write_stdin(bytes);
    }
    outcome(&mut cmd)
}

/// The JSON error entry a message stands for: `polygon I: ` becomes the index.
fn json_error(source: &str, message: &str) -> Value {
    let polygon = message.strip_prefix("polygon ").and_then(|rest| {
        let (index, text) = rest.split_once(": ")?;
        Some((index.parse::<u64>().ok()?, text))
    });
    match polygon {
        Some((index, text)) => {
            serde_json::json!({"source": source, "index": index, "message": text})
        }
        None => serde_json::json!({"source": source, "message": message}),
    }
}

#[test]
fn every_row_of_the_error_catalogue_is_exactly_what_the_binary_says() {
    let rows = catalogue_table("## Error catalogue");
    assert!(rows.len() >= 40, "{} rows", rows.len());
    let listed: Vec<&str> = rows.iter().map(|row| row[1].as_str()).collect();
    let unique: BTreeSet<&str> = listed.iter().copied().collect();
    assert_eq!(unique.len(), listed.len(), "a fixture listed twice");
    let on_disk: BTreeSet<String> = std::fs::read_dir(fixtures().join("invalid"))
        .unwrap()
        .map(|entry| entry.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert_eq!(
        on_disk.iter().map(String::as_str).collect::<BTreeSet<_>>(),
        unique,
        "every file of fixtures/invalid/ has a row, and every row a file"
    );
    for row in &rows {
        let [class, fixture, message] = row.as_slice() else {
            panic!("a row needs 3 cells: {row:?}");
        };
        let path = format!("fixtures/invalid/{fixture}");
        let (code, out, err) = run_bytes(&[&path], None);
        assert_eq!(code, 1, "{class}: {err}");
        assert_eq!(err, format!("minitri: {path}: {message}\n"), "{class}");
        // The same error under `errors`, and nothing else there.
        // (Identity fields, `feature` and such, are tested in tests/pipelines.rs.)
        let mut doc = json(&out);
        for e in doc["errors"].as_array_mut().unwrap() {
            for key in ["feature", "part", "line", "id"] {
                e.as_object_mut().unwrap().remove(key);
            }
        }
        assert_eq!(
            doc["errors"],
            serde_json::json!([json_error(&path, message)]),
            "{class}"
        );
        // From standard input: the same line, the source named `-`.
        let bytes = std::fs::read(fixtures().join("invalid").join(fixture)).unwrap();
        let (code, _, err) = run_bytes(&["--from", format_of(fixture)], Some(bytes));
        assert_eq!(code, 1, "{class} (standard input): {err}");
        assert_eq!(
            err,
            format!("minitri: -: {message}\n"),
            "{class} (standard input)"
        );
    }
}

#[test]
fn empty_standard_input_and_auto_detected_formats_are_reported_alike() {
    for (args, stdin) in [
        (&[][..], ""),
        (&[][..], " \n\t\n"),
        (&[][..], "# only a comment\n"),
        (&["--from", "wkt"][..], ""),
        (&["--from", "geojson"][..], "\n"),
        (&["--from", "vertices"][..], ""),
    ] {
        let (code, out, err) = run_bytes(args, Some(stdin.as_bytes().to_vec()));
        assert_eq!(code, 1, "{args:?} {stdin:?}");
        assert_eq!(
            err, "minitri: -: empty input: no polygon found\n",
            "{args:?} {stdin:?}"
        );
        assert_eq!(json(&out)["polygons"], serde_json::json!([]));
    }
    // Binary data on standard input, whatever the format guessed from its first byte.
    let (code, _, err) = run_bytes(&[], Some(b"\x7fELF\x02\x01\x01\x00\x00".to_vec()));
    assert_eq!(code, 1);
    assert_eq!(
        err,
        "minitri: -: line 1, column 8: binary data, not text (a NUL byte)\n"
    );
}

#[test]
fn a_failed_input_writes_no_output_file_in_any_format() {
    let dir = tempfile::tempdir().unwrap();
    for to in ["json", "svg", "geojson", "wkt", "csv"] {
        for fixture in ["spike.wkt", "unclosed.wkt", "binary.wkt", "empty.wkt"] {
            let target = dir.path().join(format!("out.{to}"));
            let path = format!("fixtures/invalid/{fixture}");
            let (code, _, err) =
                run_bytes(&["--to", to, "-o", target.to_str().unwrap(), &path], None);
            assert_eq!(code, 1, "{to} {fixture}");
            assert!(!target.exists(), "{to} {fixture}: no file");
            assert!(
                err.ends_with(&format!(
                    "minitri: nothing triangulated; {} not written\n",
                    target.display()
                )),
                "{to} {fixture}: {err}"
            );
            // An existing file of that name is left as it was.
            std::fs::write(&target, "previous").unwrap();
            let (code, _, _) =
                run_bytes(&["--to", to, "-o", target.to_str().unwrap(), &path], None);
            assert_eq!(code, 1);
            assert_eq!(std::fs::read_to_string(&target).unwrap(), "previous");
            std::fs::remove_file(&target).unwrap();
        }
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "no temporary file left behind"
    );
    // A feature collection with one good feature and one bad: written, the bad one listed.
    let target = dir.path().join("mixed.json");
    let path = "fixtures/invalid/collection_linestring.geojson";
    let (code, _, _) = run_bytes(&["-o", target.to_str().unwrap(), path], None);
    assert_eq!(code, 1);
    let doc: Value = serde_json::from_str(&std::fs::read_to_string(&target).unwrap()).unwrap();
    assert_eq!(doc["polygons"][0]["triangle_count"], 2, "the square");
    assert_eq!(doc["errors"].as_array().unwrap().len(), 1);
}

#[test]
fn a_failed_input_of_a_batch_gets_no_output_file() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("out");
    let (code, _, err) = run_bytes(
        &[
            "fixtures/invalid/spike.wkt",
            "fixtures/invalid/binary.geojson",
            "fixtures/invalid/line_point.ndjson",
            "fixtures/valid/u_shape.wkt",
            "-o",
            out.to_str().unwrap(),
        ],
        None,
    );
    assert_eq!(code, 1, "{err}");
    let mut written: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    written.sort();
    // line_point.ndjson has a good line: written, with its bad line under `errors`.
    assert_eq!(written, ["line_point.json", "u_shape.json"]);
}

/// A file of `size` bytes: `head`, then `unit` repeated, then `tail`, written in pieces.
fn generate(path: &Path, head: &str, unit: &str, tail: &str, size: usize) {
    use std::io::Write;
    let mut file = std::io::BufWriter::new(std::fs::File::create(path).unwrap());
    file.write_all(head.as_bytes()).unwrap();
    let block = unit.repeat((1 << 16) / unit.len());
    let mut written = head.len() + tail.len();
    while written + block.len() <= size {
        file.write_all(block.as_bytes()).unwrap();
        written += block.len();
    }
    while written + unit.len() <= size {
        file.write_all(unit.as_bytes()).unwrap();
        written += unit.len();
    }
    file.write_all(tail.as_bytes()).unwrap();
}

#[test]
fn hundred_megabyte_single_lines_are_rejected_with_a_short_message() {
    const SIZE: usize = 100_000_000;
    // (file name as in the docs/errors.md table, head, repeated unit, tail)
    let inputs = [
        ("number.wkt", "POLYGON ((0 ", "1", "))"),
        ("number.txt", "0 ", "1", "\n"),
        (
            "number.geojson",
            r#"{"type":"Polygon","coordinates":[[[0,"#,
            "1",
            "]]]}",
        ),
        ("coordinates.wkt", "POLYGON ((", "0 0, ", ""),
        ("coordinates.txt", "", "0 0, ", ""),
        ("garbage.wkt", "POLYGON ((0 0, ", "x", ""),
        ("garbage.txt", "", "x", ""),
        ("garbage.geojson", r#"{"type":""#, "x", ""),
    ];
    let table = catalogue_table("## Inputs too large to store");
    assert_eq!(
        table.len(),
        inputs.len(),
        "one docs/errors.md row per generated input"
    );
    let dir = tempfile::tempdir().unwrap();
    for (name, head, unit, tail) in inputs {
        let row = table
            .iter()
            .find(|row| row[0].starts_with(&format!("{name}: ")))
            .unwrap_or_else(|| panic!("{name}: no docs/errors.md row"));
        let path = dir.path().join(name);
        generate(&path, head, unit, tail, SIZE);
        assert_eq!(std::fs::metadata(&path).unwrap().len() as usize, SIZE);
        let path = path.to_str().unwrap();
        let (code, out, err) = run_bytes(&[path], None);
        std::fs::remove_file(path).unwrap();
        assert_eq!(code, 1, "{name}");
        assert_eq!(err, format!("minitri: {path}: {}\n", row[1]), "{name}");
        assert!(out.len() < 1000, "{name}: a short document");
    }
}

#[cfg(unix)]
#[test]
fn output_into_a_pipe_is_written_as_it_goes_and_the_pipe_stays() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("pipe");
    let made = std::process::Command::new("mkfifo").arg(&fifo).status();
    if !made.is_ok_and(|s| s.success()) {
        return; // no mkfifo here: nothing to check
    }
    let reader = {
        let fifo = fifo.clone();
        std::thread::spawn(move || std::fs::read_to_string(fifo).unwrap())
    };
    let (code, _, err) = run_bytes(
        &["-o", fifo.to_str().unwrap(), "fixtures/valid/u_shape.wkt"],
        None,
    );
    assert_eq!(code, 0, "{err}");
    // Checked before waiting for the reader, which would wait forever on a replaced pipe.
    let kind = std::fs::symlink_metadata(&fifo).unwrap().file_type();
    assert!(kind.is_fifo(), "still a pipe, not replaced by a file");
    let doc = json(&reader.join().unwrap());
    assert_eq!(doc["polygons"][0]["triangle_count"], 5);
}

/// Where a message starts in the source: the error constructors and the places that build a
/// message for one. The first string literal after one of these (before the statement's `;`,
/// within a few lines) is a message template.
const MESSAGE_SITES: &[&str] = &[
    "ParseError::new(",
    "ParseError::at(",
    "self.error(",
    "Failure::new(",
    "bail!(",
    "anyhow!(",
    ".context(",
    "with_context(",
    "Error::Read(",
    "Error::Output(",
    "Err(format!(",
    "let message = format!(",
    "message = format!(",
    "eprintln!(",
    "InvalidPolygon::",
    "#[error(",
    "push(format!(",
    "write!(f,",
    "cmd.error(",
];

/// The string literal starting at `text` (after its opening quote), unescaped, a line
/// continuation (`\` at the end of a line) joining the lines.
fn literal(text: &str) -> String {
    let mut out = String::new();
    let mut chars = text.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' => break,
            '\\' => match chars.next() {
                Some('\n') => {
                    while chars.peek().is_some_and(|c| c.is_whitespace()) {
                        chars.next();
                    }
                }
                Some('n' | 't') => out.push(' '),
                Some(other) => out.push(other),
                None => break,
            },
            c => out.push(c),
        }
    }
    out
}

/// The longest literal part of a `format!` template (between its `{...}` placeholders), trimmed
/// of punctuation at its ends, with runs of white space as one space.
fn longest_part(template: &str) -> String {
    let template = template.replace("{{", "\u{1}").replace("}}", "\u{2}");
    let mut parts = Vec::new();
    let mut rest = template.as_str();
    while let Some(open) = rest.find('{') {
        parts.push(&rest[..open]);
        rest = rest[open..]
            .find('}')
            .map_or("", |close| &rest[open + close + 1..]);
    }
    parts.push(rest);
    parts
        .iter()
        .map(|p| {
            let p = p.replace('\u{1}', "{").replace('\u{2}', "}");
            let p = p.trim_matches(|c: char| " :;,.()`'".contains(c));
            p.split_whitespace().collect::<Vec<_>>().join(" ")
        })
        .max_by_key(String::len)
        .unwrap_or_default()
}

/// The message templates of one source file (its `#[cfg(test)] mod tests` and comments left
/// out), each with its longest literal part.
fn message_templates(source: &str) -> Vec<(String, String)> {
    let code = source
        .split("\n#[cfg(test)]\nmod tests")
        .next()
        .unwrap_or_default();
    let code: String = code
        .lines()
        .map(|l| {
            if l.trim_start().starts_with("//") {
                ""
            } else {
                l
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    let mut found = Vec::new();
    for site in MESSAGE_SITES {
        for (at, _) in code.match_indices(site) {
            let after = &code[at + site.len()..];
            let Some(quote) = after.find('"') else {
                continue;
            };
            if quote > 120 || after[..quote].contains(';') {
                continue;
            }
            let template = literal(&after[quote + 1..]);
            let part = longest_part(&template);
            // Shorter parts are prefixes and joints (`polygon {i}: {message}`), not messages.
            if part.len() >= 12 && !found.iter().any(|(t, _)| *t == template) {
                found.push((template, part));
            }
        }
    }
    found
}

/// Every message the code can produce is in `docs/errors.md`: for every message template found
/// at an error site of `src/` (outside tests and the writers, whose texts are output, not
/// errors), its longest literal part appears in that file (white space runs as one space).
/// What this cannot see: a message assembled from parts shorter than 12 characters, or passed
/// through a variable from a site not listed in [`MESSAGE_SITES`]; `message_sites_are_found`
/// checks that the scan still finds the messages it is known to.
#[test]
fn every_message_in_the_source_is_in_errors_md() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let doc = std::fs::read_to_string(root.join("docs/errors.md")).expect("docs/errors.md");
    let doc = doc.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut missing = Vec::new();
    let mut count = 0;
    for entry in walkdir::WalkDir::new(root.join("src")).sort_by_file_name() {
        let entry = entry.expect("src/ is readable");
        let path = entry.path();
        let relative = path.strip_prefix(root).unwrap_or(path);
        let name = relative.to_string_lossy().replace('\\', "/");
        let skipped = name.ends_with("tests.rs")
            || name.ends_with("test_support.rs")
            || name.starts_with("src/io/write/");
        if path.extension().is_none_or(|e| e != "rs") || skipped {
            continue;
        }
        let source = std::fs::read_to_string(path).expect("a source file");
        for (template, part) in message_templates(&source) {
            count += 1;
            if !doc.contains(&part) {
                missing.push(format!("{name}: {template}"));
            }
        }
    }
    assert!(count > 100, "the scan found only {count} messages");
    assert!(
        missing.is_empty(),
        "messages missing from docs/errors.md (add each, as its template):\n{}",
        missing.join("\n")
    );
}

/// The scan of [`every_message_in_the_source_is_in_errors_md`] finds messages of each kind of
/// site (a constructor, a `#[error]` text, a continued line, a `format!` with placeholders).
#[test]
fn message_sites_are_found() {
    let source = r#"
        return Err(ParseError::new("empty input: no polygon found"));
        #[error("the asano dynamic program needs about {memory} and {time}")]
        let message = format!(
            "this point has {count} coordinates but \
             the polygon's first point has {first}"
        );
        let short = format!("polygon {i}: {message}");
        // ParseError::new("a comment, not a message")
    "#;
    let parts: Vec<String> = message_templates(source)
        .into_iter()
        .map(|(_, part)| part)
        .collect();
    assert_eq!(
        parts,
        [
            "empty input: no polygon found",
            "coordinates but the polygon's first point has",
            "the asano dynamic program needs about",
        ]
    );
}
