//! The `minitri` command: flags, library call, writer, exit code. All the work is in the library.

mod args;

use anyhow::Context;
use args::{Config, Flags, ToFlag};
use clap::Parser;
use minitri::io::read::{detect, Format};
use minitri::io::write::{json::write_json, svg};
use minitri::pipeline::{process, unreadable, Error, Outcome};
use std::io::{self, Read, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

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
    let config = Flags::parse().into_config();
    let mut outcomes: Vec<Outcome> = Vec::new();
    for source in sources(&config.inputs) {
        match source {
            Ok(path) => outcomes.extend(run_source(&path, &config)),
            Err((name, message)) => outcomes.push(unreadable(&name, Error::Read(message))),
        }
    }
    for outcome in &outcomes {
        if !config.quiet {
            for warning in &outcome.warnings {
                eprintln!("minitri: warning: {outcome}: {warning}");
            }
        }
        if let Err(e) = &outcome.result {
            for message in e.messages() {
                eprintln!("minitri: {outcome}: {message}");
            }
        }
    }
    let any_solved = outcomes.iter().any(|o| o.result.is_ok());
    match &config.output {
        Some(path) if any_solved => write_atomically(path, |out| write(&config, &outcomes, out))
            .with_context(|| format!("cannot write {}", path.display()))?,
        Some(path) => eprintln!(
            "minitri: nothing triangulated; {} not written",
            path.display()
        ),
        None => {
            let mut out = io::BufWriter::new(io::stdout().lock());
            write(&config, &outcomes, &mut out)?;
            out.flush()?;
        }
    }
    let verify_failed = outcomes
        .iter()
        .any(|o| matches!(&o.result, Ok(s) if s.verification.as_ref().is_some_and(|v| !v.ok)));
    let failed = outcomes.iter().any(|o| o.result.is_err());
    Ok(if verify_failed {
        ExitCode::from(3)
    } else if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    })
}

/// Reads one file (or standard input) and processes every polygon in it.
fn run_source(path: &Path, config: &Config) -> Vec<Outcome> {
    let stdin = path == Path::new("-");
    let name = path.display().to_string();
    let mut bytes = Vec::new();
    let read = if stdin {
        io::stdin().lock().read_to_end(&mut bytes)
    } else {
        std::fs::File::open(path).and_then(|mut f| f.read_to_end(&mut bytes))
    };
    if let Err(e) = read {
        return vec![unreadable(&name, Error::Read(e.to_string()))];
    }
    let text = match String::from_utf8(bytes) {
        Ok(text) => text,
        Err(e) => {
            let at = e.utf8_error().valid_up_to();
            return vec![unreadable(
                &name,
                Error::Read(format!("not UTF-8 text (invalid byte at offset {at})")),
            )];
        }
    };
    let extension = if stdin {
        None
    } else {
        path.extension().and_then(|e| e.to_str())
    };
    let format: Format = config.from.unwrap_or_else(|| detect(extension, &text));
    process(&name, &text, format, &config.options)
}

/// Expands directories (recursively, sorted, files with a known extension) into files.
fn sources(inputs: &[PathBuf]) -> Vec<Result<PathBuf, (String, String)>> {
    let mut out = Vec::new();
    for input in inputs {
        if input.is_dir() {
            let mut files = Vec::new();
            if let Err(e) = walk(input, &mut files) {
                out.push(Err((input.display().to_string(), e.to_string())));
            }
            files.sort();
            out.extend(files.into_iter().map(Ok));
        } else {
            out.push(Ok(input.clone()));
        }
    }
    out
}

const EXTENSIONS: &[&str] = &[
    "wkt", "geojson", "json", "geojsonl", "ndjson", "txt", "xy", "vertices",
];

fn walk(dir: &Path, files: &mut Vec<PathBuf>) -> io::Result<()> {
    for entry in std::fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            walk(&path, files)?;
        } else if path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
        {
            files.push(path);
        }
    }
    Ok(())
}

fn write(config: &Config, outcomes: &[Outcome], out: &mut impl Write) -> io::Result<()> {
    match config.to {
        ToFlag::Json => write_json(outcomes, out),
        ToFlag::Svg => {
            let figures: Vec<svg::Figure> = outcomes
                .iter()
                .filter_map(|o| {
                    let polygon = o.polygon.as_ref()?;
                    Some(svg::Figure {
                        title: o.to_string(),
                        polygon,
                        triangulation: o.result.as_ref().ok().map(|s| &s.triangulation),
                        error: o.result.as_ref().err().map(ToString::to_string),
                    })
                })
                .collect();
            svg::write_svg(&figures, out)
        }
    }
}

/// Writes to a temporary file beside `path`, then renames it: never a truncated output.
fn write_atomically(
    path: &Path,
    body: impl FnOnce(&mut io::BufWriter<std::fs::File>) -> io::Result<()>,
) -> io::Result<()> {
    let dir = path
        .parent()
        .filter(|d| !d.as_os_str().is_empty())
        .unwrap_or(Path::new("."));
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    let temp = dir.join(format!(".{name}.minitri-{}.tmp", std::process::id()));
    let result = (|| {
        let mut out = io::BufWriter::new(std::fs::File::create(&temp)?);
        body(&mut out)?;
        out.into_inner().map_err(|e| e.into_error())?.sync_all()?;
        std::fs::rename(&temp, path)
    })();
    if result.is_err() {
        let _ = std::fs::remove_file(&temp);
    }
    result
}
