//! Batch throughput (issue 5, item 4): polygons per second on many small random rectilinear
//! polygons with collinear vertices (`common::small_rectilinear`, 8 to 40 vertices), and how it
//! scales from 1 to 2 threads, beside the `earcut` crate on the same polygons.
//!
//! Run (release build, as every `cargo bench`):
//!
//! ```text
//! cargo bench --bench batch -- [--count 100000] [--threads 1,2] [--seed 1] [--write PATH]
//! ```
//!
//! `--write PATH` also keeps the GeoJSON Lines file at `PATH` (to time the `minitri` binary on
//! it: `minitri --jobs 1 -q PATH -o out.json`).
//!
//! What is measured, wall time of one run each:
//!
//! - `minitri batch`: the library's batch path end to end, as `minitri FILE.ndjson` runs it:
//!   [`minitri::batch::run_document`] on a newline-delimited GeoJSON file of all the polygons
//!   (streamed reading, exact decimals, validation, MINITRI, the JSON document written to a
//!   sink that discards it), on a rayon pool of 1 and 2 threads;
//! - `minitri triangulate`: validation and MINITRI alone on the polygons already read
//!   ([`minitri::pipeline::process_raw`] in a loop), one thread;
//! - `earcut`: a fresh `earcut::Earcut` per polygon on the same coordinates as `f64`, one thread
//!   (it neither validates nor reads nor writes, and keeps n - 2 triangles).

mod common;

use minitri::batch::{discover, run_document, Settings, Silent};
use minitri::io::write::OutputFormat;
use minitri::pipeline::process_raw;
use minitri::Options;
use std::fmt::Write as _;
use std::time::{Duration, Instant};

/// Command-line options.
struct Args {
    count: usize,
    threads: Vec<usize>,
    seed: u64,
    write: Option<std::path::PathBuf>,
}

fn parse_args() -> Result<Args, String> {
    let mut args = Args {
        count: 100_000,
        threads: vec![1, 2],
        seed: 1,
        write: None,
    };
    let mut it = std::env::args().skip(1);
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        match flag.as_str() {
            "--count" => args.count = value()?.parse().map_err(|e| format!("--count: {e}"))?,
            "--seed" => args.seed = value()?.parse().map_err(|e| format!("--seed: {e}"))?,
            "--threads" => {
                args.threads = value()?
                    .split(',')
                    .map(|t| t.parse().map_err(|e| format!("--threads: {e}")))
                    .collect::<Result<_, _>>()?;
            }
            "--write" => args.write = Some(value()?.into()),
            "--bench" => {} // passed by `cargo bench`
            "--help" | "-h" => {
                return Err(
                    "usage: cargo bench --bench batch -- [--count N] [--threads 1,2] [--seed S] [--write PATH]"
                        .into(),
                )
            }
            other => return Err(format!("unknown option {other}")),
        }
    }
    Ok(args)
}

fn main() -> Result<(), String> {
    let args = parse_args()?;
    let polygons: Vec<Vec<[i64; 2]>> = (0..args.count as u64)
        .map(|k| common::small_rectilinear(args.seed.wrapping_mul(1_000_003).wrapping_add(k)))
        .collect();
    let vertices: usize = polygons.iter().map(Vec::len).sum();
    let dir = tempfile::tempdir().map_err(|e| e.to_string())?;
    let path = dir.path().join("polygons.ndjson");
    let mut text = String::with_capacity(vertices * 10);
    for ring in &polygons {
        text.push_str(r#"{"type": "Polygon", "coordinates": [["#);
        for (i, [x, y]) in ring.iter().enumerate() {
            let comma = if i == 0 { "" } else { ", " };
            let _ = write!(text, "{comma}[{x}, {y}]");
        }
        text.push_str("]]}\n");
    }
    std::fs::write(&path, &text).map_err(|e| e.to_string())?;
    if let Some(keep) = &args.write {
        std::fs::write(keep, &text).map_err(|e| format!("{}: {e}", keep.display()))?;
    }
    eprintln!(
        "{} polygons, {} vertices ({:.1} per polygon), {:.1} MB of GeoJSON Lines",
        args.count,
        vertices,
        vertices as f64 / args.count as f64,
        text.len() as f64 / 1e6
    );
    drop(text);

    println!("| run | threads | polygons/s | time | triangles |");
    println!("|---|---:|---:|---:|---:|");
    let row = |name: &str, threads: usize, elapsed: Duration, triangles: usize| {
        println!(
            "| {name} | {threads} | {:.0} | {:.2} s | {triangles} |",
            args.count as f64 / elapsed.as_secs_f64(),
            elapsed.as_secs_f64()
        );
    };

    let inputs = discover(&[path], None);
    let settings = Settings::default();
    for &threads in &args.threads {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| e.to_string())?;
        let start = Instant::now();
        let report = pool
            .install(|| {
                let sink = OutputFormat::Json.sink(std::io::sink())?;
                run_document(&inputs, &settings, sink, &Silent)
            })
            .map_err(|e| e.to_string())?;
        let elapsed = start.elapsed();
        if report.tally.errors > 0 || report.tally.solved != args.count {
            return Err(format!("batch: {:?}", report.tally));
        }
        row(
            "minitri batch (read NDJSON, validate, MINITRI, write JSON)",
            threads,
            elapsed,
            report.tally.triangles,
        );
    }

    let raws: Vec<_> = polygons.iter().map(|p| common::raw(p)).collect();
    let options = Options::default();
    let start = Instant::now();
    let mut triangles = 0;
    for (k, raw) in raws.into_iter().enumerate() {
        for outcome in process_raw("bench", k, raw, &options) {
            match outcome.result {
                Ok(solved) => triangles += solved.triangulation.triangles.len(),
                Err(e) => return Err(format!("polygon {k}: {e}")),
            }
        }
    }
    row(
        "minitri triangulate (validate, MINITRI)",
        1,
        start.elapsed(),
        triangles,
    );

    let coords: Vec<Vec<[f64; 2]>> = polygons.iter().map(|p| common::earcut_input(p)).collect();
    let start = Instant::now();
    let triangles: usize = coords
        .iter()
        .map(|c| common::earcut(c, &[]).len() / 3)
        .sum();
    row("earcut", 1, start.elapsed(), triangles);
    Ok(())
}
