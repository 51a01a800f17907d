//! MINITRI beside minitri's plain triangulation (`ear`), the `earcut` crate and the Asano DP
//! (where it fits), on the same inputs, in one run: a Markdown table of time, peak heap bytes
//! per vertex and triangle counts. Issue 3's benchmark; issue 5, item 4.
//!
//! Run (release build, as every `cargo bench`):
//!
//! ```text
//! cargo bench --bench compare -- [--sizes 1000,10000,100000,1000000] [--shapes star,maze,bars,snake]
//!     [--max-seconds 10] [--kill-after 120] [--runs 5] [--dp-max 2000] [--seed 1] [--verify]
//!     [--fixtures water-huge,water-huge2,water-huge3,hilbert] [--fixtures-dir DIR] [--no-fixtures]
//! ```
//!
//! or `bench/compare.sh [options]`. What is measured:
//!
//! - Inputs: the families of `benches/common` (`star`, `maze`, `bars`, `snake`) at each nominal size, and
//!   the largest fixtures of mapbox/earcut (`fixtures/earcut/`). minitri does not do
//!   holes yet, so a fixture with holes gets earcut alone ("holes: n/a" for the others), then a
//!   second row with its outer ring alone, for all of them.
//! - Each measurement runs in a fresh worker process (this binary, `--worker`), which builds the
//!   input from the seed, then times only the algorithm: `validate` is `Polygon::from_raw`
//!   (exact decimals to grid, validation); `minitri`, `ear` and `asano` are
//!   `minitri::triangulate_with` on the validated polygon; `earcut` is a fresh `earcut::Earcut` on the
//!   same coordinates as `f64`. Up to `--runs` runs, stopping once they add up to 2 s; the table
//!   gives the median. Every worker prints a fingerprint of its input, and the parent checks that
//!   all workers of a row saw the same one.
//! - Peak heap: a counting global allocator around the system allocator; the peak is reset to the
//!   current use just before each run, so the figure is the most extra heap the run held at once
//!   (its output included, the input excluded), divided by n.
//! - Time caps: once one run of an algorithm took more than `--max-seconds`, its larger sizes of
//!   that family are skipped; a worker still running after `--kill-after` seconds (input
//!   generation included) is killed, and its larger sizes are skipped too.
//! - Counts: minitri's triangles, earcut's, and the triangles saved; checked: ear = n - 2,
//!   minitri <= earcut, minitri = DP. Departures are listed under the table.

mod common;

use common::Shape;
use minitri::{triangulate_with, Polygon, RawPolygon, Triangulator};
use std::alloc::{GlobalAlloc, Layout, System};
use std::collections::HashMap;
use std::fmt::Write as _;
use std::io::{Read, Write};
use std::path::PathBuf;
use std::process::{Command, ExitCode, Stdio};
use std::sync::atomic::{AtomicUsize, Ordering::Relaxed};
use std::time::{Duration, Instant};

// ---------------------------------------------------------------------------------------------
// Peak heap measurement.

/// The system allocator, counting the bytes in use and their peak.
struct Counting;

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

fn grew(bytes: usize) {
    let now = CURRENT.fetch_add(bytes, Relaxed) + bytes;
    PEAK.fetch_max(now, Relaxed);
}

fn shrank(bytes: usize) {
    CURRENT.fetch_sub(bytes, Relaxed);
}

// SAFETY: every call is forwarded unchanged to `System`; the counters only observe sizes.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        let p = unsafe { System.alloc_zeroed(layout) };
        if !p.is_null() {
            grew(layout.size());
        }
        p
    }

    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) };
        shrank(layout.size());
    }

    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let p = unsafe { System.realloc(ptr, layout, new_size) };
        if !p.is_null() {
            if new_size >= layout.size() {
                grew(new_size - layout.size());
            } else {
                shrank(layout.size() - new_size);
            }
        }
        p
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Runs `f`, returning its result, its wall time and the most extra heap it held at once.
fn measure<T>(f: impl FnOnce() -> T) -> (T, Duration, usize) {
    let base = CURRENT.load(Relaxed);
    PEAK.store(base, Relaxed);
    let start = Instant::now();
    let out = f();
    let elapsed = start.elapsed();
    (out, elapsed, PEAK.load(Relaxed).saturating_sub(base))
}

// ---------------------------------------------------------------------------------------------
// Worker: one algorithm on one input, in its own process.

/// The algorithms of a row, in column order.
const ALGOS: [&str; 5] = ["validate", "minitri", "ear", "earcut", "asano"];

/// One input, in both forms.
struct Input {
    raw: RawPolygon,
    coords: Vec<[f64; 2]>,
    hole_starts: Vec<u32>,
    fingerprint: u64,
}

/// FNV-1a over bytes.
fn fnv(bytes: impl IntoIterator<Item = u8>) -> u64 {
    bytes.into_iter().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// `gen:<shape>:<n>:<seed>`, `fixture:<path>` (all rings) or `outer:<path>` (outer ring only).
fn load(case: &str) -> Result<Input, String> {
    let (kind, rest) = case.split_once(':').ok_or("bad case")?;
    match kind {
        "gen" => {
            let parts: Vec<&str> = rest.split(':').collect();
            let [shape, n, seed] = parts[..] else {
                return Err(format!("bad case {case}"));
            };
            let shape = parse_shape(shape)?;
            let n: usize = n.parse().map_err(|_| "bad n")?;
            let seed: u64 = seed.parse().map_err(|_| "bad seed")?;
            let points = shape.points(n, seed);
            Ok(Input {
                raw: common::raw(&points),
                coords: common::earcut_input(&points),
                hole_starts: Vec::new(),
                fingerprint: fnv(points.iter().flatten().flat_map(|v| v.to_le_bytes())),
            })
        }
        "fixture" | "outer" => {
            let text = std::fs::read_to_string(rest).map_err(|e| format!("{rest}: {e}"))?;
            let fixture = common::earcut_fixture(&text, kind == "outer")
                .map_err(|e| format!("{rest}: {e}"))?;
            Ok(Input {
                raw: fixture.raw.map_err(|e| format!("{rest}: {e}"))?,
                coords: fixture.coords,
                hole_starts: fixture.hole_starts,
                fingerprint: fnv(kind.bytes().chain(text.bytes())),
            })
        }
        _ => Err(format!("bad case {case}")),
    }
}

fn parse_shape(name: &str) -> Result<Shape, String> {
    match name {
        "star" => Ok(Shape::Star),
        "maze" => Ok(Shape::Maze),
        "bars" => Ok(Shape::Bars),
        "snake" => Ok(Shape::Snake),
        _ => Err(format!("unknown shape {name:?} (star, maze, bars, snake)")),
    }
}

/// Runs `algo` on `case` up to `runs` times (fewer once they add up to 2 s, unless `exact_runs`:
/// `bench/instructions.sh` counts instructions) and prints one `key=value` line (or `na <why>`).
fn worker(
    case: &str,
    algo: &str,
    runs: usize,
    verify: bool,
    exact_runs: bool,
) -> Result<String, String> {
    let input = load(case)?;
    let holes = input.hole_starts.len();
    let fp = input.fingerprint;
    let n_earcut = input.coords.len();
    let mut times = Vec::new();
    let mut peak = 0;
    let mut total = Duration::ZERO;
    let mut repeat = |f: &mut dyn FnMut() -> (Duration, usize)| {
        while times.len() < runs.max(1)
            && (times.is_empty() || exact_runs || total < Duration::from_secs(2))
        {
            let (t, p) = f();
            times.push(t);
            peak = peak.max(p);
            total += t;
        }
    };
    let mut line = String::new();
    let n;
    if algo == "earcut" {
        let mut out = Vec::new();
        repeat(&mut || {
            let (o, t, p) = measure(|| common::earcut(&input.coords, &input.hole_starts));
            out = o;
            (t, p)
        });
        n = n_earcut;
        let xy = &input.coords;
        let zero = out
            .chunks_exact(3)
            .filter(|t| {
                let [a, b, c] = [xy[t[0] as usize], xy[t[1] as usize], xy[t[2] as usize]];
                (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) == 0.0
            })
            .count();
        let deviation = earcut::deviation(xy.iter().copied(), &input.hole_starts, &out);
        write!(
            line,
            " tris={} zero={zero} deviation={deviation:e}",
            out.len() / 3
        )
        .expect("string");
    } else {
        let polygon = match Polygon::from_raw(&input.raw) {
            Ok((p, _)) => p,
            Err(e) => return Ok(format!("na invalid: {e}")),
        };
        n = polygon.len();
        if algo == "validate" {
            repeat(&mut || {
                let (_, t, p) = measure(|| Polygon::from_raw(&input.raw));
                (t, p)
            });
        } else {
            let algorithm = match algo {
                "minitri" => Triangulator::Minitri,
                "ear" => Triangulator::Ear,
                "asano" => Triangulator::Asano,
                _ => return Err(format!("unknown algorithm {algo:?}")),
            };
            if holes > 0 {
                return Ok("na holes: n/a".into());
            }
            let unlimited = minitri::pipeline::Options {
                dp_limit: usize::MAX,
                ..Default::default()
            };
            let mut result = None;
            repeat(&mut || {
                let (r, t, p) = measure(|| triangulate_with(&polygon, algorithm, &unlimited));
                result = Some(r);
                (t, p)
            });
            let t = match result.expect("ran once") {
                Ok(t) => t,
                Err(e) => return Ok(format!("na {e}")),
            };
            write!(
                line,
                " tris={} deg={}",
                t.triangles.len(),
                t.degenerate.len()
            )
            .expect("string");
            if verify {
                let check = minitri::verify::check(&polygon, &t);
                if check.valid {
                    line.push_str(" verify=ok");
                } else {
                    let why = check.problems.join("; ").replace(char::is_whitespace, "_");
                    write!(line, " verify=FAILED:{why}").expect("string");
                }
            }
        }
    }
    times.sort();
    let median = times[times.len() / 2];
    Ok(format!(
        "ok n={n} holes={holes} fp={fp:016x} time={} runs={} peak={peak}{line}",
        median.as_secs_f64(),
        times.len()
    ))
}

// ---------------------------------------------------------------------------------------------
// Parent: spawns the workers, applies the caps, prints the table.

struct Config {
    shapes: Vec<Shape>,
    sizes: Vec<usize>,
    max_seconds: f64,
    kill_after: f64,
    runs: usize,
    dp_max: usize,
    seed: u64,
    verify: bool,
    fixtures: Vec<String>,
    fixtures_dir: PathBuf,
}

const USAGE: &str =
    "usage: cargo bench --bench compare -- [--sizes N,N,..] [--shapes star,maze,bars,snake]
    [--max-seconds S] [--kill-after K] [--runs R] [--dp-max N] [--seed N] [--verify]
    [--fixtures NAME,NAME,..] [--fixtures-dir DIR] [--no-fixtures]
  --sizes         nominal sizes (default 1000,10000,100000,1000000; 1e5 and 10^5 work too)
  --shapes        generated families (default star,maze,bars,snake)
  --max-seconds   skip an algorithm's larger sizes once one run took more than S s (default 10)
  --kill-after    kill a worker still running after K s, input generation included (default 120)
  --runs          at most R runs per measurement, fewer once they add up to 2 s (default 5)
  --dp-max        run the Asano DP up to this many vertices (default 2000)
  --seed          generator seed (default 1)
  --verify        check minitri's, ear's and the DP's outputs with minitri's independent checker
                  (outside the timing)
  --fixtures      earcut fixtures (default water-huge3,water-huge,water-huge2,water,hilbert)
  --fixtures-dir  where they are (default fixtures/earcut in the crate)
  --no-fixtures   generated families only";

fn parse_size(s: &str) -> Result<usize, String> {
    let s = s.trim().replace('_', "");
    let bad = || format!("bad size {s:?}");
    if let Some(e) = s.strip_prefix("10^").or_else(|| s.strip_prefix("1e")) {
        let e: u32 = e.parse().map_err(|_| bad())?;
        10usize.checked_pow(e).ok_or_else(bad)
    } else {
        s.parse().map_err(|_| bad())
    }
}

fn parse_args(args: &[String]) -> Result<Config, String> {
    let mut c = Config {
        shapes: vec![Shape::Star, Shape::Maze, Shape::Bars, Shape::Snake],
        sizes: vec![1_000, 10_000, 100_000, 1_000_000],
        max_seconds: 10.0,
        kill_after: 120.0,
        runs: 5,
        dp_max: 2000,
        seed: 1,
        verify: false,
        fixtures: [
            "water-huge3",
            "water-huge",
            "water-huge2",
            "water",
            "hilbert",
        ]
        .map(String::from)
        .to_vec(),
        fixtures_dir: common::earcut_fixtures_dir(),
    };
    let mut it = args.iter();
    while let Some(flag) = it.next() {
        let mut value = || it.next().ok_or(format!("{flag} needs a value"));
        let number = |v: &String| v.parse::<f64>().map_err(|_| format!("bad number {v:?}"));
        match flag.as_str() {
            "--bench" => {} // cargo bench passes it
            "--sizes" => {
                c.sizes = value()?
                    .split(',')
                    .map(parse_size)
                    .collect::<Result<_, _>>()?;
            }
            "--shapes" => {
                c.shapes = value()?
                    .split(',')
                    .map(parse_shape)
                    .collect::<Result<_, _>>()?;
            }
            "--max-seconds" => c.max_seconds = number(value()?)?,
            "--kill-after" => c.kill_after = number(value()?)?,
            "--runs" => c.runs = number(value()?)? as usize,
            "--dp-max" => c.dp_max = parse_size(value()?)?,
            "--seed" => c.seed = number(value()?)? as u64,
            "--verify" => c.verify = true,
            "--fixtures" => c.fixtures = value()?.split(',').map(String::from).collect(),
            "--fixtures-dir" => c.fixtures_dir = PathBuf::from(value()?),
            "--no-fixtures" => c.fixtures.clear(),
            "-h" | "--help" => return Err(USAGE.into()),
            other => return Err(format!("unknown option {other:?}\n{USAGE}")),
        }
    }
    Ok(c)
}

/// What one worker reported.
enum Cell {
    Ok(HashMap<String, String>),
    /// Not applicable or not run, with the text for the table.
    Text(String),
}

impl Cell {
    fn get(&self, key: &str) -> Option<&str> {
        match self {
            Cell::Ok(m) => m.get(key).map(String::as_str),
            Cell::Text(_) => None,
        }
    }

    fn num(&self, key: &str) -> Option<f64> {
        self.get(key).and_then(|v| v.parse().ok())
    }

    fn time(&self) -> String {
        match self {
            Cell::Ok(m) => fmt_time(m["time"].parse().unwrap_or(f64::NAN)),
            Cell::Text(t) => t.clone(),
        }
    }
}

fn fmt_time(s: f64) -> String {
    let (v, unit) = match s {
        s if s < 1e-3 => (s * 1e6, "µs"),
        s if s < 1.0 => (s * 1e3, "ms"),
        s => (s, "s"),
    };
    let digits = if v < 10.0 {
        2
    } else if v < 100.0 {
        1
    } else {
        0
    };
    format!("{v:.digits$} {unit}")
}

/// Spawns a worker, killing it after `kill_after` seconds.
fn spawn(config: &Config, case: &str, algo: &str) -> Cell {
    let exe = std::env::current_exe().expect("own path");
    let mut cmd = Command::new(exe);
    cmd.args(["--worker", case, algo, &config.runs.to_string()]);
    if config.verify {
        cmd.arg("--verify");
    }
    let mut child = match cmd.stdout(Stdio::piped()).stderr(Stdio::inherit()).spawn() {
        Ok(c) => c,
        Err(e) => return Cell::Text(format!("failed to start: {e}")),
    };
    let start = Instant::now();
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if start.elapsed().as_secs_f64() > config.kill_after => {
                let _ = child.kill();
                let _ = child.wait();
                return Cell::Text(format!("killed (> {} s)", config.kill_after));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(10)),
            Err(e) => return Cell::Text(format!("wait failed: {e}")),
        }
    };
    let mut out = String::new();
    if let Some(mut s) = child.stdout.take() {
        let _ = s.read_to_string(&mut out);
    }
    let out = out.trim();
    if !status.success() {
        return Cell::Text(format!("failed ({status})"));
    }
    if let Some(rest) = out.strip_prefix("ok ") {
        Cell::Ok(
            rest.split_whitespace()
                .filter_map(|kv| kv.split_once('='))
                .map(|(k, v)| (k.to_string(), v.to_string()))
                .collect(),
        )
    } else {
        Cell::Text(out.strip_prefix("na ").unwrap_or(out).to_string())
    }
}

const HEADER: &str = "| shape | n | validate | minitri | ear | earcut | minitri ÷ earcut | DP | \
peak B/vertex: minitri | ear | earcut | triangles: minitri | earcut | saved |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|";

/// One table row from the cells of `ALGOS`; problems go to `notes`.
fn row(label: &str, cells: &[Cell], notes: &mut Vec<String>) -> String {
    let [validate, minitri, ear, earcut, dp] = cells else {
        unreachable!("one cell per algorithm")
    };
    // n as minitri sees it (validate), else as earcut does.
    let n = validate.num("n").or(earcut.num("n")).unwrap_or(f64::NAN);
    let fps: Vec<&str> = cells.iter().filter_map(|c| c.get("fp")).collect();
    if fps.windows(2).any(|w| w[0] != w[1]) {
        notes.push(format!(
            "{label}: the workers saw DIFFERENT inputs ({fps:?})"
        ));
    }
    if let (Some(a), Some(b)) = (validate.num("n"), earcut.num("n")) {
        if a != b {
            notes.push(format!("{label}: minitri has n = {a}, earcut n = {b}"));
        }
    }
    let ratio = match (minitri.num("time"), earcut.num("time")) {
        (Some(a), Some(b)) if b > 0.0 => format!("{:.1}", a / b),
        _ => "–".into(),
    };
    let per_vertex = |c: &Cell| match c.num("peak") {
        Some(p) => format!("{:.0}", p / n),
        None => "–".into(),
    };
    let count = |c: &Cell| c.get("tris").map_or("–".into(), str::to_string);
    let saved = match (minitri.num("tris"), earcut.num("tris")) {
        (Some(m), Some(e)) => format!("{}", e - m),
        _ => "–".into(),
    };
    let holes = validate.num("holes").unwrap_or(0.0);
    if let Some(t) = ear.num("tris") {
        if t != n - 2.0 {
            notes.push(format!(
                "{label}: ear gave {t} triangles, not n - 2 = {}",
                n - 2.0
            ));
        }
    }
    if let (Some(m), Some(e)) = (minitri.num("tris"), earcut.num("tris")) {
        if m > e {
            notes.push(format!(
                "{label}: minitri has MORE triangles ({m}) than earcut ({e})"
            ));
        }
    }
    if let Some(e) = earcut.num("tris") {
        let plain = n + 2.0 * holes - 2.0;
        if e != plain {
            notes.push(format!(
                "{label}: earcut gave {e} triangles; a triangulation of a valid polygon \
                 without degenerate triangles has n + 2w - 2 = {plain}"
            ));
        }
        let zero = earcut.num("zero").unwrap_or(0.0);
        if zero > 0.0 {
            notes.push(format!("{label}: earcut output {zero} zero-area triangles"));
        }
        let dev = earcut.num("deviation").unwrap_or(0.0);
        if dev != 0.0 {
            notes.push(format!("{label}: earcut's area deviation is {dev:e}"));
        }
    }
    if let (Some(m), Some(d)) = (minitri.num("tris"), dp.num("tris")) {
        if m != d {
            notes.push(format!("{label}: minitri {m} triangles but the DP {d}"));
        }
    }
    for (algo, c) in ALGOS.iter().zip(cells) {
        if let Some(v) = c.get("verify").filter(|v| *v != "ok") {
            notes.push(format!("{label}: {algo}: verify {v}"));
        }
        if let Cell::Text(t) = c {
            if t.starts_with("failed") {
                notes.push(format!("{label}: {algo}: {t}"));
            }
        }
    }
    if let Cell::Text(t) = validate {
        if t.starts_with("invalid") {
            notes.push(format!("{label}: minitri rejects the input ({t})"));
        }
    }
    let time = |c: &Cell| match c {
        Cell::Text(t) if t.starts_with("invalid") => "invalid".to_string(),
        c => c.time(),
    };
    format!(
        "| {label} | {n} | {} | {} | {} | {} | {ratio} | {} | {} | {} | {} | {} | {} | {saved} |",
        time(validate),
        time(minitri),
        time(ear),
        time(earcut),
        time(dp),
        per_vertex(minitri),
        per_vertex(ear),
        per_vertex(earcut),
        count(minitri),
        count(earcut),
    )
}

/// Runs every algorithm of one row on `case`, in column order, and prints the row. `stopped`
/// holds, per algorithm, why it is no longer run on this family (updated by the caps).
fn run_row(
    config: &Config,
    case: &str,
    label: &str,
    stopped: &mut HashMap<&'static str, String>,
    notes: &mut Vec<String>,
) -> f64 {
    let mut cells = Vec::new();
    let mut n = f64::NAN;
    let mut holes = 0.0;
    for algo in ALGOS {
        let cell = if let Some(why) = stopped.get(algo) {
            Cell::Text(why.clone())
        } else if algo == "asano" && holes == 0.0 && (n.is_nan() || n > config.dp_max as f64) {
            Cell::Text("–".into())
        } else {
            let cell = spawn(config, case, algo);
            eprintln!("  {label} {algo}: {}", cell.time());
            if algo == "validate" || n.is_nan() {
                n = cell.num("n").unwrap_or(n);
                holes = cell.num("holes").unwrap_or(holes);
            }
            let killed = matches!(&cell, Cell::Text(t) if t.starts_with("killed"));
            if killed || cell.num("time").is_some_and(|t| t > config.max_seconds) {
                let why = if killed { "killed" } else { "took" };
                let cap = if killed {
                    config.kill_after
                } else {
                    config.max_seconds
                };
                stopped.insert(algo, format!("skipped (> {cap} s at n = {n}: {why})"));
            }
            cell
        };
        cells.push(cell);
    }
    let label = if holes > 0.0 {
        format!("{label} ({holes} holes)")
    } else {
        label.to_string()
    };
    println!("{}", row(&label, &cells, notes));
    let _ = std::io::stdout().flush();
    holes
}

fn parent(config: &Config) {
    println!("{HEADER}");
    let mut notes = Vec::new();
    for &shape in &config.shapes {
        let mut stopped = HashMap::new();
        for &size in &config.sizes {
            let case = format!("gen:{}:{size}:{}", shape.name(), config.seed);
            run_row(config, &case, shape.name(), &mut stopped, &mut notes);
        }
    }
    for name in &config.fixtures {
        let path = config.fixtures_dir.join(format!("{name}.json"));
        if !path.exists() {
            notes.push(format!("fixture {}: not found", path.display()));
            continue;
        }
        let path = path.display();
        let case = format!("fixture:{path}");
        let holes = run_row(config, &case, name, &mut HashMap::new(), &mut notes);
        if holes > 0.0 {
            let case = format!("outer:{path}");
            let label = format!("{name}, outer ring");
            run_row(config, &case, &label, &mut HashMap::new(), &mut notes);
        }
    }
    println!();
    println!(
        "Times: median of up to {} runs (fewer once they add up to 2 s); validate = \
         Polygon::from_raw (grid + validation), not included in the minitri and ear times. \
         Peak B/vertex: most extra heap held at once during one run, output included, input \
         excluded. saved = earcut's triangles - minitri's. ear = n - 2 is checked on every row.",
        config.runs
    );
    if notes.is_empty() {
        println!("Checks: no departures (minitri <= earcut, ear = n - 2, minitri = DP).");
    } else {
        println!("Notes:");
        for note in notes {
            println!("- {note}");
        }
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    if args.first().map(String::as_str) == Some("--worker") {
        let (Some(case), Some(algo), Some(runs)) = (args.get(1), args.get(2), args.get(3)) else {
            eprintln!("compare --worker CASE ALGORITHM RUNS [--verify] [--exact-runs]");
            return ExitCode::from(2);
        };
        let verify = args.iter().any(|a| a == "--verify");
        let exact_runs = args.iter().any(|a| a == "--exact-runs");
        return match worker(case, algo, runs.parse().unwrap_or(1), verify, exact_runs) {
            Ok(line) => {
                println!("{line}");
                ExitCode::SUCCESS
            }
            Err(e) => {
                eprintln!("compare worker: {e}");
                ExitCode::FAILURE
            }
        };
    }
    match parse_args(&args) {
        Ok(config) => {
            parent(&config);
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{e}");
            ExitCode::from(2)
        }
    }
}
