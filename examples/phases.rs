//! Times each phase of the default path (`--algorithm minitri`, no holes) on one WKT file, for
//! profiling: `cargo run --release --example phases -- file.wkt`. An optional second argument R
//! runs the whole of `minitri::triangulate` R more times after the timed run, for profilers
//! (`valgrind --tool=callgrind target/release/examples/phases file.wkt 100`).

use minitri::algo::minitri::{circle, degenerate, mis, partition};
use minitri::io::read::{read, Format};
use minitri::Polygon;
use std::time::Instant;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = std::env::args().nth(1).ok_or("usage: phases FILE.wkt")?;
    let clock = Instant::now();
    let lap = |name: &str, detail: String| {
        println!(
            "{name:<16} {:>9.4} s  {detail}",
            clock.elapsed().as_secs_f64()
        );
    };
    let text = std::fs::read_to_string(&path)?;
    lap("read", String::new());
    let raw = read(Format::Wkt, &text)?;
    let raw = raw.first().ok_or("no polygon in the file")?;
    lap("parse", String::new());
    let (polygon, _) = Polygon::from_raw(raw)?;
    lap("validate", format!("n = {}", polygon.len()));
    let (mdts, base) = degenerate::minimally_degenerate_and_mesh(&polygon);
    lap("step 1", format!("K = {}", mdts.len()));
    let circle = circle::circle(&polygon, &mdts);
    lap("step 2", String::new());
    let chains = mis::chains(&polygon, &mdts);
    let chosen: Vec<_> = mis::maximum_independent_set(&circle, &chains)
        .into_iter()
        .map(|t| mdts[t])
        .collect();
    lap("step 3", format!("d = {}", chosen.len()));
    let triangles = if chosen.is_empty() {
        base
    } else {
        partition::triangulate_pieces(&polygon, &chosen)
    };
    lap("steps 4-5", format!("{} triangles", triangles.len()));
    let repeats: usize = match std::env::args().nth(2) {
        Some(r) => r.parse()?,
        None => 0,
    };
    for _ in 0..repeats {
        minitri::algo::minitri::triangulate(&polygon)?;
    }
    if repeats > 0 {
        lap("repeats", format!("{repeats} more runs"));
    }
    Ok(())
}
