//! All 59 polygons of earcut's test suite (`fixtures/earcut/`, ISC, see its SOURCE.md) through the
//! command line with `--verify`: each is triangulated and verified, or rejected with the specific
//! error listed in `fixtures/earcut/expected.tsv`. Where minitri proves a minimum, it uses at most
//! as many triangles as earcut does on the fixtures where earcut's own output is exact.

use crate::util::{expected, fixtures, json, run};
use serde_json::Value;

#[test]
fn every_earcut_fixture_is_triangulated_and_verified_or_rejected_clearly() {
    let earcut: Value = serde_json::from_str(
        &std::fs::read_to_string(fixtures().join("earcut/expected.json")).expect("expected.json"),
    )
    .expect("earcut's expected.json");
    let cases = expected("earcut");
    assert_eq!(cases.len(), 59, "all 59 fixtures are listed");
    let (mut triangulated, mut compared) = (0, 0);
    for (name, outcome) in &cases {
        let path = format!("fixtures/earcut/{name}.json");
        let (code, out, err) = run(&["--verify", "--time-limit", "5", &path], None);
        let doc = json(&out);
        if outcome == "triangulated" {
            assert_eq!(code, 0, "{name}: {err}");
            let p = &doc["polygons"][0];
            assert_eq!(
                p["verification"]["ok"], true,
                "{name}: {}",
                p["verification"]
            );
            triangulated += 1;
            let count = p["triangle_count"].as_u64().expect("a count");
            let exact = earcut["errors"].get(name.as_str()).is_none();
            if p["optimal"] == true && exact {
                let theirs = earcut["triangles"][name.as_str()]
                    .as_u64()
                    .expect("earcut count");
                assert!(count <= theirs, "{name}: {count} > earcut's {theirs}");
                compared += 1;
            }
        } else {
            assert_eq!(code, 1, "{name}: rejected");
            let message = doc["errors"][0]["message"].as_str().expect("a message");
            assert!(message.starts_with(outcome.as_str()), "{name}: {message}");
            assert!(
                err.contains(name.as_str()),
                "{name}: the error names the file: {err}"
            );
        }
    }
    assert!(
        triangulated >= 31 && compared >= 5,
        "{triangulated} {compared}"
    );
}
