//! Shared helpers: running the real binary, loading fixtures.

use assert_cmd::Command;
use minitri::geom::kernel::{cross, dot, in_closed_wedge, Point};
use minitri::{Decimal, Polygon, RawPolygon};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The repository's fixtures directory.
pub fn fixtures() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures")
}

/// A fixture directory's `expected.tsv`: file name, tab, expected value; `#` comments.
pub fn expected(dir: &str) -> Vec<(String, String)> {
    let text =
        std::fs::read_to_string(fixtures().join(dir).join("expected.tsv")).expect("expected.tsv");
    text.lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let (name, value) = l
                .split_once('\t')
                .unwrap_or_else(|| panic!("no tab in {l:?}"));
            (name.to_string(), value.to_string())
        })
        .collect()
}

/// The `minitri` binary, run from the repository root.
pub fn minitri() -> Command {
    let mut cmd = Command::cargo_bin("minitri").expect("binary");
    cmd.current_dir(env!("CARGO_MANIFEST_DIR"));
    cmd
}

/// Runs the binary on `stdin` and requires exit status 1 and `message` on standard error.
pub fn fails_with(args: &[&str], stdin: &str, message: &str) {
    let (code, _, err) = run(args, Some(stdin));
    assert_eq!(code, 1, "{args:?}: {err}");
    assert!(err.contains(message), "{args:?}: {err}");
}

/// Runs the binary, returning (exit code, stdout, stderr).
pub fn run(args: &[&str], stdin: Option<&str>) -> (i32, String, String) {
    let mut cmd = minitri();
    cmd.args(args);
    if let Some(s) = stdin {
        cmd.write_stdin(s);
    }
    outcome(&mut cmd)
}

/// Runs a prepared command to its end: (exit code, stdout, stderr).
pub fn outcome(cmd: &mut Command) -> (i32, String, String) {
    let out = cmd.output().expect("run minitri");
    (
        out.status.code().expect("exit code"),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Runs the binary with `--verify` and a fault injected into every output before it is checked
/// (`MINITRI_CORRUPT_FOR_TESTS=1`: one triangle or face dropped), returning the exit code and
/// the first polygon's `verification` object.
pub fn verify_with_fault(args: &[&str]) -> (Option<i32>, Value) {
    let out = minitri()
        .args(args)
        .arg("--verify")
        .env(minitri::pipeline::CORRUPT_FOR_TESTS, "1")
        .output()
        .expect("run minitri");
    let doc = json(&String::from_utf8_lossy(&out.stdout));
    (
        out.status.code(),
        doc["polygons"][0]["verification"].clone(),
    )
}

/// Parses the JSON document on stdout.
pub fn json(stdout: &str) -> Value {
    serde_json::from_str(stdout).unwrap_or_else(|e| panic!("stdout is not JSON ({e}): {stdout}"))
}

/// Is the closed segment `a b` inside the closed polygon? Straight from the definition.
pub fn chord(poly: &Polygon, a: usize, b: usize) -> bool {
    let (pa, pb) = (poly.point(a), poly.point(b));
    let wedge = |w: usize, t: Point| {
        in_closed_wedge(
            poly.point(poly.prev(w)),
            poly.point(w),
            poly.point(poly.next(w)),
            t,
        )
    };
    if !wedge(a, pb) || !wedge(b, pa) {
        return false;
    }
    (0..poly.len()).all(|w| {
        let (p, q) = (poly.point(w), poly.point(poly.next(w)));
        let (o1, o2, o3, o4) = (
            cross(pa, pb, p),
            cross(pa, pb, q),
            cross(p, q, pa),
            cross(p, q, pb),
        );
        let crosses = o1.signum() * o2.signum() < 0 && o3.signum() * o4.signum() < 0;
        let inside = o1 == 0 && dot(p, pa, pb) < 0;
        !crosses && (!inside || (wedge(w, pa) && wedge(w, pb)))
    })
}

/// A deterministic xorshift generator: `rnd(n)` is a number in `0..n`.
pub fn xorshift(seed: u64) -> impl FnMut(i64) -> i64 {
    let mut state = seed;
    move |n: i64| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % n as u64) as i64
    }
}

/// A polygon from integer rings (outer first, any orientation), if valid.
pub fn polygon_from_rings(rings: &[Vec<(i64, i64)>]) -> Option<Polygon> {
    let d = |v: i64| Decimal::parse(&v.to_string()).ok();
    let rings: Option<Vec<Vec<[Decimal; 2]>>> = rings
        .iter()
        .map(|r| r.iter().map(|&(x, y)| Some([d(x)?, d(y)?])).collect())
        .collect();
    Polygon::from_raw(&RawPolygon {
        rings: rings?,
        ..Default::default()
    })
    .ok()
    .map(|(p, _)| p)
}
