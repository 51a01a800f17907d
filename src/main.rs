//! The `minitri` command: flags, library call, writer, exit code. All the work is in the library
//! (`minitri::batch`); this file wires the flags, the thread pool, the progress bar and the
//! output file or directory.

mod allocator;
mod args;
mod shell;

#[global_allocator]
static ALLOCATOR: allocator::Split = allocator::Split;

use anyhow::Context;
use args::{is_tree, Flags};
use indicatif::{ProgressBar, ProgressStyle};
use minitri::batch::{
    discover_counting, plan, run_document, run_tree, AtomicFile, Observer, Settings, Tally, TreeJob,
};
use minitri::io::read::limits;
use std::io::{self, IsTerminal, Write};
use std::path::Path;
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

fn main() -> ExitCode {
    match run() {
        Ok(code) => code,
        Err(err) => {
            if err
                .downcast_ref::<io::Error>()
                .is_some_and(|e| e.kind() == io::ErrorKind::BrokenPipe)
            {
                return ExitCode::SUCCESS;
            }
            say(&format!("{err:#}"));
            ExitCode::from(1)
        }
    }
}

/// The most worker threads `--jobs` starts (more only cost memory and start-up time: 10,000
/// threads took 39 s to start on a square).
const MAX_JOBS: usize = 256;

/// A line on standard error, `minitri: ` first. A failure to write it (standard error closed,
/// full, a broken pipe) is ignored: diagnostics never stop a run or lose its result.
fn say(line: &str) {
    let _ = writeln!(io::stderr().lock(), "minitri: {line}");
}

/// Is standard output an open descriptor? A program started with it closed (`>&-`) finds it
/// reopened on `/dev/null` by Rust's start-up code (read-write), which would lose the result
/// with exit status 0. That reopened descriptor looks exactly like a `/dev/null` opened
/// read-write on purpose (Python's `subprocess.DEVNULL`, systemd's `StandardOutput=null`), so
/// on Linux the question is answered before Rust's start-up code runs ([`STDOUT_AT_START`]);
/// elsewhere, and in any case, a descriptor that cannot be duplicated counts as closed.
fn stdout_is_open() -> bool {
    #[cfg(unix)]
    {
        use std::os::fd::AsFd;
        if io::stdout().as_fd().try_clone_to_owned().is_err() {
            return false;
        }
    }
    #[cfg(target_os = "linux")]
    if !STDOUT_AT_START.load(Ordering::Relaxed) {
        return false;
    }
    true
}

/// Whether descriptor 1 was open when the process started: set by [`RECORD_STDOUT`], which
/// the C runtime calls (as every `.init_array` entry) before `main`, hence before Rust's
/// start-up code reopens closed standard descriptors on `/dev/null`.
#[cfg(target_os = "linux")]
static STDOUT_AT_START: AtomicBool = AtomicBool::new(true);

#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static RECORD_STDOUT: extern "C" fn() = {
    extern "C" fn record() {
        // SAFETY: `fcntl(F_GETFD)` only reads the descriptor's flags (-1 when it is not open).
        let open = unsafe { libc::fcntl(1, libc::F_GETFD) } != -1;
        STDOUT_AT_START.store(open, Ordering::Relaxed);
    }
    record
};

fn run() -> anyhow::Result<ExitCode> {
    let started = Instant::now();
    let flags = Flags::from_env();
    let generating = flags.completions.is_some() || flags.man;
    if generating && !stdout_is_open() {
        anyhow::bail!("standard output is closed: nothing can be written");
    }
    if shell::generate(&flags, &mut io::stdout().lock())? {
        return Ok(ExitCode::SUCCESS);
    }
    let mut config = flags.into_config();
    // SIGINT (Ctrl-C), SIGTERM, SIGHUP: remove the temporary files of outputs being written and
    // stop, with exit status 130 for all three (the handler is not told which signal came; 130
    // is what a shell reports for SIGINT); outputs already written stay, complete. Without the
    // handler a temporary file could be left beside its target.
    ctrlc::set_handler(|| {
        say("interrupted");
        minitri::batch::exit_removing_temporaries(130)
    })
    .context("cannot install the signal handler")?;
    if let Some(jobs) = config.jobs.filter(|&j| j > MAX_JOBS) {
        if !config.quiet {
            say(&format!(
                "--jobs {jobs}: using {MAX_JOBS} threads, the most minitri starts"
            ));
        }
        config.jobs = Some(MAX_JOBS);
    }
    if let Some(code) = refuse_overwriting_inputs(&config.inputs, config.output.as_deref()) {
        return Ok(code);
    }
    if config.output.is_none() && !stdout_is_open() {
        anyhow::bail!("standard output is closed: the result could not be written (give -o FILE)");
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(config.jobs.unwrap_or(0))
        .build()
        .context("cannot start the worker threads")?;
    let out_dir = config
        .output
        .as_deref()
        .filter(|out| is_tree(&config.inputs, out));
    if let Some(out) = out_dir {
        if config.inputs.iter().any(|p| p == Path::new("-")) {
            say(&format!("standard input cannot be part of a batch written to a directory ({}); give its output file with -o, alone", out.display()));
            return Ok(ExitCode::from(2));
        }
        if out.exists() && !out.is_dir() {
            say(&format!(
                "{} is not a directory: with a directory input or several inputs, -o names a directory",
                out.display()
            ));
            return Ok(ExitCode::from(2));
        }
    }
    let (inputs, skipped) = discover_counting(&config.inputs, out_dir);
    // Waiting for a terminal to type into would otherwise look like a hang.
    let typing = inputs.iter().flatten().any(|i| i.is_stdin()) && io::stdin().is_terminal();
    if typing && !config.quiet {
        say("reading standard input; Ctrl-D to end (minitri --help for usage)");
    }
    let settings = Settings {
        options: config.options.clone(),
        from: config.from,
        quiet: config.quiet,
        // The cap on what one input (WKT) or feature (GeoJSON) may hold; lowered by tests only.
        limit: limits::limit_from(std::env::var_os(limits::LIMIT_FOR_TESTS).as_deref()),
        max_vertices: config.max_vertices,
    };
    let show_progress = !config.quiet && !typing && io::stderr().is_terminal();
    let progress = Progress::new(show_progress, inputs.len());
    let mut tally = match (out_dir, &config.output) {
        (Some(out), _) => {
            let found: Vec<_> = inputs
                .iter()
                .filter_map(|i| i.as_ref().ok())
                .cloned()
                .collect();
            let mut outputs = plan(&found, out, config.to.extension()).into_iter();
            let jobs: Vec<TreeJob> = inputs
                .into_iter()
                .map(|input| {
                    let output = match &input {
                        Ok(_) => outputs
                            .next()
                            .unwrap_or_else(|| Err("no output planned".into())),
                        Err(_) => Err(String::new()), // reported as unreadable
                    };
                    TreeJob { input, output }
                })
                .collect();
            pool.install(|| run_tree(&jobs, &settings, config.to, &progress))
        }
        (None, Some(path)) => {
            let mut file = AtomicFile::create(path)
                .with_context(|| format!("cannot write {}", path.display()))?;
            let report = pool
                .install(|| {
                    let sink = config.to.sink(&mut file)?;
                    run_document(&inputs, &settings, sink, &progress)
                })
                .with_context(|| format!("cannot write {}", path.display()))?;
            progress.bar.finish_and_clear();
            if file.is_direct() {
                // A device or a pipe: written as it went, like standard output.
                file.commit()
                    .with_context(|| format!("cannot write {}", path.display()))?;
            } else if report.tally.solved == 0 {
                say(&format!(
                    "nothing triangulated; {} not written",
                    path.display()
                ));
            } else if !report.complete {
                say(&format!(
                    "an input could not be read to its end; {} not written",
                    path.display()
                ));
            } else {
                file.commit()
                    .with_context(|| format!("cannot write {}", path.display()))?;
            }
            report.tally
        }
        (None, None) => {
            let report = pool
                .install(|| {
                    let stdout = io::BufWriter::new(io::stdout().lock());
                    run_document(&inputs, &settings, config.to.sink(stdout)?, &progress)
                })
                .context("cannot write to standard output")?;
            report.tally
        }
    };
    progress.bar.finish_and_clear();
    tally.skipped = skipped;
    let batch =
        out_dir.is_some() || config.inputs.len() > 1 || config.inputs.iter().any(|p| p.is_dir());
    if batch && !config.quiet {
        say(&tally.summary(started.elapsed()).to_string());
    }
    Ok(exit_code(&tally))
}

/// Exit status 2 (with a message) when the output would overwrite an input: `-o` naming an input
/// file (any spelling, a link, standard input redirected from it) or an input directory.
fn refuse_overwriting_inputs(
    inputs: &[std::path::PathBuf],
    out: Option<&Path>,
) -> Option<ExitCode> {
    let out = out?;
    let input = minitri::batch::input_that_is(inputs, out)?;
    let what = if out.is_dir() { "directory" } else { "file" };
    let input = if input == Path::new("-") {
        "standard input".to_string()
    } else {
        input.display().to_string()
    };
    say(&format!(
        "-o {}: the output {what} is the input {input}; it would be overwritten (choose another output)",
        out.display()
    ));
    Some(ExitCode::from(2))
}

/// The exit status (docs/cli.md): 3 a `--verify` problem, 1 a failure, 0 all processed.
fn exit_code(tally: &Tally) -> ExitCode {
    if tally.verify_failures > 0 {
        ExitCode::from(3)
    } else if tally.errors > 0 {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}

/// Messages on standard error, above a progress bar when standard error is a terminal.
struct Progress {
    bar: ProgressBar,
    polygons: AtomicUsize,
}

impl Progress {
    fn new(show: bool, files: usize) -> Progress {
        let bar = if show {
            let style = ProgressStyle::with_template(
                "{spinner} {elapsed_precise} [{bar:30}] {pos}/{len} files, {msg}",
            )
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> ");
            let bar = ProgressBar::new(files as u64).with_style(style);
            bar.enable_steady_tick(Duration::from_millis(120));
            bar
        } else {
            ProgressBar::hidden()
        };
        Progress {
            bar,
            polygons: AtomicUsize::new(0),
        }
    }
}

impl Observer for Progress {
    fn polygons(&self, count: usize) {
        let total = self.polygons.fetch_add(count, Ordering::Relaxed) + count;
        self.bar.set_message(format!("{total} polygons"));
    }

    fn input_finished(&self) {
        self.bar.inc(1);
    }

    fn message(&self, line: &str) {
        self.bar.suspend(|| say(line));
    }
}
