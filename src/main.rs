//! The `minitri` command: flags, library call, writer, exit code. All the work is in the library
//! (`minitri::batch`); this file wires the flags, the thread pool, the progress bar and the
//! output file or directory.

mod args;
mod shell;

use anyhow::Context;
use args::Flags;
use indicatif::{ProgressBar, ProgressStyle};
use minitri::batch::{
    discover_counting, plan, run_document, run_tree, AtomicFile, Observer, Settings, Tally, TreeJob,
};
use std::io::{self, IsTerminal};
use std::path::Path;
use std::process::ExitCode;
use std::sync::atomic::{AtomicUsize, Ordering};
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
            eprintln!("minitri: {err:#}");
            ExitCode::from(1)
        }
    }
}

fn run() -> anyhow::Result<ExitCode> {
    let started = Instant::now();
    let flags = Flags::from_env();
    if shell::generate(&flags, &mut io::stdout().lock())? {
        return Ok(ExitCode::SUCCESS);
    }
    let config = flags.into_config();
    // Ctrl-C: remove the temporary files of outputs being written and stop (exit status 130, as
    // a shell reports a process stopped by SIGINT); outputs already written stay, complete.
    // Without the handler a temporary file could be left beside its target.
    ctrlc::set_handler(|| {
        eprintln!("minitri: interrupted");
        minitri::batch::exit_removing_temporaries(130)
    })
    .context("cannot install the Ctrl-C handler")?;
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
            eprintln!("minitri: standard input cannot be part of a batch written to a directory ({}); give its output file with -o, alone", out.display());
            return Ok(ExitCode::from(2));
        }
        if out.exists() && !out.is_dir() {
            eprintln!(
                "minitri: {} is not a directory: with a directory input or several inputs, -o names a directory",
                out.display()
            );
            return Ok(ExitCode::from(2));
        }
    }
    let (inputs, skipped) = discover_counting(&config.inputs, out_dir);
    // Waiting for a terminal to type into would otherwise look like a hang.
    let typing = inputs.iter().flatten().any(|i| i.is_stdin()) && io::stdin().is_terminal();
    if typing && !config.quiet {
        eprintln!("minitri: reading standard input; Ctrl-D to end (minitri --help for usage)");
    }
    let settings = Settings {
        options: config.options.clone(),
        from: config.from,
        quiet: config.quiet,
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
                eprintln!(
                    "minitri: nothing triangulated; {} not written",
                    path.display()
                );
            } else if !report.complete {
                eprintln!(
                    "minitri: an input could not be read to its end; {} not written",
                    path.display()
                );
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
        eprintln!("minitri: {}", tally.summary(started.elapsed()));
    }
    Ok(exit_code(&tally))
}

/// Does `-o out` name a directory mirroring the inputs (rather than one output file)?
fn is_tree(inputs: &[std::path::PathBuf], out: &Path) -> bool {
    inputs.len() > 1 || inputs.iter().any(|p| p.is_dir()) || out.is_dir()
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
        self.bar.suspend(|| eprintln!("minitri: {line}"));
    }
}
