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

/// The most worker threads `--jobs` starts (more only cost memory and start-up time;
/// docs/benchmarks.md).
const MAX_JOBS: usize = 256;

/// A line on standard error, `minitri: ` first. A failure to write it (standard error closed,
/// full, a broken pipe) is ignored: diagnostics never stop a run or lose its result.
fn say(line: &str) {
    let _ = writeln!(io::stderr().lock(), "minitri: {}", printable(line));
}

/// `line` with its control characters escaped (`\n`, `\u{1b}`), as excerpts of an input's
/// contents already are: a file name holding a newline stays on its one line, and an escape
/// sequence in a name never reaches the terminal.
fn printable(line: &str) -> std::borrow::Cow<'_, str> {
    if !line.chars().any(char::is_control) {
        return line.into();
    }
    let mut out = String::with_capacity(line.len() + 8);
    for c in line.chars() {
        if c.is_control() {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out.into()
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

/// The same for descriptor 0, standard input.
#[cfg(target_os = "linux")]
static STDIN_AT_START: AtomicBool = AtomicBool::new(true);

#[cfg(target_os = "linux")]
#[used]
#[link_section = ".init_array"]
static RECORD_STDOUT: extern "C" fn() = {
    extern "C" fn record() {
        // SAFETY: `fcntl(F_GETFD)` only reads the descriptor's flags (-1 when it is not open).
        let open = unsafe { libc::fcntl(1, libc::F_GETFD) } != -1;
        STDOUT_AT_START.store(open, Ordering::Relaxed);
        // SAFETY: as above, for descriptor 0.
        let open = unsafe { libc::fcntl(0, libc::F_GETFD) } != -1;
        STDIN_AT_START.store(open, Ordering::Relaxed);
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
    install_handlers()?;
    cap_jobs(&mut config);
    if let Some(code) = refuse_overwriting_inputs(&config.inputs, config.output.as_deref()) {
        return Ok(code);
    }
    check_stdout(&config)?;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(config.jobs.unwrap_or(0))
        .build()
        .context("cannot start the worker threads")?;
    let out_dir = config
        .output
        .as_deref()
        .filter(|out| is_tree(&config.inputs, out));
    if let Some(code) = out_dir.and_then(|out| refuse_tree(&config, out)) {
        return Ok(code);
    }
    let (mut inputs, skipped) = discover_counting(&config.inputs, out_dir);
    refuse_unreadable_stdin(&mut inputs);
    // Standard output being an input, named or found in a directory, also through `>>`, `1<>`
    // or standard input redirected from it: it would be written while read (`--to geojsonl
    // f.ndjson >> f.ndjson` grows without end). (`-o FILE` is compared above.)
    if config.output.is_none() {
        if let Some(code) = refuse_writing_to_an_input(&inputs) {
            return Ok(code);
        }
    }
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
            let jobs = tree_jobs(inputs, out, &config);
            pool.install(|| run_tree(&jobs, out, &settings, config.to, &progress))
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
            commit_document(file, &report, path)?;
            report.tally
        }
        (None, None) => {
            let report = pool
                .install(|| {
                    let stdout = io::BufWriter::new(stdout_file()?);
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

/// The signal dispositions of a run.
///
/// A file-size limit (`ulimit -f`) would kill the process with SIGXFSZ at the write that
/// crosses it (status 153, no message, a temporary file left); ignored, that write fails with
/// EFBIG instead: reported, exit status 1, the temporary file removed. SIGINT (Ctrl-C), SIGTERM,
/// SIGHUP: remove the temporary files of outputs being written and stop, with exit status 130
/// for all three (the handler is not told which signal came; 130 is what a shell reports for
/// SIGINT); outputs already written stay, complete. Without the handler a temporary file could
/// be left beside its target.
fn install_handlers() -> anyhow::Result<()> {
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to "ignore" runs no code of ours in a handler.
    unsafe {
        libc::signal(libc::SIGXFSZ, libc::SIG_IGN);
    }
    ctrlc::set_handler(|| {
        say("interrupted");
        minitri::batch::exit_removing_temporaries(130)
    })
    .context("cannot install the signal handler")
}

/// `--jobs` capped at [`MAX_JOBS`], told (unless quiet); without `--jobs`, rayon reads its own
/// variables: the same cap applies to them.
fn cap_jobs(config: &mut args::Config) {
    if let Some(jobs) = config.jobs.filter(|&j| j > MAX_JOBS) {
        if !config.quiet {
            say(&format!(
                "--jobs {jobs}: using {MAX_JOBS} threads, the most minitri starts"
            ));
        }
        config.jobs = Some(MAX_JOBS);
    }
    if config.jobs.is_none() {
        for var in ["RAYON_NUM_THREADS", "RAYON_RS_NUM_CPUS"] {
            let asked = std::env::var(var)
                .ok()
                .and_then(|v| v.trim().parse::<usize>().ok());
            if let Some(threads) = asked.filter(|&n| n > MAX_JOBS) {
                if !config.quiet {
                    say(&format!(
                        "{var}={threads}: using {MAX_JOBS} threads, the most minitri starts"
                    ));
                }
                config.jobs = Some(MAX_JOBS);
                break;
            }
            if asked.is_some() {
                break; // rayon takes the first one set
            }
        }
    }
}

/// An error when the result is for standard output and it cannot take it: closed, or not
/// writable.
fn check_stdout(config: &args::Config) -> anyhow::Result<()> {
    let closed = "standard output is closed: the result could not be written (give -o FILE)";
    if config.output.is_none() && !stdout_is_open() {
        anyhow::bail!(closed);
    }
    // `-o /dev/stdout` (or `/dev/fd/1`, `/proc/self/fd/1`) with standard output closed names the
    // `/dev/null` put in its place at start: the result would be lost with exit status 0.
    if config.output.as_deref().is_some_and(names_stdout) && !stdout_is_open() {
        anyhow::bail!(closed);
    }
    if config.output.is_none() {
        if let Some(why) = stdout_not_writable() {
            anyhow::bail!(
                "standard output is {why}: the result could not be written (give -o FILE)"
            );
        }
    }
    Ok(())
}

/// Exit status 2 (with a message) when a batch cannot be written to the directory `out`:
/// standard input among the inputs, or `out` a file.
fn refuse_tree(config: &args::Config, out: &Path) -> Option<ExitCode> {
    if config.inputs.iter().any(|p| p == Path::new("-")) {
        say(&format!("standard input cannot be part of a batch written to a directory ({}); give its output file with -o, alone", out.display()));
        return Some(ExitCode::from(2));
    }
    if out.exists() && !out.is_dir() {
        say(&format!(
            "{} is not a directory: with a directory input or several inputs, -o names a directory",
            out.display()
        ));
        return Some(ExitCode::from(2));
    }
    None
}

/// Standard input closed, or open for writing only: Rust reads either as an empty input (EBADF
/// taken for the end), which would say "empty input: no polygon found"; it is made an
/// unreadable input saying why.
fn refuse_unreadable_stdin(
    inputs: &mut [Result<minitri::batch::Input, minitri::batch::Unreadable>],
) {
    if let Some(why) = stdin_not_readable() {
        for input in inputs {
            if input.as_ref().is_ok_and(|i| i.is_stdin()) {
                *input = Err(minitri::batch::Unreadable {
                    name: "-".into(),
                    message: format!("standard input is {why}: nothing to read (name a file, or redirect one with <)"),
                });
            }
        }
    }
}

/// Each input with its output file below `out` (mirrored, [`plan`]).
fn tree_jobs(
    inputs: Vec<Result<minitri::batch::Input, minitri::batch::Unreadable>>,
    out: &Path,
    config: &args::Config,
) -> Vec<TreeJob> {
    let found: Vec<_> = inputs
        .iter()
        .filter_map(|i| i.as_ref().ok())
        .cloned()
        .collect();
    let mut outputs = plan(&found, out, config.to.extension()).into_iter();
    inputs
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
        .collect()
}

/// The document written to `-o FILE` kept or not: a device or a pipe was written as it went,
/// like standard output; a file is kept only when something was triangulated and every input
/// read to its end.
fn commit_document(
    file: AtomicFile,
    report: &minitri::batch::DocumentReport,
    path: &Path,
) -> anyhow::Result<()> {
    if !file.is_direct() && report.tally.solved == 0 {
        say(&format!(
            "nothing triangulated; {} not written",
            path.display()
        ));
    } else if !file.is_direct() && !report.complete {
        say(&format!(
            "an input could not be read to its end; {} not written",
            path.display()
        ));
    } else {
        file.commit()
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    Ok(())
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

/// Exit status 2 (with a message) when standard output is a regular file that is one of the
/// inputs (also one found in a directory, or standard input redirected from it), compared by
/// device and inode.
fn refuse_writing_to_an_input(
    inputs: &[Result<minitri::batch::Input, minitri::batch::Unreadable>],
) -> Option<ExitCode> {
    let id = stdout_file_id()?;
    let input = inputs.iter().flatten().find(|input| {
        if input.is_stdin() {
            stdin_file_id().is_some_and(|stdin| stdin == id)
        } else {
            minitri::batch::file_id(&input.path).is_some_and(|i| i == id)
        }
    })?;
    let name = if input.is_stdin() {
        "standard input".to_string()
    } else {
        input.name()
    };
    say(&format!(
        "standard output is the input {name}; it would be written while it is read (choose another output)"
    ));
    Some(ExitCode::from(2))
}

/// The identity of the regular file open as descriptor `fd` (standard output or input), if it
/// is one.
#[cfg(unix)]
fn fd_file_id(fd: std::os::fd::BorrowedFd<'_>) -> Option<minitri::batch::FileId> {
    let file = std::fs::File::from(fd.try_clone_to_owned().ok()?);
    let meta = file.metadata().ok().filter(|m| m.is_file())?;
    Some(minitri::batch::file_id_of(&meta))
}

fn stdout_file_id() -> Option<minitri::batch::FileId> {
    #[cfg(unix)]
    {
        use std::os::fd::AsFd;
        fd_file_id(io::stdout().as_fd())
    }
    #[cfg(not(unix))]
    None
}

fn stdin_file_id() -> Option<minitri::batch::FileId> {
    #[cfg(unix)]
    {
        use std::os::fd::AsFd;
        fd_file_id(io::stdin().as_fd())
    }
    #[cfg(not(unix))]
    None
}

/// Does `path` name descriptor 1 (`/dev/stdout`, `/dev/fd/1`, `/proc/self/fd/1`, or a link to
/// one of them)?
fn names_stdout(path: &Path) -> bool {
    let own = format!("/proc/{}/fd/1", std::process::id());
    let names = [
        "/dev/stdout",
        "/dev/fd/1",
        "/proc/self/fd/1",
        "/proc/thread-self/fd/1",
    ];
    let mut path = path.to_path_buf();
    for _ in 0..40 {
        let absolute = std::path::absolute(&path).unwrap_or_else(|_| path.clone());
        if names.iter().any(|n| absolute == Path::new(n)) || absolute == Path::new(&own) {
            return true;
        }
        let Ok(next) = std::fs::read_link(&path) else {
            return false;
        };
        path = path.parent().unwrap_or(Path::new("")).join(next);
    }
    false
}

/// Why standard output cannot take the result, if it cannot: open read-only (`1<file`), on a
/// directory. Every write would fail with EBADF, which Rust's standard output ignores: the
/// result lost with exit status 0.
fn stdout_not_writable() -> Option<&'static str> {
    #[cfg(unix)]
    {
        // SAFETY: `fcntl(F_GETFL)` only reads the descriptor's status flags.
        let flags = unsafe { libc::fcntl(1, libc::F_GETFL) };
        if flags != -1 && flags & libc::O_ACCMODE == libc::O_RDONLY {
            let dir = std::fs::metadata("/dev/stdout").is_ok_and(|m| m.is_dir());
            return Some(if dir {
                "a directory"
            } else {
                "open for reading only"
            });
        }
    }
    None
}

/// Why standard input cannot be read, if it cannot: closed at start (reopened on `/dev/null`
/// by Rust's start-up code), or open for writing only.
fn stdin_not_readable() -> Option<&'static str> {
    #[cfg(target_os = "linux")]
    if !STDIN_AT_START.load(Ordering::Relaxed) {
        return Some("closed");
    }
    #[cfg(unix)]
    {
        // SAFETY: `fcntl(F_GETFL)` only reads the descriptor's status flags.
        let flags = unsafe { libc::fcntl(0, libc::F_GETFL) };
        if flags == -1 {
            return Some("closed");
        }
        if flags & libc::O_ACCMODE == libc::O_WRONLY {
            return Some("open for writing only");
        }
    }
    None
}

/// Standard output as a file of its own (a duplicate of descriptor 1): unlike `io::stdout()`,
/// which takes EBADF for success, every error of a write is reported.
fn stdout_file() -> io::Result<Box<dyn Write + Send>> {
    #[cfg(unix)]
    {
        use std::os::fd::AsFd;
        let fd = io::stdout().as_fd().try_clone_to_owned()?;
        Ok(Box::new(std::fs::File::from(fd)))
    }
    #[cfg(not(unix))]
    Ok(Box::new(io::stdout()))
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
