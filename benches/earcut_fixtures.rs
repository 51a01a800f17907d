//! The 59 mapbox/earcut fixtures (`fixtures/earcut/`, ISC) as one batch, beside the `earcut`
//! crate: the time to process the whole set, one polygon after another.
//!
//! - `validate`: `Polygon::from_raw` on every fixture (exact grid and validation, which earcut
//!   does not do); `ear` and `minitri`: the same, then minitri's plain triangulation (monotone
//!   pieces, n + 2w - 2 triangles) or its minimum (`minitri::triangulate`, default options: 10 s
//!   deadline for the search with holes) of every fixture that validates; `earcut`: a fresh
//!   `earcut::Earcut` on every fixture's coordinates as `f64` (closing vertex and consecutive
//!   duplicates dropped, as minitri's reader does).
//! - Not timed: reading the files. minitri starts from its reader's exact decimals, earcut from
//!   the parsed `f64` pairs.
//! - minitri rejected 47 of the 59 when docs/benchmarks.md's figures were taken (rings sharing
//!   a vertex, touching or overlapping, spikes, rings of one or two distinct points, coordinates
//!   beyond the fast kernel's grid, which `Polygon::from_raw` still refuses;
//!   `fixtures/earcut/expected.tsv` lists today's outcomes), and a rejected fixture costs only its
//!   validation, while earcut triangulates it. So there are two
//!   groups: `earcut_fixtures_all` (all 59) and `earcut_fixtures_accepted` (the 12 minitri
//!   triangulates: the same work for both, apples to apples).
//!
//! Before timing, a table of the accepted fixtures (n, holes, triangles by ear, minitri and
//! earcut, whether the minimum was proved, one run's time) and the totals is printed; the
//! accepted set is checked against `expected.tsv`.
//!
//! Run: `cargo bench --features bench --bench earcut_fixtures` (about 2 minutes).

mod common;

use common::Fixture;
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, SamplingMode};
use minitri::{triangulate_with, Options, Polygon, RawPolygon, Triangulator};
use std::hint::black_box;
use std::time::{Duration, Instant};

/// One fixture, read.
struct Case {
    name: String,
    fixture: Fixture,
}

impl Case {
    /// The validated polygon, or why minitri rejects the fixture.
    fn validate(&self) -> Result<Polygon, String> {
        let raw: &RawPolygon = self.fixture.raw.as_ref().map_err(Clone::clone)?;
        Polygon::from_raw(raw)
            .map(|(p, _warnings)| p)
            .map_err(|e| e.to_string())
    }
}

/// Every fixture of `fixtures/earcut/` (not `expected.json`), by name.
fn load() -> Vec<Case> {
    let dir = common::earcut_fixtures_dir();
    let mut names: Vec<String> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .filter_map(|entry| {
            let name = entry.expect("a directory entry").file_name();
            let name = name.to_str()?.strip_suffix(".json")?.to_string();
            (name != "expected").then_some(name)
        })
        .collect();
    names.sort();
    names
        .into_iter()
        .map(|name| {
            let path = dir.join(format!("{name}.json"));
            let text = std::fs::read_to_string(&path).expect("a fixture file");
            let fixture = common::earcut_fixture(&text, false)
                .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
            Case { name, fixture }
        })
        .collect()
}

/// The fixtures `expected.tsv` says minitri triangulates.
fn expected_accepted() -> Vec<String> {
    let path = common::earcut_fixtures_dir().join("expected.tsv");
    let text = std::fs::read_to_string(&path).expect("expected.tsv");
    let mut names: Vec<String> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once('\t'))
        .filter(|(_, outcome)| *outcome == "triangulated")
        .map(|(name, _)| name.to_string())
        .collect();
    names.sort();
    names
}

/// What one batch does with each fixture.
#[derive(Clone, Copy)]
enum Job {
    /// Validation alone.
    Validate,
    /// Validation, then minitri's `ear` or `minitri` on the valid ones.
    Minitri(Triangulator),
    /// The `earcut` crate.
    Earcut,
}

/// Processes the batch; returns the number of triangles made (all fixtures together).
fn run(cases: &[&Case], job: Job, options: &Options) -> usize {
    let mut total = 0;
    for case in cases {
        match job {
            Job::Earcut => {
                let f = &case.fixture;
                total += common::earcut(black_box(&f.coords), &f.hole_starts).len() / 3;
            }
            Job::Validate | Job::Minitri(_) => {
                let Ok(raw) = &case.fixture.raw else { continue };
                let Ok((p, _)) = Polygon::from_raw(black_box(raw)) else {
                    continue;
                };
                if let Job::Minitri(algorithm) = job {
                    let t = triangulate_with(&p, algorithm, options).expect("valid polygons");
                    total += t.triangles.len();
                }
            }
        }
    }
    total
}

/// Prints the accepted fixtures' counts and the totals; checks the accepted set.
fn summary(cases: &[Case], options: &Options) {
    println!(
        "| fixture | n | holes | ear | minitri | earcut | earcut area deviation | proved | \
         minitri, one run |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---|---:|");
    let mut accepted = Vec::new();
    let [mut ear, mut min, mut theirs, mut theirs_all, mut unread, mut nonempty] = [0; 6];
    for case in cases {
        let f = &case.fixture;
        let out = common::earcut(&f.coords, &f.hole_starts);
        let deviation = earcut::deviation(f.coords.iter().copied(), &f.hole_starts, &out);
        let earcut = out.len() / 3;
        theirs_all += earcut;
        nonempty += usize::from(earcut > 0);
        unread += usize::from(f.raw.is_err());
        let Ok(p) = case.validate() else { continue };
        let plain = triangulate_with(&p, Triangulator::Ear, options).expect("valid");
        let start = Instant::now();
        let t = triangulate_with(&p, Triangulator::Minitri, options).expect("valid");
        let took = start.elapsed();
        let proved = if t.optimal {
            "yes".to_string()
        } else {
            format!("no (bound {})", t.lower_bound.unwrap_or(0))
        };
        println!(
            "| {} | {} | {} | {} | {} | {earcut} | {deviation:.1e} | {proved} | {took:.2?} |",
            case.name,
            p.len(),
            p.holes(),
            plain.triangles.len(),
            t.triangles.len(),
        );
        accepted.push(case.name.clone());
        ear += plain.triangles.len();
        min += t.triangles.len();
        theirs += earcut;
    }
    println!(
        "accepted by minitri: {} of {} ({unread} rejected by the reader, the rest by \
         validation); triangles on them: ear {ear}, minitri {min}, earcut {theirs}; earcut on \
         all {}: {theirs_all} triangles, none at all on {}",
        accepted.len(),
        cases.len(),
        cases.len(),
        cases.len() - nonempty,
    );
    assert_eq!(
        accepted,
        expected_accepted(),
        "the accepted set of expected.tsv"
    );
}

fn batches(c: &mut Criterion) {
    let cases = load();
    assert_eq!(cases.len(), 59, "all 59 fixtures of mapbox/earcut");
    let options = Options::default();
    summary(&cases, &options);
    let all: Vec<&Case> = cases.iter().collect();
    let accepted: Vec<&Case> = cases.iter().filter(|c| c.validate().is_ok()).collect();
    for (group_name, set) in [
        ("earcut_fixtures_all", &all),
        ("earcut_fixtures_accepted", &accepted),
    ] {
        let mut group = c.benchmark_group(group_name);
        group
            .sample_size(10)
            .sampling_mode(SamplingMode::Flat)
            .measurement_time(Duration::from_secs(5));
        let jobs = [
            ("validate", Job::Validate),
            ("ear", Job::Minitri(Triangulator::Ear)),
            ("minitri", Job::Minitri(Triangulator::Minitri)),
            ("earcut", Job::Earcut),
        ];
        for (name, job) in jobs {
            let id = BenchmarkId::new(name, format!("{}_fixtures", set.len()));
            group.bench_with_input(id, set, |b, set| b.iter(|| run(set, job, &options)));
        }
        group.finish();
    }
}

criterion_group!(benches, batches);
criterion_main!(benches);
