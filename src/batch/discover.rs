//! Which files a run reads: inputs as given, directories expanded.
//!
//! Input contract: paths as given on the command line (`-` is standard input). Output guarantee:
//! one entry per input file, in order: each path as given, or for a directory every file below it
//! (recursively) with a known extension, sorted by path; each with its path relative to the
//! directory it was found in (a file given directly: its file name), which is what an output
//! directory mirrors. A directory that cannot be read is an [`Unreadable`] entry in its place.
//! Complexity: linear in the number of directory entries, plus the sort.

use std::fs;
use std::io;
use std::path::{Path, PathBuf};

/// File extensions read from a directory (lowercase): every input format's.
pub const EXTENSIONS: &[&str] = &[
    "wkt", "geojson", "json", "geojsonl", "geojsons", "ndjson", "txt", "xy", "vertices",
];

/// One input file of a run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Input {
    /// The path as given or found; `-` is standard input.
    pub path: PathBuf,
    /// The path relative to the directory input it was found in, or its file name when it was
    /// given directly.
    pub relative: PathBuf,
}

impl Input {
    /// The name used in messages and outputs: the path as given or found.
    pub fn name(&self) -> String {
        self.path.display().to_string()
    }

    /// Is this standard input?
    pub fn is_stdin(&self) -> bool {
        self.path == Path::new("-")
    }
}

/// An input (a directory) that could not be read, and why.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Unreadable {
    /// The path as given or found.
    pub name: String,
    /// What went wrong.
    pub message: String,
}

/// Expands `paths` into input files (see the module docs). Directories equal to `skip` (the
/// output directory, so that a second run does not read the first run's outputs) are not entered.
///
/// # Examples
/// ```
/// use minitri::batch::discover;
/// let inputs = discover(&["fixtures/valid".into()], None);
/// let first = inputs[0].as_ref().map_err(|e| e.message.clone())?;
/// assert!(first.path.starts_with("fixtures/valid"));
/// assert_eq!(first.relative, first.path.strip_prefix("fixtures/valid").unwrap());
/// # Ok::<(), String>(())
/// ```
pub fn discover(paths: &[PathBuf], skip: Option<&Path>) -> Vec<Result<Input, Unreadable>> {
    discover_counting(paths, skip).0
}

/// [`discover`], and how many files below the directories were skipped, their names ending in
/// no input format's extension ([`EXTENSIONS`]). A directory holding no input file at all is an
/// [`Unreadable`] entry saying so (the run then exits with status 1, naming it).
pub fn discover_counting(
    paths: &[PathBuf],
    skip: Option<&Path>,
) -> (Vec<Result<Input, Unreadable>>, usize) {
    let skip = skip.and_then(|s| fs::canonicalize(s).ok());
    let mut out = Vec::new();
    let mut skipped = 0;
    for path in paths {
        if path.is_dir() {
            let mut files = Vec::new();
            let mut unknown = 0;
            if let Err(e) = walk(path, skip.as_deref(), &mut files, &mut unknown) {
                out.push(Err(Unreadable {
                    name: path.display().to_string(),
                    message: format!("cannot read: {e}"),
                }));
            } else if files.is_empty() {
                out.push(Err(Unreadable {
                    name: path.display().to_string(),
                    message: format!(
                        "no input file found in this directory ({unknown} other file{}; inputs end in .{})",
                        if unknown == 1 { "" } else { "s" },
                        EXTENSIONS.join(", .")
                    ),
                }));
            }
            skipped += unknown;
            files.sort();
            out.extend(files.into_iter().map(|file| {
                let relative = file.strip_prefix(path).unwrap_or(&file).to_path_buf();
                Ok(Input {
                    path: file,
                    relative,
                })
            }));
        } else {
            let relative = path.file_name().map_or_else(|| path.clone(), PathBuf::from);
            out.push(Ok(Input {
                path: path.clone(),
                relative,
            }));
        }
    }
    (out, skipped)
}

/// Every file below `dir` with a known extension, not entering `skip`; `unknown` counts the
/// other files.
fn walk(
    dir: &Path,
    skip: Option<&Path>,
    files: &mut Vec<PathBuf>,
    unknown: &mut usize,
) -> io::Result<()> {
    if skip.is_some_and(|s| fs::canonicalize(dir).is_ok_and(|d| d == s)) {
        return Ok(());
    }
    for entry in fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            walk(&path, skip, files, unknown)?;
        } else if path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| EXTENSIONS.contains(&e.to_ascii_lowercase().as_str()))
        {
            files.push(path);
        } else {
            *unknown += 1;
        }
    }
    Ok(())
}
