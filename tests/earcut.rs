//! All 59 polygons of earcut's test suite (`fixtures/earcut/`, ISC, see its SOURCE.md) through the
//! command line with `--verify`: each has the outcome [`EXPECTED`] lists for it (triangulated as
//! is, triangulated with `--repair`, or rejected for the reason given), so a regression shows;
//! and where minitri proves a minimum, it uses at most as many triangles as earcut does on the
//! fixtures where earcut's own output is exact. `docs/earcut.md` is the same as a table
//! (`python3 bench/earcut_table.py` makes it).

use crate::util::{fixtures, json, run};
use serde_json::Value;

/// What minitri does with a fixture.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Expected {
    /// Triangulated and verified as it is.
    AsIs,
    /// Rejected as it is, triangulated and verified (every piece) with `--repair`.
    Repair,
    /// Rejected even with `--repair`, the first message containing this text.
    Rejected(&'static str),
}
use Expected::*;

/// Each fixture's outcome. When a branch lands that accepts more (touching rings, the wide
/// kernel), the rows it changes fail here: rerun `python3 bench/earcut_table.py` and set each
/// such row to what `docs/earcut.md` now says (AsIs or Repair).
const EXPECTED: [(&str, Expected); 59] = [
    ("bad-diagonals", Repair),
    ("bad-hole", Rejected("rings cross")),
    ("boxy", AsIs),
    ("building", AsIs),
    ("collinear-diagonal", Repair),
    ("degenerate", Rejected("distinct vertices")),
    ("dude", AsIs),
    ("earcut", AsIs),
    ("eberly-3", AsIs),
    ("eberly-6", AsIs),
    ("empty-square", Rejected("zero area")),
    ("filtered-bridge-jhl", AsIs),
    ("hilbert", AsIs),
    ("hole-touching-outer", AsIs),
    ("hourglass", Repair),
    ("infinite-loop-jhl", Repair),
    ("issue107", Rejected("distinct vertices")),
    ("issue111", Repair),
    ("issue119", AsIs),
    ("issue131", Repair),
    ("issue142", Rejected("self-intersection")),
    ("issue147", Repair),
    ("issue149", Repair),
    ("issue16", AsIs),
    ("issue17", AsIs),
    ("issue186", Repair),
    ("issue29", AsIs),
    ("issue34", AsIs),
    ("issue35", AsIs),
    ("issue45", AsIs),
    ("issue52", AsIs),
    ("issue83", Rejected("zero area")),
    ("outside-ring", Repair),
    ("rain", AsIs),
    ("self-tangent-1", AsIs),
    ("self-tangent-2", AsIs),
    ("self-tangent-3", AsIs),
    ("self-tangent-4", AsIs),
    ("self-touching", Repair),
    ("shared-points", Repair),
    ("simplified-us-border", Rejected("self-intersection")),
    ("steiner", Repair),
    ("touching-holes", Repair),
    ("touching-holes2", AsIs),
    ("touching-holes3", AsIs),
    ("touching-holes4", AsIs),
    ("touching-holes5", AsIs),
    ("touching-holes6", AsIs),
    ("touching2", AsIs),
    ("touching3", AsIs),
    ("touching4", AsIs),
    ("water-huge", Rejected("self-intersection")),
    ("water-huge2", Rejected("self-intersection")),
    ("water-huge3", AsIs),
    ("water", Rejected("self-intersection")),
    ("water2", Repair),
    ("water3", Repair),
    ("water3b", Repair),
    ("water4", Repair),
];

#[test]
fn every_earcut_fixture_has_its_expected_outcome() {
    let earcut: Value = serde_json::from_str(
        &std::fs::read_to_string(fixtures().join("earcut/expected.json")).expect("expected.json"),
    )
    .expect("earcut's expected.json");
    let names = std::fs::read_dir(fixtures().join("earcut"))
        .expect("fixtures/earcut")
        .filter_map(|e| {
            let name = e.ok()?.file_name().into_string().ok()?;
            let stem = name.strip_suffix(".json")?.to_string();
            (stem != "expected").then_some(stem)
        })
        .count();
    assert_eq!(names, EXPECTED.len(), "every fixture is listed");
    let mut compared = 0;
    for (name, expected) in EXPECTED {
        let path = format!("fixtures/earcut/{name}.json");
        let (code, out, err) = run(&["--verify", "--time-limit", "5", &path], None);
        if expected == AsIs {
            assert_eq!(code, 0, "{name}: {err}");
        } else {
            assert_eq!(code, 1, "{name}: rejected as it is");
            assert!(
                err.contains(name),
                "{name}: the error names the file: {err}"
            );
        }
        let doc = if expected == AsIs {
            json(&out)
        } else {
            let (code, out, err) = run(&["--repair", "--verify", "--time-limit", "5", &path], None);
            assert_eq!(
                code,
                if expected == Repair { 0 } else { 1 },
                "{name}: {err}"
            );
            json(&out)
        };
        if let Rejected(why) = expected {
            let message = doc["errors"][0]["message"].as_str().expect("a message");
            assert!(message.contains(why), "{name}: {message}");
            continue;
        }
        let polygons = doc["polygons"].as_array().expect("polygons");
        assert!(!polygons.is_empty(), "{name}");
        let mut count = 0;
        for p in polygons {
            assert_eq!(
                p["verification"]["ok"], true,
                "{name}: {}",
                p["verification"]
            );
            count += p["triangle_count"].as_u64().expect("a count");
        }
        let optimal = polygons.iter().all(|p| p["optimal"] == true);
        // earcut's count 0: earcut gives up on the polygon (nothing to compare with).
        let theirs = earcut["triangles"][name].as_u64().expect("earcut count");
        if optimal && earcut["errors"].get(name).is_none() && theirs > 0 {
            assert!(count <= theirs, "{name}: {count} > earcut's {theirs}");
            compared += 1;
        }
    }
    assert!(compared >= 15, "{compared} compared with earcut");
}

/// The fixtures whose rings touch and leave hole walks (beyond the walk DP): minitri's
/// triangulation with T-junctions where the bridged walk runs straight through a vertex never
/// has more triangles than earcut's (issue 19), and it passes `--verify`.
#[test]
fn touching_fixtures_take_at_most_earcuts_triangles() {
    let earcut: Value = serde_json::from_str(
        &std::fs::read_to_string(fixtures().join("earcut/expected.json")).expect("expected.json"),
    )
    .expect("earcut's expected.json");
    for name in [
        "boxy",
        "eberly-3",
        "issue45",
        "self-tangent-3",
        "touching-holes3",
        "touching-holes4",
        "touching-holes5",
        "touching4",
    ] {
        let path = format!("fixtures/earcut/{name}.json");
        let (code, out, err) = run(&["--verify", "--time-limit", "5", &path], None);
        assert_eq!(code, 0, "{name}: {err}");
        let doc = json(&out);
        let p = &doc["polygons"][0];
        assert!(p["touches"].as_u64().is_some_and(|t| t > 0), "{name}");
        assert_eq!(p["verification"]["ok"], true, "{name}");
        let count = p["triangle_count"].as_u64().expect("a count");
        let theirs = earcut["triangles"][name].as_u64().expect("earcut count");
        assert!(count <= theirs, "{name}: {count} > earcut's {theirs}");
        let degenerate = p["degenerate_triangles"].as_array().map_or(0, Vec::len);
        let (n, holes, touches) = (
            p["vertices"].as_u64().unwrap(),
            p["holes"].as_u64().unwrap(),
            p["touches"].as_u64().unwrap(),
        );
        assert_eq!(
            count + degenerate as u64,
            n + 2 * (holes - touches) - 2,
            "{name}"
        );
    }
}
