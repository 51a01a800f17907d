//! Which files a run reads: inputs as given, directories expanded.
//!
//! Input contract: paths as given on the command line (`-` is standard input). Output guarantee:
//! one entry per input file, in order: each path as given, or for a directory every file below it
//! (recursively) with a known extension, sorted by path; each with its path relative to the
//! directory it was found in (a file given directly: its file name), which is what an output
//! directory mirrors. A directory that cannot be read is an [`Unreadable`] entry in its place.
//! Complexity: linear in the number of directory entries, plus the sort.

use std::fs;
use std::path::{Path, PathBuf};

/// File extensions read from a directory (lowercase): every input format's, also before `.gz`
/// (the readers' list, [`crate::io::read::EXTENSIONS`]).
pub use crate::io::read::EXTENSIONS;

/// One input file of a run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Input {
    /// The path as given or found; `-` is standard input.
    pub path: PathBuf,
    /// The path relative to the directory input it was found in, or its file name when it was
    /// given directly.
    pub relative: PathBuf,
    /// Found by walking a directory (a regular file then), not named: opened, it must still be
    /// a regular file (one replaced by a FIFO since would block the run), see
    /// [`Input::open`].
    pub walked: bool,
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

    /// Opens the file for reading, never blocking on it when it was found by a walk: it is
    /// opened with `O_NONBLOCK`, its type checked on the open descriptor (`fstat`), and the flag
    /// cleared. A walked input that is no longer a regular file (replaced by a FIFO after the
    /// walk, whose `open` would wait for a writer forever) is an error naming what it is. A
    /// named input is opened as it is (a FIFO named is read).
    ///
    /// # Errors
    /// The file cannot be opened, or a walked one is not a regular file any more (the message
    /// is the whole reason).
    pub fn open(&self) -> std::io::Result<fs::File> {
        if !self.walked {
            return fs::File::open(&self.path);
        }
        let mut options = fs::OpenOptions::new();
        options.read(true);
        #[cfg(unix)]
        {
            use std::os::unix::fs::OpenOptionsExt;
            options.custom_flags(libc::O_NONBLOCK);
        }
        let file = options.open(&self.path)?;
        let kind = file.metadata()?.file_type();
        if !kind.is_file() {
            let what = special_kind(&kind);
            return Err(std::io::Error::other(NotRegular(format!(
                "skipped: {what}, not a regular file (it was replaced after the directory was read; name it to read it)"
            ))));
        }
        #[cfg(unix)]
        {
            let flags = rustix::fs::fcntl_getfl(&file)?;
            rustix::fs::fcntl_setfl(&file, flags - rustix::fs::OFlags::NONBLOCK)?;
        }
        Ok(file)
    }
}

/// Why a walked input was not read: it is no longer a regular file (the whole message).
#[derive(Debug)]
pub struct NotRegular(pub String);

impl std::fmt::Display for NotRegular {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for NotRegular {}

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
/// Directories are walked with `walkdir`, following links to directories but never around a
/// loop (a link to a directory above it is reported, not followed again). Only regular files
/// are read from a walk: a FIFO (which would block the run), a socket or a device found there
/// is skipped and reported as an [`Unreadable`] entry; a FIFO named on the command line is read.
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
            let mut unknown = 0;
            let mut found = walk(path, skip.as_deref(), &mut unknown);
            skipped += unknown;
            if found.is_empty() {
                out.push(Err(Unreadable {
                    name: path.display().to_string(),
                    message: format!(
                        "no input file found in this directory ({unknown} other file{}; inputs end in .{}, or one of these and .gz)",
                        if unknown == 1 { "" } else { "s" },
                        EXTENSIONS.join(", .")
                    ),
                }));
                continue;
            }
            found.sort_by(|a, b| a.0.cmp(&b.0));
            out.extend(found.into_iter().map(|(file, entry)| {
                entry.map(|()| {
                    let relative = file.strip_prefix(path).unwrap_or(&file).to_path_buf();
                    Input {
                        path: file,
                        relative,
                        walked: true,
                    }
                })
            }));
        } else {
            let relative = path.file_name().map_or_else(|| path.clone(), PathBuf::from);
            out.push(Ok(Input {
                path: path.clone(),
                relative,
                walked: false,
            }));
        }
    }
    (out, skipped)
}

/// Every file below `dir` with a known extension, not entering `skip`; with the entries that
/// cannot be read or are skipped (special files, link loops), each with its reason; `unknown`
/// counts the other files.
fn walk(
    dir: &Path,
    skip: Option<&Path>,
    unknown: &mut usize,
) -> Vec<(PathBuf, Result<(), Unreadable>)> {
    let mut found = Vec::new();
    let unreadable = |path: &Path, message: String| {
        let name = path.display().to_string();
        (path.to_path_buf(), Err(Unreadable { name, message }))
    };
    let mut entries = walkdir::WalkDir::new(dir).follow_links(true).into_iter();
    while let Some(entry) = entries.next() {
        let entry = match entry {
            Ok(entry) => entry,
            Err(e) => {
                let path = e.path().unwrap_or(dir).to_path_buf();
                let message = match (e.loop_ancestor(), e.io_error()) {
                    (Some(ancestor), _) => format!(
                        "skipped: a link back to {} (a directory loop)",
                        ancestor.display()
                    ),
                    (None, Some(io)) => format!("cannot read: {io}"),
                    (None, None) => format!("cannot read: {e}"),
                };
                found.push(unreadable(&path, message));
                continue;
            }
        };
        let kind = entry.file_type();
        if kind.is_dir() {
            if skip.is_some_and(|s| fs::canonicalize(entry.path()).is_ok_and(|d| d == s)) {
                entries.skip_current_dir();
            }
            continue;
        }
        if !crate::io::read::is_input_name(entry.path()) {
            *unknown += 1;
            continue;
        }
        if kind.is_file() {
            found.push((entry.path().to_path_buf(), Ok(())));
        } else {
            let what = special_kind(&kind);
            let message = format!("skipped: {what}, not a regular file (name it to read it)");
            found.push(unreadable(entry.path(), message));
        }
    }
    found
}

/// What a file that is neither a regular file nor a directory is, in words.
fn special_kind(kind: &fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if kind.is_fifo() {
            return "a FIFO";
        } else if kind.is_socket() {
            return "a socket";
        } else if kind.is_block_device() || kind.is_char_device() {
            return "a device";
        }
    }
    let _ = kind;
    "a special file"
}
